// The integer kernel (George 1997, section 2.3) and its pieces:
// - WideInt arithmetic against GMP;
// - the exact integer determinants against GMP at the extreme corners of the
//   index box (the worst case of the bit budget), for B = 62, 55, 30, 24;
// - the grid: covers the input, snapped values are the nearest grid points and
//   exact doubles, snapping is idempotent; statistics recounted by brute force;
// - the kernel against `mp` on the snapped points: random points over many
//   exponent ranges, exactly degenerate sets (lattices, Pythagorean
//   cocircular / cospherical sets, moved by a few ulps), the box corners, and
//   the Kettner et al. 2008 orientation experiment.
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <boost/multiprecision/gmp.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "predicates/determinants.hpp"
#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"

using namespace dlab;
using Mpz = boost::multiprecision::mpz_int;

static_assert(Kernel2<IntegerKernel> && Kernel3<IntegerKernel>);
static_assert(SnappingKernel<IntegerKernel, 2> && SnappingKernel<IntegerKernel, 3>);
static_assert(Kernel2<IntegerKernel128> && Kernel3<IntegerKernel128>);
static_assert(IntegerKernel::exact && IntegerKernel::name == "integer");
// The type choices documented in integer_kernel.hpp.
static_assert(IntegerKernel::bits2 == 62 && IntegerKernel::bits3 == 62);
static_assert(std::is_same_v<intdet::Budget<62>::Minor2, int128>);
static_assert(std::is_same_v<intdet::Budget<62>::Lift3, int128>);
static_assert(std::is_same_v<intdet::Budget<62>::InCircle, WideInt<4>>);
static_assert(std::is_same_v<intdet::Budget<62>::Minor3, WideInt<3>>);
static_assert(std::is_same_v<intdet::Budget<62>::InSphere, WideInt<5>>);
static_assert(std::is_same_v<intdet::Budget<30>::InCircle, int128>);
static_assert(std::is_same_v<intdet::Budget<24>::InSphere, int128>);

namespace {

struct Rng {  // splitmix64: same stream on every machine
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }  // [0,1)
  std::int64_t below(std::int64_t n) { return static_cast<std::int64_t>(next() % static_cast<std::uint64_t>(n)); }
};

template <int N>
Mpz to_mpz(const WideInt<N>& w) {
  Mpz r = 0;
  for (int i = N - 1; i >= 0; --i) {
    r <<= 64;
    r += w.limb[i];
  }
  if (w.negative()) r -= Mpz(1) << (64 * N);
  return r;
}
Mpz to_mpz(std::int64_t v) { return Mpz(v); }
Mpz to_mpz(int128 v) { return to_mpz(WideInt<2>(v)); }

template <int N>
WideInt<N> random_wide(Rng& r, int bits) {  // |v| < 2^bits, bits <= 64N - 1
  WideInt<N> w;
  for (int i = 0; i < N; ++i) w.limb[i] = r.next();
  for (int i = 0; i < N; ++i) {  // keep the low `bits` bits
    const int lo = 64 * i;
    if (bits <= lo) w.limb[i] = 0;
    else if (bits < lo + 64) w.limb[i] &= (std::uint64_t{1} << (bits - lo)) - 1;
  }
  return (r.next() & 1) ? -w : w;
}

}  // namespace

TEST_CASE("WideInt add, subtract, multiply agree with GMP", "[integer][wide]") {
  Rng r{1};
  for (int it = 0; it < 3000; ++it) {
    const int bits = 1 + static_cast<int>(r.below(190));
    const auto a = random_wide<3>(r, bits), b = random_wide<3>(r, bits);
    CHECK(to_mpz(a + b) == to_mpz(a) + to_mpz(b));
    CHECK(to_mpz(a - b) == to_mpz(a) - to_mpz(b));
    CHECK(to_mpz(-a) == -to_mpz(a));
    CHECK((a - a).sign() == 0);
    CHECK(a.sign() == to_mpz(a).sign());
    const auto c = random_wide<2>(r, 1 + static_cast<int>(r.below(127)));
    const auto d = random_wide<3>(r, 1 + static_cast<int>(r.below(191)));
    CHECK(to_mpz(mul<5>(c, d)) == to_mpz(c) * to_mpz(d));
    CHECK(to_mpz(mul<5>(d, c)) == to_mpz(c) * to_mpz(d));
    CHECK(to_mpz(WideInt<5>(d)) == to_mpz(d));  // sign extension
  }
  // Carries across every limb: (2^128 - 1) + 1, and -1 * -1.
  WideInt<3> m;
  m.limb[0] = m.limb[1] = ~std::uint64_t{0};
  CHECK(to_mpz(m + WideInt<3>(std::int64_t{1})) == Mpz(1) << 128);
  CHECK(to_mpz(mul<2>(WideInt<1>(std::int64_t{-1}), WideInt<1>(std::int64_t{-1}))) == 1);
  const WideInt<1> big(std::numeric_limits<std::int64_t>::max());
  CHECK(to_mpz(mul<3>(big, mul<2>(big, big))) == to_mpz(big) * to_mpz(big) * to_mpz(big));
}

