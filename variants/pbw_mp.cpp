// Parallel Bowyer–Watson x `mp` kernel (algorithms/parallel_bowyer_watson.hpp):
// one translation unit per algorithm x kernel, exact kernels only.
#include "algorithms/parallel_bowyer_watson.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_parallel_bowyer_watson_mp(PointSet&& points, const RunOptions& options) {
  return run_algorithm<ParallelBowyerWatson, MpKernel>(std::move(points), options);
}

}  // namespace dlab
