// qhull: `qdelaunay Qt i s` from Qhull 2020.2 (Barber, Dobkin, Huhdanpaa,
// "The Quickhull algorithm for convex hulls", ACM TOMS 22(4), 1996), Debian's
// qhull-bin. The Delaunay triangulation is the lower hull of the points lifted
// to a paraboloid.
//
// Options: Qhull's own for a Delaunay triangulation on the command line, no
// more: `Qt` (triangulate the non-simplicial regions of cocircular or
// cospherical points -- the result may then hold simplices of zero volume, as
// Qhull's documentation warns), `i` (the regions as input indices), `s` (the
// summary with the timing). qdelaunay's defaults add Qbb (scale the lifted
// coordinate). Not `Qz` (a point at infinity for cospherical input) nor `QJ`
// (joggle): scipy's run (baselines_scipy.cpp) uses Qz, so the two baselines
// show Qhull both ways.
//
// Timed: Qhull's "CPU seconds to compute hull (after input)" -- clock(), the
// process's CPU time, from after the input is read to the end of the hull,
// before any output. Qhull has no wall-clock timer; it is single-threaded,
// and both wall_seconds and cpu_seconds carry that number.
//
// Failures: a precision or topology error prints "QH6xxx qhull precision
// error: ..." on stderr and exits non-zero: `reported`, with the message's
// first sentence. Duplicates and points within roundoff of the lifted hull are
// left out of the output (coplanar points): run_baseline() maps a duplicate
// to its first occurrence, and a near-duplicate left out is a missing point.
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studies/baselines_process.hpp"
#include "studies/baselines_tools.hpp"

namespace dlab::baselines {
namespace {

// Reads "M" then M lines of d+1 indices; false if malformed (e.g. a
// non-simplicial region, which `Qt` rules out).
bool read_regions(const std::filesystem::path& file, int d, BaselineRun& run) {
  std::ifstream in(file);
  std::size_t m = 0;
  std::string line;
  if (!std::getline(in, line) || !(std::istringstream(line) >> m)) return false;
  return read_index_lines(in, d, run) && run.simplices.size() == (d + 1) * m;
}

}  // namespace

BaselineRun run_qhull(const PointSet& points, const BaselineOptions& options) {
  BaselineRun run;
  std::string why;
  const auto exe = tool_path("qhull", &why);
  if (!exe) {
    run.skipped = true;
    run.message = why;
    return run;
  }
  TempDir dir;
  const auto input = dir.path() / "points.txt";
  write_point_file(input, std::to_string(points.dimension) + "\n" + std::to_string(points.size()) + "\n",
                   points, false);
  const auto out = dir.path() / "stdout", err = dir.path() / "stderr";
  const ProcessResult p =
      run_process({*exe, "Qt", "i", "s"}, dir.path(), input, out, err, options.timeout_seconds);
  const std::string summary = read_text(err);
  if (p.timed_out || !p.started || p.signal) {
    run.outcome = p.timed_out ? "timeout" : "crash";
    run.message = "qdelaunay " + describe(p, options.timeout_seconds);
    return run;
  }
  if (p.exit_status != 0) {
    run.outcome = "reported";
    run.message = first_line(summary);
    if (run.message.empty()) run.message = "qdelaunay " + describe(p, options.timeout_seconds);
    return run;
  }
  const auto seconds = number_after(summary, "CPU seconds to compute hull (after input):");
  if (!seconds || !read_regions(out, points.dimension, run)) {
    run.simplices.clear();
    run.outcome = "crash";
    run.message = seconds ? "qdelaunay wrote unreadable regions" : "qdelaunay printed no CPU seconds";
    return run;
  }
  run.outcome = "ok-so-far";
  run.wall_seconds = run.cpu_seconds = *seconds;
  return run;
}

}  // namespace dlab::baselines
