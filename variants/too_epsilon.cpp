// Tanemura–Ogawa–Ogita x `epsilon` kernel: one translation unit per algorithm x
// kernel (algorithms/tanemura.hpp; explicit instantiation keeps builds parallel).
#include "algorithms/tanemura.hpp"
#include "predicates/epsilon_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_tanemura_epsilon(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Tanemura, EpsilonKernel>(std::move(points), options);
}

}  // namespace dlab
