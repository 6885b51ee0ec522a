// Bowyer–Watson through dlab::run(), checked by brute force with the exact mp
// kernel (independent of the code under test): every simplex positively
// oriented, no point strictly inside any circumcircle/circumsphere (and, for
// `sos`, none inside by the perturbed test either), every facet shared by at
// most two simplices and every boundary facet on the convex hull, every distinct
// point a vertex, the Euler characteristic of a disc/ball, and in 2D the
// simplex count 2n - h - 2.  Small inputs only: the checks are O(n * simplices).
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

#include "algorithms/merge_record.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "variants/insertion_order.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

const MpKernel mp;
const perturbed<MpKernel> pmp;

template <int D>
const std::vector<Point<D>>& pts_of(const RunResult& r) {
  if constexpr (D == 2)
    return r.points.p2;
  else
    return r.points.p3;
}

template <int D>
RunResult triangulate(const std::vector<Point<D>>& pts, std::string kernel = "mp",
                      std::string policy = "sos", std::string order = "brio", std::uint64_t seed = 1) {
  RunOptions o;
  o.kernel = kernel;
  o.policy = policy;
  o.order = order;
  o.seed = seed;
  return run(point_set<D>(pts), o);
}

// Exact convex hull boundary count in 2D (Andrew's monotone chain keeping
// collinear boundary points), on distinct points.
std::size_t hull_boundary_points(std::vector<Point2> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p.size();
  std::vector<Point2> h;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = h.size();
    for (const Point2& q : p) {
      while (h.size() >= base + 2 && mp.orient2d(h[h.size() - 2], h.back(), q) == Sign::negative) h.pop_back();
      h.push_back(q);
    }
    h.pop_back();
    std::reverse(p.begin(), p.end());
  }
  std::sort(h.begin(), h.end());
  return static_cast<std::size_t>(std::unique(h.begin(), h.end()) - h.begin());
}

// Positive orientation in the output convention det[v1-v0; ...] > 0.
Sign orient_out(const Point2& a, const Point2& b, const Point2& c) { return mp.orient2d(a, b, c); }
Sign orient_out(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return -mp.orient3d(a, b, c, d);
}

