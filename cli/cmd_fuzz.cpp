// `dlab fuzz` (design.md section 5.1, issue 12): classified robustness
// campaigns, and `dlab fuzz merge` for their shards. The work is in fuzz/
// (campaign.hpp is the entry point); this file parses the command line.
#include <cstdlib>
#include <iostream>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "fuzz/campaign.hpp"
#include "fuzz/merge.hpp"
#include "fuzz/selftest.hpp"

namespace dlab::cli {
namespace {

const char* const kFuzzHelp =
    "usage: dlab fuzz --out DIR (--cases C | --budget T) [--algo LIST] [--kernel LIST] [--gen LIST]\n"
    "                 [--dim 2|3] [--n N|LO..HI] [--seed S] [--jobs J] [--shard k/n]\n"
    "                 [--timeout SEC] [--memory MIB] [--no-timing]\n"
    "       dlab fuzz [same options] --case I        re-run case I alone, in this process\n"
    "       dlab fuzz merge DIR... --out DIR         shards -> exactly the unsharded result\n"
    "Runs C cases (or as many as fit in the budget T: 90, 90s, 15m, 2h). Case i draws its\n"
    "generator (from --gen), n (uniform in LO..HI) and the generator's options from its own seed,\n"
    "splitmix64(S)'s (i+1)-th output, and runs every pair of --algo x --kernel on those points.\n"
    "  --algo LIST    bowyer-watson (default), lawson, tanemura, george, george+exact-sphere,\n"
    "                 george+enclosing-box (comma-separated)\n"
    "  --kernel LIST  adaptive (default), integer, mp, float, epsilon\n"
    "  --gen LIST     dlab gen generators; mix (default): every generator of the dimension;\n"
    "                 degenerate: all but uniform, gaussian, clustered, huge and tiny\n"
    "  --dim 2|3 (2)  --n (20)  --seed (0)  --jobs: child processes at a time (1)\n"
    "  --shard k/n    run only the cases i with i mod n = k - 1 (merge the n directories after)\n"
    "  --timeout SEC  CPU time per case x pair (10); --memory MIB: memory per child (4096)\n"
    "  --no-timing    write every record's seconds as 0 (runs and merges then compare byte for byte)\n"
    "Each case x pair is classified: ok, lower-dimensional, not-delaunay, invalid, reported,\n"
    "differs (an exact pair whose valid Delaunay result is not the perturbed, CGAL-identical one),\n"
    "crash, timeout, out-of-memory. Cases run in child processes under the limits, in batches; a\n"
    "batch whose child dies is continued, the culprit re-run alone to name it.\n"
    "Writes DIR/campaign.json, DIR/results.jsonl (one JSON line per case x pair), DIR/summary.txt\n"
    "(also printed: failure rate per algorithm x kernel x generator with a 95% Wilson interval) and\n"
    "DIR/failures/ (one point file per new failure signature, shrunk as dlab shrink does, at most\n"
    "400 tests each, 12 for timeout and out-of-memory; with the commands that replay it).\n"
    "An interrupted campaign resumes where it stopped when run again with the same options.\n"
    "Exit status: 0; 1 if an exact pair (adaptive, integer, mp; George only with his exact sphere)\n"
    "gave anything but ok or lower-dimensional; 2 bad usage or an unusable DIR.\n";

int fuzz_merge(int argc, char** argv) {
  const Args a = parse_args(argc, argv, 3, {"--out"}, {"--help"});
  if (a.has("--help")) {
    std::cout << kFuzzHelp;
    return 0;
  }
  const auto out = a.get("--out");
  if (!out) throw UsageError("merge: missing --out DIR");
  if (a.positional.empty()) throw UsageError("merge: no shard directories given");
  return fuzz::merge_campaigns(a.positional, *out, std::cout);
}

}  // namespace

int cmd_fuzz(int argc, char** argv) {
  try {
    if (argc >= 3 && std::string(argv[2]) == "merge") return fuzz_merge(argc, argv);
    const Args a = parse_args(argc, argv, 2,
                              {"--algo", "--kernel", "--gen", "--dim", "--n", "--seed", "--cases", "--budget",
                               "--jobs", "--shard", "--out", "--timeout", "--memory", "--case"},
                              {"--no-timing", "--help"});
    if (a.has("--help")) {
      std::cout << kFuzzHelp;
      return 0;
    }
    if (!a.positional.empty()) throw UsageError("unexpected argument '" + a.positional[0] + "'");
    fuzz::CampaignOptions o;
    fuzz::CampaignSpec& spec = o.campaign.spec;
    spec.algorithms = fuzz::parse_list("--algo", a.get("--algo").value_or("bowyer-watson"));
    spec.kernels = fuzz::parse_list("--kernel", a.get("--kernel").value_or("adaptive"));
    spec.generators = fuzz::parse_list("--gen", a.get("--gen").value_or("mix"));
    spec.dim = static_cast<int>(a.i64("--dim", 2, 2, 3));
    fuzz::parse_n_range(a.get("--n").value_or("20"), spec.n_lo, spec.n_hi);
    spec.seed = a.u64("--seed", 0);
    if (auto s = a.get("--shard")) fuzz::parse_shard(*s, spec.shard, spec.shards);
    if (const char* st = std::getenv(fuzz::kSelftestVariable)) spec.selftest = st;
    fuzz::parse_selftest(spec.selftest);  // a malformed spec is a usage error
    fuzz::check_and_expand(spec);
    o.campaign.limits.cpu_seconds = a.get("--timeout") ? fuzz::parse_duration("--timeout", *a.get("--timeout")) : 10;
    o.campaign.limits.memory_bytes = a.u64("--memory", 4096, std::uint64_t{1} << 24) << 20;
    if (o.campaign.limits.memory_bytes == 0) throw UsageError("--memory must be at least 1 (MiB)");
    o.jobs = static_cast<unsigned>(a.i64("--jobs", 1, 1, 256));
    o.timing = !a.has("--no-timing");

    if (a.get("--case")) return fuzz::run_one_case(o, a.u64("--case", 0), std::cout, std::cerr);

    if (a.get("--cases") && a.get("--budget")) throw UsageError("--cases and --budget exclude each other");
    if (a.get("--cases"))
      o.campaign.cases = a.u64("--cases", 0, std::uint64_t{1} << 48);
    else if (a.get("--budget"))
      o.budget_seconds = fuzz::parse_duration("--budget", *a.get("--budget"));
    else
      throw UsageError("give --cases C or --budget T");
    const auto out = a.get("--out");
    if (!out) throw UsageError("missing --out DIR");
    o.dir = *out;
    return fuzz::run_campaign(o, std::cout, std::cerr);
  } catch (const UsageError& e) {
    std::cerr << "dlab fuzz: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
