// George's corrected cavity (algorithms/george.hpp, George 1997 section 2.3)
// through dlab::run(): the result is checked by the exact validator
// (algorithms/validate, an mp-kernel check independent of the code under test).
//   - floating sphere test (the default): ALWAYS a valid triangulation of the
//     convex hull with every distinct point a vertex, on random, lattice
//     (cocircular / cospherical ties), near-degenerate, near-duplicate, huge,
//     tiny, collinear and coplanar inputs, for each orientation kernel;
//   - the correction really runs: on inputs where the floating test is wrong
//     the counters show corrections, and the result is still valid;
//   - exact sphere test: valid AND Delaunay, with no correction at all;
//   - the floating sphere (floating_sphere.hpp) is the circumsphere;
//   - enclosing box: no box corner in the output, nothing overlaps, every
//     point kept; the hull loss is reported.
// Identity with CGAL is in test_oracle_george.cpp.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <array>
#include <bit>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "algorithms/floating_sphere.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/mp_kernel.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

RunResult george(const PointSet& ps, const std::string& kernel, bool exact_sphere = false, bool box = false,
                 const std::string& order = "brio", std::uint64_t seed = 1) {
  RunOptions o;
  o.algorithm = "george";
  o.kernel = kernel;
  o.order = order;
  o.seed = seed;
  o.exact_sphere = exact_sphere;
  o.enclosing_box = box;
  return run(ps, o);
}

PointSet make_points(const std::string& name, int dim, std::size_t n, std::uint64_t seed) {
  gen::GenOptions g;
  g.name = name;
  g.dim = dim;
  g.n = n;
  g.seed = seed;
  if (name == "kettner-grid") g.side = 40;
  return gen::generate(g);
}

const char* const kGenerators[] = {"uniform",   "clustered",       "lattice", "rotated-lattice",
                                   "cocircular", "near-degenerate", "near-duplicates", "huge",
                                   "tiny",      "collinear"};

}  // namespace

TEST_CASE("george: circumsphere_of gives the circumsphere", "[george]") {
  const Point2 a{0, 0}, b{4, 0}, c{0, 2};
  const auto s2 = circumsphere_of<2>({&a, &b, &c});
  CHECK(s2.centre[0] == 2);
  CHECK(s2.centre[1] == 1);
  CHECK(s2.r2 == 5);
  const Point3 p{0, 0, 0}, q{2, 0, 0}, r{0, 4, 0}, t{0, 0, 6};
  const auto s3 = circumsphere_of<3>({&p, &q, &r, &t});
  CHECK(s3.centre == Point3{1, 2, 3});
  CHECK(s3.r2 == 14);
  CHECK(inside_floating_sphere<3>({&p, &q, &r, &t}, Point3{1, 2, 3}));
  CHECK(inside_floating_sphere<3>({&p, &q, &r, &t}, Point3{1, 2, 3 + 3.74}));        // 3.74 < sqrt(14) = 3.7417
  CHECK_FALSE(inside_floating_sphere<3>({&p, &q, &r, &t}, Point3{1, 2, 3 + 3.75}));  // 3.75 > sqrt(14)
}

namespace {

// The table George's section 2.4 would keep, filled by the formulas in
// floating_sphere.hpp's header, written out here operation by operation.
Circumsphere<3> table_entry(const std::array<Point3, 4>& v) {
  double a[3], b[3], c[3];
  for (int j = 0; j < 3; ++j) {
    a[j] = v[1][j] - v[0][j];
    b[j] = v[2][j] - v[0][j];
    c[j] = v[3][j] - v[0][j];
  }
  const double bc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
  const double ca[3] = {c[1] * a[2] - c[2] * a[1], c[2] * a[0] - c[0] * a[2], c[0] * a[1] - c[1] * a[0]};
  const double ab[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const double a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  const double b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  const double d = 2 * (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]);
  Circumsphere<3> s;
  for (int j = 0; j < 3; ++j) {
    const double u = (a2 * bc[j] + b2 * ca[j] + c2 * ab[j]) / d;
    s.centre[j] = v[0][j] + u;
    s.r2 += u * u;
  }
  return s;
}

}  // namespace

