// Lawson (flips) x `mp` kernel: one translation unit per algorithm x kernel.
#include "algorithms/lawson.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_lawson_mp(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Lawson, MpKernel>(std::move(points), options);
}

}  // namespace dlab
