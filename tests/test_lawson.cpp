// Lawson (flips) through dlab::run(): on random and degenerate inputs, every
// exact kernel, 2D and 3D, the result
//   - passes the exact validator (algorithms/validate) as a Delaunay triangulation,
//   - equals Bowyer-Watson's (an independent implementation of the same unique
//     perturbed Delaunay triangulation; the CGAL comparison is in
//     test_oracle_lawson.cpp), simplex for simplex,
//   - does not depend on the insertion order;
// the instrumentation counts the insertion cases and flip types that the
// input forces (a lattice has points on edges and facets and 4-4 flips);
// the flip primitives keep the mesh consistent; `float` ends in a result or a
// failure outcome, never a crash, within the flip bound; flip-existing reaches
// the Delaunay triangulation from a non-Delaunay start in 2D and reports
// rather than loops in 3D.
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/flip_existing.hpp"
#include "algorithms/flips.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "fuzz/non_delaunay.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

RunResult go(const PointSet& ps, const std::string& algo, const std::string& kernel,
             const std::string& order = "brio", const std::string& policy = "sos", std::uint64_t seed = 1) {
  RunOptions o;
  o.algorithm = algo;
  o.kernel = kernel;
  o.order = order;
  o.policy = policy;
  o.seed = seed;
  return run(ps, o);
}

template <int D>
void check_exact(const std::vector<Point<D>>& pts, const std::string& what) {
  const PointSet ps = point_set<D>(pts);
  for (const std::string kernel : {"adaptive", "integer", "mp"}) {
    INFO(what << " D=" << D << " kernel " << kernel);
    const RunResult bw = go(ps, "bowyer-watson", kernel);
    const RunResult lw = go(ps, "lawson", kernel);
    REQUIRE(lw.outcome == bw.outcome);
    if (lw.outcome != RunResult::Outcome::ok) continue;
    const ValidationReport rep = validate(lw.points, lw.simplices);
    INFO(rep.summary());
    CHECK(rep.delaunay());
    const auto ref = test::canonical_simplices<D>(lw.simplices);
    CHECK(ref == test::canonical_simplices<D>(bw.simplices));
    for (const std::string order : {"input", "random", "hilbert"}) {
      INFO("order " << order);
      const RunResult o = go(ps, "lawson", kernel, order, "sos", 7);
      REQUIRE(o.outcome == RunResult::Outcome::ok);
      CHECK(test::canonical_simplices<D>(o.simplices) == ref);
    }
    const RunResult strict = go(ps, "lawson", kernel, "brio", "strict");
    REQUIRE(strict.outcome == RunResult::Outcome::ok);
    CHECK(validate(strict.points, strict.simplices).delaunay());
  }
}

}  // namespace

TEST_CASE("lawson 2D equals Bowyer-Watson, valid, order independent", "[lawson]") {
  check_exact<2>(gen::uniform<2>(300, 1), "uniform");
  check_exact<2>(gen::lattice<2>(100), "lattice");
  check_exact<2>(gen::rotated_lattice<2>(80), "rotated lattice");
  check_exact<2>(gen::cospherical<2>(40, 3), "cocircular");
  check_exact<2>(gen::collinear<2>(40, 3, 5), "collinear");
  check_exact<2>(gen::perturb_ulps<2>(gen::cospherical<2>(40, 3), 1, 9), "near-cocircular");
  check_exact<2>(gen::near_duplicates<2>(60, 4), "near-duplicates");
}

TEST_CASE("lawson 3D equals Bowyer-Watson, valid, order independent", "[lawson]") {
  check_exact<3>(gen::uniform<3>(200, 1), "uniform");
  check_exact<3>(gen::lattice<3>(64), "lattice");
  check_exact<3>(gen::rotated_lattice<3>(64), "rotated lattice");
  check_exact<3>(gen::cospherical<3>(40, 3), "cospherical");
  check_exact<3>(gen::coplanar(40, 3, 5), "coplanar");
  check_exact<3>(gen::perturb_ulps<3>(gen::cospherical<3>(40, 3), 1, 9), "near-cospherical");
}

