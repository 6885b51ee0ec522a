// The files of a campaign directory DIR:
//   DIR/campaign.json   what the campaign is (fuzz/campaign_spec.hpp), its
//                       limits and its target number of cases; a resumed or
//                       merged campaign must match it
//   DIR/results.jsonl   one record per case x pair (fuzz/record.hpp), whole
//                       cases in the shard's case order
//   DIR/summary.txt     the summary table (fuzz/summary.hpp), as printed
//   DIR/failures/       one point file per failure signature (fuzz/failures.hpp)
#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/isolation.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {

struct StoredCampaign {
  CampaignSpec spec;
  Limits limits;
  std::optional<std::uint64_t> cases;  // --cases; none for --budget
};

// One JSON object, keys in a fixed order, ending '\n'.
std::string campaign_json(const StoredCampaign& c);
// Throws UsageError naming the file for an unreadable or malformed file.
StoredCampaign read_campaign_json(const std::string& path);
// What differs between two campaigns ("--seed: 7 there, 8 here"), ignoring
// the number of cases and, if asked, the shard; empty when they match.
std::string campaign_difference(const StoredCampaign& there, const StoredCampaign& here, bool ignore_shard);

// The complete cases at the start of a results.jsonl (each a group of
// `pairs` lines of case spec.case_index(j) for j = 0, 1, ...), and the bytes
// they take. A last line without its newline (torn by an interruption) and the
// lines of an incomplete last case are not counted: the campaign truncates the
// file there and redoes that case. Any other irregularity throws UsageError
// naming the file and line.
struct ResultsScan {
  std::uint64_t cases = 0;
  std::uint64_t bytes = 0;
  std::uint64_t dropped_lines = 0;  // torn or incomplete, to be redone
};
ResultsScan scan_results(const std::string& path, const CampaignSpec& spec, std::size_t pairs);

// Calls f for each record of a results file (every line must be complete and
// well formed); throws UsageError "PATH:LINE: what" otherwise.
void for_each_record(const std::string& path, const std::function<void(const PairRecord&)>& f);

// Writes `text` to `path` (replacing it); throws UsageError if it cannot.
void write_text_file(const std::string& path, const std::string& text);

}  // namespace dlab::fuzz
