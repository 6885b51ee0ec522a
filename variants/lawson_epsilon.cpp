// Lawson (flips) x `epsilon` kernel: one translation unit per algorithm x kernel.
#include "algorithms/lawson.hpp"
#include "predicates/epsilon_kernel.hpp"
#include "variants/driver.hpp"

namespace dlab {

RunResult run_lawson_epsilon(PointSet&& points, const RunOptions& options) {
  return run_algorithm<Lawson, EpsilonKernel>(std::move(points), options);
}

}  // namespace dlab