// Hull insertions are all flips now (Joe's exterior rule, then flips; the
// coplanar hull edge flip): a two-layer grid in input order puts every new
// point outside the hull and coplanar with hull faces, on the lines of hull
// edges, or on a hull vertex (duplicates).
TEST_CASE("lawson 3D: points outside and on the hull, coplanar with hull faces", "[lawson]") {
  std::vector<Point3> pts = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int z = 0; z < 2; ++z)
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x) pts.push_back({double(x), double(y), double(z)});
  check_exact<3>(pts, "two-layer grid");
  const RunResult r = go(point_set<3>(pts), "lawson", "adaptive", "input");
  REQUIRE(r.outcome == RunResult::Outcome::ok);
  CHECK(test::counter(r.counters, "insert_exterior") > 60);   // every new point but the 4 duplicates
  CHECK(test::counter(r.counters, "exterior_facets") >= test::counter(r.counters, "insert_exterior"));
  CHECK(test::counter(r.counters, "flips_4_4") > 0);          // coplanar hull faces re-triangulated
  CHECK(test::counter(r.counters, "duplicates") == 4);
  // The same points in reverse order: on hull facets and edges of the big box first.
  std::vector<Point3> rev(pts.rbegin(), pts.rend());
  check_exact<3>(rev, "two-layer grid, reversed");
}

TEST_CASE("lawson on random small lattices equals Bowyer-Watson", "[lawson][property]") {
  rc::prop("2D and 3D, points on a 4^d grid (many ties)", [](std::uint64_t seed) {
    for (int dim : {2, 3}) {
      PointSet ps;
      ps.dimension = dim;
      std::uint64_t x = seed;
      auto next = [&] {
        x += 0x9E3779B97F4A7C15ull;
        std::uint64_t z = x;
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
      };
      const int n = 5 + static_cast<int>(next() % 30);
      for (int i = 0; i < n; ++i) {
        if (dim == 2)
          ps.p2.push_back({double(next() % 4), double(next() % 4)});
        else
          ps.p3.push_back({double(next() % 4), double(next() % 4), double(next() % 4)});
      }
      const RunResult bw = go(ps, "bowyer-watson", "mp");
      const RunResult lw = go(ps, "lawson", "mp", "random", "sos", seed);
      RC_ASSERT(lw.outcome == bw.outcome);
      if (lw.outcome != RunResult::Outcome::ok) continue;
      RC_ASSERT(validate(lw.points, lw.simplices).delaunay());
      if (dim == 2)
        RC_ASSERT(test::canonical_simplices<2>(lw.simplices) == test::canonical_simplices<2>(bw.simplices));
      else
        RC_ASSERT(test::canonical_simplices<3>(lw.simplices) == test::canonical_simplices<3>(bw.simplices));
    }
  });
}

TEST_CASE("lawson counters show the insertion cases and flip types", "[lawson]") {
  const RunResult u2 = go(point_set<2>(gen::uniform<2>(500, 2)), "lawson", "adaptive");
  CHECK(test::counter(u2.counters, "insert_1_3") > 0);
  CHECK(test::counter(u2.counters, "flips_2_2") > 0);
  // Random order on a lattice: later points land on edges of earlier triangles.
  const RunResult l2 = go(point_set<2>(gen::lattice<2>(400)), "lawson", "adaptive", "random");
  CHECK(test::counter(l2.counters, "insert_2_4") > 0);
  const RunResult l3 = go(point_set<3>(gen::lattice<3>(512)), "lawson", "adaptive", "random");
  CHECK(test::counter(l3.counters, "insert_2_6") > 0);
  CHECK(test::counter(l3.counters, "insert_n_2n") > 0);
  CHECK(test::counter(l3.counters, "flips_4_4") > 0);
  CHECK(test::counter(l3.counters, "insert_exterior") > 0);
  CHECK(test::counter(l3.counters, "insert_on_hull") > 0);  // on a hull facet or edge: split with its ghosts
  CHECK(test::counter(l3.counters, "insert_on_hull") <= test::counter(l3.counters, "insert_2_6") + test::counter(l3.counters, "insert_n_2n"));
  CHECK(test::counter(l3.counters, "hull_edge_removals") > 0);  // coplanar hull edges with more than 2 tetrahedra below
  const RunResult u3 = go(point_set<3>(gen::uniform<3>(500, 2)), "lawson", "adaptive");
  CHECK(test::counter(u3.counters, "insert_1_4") > 0);
  CHECK(test::counter(u3.counters, "flips_2_3") > 0);
  CHECK(test::counter(u3.counters, "flips_3_2") > 0);
  CHECK(test::counter(u3.counters, "flips_total") ==
        test::counter(u3.counters, "flips_2_3") + test::counter(u3.counters, "flips_3_2") + test::counter(u3.counters, "flips_4_4"));
}