namespace {

// Integer determinants at the extreme corners of [lo, lo + M]^D, M = 2^B - 1,
// compared exactly (value, not only sign) with GMP. Returns log2 of the
// largest |value| met, to show the test reaches the top of the budget.
template <int B>
void corner_test_2d(double& max_bits_o, double& max_bits_i) {
  const std::int64_t M = (std::int64_t{1} << B) - 1, lo = -(std::int64_t{1} << 53);
  const std::int64_t vals[] = {lo, lo + 1, lo + M / 2, lo + M};
  std::vector<intdet::I2> pts;
  for (auto x : vals)
    for (auto y : vals) pts.push_back({x, y});
  std::vector<std::array<Mpz, 2>> mp;
  for (const auto& p : pts) mp.push_back({Mpz(p[0]), Mpz(p[1])});
  Mpz max_o = 0, max_i = 0;
  const std::size_t n = pts.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t c = 0; c < n; ++c) {
        const Mpz o = det::orient2d<Mpz>(mp[a], mp[b], mp[c]);
        REQUIRE(to_mpz(intdet::orient2d<B>(pts[a], pts[b], pts[c])) == o);
        if (abs(o) > max_o) max_o = abs(o);
        for (std::size_t d = 0; d < n; d += 3) {
          const Mpz v = det::incircle<Mpz>(mp[a], mp[b], mp[c], mp[d]);
          REQUIRE(to_mpz(intdet::incircle<B>(pts[a], pts[b], pts[c], pts[d])) == v);
          if (abs(v) > max_i) max_i = abs(v);
        }
      }
  max_bits_o = static_cast<double>(msb(max_o));
  max_bits_i = static_cast<double>(msb(max_i));
}

template <int B>
void corner_test_3d(double& max_bits_o, double& max_bits_i) {
  const std::int64_t M = (std::int64_t{1} << B) - 1, lo = -(std::int64_t{1} << 53);
  std::vector<intdet::I3> pts;  // the 8 corners, then the centre
  for (int k = 0; k < 8; ++k)
    pts.push_back({lo + ((k & 1) ? M : 0), lo + ((k & 2) ? M : 0), lo + ((k & 4) ? M : 0)});
  pts.push_back({lo + M / 2, lo + M / 2, lo + M / 2});
  std::vector<std::array<Mpz, 3>> mp;
  for (const auto& p : pts) mp.push_back({Mpz(p[0]), Mpz(p[1]), Mpz(p[2])});
  Mpz max_o = 0, max_i = 0;
  const std::size_t n = pts.size();
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t c = 0; c < n; ++c)
        for (std::size_t d = 0; d < n; ++d) {
          const Mpz o = det::orient3d<Mpz>(mp[a], mp[b], mp[c], mp[d]);
          REQUIRE(to_mpz(intdet::orient3d<B>(pts[a], pts[b], pts[c], pts[d])) == o);
          if (abs(o) > max_o) max_o = abs(o);
          for (std::size_t e = 0; e < n; e += 2) {
            const Mpz v = det::insphere<Mpz>(mp[a], mp[b], mp[c], mp[d], mp[e]);
            REQUIRE(to_mpz(intdet::insphere<B>(pts[a], pts[b], pts[c], pts[d], pts[e])) == v);
            if (abs(v) > max_i) max_i = abs(v);
          }
        }
  max_bits_o = static_cast<double>(msb(max_o));
  max_bits_i = static_cast<double>(msb(max_i));
}

// Random index points in the box, exact values against GMP.
template <int B>
void random_box_test(std::uint64_t seed) {
  Rng r{seed};
  const std::int64_t M = (std::int64_t{1} << B) - 1;
  auto coord = [&] {  // corners, near-corners and uniform values
    switch (r.below(4)) {
      case 0: return std::int64_t{0} + r.below(3);
      case 1: return M - r.below(3);
      default: return r.below(M) + 1;
    }
  };
  for (int it = 0; it < 2000; ++it) {
    std::array<intdet::I3, 5> p;
    std::array<std::array<Mpz, 3>, 5> m;
    for (int i = 0; i < 5; ++i)
      for (int j = 0; j < 3; ++j) {
        p[i][j] = coord();
        m[i][j] = p[i][j];
      }
    const intdet::I2 a{p[0][0], p[0][1]}, b{p[1][0], p[1][1]}, c{p[2][0], p[2][1]}, d{p[3][0], p[3][1]};
    const std::array<Mpz, 2> ma{m[0][0], m[0][1]}, mb{m[1][0], m[1][1]}, mc{m[2][0], m[2][1]},
        md{m[3][0], m[3][1]};
    REQUIRE(to_mpz(intdet::orient2d<B>(a, b, c)) == det::orient2d<Mpz>(ma, mb, mc));
    REQUIRE(to_mpz(intdet::incircle<B>(a, b, c, d)) == det::incircle<Mpz>(ma, mb, mc, md));
    REQUIRE(to_mpz(intdet::orient3d<B>(p[0], p[1], p[2], p[3])) ==
            det::orient3d<Mpz>(m[0], m[1], m[2], m[3]));
    REQUIRE(to_mpz(intdet::insphere<B>(p[0], p[1], p[2], p[3], p[4])) ==
            det::insphere<Mpz>(m[0], m[1], m[2], m[3], m[4]));
  }
}

}  // namespace

