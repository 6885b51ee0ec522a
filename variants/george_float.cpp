// George's corrected cavity x `float` kernel: the inexact baseline for the
// paper's claim (George 1997 section 2.3) that the volume tests must be exact.
// With float volumes the corrections may themselves be wrong; the run then ends as
// a reported failure or a result the exact validator rejects (the CLI checks
// it), never a crash or a hang (every loop of algorithms/george.hpp is bounded
// by the structure, not by the arithmetic). One translation unit per
// algorithm x kernel.
#include "predicates/float_kernel.hpp"
#include "variants/george_run.hpp"

namespace dlab {

RunResult run_george_float(PointSet&& points, const RunOptions& options) {
  return run_george<FloatKernel>(std::move(points), options);
}

}  // namespace dlab
