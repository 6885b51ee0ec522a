// The baselines one by one (private to studies/baselines*.cpp). Each returns
// the tool's simplices as the tool numbered them, or a final outcome;
// run_baseline() (baselines.cpp) then maps duplicate points to their first
// occurrence. What each timer covers is said at each function's definition.
#pragma once
#include <cstdio>
#include <filesystem>
#include <istream>
#include <optional>
#include <string>
#include <string_view>

#include "studies/baselines.hpp"

namespace dlab::baselines {

// cgal-epick (exact = false) and cgal-epeck (exact = true): baselines_cgal.cpp,
// the only translation unit that includes CGAL.
BaselineRun run_cgal(const PointSet& points, bool exact);
std::optional<std::string> cgal_unavailable();  // "built without CGAL", or nullopt

BaselineRun run_tetgen(const PointSet& points, const BaselineOptions& options);  // baselines_tetgen.cpp
BaselineRun run_qhull(const PointSet& points, const BaselineOptions& options);   // baselines_qhull.cpp
BaselineRun run_scipy(const PointSet& points, const BaselineOptions& options);   // baselines_scipy.cpp

// The executables, after the environment overrides (baselines.cpp): DLAB_TETGEN,
// DLAB_QDELAUNAY, DLAB_PYTHON. nullopt with the reason in `why` when missing.
std::optional<std::string> tool_path(const std::string& name, std::string* why);

// Writes `x` with 17 significant digits ("%.17g"): every double, subnormals
// included, reads back to itself with a correctly rounded reader (glibc's
// strtod, which TetGen and Qhull use; Python's float()), because 17
// significant decimal digits identify a binary64 value uniquely (IEEE 754-2008
// section 5.12.2). Infinite and NaN coordinates never get here (the point
// readers refuse them).
void write_coordinate(std::FILE* f, double x);

// Writes `header` then one point per line ("I X Y [Z]" with its zero-based
// index I when `numbered`, else "X Y [Z]"), coordinates by write_coordinate.
// Throws std::runtime_error when the file cannot be written.
void write_point_file(const std::filesystem::path& file, const std::string& header, const PointSet& points,
                      bool numbered);

// Reads lines of exactly d+1 non-negative indices (up to the end of `in`)
// into `run.simplices`; false at the first malformed line.
bool read_index_lines(std::istream& in, int d, BaselineRun& run);

// The number after the first occurrence of `key` in `text` (a tool's timing
// line), or nullopt.
std::optional<double> number_after(const std::string& text, const std::string& key);

// The first line of `text` that is not blank, cut at its first ".  " (Qhull
// continues a message with advice after two spaces) and at 300 characters.
std::string first_line(std::string_view text);

// Seconds of the process's CPU time (CLOCK_PROCESS_CPUTIME_ID) and of a steady wall clock.
double process_cpu_seconds();
double wall_seconds_now();

}  // namespace dlab::baselines