TEST_CASE("integer determinants are exact at the corners of the index box", "[integer][budget]") {
  double o2, i2, o3, i3;
  corner_test_2d<55>(o2, i2);
  corner_test_3d<55>(o3, i3);
  // The corners reach within a few bits of the budgets 2B+1, 4B+4, 3B+3, 5B+7
  // (log2 of the largest |value|: 109, 218, 165, 276 at B = 55; 186 and 310
  // for orient3d and insphere at B = 62).
  CHECK(o2 >= 2 * 55 - 1);
  CHECK(i2 >= 4 * 55 - 2);
  CHECK(o3 >= 3 * 55 - 1);
  CHECK(i3 >= 5 * 55 - 1);
  corner_test_2d<30>(o2, i2);
  CHECK(i2 >= 4 * 30 - 2);
  corner_test_3d<24>(o3, i3);
  CHECK(i3 >= 5 * 24 - 1);
  corner_test_2d<62>(o2, i2);
  corner_test_3d<62>(o3, i3);
  CHECK(i2 >= 4 * 62 - 2);
  CHECK(i3 >= 5 * 62 - 1);
  random_box_test<55>(7);
  random_box_test<30>(8);
  random_box_test<24>(9);
  random_box_test<62>(10);
}

namespace {

// Independent check of one snapped coordinate: s = i h with i an integer and
// |x/h - i| <= 1/2 (ties away from zero), all exact: the returned double is
// the nearest grid point itself.
bool nearest_on_grid(double x, double s, int e) {
  const double i = std::ldexp(s, -e);
  if (i != std::floor(i) || std::fabs(i) > 0x1p62) return false;
  const double t = std::ldexp(x, -e);
  const double f = std::fabs(t - i);  // exact (Sterbenz, or i = 0)
  if (f > 0.5) return false;
  if (f == 0.5 && std::fabs(i) < std::fabs(t)) return false;
  return true;
}

template <class K, int D>
void check_grid_and_snap(const std::vector<Point<D>>& pts) {
  const K k = K::template fit<D>(pts);
  const IntegerGrid<D>& g = [&]() -> const IntegerGrid<D>& {
    if constexpr (D == 2) return k.grid2(); else return k.grid3();
  }();
  for (const auto& p : pts) {
    REQUIRE(g.covers(p));
    const Point<D> s = k.snap(p);
    REQUIRE(k.snap(s) == s);
    for (int j = 0; j < D; ++j) {
      REQUIRE(nearest_on_grid(p[j], s[j], g.exponent()));
      REQUIRE(std::isfinite(s[j]));
    }
  }
  for (int j = 0; j < D; ++j) REQUIRE(g.hi(j) - g.lo(j) <= (std::int64_t{1} << g.bits()) - 1);
}

template <int D>
Point<D> random_point(Rng& r, double scale, double shift) {
  Point<D> p;
  for (int j = 0; j < D; ++j) p[j] = shift + scale * (2 * r.unit() - 1);
  return p;
}

}  // namespace

TEST_CASE("grid covers the input; snapped values are the nearest grid points, exact doubles",
          "[integer][grid]") {
  Rng r{11};
  for (int ex : {-1070, -1040, -600, -60, -1, 0, 1, 30, 52, 60, 600, 1000, 1023}) {
    for (double shift_factor : {0.0, 0.25, 3.0, 1e6}) {
      const double scale = std::ldexp(1.0, ex);
      const double shift = shift_factor * scale;
      if (!std::isfinite(shift + scale)) continue;
      std::vector<Point2> p2;
      std::vector<Point3> p3;
      for (int i = 0; i < 50; ++i) {
        p2.push_back(random_point<2>(r, scale, shift));
        p3.push_back(random_point<3>(r, scale, shift));
      }
      check_grid_and_snap<IntegerKernel, 2>(p2);
      check_grid_and_snap<IntegerKernel, 3>(p3);
      check_grid_and_snap<IntegerKernel128, 2>(p2);
      check_grid_and_snap<IntegerKernel128, 3>(p3);
    }
  }
  // Subnormals, signed zeros and the ends of the double range.
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double big = std::numeric_limits<double>::max();
  std::vector<Point2> edge = {{tiny, -tiny}, {0.0, -0.0}, {3 * tiny, 5 * tiny}};
  check_grid_and_snap<IntegerKernel, 2>(edge);
  {
    const IntegerKernel k = IntegerKernel::fit<2>(edge);
    for (const auto& p : edge) CHECK(k.snap(p) == p);  // subnormals are on the finest grid
  }
  std::vector<Point3> ends = {{big, -big, 0}, {-big, big, 1}, {big / 3, tiny, -1e300}};
  check_grid_and_snap<IntegerKernel, 3>(ends);
}