// The brute-force check.  `perturbed_empty`: also no point inside any
// circumsphere by the perturbed test (the unique sos triangulation).
template <int D>
void check_triangulation(const std::vector<Point<D>>& input, const RunResult& r, bool perturbed_empty) {
  constexpr int V = D + 1;
  REQUIRE(r.outcome == RunResult::Outcome::ok);
  const std::vector<Point<D>>& pts = pts_of<D>(r);
  REQUIRE(pts.size() == input.size());
  REQUIRE(r.simplices.size() % V == 0);
  const std::size_t ns = r.simplices.size() / V;
  REQUIRE(ns > 0);

  // First occurrences: every distinct point, and only those, are vertices.
  std::map<Point<D>, std::uint32_t> first;
  for (std::uint32_t i = 0; i < pts.size(); ++i) first.emplace(pts[i], i);
  std::set<std::uint32_t> used(r.simplices.begin(), r.simplices.end());
  std::set<std::uint32_t> firsts;
  for (const auto& [p, i] : first) firsts.insert(i);
  CHECK(used == firsts);
  CHECK(r.distinct_points == first.size());

  std::map<std::array<std::uint32_t, D>, int> facets;
  std::set<std::array<std::uint32_t, 2>> edges;
  for (std::size_t s = 0; s < ns; ++s) {
    const std::uint32_t* v = &r.simplices[s * V];
    for (int j = 0; j < V; ++j) REQUIRE(v[j] < pts.size());
    if constexpr (D == 2) {
      REQUIRE(orient_out(pts[v[0]], pts[v[1]], pts[v[2]]) == Sign::positive);
      for (const auto& [p, i] : first) {
        if (i == v[0] || i == v[1] || i == v[2]) continue;
        REQUIRE(mp.incircle(pts[v[0]], pts[v[1]], pts[v[2]], p) != Sign::positive);
        if (perturbed_empty) REQUIRE(pmp.incircle(pts[v[0]], pts[v[1]], pts[v[2]], p) == Sign::negative);
      }
    } else {
      REQUIRE(orient_out(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]) == Sign::positive);
      for (const auto& [p, i] : first) {
        if (i == v[0] || i == v[1] || i == v[2] || i == v[3]) continue;
        // inside iff insphere > 0 when orient3d > 0; here orient3d < 0.
        REQUIRE(mp.insphere(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], p) != Sign::negative);
        if (perturbed_empty)
          REQUIRE(pmp.insphere(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]], p) == Sign::positive);
      }
    }
    for (int j = 0; j < V; ++j) {
      std::array<std::uint32_t, D> f;
      int n = 0;
      for (int k = 0; k < V; ++k)
        if (k != j) f[n++] = v[k];
      std::sort(f.begin(), f.end());
      ++facets[f];
      for (int k = j + 1; k < V; ++k) edges.insert({std::min(v[j], v[k]), std::max(v[j], v[k])});
    }
  }
  // Facets shared by at most two simplices; boundary facets are hull facets
  // (no point strictly on both sides of their supporting line/plane).
  std::size_t boundary = 0;
  for (const auto& [f, count] : facets) {
    REQUIRE(count <= 2);
    if (count == 2) continue;
    ++boundary;
    bool pos = false, neg = false;
    for (const auto& [p, i] : first) {
      Sign o;
      if constexpr (D == 2)
        o = mp.orient2d(pts[f[0]], pts[f[1]], p);
      else
        o = mp.orient3d(pts[f[0]], pts[f[1]], pts[f[2]], p);
      pos |= o == Sign::positive;
      neg |= o == Sign::negative;
    }
    REQUIRE(!(pos && neg));
  }
  const long long nv = static_cast<long long>(first.size());
  if constexpr (D == 2) {
    // Euler for a triangulated disc whose vertices are all the points.
    const std::size_t h = hull_boundary_points(pts);
    CHECK(ns == 2 * first.size() - h - 2);
    CHECK(boundary == h);
    CHECK(nv - static_cast<long long>(edges.size()) + static_cast<long long>(ns) == 1);
  } else {
    CHECK(nv - static_cast<long long>(edges.size()) + static_cast<long long>(facets.size()) -
              static_cast<long long>(ns) ==
          1);
  }
}

template <int D>
std::vector<Point<D>> uniform_points(std::size_t n, std::uint64_t seed, double scale = 1.0) {
  std::mt19937_64 g(seed);
  std::vector<Point<D>> p(n);
  for (auto& q : p)
    for (int a = 0; a < D; ++a) q[a] = scale * static_cast<double>(g() >> 11) * 0x1.0p-53;
  return p;
}

template <int D>
std::vector<Point<D>> lattice(int k) {
  std::vector<Point<D>> p;
  if constexpr (D == 2) {
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j) p.push_back({double(i), double(j)});
  } else {
    for (int i = 0; i < k; ++i)
      for (int j = 0; j < k; ++j)
        for (int l = 0; l < k; ++l) p.push_back({double(i), double(j), double(l)});
  }
  return p;
}

// 12 points on the circle of radius 5 (Pythagorean triples), exact.
std::vector<Point2> cocircular12() {
  std::vector<Point2> p;
  for (double a : {3.0, 4.0})
    for (double sx : {1.0, -1.0})
      for (double sy : {1.0, -1.0}) p.push_back({sx * a, sy * (7.0 - a)});
  p.push_back({5, 0});
  p.push_back({-5, 0});
  p.push_back({0, 5});
  p.push_back({0, -5});
  return p;
}

template <int D>
void check_all_orders(const std::vector<Point<D>>& pts, const std::string& kernel = "mp") {
  const RunResult ref = triangulate<D>(pts, kernel, "sos", "input");
  check_triangulation<D>(pts, ref, true);
  const auto want = test::canonical_simplices<D>(ref.simplices);
  for (const char* order : {"random", "brio", "hilbert"})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      const RunResult r = triangulate<D>(pts, kernel, "sos", order, seed);
      REQUIRE(r.outcome == RunResult::Outcome::ok);
      CHECK(test::canonical_simplices<D>(r.simplices) == want);
    }
}

}  // namespace

