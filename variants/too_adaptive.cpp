// Tanemura–Ogawa–Ogita x `adaptive` kernel: one translation unit per algorithm x
// kernel (algorithms/tanemura.hpp; explicit instantiation keeps builds parallel).
#include "algorithms/tanemura.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_tanemura_adaptive(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Tanemura, AdaptiveKernel>(std::move(points), options);
}

}  // namespace dlab
