// Bowyer–Watson x `adaptive` kernel: one translation unit per algorithm x kernel
// (explicit instantiation keeps builds parallel and error messages short).
#include "algorithms/bowyer_watson.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_bowyer_watson_adaptive(PointSet&& points, const RunOptions& options) {
  return run_algorithm<BowyerWatson, AdaptiveKernel>(std::move(points), options);
}

}  // namespace dlab