// The floating test recomputes the sphere at every test: its answers must be
// those of a table of centres and radii, bit for bit, on points within a few
// ulps of the sphere, where a sphere computed any other way (say r^2 from
// the rounded centre to vertex 0, or a reciprocal of d) answers differently
// (George's outcomes on degenerate input, which the corpus records, rest on it).
TEST_CASE("george: the floating test answers as the paper's table of centres and radii", "[george]") {
  std::mt19937_64 g(19);
  std::uniform_real_distribution<double> unit(-1, 1);
  int disagreements = 0, inside = 0, tests = 0;
  for (int k = 0; k < 3000; ++k) {
    const double scale = std::ldexp(1.0, static_cast<int>(g() % 61) - 30);
    std::array<Point3, 4> v;
    for (Point3& q : v)
      for (double& x : q) x = 7 + scale * unit(g);
    const Circumsphere<3> s = table_entry(v);
    for (int j = 0; j < 4; ++j) {
      // A vertex nudged by a few ulps in each coordinate: on the sphere within rounding.
      Point3 p = v[j];
      for (double& x : p) x = std::nextafter(x, (g() & 1) ? 1e300 : -1e300);
      double d2 = 0;
      for (int i = 0; i < 3; ++i) d2 += (p[i] - s.centre[i]) * (p[i] - s.centre[i]);
      const bool table = d2 < s.r2;
      disagreements += inside_floating_sphere<3>({&v[0], &v[1], &v[2], &v[3]}, p) != table;
      inside += table;
      ++tests;
    }
  }
  CHECK(disagreements == 0);
  // Both answers occur: the points straddle the sphere.
  CHECK(inside > tests / 10);
  CHECK(inside < tests - tests / 10);
}

#if defined(__SSE2__)
// The packed circumcentre and its plain twin give the same bits, on any
// input: scales from subnormal to overflow, flat and repeated vertices (d = 0:
// infinities and NaNs, compared as bit patterns).
TEST_CASE("george: the SSE2 circumcentre is its plain twin bit for bit", "[george]") {
  std::mt19937_64 g(23);
  std::uniform_real_distribution<double> unit(-1, 1);
  int nonfinite = 0;
  for (int k = 0; k < 200000; ++k) {
    const double scale = std::ldexp(1.0, static_cast<int>(g() % 2100) - 1074);
    std::array<Point3, 4> v;
    for (Point3& q : v)
      for (double& x : q) x = (g() % 4 == 0 ? 0.0 : 1.0) + scale * unit(g);
    if (k % 7 == 0) v[3] = v[k % 3];                                        // a repeated vertex
    if (k % 11 == 0) v[3] = {v[1][0] + v[2][0], v[1][1] + v[2][1], v[1][2] + v[2][2]};  // near flat
    const std::array<const Point3*, 4> p{&v[0], &v[1], &v[2], &v[3]};
    const Point3 packed = circumcentre_offset_sse2(v[0], v[1], v[2], v[3]);
    const Point3 plain = circumcentre_offset_plain<3>(p);
    for (int j = 0; j < 3; ++j) {
      INFO(k << " " << j);
      REQUIRE(std::bit_cast<std::uint64_t>(packed[j]) == std::bit_cast<std::uint64_t>(plain[j]));
      nonfinite += !std::isfinite(plain[j]);
    }
  }
  CHECK(nonfinite > 0);  // the degenerate cases were reached
}
#endif

TEST_CASE("george: floating sphere test, always valid on every generator", "[george]") {
  for (const std::string kernel : {"integer", "adaptive"})
    for (int dim : {2, 3})
      for (const char* name : kGenerators) {
        const PointSet ps = make_points(name, dim, dim == 2 ? 1500 : 600, 7);
        const RunResult r = george(ps, kernel);
        INFO(kernel << " " << dim << "D " << name << ": " << r.message);
        REQUIRE(r.outcome == RunResult::Outcome::ok);
        const ValidationReport rep = validate(r.points, r.simplices);
        INFO(rep.summary());
        CHECK(rep.valid());
        CHECK(test::counter(r.counters, "valid") == 1);
        CHECK(test::counter(r.counters, "non_delaunay_facets") == rep.non_delaunay_facets());
      }
}

