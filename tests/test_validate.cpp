// The validator, on triangulations built independently of the code under test:
// brute-force Delaunay triangulations of points in general position (every
// triple / quadruple whose circumcircle / circumsphere is empty, by the exact
// mp kernel: O(n^4), fine for a few dozen points), hand-built small cases, and
// deliberately broken versions of both. Each broken case must fail for the
// right reason (its check count), and a valid one must pass every check.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <vector>

#include "algorithms/validate.hpp"
#include "predicates/mp_kernel.hpp"

namespace {

using dlab::Check;
using dlab::Point2;
using dlab::Point3;
using dlab::Sign;

// splitmix64 -> doubles in [0, 1) (k * 2^-53): random points are in general
// position with probability 1 (no four cocircular, no five cospherical).
struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }
};

std::vector<Point2> random2(std::size_t n, std::uint64_t seed) {
  Rng r{seed};
  std::vector<Point2> p(n);
  for (auto& q : p) q = {r.unit(), r.unit()};
  return p;
}
std::vector<Point3> random3(std::size_t n, std::uint64_t seed) {
  Rng r{seed};
  std::vector<Point3> p(n);
  for (auto& q : p) q = {r.unit(), r.unit(), r.unit()};
  return p;
}

// Brute force: a triangle is Delaunay iff no point is strictly inside its circle.
std::vector<std::uint32_t> brute_delaunay(const std::vector<Point2>& p) {
  const dlab::MpKernel k;
  std::vector<std::uint32_t> out;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c) {
        const Sign o = k.orient2d(p[a], p[b], p[c]);
        if (o == Sign::zero) continue;
        const std::uint32_t x = o == Sign::positive ? b : c, y = o == Sign::positive ? c : b;
        bool empty = true;
        for (std::uint32_t d = 0; d < n && empty; ++d)
          empty = k.incircle(p[a], p[x], p[y], p[d]) != Sign::positive;
        if (empty) out.insert(out.end(), {a, x, y});
      }
  return out;
}

// Positive orientation (det[v1-v0; v2-v0; v3-v0] > 0) is Shewchuk's orient3d < 0.
std::vector<std::uint32_t> brute_delaunay(const std::vector<Point3>& p) {
  const dlab::MpKernel k;
  std::vector<std::uint32_t> out;
  const auto n = static_cast<std::uint32_t>(p.size());
  for (std::uint32_t a = 0; a < n; ++a)
    for (std::uint32_t b = a + 1; b < n; ++b)
      for (std::uint32_t c = b + 1; c < n; ++c)
        for (std::uint32_t d = c + 1; d < n; ++d) {
          const Sign o = k.orient3d(p[a], p[b], p[c], p[d]);
          if (o == Sign::zero) continue;
          // orient3d(a,y,x,d) > 0 after the swap, so insphere > 0 means inside.
          const std::uint32_t x = o == Sign::negative ? b : c, y = o == Sign::negative ? c : b;
          bool empty = true;
          for (std::uint32_t e = 0; e < n && empty; ++e)
            empty = k.insphere(p[a], p[y], p[x], p[d], p[e]) != Sign::positive;
          if (empty) out.insert(out.end(), {a, x, y, d});
        }
  return out;
}

// Every check passes except those listed.
void require_only(const dlab::ValidationReport& r, std::initializer_list<Check> failing) {
  INFO(r.summary());
  for (int c = 0; c < dlab::kCheckCount; ++c) {
    const bool expected = std::find(failing.begin(), failing.end(), static_cast<Check>(c)) != failing.end();
    INFO(dlab::check_name(static_cast<Check>(c)));
    if (expected)
      CHECK(r.checks[c].count > 0);
    else
      CHECK(r.checks[c].count == 0);
  }
}

// The kite A(0,0) B(4,-1) C(8,0) D(4,1): BD is the Delaunay diagonal
// (circle ABD: centre (17/8, 0), radius 17/8, C outside); AC is not (circle
// ABC: centre (4, 7.5), radius 8.5, D at distance 6.5 inside).
const std::vector<Point2> kite{{0, 0}, {4, -1}, {8, 0}, {4, 1}};

}  // namespace