TEST_CASE("points whose bits fit the grid do not move (B = 62)", "[integer][grid]") {
  // All coordinates multiples of ulp(max |coordinate|): integers, dyadic lattices.
  std::vector<Point3> pts;
  for (int i = -3; i <= 3; ++i)
    for (int j = -3; j <= 3; ++j) pts.push_back({i * 0x1p-40, j * 0x1p-40 + 0.5, 0.75});
  IntegerKernel k;
  const auto before = pts;
  const SnapStats st = k.snap_all(pts);
  CHECK(pts == before);
  CHECK(st.moved == 0);
  CHECK(st.merged == 0);
  CHECK(st.max_displacement == 0);
  CHECK(k.last_snap().points == pts.size());
}

namespace {

template <int D>
std::size_t brute_distinct(const std::vector<Point<D>>& v) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    bool seen = false;
    for (std::size_t j = 0; j < i && !seen; ++j) seen = v[j] == v[i];
    n += !seen;
  }
  return n;
}

using Mpq = boost::multiprecision::mpq_rational;

// The exact squared distance |a - b|^2 (doubles convert to rationals exactly).
template <int D>
Mpq exact_distance2(const Point<D>& a, const Point<D>& b) {
  Mpq s = 0;
  for (int j = 0; j < D; ++j) {
    const Mpq d = Mpq(a[j]) - Mpq(b[j]);
    s += d * d;
  }
  return s;
}

// d is within `ulps` ulps of sqrt(s): doubles that many steps away on either
// side have squares that bracket s exactly.
bool within_ulps_of_sqrt(double d, const Mpq& s, int ulps) {
  double lo = d, hi = d;
  for (int i = 0; i < ulps; ++i) {
    lo = std::nextafter(lo, 0.0);
    hi = std::nextafter(hi, INFINITY);
  }
  return Mpq(lo) * Mpq(lo) <= s && s <= Mpq(hi) * Mpq(hi);
}

template <class K, int D>
void check_stats(std::vector<Point<D>> pts) {
  K k = K::template fit<D>(pts);
  const auto before = pts;
  const SnapStats st = k.snap_all(pts);
  std::size_t moved = 0;
  Mpq max2 = 0;  // exact squared largest displacement
  for (std::size_t i = 0; i < pts.size(); ++i) {
    REQUIRE(pts[i] == k.snap(before[i]));
    if (pts[i] != before[i]) {
      ++moved;
      max2 = std::max(max2, exact_distance2<D>(pts[i], before[i]));
      // integer_grid.hpp: each coordinate difference is exact in doubles.
      for (int j = 0; j < D; ++j) CHECK(Mpq(pts[i][j] - before[i][j]) == Mpq(pts[i][j]) - Mpq(before[i][j]));
    }
  }
  CHECK(st.points == pts.size());
  CHECK(st.moved == moved);
  CHECK(st.merged == brute_distinct<D>(before) - brute_distinct<D>(pts));
  // integer_grid.hpp: 2D within 1 ulp, 3D within 3 ulps.
  INFO("max_displacement " << std::hexfloat << st.max_displacement);
  CHECK(within_ulps_of_sqrt(st.max_displacement, max2, D == 2 ? 1 : 3));
  CHECK((st.max_displacement > 0) == (moved > 0));
}

}  // namespace

TEST_CASE("snapping statistics match a brute-force recount", "[integer][grid]") {
  Rng r{12};
  for (int round = 0; round < 20; ++round) {
    // Near-duplicates a few grid steps apart (the coarse 2^24 grid merges them),
    // exact duplicates, and points already on the grid.
    std::vector<Point3> p3;
    std::vector<Point2> p2;
    for (int i = 0; i < 60; ++i) {
      const double x = r.unit(), y = r.unit(), z = r.unit();
      p3.push_back({x, y, z});
      p3.push_back({x + 0x1p-27 * r.unit(), y, z});  // below the 2^24-grid step
      p3.push_back({x, y, z});
      p3.push_back({std::round(x * 64) / 64, 0.5, 0.25});
      p2.push_back({x, y});
      p2.push_back({x, y + 0x1p-33 * r.unit()});
      p2.push_back({std::round(x * 64) / 64, 1.0});
    }
    p3.push_back({0, 0, 0});
    p3.push_back({1, 1, 1});
    check_stats<IntegerKernel128, 3>(p3);
    check_stats<IntegerKernel, 3>(p3);
    check_stats<IntegerKernel128, 2>(p2);
    check_stats<IntegerKernel, 2>(p2);
  }
  // A hand-counted case: grid step 1 (points span [0, 2^24 - 1] on the 24-bit grid).
  std::vector<Point3> h = {{0, 0, 0}, {0x1p24 - 1, 0, 0}, {0.4, 0, 0}, {0.6, 0, 0}, {1, 0, 0}, {0.5, 0, 0}};
  IntegerKernel128 k;
  const SnapStats st = k.snap_all(h);
  CHECK(k.grid3().step() == 1);
  CHECK(st.moved == 3);        // 0.4 -> 0, 0.6 -> 1, 0.5 -> 1 (ties away from zero)
  CHECK(st.merged == 3);       // {0, 0.4} -> 0 and {0.6, 1, 0.5} -> 1
  CHECK(st.max_displacement == 0.5);
  CHECK(h[2] == Point3{0, 0, 0});
  CHECK(h[5] == Point3{1, 0, 0});
}

