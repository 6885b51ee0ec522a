// tetgen: TetGen 1.5 (Si, "TetGen, a Delaunay-based quality tetrahedral mesh
// generator", ACM TOMS 41(2), 2015) as Debian ships it, on a .node file.
//
// Switches: no -p (a point set: plain Delaunay tetrahedralization, no Steiner
// point), -z (numbering from zero), -N -F (no .node, no .face output), -I (no
// iteration number in the output name), -J (do not jettison duplicate points:
// the .ele then indexes the input points; TetGen otherwise renumbers the
// points that remain). Not -Q: its "Delaunay seconds:" line is the timing.
//
// Timed: TetGen's own "Delaunay seconds" -- clock(), the process's CPU time,
// around its vertex insertion only (no file reading or writing). TetGen has no
// wall-clock timer; it is single-threaded, and both wall_seconds and
// cpu_seconds carry that number.
//
// Failures: TetGen ends an error by throwing an int that nothing catches
// (terminatetetgen), so the process dies by SIGABRT after printing
// "terminate called after throwing an instance of 'int'"; with its last
// stdout line ("Exception:  All vertices are coplanar (Tol = 1e-08).") that is
// `reported`. Its stdout is made line-buffered with coreutils' stdbuf (when
// present) so that this line survives the abort. A failed assertion or any
// other signal is a `crash`. Duplicates: "Point #i is coincident with #j.
// Ignored!" and the .ele uses the copy it kept.
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studies/baselines_process.hpp"
#include "studies/baselines_tools.hpp"

namespace dlab::baselines {
namespace {

constexpr std::string_view kUncaught = "terminate called after throwing an instance of 'int'";

// TetGen's last words before an error exit: the last line holding
// "Exception" or "Error", else the last non-blank line of stdout.
std::string error_line(const std::string& out) {
  std::istringstream s(out);
  std::string last, marked;
  for (std::string line; std::getline(s, line);) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    last = line;
    if (line.find("Exception") != std::string::npos || line.find("Error") != std::string::npos)
      marked = line;
  }
  return first_line(marked.empty() ? last : marked);
}

// Reads "M 4 0" then M lines "t a b c d" into `run.simplices`; false if malformed.
bool read_ele(const std::filesystem::path& file, BaselineRun& run) {
  std::ifstream in(file);
  std::size_t m = 0, corners = 0, attributes = 0;
  if (!(in >> m >> corners >> attributes) || corners != 4) return false;
  run.simplices.reserve(4 * m);
  for (std::size_t t = 0; t < m; ++t) {
    long long id = 0, v[4];
    if (!(in >> id >> v[0] >> v[1] >> v[2] >> v[3])) return false;
    for (long long x : v) {
      if (x < 0 || x > 0xffffffffLL) return false;
      run.simplices.push_back(static_cast<std::uint32_t>(x));
    }
    for (std::size_t a = 0; a < attributes; ++a) {
      double skip = 0;
      if (!(in >> skip)) return false;
    }
  }
  return true;
}

}  // namespace

BaselineRun run_tetgen(const PointSet& points, const BaselineOptions& options) {
  BaselineRun run;
  std::string why;
  const auto exe = tool_path("tetgen", &why);
  if (!exe) {
    run.skipped = true;
    run.message = why;
    return run;
  }
  if (points.dimension != 3) {
    run.skipped = true;
    run.message = "tetgen triangulates 3D point sets only";
    return run;
  }
  TempDir dir;
  write_point_file(dir.path() / "points.node", std::to_string(points.size()) + " 3 0 0\n", points, true);
  std::vector<std::string> argv;
  if (find_executable("stdbuf")) argv = {"stdbuf", "-oL"};
  argv.insert(argv.end(), {*exe, "-zNFIJ", "points.node"});
  const auto out = dir.path() / "stdout", err = dir.path() / "stderr";
  const ProcessResult p = run_process(argv, dir.path(), std::nullopt, out, err, options.timeout_seconds);
  const std::string text = read_text(out), errors = read_text(err);
  if (p.timed_out) {
    run.outcome = "timeout";
    run.message = "tetgen " + describe(p, options.timeout_seconds);
    return run;
  }
  if (p.signal == SIGABRT && errors.find(kUncaught) != std::string::npos) {
    run.outcome = "reported";
    run.message = error_line(text);
    if (run.message.empty()) run.message = "tetgen stopped with an error and no message";
    return run;
  }
  if (!p.started || p.signal || p.exit_status != 0) {
    run.outcome = "crash";
    run.message = "tetgen " + describe(p, options.timeout_seconds);
    if (const auto e = first_line(errors); !e.empty()) run.message += ": " + e;
    return run;
  }
  const auto seconds = number_after(text, "Delaunay seconds:");
  if (!seconds || !read_ele(dir.path() / "points.ele", run)) {
    run.simplices.clear();
    run.outcome = "crash";
    run.message = seconds ? "tetgen wrote no readable points.ele" : "tetgen printed no 'Delaunay seconds:' line";
    return run;
  }
  run.outcome = "ok-so-far";
  run.wall_seconds = run.cpu_seconds = *seconds;
  return run;
}

}  // namespace dlab::baselines
