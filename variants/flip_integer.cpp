// dlab flip x `integer` kernel: one translation unit per kernel (variants/flip.hpp).
#include "predicates/integer_kernel.hpp"
#include "variants/flip_driver.hpp"

namespace dlab {

RunResult run_flip_integer(const PointSet& points, std::span<const std::uint32_t> simplices) {
  return run_flip_with<IntegerKernel>(points, simplices);
}

}  // namespace dlab
