// `dlab corpus replay` and `dlab corpus add` (design.md section 5.1, issue 12):
// the degeneracy regression corpus, tests/corpus/ (format: tests/corpus/README.md).
// The work is in fuzz/corpus_*.hpp; this file parses the command line.
#include <iostream>
#include <string>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "fuzz/campaign_spec.hpp"
#include "fuzz/corpus_add.hpp"
#include "fuzz/corpus_replay.hpp"

namespace dlab::cli {
namespace {

const char* const kCorpusHelp =
    "usage: dlab corpus replay DIR|FILE... [--jobs J] [--timeout SEC] [--memory MIB]\n"
    "                          [--algo LIST] [--kernel LIST]\n"
    "       dlab corpus add INPUT --to DIR [--name NAME] [--source TEXT] [--exercises TEXT]\n"
    "                       [--replace] [--jobs J] [--timeout SEC] [--memory MIB]\n"
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
    "        not to record), or any pair that times out (machine-dependent: never recorded).\n"
    "  --jobs J       child processes at a time (1); the output does not depend on it\n"
    "  --timeout SEC  CPU time per case x pair (60); --memory MIB: memory per child (4096)\n"
    "Examples:\n"
    "  dlab corpus replay tests/corpus --jobs 2\n"
    "  dlab corpus replay tests/corpus/issue17-half-integer-square.pts --kernel float,epsilon\n"
    "  dlab corpus add c1/failures/lawson.float.2d.not-delaunay.txt --to tests/corpus \\\n"
    "      --name lawson-float-near-lattice --exercises 'float flips a near-cocircular lattice wrongly'\n"
    "  dlab corpus add tests/corpus/NAME.pts --to tests/corpus --replace\n"
    "Exit status: 0 (replay: no change); 1 replay: some outcome changed, add: refused;\n"
    "2 bad usage, an unreadable DIR or INPUT, a malformed case (FILE:LINE: problem), an\n"
    "existing case without --replace.\n";

void read_limits(const Args& a, fuzz::Limits& limits, unsigned& jobs) {
  if (a.get("--timeout")) limits.cpu_seconds = fuzz::parse_duration("--timeout", *a.get("--timeout"));
  limits.memory_bytes = a.u64("--memory", 4096, std::uint64_t{1} << 24) << 20;
  if (limits.memory_bytes == 0) throw UsageError("--memory must be at least 1 (MiB)");
  jobs = static_cast<unsigned>(a.i64("--jobs", 1, 1, 256));
}

int corpus_replay(int argc, char** argv) {
  const Args a = parse_args(argc, argv, 3, {"--jobs", "--timeout", "--memory", "--algo", "--kernel"}, {"--help"});
  if (a.has("--help")) {
    std::cout << kCorpusHelp;
    return 0;
  }
  fuzz::ReplayOptions o;
  o.inputs = a.positional;
  if (o.inputs.empty()) throw UsageError("replay: give the corpus directory or case files");
  if (auto v = a.get("--algo")) o.algorithms = fuzz::parse_list("--algo", *v);
  if (auto v = a.get("--kernel")) o.kernels = fuzz::parse_list("--kernel", *v);
  read_limits(a, o.limits, o.jobs);
  return fuzz::replay_corpus(o, std::cout, std::cerr);
}

int corpus_add(int argc, char** argv) {
  const Args a = parse_args(argc, argv, 3,
                            {"--to", "--name", "--source", "--exercises", "--jobs", "--timeout", "--memory"},
                            {"--replace", "--help"});
  if (a.has("--help")) {
    std::cout << kCorpusHelp;
    return 0;
  }
  fuzz::AddOptions o;
  if (a.positional.size() != 1) throw UsageError("add: give one INPUT");
  o.input = a.positional[0];
  const auto to = a.get("--to");
  if (!to) throw UsageError("add: missing --to DIR");
  o.dir = *to;
  o.name = a.get("--name");
  o.source = a.get("--source");
  o.exercises = a.get("--exercises");
  o.replace = a.has("--replace");
  read_limits(a, o.limits, o.jobs);
  return fuzz::add_corpus_case(o, std::cout, std::cerr);
}

}  // namespace

int cmd_corpus(int argc, char** argv) {
  try {
    const std::string sub = argc >= 3 ? argv[2] : "";
    if (sub == "replay") return corpus_replay(argc, argv);
    if (sub == "add") return corpus_add(argc, argv);
    if (sub == "--help" || sub == "-h" || sub == "help") {
      std::cout << kCorpusHelp;
      return 0;
    }
    throw UsageError(sub.empty() ? "give a subcommand: replay or add (dlab corpus --help)"
                                 : "unknown subcommand '" + sub + "' (replay or add; dlab corpus --help)");
  } catch (const io::InputError& e) {
    std::cerr << "dlab corpus: " << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "dlab corpus: " << e.what() << "\n";
    return 2;
  } catch (const std::runtime_error& e) {  // a child that broke the line protocol
    std::cerr << "dlab corpus: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
