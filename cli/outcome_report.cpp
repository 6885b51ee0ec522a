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

const char* const kOutcomeHelp =
    "Outcomes of triangulate and flip: exit status and one stderr line (`outcome` in --stats):\n"
    "  ok                 0  nothing\n"
    "  lower-dimensional  0  dlab CMD: lower-dimensional: WHY (PAIR)\n"
    "  not-delaunay       1  dlab CMD: not-delaunay: N facets not locally Delaunay (first: ...) (PAIR)\n"
    "  invalid            1  dlab CMD: invalid: CHECK: WHAT (first: ...) (PAIR)   CHECK: indices,\n"
    "                        orientation, overlap, adjacency, hull-coverage, missing-point\n"
    "  reported           1  dlab CMD: reported: THE ALGORITHM'S MESSAGE (PAIR)\n"
    "  bad input or usage 2  dlab CMD: FILE:LINE: PROBLEM\n"
    "PAIR is 'ALGORITHM, KERNEL kernel'. A pair that promises a Delaunay triangulation (an exact\n"
    "kernel; for george with --exact-sphere and without --enclosing-box) ends any line but ok and\n"
    "lower-dimensional with '; a bug: the pair is exact'. The exact validator judges every result\n"
    "the pair does not promise (and, with --validate, every result). Points the integer kernel\n"
    "moves: 'dlab CMD: snapped: M of N points moved to the integer kernel's grid, K merged,\n"
    "largest displacement X' (exit status unchanged).\n";

io::StatsRecord stats_record(const RunOptions& options, std::size_t input_points,
                             const RunResult& result, const Outcome& o, std::uint64_t peak_rss) {
  io::StatsRecord rec;
  rec.options = options;
  rec.input_points = input_points;
  rec.result = &result;
  rec.outcome = std::string(outcome_name(o.kind));
  rec.message = o.kind == OutcomeClass::ok ? result.message : o.detail;
  rec.validated = o.validated;
  rec.peak_rss_bytes = peak_rss;
  return rec;
}

}  // namespace dlab::cli
