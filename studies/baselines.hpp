// External Delaunay baselines for `dlab study` (issue 13; contract in
// studies/README.md): CGAL in process, TetGen, Qhull's qdelaunay and
// scipy.spatial.Delaunay as child processes. Each runs on a PointSet and gives
// back simplices as indices into the input, plus the time the tool spent
// triangulating (what each timer covers is documented per tool in
// baselines.cpp and below).
//
// Who validates: run_baseline() does NOT validate. It returns the tool's
// simplices (d+1 zero-based indices into the input, either orientation, a
// duplicate point referring to its first occurrence when the tool exposes
// which copy it kept) and an outcome that is either final (`reported`,
// `crash`, `timeout`, skipped) or `ok-so-far`. The caller then judges an
// `ok-so-far` run with classify_baseline(), which runs the exact validator
// (algorithms/validate.hpp, orientation any) and gives `ok`,
// `lower-dimensional`, `missing-points`, `invalid` or `not-delaunay`.
// Timing: wall_seconds and cpu_seconds never include process start, file I/O
// or validation; TetGen and Qhull time themselves with clock() (CPU time) only,
// and both fields carry that number (baselines_tetgen.cpp, baselines_qhull.cpp).
//
// Tool names (README.md): cgal-epick, cgal-epeck, tetgen, qhull, scipy.
// Executables can be overridden with environment variables (tests use them to
// simulate a missing tool): DLAB_TETGEN, DLAB_QDELAUNAY, DLAB_PYTHON (an
// interpreter that imports scipy; default: the first of /usr/bin/python3,
// python3 on PATH that does). An empty or nonexistent override makes the tool
// unavailable.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "variants/run.hpp"

namespace dlab {

struct ValidationReport;  // algorithms/validate.hpp

struct BaselineRun {
  // Before classify_baseline(): "ok-so-far" (simplices to be judged),
  // "reported" (the tool itself refused: Qhull's precision error, scipy's
  // QhullError, TetGen's error exit; `message` holds its first line),
  // "crash" (killed by a signal or an unexpected exit status / unreadable
  // output), "timeout" (killed at the time limit), "skipped" (see `skipped`).
  // After classify_baseline(): "ok", "lower-dimensional", "missing-points",
  // "invalid", "not-delaunay" replace "ok-so-far"; "reported" on
  // lower-dimensional input becomes "lower-dimensional" (the tool's message kept).
  std::string outcome;
  std::string message;       // one line, no newline; empty for ok
  double wall_seconds = 0;   // the tool's triangulation alone (see baselines.cpp per tool)
  double cpu_seconds = 0;    // ditto, CPU time; 0 where the tool reports none
  std::vector<std::uint32_t> simplices;  // (d+1) indices per finite simplex, any orientation
  bool skipped = false;      // the tool cannot run here or on this input: `message` says why
};

struct BaselineOptions {
  double timeout_seconds = 60;  // external processes are killed after this (wall clock)
};

// "cgal-epick", "cgal-epeck", "tetgen", "qhull", "scipy".
std::vector<std::string> baseline_names();

// Why `name` cannot run on this machine (tool not installed, no scipy, unknown
// name), or nullopt when it can. Cheap after the first call per name (cached
// per process; the environment overrides are read on each call).
std::optional<std::string> baseline_unavailable(const std::string& name);

// Runs one baseline. Never throws for a tool's failure: it becomes the outcome.
// Returns skipped (with the reason in `message`) when the tool is unavailable
// or cannot take this input (tetgen in 2D). Throws std::invalid_argument for
// an unknown name.
BaselineRun run_baseline(const std::string& name, const PointSet& points,
                         const BaselineOptions& options = {});

// Judges an "ok-so-far" run with the exact validator (orientation any: the
// simplices are re-oriented positively on a copy) and sets `outcome` and
// `message`: ok | lower-dimensional | missing-points (a distinct input point
// is no vertex, and nothing else is wrong) | invalid | not-delaunay. Other
// outcomes are returned unchanged. If `report` is non-null it receives the
// validator's report.
void classify_baseline(const PointSet& points, BaselineRun& run,
                       ValidationReport* report = nullptr);

}  // namespace dlab