TEST_CASE("lawson with inexact kernels: results or failure outcomes", "[lawson]") {
  int failures = 0;
  for (const std::string kernel : {"float", "epsilon"})
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      const PointSet ps2 = point_set<2>(gen::perturb_ulps<2>(gen::cospherical<2>(200, seed), 2, seed));
      const PointSet ps3 = point_set<3>(gen::perturb_ulps<3>(gen::cospherical<3>(200, seed), 2, seed));
      const PointSet grid = point_set<2>(gen::kettner_grid(64));
      for (const PointSet* ps : {&ps2, &ps3, &grid}) {
        const RunResult r = go(*ps, "lawson", kernel);
        if (r.outcome == RunResult::Outcome::failed) {
          CHECK(!r.message.empty());
          ++failures;
          continue;
        }
        if (r.outcome != RunResult::Outcome::ok) continue;
        CHECK(test::counter(r.counters, "flips_total") <= flip_bound(ps->size(), false));
        if (!validate(r.points, r.simplices).delaunay()) ++failures;
      }
    }
  CHECK(failures > 0);  // near-degenerate inputs do defeat the inexact kernels
}

TEST_CASE("2D edge flip primitive relinks a quad consistently", "[lawson]") {
  // Square 0(0,0) 1(1,0) 2(1,1) 3(0,1) split by diagonal 0-2; flipping gives 1-3.
  const std::vector<Point2> pts = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  Mesh<2> m;
  std::vector<std::uint32_t> ids;
  const std::array<std::array<std::uint32_t, 3>, 6> tris = {{{0, 1, 2}, {0, 2, 3}, {1, 0, kGhost},
                                                             {2, 1, kGhost}, {3, 2, kGhost}, {0, 3, kGhost}}};
  for (const auto& t : tris) ids.push_back(m.create(t.data()));
  REQUIRE(m.link_by_facets(ids));
  REQUIRE(m.check_structure().empty());
  const MpKernel k;
  Flipper<MpKernel, 2> fl(k, m);
  fl.set_points(pts.data());
  // Cocircular square, strict kernel: no conflict, no flip.
  CHECK(fl.try_flip(ids[0], 1) == Flipper<MpKernel, 2>::Result::delaunay);
  // Move vertex 3 inside the circle of 0,1,2: now the diagonal must flip.
  std::vector<Point2> pts2 = pts;
  pts2[3] = {0.25, 0.75};
  fl.set_points(pts2.data());
  REQUIRE(fl.try_flip(ids[0], 1) == Flipper<MpKernel, 2>::Result::flipped);
  CHECK(m.check_structure().empty());
  CHECK(fl.counts.f22 == 1);
  std::vector<std::uint32_t> flat;
  m.for_each_finite([&](std::uint32_t s) {
    for (int j = 0; j < 3; ++j) flat.push_back(m.vertex(s, j));
  });
  const std::vector<std::uint32_t> expect = {1, 2, 3, 3, 0, 1};
  CHECK(test::canonical_simplices<2>(flat) == test::canonical_simplices<2>(expect));
}

