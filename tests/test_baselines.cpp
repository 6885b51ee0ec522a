// The external baselines of `dlab study` (studies/baselines.hpp). Each tool
// that is installed is checked against dlab's own exact run (Bowyer-Watson x
// adaptive with symbolic perturbation, whose triangulation is unique) and the
// exact validator; a tool that is missing must be skipped with a reason. The
// ctest tests baselines.common / .cgal / .tetgen / .qhull / .scipy run the
// tags below.
#include <catch2/catch.hpp>

#include <sys/types.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "studies/baselines.hpp"
#include "studies/baselines_process.hpp"
#include "studies/baselines_tools.hpp"
#include "variants/run.hpp"

namespace {

using dlab::BaselineRun;
using dlab::PointSet;

// Sets an environment variable for one scope, restoring the old value after.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const std::string& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    setenv(name, value.c_str(), 1);
  }
  ~ScopedEnv() {
    if (old_)
      setenv(name_, old_->c_str(), 1);
    else
      unsetenv(name_);
  }

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// Each simplex's vertex set sorted, then the list sorted: orientation-free.
std::vector<std::vector<std::uint32_t>> canonical(const std::vector<std::uint32_t>& flat, int d) {
  std::vector<std::vector<std::uint32_t>> out;
  for (std::size_t i = 0; i < flat.size(); i += d + 1) {
    std::vector<std::uint32_t> s(flat.begin() + i, flat.begin() + i + d + 1);
    std::sort(s.begin(), s.end());
    out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// dlab's exact triangulation (the symbolically perturbed one, identical to
// CGAL's by design.md section 2).
std::vector<std::vector<std::uint32_t>> dlab_reference(const PointSet& ps) {
  const dlab::RunResult r = dlab::run(ps, dlab::RunOptions{});
  REQUIRE(r.outcome == dlab::RunResult::Outcome::ok);
  return canonical(r.simplices, ps.dimension);
}

BaselineRun run_and_classify(const std::string& tool, const PointSet& ps, double timeout = 60) {
  BaselineRun run = dlab::run_baseline(tool, ps, dlab::BaselineOptions{timeout});
  dlab::classify_baseline(ps, run);
  return run;
}

// True (after a WARN) when `tool` cannot run here; then run_baseline must say skipped.
bool unavailable(const std::string& tool) {
  const auto why = dlab::baseline_unavailable(tool);
  if (!why) return false;
  WARN(tool << " unavailable: " << *why);
  const BaselineRun run = dlab::run_baseline(tool, dlab::point_set<3>(dlab::gen::uniform<3>(10, 1)));
  CHECK(run.skipped);
  CHECK(run.outcome == "skipped");
  CHECK(run.message == *why);
  return true;
}

// A uniform set whose Delaunay triangulation is unique: every tool must give
// exactly dlab's simplices, validated as Delaunay.
void agrees_on_uniform(const std::string& tool, int d) {
  const PointSet ps = d == 2 ? dlab::point_set<2>(dlab::gen::uniform<2>(300, 7))
                             : dlab::point_set<3>(dlab::gen::uniform<3>(300, 7));
  dlab::ValidationReport rep;
  BaselineRun run = dlab::run_baseline(tool, ps);
  dlab::classify_baseline(ps, run, &rep);
  INFO(tool << " " << d << "D: " << run.outcome << " " << run.message);
  REQUIRE(run.outcome == "ok");
  CHECK(rep.delaunay());
  CHECK(rep.cospherical_facets == 0);  // so the triangulation is unique
  CHECK(canonical(run.simplices, d) == dlab_reference(ps));
  CHECK(run.wall_seconds >= 0);
  CHECK(run.cpu_seconds >= 0);
  CHECK(run.wall_seconds < 10);
}

// Every point twice or three times, copies placed early and late: the output
// refers to first occurrences only and is the triangulation of the distinct points.
void handles_duplicates(const std::string& tool, int d) {
  PointSet ps;
  std::vector<std::uint32_t> first_of;
  if (d == 2) {
    auto p = dlab::gen::uniform<2>(60, 11);
    const auto distinct = p;
    for (std::size_t i = 0; i < 60; i += 3) p.push_back(distinct[i]);
    for (std::size_t i = 0; i < 60; i += 7) p.insert(p.begin() + 5, distinct[59 - i]);
    ps = dlab::point_set<2>(p);
  } else {
    auto p = dlab::gen::uniform<3>(60, 11);
    const auto distinct = p;
    for (std::size_t i = 0; i < 60; i += 3) p.push_back(distinct[i]);
    for (std::size_t i = 0; i < 60; i += 7) p.insert(p.begin() + 5, distinct[59 - i]);
    ps = dlab::point_set<3>(p);
  }
  const BaselineRun run = run_and_classify(tool, ps);
  INFO(tool << " " << d << "D duplicates: " << run.outcome << " " << run.message);
  CHECK(run.outcome == "ok");
  CHECK(canonical(run.simplices, d) == dlab_reference(ps));
}

PointSet collinear_2d() { return dlab::point_set<2>({{0, 0}, {1, 1}, {2, 2}, {0.5, 0.5}, {3, 3}}); }
PointSet coplanar_3d() {  // a tilted plane z = x + y
  return dlab::point_set<3>({{0, 0, 0}, {1, 0, 1}, {0, 1, 1}, {1, 1, 2}, {0.5, 0.25, 0.75}});
}

// An executable shell script in `dir` (a fake tool).
std::string fake_tool(const std::filesystem::path& dir, const std::string& name, const std::string& body) {
  const auto path = dir / name;
  std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path.string();
}

}  // namespace

// ---------------------------------------------------------------- common

TEST_CASE("baselines: the five names, and an unknown one is refused", "[baselines][common]") {
  CHECK(dlab::baseline_names() ==
        std::vector<std::string>{"cgal-epick", "cgal-epeck", "tetgen", "qhull", "scipy"});
  CHECK(dlab::baseline_unavailable("triangle"));
  CHECK_THROWS_AS(dlab::run_baseline("triangle", collinear_2d()), std::invalid_argument);
}

TEST_CASE("baselines: coordinates written with %.17g read back exactly", "[baselines][common]") {
  std::vector<double> xs = {0.1, -0.0, 1.0 / 3, std::numeric_limits<double>::max(),
                            std::numeric_limits<double>::min(), std::numeric_limits<double>::denorm_min(),
                            std::nextafter(1.0, 2.0), std::nextafter(0.001, 1.0), 29.999, 1e-300};
  dlab::gen::SplitMix64 rng(3);
  for (int i = 0; i < 20000; ++i) {  // random bit patterns: every binade, subnormals included
    double x;
    std::uint64_t b = rng.next();
    std::memcpy(&x, &b, sizeof x);
    if (std::isfinite(x)) xs.push_back(x);
  }
  for (double x : xs) {
    char buf[64];
    std::FILE* f = fmemopen(buf, sizeof buf, "w");
    dlab::baselines::write_coordinate(f, x);
    std::fclose(f);
    const double back = std::strtod(buf, nullptr);
    INFO(buf);
    REQUIRE(std::memcmp(&back, &x, sizeof x) == 0);
  }
}

TEST_CASE("baselines: first_line keeps Qhull's first sentence", "[baselines][common]") {
  using dlab::baselines::first_line;
  CHECK(first_line("\n  \nQH6239 Qhull precision error: initial sites are cospherical.  Use option 'Qz'\nmore")
        == "QH6239 Qhull precision error: initial sites are cospherical.");
  CHECK(first_line("  Exception:  All vertices are coplanar (Tol = 1e-08).\r\n") ==
        "Exception:  All vertices are coplanar (Tol = 1e-08).");
  CHECK(first_line("") == "");
  CHECK(first_line(std::string(500, 'x')).size() == 300);
}

TEST_CASE("baselines: classify_baseline judges with the exact validator", "[baselines][common]") {
  // A square with its centre: the four triangles of the centre are its unique
  // Delaunay triangulation (the corners are cocircular, the centre is inside).
  const PointSet square = dlab::point_set<2>({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}});
  const auto judged = [&](const PointSet& ps, std::vector<std::uint32_t> simplices,
                          std::string outcome = "ok-so-far") {
    BaselineRun run;
    run.outcome = outcome;
    run.simplices = std::move(simplices);
    dlab::classify_baseline(ps, run);
    return run;
  };
  SECTION("valid Delaunay, mixed orientations") {
    const auto run = judged(square, {0, 1, 4, 2, 1, 4, 2, 3, 4, 0, 4, 3});
    CHECK(run.outcome == "ok");
    CHECK(run.message.empty());
  }
  SECTION("the centre left out: missing-points") {
    const auto run = judged(square, {0, 1, 2, 0, 2, 3});
    CHECK(run.outcome == "missing-points");
    CHECK(run.message.find("point 4") != std::string::npos);
  }
  SECTION("a hull corner left out: missing-points") {
    // Corner 0 dropped; (1.5, 1.2) lies inside the triangle of the other corners.
    const PointSet off = dlab::point_set<2>({{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1.5, 1.2}});
    const auto run = judged(off, {1, 2, 4, 2, 3, 4, 3, 1, 4});
    CHECK(run.outcome == "missing-points");
    CHECK(run.message.find("point 0") != std::string::npos);
  }
  SECTION("every point a vertex but part of the hull uncovered: invalid") {
    const auto run = judged(square, {0, 1, 4, 1, 2, 4, 2, 3, 4});
    CHECK(run.outcome == "invalid");
  }
  SECTION("the wrong diagonal of a convex quadrilateral: not-delaunay") {
    const PointSet quad = dlab::point_set<2>({{0, 0}, {4, 0}, {5, 3}, {0, 1}});
    // 0 1 3 / 1 2 3 or 0 1 2 / 0 2 3: exactly one is Delaunay (not cocircular).
    const auto a = judged(quad, {0, 1, 3, 1, 2, 3});
    const auto b = judged(quad, {0, 1, 2, 0, 2, 3});
    CHECK(((a.outcome == "ok" && b.outcome == "not-delaunay") ||
           (a.outcome == "not-delaunay" && b.outcome == "ok")));
  }
  SECTION("overlapping triangles: invalid") {
    const auto run = judged(square, {0, 1, 4, 2, 1, 4, 2, 3, 4, 0, 4, 3, 0, 1, 2});
    CHECK(run.outcome == "invalid");
  }
  SECTION("a flat simplex: invalid") {
    const auto run = judged(square, {0, 1, 4, 2, 1, 4, 2, 3, 4, 0, 4, 3, 0, 4, 2});
    CHECK(run.outcome == "invalid");
  }
  SECTION("a tool's refusal: reported, or lower-dimensional on collinear input") {
    auto run = judged(square, {}, "reported");
    CHECK(run.outcome == "reported");
    run = judged(collinear_2d(), {}, "reported");
    CHECK(run.outcome == "lower-dimensional");
    run = judged(collinear_2d(), {}, "ok-so-far");
    CHECK(run.outcome == "lower-dimensional");
  }
  SECTION("final outcomes are left alone") {
    for (const char* o : {"crash", "timeout", "skipped"}) CHECK(judged(square, {0, 1, 2}, o).outcome == o);
  }
}

