// See merge.hpp.
#include "fuzz/merge.hpp"

#include <filesystem>
#include <fstream>
#include <memory>

#include "fuzz/campaign.hpp"
#include "fuzz/campaign_files.hpp"

namespace dlab::fuzz {
namespace {

namespace fs = std::filesystem;

struct Shard {
  std::string dir;
  StoredCampaign campaign;
  std::uint64_t cases = 0;  // complete cases in its results
  std::unique_ptr<std::ifstream> in;
  std::uint64_t taken = 0;
};

}  // namespace

int merge_campaigns(const std::vector<std::string>& dirs, const std::string& out_dir, std::ostream& out) {
  if (dirs.empty()) throw UsageError("merge: no shard directories given");
  std::vector<Shard> shards;
  for (const auto& d : dirs) {
    Shard s;
    s.dir = d;
    s.campaign = read_campaign_json((fs::path(d) / "campaign.json").string());
    shards.push_back(std::move(s));
  }
  const StoredCampaign& first = shards.front().campaign;
  const std::uint64_t n = first.spec.shards;
  std::vector<Shard*> by_number(n, nullptr);
  for (auto& s : shards) {
    const std::string d = campaign_difference(first, s.campaign, true);
    if (!d.empty()) throw UsageError("merge: '" + s.dir + "' is another campaign than '" + shards[0].dir + "' (" + d + ")");
    if (s.campaign.spec.shards != n)
      throw UsageError("merge: '" + s.dir + "' is shard " + std::to_string(s.campaign.spec.shard) + "/" +
                       std::to_string(s.campaign.spec.shards) + ", not one of " + std::to_string(n));
    if (s.campaign.cases != first.cases)
      throw UsageError("merge: '" + s.dir + "' ran another number of cases than '" + shards[0].dir + "'");
    Shard*& slot = by_number[s.campaign.spec.shard - 1];
    if (slot) throw UsageError("merge: shard " + std::to_string(s.campaign.spec.shard) + " given twice ('" +
                               slot->dir + "', '" + s.dir + "')");
    slot = &s;
  }
  for (std::uint64_t k = 0; k < n; ++k)
    if (!by_number[k]) throw UsageError("merge: shard " + std::to_string(k + 1) + "/" + std::to_string(n) + " is missing");

  const std::size_t P = first.spec.algorithms.size() * first.spec.kernels.size();
  for (auto& s : shards) {
    const std::string path = (fs::path(s.dir) / "results.jsonl").string();
    const ResultsScan scan = scan_results(path, s.campaign.spec, P);
    if (scan.dropped_lines > 0)
      throw UsageError("merge: '" + s.dir + "' was interrupted in a case: resume it first");
    if (s.campaign.cases && scan.cases != s.campaign.spec.cases_in_shard(*s.campaign.cases))
      throw UsageError("merge: '" + s.dir + "' has " + std::to_string(scan.cases) + " of its " +
                       std::to_string(s.campaign.spec.cases_in_shard(*s.campaign.cases)) +
                       " cases: finish it first");
    s.cases = scan.cases;
    s.in = std::make_unique<std::ifstream>(path, std::ios::binary);
  }

  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec || !fs::is_directory(out_dir)) throw UsageError("merge: cannot create '" + out_dir + "'");
  const std::string results = (fs::path(out_dir) / "results.jsonl").string();
  if (fs::exists(results) || fs::exists(fs::path(out_dir) / "campaign.json"))
    throw UsageError("merge: '" + out_dir + "' already holds a campaign");
  StoredCampaign merged = first;
  merged.spec.shard = merged.spec.shards = 1;
  write_text_file((fs::path(out_dir) / "campaign.json").string(), campaign_json(merged));

  std::ofstream res(results, std::ios::binary);
  if (!res) throw UsageError("merge: cannot write '" + results + "'");
  std::string line;
  for (bool any = true; any;) {  // pass j writes cases j n + k - 1, k = 1..n: round robin
    any = false;
    for (Shard* s : by_number) {
      if (s->taken == s->cases) continue;
      any = true;
      for (std::size_t p = 0; p < P; ++p) {
        std::getline(*s->in, line);
        res << line << '\n';
      }
      ++s->taken;
    }
  }
  if (!res.flush()) throw UsageError("merge: error writing '" + results + "'");
  res.close();
  return finish_campaign(out_dir, merged.spec, out);
}

}  // namespace dlab::fuzz
