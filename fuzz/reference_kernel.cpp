// The reference's instantiation (fuzz/reference.hpp): Bowyer-Watson under the
// sos policy with the validator's exact kernel -- a floating filter that
// answers only when its error bound proves the sign, then GMP
// (predicates/filtered.hpp, predicates/float_filter.hpp) -- instead of plain
// GMP: the same signs, so the same perturbed triangulation, at a fraction of
// the cost on non-degenerate calls; and no code of the adaptive kernel.
#include "algorithms/bowyer_watson.hpp"
#include "fuzz/reference.hpp"
#include "predicates/filtered.hpp"
#include "predicates/float_filter.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab::fuzz {

RunResult run_reference(const PointSet& points) {
  RunOptions o;
  o.algorithm = "bowyer-watson";
  o.kernel = "mp";  // what the stats say; the kernel is filtered<FloatFilter, MpKernel>
  o.policy = "sos";
  o.order = "brio";
  return run_algorithm<BowyerWatson, filtered<FloatFilter, MpKernel>>(points, o);
}

}  // namespace dlab::fuzz