TEST_CASE("validate: brute-force Delaunay triangulations pass", "[validate]") {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const auto p2 = random2(30, seed);
    const auto t2 = brute_delaunay(p2);
    const auto r2 = dlab::validate(std::span<const Point2>(p2), t2);
    INFO(r2.summary());
    CHECK(r2.delaunay());
    // Euler: 2n - 2 - h triangles and 3n - 3 - h edges, with h = boundary edges.
    CHECK(r2.simplices == 2 * 30 - 2 - r2.boundary_facets);
    CHECK(r2.interior_facets + r2.boundary_facets == 3 * 30 - 3 - r2.boundary_facets);

    const auto p3 = random3(16, seed);
    const auto t3 = brute_delaunay(p3);
    const auto r3 = dlab::validate(std::span<const Point3>(p3), t3);
    INFO(r3.summary());
    CHECK(r3.delaunay());
    CHECK(2 * r3.interior_facets + r3.boundary_facets == 4 * r3.simplices);
  }
}

TEST_CASE("validate: the kite, Delaunay and flipped", "[validate]") {
  const std::vector<std::uint32_t> good{0, 1, 3, 1, 2, 3};
  require_only(dlab::validate(std::span<const Point2>(kite), good), {});
  const std::vector<std::uint32_t> flipped{0, 1, 2, 0, 2, 3};
  const auto r = dlab::validate(std::span<const Point2>(kite), flipped);
  require_only(r, {Check::not_delaunay});
  CHECK(r.valid());
  CHECK(!r.delaunay());
  CHECK(r.non_delaunay_facets() == 1);
}

TEST_CASE("validate: broken 2D triangulations fail for the right reason", "[validate]") {
  const auto p = random2(30, 7);
  const auto t = brute_delaunay(p);
  const std::span<const Point2> pts(p);
  const std::size_t m = t.size() / 3;

  SECTION("a reversed triangle") {
    auto b = t;
    std::swap(b[3 * 5 + 1], b[3 * 5 + 2]);
    const auto r = dlab::validate(pts, b);
    CHECK(r[Check::orientation].count == 1);
    CHECK(r[Check::orientation].simplex == 5);
    CHECK(!r.valid());
  }
  SECTION("an index out of range") {
    auto b = t;
    b[7] = 30;
    const auto r = dlab::validate(pts, b);
    require_only(r, {Check::index_range});
    CHECK(r[Check::index_range].simplex == 2);
    CHECK(r.skipped);
  }
  SECTION("a truncated list") {
    auto b = t;
    b.pop_back();
    CHECK(dlab::validate(pts, b)[Check::index_range].count == 1);
  }
  SECTION("a missing vertex") {
    auto q = p;
    q.push_back({0.5, 0.5});  // inside the hull, in no triangle as a vertex
    const auto r = dlab::validate(std::span<const Point2>(q), t);
    require_only(r, {Check::missing_vertex});
    CHECK(r[Check::missing_vertex].point == 30);
  }
  SECTION("a duplicated triangle") {
    auto b = t;
    b.insert(b.end(), t.begin() + 6, t.begin() + 9);
    const auto r = dlab::validate(pts, b);
    CHECK(r[Check::duplicate_simplex].count == 1);
    CHECK(r[Check::duplicate_simplex].simplex == static_cast<std::int64_t>(m));
    CHECK(!r.valid());
  }
  SECTION("a hole: an interior triangle removed") {
    const auto r0 = dlab::validate(pts, t);
    // Find a triangle with no boundary edge: remove it and check each one found.
    int holes = 0;
    for (std::size_t s = 0; s < m && holes < 3; ++s) {
      auto b = t;
      b.erase(b.begin() + 3 * s, b.begin() + 3 * s + 3);
      const auto r = dlab::validate(pts, b);
      if (r.boundary_facets != r0.boundary_facets + 3) continue;  // it touched the hull
      ++holes;
      INFO(r.summary());
      CHECK(!r.valid());
      CHECK(r[Check::boundary_convex].count > 0);
      CHECK(r[Check::missing_vertex].count == 0);
    }
    CHECK(holes == 3);
  }
  SECTION("an overlapping extra triangle") {
    auto b = t;
    // A ccw triangle on three vertices of two adjacent triangles: (0,1,2) + far vertex.
    const std::uint32_t a0 = t[0], a1 = t[1], a2 = t[2];
    const dlab::MpKernel k;
    int added = 0;
    for (std::uint32_t x = 0; x < p.size() && added == 0; ++x) {
      if (x == a0 || x == a1 || x == a2) continue;
      if (k.orient2d(p[a0], p[a1], p[x]) == Sign::positive) {
        b.insert(b.end(), {a0, a1, x});
        ++added;
      }
    }
    REQUIRE(added == 1);
    const auto r = dlab::validate(pts, b);
    INFO(r.summary());
    CHECK(!r.valid());
    CHECK(r[Check::facet_same_side].count + r[Check::non_manifold_facet].count +
              r[Check::cover_degree].count >
          0);
  }
}

