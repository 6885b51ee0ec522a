// dlab flip x `epsilon` kernel: one translation unit per kernel (variants/flip.hpp).
#include "predicates/epsilon_kernel.hpp"
#include "variants/flip_driver.hpp"

namespace dlab {

RunResult run_flip_epsilon(const PointSet& points, std::span<const std::uint32_t> simplices) {
  return run_flip_with<EpsilonKernel>(points, simplices);
}

}  // namespace dlab
