// Lawson (flips) x `integer` kernel: one translation unit per algorithm x kernel.
#include "algorithms/lawson.hpp"
#include "predicates/integer_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_lawson_integer(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Lawson, IntegerKernel>(std::move(points), options);
}

}  // namespace dlab
