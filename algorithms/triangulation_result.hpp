// What a triangulation algorithm hands back to the driver (variants/driver.hpp),
// in terms of the point sequence it was given (already in insertion order).
// The driver maps ids back to input indices and first occurrences.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/run_outcome.hpp"
#include "predicates/counters.hpp"

namespace dlab {

inline constexpr std::uint32_t kNotProcessed = 0xFFFFFFFFu;

struct TriangulationResult {
  RunOutcome outcome = RunOutcome::ok;
  std::string message;
  // (D+1) ids into the sequence per finite simplex, positively oriented.
  std::vector<std::uint32_t> simplices;
  // Per point of the sequence: the id of the vertex it became or duplicates
  // (its own id when it is a vertex), kNotProcessed when the run stopped first.
  std::vector<std::uint32_t> merged_into;
  Counters counters;
};

}  // namespace dlab
