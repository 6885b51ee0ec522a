// What `dlab triangulate` and `dlab flip` say on stderr about a run: the one
// line of its outcome class (variants/outcome.hpp) and what snapping did.
#pragma once
#include <cstdint>
#include <string_view>

#include "cli/stats_json.hpp"
#include "variants/outcome.hpp"
#include "variants/run.hpp"

namespace dlab::cli {

// "dlab COMMAND: snapped: M of N points moved to the integer kernel's grid, K
// merged, largest displacement X" when the integer kernel moved or merged a point.
void announce_snapping(std::string_view command, const RunResult& r);

// The outcome's one stderr line (variants/outcome.hpp); nothing for ok.
void print_outcome(std::string_view command, const Outcome& o, std::string_view pair);

// The --stats record of a run and its outcome (the outcome's detail as the
// message unless ok).
io::StatsRecord stats_record(const RunOptions& options, std::size_t input_points,
                             const RunResult& result, const Outcome& o, std::uint64_t peak_rss);

// The table class -> exit status -> stderr line, for `dlab --help`,
// `dlab triangulate --help` and `dlab flip --help` (README.md has the same).
extern const char* const kOutcomeHelp;

}  // namespace dlab::cli