TEST_CASE("validate: a non-convex boundary (a dent)", "[validate]") {
  // Square A B C D with E = (2,1) inside; dropping triangle ABE leaves a dent at E.
  const std::vector<Point2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 1}};
  const std::vector<std::uint32_t> full{0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  require_only(dlab::validate(std::span<const Point2>(p), full), {});
  const std::vector<std::uint32_t> dent{1, 2, 4, 2, 3, 4, 3, 0, 4};
  const auto r = dlab::validate(std::span<const Point2>(p), dent);
  require_only(r, {Check::boundary_convex});
  CHECK(r[Check::boundary_convex].point == 4);
}

TEST_CASE("validate: two triangulations of one quad on top of each other", "[validate]") {
  // Both diagonals of the kite at once: every edge is in two triangles on the same side.
  const std::vector<std::uint32_t> both{0, 1, 3, 1, 2, 3, 0, 1, 2, 0, 2, 3};
  const auto r = dlab::validate(std::span<const Point2>(kite), both);
  CHECK(r[Check::cover_degree].count == 1);
  CHECK(r[Check::facet_same_side].count > 0);
  CHECK(!r.valid());
}

TEST_CASE("validate: collinear boundary points and cocircular ties", "[validate]") {
  // 3x3 grid: every square's diagonal is a cocircular tie, both choices are Delaunay;
  // the midpoints of the sides are boundary vertices where the boundary goes straight on.
  std::vector<Point2> p;
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x) p.push_back({double(x), double(y)});
  std::vector<std::uint32_t> t;
  for (std::uint32_t y = 0; y < 2; ++y)
    for (std::uint32_t x = 0; x < 2; ++x) {
      const std::uint32_t a = 3 * y + x, b = a + 1, c = a + 4, d = a + 3;
      if ((x + y) % 2 == 0)
        t.insert(t.end(), {a, b, c, a, c, d});
      else
        t.insert(t.end(), {a, b, d, b, c, d});
    }
  require_only(dlab::validate(std::span<const Point2>(p), t), {});
  // Bottom row re-triangulated as (0,2,4) (0,4,3) (2,5,4): point 1 is on the
  // boundary edge 0-2 without being a vertex.
  std::vector<std::uint32_t> bad{0, 2, 4, 0, 4, 3, 2, 5, 4};
  bad.insert(bad.end(), t.begin() + 12, t.end());
  const auto r = dlab::validate(std::span<const Point2>(p), bad);
  require_only(r, {Check::missing_vertex});
  CHECK(r[Check::missing_vertex].point == 1);
}

TEST_CASE("validate: lower-dimensional input and duplicates", "[validate]") {
  const std::vector<Point2> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}};
  const auto r = dlab::validate(std::span<const Point2>(line), std::vector<std::uint32_t>{});
  CHECK(r.lower_dimensional);
  CHECK(r.delaunay());
  // Any simplex on collinear points is flat.
  const auto r1 = dlab::validate(std::span<const Point2>(line), std::vector<std::uint32_t>{0, 1, 2});
  CHECK(r1[Check::orientation].count == 1);
  // Full-dimensional input with no simplex: every point missing.
  const auto r2 = dlab::validate(std::span<const Point2>(kite), std::vector<std::uint32_t>{});
  CHECK(!r2.lower_dimensional);
  CHECK(r2[Check::missing_vertex].count == 4);
  // Empty input.
  CHECK(dlab::validate(std::span<const Point2>(), std::vector<std::uint32_t>{}).delaunay());
  // Coplanar 3D input with no simplex is valid.
  const std::vector<Point3> plane{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
  CHECK(dlab::validate(std::span<const Point3>(plane), std::vector<std::uint32_t>{}).lower_dimensional);

  // Duplicates: a copy of a used point is fine; naming the copy is not.
  auto dup = kite;
  dup.push_back({4, 1});     // copy of D = 3
  dup.push_back({-0.0, 0});  // copy of A = 0 (-0 equals +0)
  const std::vector<std::uint32_t> good{0, 1, 3, 1, 2, 3};
  const auto rd = dlab::validate(std::span<const Point2>(dup), good);
  require_only(rd, {});
  CHECK(rd.distinct_points == 4);
  const std::vector<std::uint32_t> copy{0, 1, 4, 1, 2, 4};
  require_only(dlab::validate(std::span<const Point2>(dup), copy), {Check::duplicate_reference});
}