// On points in general position with no near-degeneracy the floating sphere
// is right wherever it is asked, so the floating test must give the Delaunay
// triangulation itself: a sphere rebuilt about the wrong vertex or with the
// wrong radius (floating_sphere.hpp) leaves non-Delaunay facets here.
TEST_CASE("george: the floating sphere test is Delaunay on uniform points", "[george]") {
  for (int dim : {2, 3}) {
    const PointSet ps = make_points("uniform", dim, dim == 2 ? 3000 : 1500, 11);
    const RunResult r = george(ps, "adaptive");
    REQUIRE(r.outcome == RunResult::Outcome::ok);
    const ValidationReport rep = validate(r.points, r.simplices);
    CHECK(rep.valid());
    CHECK(rep.non_delaunay_facets() == 0);
    CHECK(test::counter(r.counters, "float_sphere_tests") > 0);
  }
}

TEST_CASE("george: coplanar and kettner inputs stay valid", "[george]") {
  for (const std::string kernel : {"integer", "mp"}) {
    const RunResult r3 = george(make_points("coplanar", 3, 500, 3), kernel);
    REQUIRE(r3.outcome == RunResult::Outcome::ok);
    CHECK(validate(r3.points, r3.simplices).valid());
    const RunResult r2 = george(make_points("kettner-grid", 2, 0, 0), kernel);
    REQUIRE(r2.outcome == RunResult::Outcome::ok);
    CHECK(validate(r2.points, r2.simplices).valid());
  }
}

// The inexact baselines (variants/george_float.cpp, george_epsilon.cpp): on easy
// input the volumes are right and the result is valid; on the hard generators any
// outcome is allowed except a crash, a hang or an unexplained failure.
TEST_CASE("george: inexact kernels never crash; on easy inputs they are valid", "[george]") {
  for (const std::string kernel : {"float", "epsilon"}) {
    for (int dim : {2, 3}) {
      const RunResult easy = george(make_points("uniform", dim, dim == 2 ? 1000 : 400, 5), kernel);
      INFO(kernel << " " << dim << "D uniform: " << easy.message);
      REQUIRE(easy.outcome == RunResult::Outcome::ok);
      CHECK(validate(easy.points, easy.simplices).valid());
      for (const char* name : kGenerators) {
        const RunResult r = george(make_points(name, dim, dim == 2 ? 600 : 300, 9), kernel);
        INFO(kernel << " " << dim << "D " << name << ": " << r.message);
        if (r.outcome == RunResult::Outcome::failed) CHECK(!r.message.empty());
        if (r.outcome == RunResult::Outcome::ok)  // what the registry says of it is the truth
          CHECK(test::counter(r.counters, "valid") == (validate(r.points, r.simplices).valid() ? 1u : 0u));
      }
    }
  }
}

TEST_CASE("george: the correction runs where the floating test errs, and repairs", "[george]") {
  // 3D lattices are full of cospherical ties: the floating test gets many
  // wrong, so cavities must be corrected (counters), and the mesh stays valid.
  const RunResult r = george(make_points("lattice", 3, 1000, 1), "integer");
  REQUIRE(r.outcome == RunResult::Outcome::ok);
  CHECK(test::counter(r.counters, "corrected_insertions") > 0);
  CHECK(test::counter(r.counters, "removed_for_visibility") + test::counter(r.counters, "removed_for_connectivity") +
            test::counter(r.counters, "added_for_zero_volume") + test::counter(r.counters, "removed_for_enclosed_vertex") >
        0);
  CHECK(validate(r.points, r.simplices).valid());
}

