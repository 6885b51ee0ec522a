// The columns of runs.csv (studies/README.md "runs.csv"): a fixed header, the
// same for every study, so that rows of different studies line up.
//
// The pred.* and ctr.* columns are fixed lists: every predicate counter
// (predicates/counted.hpp names: "<pred>" and "<pred>.<stage>") and every
// algorithm counter (TriangulationResult::counters of the four algorithms,
// George's variants included) that any algorithm x kernel x policy emits.
// tests/test_study_columns.cpp runs every combination in 2D and 3D and fails
// when one emits a name missing here; a run that emits one anyway gets a
// warning on stderr and the value is dropped (columns never move).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "variants/run.hpp"

namespace dlab::study {

const std::vector<std::string>& predicate_counter_names();
const std::vector<std::string>& algorithm_counter_names();

// The columns before pred.*: run ... peak_rss_bytes.
const std::vector<std::string>& leading_columns();
// The measured columns (left out when comparing studies): wall_seconds, cpu_seconds, peak_rss_bytes.
const std::vector<std::string>& measured_columns();
// The whole header line, without the newline.
std::string csv_header();
std::size_t column_count();

// What one run measured (everything after the run's description).
struct RunMeasure {
  std::optional<std::uint64_t> input_points, distinct_points, simplices;
  std::string outcome;
  std::string message;
  std::optional<double> wall_seconds, cpu_seconds;
  std::optional<std::uint64_t> peak_rss_bytes;
  Counters predicates, counters;
};

struct RunSpec;
struct StudyConfig;

// One CSV row (no newline). Counter names outside the fixed lists are passed
// to `unknown` (once per name is the caller's business) and dropped.
std::string csv_row(const StudyConfig& config, const RunSpec& spec, const RunMeasure& m,
                    std::vector<std::string>* unknown = nullptr);

// RFC 4180: quoted when it holds a comma, a quote or a line break.
std::string csv_field(std::string_view s);
// Splits one line (no newline) into fields; throws std::invalid_argument on a malformed quote.
std::vector<std::string> csv_split(std::string_view line);

}  // namespace dlab::study