TEST_CASE("bw: unit square, both diagonals are Delaunay; sos picks one for every order", "[bw]") {
  const std::vector<Point2> sq{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  check_all_orders<2>(sq);
  const RunResult r = triangulate<2>(sq, "mp", "strict", "input");
  check_triangulation<2>(sq, r, false);
  CHECK(r.simplices.size() == 6);
}

TEST_CASE("bw: cocircular polygon and lattices (2D)", "[bw]") {
  check_all_orders<2>(cocircular12());
  check_all_orders<2>(lattice<2>(7));
  for (const char* order : {"input", "random", "hilbert"})
    check_triangulation<2>(lattice<2>(6), triangulate<2>(lattice<2>(6), "mp", "strict", order), false);
}

TEST_CASE("bw: points on the hull edges, outside on the hull lines (2D)", "[bw]") {
  // Collinear points on the hull, then points beyond the ends of hull edges.
  std::vector<Point2> p{{0, 0}, {4, 0}, {0, 4}, {1, 0}, {2, 0}, {3, 0}, {0, 1}, {0, 3},
                        {2, 2}, {6, 0}, {0, 7}, {-1, 0}, {1, 1}, {5, -1}};
  check_all_orders<2>(p);
  check_triangulation<2>(p, triangulate<2>(p, "mp", "strict", "input"), false);
}

TEST_CASE("bw: uniform random points (2D, 3D)", "[bw]") {
  check_all_orders<2>(uniform_points<2>(200, 7));
  check_all_orders<3>(uniform_points<3>(120, 8));
}

TEST_CASE("bw: cube, lattices and cospherical points (3D)", "[bw]") {
  std::vector<Point3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  check_all_orders<3>(cube);
  check_triangulation<3>(cube, triangulate<3>(cube, "mp", "strict", "input"), false);
  check_all_orders<3>(lattice<3>(4));
  check_triangulation<3>(lattice<3>(4), triangulate<3>(lattice<3>(4), "mp", "strict", "random"), false);
  // Points on the sphere of radius 3 (Pythagorean quadruples 1^2+2^2+2^2 = 3^2).
  std::vector<Point3> sph{{3, 0, 0}, {-3, 0, 0}, {0, 3, 0}, {0, -3, 0}, {0, 0, 3}, {0, 0, -3}};
  for (double a : {1.0, -1.0})
    for (double b : {2.0, -2.0})
      for (double c : {2.0, -2.0}) {
        sph.push_back({a, b, c});
        sph.push_back({b, a, c});
        sph.push_back({b, c, a});
      }
  check_all_orders<3>(sph);
}

TEST_CASE("bw: coplanar points on the 3D hull", "[bw]") {
  // A square face of points, coplanar hull points, plus points off it.
  std::vector<Point3> p;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) p.push_back({double(i), double(j), 0});
  p.push_back({1.5, 1.5, 2});
  p.push_back({5, 1, 0});   // coplanar with the face, outside it
  p.push_back({1, -3, 0});  // idem
  p.push_back({0.5, 0.5, -1});
  check_all_orders<3>(p);
  check_triangulation<3>(p, triangulate<3>(p, "mp", "strict", "input"), false);
}

TEST_CASE("bw: duplicates map to their first occurrence, whatever the order", "[bw]") {
  std::vector<Point2> base = uniform_points<2>(30, 3);
  std::vector<Point2> p = base;
  std::mt19937_64 g(5);
  for (int k = 0; k < 40; ++k) p.push_back(base[g() % base.size()]);
  std::shuffle(p.begin(), p.end(), g);
  for (const char* order : {"input", "random", "brio", "hilbert"}) {
    const RunResult r = triangulate<2>(p, "mp", "sos", order, 9);
    check_triangulation<2>(p, r, true);  // checks that only first occurrences are used
    CHECK(r.distinct_points == 30);
  }
  // 3D: the cube with every corner repeated.
  std::vector<Point3> c;
  for (int rep = 0; rep < 3; ++rep)
    for (int i = 7; i >= 0; --i) c.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  for (const char* order : {"input", "random", "hilbert"}) {
    const RunResult r = triangulate<3>(c, "mp", "sos", order, 4);
    check_triangulation<3>(c, r, true);
    for (std::uint32_t v : r.simplices) CHECK(v < 8);
  }
}

