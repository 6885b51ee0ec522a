// Lawson (flips) x `float` kernel: one translation unit per algorithm x kernel.
#include "algorithms/lawson.hpp"
#include "predicates/float_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_lawson_float(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Lawson, FloatKernel>(std::move(points), options);
}

}  // namespace dlab
