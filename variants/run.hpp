// The one entry point that the command line, the tests and the benchmarks use
// to triangulate: pick algorithm x kernel x policy x order by name, run, and get
// the finite simplices back with the counters of the run.
#pragma once
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/run_outcome.hpp"
#include "predicates/counters.hpp"
#include "predicates/point_set.hpp"

namespace dlab {

struct ValidationReport;  // algorithms/validate.hpp

struct RunOptions {
  std::string algorithm = "bowyer-watson";  // bowyer-watson | lawson | tanemura | george
  std::string kernel = "adaptive";          // adaptive | integer | mp | float | epsilon
  std::string policy = "sos";               // sos | strict
  std::string order = "brio";               // input | random | brio | hilbert
  // Point location of the incremental algorithms: walk (the visibility walk
  // from the last insertion) | scan (no location structure: every live simplex
  // tested in storage order; bowyer-watson and lawson only).
  std::string location = "walk";
  std::uint64_t seed = 0;
  // 0: the algorithm as it is; T >= 1: bowyer-watson's parallel variant with T
  // workers (algorithms/parallel_bowyer_watson.hpp; exact kernels, sos), whose
  // simplices are written in canonical order.
  unsigned threads = 0;
  // Simplices in canonical order (algorithms/canonical_simplices.hpp): each
  // rotated or permuted evenly to start at its smallest index, the list sorted,
  // so that equal triangulations are equal files, whatever produced them.
  bool canonical = false;
  bool exact_sphere = false;   // george: exact circumsphere test (default: the floating sphere test)
  bool enclosing_box = false;  // george: the paper's enclosing box instead of the ghost vertex
};

// Thrown for an unknown algorithm / kernel / policy / order name, or a
// combination that does not exist: the caller reports it as a usage error (exit 2).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct RunResult {
  using Outcome = RunOutcome;  // ok, lower_dimensional, failed (algorithms/run_outcome.hpp)
  Outcome outcome = Outcome::ok;
  std::string message;  // why lower-dimensional, or what failed
  int dimension = 2;
  // (dimension+1) zero-based indices per finite simplex, each positively
  // oriented (det[v1-v0; ...; vd-v0] > 0); duplicates refer to their first
  // occurrence in the input.
  std::vector<std::uint32_t> simplices;
  PointSet points;           // the points actually triangulated (snapped by `integer`)
  std::size_t distinct_points = 0;  // of the input (of the snapped points for `integer`)
  // Input points the algorithm processed -- inserted as a vertex or found to
  // duplicate one -- before it stopped: all of them after a run to the end,
  // fewer after a failure, 0 for lower-dimensional input (no simplex is built).
  std::size_t inserted_points = 0;
  double seconds = 0;        // triangulating only
  double cpu_seconds = 0;    // CPU time over the same span (CLOCK_THREAD_CPUTIME_ID: variants/driver.hpp)
  // `seconds` in three consecutive parts (wall time): putting the points in
  // insertion order, the algorithm's run (taking the simplices out of its mesh
  // included), and mapping them to input indices and sorting them (--canonical,
  // --threads).  Zero where they are not timed (`dlab flip`).
  struct Phases {
    double order = 0, triangulate = 0, output = 0;
  } phase_seconds;
  Counters counters;         // algorithm counters: "walk_steps", "cavity_simplices", "flips_2_3", ...
  Counters predicates;       // "orient2d", "orient2d.A", ... calls per predicate and per stage answered
  Counters snapping;         // integer kernel: "points_moved", "points_merged", ...; empty otherwise
  double max_snap_displacement = 0;
  // The exact validator's verdict on `simplices`, when the run computed it
  // (George's runs do, variants/george_run.hpp); variants/outcome.hpp reuses it.
  std::shared_ptr<const ValidationReport> validation;
};

// Triangulates `points` with the algorithm and kernel `options` name. The
// first form copies them; the second takes them, so that a large input is not
// held twice (`dlab triangulate`): they end in the result's `points`, in their
// order (snapped by `integer`); after an exception they are left in `points`
// as they were.
RunResult run(const PointSet& points, const RunOptions& options);
RunResult run(PointSet&& points, const RunOptions& options);

std::vector<std::string> algorithm_names();
std::vector<std::string> kernel_names();
// adaptive, integer, mp: true; float, epsilon (the inexact baselines): false.
bool kernel_is_exact(std::string_view kernel);

}  // namespace dlab