TEST_CASE("snapping a subnormal to zero reports its displacement", "[integer][grid]") {
  // With 1 in the set the grid step is 2^-61: every subnormal snaps to 0 and
  // moves by exactly its own magnitude (squaring it in doubles underflows to 0).
  for (const double tiny : {0x1p-1074, 0x1.8p-1070, -0x1p-1040, 0x1p-1022}) {
    std::vector<Point2> p = {{0, 0}, {1, 1}, {tiny, 0}};
    IntegerKernel k;
    const SnapStats st = k.snap_all(p);
    CHECK(p[2] == Point2{0, 0});
    CHECK(st.moved == 1);
    CHECK(st.merged == 1);  // onto the origin
    CHECK(st.max_displacement == std::fabs(tiny));
  }
  // A 3-4-5 triangle of subnormals: exactly 5 * 2^-1074, in 2D and in 3D.
  std::vector<Point2> p2 = {{1, 1}, {3 * 0x1p-1074, 4 * 0x1p-1074}};
  std::vector<Point3> p3 = {{1, 1, 1}, {0, 3 * 0x1p-1074, 4 * 0x1p-1074}};
  IntegerKernel k2, k3;
  CHECK(k2.snap_all(p2).max_displacement == 5 * 0x1p-1074);
  CHECK(k3.snap_all(p3).max_displacement == 5 * 0x1p-1074);
  // Mixed magnitudes at random scales against the exact rational distance.
  Rng r{29};
  for (int round = 0; round < 50; ++round) {
    std::vector<Point3> p = {{1, -1, 0.5}};
    for (int i = 0; i < 20; ++i) {
      const int e = -1074 + static_cast<int>(r.unit() * 1080);  // from subnormal to 2^6
      p.push_back({std::ldexp(r.unit(), e), std::ldexp(r.unit() - 0.5, e), std::ldexp(r.unit(), e / 2)});
    }
    check_stats<IntegerKernel, 3>(p);
    check_stats<IntegerKernel128, 3>(p);
  }
}

TEST_CASE("snap_all fits an unfitted kernel, and keeps a fitted grid", "[integer][grid]") {
  std::vector<Point2> big = {{0, 0}, {1000, 1000}};
  std::vector<Point2> small = {{0.1, 0.2}, {0.3, 0.4}};
  IntegerKernel128 fitted = IntegerKernel128::fit<2>(big);
  auto s1 = small;
  fitted.snap_all(s1);
  CHECK(fitted.grid2().step() == 0x1p-20);  // 1000 / h <= 2^30 - 1 first holds at h = 2^-20
  IntegerKernel128 fresh;
  auto s2 = small;
  fresh.snap_all(s2);
  CHECK(fresh.grid2().step() < fitted.grid2().step());
  for (const auto& p : small) CHECK(fresh.grid2().covers(p));
}

TEST_CASE("a default-constructed integer kernel works on integer points", "[integer]") {
  const IntegerKernel k;
  const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
  CHECK(k.orient2d({0, 0}, {1, 0}, {0, 1}) == Sign::positive);
  CHECK(k.incircle({0, 0}, {1, 0}, {0, 1}, {1, 1}) == Sign::zero);
  CHECK(k.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}) == Sign::positive);
  CHECK(k.insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0.2, 0.2, -0.2}) ==
        mp.insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 0}));  // snapped to 0
  CHECK(k.snap(Point2{0.4, -2.5}) == Point2{0, -3});
}

