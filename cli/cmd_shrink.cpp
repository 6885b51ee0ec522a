// `dlab shrink` (issue 12): a failing point set -> a smaller one with the same
// failure. The work is in fuzz/shrink*.hpp (ddmin, coordinate passes, the
// child-process oracle); this file parses the command line and writes the
// result with its header.
#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "cli/run_choices.hpp"
#include "fuzz/campaign_spec.hpp"
#include "fuzz/case_plan.hpp"
#include "fuzz/fuzz_outcome.hpp"
#include "fuzz/shrink.hpp"
#include "fuzz/shrink_oracle.hpp"

namespace dlab::cli {
namespace {

const char* const kShrinkSynopsis =
    "usage: dlab shrink INPUT --algo A --kernel K [--exact-sphere] [--enclosing-box]\n"
    "                   [--policy sos|strict] [--order input|random|brio|hilbert] [--seed S]\n"
    "                   [--outcome CLASS] [--kind KIND | --any-kind] [--dim 2|3] [-o OUT]\n"
    "                   [--timeout SEC] [--memory MIB] [--max-tests N]\n";

const char* const kShrinkDescription =
    "Shrinks a point set on which the pair fails to a smaller one on which it fails the same\n"
    "way: ddmin over the points (Zeller and Hildebrandt, IEEE TSE 2002) down to a 1-minimal set,\n"
    "then coordinate passes -- translate toward the origin by exact offsets, snap coordinates to\n"
    "integers, round them to fewer significant bits -- each kept only while the failure persists,\n"
    "repeated until nothing changes. Deterministic: same input and options, same output.\n"
    "INPUT: any point file dlab reads, e.g. a campaign's DIR/failures/*.txt ('-': stdin).\n"
    "The pair runs as dlab triangulate runs it (A, K, --policy, --order, --seed: same meaning and\n"
    "defaults; without --seed, the --seed of INPUT's '# replay: ... dlab triangulate ...' comment,\n"
    "as a campaign's failure files and dlab shrink's output have, else 0). Every test runs in a\n"
    "child process under dlab fuzz's limits and classification (--timeout SEC CPU time, 10;\n"
    "--memory MIB, 4096), so crash, timeout and out-of-memory shrink too.\n"
    "The same failure: the outcome class INPUT gives (--outcome CLASS: check that it is that one:\n"
    "not-delaunay, invalid, reported, differs, crash, timeout, out-of-memory) and its kind -- the\n"
    "invalid check group, the reported message with numbers as '#', the crash's signal (--kind\n"
    "KIND: check it; --any-kind: any kind of that class will do).\n"
    "Prints the sizes before and after (points, significant bits of all coordinates) and the\n"
    "number of tests on stderr. -o OUT: the shrunk points, hexadecimal floats after '#' comment\n"
    "lines (what was shrunk, the pair, the failure, the sizes, the dlab triangulate command that\n"
    "replays it, and INPUT's own comments).\n";

const char* const kShrinkExamples =
    "  dlab fuzz --algo lawson --kernel float --gen near-degenerate --cases 200 --out c1\n"
    "  dlab shrink c1/failures/lawson.float.2d.not-delaunay.txt --algo lawson --kernel float \\\n"
    "      -o small.txt\n"
    "  dlab triangulate small.txt --algo lawson --kernel float --seed SEED --validate\n"
    "      (SEED: the failure file's; small.txt's '# replay:' line is this command)\n"
    "  dlab shrink bad.txt --algo bowyer-watson --kernel float --order input --max-tests 500 \\\n"
    "      --any-kind -o small.txt\n";

const char* const kShrinkEpilogue =
    "Exit status: 0 shrunk; 1 the shrunk set did not fail the same way when run again (a flaky\n"
    "failure, e.g. a timeout near its limit); 2 bad usage or INPUT (FILE:LINE: problem), or an\n"
    "INPUT on which the pair does not fail (or not as --outcome / --kind say): nothing to shrink.\n";

struct Options {
  std::string input, output = "-";
  fuzz::Pair pair;
  std::optional<std::uint64_t> order_seed;  // --seed
  std::optional<std::string> outcome, kind;
  bool any_kind = false;
  fuzz::Limits limits;
  std::uint64_t max_tests = 20000;
  std::optional<int> dim;
};

// The command line -> Options; nullopt after --help or a usage error (*rc set).
std::optional<Options> parse(int argc, char** argv, int& rc) {
  Options o;
  std::string algo, kernel, outcome, kind, timeout, policy, order = "brio";
  std::uint64_t seed = 0, memory_mib = 4096;
  int dim = 2;
  bool exact_sphere = false, enclosing_box = false;
  CommandLine cl("shrink", kShrinkSynopsis, kShrinkDescription, kShrinkExamples, kShrinkEpilogue);
  CLI::App& app = cl.app();
  app.add_option("INPUT", o.input, "a point file on which the pair fails ('-': standard input)")->required();
  app.add_option("--algo", algo, "the pair's algorithm, as dlab triangulate --algo")->type_name("A");
  app.add_option("--kernel", kernel, "the pair's kernel, as dlab triangulate --kernel")->type_name("K");
  app.add_flag("--exact-sphere", exact_sphere, "george: the exact circumsphere test");
  app.add_flag("--enclosing-box", enclosing_box, "george: the enclosing box");
  add_choice(app, "--policy", policy, kPolicies, "as dlab triangulate --policy");
  add_choice(app, "--order", order, kOrders, "as dlab triangulate --order");
  add_unsigned(app, "--seed", seed, UINT64_MAX, "as dlab triangulate --seed (default: INPUT's replay line, else 0)")
      ->type_name("S")->default_str("");
  app.add_option("--outcome", outcome,
                 "check that INPUT fails this way: not-delaunay, invalid, reported, differs, crash,\n"
                 "timeout or out-of-memory")
      ->type_name("CLASS");
  app.add_option("--kind", kind, "check INPUT's kind of failure (the check group, message or signal)");
  app.add_flag("--any-kind", o.any_kind, "any kind of INPUT's outcome class will do")->excludes("--kind");
  add_integer(app, "--dim", dim, 2, 3, "check INPUT's dimension")->type_name("2|3")->default_str("");
  app.add_option("-o", o.output, "the shrunk points (-: standard output)")->type_name("OUT")->capture_default_str();
  app.add_option("--timeout", timeout, "CPU time per test (default 10)")->type_name("SEC");
  add_unsigned(app, "--memory", memory_mib, std::uint64_t{1} << 24, "memory per test")->type_name("MIB");
  add_unsigned(app, "--max-tests", o.max_tests, UINT64_MAX,
               "runs of the pair at most, those of INPUT and of the result included");
  if (auto r = cl.parse(argc, argv, 2)) {
    rc = *r;
    return std::nullopt;
  }
  try {
    if (algo.empty() || kernel.empty()) throw UsageError("give the pair that fails: --algo A --kernel K");
    std::string name = algo;
    if (exact_sphere) name += "+exact-sphere";
    if (enclosing_box) name += "+enclosing-box";
    o.pair = fuzz::make_pair(name, kernel);
    o.pair.policy = policy;  // empty: dlab triangulate's default for the kernel
    o.pair.order = order;
    if (app.count("--seed")) o.order_seed = seed;
    if (app.count("--outcome")) {
      o.outcome = outcome;
      if (!fuzz::is_failure(outcome) || std::find(std::begin(fuzz::kOutcomeOrder), std::end(fuzz::kOutcomeOrder),
                                                  outcome) == std::end(fuzz::kOutcomeOrder))
        throw UsageError("--outcome must be a failure class: not-delaunay, invalid, reported, differs, crash, "
                         "timeout or out-of-memory, not '" + outcome + "'");
    }
    if (app.count("--kind")) o.kind = kind;
    if (app.count("--dim")) o.dim = dim;
    if (!timeout.empty()) o.limits.cpu_seconds = fuzz::parse_duration("--timeout", timeout);
    o.limits.memory_bytes = memory_mib << 20;
    if (o.limits.memory_bytes == 0) throw UsageError("--memory must be at least 1 (MiB)");
    if (o.max_tests < 2) throw UsageError("--max-tests must be at least 2 (the run of INPUT and the final one)");
  } catch (const UsageError& e) {
    rc = cl.usage_error(e.what());
    return std::nullopt;
  }
  return o;
}

// The comment lines of INPUT's text, each without its '#' and leading blanks.
std::vector<std::string_view> comments(std::string_view text) {
  std::vector<std::string_view> out;
  for (std::size_t pos = 0; pos < text.size();) {
    const std::size_t nl = std::min(text.find('\n', pos), text.size());
    std::string_view l = text.substr(pos, nl - pos);
    pos = nl + 1;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    const std::size_t hash = l.find_first_not_of(" \t");
    if (hash == l.npos || l[hash] != '#') continue;
    l.remove_prefix(hash + 1);
    while (!l.empty() && l.front() == ' ') l.remove_prefix(1);
    out.push_back(l);
  }
  return out;
}

// INPUT's comment lines, for the output: a line whose key the header writes
// ("replay: ...") is kept as "unshrunk KEY: ..." so that the header's own is the
// only one a reader (dlab corpus add) finds; INPUT's "shrunk:" line is dropped.
std::string input_comments(std::string_view text) {
  static const char* const keys[] = {"dlab shrink:", "input:", "detail:", "replay:", "replay the points below:"};
  std::string out;
  for (std::string_view body : comments(text)) {
    if (body.rfind("shrunk:", 0) == 0) continue;
    bool ours = false;
    for (const char* k : keys) ours = ours || body.rfind(k, 0) == 0;
    out += ours ? "# unshrunk " + std::string(body) + "\n" : "# " + std::string(body) + "\n";
  }
  return out;
}

// The --seed of INPUT's "# replay: ... dlab triangulate ... --seed N ..." line, if it has one.
std::optional<std::uint64_t> replay_seed(std::string_view text) {
  for (std::string_view l : comments(text)) {
    if (l.rfind("replay: ", 0) != 0) continue;
    const std::size_t tri = l.find("dlab triangulate ");
    const std::size_t seed = tri == l.npos ? l.npos : l.find(" --seed ", tri);
    if (seed == l.npos) continue;
    const std::string_view digits = l.substr(seed + 8);
    std::uint64_t v = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec == std::errc() && end != digits.data() && (end == digits.data() + digits.size() || *end == ' '))
      return v;
  }
  return std::nullopt;
}

std::string dim_text(const PointSet& p) { return std::to_string(p.dimension) + "D"; }

int run_shrink(const Options& o) {
  const std::string text = io::read_file(o.input);
  const PointSet input = io::parse_points(text, io::display_name(o.input), io::is_node_file(o.input));
  if (input.size() == 0) throw io::InputError(io::display_name(o.input) + ": no points: nothing to shrink");
  if (o.dim && *o.dim != input.dimension)
    throw UsageError(io::display_name(o.input) + " holds " + dim_text(input) + " points, not --dim " +
                     std::to_string(*o.dim));
  std::vector<fuzz::Misbehaviour> selftest;
  if (const char* st = std::getenv(fuzz::kSelftestVariable)) {
    selftest = fuzz::parse_selftest(st);
    std::cerr << "dlab shrink: " << fuzz::kSelftestVariable << "=" << st
              << " is set: deliberate failures are injected (CASE 0: every test; a test of dlab shrink)\n";
  }
  const std::string pair_text = o.pair.algo_name() + " x " + o.pair.kernel;
  std::uint64_t order_seed = 0;
  if (o.order_seed) {
    order_seed = *o.order_seed;
  } else if (auto s = replay_seed(text)) {
    order_seed = *s;
    std::cerr << "dlab shrink: --seed " << order_seed << ", from the replay line of " << io::display_name(o.input)
              << "\n";
  }
  const fuzz::ChildOracle oracle(o.pair, order_seed, o.limits, selftest);
  const fuzz::Observed first = oracle.observe(input);
  const fuzz::FailureClass seen{first.outcome, first.kind};
  if (!fuzz::is_failure(first.outcome))
    throw UsageError(io::display_name(o.input) + " does not fail: " + pair_text + " gives " + first.outcome +
                     ": nothing to shrink");
  if ((o.outcome && *o.outcome != first.outcome) || (o.kind && *o.kind != first.kind))
    throw UsageError(io::display_name(o.input) + ": " + pair_text + " gives " + seen.describe() + ", not " +
                     fuzz::FailureClass{o.outcome.value_or(first.outcome), o.kind.value_or(first.kind)}.describe() +
                     ": nothing to shrink");
  fuzz::FailureClass target = seen;
  if (o.any_kind) target.kind.reset();

  // Opened before the long part, after INPUT is read (OUT may be INPUT).
  std::ofstream file;
  if (o.output != "-") {
    file.open(o.output, std::ios::binary);
    if (!file) throw UsageError("cannot write '" + o.output + "'");
  }
  fuzz::ShrinkLimits limits;
  limits.max_tests = o.max_tests - 2;  // the run of INPUT and the final one count
  const fuzz::ShrinkReport r =
      fuzz::shrink(input, [&](const PointSet& p) { return target.matches(oracle.observe(p)); }, limits);
  const fuzz::Observed last = oracle.observe(r.points);  // a run outside the shrinker's loop, for its detail
  const std::uint64_t tests = 1 + r.tests + 1;
  fuzz::ShrinkReport shown = r;
  shown.tests = tests;

  std::ostringstream out;
  out << "# dlab shrink: " << pair_text << ", " << dim_text(input) << ": " << target.describe() << "\n"
      << "# shrunk: yes: " << fuzz::describe(shown) << "\n"
      << "# input: " << io::display_name(o.input) << "\n"
      << "# detail: " << last.detail << "\n"
      << "# replay: dlab triangulate " << (o.output == "-" ? "FILE" : o.output)
      << fuzz::triangulate_options(o.pair, order_seed) << "\n"
      << input_comments(text);
  io::write_points(out, r.points, io::FloatFormat::hex);
  std::ostream& dest = o.output == "-" ? std::cout : file;
  dest << out.str();
  if (!dest.flush()) throw UsageError("error writing '" + o.output + "'");
  std::cerr << "dlab shrink: " << pair_text << ", " << target.describe() << ": " << fuzz::describe(shown) << "\n";
  if (!target.matches(last)) {
    std::cerr << "dlab shrink: the shrunk set gave " << fuzz::FailureClass{last.outcome, last.kind}.describe()
              << " when run again, not " << target.describe() << " (a flaky failure?)\n";
    return 1;
  }
  return 0;
}

}  // namespace

int cmd_shrink(int argc, char** argv) {
  int rc = 0;
  const std::optional<Options> o = parse(argc, argv, rc);
  if (!o) return rc;
  try {
    return run_shrink(*o);
  } catch (const UsageError& e) {
    std::cerr << "dlab shrink: " << e.what() << "\n";
    return 2;
  } catch (const io::InputError& e) {
    std::cerr << "dlab shrink: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