// The directly wired 3D flips keep the mesh consistent: a bipyramid over
// triangle 012 with apexes 3 (above) and 4 (below).  Apexes close to the
// plane: 4 is inside the sphere of 0123, and the 2-3 flip gives the three
// tetrahedra around edge 34; apexes far: the three tetrahedra around 34 are
// not Delaunay and the 3-2 flip about 34 gives back 0123 + 1024.
TEST_CASE("3D 2-3 and 3-2 flip primitives relink consistently", "[lawson]") {
  using F = Flipper<MpKernel, 3>;
  const MpKernel k;
  auto finite = [](const Mesh<3>& m) {
    std::vector<std::uint32_t> flat;
    m.for_each_finite([&](std::uint32_t s) {
      for (int j = 0; j < 4; ++j) flat.push_back(m.vertex(s, j));
    });
    return test::canonical_simplices<3>(flat);
  };
  auto apex_tet = [](const Mesh<3>& m, std::uint32_t v) {  // a finite tetrahedron holding v
    for (std::uint32_t s = 0; s < m.slots(); ++s)
      if (m.alive(s) && !m.is_ghost(s))
        for (int j = 0; j < 4; ++j)
          if (m.vertex(s, j) == v) return std::pair<std::uint32_t, int>(s, j);
    return std::pair<std::uint32_t, int>(kDead, -1);
  };
  const std::vector<Point3> near = {{-2, -2, 0}, {4, -2, 0}, {-2, 4, 0}, {0, 0, 1}, {0, 0, -1}};
  const std::vector<std::uint32_t> two = {0, 1, 2, 3, 1, 0, 2, 4};
  Mesh<3> m;
  std::int64_t bad = -1;
  REQUIRE(flip_existing_detail::build<3>(k, std::span<const Point3>(near), std::span<const std::uint32_t>(two),
                                         m, bad)
              .empty());
  F fl(k, m);
  fl.set_points(near.data());
  const auto [s, f] = apex_tet(m, 3);
  REQUIRE(fl.try_flip(s, f) == F::Result::flipped);
  CHECK(fl.counts.f23 == 1);
  CHECK(m.check_structure().empty());
  const std::vector<std::uint32_t> three = {3, 4, 0, 1, 3, 4, 1, 2, 3, 4, 2, 0};
  // (orientation-free comparison: sort each simplex's vertices)
  auto sorted = [](std::vector<std::array<std::uint32_t, 4>> v) {
    for (auto& a : v) std::sort(a.begin(), a.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  CHECK(sorted(finite(m)) == sorted(test::canonical_simplices<3>(three)));

  // Far apexes: from tetrahedron 2+{3,4,0}, facet 340 (opposite 2) is shared
  // with 1+{3,4,0}; segment 2-1 passes beyond edge 34: 3-2 about 34.
  const std::vector<Point3> far = {{-2, -2, 0}, {4, -2, 0}, {-2, 4, 0}, {0, 0, 50}, {0, 0, -50}};
  fl.set_points(far.data());
  std::uint32_t s2 = kDead;
  int f2 = -1;
  for (std::uint32_t t = 0; t < m.slots(); ++t)
    if (m.alive(t) && !m.is_ghost(t) && FlipMesh<3>::slot_of(m, t, 2) >= 0 && FlipMesh<3>::slot_of(m, t, 0) >= 0) {
      s2 = t;
      f2 = FlipMesh<3>::slot_of(m, t, 2);
    }
  REQUIRE(s2 != kDead);
  REQUIRE(fl.try_flip(s2, f2) == F::Result::flipped);
  CHECK(fl.counts.f32 == 1);
  CHECK(m.check_structure().empty());
  CHECK(sorted(finite(m)) == sorted(test::canonical_simplices<3>(two)));
}

// slot_of in 3D compares the four vertex words at once (flips.hpp): every slot,
// a vertex absent, the ghost, and the lowest slot when a (corrupt) simplex holds
// a vertex twice, as the loop of 2D answers.
TEST_CASE("slot_of: the first slot holding a vertex, or -1", "[lawson]") {
  Mesh<3> m3;
  const std::uint32_t t = m3.create({7, 3, 9, kGhost});
  const std::uint32_t twice = m3.create({5, 8, 5, 8});
  for (int j = 0; j < 4; ++j) CHECK(FlipMesh<3>::slot_of(m3, t, m3.vertex(t, j)) == j);
  CHECK(FlipMesh<3>::slot_of(m3, t, 4) == -1);
  CHECK(FlipMesh<3>::slot_of(m3, t, 0) == -1);
  CHECK(FlipMesh<3>::slot_of(m3, twice, 5) == 0);
  CHECK(FlipMesh<3>::slot_of(m3, twice, 8) == 1);
  Mesh<2> m2;
  const std::uint32_t u = m2.create({4, 2, 6});
  for (int j = 0; j < 3; ++j) CHECK(FlipMesh<2>::slot_of(m2, u, m2.vertex(u, j)) == j);
  CHECK(FlipMesh<2>::slot_of(m2, u, 5) == -1);
}

TEST_CASE("flip-existing: 2D converges to Delaunay, 3D reports when stuck", "[lawson]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const std::vector<Point2> p2 = gen::uniform<2>(300, seed);
    const std::vector<std::uint32_t> start = non_delaunay_start<2>(p2, seed);
    const ValidationReport s = validate(std::span<const Point2>(p2), start);
    REQUIRE(s.valid());
    CHECK(!s.delaunay());  // the start is a genuine test
    const FlipExistingResult r = flip_existing<2>(p2, start);
    REQUIRE(r.outcome == RunResult::Outcome::ok);
    CHECK(r.stuck_facets == 0);
    CHECK(r.flips > 0);
    CHECK(validate(std::span<const Point2>(p2), r.simplices).delaunay());
    // The perturbed Delaunay triangulation is unique: Bowyer-Watson's.
    const RunResult bw = go(point_set<2>(p2), "bowyer-watson", "mp", "input");
    CHECK(test::canonical_simplices<2>(r.simplices) == test::canonical_simplices<2>(bw.simplices));

    const std::vector<Point3> p3 = gen::uniform<3>(150, seed);
    const std::vector<std::uint32_t> start3 = non_delaunay_start<3>(p3, seed);
    const ValidationReport s3 = validate(std::span<const Point3>(p3), start3);
    REQUIRE(s3.valid());
    CHECK(!s3.delaunay());
    const FlipExistingResult r3 = flip_existing<3>(p3, start3);
    REQUIRE(r3.outcome != RunResult::Outcome::failed);
    const ValidationReport e3 = validate(std::span<const Point3>(p3), r3.simplices);
    CHECK(e3.valid());
    // Either Delaunay, or stuck with exactly the non-Delaunay facets reported.
    if (r3.stuck_facets == 0)
      CHECK(e3.delaunay());
    else
      CHECK(!e3.delaunay());
  }
}