TEST_CASE("baselines: child processes are timed out, their crashes reported", "[baselines][common]") {
  dlab::baselines::TempDir dir;
  const auto p = dir.path();
  SECTION("a hanging tool is killed at the limit, its children with it") {
    const auto pid_file = p / "background.pid";
    const std::string tool = fake_tool(p, "hang", "sleep 30 & echo $! > " + pid_file.string() + "; sleep 30");
    const ScopedEnv env("DLAB_QDELAUNAY", tool);
    const double t0 = dlab::baselines::wall_seconds_now();
    const auto run = run_and_classify("qhull", collinear_2d(), 0.3);
    CHECK(run.outcome == "timeout");
    CHECK(dlab::baselines::wall_seconds_now() - t0 < 5);
    // The background sleep went too (init reaps it soon after the kill).
    pid_t background = 0;
    REQUIRE(std::ifstream(pid_file) >> background);
    bool gone = false;
    for (int i = 0; i < 200 && !gone; ++i) {
      std::ifstream stat("/proc/" + std::to_string(background) + "/stat");
      std::string pid, comm, state;
      gone = !(stat >> pid >> comm >> state) || state == "Z";
      if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    CHECK(gone);
  }
  SECTION("a tool killed by a signal is a crash") {
    const ScopedEnv env("DLAB_QDELAUNAY", fake_tool(p, "segv", "kill -SEGV $$"));
    const auto run = run_and_classify("qhull", collinear_2d());
    CHECK(run.outcome == "crash");
    CHECK(run.message.find("SIGSEGV") != std::string::npos);
  }
  SECTION("a tool that writes garbage is a crash, not an ok") {
    const ScopedEnv env("DLAB_QDELAUNAY", fake_tool(p, "garbage", "echo 2; echo 0 1 2 3 4; echo x"));
    const auto run = run_and_classify("qhull", collinear_2d());
    CHECK(run.outcome == "crash");
  }
  SECTION("TetGen's uncaught-int error exit is reported with its last words") {
    const ScopedEnv env(
        "DLAB_TETGEN",
        fake_tool(p, "tetgen", "echo 'Exception:  no luck.'; echo \"terminate called after throwing an "
                               "instance of 'int'\" >&2; kill -ABRT $$"));
    const auto run = run_and_classify("tetgen", dlab::point_set<3>(dlab::gen::uniform<3>(10, 1)));
    CHECK(run.outcome == "reported");
    CHECK(run.message == "Exception:  no luck.");
  }
  SECTION("a missing tool is skipped with the reason") {
    for (const auto& [var, tool] : {std::pair{"DLAB_TETGEN", "tetgen"}, std::pair{"DLAB_QDELAUNAY", "qhull"},
                                    std::pair{"DLAB_PYTHON", "scipy"}}) {
      const ScopedEnv env(var, "/nonexistent/tool");
      const auto why = dlab::baseline_unavailable(tool);
      REQUIRE(why);
      CHECK(why->find("/nonexistent/tool") != std::string::npos);
      const auto run = dlab::run_baseline(tool, dlab::point_set<3>(dlab::gen::uniform<3>(10, 1)));
      CHECK(run.skipped);
      CHECK(run.outcome == "skipped");
    }
  }
  SECTION("a Python without scipy is no scipy") {
    const ScopedEnv env("DLAB_PYTHON", fake_tool(p, "python", "exit 1"));
    const auto why = dlab::baseline_unavailable("scipy");
    REQUIRE(why);
    CHECK(why->find("scipy") != std::string::npos);
  }
}

// ---------------------------------------------------------------- CGAL

TEST_CASE("baselines: cgal-epick and cgal-epeck", "[baselines][cgal]") {
  for (const std::string tool : {"cgal-epick", "cgal-epeck"}) {
    if (unavailable(tool)) continue;
    agrees_on_uniform(tool, 2);
    agrees_on_uniform(tool, 3);
    handles_duplicates(tool, 2);
    handles_duplicates(tool, 3);
    // Exactly cospherical: CGAL's symbolic perturbation is dlab's (design.md section 2).
    const PointSet cs = dlab::point_set<3>(dlab::gen::cospherical<3>(40, 5));
    const auto run = run_and_classify(tool, cs);
    CHECK(run.outcome == "ok");
    CHECK(canonical(run.simplices, 3) == dlab_reference(cs));
    CHECK(run_and_classify(tool, collinear_2d()).outcome == "lower-dimensional");
    CHECK(run_and_classify(tool, coplanar_3d()).outcome == "lower-dimensional");
  }
}

// ---------------------------------------------------------------- TetGen

TEST_CASE("baselines: tetgen", "[baselines][tetgen]") {
  if (unavailable("tetgen")) return;
  agrees_on_uniform("tetgen", 3);
  handles_duplicates("tetgen", 3);
  const auto flat = run_and_classify("tetgen", dlab::point_set<2>(dlab::gen::uniform<2>(10, 1)));
  CHECK(flat.skipped);
  CHECK(flat.message.find("3D") != std::string::npos);
  // TetGen refuses coplanar points (a tolerance test): the right answer.
  const auto cop = run_and_classify("tetgen", coplanar_3d());
  CHECK(cop.outcome == "lower-dimensional");
  CHECK(cop.message.find("coplanar") != std::string::npos);
}

// ---------------------------------------------------------------- Qhull

TEST_CASE("baselines: qhull", "[baselines][qhull]") {
  if (unavailable("qhull")) return;
  agrees_on_uniform("qhull", 2);
  agrees_on_uniform("qhull", 3);
  handles_duplicates("qhull", 2);
  handles_duplicates("qhull", 3);
  // Exactly cospherical without 'Qz': Qhull stops with a precision error.
  const auto cs = run_and_classify("qhull", dlab::point_set<3>(dlab::gen::cospherical<3>(30, 1)));
  CHECK(cs.outcome == "reported");
  CHECK(cs.message.rfind("QH6019", 0) == 0);
  // A cubic grid: 'Qt' splits each cube with flat tetrahedra among them.
  const auto grid = run_and_classify("qhull", dlab::point_set<3>(dlab::gen::lattice<3>(64)));
  CHECK(grid.outcome == "invalid");
  CHECK(grid.message.rfind("orientation", 0) == 0);
  const auto line = run_and_classify("qhull", collinear_2d());
  CHECK(line.outcome == "lower-dimensional");
  CHECK(line.message.rfind("QH", 0) == 0);
}

// ---------------------------------------------------------------- scipy

TEST_CASE("baselines: scipy", "[baselines][scipy]") {
  if (unavailable("scipy")) return;
  agrees_on_uniform("scipy", 2);
  agrees_on_uniform("scipy", 3);
  handles_duplicates("scipy", 2);
  // Exactly cospherical: scipy adds 'Qz', so Qhull gets through the start.
  const auto cs = run_and_classify("scipy", dlab::point_set<3>(dlab::gen::cospherical<3>(30, 1)));
  CHECK(cs.outcome != "crash");
  CHECK(cs.outcome != "reported");
  const auto line = run_and_classify("scipy", collinear_2d());
  CHECK(line.outcome == "lower-dimensional");
  CHECK(line.message.rfind("QH6154", 0) == 0);
}
