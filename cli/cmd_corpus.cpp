// `dlab corpus replay` and `dlab corpus add` (design.md section 5.1, issue 12):
// the degeneracy regression corpus, tests/corpus/ (format: tests/corpus/README.md).
// The work is in fuzz/corpus_*.hpp; this file parses the command line.
#include <iostream>
#include <string>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "fuzz/campaign_spec.hpp"
#include "fuzz/corpus_add.hpp"
#include "fuzz/corpus_replay.hpp"

namespace dlab::cli {
namespace {

const char* const kCorpusSynopsis =
    "usage: dlab corpus replay DIR|FILE... [--jobs J] [--timeout SEC] [--memory MIB]\n"
    "                          [--algo LIST] [--kernel LIST]\n"
    "       dlab corpus add INPUT --to DIR [--name NAME] [--source TEXT] [--exercises TEXT]\n"
    "                       [--replace] [--jobs J] [--timeout SEC] [--memory MIB]\n";

const char* const kCorpusDescription =
    "The regression corpus (tests/corpus/README.md): each case NAME.pts holds a header of\n"
    "'# key: value' lines (case, source, exercises, dimension, optional order-seed, and one\n"
    "'# expect: ALGO KERNEL OUTCOME' per pair of the 6 algorithms x 5 kernels), then its points\n"
    "in hexadecimal floats.\n"
    "replay  runs every case (each *.pts of a DIR, in name order) with every pair, in child\n"
    "        processes under the limits, and compares each outcome class with the expected one;\n"
    "        an exact pair (adaptive, integer, mp; George only with his exact sphere) must also\n"
    "        give the perturbed, CGAL-identical triangulation (else: differs). Prints each change,\n"
    "        either way, as 'CASE: ALGO KERNEL expected X, got Y (detail)', then a summary.\n"
    "        --algo / --kernel LIST run only those pairs (e.g. a bounded smoke).\n"
    "add     runs all 30 pairs on INPUT's points and writes DIR/NAME.pts with every expect line.\n"
    "        INPUT: any point file dlab reads -- dlab shrink's output or a campaign's\n"
    "        DIR/failures/*.txt (source, exercises and order-seed come from their comments),\n"
    "        a corpus case (its keys are kept unless overridden; --replace refills its\n"
    "        expect lines), or plain points with --source and --exercises. NAME defaults to\n"
    "        the case's name or INPUT's file name.\n"
    "        Refused (exit 1, nothing written): an exact pair that is not ok (a bug to fix,\n"
    "        not to record), or any pair that times out (machine-dependent: never recorded).\n";

const char* const kCorpusExamples =
    "  dlab corpus replay tests/corpus --jobs 2\n"
    "  dlab corpus replay tests/corpus/issue17-half-integer-square.pts --kernel float,epsilon\n"
    "  dlab corpus add c1/failures/lawson.float.2d.not-delaunay.txt --to tests/corpus \\\n"
    "      --name lawson-float-near-lattice --exercises 'float flips a near-cocircular lattice wrongly'\n"
    "  dlab corpus add tests/corpus/NAME.pts --to tests/corpus --replace\n";

const char* const kCorpusEpilogue =
    "Exit status: 0 (replay: no change); 1 replay: some outcome changed, add: refused;\n"
    "2 bad usage, an unreadable DIR or INPUT, a malformed case (FILE:LINE: problem), an\n"
    "existing case without --replace.\n";

// --jobs, --timeout and --memory, shared by replay and add.
struct LimitOptions {
  unsigned jobs = 1;
  std::string timeout;
  std::uint64_t memory_mib = 4096;

