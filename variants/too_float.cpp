// Tanemura–Ogawa–Ogita x `float` kernel: one translation unit per algorithm x
// kernel (algorithms/tanemura.hpp; explicit instantiation keeps builds parallel).
#include "algorithms/tanemura.hpp"
#include "predicates/float_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_tanemura_float(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Tanemura, FloatKernel>(std::move(points), options);
}

}  // namespace dlab
