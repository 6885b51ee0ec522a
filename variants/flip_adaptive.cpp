// dlab flip x `adaptive` kernel: one translation unit per kernel (variants/flip.hpp).
#include "predicates/adaptive_kernel.hpp"
#include "variants/flip_driver.hpp"

namespace dlab {

RunResult run_flip_adaptive(const PointSet& points, std::span<const std::uint32_t> simplices) {
  return run_flip_with<AdaptiveKernel>(points, simplices);
}

}  // namespace dlab
