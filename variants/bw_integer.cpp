// Bowyer–Watson x `integer` kernel: one translation unit per algorithm x kernel
// (explicit instantiation keeps builds parallel and error messages short).
#include "algorithms/bowyer_watson.hpp"
#include "predicates/integer_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_bowyer_watson_integer(PointSet&& points, const RunOptions& options) {
  return run_algorithm<BowyerWatson, IntegerKernel>(std::move(points), options);
}

}  // namespace dlab