// The sparse record behind merged_into (algorithms/merge_record.hpp), as both
// Bowyer–Watson and George fill it: initial vertices first, duplicates merged,
// a run that stops before point 3.
TEST_CASE("bw: the merge record gives every point's vertex, kNotProcessed after a stop", "[bw]") {
  MergeRecord<2> m;
  m.start(7, {4, 1, 6});
  CHECK(m.is_initial(4));
  CHECK(m.is_initial(6));
  CHECK_FALSE(m.is_initial(0));
  m.merge(2, 1);
  m.stop_before(3);
  const std::uint32_t np = kNotProcessed;
  CHECK(m.merged_into() == std::vector<std::uint32_t>{0, 1, 1, np, 4, np, 6});
  // No initial vertices (George's enclosing box); a run to the end.
  m.start(4);
  CHECK_FALSE(m.is_initial(0));
  m.merge(3, 0);
  CHECK(m.merged_into() == std::vector<std::uint32_t>{0, 1, 2, 0});
}

TEST_CASE("bw: lower-dimensional inputs give no simplex and say why", "[bw]") {
  auto lower2 = [](const std::vector<Point2>& p) {
    const RunResult r = triangulate<2>(p);
    CHECK(r.outcome == RunResult::Outcome::lower_dimensional);
    CHECK(r.simplices.empty());
    CHECK(!r.message.empty());
    return r;
  };
  auto lower3 = [](const std::vector<Point3>& p) {
    const RunResult r = triangulate<3>(p);
    CHECK(r.outcome == RunResult::Outcome::lower_dimensional);
    CHECK(r.simplices.empty());
    CHECK(!r.message.empty());
    return r;
  };
  lower2({});
  lower2({{1, 2}});
  CHECK(lower2({{1, 2}, {1, 2}, {1, 2}}).distinct_points == 1);
  CHECK(lower2({{0, 0}, {1, 1}, {2, 2}, {3, 3}, {1, 1}}).distinct_points == 4);
  lower3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  lower3({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-5, -5, -5}});
  std::vector<Point3> plane;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) plane.push_back({double(i), double(j), double(i + 2 * j)});
  const RunResult r = lower3(plane);
  CHECK(r.message.find("coplanar") != std::string::npos);
  // One point off the line / plane is enough.
  std::vector<Point2> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {2, 2.5}};
  check_triangulation<2>(line, triangulate<2>(line), true);
  plane.push_back({0, 0, 1});
  check_triangulation<3>(plane, triangulate<3>(plane), true);
}

TEST_CASE("bw: the integer kernel triangulates its snapped points", "[bw]") {
  for (const std::vector<Point2>& p : {uniform_points<2>(150, 11, 1e3), lattice<2>(6), cocircular12()}) {
    const RunResult r = triangulate<2>(p, "integer");
    check_triangulation<2>(r.points.p2, r, true);
  }
  const auto q = uniform_points<3>(80, 12, 1e-3);
  const RunResult r = triangulate<3>(q, "integer");
  check_triangulation<3>(r.points.p3, r, true);
  // Coplanar points on the hull (the perturbed coplanar in-circle test) at a
  // scale where the grid is not the unit grid.
  std::vector<Point3> face;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) face.push_back({0.1 * i, 0.1 * j, 0});
  face.push_back({0.21, 0.13, 0.3});
  face.push_back({0.33, 0.27, -0.2});
  for (const char* order : {"input", "brio"}) {
    const RunResult f = triangulate<3>(face, "integer", "sos", order);
    check_triangulation<3>(f.points.p3, f, true);
  }
}

TEST_CASE("bw: inexact kernels never crash; on easy inputs they succeed", "[bw]") {
  for (const char* k : {"float", "epsilon"}) {
    check_triangulation<2>(uniform_points<2>(300, 21), triangulate<2>(uniform_points<2>(300, 21), k), false);
    check_triangulation<3>(uniform_points<3>(150, 22), triangulate<3>(uniform_points<3>(150, 22), k), false);
    // Near-degenerate: a lattice moved by a few ulps; any outcome is fine, as
    // long as a reported success is a correct triangulation.
    for (int trial = 0; trial < 5; ++trial) {
      std::vector<Point2> p = lattice<2>(12);
      std::mt19937_64 g(trial);
      for (auto& q : p)
        for (double& c : q)
          for (int u = static_cast<int>(g() % 4); u > 0; --u) c = std::nextafter(c, (g() & 1) ? 1e9 : -1e9);
      const RunResult r = triangulate<2>(p, k, "strict", "random", trial);
      if (r.outcome == RunResult::Outcome::failed) {
        CHECK(!r.message.empty());
      }
    }
  }
}

