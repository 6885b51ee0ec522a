// The registry of external baselines (studies/baselines.hpp): names, which
// executables they use, duplicates mapped to their first occurrence, and the
// exact validator's verdict on their output.
#include "studies/baselines.hpp"

#include <array>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <map>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "algorithms/validate.hpp"
#include "studies/baselines_process.hpp"
#include "studies/baselines_tools.hpp"
#include "variants/outcome.hpp"

namespace dlab {
namespace baselines {

void write_coordinate(std::FILE* f, double x) { std::fprintf(f, "%.17g", x); }

void write_point_file(const std::filesystem::path& file, const std::string& header, const PointSet& points,
                      bool numbered) {
  std::FILE* f = std::fopen(file.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + file.string());
  std::fputs(header.c_str(), f);
  const int d = points.dimension;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (numbered) std::fprintf(f, "%zu ", i);
    for (int j = 0; j < d; ++j) {
      if (j) std::fputc(' ', f);
      write_coordinate(f, d == 2 ? points.p2[i][j] : points.p3[i][j]);
    }
    std::fputc('\n', f);
  }
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + file.string());
}

std::optional<double> number_after(const std::string& text, const std::string& key) {
  const auto at = text.find(key);
  if (at == std::string::npos) return std::nullopt;
  std::istringstream s(text.substr(at + key.size(), 64));
  double x = 0;
  if (!(s >> x)) return std::nullopt;
  return x;
}

bool read_index_lines(std::istream& in, int d, BaselineRun& run) {
  for (std::string line; std::getline(in, line);) {
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

std::string first_line(std::string_view text) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    const std::size_t end = std::min(text.find('\n', begin), text.size());
    std::string_view line = text.substr(begin, end - begin);
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ' || line.back() == '\t'))
      line.remove_suffix(1);
    if (line.find_first_not_of(" \t") != std::string_view::npos) {
      line.remove_prefix(line.find_first_not_of(" \t"));
      if (const auto cut = line.find(".  "); cut != std::string_view::npos) line = line.substr(0, cut + 1);
      return std::string(line.substr(0, 300));
    }
    begin = end + 1;
  }
  return {};
}

double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

double wall_seconds_now() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

namespace {

// An environment override: nullopt when unset; its value (maybe empty) when set.
std::optional<std::string> env(const char* name) {
  const char* v = std::getenv(name);
  if (!v) return std::nullopt;
  return std::string(v);
}

// Does `python` import scipy.spatial? Asked once per interpreter and process.
bool imports_scipy(const std::filesystem::path& python) {
  static std::mutex mutex;
  static std::map<std::string, bool> known;
  const std::lock_guard lock(mutex);
  if (const auto it = known.find(python.string()); it != known.end()) return it->second;
  bool ok = false;
  try {
    TempDir dir;
    const auto r = run_process({python.string(), "-c", "import scipy.spatial"}, dir.path(), std::nullopt,
                               dir.path() / "out", dir.path() / "err", 60);
    ok = r.started && !r.timed_out && !r.signal && r.exit_status == 0;
  } catch (const std::exception&) {
    ok = false;
  }
  known[python.string()] = ok;
  return ok;
}

// An executable named by the variable `var` if set, else `fallback` in PATH.
std::optional<std::string> executable(const char* var, const std::string& fallback, const std::string& what,
                                      std::string* why) {
  const auto over = env(var);
  const std::string name = over ? *over : fallback;
  if (const auto path = find_executable(name)) return path->string();
  *why = what + " not found: " + (over ? std::string(var) + "=" + name : name + " is not in PATH") +
         (over ? "" : " (or set " + std::string(var) + ")");
  return std::nullopt;
}

}  // namespace

