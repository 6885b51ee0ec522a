// RunOptions::location = "scan" (algorithms/locate.hpp, scan_locate): point
// location without a location structure, every live simplex tested in storage
// order.  With an exact kernel and the sos policy the Delaunay triangulation is
// unique, so the scan must give exactly the walk's simplices; each scan result
// is also judged by the exact validator (mp arithmetic, independent of the
// kernel under test).  With an inexact kernel a scan that finds nothing is a
// reported failure, not a crash.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "algorithms/bowyer_watson.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/float_kernel.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

RunResult triangulate(const PointSet& ps, const std::string& algo, const std::string& kernel,
                      const std::string& location, const std::string& order = "random") {
  RunOptions o;
  o.algorithm = algo;
  o.kernel = kernel;
  o.location = location;
  o.order = order;
  o.seed = 7;
  return run(ps, o);
}

template <int D>
void scan_equals_walk(const std::vector<Point<D>>& pts, const std::string& what) {
  const PointSet ps = point_set<D>(pts);
  for (const std::string algo : {"bowyer-watson", "lawson"})
    for (const std::string kernel : {"adaptive", "integer", "mp"}) {
      INFO(what << ", " << algo << " x " << kernel);
      const RunResult walk = triangulate(ps, algo, kernel, "walk");
      const RunResult scan = triangulate(ps, algo, kernel, "scan");
      REQUIRE(walk.outcome == RunResult::Outcome::ok);
      REQUIRE(scan.outcome == RunResult::Outcome::ok);
      CHECK(canonical_simplices<D>(scan.simplices) == canonical_simplices<D>(walk.simplices));
      const ValidationReport v = validate(scan.points, scan.simplices);
      CHECK(v.delaunay());
      // The scan replaced the walk: no step walked, at least one test per insertion.
      CHECK(test::counter(scan.counters, "walk_steps") == 0);
      CHECK(test::counter(scan.counters, "scan_tests") >= pts.size() - D - 1);
      CHECK(test::counter(walk.counters, "scan_tests") == 0);
    }
}

// A float kernel that sees every orientation involving `poison` as negative:
// no simplex then contains the poison point and no ghost sees it, so a scan
// for it finds nothing.
struct PoisonKernel {
  static constexpr bool exact = false;
  static constexpr std::string_view name = "poison";
  Point2 poison{};
  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const {
    if (a == poison || b == poison || c == poison) return Sign::negative;
    return FloatKernel{}.orient2d(a, b, c);
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return FloatKernel{}.incircle(a, b, c, d);
  }
};

}  // namespace

TEST_CASE("scan and walk give the same triangulation, 2D", "[location]") {
  scan_equals_walk<2>(gen::uniform<2>(200, 3), "uniform");
  scan_equals_walk<2>(gen::cospherical<2>(120, 3), "cocircular");
  scan_equals_walk<2>(gen::lattice<2>(100), "lattice");
}

TEST_CASE("scan and walk give the same triangulation, 3D", "[location]") {
  scan_equals_walk<3>(gen::uniform<3>(100, 3), "uniform");
  scan_equals_walk<3>(gen::cospherical<3>(80, 3), "cospherical");
  scan_equals_walk<3>(gen::lattice<3>(64), "lattice");
}

TEST_CASE("scan counts one test per live simplex before the one found", "[location]") {
  // Triangle (0,0) (4,0) (0,4): mesh slots 0 = the finite triangle, then its
  // three ghosts (algorithms/initial_simplex.hpp). A point inside is found by
  // the first test; a point outside by a ghost, after the finite one.
  const std::vector<Point2> pts = {{0, 0}, {4, 0}, {0, 4}, {1, 1}, {-1, -1}};
  Mesh<2> m;
  build_initial_mesh<2>(m, {0, 1, 2});
  REQUIRE(m.live() == 4);
  REQUIRE_FALSE(m.is_ghost(0));
  const FloatKernel k;
  const Located in = scan_locate<FloatKernel, 2>(k, m, pts.data(), pts[3]);
  CHECK(in.end == Located::End::inside);
  CHECK(in.simplex == 0);
  CHECK(in.tests == 1);
  const Located out = scan_locate<FloatKernel, 2>(k, m, pts.data(), pts[4]);
  CHECK(out.end == Located::End::outside);
  CHECK(m.is_ghost(out.simplex));
  CHECK(out.tests >= 2);
  // A vertex is in the closed triangle, on two of its edges.
  const Located on = scan_locate<FloatKernel, 2>(k, m, pts.data(), pts[1]);
  CHECK(on.end == Located::End::inside);
  CHECK(on.zeros == 2);
}

TEST_CASE("an inexact scan that finds nothing is a reported failure", "[location]") {
  const std::vector<Point2> pts = {{0, 0}, {4, 0}, {0, 4}, {1, 1}, {3, 3}, {1, 2}};
  PoisonKernel k;
  k.poison = pts[4];
  for (int algo = 0; algo < 2; ++algo) {
    TriangulationResult t;
    if (algo == 0) {
      BowyerWatson<PoisonKernel, 2> bw(k);
      bw.set_location(LocationScheme::scan);
      t = bw.run(pts);
    } else {
      Lawson<PoisonKernel, 2> lw(k);
      lw.set_location(LocationScheme::scan);
      t = lw.run(pts);
    }
    INFO(algo);
    CHECK(t.outcome == RunResult::Outcome::failed);
    CHECK(t.message.find("the scan found no simplex") != std::string::npos);
  }
}

TEST_CASE("inexact kernels with scan: failures are outcomes", "[location]") {
  gen::GenOptions g;
  g.name = "near-degenerate";
  g.n = 300;
  g.seed = 2;
  for (int dim : {2, 3}) {
    g.dim = dim;
    const PointSet ps = gen::generate(g);
    for (const std::string algo : {"bowyer-watson", "lawson"})
      for (const std::string kernel : {"float", "epsilon"}) {
        const RunResult r = triangulate(ps, algo, kernel, "scan");
        CHECK((r.outcome == RunResult::Outcome::ok || r.outcome == RunResult::Outcome::failed));
      }
  }
}

TEST_CASE("location names and the algorithms that take scan", "[location]") {
  const PointSet ps = point_set<2>(gen::uniform<2>(20, 1));
  CHECK_THROWS_AS(triangulate(ps, "bowyer-watson", "adaptive", "kd-tree"), UsageError);
  CHECK_THROWS_AS(triangulate(ps, "tanemura", "adaptive", "scan"), UsageError);
  CHECK_THROWS_AS(triangulate(ps, "george", "integer", "scan"), UsageError);
  CHECK(triangulate(ps, "tanemura", "adaptive", "walk").outcome == RunResult::Outcome::ok);
}