// Clusters of 4 copies of each of `base` uniform points, every coordinate
// moved by 0..2 ulps: orientation signs that plain doubles get wrong.
template <int D>
std::vector<Point<D>> near_duplicates(int base, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::vector<Point<D>> p;
  for (int i = 0; i < base; ++i) {
    Point<D> b;
    for (double& c : b) c = static_cast<double>(g() >> 11) * 0x1.0p-53;
    for (int k = 0; k < 4; ++k) {
      Point<D> q = b;
      for (double& c : q)
        for (int u = static_cast<int>(g() % 3); u > 0; --u) c = std::nextafter(c, (g() & 1) ? 2.0 : -1.0);
      p.push_back(q);
    }
  }
  return p;
}

TEST_CASE("bw: inexact kernels report failures on near-duplicates, exact ones succeed", "[bw]") {
  int failures2 = 0, failures3 = 0;
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto p2 = near_duplicates<2>(100, seed);
    const auto p3 = near_duplicates<3>(60, seed);
    for (const char* k : {"float", "epsilon"}) {
      const RunResult r2 = triangulate<2>(p2, k, "strict", "brio", seed);
      const RunResult r3 = triangulate<3>(p3, k, "strict", "brio", seed);
      for (const RunResult* r : {&r2, &r3})
        if (r->outcome == RunResult::Outcome::failed) {
          CHECK(!r->message.empty());
          CHECK(r->simplices.empty());
        }
      failures2 += r2.outcome == RunResult::Outcome::failed;
      failures3 += r3.outcome == RunResult::Outcome::failed;
    }
    check_triangulation<2>(p2, triangulate<2>(p2, "adaptive", "sos", "brio", seed), true);
    CHECK(triangulate<3>(p3, "adaptive", "sos", "brio", seed).outcome == RunResult::Outcome::ok);
  }
  // The testbed must be able to see failures (recorded: every run fails here).
  CHECK(failures2 > 0);
  CHECK(failures3 > 0);
}

