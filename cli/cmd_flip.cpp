// `dlab flip INPUT SIMPLICES [-o OUT] [--kernel K] [--stats FILE.json]`: flip a
// given triangulation toward Delaunay (variants/flip.hpp, any kernel of the
// registry). SIMPLICES must triangulate INPUT -- the exact validator decides;
// otherwise exit 2 naming the file, the line of the first offending simplex
// (or INPUT's line of a missing point) and the check that failed. The result is
// judged by the exact validator and classified as by `dlab triangulate`
// (variants/outcome.hpp): exit 0 ok, 1 not-delaunay (3D flips stuck), invalid or
// reported, each with its one stderr line.
//
// `dlab flip INPUT --make-start [--seed S] [--flips K] [-o OUT]`: writes a
// valid but non-Delaunay triangulation of INPUT (fuzz/non_delaunay.hpp: the
// Delaunay triangulation with K random valid flips, default K = n), the
// starting point for the first form.
#include <cstdint>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>

#include "algorithms/validate.hpp"
#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/outcome_report.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"
#include "cli/stats_json.hpp"
#include "fuzz/non_delaunay.hpp"
#include "variants/flip.hpp"
#include "variants/outcome.hpp"

namespace dlab::cli {

namespace {

// 1-based line of the k-th data line (0-based) of a file: blank and
// '#'-comment lines skipped, as the readers do; 0 if it cannot be told
// (standard input, unreadable, k < 0).
std::size_t data_line(const std::string& path, std::int64_t k) {
  if (path == "-" || k < 0) return 0;
  std::ifstream f(path, std::ios::binary);
  std::string text;
  std::size_t line = 0;
  std::int64_t seen = 0;
  while (std::getline(f, text)) {
    ++line;
    const std::size_t hash = text.find('#');
    if (hash != std::string::npos) text.resize(hash);
    if (text.find_first_not_of(" \t\r,") == std::string::npos) continue;
    if (seen++ == k) return line;
  }
  return 0;
}

// INPUT's line of point k: its k-th data line (a .node file's header comes first).
std::size_t point_line(const std::string& path, std::int64_t k) {
  return data_line(path, k < 0 ? k : k + (io::is_node_file(path) ? 1 : 0));
}

void write_out(const std::string& path, const std::vector<std::uint32_t>& s, int dim) {
  if (path == "-") {
    io::write_simplices(std::cout, s, dim);
    std::cout.flush();
    return;
  }
  std::ofstream f(path, std::ios::binary);
  if (!f) throw UsageError("cannot write '" + path + "'");
  io::write_simplices(f, s, dim);
  if (!f.flush()) throw UsageError("error writing '" + path + "'");
}

}  // namespace

int cmd_flip(int argc, char** argv) {
  std::string input, input_format, simplices_path, out_path = "-", stats_path;
  bool make = false;
  std::uint64_t seed = 1, flips = 0;
  RunOptions opt;
  opt.algorithm = "flip";
  opt.order = "input";
  opt.location = "none";  // flips from a given triangulation locate nothing
  CommandLine cl(
      "flip",
      "usage: dlab flip INPUT SIMPLICES [-o OUT] [--kernel K] [--stats FILE.json]\n"
      "       dlab flip INPUT --make-start [--seed S] [--flips K] [-o OUT]\n",
      "Flips SIMPLICES toward the Delaunay triangulation of INPUT (Lawson in 2D, Joe's flips in 3D,\n"
      "which may get stuck: not-delaunay). SIMPLICES must triangulate INPUT -- checked by the exact\n"
      "validator; otherwise exit 2 naming the file, line and check. --make-start writes a valid,\n"
      "non-Delaunay start instead (the Delaunay triangulation with K random valid flips).\n",
      "  dlab gen uniform --n 500 --seed 1 > p.txt\n"
      "  dlab flip p.txt --make-start --seed 3 -o start.txt\n"
      "  dlab flip p.txt start.txt --kernel float -o flipped.txt --stats flip.json\n",
      kOutcomeHelp);
  CLI::App& app = cl.app();
  app.add_option("INPUT", input, "the points, as dlab triangulate reads them")->required();
  app.add_option("SIMPLICES", simplices_path, "a triangulation of INPUT (not with --make-start)");
  add_input_format(app, input_format, "INPUT");
  app.add_option("-o", out_path, "the result's simplices (-: standard output)")->type_name("OUT")->capture_default_str();
  app.add_option("--kernel", opt.kernel, "adaptive, integer, mp (exact); float, epsilon (inexact)")
      ->type_name("K")->capture_default_str();
  app.add_option("--stats", stats_path, "one JSON object, as dlab triangulate --stats writes")->type_name("FILE.json");
  app.add_flag("--make-start", make, "write a valid, non-Delaunay triangulation of INPUT instead");
  add_unsigned(app, "--seed", seed, UINT64_MAX, "--make-start: seed of the random flips");
  add_unsigned(app, "--flips", flips, std::uint64_t{1} << 40, "--make-start: number of random flips (0: n)")
      ->type_name("K");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  if (make && !simplices_path.empty()) return cl.usage_error("--make-start takes INPUT only, not SIMPLICES");
  if (!make && simplices_path.empty()) return cl.usage_error("missing SIMPLICES (or --make-start)");

  PointSet points;
  std::vector<std::uint32_t> in;
  std::size_t distinct = 0;
  std::unique_ptr<std::ofstream> stats;
  try {
    points = io::read_points(input, input_format);
    const int dim = points.dimension;
    if (make) {
      const std::vector<std::uint32_t> s = dim == 2 ? non_delaunay_start<2>(points.p2, seed, flips)
                                                    : non_delaunay_start<3>(points.p3, seed, flips);
      if (s.empty()) {
        std::cerr << "dlab flip: the points are lower-dimensional: no triangulation\n";
        return 1;
      }
      write_out(out_path, s, dim);
      return 0;
    }
    if (!kernel_available(opt.kernel))
      throw UsageError("unknown kernel '" + opt.kernel + "' (expected adaptive, integer, mp, float or epsilon)");
    opt.policy = kernel_is_exact(opt.kernel) ? "sos" : "strict";
    in = io::read_simplices(simplices_path, dim, points.size());
    // The given mesh must triangulate the points (design.md section 5: refused
    // with exit 2 otherwise): the exact validator decides, whatever the kernel.
    const ValidationReport given = validate(points, in);
    if (!given.valid()) {
      const Outcome why = classify_report(given, false);
      const CheckResult& first = given[why.first_check];
      std::cerr << "dlab flip: " << io::display_name(simplices_path);
      if (const std::size_t line = data_line(simplices_path, first.simplex)) std::cerr << ":" << line;
      std::cerr << ": not a triangulation of " << io::display_name(input) << ": " << why.detail;
      if (first.point >= 0 && why.first_check == Check::missing_vertex)
        if (const std::size_t line = point_line(input, first.point))
          std::cerr << " (" << io::display_name(input) << ":" << line << ")";
      std::cerr << "\n";
      return 2;
    }
    distinct = given.distinct_points;
    if (!stats_path.empty()) {  // opened before the run: an unwritable path is a usage error now
      stats = std::make_unique<std::ofstream>(stats_path, std::ios::binary);
      if (!*stats) throw UsageError("cannot write '" + stats_path + "'");
    }
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }

  RunResult res;
  try {
    res = run_flip(points, in, opt);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const std::exception& e) {  // a run that throws has failed, not crashed
    res = RunResult{};
    res.dimension = points.dimension;
    res.points = points;
    res.outcome = RunResult::Outcome::failed;
    res.message = std::string("exception: ") + e.what();
  }
  const std::uint64_t peak_rss = io::peak_rss_bytes();  // before the validator's
  res.distinct_points = distinct;
  announce_snapping("flip", res);
  // Lawson's flips end Delaunay in 2D with an exact kernel; in 3D they may be
  // stuck (Joe 1991), and snapping may move the points: the exact validator
  // judges every result.
  bool moved = false;
  for (const auto& [key, v] : res.snapping) moved = moved || v != 0;
  const bool exact_pair = kernel_is_exact(opt.kernel) && points.dimension == 2 && !moved;
  const Outcome outcome = classify(points, res, exact_pair, Validate::always);
  print_outcome("flip", outcome, "flip, " + opt.kernel + " kernel");
  try {
    write_out(out_path, res.simplices, points.dimension);
    if (stats) {
      const io::StatsRecord rec = stats_record(opt, points.size(), res, outcome, peak_rss);
      io::write_stats_json(*stats, rec);
      if (!stats->flush()) throw UsageError("error writing '" + stats_path + "'");
    }
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
  return exit_status(outcome.kind);
}

}  // namespace dlab::cli
