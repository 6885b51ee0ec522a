// `dlab fuzz` (design.md section 5.1, issue 12): classified robustness
// campaigns, and `dlab fuzz merge` for their shards. The work is in fuzz/
// (campaign.hpp is the entry point); this file parses the command line.
#include <cstdlib>
#include <iostream>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/merge.hpp"
#include "fuzz/selftest.hpp"

namespace dlab::cli {
namespace {

const char* const kFuzzSynopsis =
    "usage: dlab fuzz --out DIR (--cases C | --budget T) [--algo LIST] [--kernel LIST] [--gen LIST]\n"
    "                 [--dim 2|3] [--n N|LO..HI] [--seed S] [--jobs J] [--shard k/n]\n"
    "                 [--timeout SEC] [--memory MIB] [--no-timing]\n"
    "       dlab fuzz [same options] --case I        re-run case I alone, in this process\n"
    "       dlab fuzz merge DIR... --out DIR         shards -> exactly the unsharded result\n";

const char* const kFuzzDescription =
    "Runs C cases (or as many as fit in the budget T: 90, 90s, 15m, 2h). Case i draws its\n"
    "generator (from --gen), n (uniform in LO..HI) and the generator's options from its own seed,\n"
    "splitmix64(S)'s (i+1)-th output, and runs every pair of --algo x --kernel on those points.\n"
    "Each case x pair is classified: ok, lower-dimensional, not-delaunay, invalid, reported,\n"
    "differs (an exact pair whose valid Delaunay result is not the perturbed, CGAL-identical one),\n"
    "crash, timeout, out-of-memory. Cases run in child processes under the limits, in batches; a\n"
    "batch whose child dies is continued, the culprit re-run alone to name it.\n"
    "Writes DIR/campaign.json, DIR/results.jsonl (one JSON line per case x pair), DIR/summary.txt\n"
    "(also printed: failure rate per algorithm x kernel x generator with a 95% Wilson interval) and\n"
    "DIR/failures/ (one point file per new failure signature, shrunk as dlab shrink does, at most\n"
    "400 tests each, 12 for timeout and out-of-memory; with the commands that replay it).\n"
    "An interrupted campaign resumes where it stopped when run again with the same options.\n";

const char* const kFuzzExamples =
    "  dlab fuzz --algo lawson,bowyer-watson --kernel float,adaptive --gen degenerate --cases 500 --out c1\n"
    "  dlab fuzz --dim 3 --n 10..40 --budget 15m --jobs 2 --out c3\n"
    "  dlab fuzz --gen mix --cases 300 --shard 1/3 --out s1   # and 2/3, 3/3, then:\n"
    "  dlab fuzz merge s1 s2 s3 --out merged\n";

const char* const kFuzzEpilogue =
    "Exit status: 0; 1 if an exact pair (adaptive, integer, mp; George only with his exact sphere)\n"
    "gave anything but ok or lower-dimensional; 2 bad usage or an unusable DIR.\n";

int fuzz_merge(int argc, char** argv) {
  std::vector<std::string> dirs;
  std::string out;
  CommandLine cl("fuzz", kFuzzSynopsis, kFuzzDescription, kFuzzExamples, kFuzzEpilogue);
  cl.app().add_option("DIR", dirs, "the n shard directories of one campaign");
  cl.app().add_option("--out", out, "the merged campaign's directory")->required();
  if (auto rc = cl.parse(argc, argv, 3)) return *rc;
  if (dirs.empty()) return cl.usage_error("no shard directories given");
  try {
    return fuzz::merge_campaigns(dirs, out, std::cout);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace

int cmd_fuzz(int argc, char** argv) {
  if (argc >= 3 && std::string(argv[2]) == "merge") return fuzz_merge(argc, argv);
  std::string algos = "bowyer-watson", kernels = "adaptive", gens = "mix", n_range = "20", shard, timeout,
              budget, out;
  std::uint64_t seed = 0, memory_mib = 4096, cases = 0, case_index = 0;
  int dim = 2;
  unsigned jobs = 1;
  bool no_timing = false;
  CommandLine cl("fuzz", kFuzzSynopsis, kFuzzDescription, kFuzzExamples, kFuzzEpilogue);
  CLI::App& app = cl.app();
  app.add_option("--out", out, "the campaign's directory")->type_name("DIR");
  add_unsigned(app, "--cases", cases, std::uint64_t{1} << 48, "number of cases")->type_name("C")->default_str("");
  app.add_option("--budget", budget, "run cases until this much time has passed: 90, 90s, 15m, 2h")
      ->type_name("T");
  app.add_option("--algo", algos,
                 "bowyer-watson, lawson, tanemura, george, george+exact-sphere, george+enclosing-box\n"
                 "(comma-separated)")
      ->type_name("LIST")->capture_default_str();
  app.add_option("--kernel", kernels, "adaptive, integer, mp, float, epsilon (comma-separated)")
      ->type_name("LIST")->capture_default_str();
  app.add_option("--gen", gens,
                 "dlab gen generators; mix: every generator of the dimension; degenerate: all but\n"
                 "uniform, gaussian, clustered, huge and tiny")
      ->type_name("LIST")->capture_default_str();
  add_integer(app, "--dim", dim, 2, 3, "dimension")->type_name("2|3");
  app.add_option("--n", n_range, "points per case: N, or uniform in LO..HI")->type_name("N|LO..HI")->capture_default_str();
  add_unsigned(app, "--seed", seed, UINT64_MAX, "the campaign's seed")->type_name("S");
  add_integer(app, "--jobs", jobs, 1, 256, "child processes at a time")->type_name("J");
  app.add_option("--shard", shard, "run only the cases i with i mod n = k - 1 (merge the n directories after)")
      ->type_name("k/n");
  app.add_option("--timeout", timeout, "CPU time per case x pair (default 10)")->type_name("SEC");
  add_unsigned(app, "--memory", memory_mib, std::uint64_t{1} << 24, "memory per child")->type_name("MIB");
  app.add_flag("--no-timing", no_timing,
               "write every record's seconds as 0 (runs and merges then compare byte for byte)");
  add_unsigned(app, "--case", case_index, UINT64_MAX, "re-run case I alone, in this process")
      ->type_name("I")->default_str("");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  try {
    fuzz::CampaignOptions o;
    fuzz::CampaignSpec& spec = o.campaign.spec;
    spec.algorithms = fuzz::parse_list("--algo", algos);
    spec.kernels = fuzz::parse_list("--kernel", kernels);
    spec.generators = fuzz::parse_list("--gen", gens);
    spec.dim = dim;
    fuzz::parse_n_range(n_range, spec.n_lo, spec.n_hi);
    spec.seed = seed;
    if (!shard.empty()) fuzz::parse_shard(shard, spec.shard, spec.shards);
    if (const char* st = std::getenv(fuzz::kSelftestVariable)) spec.selftest = st;
    fuzz::parse_selftest(spec.selftest);  // a malformed spec is a usage error
    fuzz::check_and_expand(spec);
    o.campaign.limits.cpu_seconds = timeout.empty() ? 10 : fuzz::parse_duration("--timeout", timeout);
    o.campaign.limits.memory_bytes = memory_mib << 20;
    if (o.campaign.limits.memory_bytes == 0) throw UsageError("--memory must be at least 1 (MiB)");
    o.jobs = jobs;
    o.timing = !no_timing;

    if (app.count("--case")) return fuzz::run_one_case(o, case_index, std::cout, std::cerr);

    const bool by_cases = app.count("--cases") > 0, by_budget = app.count("--budget") > 0;
    if (by_cases && by_budget) throw UsageError("--cases and --budget exclude each other");
    if (by_cases)
      o.campaign.cases = cases;
    else if (by_budget)
      o.budget_seconds = fuzz::parse_duration("--budget", budget);
    else
      throw UsageError("give --cases C or --budget T");
    if (out.empty()) throw UsageError("missing --out DIR");
    o.dir = out;
    return fuzz::run_campaign(o, std::cout, std::cerr);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace dlab::cli
