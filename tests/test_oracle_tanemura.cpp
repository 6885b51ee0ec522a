// Tanemura–Ogawa–Ogita against CGAL (tests/cgal_oracle.hpp): for every exact
// kernel, the simplex set equals CGAL's Delaunay_triangulation_2/3 (sos
// policy), and the result passes the exact validator, on inputs where
// the search tree (algorithms/kd_tree.hpp) and the tie-breaking both matter:
// uniform sets large enough for many leaves, integer lattices (cocircular / cospherical ties everywhere,
// coplanar hull faces), cube corners, exact cocircular / cospherical sets with
// points inside, rotated lattices, points on hull edges and faces, clustered
// sets and Kettner's grid of consecutive doubles with two far points (very
// uneven density), huge and tiny magnitudes. The strict policy must
// give a valid Delaunay triangulation. (test_oracle_properties.cpp also runs
// tanemura in its random families, through the registry.)
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>

#include <cstdint>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "tests/cgal_oracle.hpp"
#include "variants/run.hpp"

namespace {

using dlab::Point;
using dlab::Point2;
using dlab::Point3;
using dlab::PointSet;
using dlab::point_set;
using dlab::RunOptions;
using dlab::RunResult;
using Outcome = RunResult::Outcome;

template <int D>
const std::vector<Point<D>>& pts(const RunResult& r) {
  if constexpr (D == 2)
    return r.points.p2;
  else
    return r.points.p3;
}

template <int D>
void equals_cgal(const std::vector<Point<D>>& p, const std::string& what) {
  for (const char* kernel : {"adaptive", "integer", "mp"}) {
    INFO(what << " n=" << p.size() << " kernel " << kernel);
    RunOptions o;
    o.algorithm = "tanemura";
    o.kernel = kernel;
    const RunResult r = dlab::run(point_set<D>(p), o);
    INFO(r.message);
    REQUIRE(r.outcome != Outcome::failed);
    const auto cgal = dlab::oracle::cgal_delaunay(pts<D>(r));  // on the snapped points for `integer`
    CHECK((r.outcome == Outcome::lower_dimensional) == cgal.empty());
    const auto mine = dlab::oracle::canonical_simplices<D>(r.simplices);
    CHECK(mine.size() == cgal.size());
    CHECK(mine == cgal);
    const auto rep = dlab::validate(r.points, r.simplices);
    INFO(rep.summary());
    CHECK(rep.delaunay());
    o.policy = "strict";
    const RunResult s = dlab::run(point_set<D>(p), o);
    REQUIRE(s.outcome != Outcome::failed);
    CHECK(dlab::validate(s.points, s.simplices).delaunay());
  }
}

template <int D>
std::vector<Point<D>> grid(int side) {
  std::vector<Point<D>> p;
  const int total = D == 2 ? side * side : side * side * side;
  for (int k = 0; k < total; ++k) {
    Point<D> q;
    int t = k;
    for (int i = 0; i < D; ++i) {
      q[i] = t % side;
      t /= side;
    }
    p.push_back(q);
  }
  return p;
}

}  // namespace

TEST_CASE("oracle tanemura: 2D equals CGAL", "[oracle][tanemura]") {
  namespace gen = dlab::gen;
  equals_cgal<2>(gen::uniform<2>(5000, 1), "uniform");
  equals_cgal<2>(gen::clustered<2>(3000, 2), "clustered");
  equals_cgal<2>(grid<2>(20), "lattice 20x20");
  equals_cgal<2>(gen::rotated_lattice<2>(400), "rotated lattice");
  auto c = gen::cospherical<2>(200, 3);
  const auto in = gen::uniform<2>(50, 4, -0.5, 0.5);
  c.insert(c.end(), in.begin(), in.end());
  equals_cgal<2>(c, "cocircular + inside");
  equals_cgal<2>(gen::collinear<2>(200, 5, 6), "collinear + 5 off");
  equals_cgal<2>(gen::huge<2>(300, 7), "huge");
  equals_cgal<2>(gen::tiny<2>(300, 8), "tiny");
  equals_cgal<2>(gen::near_duplicates<2>(300, 9), "near duplicates");
  equals_cgal<2>(gen::kettner_grid(24), "kettner grid 24x24 + 2");
}

TEST_CASE("oracle tanemura: 3D equals CGAL", "[oracle][tanemura]") {
  namespace gen = dlab::gen;
  equals_cgal<3>(gen::uniform<3>(2000, 1), "uniform");
  equals_cgal<3>(gen::clustered<3>(1000, 2), "clustered");
  equals_cgal<3>(grid<3>(2), "cube corners");
  equals_cgal<3>(grid<3>(6), "lattice 6^3");
  equals_cgal<3>(gen::rotated_lattice<3>(200), "rotated lattice");
  auto c = gen::cospherical<3>(150, 3);
  const auto in = gen::uniform<3>(30, 4, -0.5, 0.5);
  c.insert(c.end(), in.begin(), in.end());
  equals_cgal<3>(c, "cospherical + inside");
  equals_cgal<3>(gen::coplanar(150, 4, 5), "coplanar + 4 off");
  equals_cgal<3>(gen::huge<3>(200, 7), "huge");
  equals_cgal<3>(gen::tiny<3>(200, 8), "tiny");
}

TEST_CASE("oracle tanemura: random lattices equal CGAL (property)", "[oracle][tanemura]") {
  rc::prop("3D lattice subsets", [] {
    const int r = *rc::gen::inRange(1, 4);
    const auto raw = *rc::gen::resize(80, rc::gen::container<std::vector<std::array<int, 3>>>(
        rc::gen::container<std::array<int, 3>>(rc::gen::inRange(-r, r + 1))));
    std::vector<Point3> p;
    for (const auto& q : raw) p.push_back({double(q[0]), double(q[1]), double(q[2])});
    RunOptions o;
    o.algorithm = "tanemura";
    o.kernel = *rc::gen::elementOf(std::vector<std::string>{"adaptive", "integer", "mp"});
    const RunResult res = dlab::run(point_set<3>(p), o);
    RC_ASSERT(res.outcome != Outcome::failed);
    RC_ASSERT(dlab::oracle::canonical_simplices<3>(res.simplices) == dlab::oracle::cgal_delaunay(res.points.p3));
  });
}
