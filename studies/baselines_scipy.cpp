// scipy: scipy.spatial.Delaunay (Virtanen et al., "SciPy 1.0", Nature Methods
// 17, 2020), i.e. Qhull through its library with scipy's options "Qbb Qc Qz
// Q12 Qt", run by studies/baselines/scipy_delaunay.py in a Python that
// imports scipy (baselines.cpp picks it).
//
// Timed: inside Python, the Delaunay(points) call alone -- time.perf_counter
// (wall) and time.process_time (CPU) -- not the interpreter's start, the
// import of scipy, reading the points or writing the simplices.
//
// Failures: QhullError -> `reported` with its first line; the script's other
// non-zero exits and signals -> `crash`.
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studies/baselines_process.hpp"
#include "studies/baselines_tools.hpp"

namespace dlab::baselines {
namespace {

constexpr int kReportedExit = 3;  // scipy_delaunay.py after a QhullError

}  // namespace

BaselineRun run_scipy(const PointSet& points, const BaselineOptions& options) {
  BaselineRun run;
  std::string why;
  const auto python = tool_path("scipy", &why);
  if (!python) {
    run.skipped = true;
    run.message = why;
    return run;
  }
  TempDir dir;
  write_point_file(dir.path() / "points.txt",
                   std::to_string(points.dimension) + " " + std::to_string(points.size()) + "\n", points, false);
  const auto out = dir.path() / "stdout", err = dir.path() / "stderr";
  const ProcessResult p = run_process({*python, DLAB_SCIPY_SCRIPT, "points.txt", "simplices.txt"},
                                      dir.path(), std::nullopt, out, err, options.timeout_seconds);
  const std::string text = read_text(out);
  if (p.started && !p.timed_out && !p.signal && p.exit_status == kReportedExit &&
      text.rfind("reported: ", 0) == 0) {
    run.outcome = "reported";
    run.message = first_line(text.substr(10));
    return run;
  }
  if (!p.started || p.timed_out || p.signal || p.exit_status != 0) {
    run.outcome = p.timed_out ? "timeout" : "crash";
    run.message = "scipy " + describe(p, options.timeout_seconds);
    // A Python traceback ends with the exception.
    std::istringstream e(read_text(err));
    std::string last;
    for (std::string line; std::getline(e, line);)
      if (!line.empty()) last = line;
    if (!last.empty()) run.message += ": " + first_line(last);
    return run;
  }
  double wall = 0, cpu = 0;
  std::string word;
  std::istringstream s(text);
  std::ifstream simplices(dir.path() / "simplices.txt");
  if (!(s >> word >> wall >> cpu) || word != "seconds" ||
      !read_index_lines(simplices, points.dimension, run)) {
    run.simplices.clear();
    run.outcome = "crash";
    run.message = "scipy_delaunay.py wrote unreadable output";
    return run;
  }
  run.outcome = "ok-so-far";
  run.wall_seconds = wall;
  run.cpu_seconds = cpu;
  return run;
}

}  // namespace dlab::baselines
