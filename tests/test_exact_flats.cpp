// The exactly flat nodes of the Tanemura search tree (algorithms/exact_flats.hpp),
// checked in rational arithmetic, independently of the kernels:
//   - every node marked flat has its D reference points spanning a hyperplane
//     (a non-zero rational normal) and every one of its points exactly on it,
//     on exact lines and planes with points off them, and on the same sets
//     moved by one ulp (where most nodes must not be marked);
//   - a line in 3D (its reference points collinear) marks nothing;
//   - the search skips nodes in a facet's plane (dlab gen coplanar: the
//     facets in the plane looked for their far apex through every point
//     between), with the same triangulation as Bowyer-Watson's.
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

#include "algorithms/exact_flats.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/kd_tree.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "tests/cgal_oracle.hpp"  // canonical_simplices only (header part; no CGAL here)
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;

// det[b - a; c - a] (2D) or det[b - a; c - a; d - a] (3D), exactly.
Q det(const Point2& a, const Point2& b, const Point2& c) {
  return (Q(b[0]) - Q(a[0])) * (Q(c[1]) - Q(a[1])) - (Q(b[1]) - Q(a[1])) * (Q(c[0]) - Q(a[0]));
}
std::array<Q, 3> normal(const Point3& a, const Point3& b, const Point3& c) {
  std::array<Q, 3> u, v;
  for (int i = 0; i < 3; ++i) u[i] = Q(b[i]) - Q(a[i]), v[i] = Q(c[i]) - Q(a[i]);
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Checks every marked node exactly; returns how many nodes are marked.
template <int D>
std::size_t check_flats(const std::vector<Point<D>>& pts) {
  std::vector<std::uint32_t> ids(pts.size());
  std::iota(ids.begin(), ids.end(), 0u);
  KdTree<D> tree;
  tree.build(pts, ids);
  const AdaptiveKernel k;
  const InitialSimplex<D> init = find_initial_simplex<D>(k, std::span<const Point<D>>(pts));
  REQUIRE(init.found);
  ExactFlats<D> flats;
  flats.build(k, tree, pts, init.ids);
  std::size_t marked = 0;
  for (std::uint32_t n = 0; n < tree.node_count(); ++n) {
    const std::uint32_t h = flats.of_node(n);
    if (h == ExactFlats<D>::kNone) continue;
    ++marked;
    const auto& r = flats.refs(h);
    const auto& node = tree.node(n);
    if constexpr (D == 2) {
      REQUIRE(pts[r[0]] != pts[r[1]]);
      for (std::uint32_t s = node.begin; s < node.end; ++s) REQUIRE(det(pts[r[0]], pts[r[1]], tree.coords(s)) == 0);
    } else {
      const auto nrm = normal(pts[r[0]], pts[r[1]], pts[r[2]]);
      REQUIRE((nrm[0] != 0 || nrm[1] != 0 || nrm[2] != 0));
      for (std::uint32_t s = node.begin; s < node.end; ++s) {
        Q dot = 0;
        for (int i = 0; i < 3; ++i) dot += nrm[i] * (Q(tree.coords(s)[i]) - Q(pts[r[0]][i]));
        REQUIRE(dot == 0);
      }
    }
  }
  return marked;
}


}  // namespace

TEST_CASE("exact flats: marked nodes lie exactly on their hyperplane (rational arithmetic)", "[exact_flats]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto line = gen::collinear<2>(3000, 3, seed);
    const auto plane = gen::coplanar(3000, 3, seed);
    // Exact sets: most of the tree is flat.
    CHECK(check_flats<2>(line) > 100);
    CHECK(check_flats<3>(plane) > 100);
    // One ulp off: still framed (flat to rounding), marked only where a
    // node's points happen to stay exactly on a line or plane.
    check_flats<2>(gen::perturb_ulps<2>(line, 1, seed));
    check_flats<3>(gen::perturb_ulps<3>(plane, 1, seed));
  }
  // A line in 3D spans no plane: its reference points are collinear.
  CHECK(check_flats<3>(gen::collinear<3>(3000, 3, 1)) == 0);
  CHECK(check_flats<3>(gen::uniform<3>(3000, 1)) == 0);
}

TEST_CASE("exact flats: facets in the plane skip its nodes, same triangulation", "[exact_flats]") {
  // Points examined per facet (x1000), coplanar n = 4000: 12 203 with the
  // skip, 18 232 without it.
  const PointSet ps = point_set<3>(gen::coplanar(4000, 3, 1));
  RunOptions o;
  o.algorithm = "tanemura";
  const RunResult t = run(ps, o);
  REQUIRE(t.outcome == RunResult::Outcome::ok);
  CHECK(test::counter(t.counters, "flat_nodes_skipped") > 0);
  CHECK(test::counter(t.counters, "points_examined_per_facet_x1000") < 14000);
  o.algorithm = "bowyer-watson";
  const RunResult b = run(ps, o);
  CHECK(oracle::canonical_simplices<3>(t.simplices) == oracle::canonical_simplices<3>(b.simplices));
}
