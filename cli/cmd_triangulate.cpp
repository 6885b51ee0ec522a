// `dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]
//   [--order input|random|brio|hilbert] [--location walk|scan] [--seed N]
//   [--points-out FILE [--decimal]] [--stats FILE.json]
//   [--exact-sphere] [--enclosing-box] [--validate] [--threads T] [--canonical]`
// (--exact-sphere and --enclosing-box: --algo george only; --threads:
// bowyer-watson with an exact kernel) (design.md section 5). Calls dlab::run() and
// classifies the result (variants/outcome.hpp): the exact validator judges
// every result that the pair does not promise to be Delaunay (inexact kernels,
// George's floating sphere and enclosing box), and, with --validate, every
// result. Exit status and the one stderr line follow the class; points the
// integer kernel moved or merged are announced on stderr.
#include <fstream>
#include <iostream>
#include <memory>
#include <utility>

#include "algorithms/mesh.hpp"
#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/outcome_report.hpp"
#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "cli/run_choices.hpp"
#include "cli/simplex_io.hpp"
#include "cli/stats_json.hpp"
#include "variants/outcome.hpp"

namespace dlab::cli {
namespace {

// An output named on the command line, opened before the (possibly long) run
// so that an unwritable path is a usage error at once. "-" or absent: stdout.
class Output {
 public:
  explicit Output(std::string path) : path_(std::move(path)) {
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

int cmd_triangulate(int argc, char** argv) {
  RunOptions opt;
  opt.policy.clear();  // sos for exact kernels, strict for the inexact baselines
  std::string input, input_format, simplex_path = "-", points_path, stats_path;
  bool validate = false, decimal = false;
  CommandLine cl(
      "triangulate",
      "usage: dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]\n"
      "         [--order input|random|brio|hilbert] [--location walk|scan] [--seed N]\n"
      "         [--points-out FILE [--decimal]] [--stats FILE.json] [--validate] [--input-format FMT]\n"
      "         [--exact-sphere] [--enclosing-box] [--threads T] [--canonical]\n",
      "Triangulates INPUT with one algorithm x kernel pair and classifies the result: the exact\n"
      "validator judges every result the pair does not promise to be Delaunay (inexact kernels,\n"
      "George's floating sphere or box) and, with --validate, every result. Points the integer\n"
      "kernel moves or merges are announced on stderr.\n"
      "INPUT: one point per line (2 or 3 coordinates, decimal or hex floats), a Triangle/TetGen\n"
      ".node file, or the vertices of a .xyz, .off or ASCII .ply file; '-': standard input.\n",
      "  dlab gen uniform --n 1000 --seed 1 > p.txt\n"
      "  dlab triangulate p.txt -o t.txt --stats s.json\n"
      "  dlab triangulate p.txt --algo lawson --kernel float --validate -o t.txt\n"
      "  dlab triangulate p.txt --algo george --exact-sphere --order hilbert --seed 7\n"
      "  dlab triangulate p.txt --threads 4 -o t.txt     # same bytes as --canonical, any T\n",
      kOutcomeHelp);
  CLI::App& app = cl.app();
  app.add_option("INPUT", input, "the points")->required();
  add_input_format(app, input_format, "INPUT");
  app.add_option("-o", simplex_path,
                 "the simplices, d+1 zero-based indices per line, positively oriented (-: standard output)")
      ->type_name("SIMPLICES")->default_str("-");
  app.add_option("--algo", opt.algorithm, "bowyer-watson, lawson, tanemura, george")
      ->type_name("A")->capture_default_str();
  app.add_option("--kernel", opt.kernel, "adaptive, integer, mp (exact); float, epsilon (inexact)")
      ->type_name("K")->capture_default_str();
  add_choice(app, "--policy", opt.policy, kPolicies,
             "degeneracies: sos (symbolic perturbation) or strict; default sos for exact kernels,\n"
             "strict for float and epsilon");
  add_choice(app, "--order", opt.order, kOrders, "insertion order (random, brio, hilbert: seeded)");
  add_choice(app, "--location", opt.location, kLocations,
             "point location of bowyer-watson and lawson: walk (the visibility walk from the last\n"
             "insertion) or scan (every live simplex tested in storage order: O(n^2); counter\n"
             "scan_tests)");
  add_unsigned(app, "--seed", opt.seed, UINT64_MAX, "seed of the insertion order");
  app.add_option("--points-out", points_path,
                 "the coordinates triangulated (after the integer kernel's snapping), in INPUT's order,\n"
                 "as hexadecimal floats")->type_name("FILE");
  app.add_flag("--decimal", decimal, "--points-out as shortest round-trip decimals instead");
  app.add_option("--stats", stats_path, "one JSON object: the pair, sizes, seconds, peak memory, counters")
      ->type_name("FILE.json");
  app.add_flag("--validate", validate,
               "the exact validator judges an exact pair's result too (not counted in seconds or\n"
               "peak_rss_bytes)");
  app.add_flag("--exact-sphere", opt.exact_sphere, "george: exact circumsphere test instead of George's floating one");
  app.add_flag("--enclosing-box", opt.enclosing_box, "george: the paper's enclosing box instead of a ghost vertex");
  add_unsigned(app, "--threads", opt.threads, 255,
               "bowyer-watson on T threads (oneTBB; exact kernels; 0: the serial algorithm): the same\n"
               "simplices for every T and schedule, in canonical order (as --canonical); the work\n"
               "counters vary")->type_name("T");
  app.add_flag("--canonical", opt.canonical,
               "simplices in canonical order: each starts at its smallest index (an even permutation),\n"
               "the lines sorted; equal triangulations give equal files, whatever the algorithm");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  if (opt.policy.empty()) opt.policy = kernel_is_exact(opt.kernel) ? "sos" : "strict";

  PointSet points;
  std::unique_ptr<Output> simplex_out, points_out, stats_out;
  try {
    points = io::read_points(input, input_format);
    simplex_out = std::make_unique<Output>(simplex_path);
    if (!points_path.empty()) points_out = std::make_unique<Output>(points_path);
    if (!stats_path.empty()) stats_out = std::make_unique<Output>(stats_path);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }

  // run() takes the points (no second copy of a large input) and returns them
  // in res.points; after an exception they are still in `points`.
  const std::size_t input_points = points.size();
  RunResult res;
  try {
    res = run(std::move(points), opt);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const MeshTooLarge& e) {  // dlab's limit, not the algorithm's failure
    return cl.usage_error(input + ": " + std::to_string(input_points) + " points: " + e.what());
  } catch (const std::exception& e) {  // an algorithm that throws has failed, not crashed
    res = RunResult{};
    res.dimension = points.dimension;
    res.outcome = RunResult::Outcome::failed;
    res.message = std::string("exception: ") + e.what();
  }
  // The run's peak memory, before the validator's.
  const std::uint64_t peak_rss = io::peak_rss_bytes();
  if (res.points.size() != input_points) res.points = std::move(points);  // after an exception
  res.dimension = res.points.dimension;
  announce_snapping("triangulate", res);
  const Outcome outcome = classify(res.points, res, pair_is_exact(opt),
                                   validate ? Validate::always : Validate::unless_exact);
  print_outcome("triangulate", outcome, describe_pair(opt));
  try {
    simplex_out->write([&](std::ostream& out) { io::write_simplices(out, res.simplices, res.dimension); });
    const auto format = decimal ? io::FloatFormat::decimal : io::FloatFormat::hex;
    if (points_out) points_out->write([&](std::ostream& out) { io::write_points(out, res.points, format); });
    if (stats_out) {
      const io::StatsRecord rec = stats_record(opt, input_points, res, outcome, peak_rss);
      stats_out->write([&](std::ostream& out) { io::write_stats_json(out, rec); });
    }
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
  return exit_status(outcome.kind);
}

}  // namespace dlab::cli
