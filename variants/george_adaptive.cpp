// George's corrected cavity x `adaptive` kernel (the kernel of the exact volume
// tests, George 1997 section 2.3; the circumsphere test is floating unless
// --exact-sphere): one translation unit per algorithm x kernel.
#include "predicates/adaptive_kernel.hpp"
#include "variants/george_run.hpp"

namespace dlab {

RunResult run_george_adaptive(PointSet&& points, const RunOptions& options) {
  return run_george<AdaptiveKernel>(std::move(points), options);
}

}  // namespace dlab
