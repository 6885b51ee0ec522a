// Tanemura–Ogawa–Ogita x `mp` kernel: one translation unit per algorithm x
// kernel (algorithms/tanemura.hpp; explicit instantiation keeps builds parallel).
#include "algorithms/tanemura.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_tanemura_mp(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Tanemura, MpKernel>(std::move(points), options);
}

}  // namespace dlab
