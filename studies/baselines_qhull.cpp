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

// The number after "CPU seconds to compute hull (after input):", or nullopt.
std::optional<double> hull_seconds(const std::string& summary) {
  const std::string key = "CPU seconds to compute hull (after input):";
  const auto at = summary.find(key);
  if (at == std::string::npos) return std::nullopt;
  std::istringstream s(summary.substr(at + key.size(), 64));
  double x = 0;
  if (!(s >> x)) return std::nullopt;
  return x;
}

// Reads "M" then M lines of d+1 indices; false if malformed (e.g. a
// non-simplicial region, which `Qt` rules out).
bool read_regions(const std::filesystem::path& file, int d, BaselineRun& run) {
  std::ifstream in(file);
  std::string line;
  std::size_t m = 0;
  if (!std::getline(in, line) || !(std::istringstream(line) >> m)) return false;
  run.simplices.reserve((d + 1) * m);
  for (std::size_t r = 0; r < m; ++r) {
    if (!std::getline(in, line)) return false;
    std::istringstream s(line);
    long long v = 0;
    int count = 0;
    while (s >> v) {
      if (v < 0 || v > 0xffffffffLL || ++count > d + 1) return false;
      run.simplices.push_back(static_cast<std::uint32_t>(v));
    }
    if (count != d + 1 || !s.eof()) return false;
  }
  return true;
}

template <int D>
void write_points(std::FILE* f, const std::vector<Point<D>>& pts) {
  std::fprintf(f, "%d\n%zu\n", D, pts.size());
  for (const auto& p : pts) {
    for (int j = 0; j < D; ++j) {
      if (j) std::fputc(' ', f);
      write_coordinate(f, p[j]);
    }
    std::fputc('\n', f);
  }
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
  {
    std::FILE* f = std::fopen(input.c_str(), "w");
    if (!f) throw std::runtime_error("cannot write " + input.string());
    if (points.dimension == 2)
      write_points<2>(f, points.p2);
    else
      write_points<3>(f, points.p3);
    if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + input.string());
  }
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
  const auto seconds = hull_seconds(summary);
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
