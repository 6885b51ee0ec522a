// `dlab study CONFIG.json --out DIR [--shard k/n] [--jobs J]`, `dlab study
// --default --out DIR ...` and `dlab study merge DIR... --out DIR`: option
// parsing only; the work is studies/study.hpp's (contract: studies/README.md).
#include <iostream>
#include <string_view>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "dlab_version.hpp"
#include "default_study.hpp"
#include "studies/study.hpp"

namespace dlab::cli {
namespace {

const char* const kStudySynopsis =
    "usage: dlab study CONFIG.json --out DIR [--shard k/n] [--jobs J]\n"
    "       dlab study --default --out DIR [--shard k/n] [--jobs J]\n"
    "       dlab study merge DIR... --out DIR\n";

const char* const kStudyDescription =
    "Runs the matrix a JSON config names (algorithms x kernels x orders x policies x locations x\n"
    "inputs x repeats, plus external baselines; studies/README.md) and writes DIR/runs.csv, one\n"
    "row per run, and DIR/meta.json (the config, git commit, compiler and flags, CPU, date).\n"
    "Each run is a child process: a crash, timeout or memory exhaustion is the run's outcome.\n"
    "Measured: wall and CPU seconds of the triangulation alone, peak resident size, the --stats\n"
    "counters; every result is judged by the exact validator. Rerunning with the same --out and\n"
    "config resumes: finished rows are kept. A progress line shows on a terminal.\n"
    "merge joins the n shards of one study into exactly the unsharded runs.csv (measured columns\n"
    "aside).\n";

const char* const kStudyExamples =
    "  dlab study --default --out s1 --jobs 2\n"
    "  dlab study studies/configs/default.json --out part1 --shard 1/2\n"
    "  dlab study studies/configs/default.json --out part2 --shard 2/2\n"
    "  dlab study merge part1 part2 --out s1 && dlab plot s1\n";

const char* const kStudyEpilogue = "Exit status: 0; 1 if an exact pair failed; 2 bad config or usage.\n";

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
  std::vector<std::string> positional;
  std::string out, shard;
  bool use_default = false;
  std::uint64_t jobs = 1;
  CommandLine cl("study", kStudySynopsis, kStudyDescription, kStudyExamples,
                 kStudyEpilogue);
  CLI::App& app = cl.app();
  app.add_option(merge ? "DIR" : "CONFIG.json", positional,
                 merge ? "the shard directories of one study" : "the study's config (studies/README.md)");
  app.add_option("--out", out, merge ? "the merged study's directory" : "the study's directory")
      ->type_name("DIR")->required();
  if (!merge) {
    app.add_flag("--default", use_default, "the built-in matrix (studies/configs/default.json: n <= 10^4, 2D and 3D)");
    add_unsigned(app, "--jobs", jobs, 1024, "runs at a time (more than the cores disturbs the timings)")
        ->type_name("J");
    app.add_option("--shard", shard, "only the runs whose id mod n is k-1; dlab study merge joins the n shards")
        ->type_name("k/n");
  }
  if (auto rc = cl.parse(argc, argv, merge ? 3 : 2)) return *rc;
  try {
    if (merge) return study::merge_studies(positional, out, this_build(), std::cout, std::cerr);
    study::StudyOptions o;
    if (use_default) {
      if (!positional.empty()) throw UsageError("--default and a CONFIG exclude each other");
      o.config = study::parse_config(study::kDefaultStudyJson, "<default>");
    } else {
      if (positional.size() != 1)
        throw UsageError(positional.empty() ? "missing CONFIG.json (or --default)"
                                            : "unexpected argument '" + positional[1] + "'");
      o.config = study::read_config(positional[0]);
    }
    o.dir = out;
    o.jobs = static_cast<unsigned>(jobs);
    if (o.jobs == 0) throw UsageError("--jobs must be at least 1");
    if (!shard.empty()) o.shard = study::parse_shard(shard);
    o.build = this_build();
    return study::run_study(std::move(o), std::cout, std::cerr);
  } catch (const UsageError& e) {
    return cl.usage_error(std::string(e.what()) + " (dlab study --help)");
  } catch (const study::ConfigError& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace dlab::cli
