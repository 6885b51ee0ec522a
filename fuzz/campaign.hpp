// `dlab fuzz`: run or resume a campaign into DIR (fuzz/campaign_files.hpp),
// re-run one case alone, and the summary and failure files of a directory.
#pragma once
#include <cstdint>
#include <optional>
#include <ostream>
#include <string>

#include "fuzz/campaign_files.hpp"

namespace dlab::fuzz {

struct CampaignOptions {
  StoredCampaign campaign;
  std::optional<double> budget_seconds;  // instead of campaign.cases
  unsigned jobs = 1;
  bool timing = true;  // false: every record's seconds is 0, so runs compare byte for byte
  std::string dir;
};

// Runs the campaign, resuming from DIR/results.jsonl; prints the summary to
// `out`. Returns 1 if an exact pair failed in any case of DIR, else 0. Throws
// UsageError (exit 2) for a directory it cannot use or that holds another
// campaign.
int run_campaign(const CampaignOptions& o, std::ostream& out, std::ostream& err);

// Case `i` of the campaign in this process, without isolation (for a
// debugger): its records to `out` (the lines results.jsonl has), the commands
// that replay each pair to `err`. Returns 1 if an exact pair failed.
int run_one_case(const CampaignOptions& o, std::uint64_t i, std::ostream& out, std::ostream& err);

// Reads DIR/results.jsonl: prints the summary to `out` and writes it to
// DIR/summary.txt, writes DIR/failures/ for new signatures. Returns 1 if an
// exact pair failed, else 0.
int finish_campaign(const std::string& dir, const CampaignSpec& spec, std::ostream& out);

}  // namespace dlab::fuzz
