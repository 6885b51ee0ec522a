// The generators of fuzz/generators.hpp: reproducible bit for bit, and the
// exact degeneracies they promise really are exact (checked with the ground-
// truth MpKernel, not with the generator's own arithmetic).
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>

#include "fuzz/generators.hpp"
#include "predicates/mp_kernel.hpp"

using namespace dlab;
using namespace dlab::gen;

namespace {

template <class P>
bool same_bits(const std::vector<P>& a, const std::vector<P>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(P)) == 0);
}

bool same_bits(const PointSet& a, const PointSet& b) {
  return a.dimension == b.dimension && same_bits(a.p2, b.p2) && same_bits(a.p3, b.p3);
}

template <class P>
std::size_t distinct(std::vector<P> v) {
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

// 3D collinearity through the three coordinate-plane projections.
bool collinear3(const MpKernel& k, const Point3& a, const Point3& b, const Point3& c) {
  for (int i = 0; i < 3; ++i) {
    const int u = i, v = (i + 1) % 3;
    if (k.orient2d({a[u], a[v]}, {b[u], b[v]}, {c[u], c[v]}) != Sign::zero) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("splitmix64 matches the reference stream", "[gen]") {
  // Vigna's reference splitmix64.c, seed 0: the first three outputs.
  SplitMix64 r(0);
  CHECK(r.next() == 0xe220a8397b1dcdafULL);
  CHECK(r.next() == 0x6e789e6aa1b965f4ULL);
  CHECK(r.next() == 0x06c45d188009454fULL);
  SplitMix64 u(42);
  for (int i = 0; i < 1000; ++i) {
    const double x = u.uniform01();
    REQUIRE(x >= 0);
    REQUIRE(x < 1);
    REQUIRE(std::ldexp(x, 53) == std::floor(std::ldexp(x, 53)));  // a multiple of 2^-53
  }
}

TEST_CASE("pdb-like: three decimals, well spaced", "[gen]") {
  // Liu & Snoeyink 2005's setting: PDB's 8.3f coordinates of evenly spread atoms.
  for (int dim : {2, 3}) {
    GenOptions o;
    o.name = "pdb-like";
    o.n = 500;
    o.dim = dim;
    o.seed = 3;
    const PointSet ps = generate(o);
    REQUIRE(ps.size() == 500);
    std::vector<std::array<double, 3>> pts;
    for (const auto& p : ps.p2) pts.push_back({p[0], p[1], 0});
    for (const auto& p : ps.p3) pts.push_back({p[0], p[1], p[2]});
    char buf[64];
    for (const auto& p : pts)
      for (double c : p) {
        // The nearest double to a multiple of 0.001 that prints in 8 columns.
        std::snprintf(buf, sizeof buf, "%8.3f", c);
        CHECK(std::strlen(buf) == 8);
        CHECK(std::strtod(buf, nullptr) == c);
        CHECK(std::fabs(c * 1000 - std::nearbyint(c * 1000)) < 1e-6);
      }
    // Jitter of at most a quarter spacing per axis: at least half a spacing
    // apart, less the rounding of each coordinate (0.0005 per axis).
    double closest = 1e300;
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = 0; j < i; ++j) {
        double d2 = 0;
        for (int k = 0; k < 3; ++k) d2 += (pts[i][k] - pts[j][k]) * (pts[i][k] - pts[j][k]);
        closest = std::min(closest, std::sqrt(d2));
      }
    CHECK(closest >= 1.9 / 2 - 0.001 * std::sqrt(3.0));
    CHECK(closest < 1.9);  // neighbours in adjacent cells come closer than a spacing somewhere
  }
}

TEST_CASE("every generator is reproducible and the seed matters", "[gen]") {
  for (const auto& name : generator_names()) {
    for (int dim : {2, 3}) {
      if (!generator_has_dimension(name, dim)) continue;
      GenOptions o;
      o.name = name;
      o.n = 200;
      o.dim = dim;
      o.side = 16;
      o.seed = 7;
      INFO(name << " dim " << dim);
      const PointSet a = generate(o), b = generate(o);
      CHECK(same_bits(a, b));
      CHECK(a.dimension == dim);
      if (name != "kettner-grid" && name != "kettner-hull") CHECK(a.size() == 200);
      for (const auto& p : a.p2) CHECK((std::isfinite(p[0]) && std::isfinite(p[1])));
      for (const auto& p : a.p3) CHECK((std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])));
      const bool seeded = name != "lattice" && name != "rotated-lattice" && name.rfind("kettner", 0) != 0;
      if (seeded) {
        o.seed = 8;
        CHECK_FALSE(same_bits(a, generate(o)));
      }
    }
  }
  const auto named = [](const char* name, int dim) {
    GenOptions o;
    o.name = name;
    o.dim = dim;
    return o;
  };
  CHECK_THROWS_AS(generate(named("nope", 0)), std::invalid_argument);
  CHECK_THROWS_AS(generate(named("coplanar", 2)), std::invalid_argument);
  CHECK_THROWS_AS(generate(named("kettner-grid", 3)), std::invalid_argument);
  GenOptions over = named("uniform", 2);
  over.lo = -1e308;
  over.hi = 1e308;
  CHECK_THROWS_AS(generate(over), std::invalid_argument);  // would overflow: refused, not emitted
}

