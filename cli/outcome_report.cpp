// See outcome_report.hpp.
#include "cli/outcome_report.hpp"

#include <cstdint>
#include <iostream>

#include "cli/numbers.hpp"

namespace dlab::cli {

void announce_snapping(std::string_view command, const RunResult& r) {
  std::uint64_t moved = 0, merged = 0;
  for (const auto& [key, v] : r.snapping) {
    if (key == "points_moved") moved = v;
    if (key == "points_merged") merged = v;
  }
  if (moved == 0 && merged == 0) return;
  std::cerr << "dlab " << command << ": snapped: " << moved << " of " << r.points.size()
            << " points moved to the integer kernel's grid, " << merged << " merged, largest displacement "
            << io::format_decimal(r.max_snap_displacement) << "\n";
}

void print_outcome(std::string_view command, const Outcome& o, std::string_view pair) {
  if (o.kind != OutcomeClass::ok) std::cerr << outcome_line(command, o, pair) << "\n";
}

}  // namespace dlab::cli
