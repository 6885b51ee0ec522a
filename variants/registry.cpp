// The registry: algorithm x kernel names -> the translation unit that runs
// them (variants/bw_<kernel>.cpp, ...).  Other algorithms add rows here.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "variants/run.hpp"

namespace dlab {

RunResult run_bowyer_watson_adaptive(PointSet&&, const RunOptions&);
RunResult run_bowyer_watson_float(PointSet&&, const RunOptions&);
RunResult run_bowyer_watson_mp(PointSet&&, const RunOptions&);
RunResult run_bowyer_watson_epsilon(PointSet&&, const RunOptions&);
RunResult run_bowyer_watson_integer(PointSet&&, const RunOptions&);
RunResult run_george_integer(PointSet&&, const RunOptions&);
RunResult run_george_adaptive(PointSet&&, const RunOptions&);
RunResult run_george_mp(PointSet&&, const RunOptions&);
RunResult run_george_float(PointSet&&, const RunOptions&);
RunResult run_george_epsilon(PointSet&&, const RunOptions&);
RunResult run_lawson_adaptive(PointSet&&, const RunOptions&);
RunResult run_lawson_float(PointSet&&, const RunOptions&);
RunResult run_lawson_mp(PointSet&&, const RunOptions&);
RunResult run_lawson_epsilon(PointSet&&, const RunOptions&);
RunResult run_lawson_integer(PointSet&&, const RunOptions&);
RunResult run_tanemura_adaptive(PointSet&&, const RunOptions&);
RunResult run_tanemura_integer(PointSet&&, const RunOptions&);
RunResult run_tanemura_mp(PointSet&&, const RunOptions&);
RunResult run_tanemura_float(PointSet&&, const RunOptions&);
RunResult run_tanemura_epsilon(PointSet&&, const RunOptions&);
RunResult run_parallel_bowyer_watson_adaptive(PointSet&&, const RunOptions&);
RunResult run_parallel_bowyer_watson_integer(PointSet&&, const RunOptions&);
RunResult run_parallel_bowyer_watson_mp(PointSet&&, const RunOptions&);

namespace {

struct Entry {
  const char* algorithm;
  const char* kernel;
  RunResult (*run)(PointSet&&, const RunOptions&);
};

const Entry kEntries[] = {
    {"bowyer-watson", "adaptive", &run_bowyer_watson_adaptive},
    {"bowyer-watson", "integer", &run_bowyer_watson_integer},
    {"bowyer-watson", "mp", &run_bowyer_watson_mp},
    {"bowyer-watson", "float", &run_bowyer_watson_float},
    {"bowyer-watson", "epsilon", &run_bowyer_watson_epsilon},
    {"george", "integer", &run_george_integer},
    {"george", "adaptive", &run_george_adaptive},
    {"george", "mp", &run_george_mp},
    {"george", "float", &run_george_float},
    {"george", "epsilon", &run_george_epsilon},
    {"lawson", "adaptive", &run_lawson_adaptive},
    {"lawson", "integer", &run_lawson_integer},
    {"lawson", "mp", &run_lawson_mp},
    {"lawson", "float", &run_lawson_float},
    {"lawson", "epsilon", &run_lawson_epsilon},
    {"tanemura", "adaptive", &run_tanemura_adaptive},
    {"tanemura", "integer", &run_tanemura_integer},
    {"tanemura", "mp", &run_tanemura_mp},
    {"tanemura", "float", &run_tanemura_float},
    {"tanemura", "epsilon", &run_tanemura_epsilon},
};

// --threads T: the parallel Bowyer–Watson (exact kernels only).
const Entry kParallelEntries[] = {
    {"bowyer-watson", "adaptive", &run_parallel_bowyer_watson_adaptive},
    {"bowyer-watson", "integer", &run_parallel_bowyer_watson_integer},
    {"bowyer-watson", "mp", &run_parallel_bowyer_watson_mp},
};

const char* const kKernels[] = {"adaptive", "integer", "mp", "float", "epsilon"};
const char* const kAlgorithms[] = {"bowyer-watson", "lawson", "tanemura", "george"};

template <int D>
void check_points(const std::vector<Point<D>>& pts) {
  if (pts.size() >= std::numeric_limits<std::uint32_t>::max() - 1)
    throw UsageError("too many points (" + std::to_string(pts.size()) + "): at most 2^32 - 2");
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (double c : pts[i])
      if (!std::isfinite(c))
        throw UsageError("point " + std::to_string(i) + " has a non-finite coordinate");
}

}  // namespace

std::vector<std::string> algorithm_names() { return {std::begin(kAlgorithms), std::end(kAlgorithms)}; }
std::vector<std::string> kernel_names() { return {std::begin(kKernels), std::end(kKernels)}; }
bool kernel_is_exact(std::string_view kernel) { return kernel != "float" && kernel != "epsilon"; }

RunResult run(PointSet&& points, const RunOptions& options) {
  const auto algos = algorithm_names();
  const auto kernels = kernel_names();
  if (std::find(algos.begin(), algos.end(), options.algorithm) == algos.end())
    throw UsageError("unknown algorithm '" + options.algorithm +
                     "' (expected bowyer-watson, lawson, tanemura or george)");
  if (std::find(kernels.begin(), kernels.end(), options.kernel) == kernels.end())
    throw UsageError("unknown kernel '" + options.kernel +
                     "' (expected adaptive, integer, mp, float or epsilon)");
  if ((options.exact_sphere || options.enclosing_box) && options.algorithm != "george")
    throw UsageError("--exact-sphere and --enclosing-box are options of --algo george only");
  if (points.dimension == 2)
    check_points<2>(points.p2);
  else if (points.dimension == 3)
    check_points<3>(points.p3);
  else
    throw UsageError("dimension must be 2 or 3, not " + std::to_string(points.dimension));
  if (options.threads > 0) {
    if (options.algorithm != "bowyer-watson")
      throw UsageError("--threads is an option of --algo bowyer-watson only");
    if (!kernel_is_exact(options.kernel))
      throw UsageError("--threads needs an exact kernel (adaptive, integer or mp): with inexact predicates "
                       "the result would depend on the threads' schedule");
    if (options.policy != "sos")
      throw UsageError("--threads needs --policy sos: without the perturbation a degenerate input has several "
                       "Delaunay triangulations, and the schedule would choose among them");
    if (options.location != "walk") throw UsageError("--threads needs --location walk");
    if (options.threads > 255) throw UsageError("--threads must be in 1..255");
    for (const Entry& e : kParallelEntries)
      if (options.kernel == e.kernel) return e.run(std::move(points), options);
  }
  for (const Entry& e : kEntries)
    if (options.algorithm == e.algorithm && options.kernel == e.kernel) return e.run(std::move(points), options);
  throw UsageError("algorithm '" + options.algorithm + "' is not available with kernel '" +
                   options.kernel + "' yet");
}

RunResult run(const PointSet& points, const RunOptions& options) {
  PointSet copy = points;
  return run(std::move(copy), options);
}

}  // namespace dlab
