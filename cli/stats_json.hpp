// The --stats JSON object of `dlab triangulate` and `dlab flip` (design.md
// section 5). Keys in this fixed order: algorithm, kernel, policy, order,
// location (walk or scan; none for dlab flip), seed,
// dimension, input_points, distinct_points, inserted_points (input points
// processed before the run stopped: variants/run.hpp), simplices, seconds
// (wall) and cpu_seconds (the thread's CPU time: steadier on a loaded machine)
// of the triangulation alone, peak_rss_bytes (before validation), predicates, counters, snapping, outcome
// (the class of variants/outcome.hpp: ok, lower-dimensional, not-delaunay,
// invalid, reported), validated (whether the exact validator judged the
// result), message (the outcome's detail). Everything but `seconds`,
// `cpu_seconds` and `peak_rss_bytes` is a function of the input, the options
// and the seed, so the file is byte-identical across runs apart from those.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

#include "variants/run.hpp"

namespace dlab::io {

struct StatsRecord {
  RunOptions options;
  std::size_t input_points = 0;
  const RunResult* result = nullptr;
  std::string outcome;   // "ok", "lower-dimensional", "not-delaunay", "invalid", "reported"
  bool validated = false;
  std::string message;
  std::uint64_t peak_rss_bytes = 0;
};

void write_stats_json(std::ostream& out, const StatsRecord& r);

// JSON string literal (nlohmann's escapes; invalid UTF-8 replaced by U+FFFD).
std::string json_string(std::string_view s);

// Peak resident set size of this process (getrusage ru_maxrss, KiB -> bytes).
std::uint64_t peak_rss_bytes();

}  // namespace dlab::io
