// Parallel Bowyer–Watson x `integer` kernel (algorithms/parallel_bowyer_watson.hpp):
// one translation unit per algorithm x kernel, exact kernels only.
#include "algorithms/parallel_bowyer_watson.hpp"
#include "predicates/integer_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_parallel_bowyer_watson_integer(PointSet&& points, const RunOptions& options) {
  return run_algorithm<ParallelBowyerWatson, IntegerKernel>(std::move(points), options);
}

}  // namespace dlab