TEST_CASE("generator output is pinned (same bytes on every machine)", "[gen]") {
  // Values computed by hand from the splitmix64 reference outputs above:
  // uniform01 = (x >> 11) * 2^-53.
  const auto u = uniform<2>(1, 0);
  CHECK(u[0][0] == static_cast<double>(0xe220a8397b1dcdafULL >> 11) * 0x1p-53);
  CHECK(u[0][1] == static_cast<double>(0x6e789e6aa1b965f4ULL >> 11) * 0x1p-53);
}

TEST_CASE("cocircular and cospherical sets are exactly cocircular / cospherical", "[gen]") {
  const MpKernel k;
  for (std::size_t n : {4u, 12u, 100u, 500u}) {
    const auto c = cospherical<2>(n, 3);
    REQUIRE(c.size() == n);
    REQUIRE(distinct(c) == n);
    std::size_t nonzero_orient = 0;
    for (std::size_t i = 0; i + 3 < n; ++i) {
      CHECK(k.incircle(c[i], c[i + 1], c[i + 2], c[i + 3]) == Sign::zero);
      CHECK(k.incircle(c[0], c[i + 1], c[n / 2], c[i + 3]) == Sign::zero);
      nonzero_orient += k.orient2d(c[i], c[i + 1], c[i + 2]) != Sign::zero;
    }
    CHECK(nonzero_orient > 0);  // really a circle, not a degenerate line
  }
  for (std::size_t n : {6u, 50u, 400u}) {
    const auto s = cospherical<3>(n, 3);
    REQUIRE(s.size() == n);
    REQUIRE(distinct(s) == n);
    std::size_t nonzero_orient = 0;
    for (std::size_t i = 0; i + 4 < n; ++i) {
      CHECK(k.insphere(s[i], s[i + 1], s[i + 2], s[i + 3], s[i + 4]) == Sign::zero);
      nonzero_orient += k.orient3d(s[i], s[i + 1], s[i + 2], s[i + 3]) != Sign::zero;
    }
    CHECK(nonzero_orient > 0);
  }
  // The largest 2D set still fits the double mantissa: check a sample.
  const auto big = cospherical<2>(20000, 1);
  for (std::size_t i = 0; i + 3 < big.size(); i += 997)
    CHECK(k.incircle(big[i], big[i + 1], big[i + 2], big[i + 3]) == Sign::zero);
  // A point moved by one ulp leaves the circle.
  auto moved = cospherical<2>(8, 1);
  moved[3][0] = move_ulps(moved[3][0], 1);
  CHECK(k.incircle(moved[0], moved[1], moved[2], moved[3]) != Sign::zero);
}

TEST_CASE("collinear and coplanar sets: exactly `off` points off the line / plane", "[gen]") {
  const MpKernel k;
  for (std::size_t off : {0u, 1u, 3u}) {
    const auto p = collinear<2>(60, off, 5);
    REQUIRE(distinct(p) == 60);
    // The line is the one through the first pair with the most points on it.
    std::size_t best = 0;
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = i + 1; j < 6; ++j) {
        std::size_t on = 0;
        for (const auto& q : p) on += k.orient2d(p[i], p[j], q) == Sign::zero;
        best = std::max(best, on);
      }
    CHECK(best == 60 - off);

    const auto p3 = collinear<3>(40, off, 5);
    std::size_t best3 = 0;
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = i + 1; j < 5; ++j) {
        std::size_t on = 0;
        for (const auto& q : p3) on += collinear3(k, p3[i], p3[j], q);
        best3 = std::max(best3, on);
      }
    CHECK(best3 == 40 - off);

    const auto c = coplanar(50, off, 5);
    REQUIRE(distinct(c) == 50);
    std::size_t bestp = 0;
    for (std::size_t i = 0; i < 5; ++i)
      for (std::size_t j = i + 1; j < 5; ++j)
        for (std::size_t l = j + 1; l < 6; ++l) {
          if (collinear3(k, c[i], c[j], c[l])) continue;
          std::size_t on = 0;
          for (const auto& q : c) on += k.orient3d(c[i], c[j], c[l], q) == Sign::zero;
          bestp = std::max(bestp, on);
        }
    CHECK(bestp == 50 - off);
  }
}

