// `dlab triangulate INPUT [-o SIMPLICES] [--algo A] [--kernel K] [--policy sos|strict]
//   [--order input|random|brio|hilbert] [--seed N] [--points-out FILE [--decimal]]
//   [--stats FILE.json]
//   [--exact-sphere] [--enclosing-box]` (the last two: --algo george only)
// (design.md section 5). Calls dlab::run(); after an inexact kernel (float,
// epsilon) the result is checked by the exact validator, and an invalid or
// non-Delaunay result is a failure (exit 1) like an algorithm that reports one.
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>

#include "algorithms/validate.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/point_reader.hpp"
#include "cli/point_writer.hpp"
#include "cli/simplex_io.hpp"
#include "cli/stats_json.hpp"

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

const char* outcome_name(RunResult::Outcome o) {
  switch (o) {
    case RunResult::Outcome::ok: return "ok";
    case RunResult::Outcome::lower_dimensional: return "lower_dimensional";
    case RunResult::Outcome::failed: return "failed";
  }
  return "failed";
}

}  // namespace

int cmd_triangulate(int argc, char** argv) {
  RunOptions opt;
  Args a;
  PointSet points;
  std::unique_ptr<Output> simplex_out, points_out, stats_out;
  try {
    a = parse_args(argc, argv, 2,
                   {"-o", "--algo", "--kernel", "--policy", "--order", "--seed", "--points-out",
                    "--stats"},
                   {"--exact-sphere", "--enclosing-box", "--decimal"});
    if (a.positional.size() != 1)
      throw UsageError(a.positional.empty() ? "missing INPUT"
                                            : "unexpected argument '" + a.positional[1] + "'");
    opt.algorithm = a.get("--algo").value_or(opt.algorithm);
    opt.kernel = a.get("--kernel").value_or(opt.kernel);
    // sos is the default for exact kernels; the inexact baselines run plain.
    opt.policy = a.get("--policy").value_or(kernel_is_exact(opt.kernel) ? "sos" : "strict");
    opt.order = a.get("--order").value_or(opt.order);
    opt.seed = a.u64("--seed", opt.seed);
    opt.exact_sphere = a.has("--exact-sphere");    // george only
    opt.enclosing_box = a.has("--enclosing-box");  // george only
    if (opt.policy != "sos" && opt.policy != "strict")
      throw UsageError("--policy must be sos or strict, not '" + opt.policy + "'");
    if (opt.order != "input" && opt.order != "random" && opt.order != "brio" && opt.order != "hilbert")
      throw UsageError("--order must be input, random, brio or hilbert, not '" + opt.order + "'");
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
  std::string outcome, message;
  int status = 0;
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
  outcome = outcome_name(res.outcome);
  message = res.message;
  if (res.points.size() != points.size()) res.points = points;  // e.g. after an exception
  res.dimension = points.dimension;
  // Inexact kernels: the exact validator judges the result, a claimed
  // lower-dimensional input included (float can call a full-dimensional set flat).
  if (!kernel_is_exact(opt.kernel) && res.outcome != RunResult::Outcome::failed) {
    std::string verdict;
    try {
      const ValidationReport rep = validate(res.points, res.simplices);
      if (!rep.valid()) verdict = "invalid";
      else if (!rep.delaunay()) verdict = "not_delaunay";
      if (!verdict.empty()) {
        message = rep.summary();
        while (!message.empty() && message.back() == '\n') message.pop_back();
      }
    } catch (const std::exception& e) {
      verdict = "invalid";
      message = std::string("validator: ") + e.what();
    }
    if (!verdict.empty()) {
      std::cerr << "dlab triangulate: the " << opt.kernel << " kernel's result is "
                << (verdict == "invalid" ? "invalid" : "valid but not Delaunay")
                << " (the algorithm itself reported " << outcome << "): " << message << "\n";
      outcome = verdict;
      status = 1;
    }
  }
  if (status == 0 && res.outcome == RunResult::Outcome::lower_dimensional)
    std::cerr << "dlab triangulate: lower-dimensional input, no simplices"
              << (res.message.empty() ? "" : ": " + res.message) << "\n";
  if (res.outcome == RunResult::Outcome::failed) {
    std::cerr << "dlab triangulate: " << opt.algorithm << " with the " << opt.kernel
              << " kernel failed: " << res.message << "\n";
    status = 1;
  }
  try {
    simplex_out->write([&](std::ostream& out) { io::write_simplices(out, res.simplices, res.dimension); });
    const auto format = a.has("--decimal") ? io::FloatFormat::decimal : io::FloatFormat::hex;
    if (points_out) points_out->write([&](std::ostream& out) { io::write_points(out, res.points, format); });
    if (stats_out) {
      io::StatsRecord rec;
      rec.options = opt;
      rec.input_points = points.size();
      rec.result = &res;
      rec.outcome = outcome;
      rec.message = message;
      rec.peak_rss_bytes = io::peak_rss_bytes();
      stats_out->write([&](std::ostream& out) { io::write_stats_json(out, rec); });
    }
  } catch (const UsageError& e) {
    std::cerr << "dlab triangulate: " << e.what() << "\n";
    return 2;
  }
  return status;
}

}  // namespace dlab::cli
