// dlab flip x `float` kernel: one translation unit per kernel (variants/flip.hpp).
#include "predicates/float_kernel.hpp"
#include "variants/flip_driver.hpp"

namespace dlab {

RunResult run_flip_float(const PointSet& points, std::span<const std::uint32_t> simplices) {
  return run_flip_with<FloatKernel>(points, simplices);
}

}  // namespace dlab
