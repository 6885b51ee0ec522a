// George's corrected cavity x `integer` kernel (the kernel of the exact volume
// tests, George 1997 section 2.3; the circumsphere test is floating unless
// --exact-sphere): one translation unit per algorithm x kernel.
#include "predicates/integer_kernel.hpp"
#include "variants/george_run.hpp"

namespace dlab {

RunResult run_george_integer(PointSet&& points, const RunOptions& options) {
  return run_george<IntegerKernel>(std::move(points), options);
}

}  // namespace dlab