std::optional<std::string> tool_path(const std::string& name, std::string* why) {
  if (name == "tetgen") return executable("DLAB_TETGEN", "tetgen", "tetgen (Debian package tetgen)", why);
  if (name == "qhull") return executable("DLAB_QDELAUNAY", "qdelaunay", "qdelaunay (Debian package qhull-bin)", why);
  if (name == "scipy") {
    if (!std::filesystem::exists(DLAB_SCIPY_SCRIPT)) {
      *why = std::string("the script ") + DLAB_SCIPY_SCRIPT + " is missing";
      return std::nullopt;
    }
    std::vector<std::string> candidates;
    if (const auto over = env("DLAB_PYTHON"))
      candidates = {*over};
    else
      candidates = {"/usr/bin/python3", "python3"};
    for (const auto& c : candidates)
      if (const auto path = find_executable(c); path && imports_scipy(*path)) return path->string();
    *why = "no Python that imports scipy.spatial (Debian package python3-scipy): tried ";
    for (std::size_t i = 0; i < candidates.size(); ++i) *why += (i ? ", " : "") + candidates[i];
    if (!env("DLAB_PYTHON")) *why += " (or set DLAB_PYTHON)";
    return std::nullopt;
  }
  *why = "unknown baseline " + name;
  return std::nullopt;
}

namespace {

// Replaces each index of a duplicated point by its first occurrence (-0.0 and
// +0.0 equal, as everywhere in dlab); indices out of range are left for the
// validator to report.
template <int D>
void first_occurrences(const std::vector<Point<D>>& pts, std::vector<std::uint32_t>& simplices) {
  struct Hash {
    std::size_t operator()(const std::array<double, D>& p) const {
      std::size_t h = 0;
      for (double x : p) h = h * 1000003u ^ std::hash<double>{}(x == 0 ? 0.0 : x);
      return h;
    }
  };
  std::unordered_map<std::array<double, D>, std::uint32_t, Hash> first;
  first.reserve(pts.size());
  std::vector<std::uint32_t> canonical(pts.size());
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    std::array<double, D> key;
    for (int j = 0; j < D; ++j) key[j] = pts[i][j];
    canonical[i] = first.emplace(key, i).first->second;
  }
  for (auto& v : simplices)
    if (v < canonical.size()) v = canonical[v];
}

}  // namespace
}  // namespace baselines

std::vector<std::string> baseline_names() { return {"cgal-epick", "cgal-epeck", "tetgen", "qhull", "scipy"}; }

std::optional<std::string> baseline_unavailable(const std::string& name) {
  if (name == "cgal-epick" || name == "cgal-epeck") return baselines::cgal_unavailable();
  std::string why;
  if (baselines::tool_path(name, &why)) return std::nullopt;
  return why;
}

BaselineRun run_baseline(const std::string& name, const PointSet& points, const BaselineOptions& options) {
  BaselineRun run;
  if (name == "cgal-epick" || name == "cgal-epeck")
    run = baselines::run_cgal(points, name == "cgal-epeck");
  else if (name == "tetgen")
    run = baselines::run_tetgen(points, options);
  else if (name == "qhull")
    run = baselines::run_qhull(points, options);
  else if (name == "scipy")
    run = baselines::run_scipy(points, options);
  else
    throw std::invalid_argument("unknown baseline " + name);
  if (run.skipped) run.outcome = "skipped";
  if (run.outcome == "ok-so-far") {
    if (points.dimension == 2)
      baselines::first_occurrences<2>(points.p2, run.simplices);
    else
      baselines::first_occurrences<3>(points.p3, run.simplices);
  }
  return run;
}

void classify_baseline(const PointSet& points, BaselineRun& run, ValidationReport* report) {
  if (run.outcome == "reported") {
    // A tool that refuses input of too low a dimension is right to.
    const ValidationReport empty = validate(points, {});
    if (empty.lower_dimensional) run.outcome = "lower-dimensional";
    if (report) *report = empty;
    return;
  }
  if (run.outcome != "ok-so-far") return;
  std::vector<std::uint32_t> oriented = run.simplices;
  const ValidationReport rep = [&] {
    orient_positively(points, oriented);
    return validate(points, oriented);
  }();
  const Outcome o = classify_report(rep, false);
  run.outcome = std::string(outcome_name(o.kind));
  run.message = o.detail;
  if (o.kind == OutcomeClass::invalid && o.first_check == Check::missing_vertex) {
    run.outcome = "missing-points";
    if (const auto nd = rep.non_delaunay_facets())
      run.message += "; " + std::to_string(nd) + " facets not locally Delaunay";
  }
  if (report) *report = rep;
}

}  // namespace dlab
