// How a triangulation run ended: shared by the algorithms
// (algorithms/triangulation_result.hpp) and the entry point dlab::run()
// (variants/run.hpp, where RunResult::Outcome names this enum).
#pragma once

namespace dlab {

enum class RunOutcome {
  ok,                 // simplices hold the triangulation
  lower_dimensional,  // fewer than d+1 distinct points, or all collinear/coplanar: no simplex
  failed              // the algorithm detected a failure (inexact kernels only)
};

}  // namespace dlab
