// `dlab study CONFIG.json --out DIR [--shard k/n] [--jobs J]`, `dlab study
// --default --out DIR ...` and `dlab study merge DIR... --out DIR`: option
// parsing only; the work is studies/study.hpp's (contract: studies/README.md).
#include <iostream>
#include <string_view>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "dlab_version.hpp"
#include "default_study.hpp"
#include "studies/study.hpp"

namespace dlab::cli {
namespace {

const char* const kStudyHelp =
    "usage: dlab study CONFIG.json --out DIR [--shard k/n] [--jobs J]\n"
    "       dlab study --default --out DIR [--shard k/n] [--jobs J]\n"
    "       dlab study merge DIR... --out DIR\n"
    "Runs the matrix a JSON config names (algorithms x kernels x orders x policies x locations x\n"
    "inputs x repeats, plus external baselines; studies/README.md) and writes DIR/runs.csv, one\n"
    "row per run, and DIR/meta.json (the config, git commit, compiler and flags, CPU, date).\n"
    "Each run is a child process: a crash, timeout or memory exhaustion is the run's outcome.\n"
    "Measured: wall and CPU seconds of the triangulation alone, peak resident size, the --stats\n"
    "counters; every result is judged by the exact validator.\n"
    "  --default    the built-in matrix (studies/configs/default.json: n <= 10^4, 2D and 3D)\n"
    "  --jobs J     runs at a time (default 1; more than the cores disturbs the timings)\n"
    "  --shard k/n  only the runs whose id mod n is k-1; `dlab study merge` joins the n shards\n"
    "               into exactly the unsharded runs.csv (measured columns aside)\n"
    "Rerunning with the same --out and config resumes: finished rows are kept. A progress line\n"
    "shows on a terminal. Exit status: 0; 1 if an exact pair failed; 2 bad config or usage.\n";

study::BuildInfo this_build() {
  study::BuildInfo b;
  b.version = build_info::kVersion;
  b.commit = build_info::kCommit;
  b.commit_dirty = build_info::kCommitDirty;
  b.compiler = build_info::kCompiler;
  b.build_type = build_info::kBuildType;
  b.flags = build_info::kCxxFlags;
  return b;
}

}  // namespace

int cmd_study(int argc, char** argv) {
  const bool merge = argc > 2 && std::string_view(argv[2]) == "merge";
  try {
    const Args a = parse_args(argc, argv, merge ? 3 : 2, {"--out", "--shard", "--jobs"}, {"--default", "--help"});
    if (a.has("--help")) {
      std::cout << kStudyHelp;
      return 0;
    }
    const auto out = a.get("--out");
    if (!out) throw UsageError("missing --out DIR");
    if (merge) {
      if (a.get("--shard") || a.get("--jobs") || a.has("--default"))
        throw UsageError("study merge takes shard directories and --out only");
      return study::merge_studies(a.positional, *out, this_build(), std::cout, std::cerr);
    }
    study::StudyOptions o;
    if (a.has("--default")) {
      if (!a.positional.empty()) throw UsageError("--default and a CONFIG exclude each other");
      o.config = study::parse_config(study::kDefaultStudyJson, "<default>");
    } else {
      if (a.positional.size() != 1)
        throw UsageError(a.positional.empty() ? "missing CONFIG.json (or --default)"
                                              : "unexpected argument '" + a.positional[1] + "'");
      o.config = study::read_config(a.positional[0]);
    }
    o.dir = *out;
    o.jobs = static_cast<unsigned>(a.u64("--jobs", 1, 1024));
    if (o.jobs == 0) throw UsageError("--jobs must be at least 1");
    if (auto s = a.get("--shard")) o.shard = study::parse_shard(*s);
    o.build = this_build();
    return study::run_study(std::move(o), std::cout, std::cerr);
  } catch (const UsageError& e) {
    std::cerr << "dlab study: " << e.what() << " (dlab study --help)\n";
    return 2;
  } catch (const study::ConfigError& e) {
    std::cerr << "dlab study: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