TEST_CASE("move_ulps moves by exactly k ulps", "[gen]") {
  // Inside one binade an ulp is 2^(e-52): the move is exactly k of them.
  for (std::int64_t kk : {1, 2, 5, 100}) {
    const double x = 1.25;  // ulp 2^-52
    CHECK(move_ulps(x, kk) - x == static_cast<double>(kk) * 0x1p-52);
    CHECK(x - move_ulps(x, -kk) == static_cast<double>(kk) * 0x1p-52);
    CHECK(ulp_distance(x, move_ulps(x, kk)) == kk);
  }
  const double dmin = std::numeric_limits<double>::denorm_min();
  CHECK(move_ulps(dmin, -1) == 0);
  CHECK(move_ulps(dmin, -2) == -dmin);          // across zero (counting +0 once)
  CHECK(ulp_distance(dmin, -dmin) == -2);
  CHECK(move_ulps(1.0, -1) == 1.0 - 0x1p-53);  // below a power of two the ulp halves
  CHECK(ulp_distance(0.5, 1.0) == (std::int64_t{1} << 52));

  const auto base = cospherical<2>(50, 2);
  const auto moved = perturb_ulps<2>(base, 3, 9);
  std::int64_t largest = 0;
  bool any_moved = false;
  for (std::size_t i = 0; i < base.size(); ++i)
    for (int j = 0; j < 2; ++j) {
      const std::int64_t d = ulp_distance(base[i][j], moved[i][j]);
      CHECK(std::abs(d) <= 3);
      largest = std::max(largest, std::abs(d));
      any_moved = any_moved || d != 0;
    }
  CHECK(largest == 3);
  CHECK(any_moved);
}

TEST_CASE("near-duplicates, magnitudes, lattices", "[gen]") {
  const auto nd = near_duplicates<2>(400, 1, 4, 0);  // k = 0: exact duplicates
  CHECK(distinct(nd) <= 100);
  const auto nd2 = near_duplicates<3>(400, 1, 4, 2);
  CHECK(distinct(nd2) > 100);

  for (const auto& p : tiny<3>(300, 4))
    for (double c : p) CHECK(std::fabs(c) < std::numeric_limits<double>::min());
  double m = 0;
  for (const auto& p : huge<2>(300, 4))
    for (double c : p) m = std::max(m, std::fabs(c));
  CHECK(m > 1e300);
  CHECK(std::isfinite(m));

  const auto l = lattice<3>(27);
  CHECK(distinct(l) == 27);
  for (const auto& p : l)
    for (double c : p) CHECK((c >= 0 && c <= 2 && c == std::floor(c)));

  // The rotation is exact: the first row of the lattice stays collinear, and
  // the rotated 3D lattice keeps its planes.
  const MpKernel k;
  const auto r2 = rotated_lattice<2>(100);  // 10 x 10, row y = 0 is points 0..9
  for (int i = 2; i < 10; ++i) CHECK(k.orient2d(r2[0], r2[1], r2[static_cast<std::size_t>(i)]) == Sign::zero);
  CHECK(k.orient2d(r2[0], r2[1], r2[10]) != Sign::zero);
  CHECK(k.incircle(r2[0], r2[1], r2[11], r2[10]) == Sign::zero);  // a unit square stays cocircular
  const auto r3 = rotated_lattice<3>(64);  // 4 x 4 x 4; z = 0 is points 0..15
  for (int i = 3; i < 16; ++i)
    CHECK(k.orient3d(r3[0], r3[1], r3[4], r3[static_cast<std::size_t>(i)]) == Sign::zero);
  CHECK(k.orient3d(r3[0], r3[1], r3[4], r3[16]) != Sign::zero);
}

TEST_CASE("Kettner et al. 2008 configurations", "[gen]") {
  const auto g = kettner_grid(256);
  REQUIRE(g.size() == 256 * 256 + 2);
  const Point2 q = g[g.size() - 2], r = g.back();
  CHECK(q == Point2{12, 12});
  CHECK(r == Point2{24, 24});
  CHECK(g[0] == Point2{0.5, 0.5});
  CHECK(g[1] == Point2{0.5 + 0x1p-53, 0.5});
  CHECK(g[256] == Point2{0.5, 0.5 + 0x1p-53});
  // All 65536 points distinct, and the exact sign is sign(y - x).
  CHECK(distinct(std::vector<Point2>(g.begin(), g.end() - 2)) == 256 * 256);
  const MpKernel k;
  for (int y = 0; y < 256; y += 5)
    for (int x = 0; x < 256; x += 3) {
      const Sign want = y > x ? Sign::positive : (y < x ? Sign::negative : Sign::zero);
      REQUIRE(k.orient2d(g[static_cast<std::size_t>(y * 256 + x)], q, r) == want);
    }
  CHECK(kettner_hull("A1").size() == 9);
  CHECK(kettner_hull("A2").size() == 4);
  CHECK(kettner_hull("B1").size() == 4);
  CHECK(kettner_hull("B2").size() == 5);
  CHECK(kettner_hull("A1")[3] == Point2{0.50000000000001621, 0.50000000000001243});
  CHECK_THROWS_AS(kettner_hull("C9"), std::invalid_argument);
}