TEST_CASE("validate: broken 3D triangulations fail for the right reason", "[validate]") {
  const auto p = random3(16, 11);
  const auto t = brute_delaunay(p);
  const std::span<const Point3> pts(p);
  const std::size_t m = t.size() / 4;
  const auto r0 = dlab::validate(pts, t);
  REQUIRE(r0.delaunay());

  // The facet table is sized for a closed triangulation (about two facets per
  // tetrahedron) and grows past that: here in the middle of the list, between
  // the two halves of t, whose shared facets must still find each other.
  // Would catch: entries lost or misplaced when the table grows.
  SECTION("a soup of disjoint tetrahedra between the two halves") {
    auto q = p;
    std::vector<std::uint32_t> b(t.begin(), t.begin() + 4 * (m / 2));
    const std::size_t soup = 300;
    for (std::size_t k = 0; k < soup; ++k) {
      const auto first = static_cast<std::uint32_t>(q.size());
      const double x = 10.0 + 3.0 * static_cast<double>(k);
      q.insert(q.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}, {x, 0, 1}});
      b.insert(b.end(), {first, first + 1, first + 2, first + 3});
    }
    b.insert(b.end(), t.begin() + 4 * (m / 2), t.end());
    const auto r = dlab::validate(std::span<const Point3>(q), b);
    INFO(r.summary());
    CHECK(r.interior_facets == r0.interior_facets);
    CHECK(r.boundary_facets == r0.boundary_facets + 4 * soup);
    CHECK(r[Check::non_manifold_facet].count == 0);
    CHECK(r[Check::facet_same_side].count == 0);
    CHECK(r[Check::disconnected].count > 0);
  }
  SECTION("a reversed tetrahedron") {
    auto b = t;
    std::swap(b[4 * 3 + 2], b[4 * 3 + 3]);
    const auto r = dlab::validate(pts, b);
    CHECK(r[Check::orientation].count == 1);
    CHECK(r[Check::orientation].simplex == 3);
  }
  SECTION("a missing vertex") {
    auto q = p;
    q.push_back({0.5, 0.5, 0.5});
    require_only(dlab::validate(std::span<const Point3>(q), t), {Check::missing_vertex});
  }
  SECTION("an index out of range") {
    auto b = t;
    b[5] = 1000;
    require_only(dlab::validate(pts, b), {Check::index_range});
  }
  SECTION("a hole or a dent: any tetrahedron removed") {
    for (std::size_t s = 0; s < m; ++s) {
      auto b = t;
      b.erase(b.begin() + 4 * s, b.begin() + 4 * s + 4);
      const auto r = dlab::validate(pts, b);
      INFO("removed " << s << "\n" << r.summary());
      CHECK(!r.valid());
    }
  }
  SECTION("a 2-3 flip makes it valid but not Delaunay") {
    // For each interior facet abc with apexes d, e: if segment de crosses the
    // triangle, replace the two tetrahedra by the three around edge de.
    const dlab::MpKernel k;
    const auto orient = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
      return -k.orient3d(p[a], p[b], p[c], p[d]);  // det[b-a; c-a; d-a]
    };
    int flips = 0;
    for (std::size_t s = 0; s < m && flips < 3; ++s)
      for (std::size_t u = s + 1; u < m; ++u) {
        std::vector<std::uint32_t> S(t.begin() + 4 * s, t.begin() + 4 * s + 4);
        std::vector<std::uint32_t> U(t.begin() + 4 * u, t.begin() + 4 * u + 4);
        std::vector<std::uint32_t> common;
        for (auto x : S)
          if (std::find(U.begin(), U.end(), x) != U.end()) common.push_back(x);
        if (common.size() != 3) continue;
        std::uint32_t d = 0, e = 0;
        for (auto x : S)
          if (std::find(common.begin(), common.end(), x) == common.end()) d = x;
        for (auto x : U)
          if (std::find(common.begin(), common.end(), x) == common.end()) e = x;
        const std::uint32_t a = common[0], b = common[1], c = common[2];
        const Sign s1 = orient(d, e, a, b), s2 = orient(d, e, b, c), s3 = orient(d, e, c, a);
        if (s1 == Sign::zero || s1 != s2 || s2 != s3) continue;  // not a convex pair
        std::vector<std::uint32_t> b2;
        for (std::size_t w = 0; w < m; ++w)
          if (w != s && w != u) b2.insert(b2.end(), t.begin() + 4 * w, t.begin() + 4 * w + 4);
        for (auto [x, y] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
          if (orient(d, e, x, y) == Sign::positive)
            b2.insert(b2.end(), {d, e, x, y});
          else
            b2.insert(b2.end(), {e, d, x, y});
        }
        const auto r = dlab::validate(pts, b2);
        INFO(r.summary());
        CHECK(r.valid());
        CHECK(r.non_delaunay_facets() >= 1);
        ++flips;
        break;
      }
    CHECK(flips == 3);
  }
  SECTION("an overlapping extra tetrahedron") {
    auto b = t;
    const std::uint32_t a0 = t[0], a1 = t[1], a2 = t[2], a3 = t[3];
    b.insert(b.end(), {a1, a0, a2, a3});          // the same tetrahedron reversed...
    std::swap(b[b.size() - 1], b[b.size() - 2]);  // ...and back: a duplicate in another order
    const auto r = dlab::validate(pts, b);
    CHECK(r[Check::duplicate_simplex].count == 1);
    // A new tetrahedron through the interior: first vertex of tet 0 and three far points.
    auto c = t;
    const dlab::MpKernel k;
    bool added = false;
    for (std::uint32_t x = 0; x < 16 && !added; ++x)
      for (std::uint32_t y = x + 1; y < 16 && !added; ++y)
        for (std::uint32_t z = y + 1; z < 16 && !added; ++z) {
          std::vector<std::uint32_t> q{a0, x, y, z};
          if (x == a0 || y == a0 || z == a0) continue;
          const Sign o = k.orient3d(p[a0], p[x], p[y], p[z]);
          if (o == Sign::zero) continue;
          if (o == Sign::positive) std::swap(q[1], q[2]);
          // Skip tetrahedra of the triangulation.
          auto sorted = q;
          std::sort(sorted.begin(), sorted.end());
          bool present = false;
          for (std::size_t w = 0; w < m && !present; ++w) {
            std::vector<std::uint32_t> tw(t.begin() + 4 * w, t.begin() + 4 * w + 4);
            std::sort(tw.begin(), tw.end());
            present = tw == sorted;
          }
          if (present) continue;
          c.insert(c.end(), q.begin(), q.end());
          added = true;
        }
    REQUIRE(added);
    const auto rc = dlab::validate(pts, c);
    INFO(rc.summary());
    CHECK(!rc.valid());
  }
}

