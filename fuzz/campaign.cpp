// See campaign.hpp.
#include "fuzz/campaign.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>

#include "fuzz/case_runner.hpp"
#include "fuzz/failures.hpp"
#include "fuzz/fuzz_outcome.hpp"
#include "fuzz/progress.hpp"
#include "fuzz/scheduler.hpp"
#include "fuzz/selftest.hpp"
#include "fuzz/summary.hpp"

namespace dlab::fuzz {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

std::string results_path(const std::string& dir) { return (fs::path(dir) / "results.jsonl").string(); }
std::string campaign_path(const std::string& dir) { return (fs::path(dir) / "campaign.json").string(); }

// Creates DIR if needed and checks that it holds this campaign or none.
void prepare_directory(const CampaignOptions& o, std::ostream& err) {
  std::error_code ec;
  fs::create_directories(o.dir, ec);
  if (ec || !fs::is_directory(o.dir))
    throw UsageError("cannot use '" + o.dir + "' as the campaign directory" + (ec ? ": " + ec.message() : ""));
  if (access(o.dir.c_str(), R_OK | W_OK | X_OK) != 0)
    throw UsageError("cannot read and write '" + o.dir + "': " + std::strerror(errno));
  const bool has_campaign = fs::exists(campaign_path(o.dir));
  if (has_campaign) {
    const StoredCampaign there = read_campaign_json(campaign_path(o.dir));
    const std::string d = campaign_difference(there, o.campaign, false);
    if (!d.empty()) throw UsageError("'" + o.dir + "' holds another campaign (" + d + ")");
  } else if (fs::exists(results_path(o.dir))) {
    throw UsageError("'" + results_path(o.dir) + "' exists without campaign.json: not a campaign directory");
  }
  if (!o.campaign.spec.selftest.empty())
    err << "dlab fuzz: " << kSelftestVariable << "=" << o.campaign.spec.selftest
        << " is set: deliberate failures are injected (a test of isolation, not a campaign)\n";
  write_text_file(campaign_path(o.dir), campaign_json(o.campaign));
}

Work make_work(const CampaignOptions& o) {
  Work w;
  w.spec = o.campaign.spec;
  w.pairs = w.spec.pairs();
  w.selftest = parse_selftest(w.spec.selftest);
  w.limits = o.campaign.limits;
  w.timing = o.timing;
  return w;
}

void append_all(int fd, const std::string& s, const std::string& path) {
  std::size_t done = 0;
  while (done < s.size()) {
    const ssize_t w = ::write(fd, s.data() + done, s.size() - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) throw UsageError("error writing '" + path + "': " + std::strerror(errno));
    done += static_cast<std::size_t>(w);
  }
}

}  // namespace

int run_campaign(const CampaignOptions& o, std::ostream& out, std::ostream& err) {
  prepare_directory(o, err);
  const Work work = make_work(o);
  const std::string results = results_path(o.dir);
  const ResultsScan scan = scan_results(results, work.spec, work.pairs.size());
  if (fs::exists(results)) {
    std::error_code ec;
    fs::resize_file(results, scan.bytes, ec);
    if (ec) throw UsageError("cannot truncate '" + results + "': " + ec.message());
    if (scan.cases > 0 || scan.dropped_lines > 0)
      err << "dlab fuzz: resuming after " << scan.cases << " complete cases"
          << (scan.dropped_lines ? " (" + std::to_string(scan.dropped_lines) +
                                       " lines of an interrupted case dropped, to be redone)"
                                 : std::string())
          << "\n";
  }
  const int fd = ::open(results.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) throw UsageError("cannot write '" + results + "': " + std::strerror(errno));

  Schedule s;
  s.jobs = o.jobs;
  s.start = scan.cases;
  s.end = o.campaign.cases ? work.spec.cases_in_shard(*o.campaign.cases) : UINT64_MAX;
  if (o.budget_seconds)
    s.deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(*o.budget_seconds));
  s.wall_seconds = 10 * o.campaign.limits.cpu_seconds + 10;
  const std::optional<std::uint64_t> to_run =
      o.campaign.cases ? std::optional(s.end - std::min(s.end, s.start)) : std::nullopt;
  Progress progress(to_run, s.deadline);
  std::uint64_t done = 0, failures = 0;
  const auto t0 = Clock::now();
  try {
    run_schedule(
        work, s,
        [&](const CaseDone& c) {
          append_all(fd, c.lines, results);
          ++done;
          failures += c.failures;
        },
        [&] { progress.update(done, failures); });
  } catch (const UsageError&) {
    ::close(fd);
    progress.finish();
    throw;
  } catch (const std::exception& e) {  // a generator that refused a case, a broken child
    ::close(fd);
    progress.finish();
    throw UsageError(e.what());
  }
  ::close(fd);
  progress.finish();
  const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  const int status = finish_campaign(o.dir, work.spec, out);
  err << "dlab fuzz: " << done << " cases (" << done * work.pairs.size() << " case x pairs) run in " << seconds
      << " s with " << o.jobs << " job" << (o.jobs == 1 ? "" : "s") << "\n";
  return status;
}

int run_one_case(const CampaignOptions& o, std::uint64_t i, std::ostream& out, std::ostream& err) {
  const CampaignSpec& spec = o.campaign.spec;
  const PreparedCase c = prepare_case(spec, i);
  CaseRunner runner(c);
  int status = 0;
  for (const Pair& p : spec.pairs()) {
    const PairRecord r = runner.run(p, o.timing);
    out << to_json_line(r) << "\n";
    err << "# " << r.algo << " x " << r.kernel << ": " << r.outcome << "; replay: " << replay_command(c.plan, p)
        << "\n";
    if (r.exact && is_failure(r.outcome)) status = 1;
  }
  return status;
}

int finish_campaign(const std::string& dir, const CampaignSpec& spec, std::ostream& out) {
  Summary summary(spec);
  FailureIndex failures;
  for_each_record(results_path(dir), [&](const PairRecord& r) {
    summary.add(r);
    failures.add(r);
  });
  const std::string table = summary.table();
  write_text_file((fs::path(dir) / "summary.txt").string(), table);
  // The limits stored in DIR/campaign.json, so that a run and a merge of its
  // shards shrink under the same ones (the file keeps --timeout in whole seconds).
  failures.write(dir, spec, read_campaign_json((fs::path(dir) / "campaign.json").string()).limits);
  out << table;
  out.flush();
  return summary.exact_failures() > 0 ? 1 : 0;
}

}  // namespace dlab::fuzz
