// Parallel Bowyer–Watson x `adaptive` kernel (algorithms/parallel_bowyer_watson.hpp):
// one translation unit per algorithm x kernel, exact kernels only.
#include "algorithms/parallel_bowyer_watson.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_parallel_bowyer_watson_adaptive(PointSet&& points, const RunOptions& options) {
  return run_algorithm<ParallelBowyerWatson, AdaptiveKernel>(std::move(points), options);
}

}  // namespace dlab
