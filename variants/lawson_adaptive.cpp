// Lawson (flips) x `adaptive` kernel: one translation unit per algorithm x kernel.
#include "algorithms/lawson.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_lawson_adaptive(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Lawson, AdaptiveKernel>(std::move(points), options);
}

}  // namespace dlab