TEST_CASE("bw: insertion orders are permutations and deterministic", "[bw]") {
  const auto p = uniform_points<3>(5000, 99);
  for (auto o : {InsertionOrder::input, InsertionOrder::random, InsertionOrder::brio, InsertionOrder::hilbert}) {
    auto a = insertion_order(std::span<const Point3>(p), o, 17);
    const auto b = insertion_order(std::span<const Point3>(p), o, 17);
    CHECK(a == b);
    // apply_order: the gathered copy, then the points as they were.
    std::vector<Point3> in_place = p, gathered(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) gathered[i] = p[a[i]];
    for (bool cycles : {false, true}) {  // out of place, and the in-place fallback
      std::vector<bool> scratch;
      apply_order(in_place, std::span<const std::uint32_t>(a), false, scratch, cycles);
      CHECK(in_place == gathered);
      apply_order(in_place, std::span<const std::uint32_t>(a), true, scratch, cycles);
      CHECK(in_place == p);
    }
    std::sort(a.begin(), a.end());
    for (std::uint32_t i = 0; i < a.size(); ++i) REQUIRE(a[i] == i);
  }
  // Out of place on 3 threads (ranges of 2^14 points: several here).
  const auto many = uniform_points<3>(50000, 98);
  const auto order = insertion_order(std::span<const Point3>(many), InsertionOrder::brio, 5, 3);
  std::vector<Point3> moved = many, gathered(many.size());
  for (std::size_t i = 0; i < many.size(); ++i) gathered[i] = many[order[i]];
  std::vector<bool> scratch;
  apply_order(moved, std::span<const std::uint32_t>(order), false, scratch, false, 3);
  CHECK(moved == gathered);
  apply_order(moved, std::span<const std::uint32_t>(order), true, scratch, false, 3);
  CHECK(moved == many);
  // The Hilbert order does not depend on the scale: the same points times
  // 2^-1073 (subnormals: cells / extent would overflow) and times 2^900 make a
  // tour as short as the unscaled ones (within rounding at cell edges). It
  // was random on subnormals once: every point fell in a corner cell.
  std::vector<Point3> ints(2000);
  std::mt19937_64 g(5);
  for (auto& q : ints)
    for (auto& c : q) c = double(g() % (1u << 20)) - double(1u << 19);
  auto tour = [&](std::span<const Point3> pts) {
    const auto order = insertion_order(pts, InsertionOrder::hilbert, 3);
    double length = 0;  // on the unscaled points
    for (std::size_t k = 1; k < order.size(); ++k)
      for (int a = 0; a < 3; ++a) length += std::fabs(ints[order[k]][a] - ints[order[k - 1]][a]);
    return length;
  };
  const double ref = tour(ints);
  for (int e : {-1073, -1000, 900}) {
    auto scaled = ints;
    for (auto& q : scaled)
      for (auto& c : q) c = std::ldexp(c, e);
    CHECK(tour(scaled) <= 1.02 * ref);
  }
  // The Hilbert key of the 2x2 grid visits (0,0), (0,1), (1,1), (1,0) in order.
  std::array<std::uint32_t, 2> c00{0, 0}, c01{0, 1}, c11{1, 1}, c10{1, 0};
  const auto k00 = hilbert_key(c00.data(), 2, 1), k01 = hilbert_key(c01.data(), 2, 1);
  const auto k11 = hilbert_key(c11.data(), 2, 1), k10 = hilbert_key(c10.data(), 2, 1);
  CHECK(std::set<std::uint64_t>{k00, k01, k11, k10}.size() == 4);
  // Consecutive keys are grid neighbours on 16x16 and 32x32 grids (the curve
  // is continuous; 2D reads an even number of levels two at a time, an odd
  // one first on its own).
  for (int bits : {4, 5}) {
    std::vector<std::pair<std::uint64_t, std::array<int, 2>>> cells;
    for (int x = 0; x < (1 << bits); ++x)
      for (int y = 0; y < (1 << bits); ++y) {
        std::uint32_t c[2] = {std::uint32_t(x), std::uint32_t(y)};
        cells.push_back({hilbert_key(c, 2, bits), {x, y}});
      }
    std::sort(cells.begin(), cells.end());
    for (std::size_t i = 0; i < cells.size(); ++i) REQUIRE(cells[i].first == i);
    for (std::size_t i = 1; i < cells.size(); ++i)
      REQUIRE(std::abs(cells[i].second[0] - cells[i - 1].second[0]) +
                  std::abs(cells[i].second[1] - cells[i - 1].second[1]) ==
              1);
  }
  // One level finer refines the coarser curve: the key of (x, y) on b bits
  // begins with the key of (x/2, y/2) on b - 1 bits (odd and even b alike).
  std::uint64_t state = 7;
  for (int bits = 2; bits <= 24; ++bits)
    for (int trial = 0; trial < 200; ++trial) {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      const auto mask = (std::uint32_t(1) << bits) - 1;
      std::uint32_t c[2] = {std::uint32_t(state >> 20) & mask, std::uint32_t(state >> 40) & mask};
      std::uint32_t coarse[2] = {c[0] >> 1, c[1] >> 1};
      REQUIRE(hilbert_key(c, 2, bits) >> 2 == hilbert_key(coarse, 2, bits - 1));
    }
  // Same in 3D on an 8x8x8 grid.
  std::vector<std::pair<std::uint64_t, std::array<int, 3>>> cells3;
  for (int x = 0; x < 8; ++x)
    for (int y = 0; y < 8; ++y)
      for (int z = 0; z < 8; ++z) {
        std::uint32_t c[3] = {std::uint32_t(x), std::uint32_t(y), std::uint32_t(z)};
        cells3.push_back({hilbert_key(c, 3, 3), {x, y, z}});
      }
  std::sort(cells3.begin(), cells3.end());
  for (std::size_t i = 1; i < cells3.size(); ++i) {
    int d = 0;
    for (int a = 0; a < 3; ++a) d += std::abs(cells3[i].second[a] - cells3[i - 1].second[a]);
    REQUIRE(d == 1);
  }
}