  explicit LimitOptions(CLI::App& app) {
    add_integer(app, "--jobs", jobs, 1, 256, "child processes at a time; the output does not depend on it")
        ->type_name("J");
    app.add_option("--timeout", timeout, "CPU time per case x pair (default 60)")->type_name("SEC");
    add_unsigned(app, "--memory", memory_mib, std::uint64_t{1} << 24, "memory per child")->type_name("MIB");
  }
  void apply(fuzz::Limits& limits, unsigned& jobs_out) const {
    if (!timeout.empty()) limits.cpu_seconds = fuzz::parse_duration("--timeout", timeout);
    limits.memory_bytes = memory_mib << 20;
    if (limits.memory_bytes == 0) throw UsageError("--memory must be at least 1 (MiB)");
    jobs_out = jobs;
  }
};

int corpus_replay(int argc, char** argv) {
  fuzz::ReplayOptions o;
  std::string algos, kernels;
  CommandLine cl("corpus", kCorpusSynopsis, kCorpusDescription, kCorpusExamples, kCorpusEpilogue);
  CLI::App& app = cl.app();
  app.add_option("DIR|FILE", o.inputs, "corpus directories (every *.pts, in name order) or case files");
  app.add_option("--algo", algos, "only these algorithms (comma-separated; default all 6)")->type_name("LIST");
  app.add_option("--kernel", kernels, "only these kernels (comma-separated; default all 5)")->type_name("LIST");
  const LimitOptions limits(app);
  if (auto rc = cl.parse(argc, argv, 3)) return *rc;
  try {
    if (o.inputs.empty()) throw UsageError("give the corpus directory or case files");
    if (!algos.empty()) o.algorithms = fuzz::parse_list("--algo", algos);
    if (!kernels.empty()) o.kernels = fuzz::parse_list("--kernel", kernels);
    limits.apply(o.limits, o.jobs);
    return fuzz::replay_corpus(o, std::cout, std::cerr);
  } catch (const std::runtime_error& e) {  // io::InputError, UsageError, a child that broke the line protocol
    return cl.usage_error(e.what());
  }
}

int corpus_add(int argc, char** argv) {
  fuzz::AddOptions o;
  std::string name, source, exercises;
  CommandLine cl("corpus", kCorpusSynopsis, kCorpusDescription, kCorpusExamples, kCorpusEpilogue);
  CLI::App& app = cl.app();
  app.add_option("INPUT", o.input, "the point file to record")->required();
  app.add_option("--to", o.dir, "the corpus directory")->type_name("DIR")->required();
  app.add_option("--name", name, "the case's name (default: the case's or INPUT's file name)");
  app.add_option("--source", source, "where the points come from (default: INPUT's comments)")->type_name("TEXT");
  app.add_option("--exercises", exercises, "what the case exercises (default: INPUT's comments)")
      ->type_name("TEXT");
  app.add_flag("--replace", o.replace, "overwrite an existing case, refilling its expect lines");
  const LimitOptions limits(app);
  if (auto rc = cl.parse(argc, argv, 3)) return *rc;
  if (app.count("--name")) o.name = name;
  if (app.count("--source")) o.source = source;
  if (app.count("--exercises")) o.exercises = exercises;
  try {
    limits.apply(o.limits, o.jobs);
    return fuzz::add_corpus_case(o, std::cout, std::cerr);
  } catch (const std::runtime_error& e) {  // io::InputError, UsageError, a child that broke the line protocol
    return cl.usage_error(e.what());
  }
}

}  // namespace

int cmd_corpus(int argc, char** argv) {
  const std::string sub = argc >= 3 ? argv[2] : "";
  if (sub == "replay") return corpus_replay(argc, argv);
  if (sub == "add") return corpus_add(argc, argv);
  if (sub == "--help" || sub == "-h" || sub == "help") {
    CommandLine cl("corpus", kCorpusSynopsis, kCorpusDescription, kCorpusExamples, kCorpusEpilogue);
    std::cout << cl.app().help();
    return 0;
  }
  std::cerr << "dlab corpus: "
            << (sub.empty() ? "give a subcommand: replay or add (dlab corpus --help)"
                            : "unknown subcommand '" + sub + "' (replay or add; dlab corpus --help)")
            << "\n";
  return 2;
}

}  // namespace dlab::cli
