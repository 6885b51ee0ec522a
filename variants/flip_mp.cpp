// dlab flip x `mp` kernel: one translation unit per kernel (variants/flip.hpp).
#include "predicates/mp_kernel.hpp"
#include "variants/flip_driver.hpp"

namespace dlab {

RunResult run_flip_mp(const PointSet& points, std::span<const std::uint32_t> simplices) {
  return run_flip_with<MpKernel>(points, simplices);
}

}  // namespace dlab