// The 2D and 3D tables are Skilling's transform read as state machines
// (variants/insertion_order.cpp): the same index on every cell of the small
// grids, and on random cells up to the largest level count a 64-bit key holds.
TEST_CASE("bw: sort_indices_by_key sorts stably, the same on every thread count", "[bw]") {
  // Keys with many ties (stability decides their order), a digit that never
  // varies (skipped) and ranges of several of the sort's chunks (32 768
  // entries each): checked against std::stable_sort.
  std::mt19937_64 g(11);
  for (std::size_t n : {std::size_t{200}, std::size_t{5000}, std::size_t{200000}}) {
    std::vector<std::uint64_t> keys(n + 100);
    for (auto& k : keys) k = (g() % 50) << 53 | (g() % 64) << 11 | 5;
    std::vector<std::uint32_t> idx(keys.size());
    std::iota(idx.begin(), idx.end(), 0u);
    std::shuffle(idx.begin(), idx.end(), g);
    std::vector<std::uint32_t> expected = idx;
    std::stable_sort(expected.begin() + 50, expected.begin() + 50 + n,
                     [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    for (unsigned threads : {1u, 2u, 3u}) {
      std::vector<std::uint32_t> got = idx;
      sort_indices_by_key(got, 50, 50 + n, keys, threads);
      INFO("n " << n << ", threads " << threads);
      const bool same = got == expected;  // not the vectors themselves: Catch would print 200 000 numbers
      CHECK(same);
    }
  }
}

TEST_CASE("bw: the phases of `seconds` add up to it", "[bw]") {
  RunOptions o;
  o.kernel = "adaptive";
  for (unsigned threads : {0u, 2u}) {
    o.threads = threads;
    const RunResult r = run(point_set<3>(uniform_points<3>(20000, 4)), o);
    REQUIRE(r.outcome == RunResult::Outcome::ok);
    const RunResult::Phases& p = r.phase_seconds;
    INFO("threads " << threads);
    CHECK(p.order > 0);
    CHECK(p.triangulate > 0);
    CHECK(p.output > 0);
    CHECK(std::fabs(p.order + p.triangulate + p.output - r.seconds) <= 1e-9 * r.seconds);
  }
}

TEST_CASE("bw: the Hilbert tables give Skilling's index", "[bw]") {
  auto same = [](std::array<std::uint32_t, 3> c, int n, int bits) {
    std::array<std::uint32_t, 3> d = c;
    return hilbert_key(c.data(), n, bits) == hilbert_key_skilling(d.data(), n, bits);
  };
  for (int bits = 1; bits <= 5; ++bits) {
    const std::uint32_t cells = 1u << bits;
    for (std::uint32_t x = 0; x < cells; ++x)
      for (std::uint32_t y = 0; y < cells; ++y) {
        REQUIRE(same({x, y, 0}, 2, bits));
        for (std::uint32_t z = 0; z < cells; ++z) REQUIRE(same({x, y, z}, 3, bits));
      }
  }
  std::mt19937_64 g(5);
  for (int n : {2, 3})
    for (int bits = 6; bits <= 64 / n; ++bits)
      for (int trial = 0; trial < 2000; ++trial) {
        const std::uint64_t mask = (std::uint64_t(1) << bits) - 1;
        REQUIRE(same({std::uint32_t(g() & mask), std::uint32_t(g() & mask), std::uint32_t(g() & mask)}, n, bits));
      }
}

TEST_CASE("bw: unknown names are usage errors", "[bw]") {
  RunOptions o;
  o.kernel = "mp";
  o.order = "spiral";
  CHECK_THROWS_AS(run(point_set<2>(lattice<2>(3)), o), UsageError);
  o.order = "brio";
  o.policy = "loose";
  CHECK_THROWS_AS(run(point_set<2>(lattice<2>(3)), o), UsageError);
  o.policy = "sos";
  o.kernel = "exactish";
  CHECK_THROWS_AS(run(point_set<2>(lattice<2>(3)), o), UsageError);
}