namespace {

// Every predicate on random tuples of pts: the kernel on the snapped points
// equals mp on the snapped points, and the kernel on the raw points (snapping
// on the fly) gives the same answer.
template <class K>
void agree_with_mp_2d(const std::vector<Point2>& raw, Rng& r, int tuples) {
  const K k = K::template fit<2>(raw);
  std::vector<Point2> s = raw;
  K k2 = k;
  k2.snap_all(s);
  const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
  const auto n = static_cast<std::int64_t>(raw.size());
  for (int t = 0; t < tuples; ++t) {
    const auto a = r.below(n), b = r.below(n), c = r.below(n), d = r.below(n);
    REQUIRE(k.orient2d(s[a], s[b], s[c]) == mp.orient2d(s[a], s[b], s[c]));
    REQUIRE(k.incircle(s[a], s[b], s[c], s[d]) == mp.incircle(s[a], s[b], s[c], s[d]));
    REQUIRE(k.orient2d(raw[a], raw[b], raw[c]) == k.orient2d(s[a], s[b], s[c]));
    REQUIRE(k.incircle(raw[a], raw[b], raw[c], raw[d]) == k.incircle(s[a], s[b], s[c], s[d]));
  }
}

template <class K>
void agree_with_mp_3d(const std::vector<Point3>& raw, Rng& r, int tuples) {
  const K k = K::template fit<3>(raw);
  std::vector<Point3> s = raw;
  K k2 = k;
  k2.snap_all(s);
  const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
  const auto n = static_cast<std::int64_t>(raw.size());
  for (int t = 0; t < tuples; ++t) {
    const auto a = r.below(n), b = r.below(n), c = r.below(n), d = r.below(n), e = r.below(n);
    REQUIRE(k.orient3d(s[a], s[b], s[c], s[d]) == mp.orient3d(s[a], s[b], s[c], s[d]));
    REQUIRE(k.insphere(s[a], s[b], s[c], s[d], s[e]) == mp.insphere(s[a], s[b], s[c], s[d], s[e]));
    REQUIRE(k.orient3d(raw[a], raw[b], raw[c], raw[d]) == k.orient3d(s[a], s[b], s[c], s[d]));
    REQUIRE(k.insphere(raw[a], raw[b], raw[c], raw[d], raw[e]) ==
            k.insphere(s[a], s[b], s[c], s[d], s[e]));
  }
}

// Moves a coordinate by k ulps (k may be negative).
double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, std::numeric_limits<double>::infinity());
  for (; k < 0; ++k) x = std::nextafter(x, -std::numeric_limits<double>::infinity());
  return x;
}

}  // namespace

TEST_CASE("integer kernel agrees with mp on snapped random points across exponent ranges",
          "[integer][mp]") {
  Rng r{13};
  for (int ex : {-1060, -700, -100, -30, 0, 20, 100, 700, 1015}) {
    for (double shift_factor : {0.0, 1.0, 1e5}) {
      const double scale = std::ldexp(1.0, ex), shift = shift_factor * scale;
      std::vector<Point2> p2;
      std::vector<Point3> p3;
      for (int i = 0; i < 40; ++i) {
        p2.push_back(random_point<2>(r, scale, shift));
        p3.push_back(random_point<3>(r, scale, shift));
      }
      agree_with_mp_2d<IntegerKernel>(p2, r, 150);
      agree_with_mp_3d<IntegerKernel>(p3, r, 150);
      agree_with_mp_2d<IntegerKernel128>(p2, r, 150);
      agree_with_mp_3d<IntegerKernel128>(p3, r, 150);
    }
  }
}

