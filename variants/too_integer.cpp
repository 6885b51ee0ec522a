// Tanemura–Ogawa–Ogita x `integer` kernel: one translation unit per algorithm x
// kernel (algorithms/tanemura.hpp; explicit instantiation keeps builds parallel).
#include "algorithms/tanemura.hpp"
#include "predicates/integer_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_tanemura_integer(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Tanemura, IntegerKernel>(std::move(points), options);
}

}  // namespace dlab