TEST_CASE("orient_positively: reversed simplices are turned back, zero volume is left", "[validate]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    dlab::PointSet ps2, ps3;
    ps2.dimension = 2;
    ps2.p2 = random2(24, seed);
    ps3.dimension = 3;
    ps3.p3 = random3(14, seed);
    for (const dlab::PointSet* ps : {&ps2, &ps3}) {
      const std::size_t k = static_cast<std::size_t>(ps->dimension) + 1;
      const auto good = ps->dimension == 2 ? brute_delaunay(ps->p2) : brute_delaunay(ps->p3);
      auto given = good;
      CHECK(dlab::orient_positively(*ps, given) == 0);  // all positive already
      CHECK(given == good);
      // Reverse every simplex whose index is a multiple of 3 or 5 (swap its last two vertices).
      std::size_t reversed = 0;
      for (std::size_t s = 0; s * k < given.size(); ++s)
        if (s % 3 == 0 || s % 5 == 0) {
          std::swap(given[s * k + k - 2], given[s * k + k - 1]);
          ++reversed;
        }
      CHECK_FALSE(dlab::validate(*ps, given).valid());
      CHECK(dlab::orient_positively(*ps, given) == reversed);
      const auto r = dlab::validate(*ps, given);
      INFO(r.summary());
      CHECK(r.delaunay());
      // Zero volume (a repeated vertex) is neither positive nor negative: left as it is.
      std::vector<std::uint32_t> flat(k, 0);
      flat[1] = 1;
      const auto before = flat;
      CHECK(dlab::orient_positively(*ps, flat) == 0);
      CHECK(flat == before);
    }
  }
}