TEST_CASE("integer kernel on exactly degenerate sets, scaled, translated, moved by ulps",
          "[integer][mp][degenerate]") {
  Rng r{14};
  // Pythagorean cocircular set: the 12 integer points of the circle of radius 5.
  std::vector<Point2> circle;
  for (int sx : {-1, 1})
    for (int sy : {-1, 1}) {
      circle.push_back({3.0 * sx, 4.0 * sy});
      circle.push_back({4.0 * sx, 3.0 * sy});
    }
  for (double v : {-5.0, 5.0}) {
    circle.push_back({v, 0});
    circle.push_back({0, v});
  }
  // Pythagorean quadruples 1^2 + 2^2 + 2^2 = 3^2: 30 integer points of the sphere of radius 3.
  std::vector<Point3> sphere;
  for (int perm = 0; perm < 3; ++perm)
    for (int s = 0; s < 8; ++s) {
      Point3 p{1, 2, 2};
      std::swap(p[0], p[perm]);
      for (int j = 0; j < 3; ++j)
        if (s & (1 << j)) p[j] = -p[j];
      sphere.push_back(p);
    }
  for (int j = 0; j < 3; ++j)
    for (double v : {-3.0, 3.0}) {
      Point3 p{0, 0, 0};
      p[j] = v;
      sphere.push_back(p);
    }
  // A 2D and a 3D lattice: collinear triples, cocircular squares, coplanar quadruples.
  std::vector<Point2> lattice2;
  std::vector<Point3> lattice3;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      lattice2.push_back({double(i), double(j)});
      for (int k = 0; k < 3; ++k) lattice3.push_back({double(i), double(j), double(k)});
    }

  for (int s : {-1000, -60, 0, 7, 60, 990}) {
    for (double t : {0.0, 3.0, 1e9}) {  // translation, in units of the scale
      auto place2 = [&](std::vector<Point2> v) {
        for (auto& p : v)
          for (auto& x : p) x = std::ldexp(x + t, s);
        return v;
      };
      auto place3 = [&](std::vector<Point3> v) {
        for (auto& p : v)
          for (auto& x : p) x = std::ldexp(x + t, s);
        return v;
      };
      const auto c = place2(circle), l2 = place2(lattice2);
      const auto sp = place3(sphere), l3 = place3(lattice3);
      // With B = 62 these exact sets stay put, so the degeneracies survive snapping.
      {
        auto cc = c;
        IntegerKernel k;
        CHECK(k.snap_all(cc).moved == 0);
        for (int i = 0; i < 50; ++i) {
          const auto a = r.below(12), b = r.below(12), cidx = r.below(12), d = r.below(12);
          REQUIRE(k.incircle(c[a], c[b], c[cidx], c[d]) == Sign::zero);
        }
        auto ss = sp;
        IntegerKernel k3;
        CHECK(k3.snap_all(ss).moved == 0);
        for (int i = 0; i < 50; ++i) {
          const auto a = r.below(30), b = r.below(30), cc3 = r.below(30), d = r.below(30),
                     e = r.below(30);
          REQUIRE(k3.insphere(sp[a], sp[b], sp[cc3], sp[d], sp[e]) == Sign::zero);
        }
        IntegerKernel k2 = IntegerKernel::fit<2>(l2);
        REQUIRE(k2.orient2d(l2[0], l2[6], l2[12]) == Sign::zero);   // diagonal
        REQUIRE(k2.incircle(l2[0], l2[1], l2[6], l2[5]) == Sign::zero);  // unit square
        IntegerKernel k33 = IntegerKernel::fit<3>(l3);
        REQUIRE(k33.orient3d(l3[0], l3[3], l3[15], l3[18]) == Sign::zero);  // plane z = 0
      }
      agree_with_mp_2d<IntegerKernel>(c, r, 100);
      agree_with_mp_2d<IntegerKernel>(l2, r, 100);
      agree_with_mp_3d<IntegerKernel>(sp, r, 100);
      agree_with_mp_3d<IntegerKernel>(l3, r, 100);
      agree_with_mp_2d<IntegerKernel128>(c, r, 100);
      agree_with_mp_3d<IntegerKernel128>(sp, r, 100);
      // The same moved by 1..3 ulps: snapping may or may not undo the move;
      // on the snapped points the kernel must still be exact.
      auto c2 = c;
      auto sp2 = sp;
      for (auto& p : c2)
        for (auto& x : p) x = ulps(x, static_cast<int>(r.below(7)) - 3);
      for (auto& p : sp2)
        for (auto& x : p) x = ulps(x, static_cast<int>(r.below(7)) - 3);
      agree_with_mp_2d<IntegerKernel>(c2, r, 100);
      agree_with_mp_3d<IntegerKernel>(sp2, r, 100);
      agree_with_mp_2d<IntegerKernel128>(c2, r, 100);
      agree_with_mp_3d<IntegerKernel128>(sp2, r, 100);
    }
  }
}

namespace {

// All predicates over all tuples of the box corners (and the centre), as
// doubles through a fitted kernel, against mp.
template <class K, int D>
void corners_vs_mp(double lo, double hi) {
  std::vector<Point<D>> pts;
  for (int k = 0; k < (1 << D); ++k) {
    Point<D> p;
    for (int j = 0; j < D; ++j) p[j] = (k >> j) & 1 ? hi : lo;
    pts.push_back(p);
  }
  Point<D> mid;
  mid.fill(std::round((lo + hi) / 2));
  pts.push_back(mid);
  const K k = K::template fit<D>(pts);
  const auto& g = [&]() -> const auto& {
    if constexpr (D == 2) return k.grid2(); else return k.grid3();
  }();
  // The corners are the extreme grid points: index span exactly hi - lo.
  for (int j = 0; j < D; ++j) REQUIRE(g.value(g.hi(j)) - g.value(g.lo(j)) == hi - lo);
  for (const auto& p : pts) REQUIRE(k.snap(p) == p);
  const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
  const std::size_t n = pts.size();
  std::size_t nonzero = 0;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      for (std::size_t c = 0; c < n; ++c)
        for (std::size_t d = 0; d < n; ++d) {
          if constexpr (D == 2) {
            const Sign s = mp.incircle(pts[a], pts[b], pts[c], pts[d]);
            REQUIRE(k.incircle(pts[a], pts[b], pts[c], pts[d]) == s);
            REQUIRE(k.orient2d(pts[a], pts[b], pts[d]) == mp.orient2d(pts[a], pts[b], pts[d]));
            nonzero += s != Sign::zero;
          } else {
            REQUIRE(k.orient3d(pts[a], pts[b], pts[c], pts[d]) ==
                    mp.orient3d(pts[a], pts[b], pts[c], pts[d]));
            for (std::size_t e = 0; e < n; ++e) {
              const Sign s = mp.insphere(pts[a], pts[b], pts[c], pts[d], pts[e]);
              REQUIRE(k.insphere(pts[a], pts[b], pts[c], pts[d], pts[e]) == s);
              nonzero += s != Sign::zero;
            }
          }
        }
  CHECK(nonzero > 0);
}

}  // namespace