// Step 3 drops the cavity elements that removals cut off from the base. The
// first round needs no check (step 2 grows the cavity from the base), every
// later one does: on near-degenerate 3D points the removals for visibility
// disconnect cavities (papers/george1997/README.md's table), and step 3 must
// have run there.
TEST_CASE("george: connectivity removals happen after visibility removals, and keep it valid", "[george]") {
  const RunResult r = george(make_points("near-degenerate", 3, 1500, 3), "integer");
  INFO(r.message);
  REQUIRE(r.outcome == RunResult::Outcome::ok);
  CHECK(test::counter(r.counters, "removed_for_connectivity") > 0);
  CHECK(validate(r.points, r.simplices).valid());
}

TEST_CASE("george: exact sphere test gives a Delaunay triangulation with no correction", "[george]") {
  for (const std::string kernel : {"integer", "adaptive", "mp"})
    for (int dim : {2, 3})
      for (const char* name : kGenerators) {
        const PointSet ps = make_points(name, dim, dim == 2 ? 800 : 300, 11);
        const RunResult r = george(ps, kernel, true);
        INFO(kernel << " " << dim << "D " << name << ": " << r.message);
        REQUIRE(r.outcome == RunResult::Outcome::ok);
        const ValidationReport rep = validate(r.points, r.simplices);
        INFO(rep.summary());
        CHECK(rep.delaunay());
        CHECK(test::counter(r.counters, "corrected_insertions") == 0);
      }
}

TEST_CASE("george: property, small integer grids (heavy ties) are always valid", "[george]") {
  rc::prop("2D and 3D, floating and exact sphere", [](bool three, bool exact, std::uint8_t nraw) {
    const std::size_t n = 5 + nraw % 60;
    PointSet ps;
    ps.dimension = three ? 3 : 2;
    const int range = *rc::gen::inRange(2, 7);
    for (std::size_t i = 0; i < n; ++i) {
      if (three)
        ps.p3.push_back({double(*rc::gen::inRange(0, range)), double(*rc::gen::inRange(0, range)),
                         double(*rc::gen::inRange(0, range))});
      else
        ps.p2.push_back({double(*rc::gen::inRange(0, range)), double(*rc::gen::inRange(0, range))});
    }
    const RunResult r = george(ps, "integer", exact, false, "random", n);
    if (r.outcome == RunResult::Outcome::lower_dimensional) return;
    RC_ASSERT(r.outcome == RunResult::Outcome::ok);
    const ValidationReport rep = validate(r.points, r.simplices);
    RC_ASSERT(rep.valid());
    if (exact) RC_ASSERT(rep.delaunay());
  });
}

TEST_CASE("george: enclosing box, box removed, nothing overlaps, loss reported", "[george]") {
  // integer: the grid is fitted to the input and its box (variants/driver.hpp),
  // the corners snapped onto it; a corner off the grid would be clamped and
  // break the orientation and same-side checks below.
  for (const char* kernel : {"adaptive", "integer"})
  for (int dim : {2, 3}) {
    INFO(kernel << " " << dim << "D");
    const PointSet ps = make_points("uniform", dim, 400, 5);
    const RunResult r = george(ps, kernel, false, true);
    REQUIRE(r.outcome == RunResult::Outcome::ok);
    for (std::uint32_t v : r.simplices) REQUIRE(v < ps.size());
    const ValidationReport rep = validate(r.points, r.simplices);
    CHECK(rep[Check::orientation].count == 0);
    CHECK(rep[Check::non_manifold_facet].count == 0);
    CHECK(rep[Check::facet_same_side].count == 0);
    CHECK(rep[Check::missing_vertex].count == test::counter(r.counters, "missing_vertices"));
    CHECK(test::counter(r.counters, "box_simplices_removed") > 0);
    // Uniform points: some hull facets are always lost with the box's elements.
    CHECK(test::counter(r.counters, "hull_facets_missing") > 0);
    CHECK(test::counter(r.counters, "valid") == (rep.valid() ? 1u : 0u));
  }
}
