// `dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]
//   [--order input|random|brio|hilbert] [--location walk|scan] [--seed N]
//   [--points-out FILE [--decimal]] [--stats FILE.json]
//   [--exact-sphere] [--enclosing-box] [--validate]` (the first two of the last
// three: --algo george only) (design.md section 5). Calls dlab::run() and
// classifies the result (variants/outcome.hpp): the exact validator judges
// every result that the pair does not promise to be Delaunay (inexact kernels,
// George's floating sphere and enclosing box), and, with --validate, every
// result. Exit status and the one stderr line follow the class; points the
// integer kernel moved or merged are announced on stderr.
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <string_view>

#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/outcome_report.hpp"
#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "cli/simplex_io.hpp"
#include "cli/stats_json.hpp"
#include "variants/outcome.hpp"

namespace dlab::cli {
namespace {

// An output named on the command line, opened before the (possibly long) run
// so that an unwritable path is a usage error at once. "-" or absent: stdout.
class Output {
 public:
  explicit Output(const std::optional<std::string>& path) : path_(path.value_or("-")) {
    if (path_ != "-") {
      file_.open(path_, std::ios::binary);
      if (!file_) throw UsageError("cannot write '" + path_ + "'");
    }
  }
  template <class W>
  void write(W&& w) {
    std::ostream& out = path_ == "-" ? std::cout : file_;
    w(out);
    if (!out.flush()) throw UsageError("error writing '" + path_ + "'");
  }

 private:
  std::string path_;
  std::ofstream file_;
};

}  // namespace

const char* const kTriangulateUsage =
    "usage: dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]\n"
    "         [--order input|random|brio|hilbert] [--location walk|scan] [--seed N]\n"
    "         [--points-out FILE [--decimal]] [--stats FILE.json] [--validate]\n"
    "         [--exact-sphere] [--enclosing-box]\n"
    "A: bowyer-watson (default), lawson, tanemura, george (--exact-sphere: exact circumsphere test\n"
    "instead of George's floating one; --enclosing-box: the paper's box instead of a ghost vertex).\n"
    "K: adaptive (default), integer, mp (exact); float, epsilon (inexact baselines).\n"
    "--location: point location of bowyer-watson and lawson: walk (default; the visibility walk\n"
    "from the last insertion) or scan (every live simplex tested in storage order: O(n^2);\n"
    "counter scan_tests).\n"
    "--validate: the exact validator judges the result of an exact pair too (it may take longer\n"
    "than the triangulation; not counted in seconds or peak_rss_bytes).\n";

int cmd_triangulate(int argc, char** argv) {
  RunOptions opt;
  Args a;
  PointSet points;
  std::unique_ptr<Output> simplex_out, points_out, stats_out;
  for (int i = 2; i < argc; ++i)
    if (std::string_view(argv[i]) == "--help") {
      std::cout << kTriangulateUsage << kOutcomeHelp;
      return 0;
    }
  try {
    a = parse_args(argc, argv, 2,
                   {"-o", "--algo", "--kernel", "--policy", "--order", "--location", "--seed",
                    "--points-out", "--stats"},
                   {"--exact-sphere", "--enclosing-box", "--validate", "--decimal"});
    if (a.positional.size() != 1)
      throw UsageError(a.positional.empty() ? "missing INPUT"
                                            : "unexpected argument '" + a.positional[1] + "'");
    opt.algorithm = a.get("--algo").value_or(opt.algorithm);
    opt.kernel = a.get("--kernel").value_or(opt.kernel);
    // sos is the default for exact kernels; the inexact baselines run plain.
    opt.policy = a.get("--policy").value_or(kernel_is_exact(opt.kernel) ? "sos" : "strict");
    opt.order = a.get("--order").value_or(opt.order);
    opt.location = a.get("--location").value_or(opt.location);
    opt.seed = a.u64("--seed", opt.seed);
    opt.exact_sphere = a.has("--exact-sphere");    // george only
    opt.enclosing_box = a.has("--enclosing-box");  // george only
    if (opt.policy != "sos" && opt.policy != "strict")
      throw UsageError("--policy must be sos or strict, not '" + opt.policy + "'");
    if (opt.order != "input" && opt.order != "random" && opt.order != "brio" && opt.order != "hilbert")
      throw UsageError("--order must be input, random, brio or hilbert, not '" + opt.order + "'");
    if (opt.location != "walk" && opt.location != "scan")
      throw UsageError("--location must be walk or scan, not '" + opt.location + "'");
    points = io::read_points(a.positional[0]);
    simplex_out = std::make_unique<Output>(a.get("-o"));
    if (auto p = a.get("--points-out")) points_out = std::make_unique<Output>(p);
    if (auto p = a.get("--stats")) stats_out = std::make_unique<Output>(p);
  } catch (const UsageError& e) {
    std::cerr << "dlab triangulate: " << e.what() << "\n";
    return 2;
  } catch (const io::InputError& e) {
    std::cerr << "dlab triangulate: " << e.what() << "\n";
    return 2;
  }

  RunResult res;
  try {
    res = run(points, opt);
  } catch (const UsageError& e) {
    std::cerr << "dlab triangulate: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {  // an algorithm that throws has failed, not crashed
    res = RunResult{};
    res.dimension = points.dimension;
    res.outcome = RunResult::Outcome::failed;
    res.message = std::string("exception: ") + e.what();
  }
  // The run's peak memory, before the validator's.
  const std::uint64_t peak_rss = io::peak_rss_bytes();
  if (res.points.size() != points.size()) res.points = points;  // e.g. after an exception
  res.dimension = points.dimension;
  announce_snapping("triangulate", res);
  const Outcome outcome = classify(points, res, pair_is_exact(opt),
                                   a.has("--validate") ? Validate::always : Validate::unless_exact);
  print_outcome("triangulate", outcome, describe_pair(opt));
  try {
    simplex_out->write([&](std::ostream& out) { io::write_simplices(out, res.simplices, res.dimension); });
    const auto format = a.has("--decimal") ? io::FloatFormat::decimal : io::FloatFormat::hex;
    if (points_out) points_out->write([&](std::ostream& out) { io::write_points(out, res.points, format); });
    if (stats_out) {
      const io::StatsRecord rec = stats_record(opt, points.size(), res, outcome, peak_rss);
      stats_out->write([&](std::ostream& out) { io::write_stats_json(out, rec); });
    }
  } catch (const UsageError& e) {
    std::cerr << "dlab triangulate: " << e.what() << "\n";
    return 2;
  }
  return exit_status(outcome.kind);
}

}  // namespace dlab::cli