TEST_CASE("points at the grid's extreme corners: the largest differences doubles allow",
          "[integer][budget][mp]") {
  // B = 30 / 24: the corners 0 and 2^B - 1 on a unit grid are the full budget.
  corners_vs_mp<IntegerKernel128, 2>(0, 0x1p30 - 1);
  corners_vs_mp<IntegerKernel128, 3>(0, 0x1p24 - 1);
  corners_vs_mp<IntegerKernel128, 2>(-0x1p29, 0x1p29 - 1);
  // B = 62: a unit grid over [-2^61, 2^61 - 256] spans 2^62 - 256 steps, the
  // widest box of doubles under 2^62 - 1.
  corners_vs_mp<IntegerKernel, 2>(-0x1p61, 0x1p61 - 256);
  corners_vs_mp<IntegerKernel, 3>(-0x1p61, 0x1p61 - 256);
  corners_vs_mp<IntegerKernel, 3>(-std::numeric_limits<double>::max(),
                                   std::numeric_limits<double>::max());
}

TEST_CASE("Kettner et al. 2008 orientation experiment on the snapped points", "[integer][kettner]") {
  // p = (0.5 + x 2^-53, 0.5 + y 2^-53), x, y in 0..255; q = (12,12), r = (24,24).
  std::vector<Point2> pts;
  for (int x = 0; x < 256; ++x)
    for (int y = 0; y < 256; ++y) pts.push_back({0.5 + x * 0x1p-53, 0.5 + y * 0x1p-53});
  const Point2 q{12, 12}, r{24, 24};
  pts.push_back(q);
  pts.push_back(r);
  const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
  // Returns how many snapped p are collinear with q, r; checks every sign
  // against mp on the same snapped points and against `expected(x, y)`.
  auto run = [&](auto k, auto expected) {
    auto snapped = pts;
    const SnapStats st = k.snap_all(snapped);  // the grid fitted on all points together
    const Point2 sq = snapped[65536], sr = snapped[65537];
    REQUIRE(sq == q);
    REQUIRE(sr == r);
    std::size_t agree = 0, zero = 0, as_expected = 0;
    for (int x = 0; x < 256; ++x)
      for (int y = 0; y < 256; ++y) {
        const std::size_t i = static_cast<std::size_t>(x * 256 + y);
        const Sign s = k.orient2d(snapped[i], sq, sr);
        agree += s == mp.orient2d(snapped[i], sq, sr);
        as_expected += s == expected(x, y);
        zero += s == Sign::zero;
        REQUIRE(k.orient2d(pts[i], q, r) == s);  // on-the-fly snapping agrees
      }
    CHECK(agree == 65536);
    CHECK(as_expected == 65536);
    return std::pair{st, zero};
  };
  // B = 62: h = 2^-57 (23.5 / h < 2^62 - 1), a divisor of 2^-53: nothing moves,
  // and every sign is the exact one for the original points, sign(y - x).
  const auto [st62, zero62] = run(IntegerKernel{}, [](int x, int y) {
    return sign_of(static_cast<double>(y - x));
  });
  CHECK(st62.moved == 0);
  CHECK(st62.merged == 0);
  CHECK(zero62 == 256);
  // B = 55 (a grid 2^7 coarser): h = 2^-50, p's offsets x 2^-53 become
  // 8 round(x / 8) 2^-53 (ties up): exact sign = sign(y' - x').
  auto r8 = [](int v) { return (v + 4) / 8; };
  const auto [st55, zero55] = run(BasicIntegerKernel<55, 55>{}, [&](int x, int y) {
    return sign_of(static_cast<double>(r8(y) - r8(x)));
  });
  CHECK(st55.moved == 65536 - 32 * 32);   // unmoved: x, y multiples of 8
  CHECK(st55.merged == 65536 - 33 * 33);  // 33 x 33 snapped p remain, q and r distinct
  CHECK(zero55 == 4 * 4 + 31 * 8 * 8 + 4 * 4);  // pairs with r8(x) == r8(y)
  // B = 30: 23.5 / h <= 2^30 - 1 needs h = 2^-25: every p lands on (0.5, 0.5).
  const auto [st128, zero128] = run(IntegerKernel128{}, [](int, int) { return Sign::zero; });
  CHECK(st128.moved == 65535);
  CHECK(st128.merged == 65535);
  CHECK(zero128 == 65536);
}

TEST_CASE("snapping is idempotent and covers the input (property)", "[integer][grid][rc]") {
  rc::prop("snap(snap(p)) == snap(p), grid covers p", [](double a, double b, double c) {
    RC_PRE(std::isfinite(a) && std::isfinite(b) && std::isfinite(c));
    const std::vector<Point3> pts = {{a, b, c}, {b, c, a}, {c, a, b}};
    const IntegerKernel k = IntegerKernel::fit<3>(pts);
    for (const auto& p : pts) {
      RC_ASSERT(k.grid3().covers(p));
      const Point3 s = k.snap(p);
      RC_ASSERT(k.snap(s) == s);
      for (int j = 0; j < 3; ++j) RC_ASSERT(nearest_on_grid(p[j], s[j], k.grid3().exponent()));
    }
  });
}
