// The epsilon kernel (Baker's tolerance mu, relative): invariant under scaling
// by powers of two and under translation, answers zero on near-degenerate
// configurations that mp calls non-zero, and agrees with mp on
// well-separated random configurations. Its non-zero answers are never wrong
// (checked against mp on near-degenerate inputs too).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "predicates/epsilon_kernel.hpp"
#include "predicates/float_kernel.hpp"
#include "predicates/mp_kernel.hpp"

using namespace dlab;

static_assert(Kernel2<EpsilonKernel> && Kernel3<EpsilonKernel>);
static_assert(!EpsilonKernel::exact && EpsilonKernel::name == "epsilon");

namespace {

struct Rng {  // splitmix64
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53; }
};

// Random configurations: uniform ones, and near-degenerate ones (the last point
// placed on a line / circle / plane / sphere through the others in doubles,
// then moved by a few ulps), so that zero answers occur.
struct Config2 {
  Point2 a, b, c, d;
};
struct Config3 {
  Point3 a, b, c, d, e;
};

double nudge(Rng& r, double x) {
  const int k = static_cast<int>(r.next() % 5) - 2;
  for (int i = 0; i < k; ++i) x = std::nextafter(x, 1e300);
  for (int i = 0; i > k; --i) x = std::nextafter(x, -1e300);
  return x;
}

Config2 config2(Rng& r, bool degenerate) {
  Config2 c{{r.unit(), r.unit()}, {r.unit(), r.unit()}, {r.unit(), r.unit()}, {r.unit(), r.unit()}};
  if (degenerate) {
    const double t = r.unit();
    // c on segment ab (or on the circle below), d on the circle of diameter ab (Thales).
    c.c = {nudge(r, c.a[0] + t * (c.b[0] - c.a[0])), nudge(r, c.a[1] + t * (c.b[1] - c.a[1]))};
    const double mx = (c.a[0] + c.b[0]) / 2, my = (c.a[1] + c.b[1]) / 2;
    const double rad = std::hypot(c.a[0] - mx, c.a[1] - my), th = 6.283185307179586 * r.unit();
    c.d = {nudge(r, mx + rad * std::cos(th)), nudge(r, my + rad * std::sin(th))};
    const double th2 = 6.283185307179586 * r.unit();
    c.c = r.next() & 1 ? c.c : Point2{mx + rad * std::cos(th2), my + rad * std::sin(th2)};
  }
  return c;
}

Config3 config3(Rng& r, bool degenerate) {
  auto rp = [&] { return Point3{r.unit(), r.unit(), r.unit()}; };
  Config3 c{rp(), rp(), rp(), rp(), rp()};
  if (degenerate) {
    // d in the plane of a, b, c; e on the sphere of diameter ab (Thales in 3D).
    const double s = r.unit(), t = r.unit();
    for (int j = 0; j < 3; ++j)
      c.d[j] = nudge(r, c.a[j] + s * (c.b[j] - c.a[j]) + t * (c.c[j] - c.a[j]));
    const double th = 6.283185307179586 * r.unit(), ph = std::acos(2 * r.unit() - 1);
    Point3 m, u{std::sin(ph) * std::cos(th), std::sin(ph) * std::sin(th), std::cos(ph)};
    double rad2 = 0;
    for (int j = 0; j < 3; ++j) {
      m[j] = (c.a[j] + c.b[j]) / 2;
      rad2 += (c.a[j] - m[j]) * (c.a[j] - m[j]);
    }
    for (int j = 0; j < 3; ++j) c.e[j] = nudge(r, m[j] + std::sqrt(rad2) * u[j]);
  }
  return c;
}

template <class P>
P scaled(P p, int k, double shift) {
  for (auto& x : p) x = std::ldexp(x + shift, k);
  return p;
}

}  // namespace

TEST_CASE("epsilon kernel: same answers under scaling by 2^k", "[epsilon]") {
  const EpsilonKernel eps;
  Rng r{21};
  std::size_t zeros = 0;
  for (int it = 0; it < 4000; ++it) {
    const bool deg = it % 2 == 1;
    const Config2 c = config2(r, deg);
    const Config3 d = config3(r, deg);
    const Sign o2 = eps.orient2d(c.a, c.b, c.c), i2 = eps.incircle(c.a, c.b, c.c, c.d);
    const Sign o3 = eps.orient3d(d.a, d.b, d.c, d.d), i3 = eps.insphere(d.a, d.b, d.c, d.d, d.e);
    zeros += (o2 == Sign::zero) + (i2 == Sign::zero) + (o3 == Sign::zero) + (i3 == Sign::zero);
    for (int k : {-150, -40, -1, 1, 13, 40, 150}) {
      auto s2 = [&](const Point2& p) { return scaled(p, k, 0.0); };
      auto s3 = [&](const Point3& p) { return scaled(p, k, 0.0); };
      REQUIRE(eps.orient2d(s2(c.a), s2(c.b), s2(c.c)) == o2);
      REQUIRE(eps.incircle(s2(c.a), s2(c.b), s2(c.c), s2(c.d)) == i2);
      REQUIRE(eps.orient3d(s3(d.a), s3(d.b), s3(d.c), s3(d.d)) == o3);
      REQUIRE(eps.insphere(s3(d.a), s3(d.b), s3(d.c), s3(d.d), s3(d.e)) == i3);
    }
  }
  CHECK(zeros > 1000);  // the near-degenerate half does exercise the tolerance
}

TEST_CASE("epsilon kernel answers zero where mp does not (near-degenerate)", "[epsilon]") {
  const EpsilonKernel eps;
  const MpKernel mp;
  const FloatKernel fl;
  const double e = 0x1p-50;
  // c one 2^-50 off the diagonal through a and b.
  const Point2 a{0, 0}, b{1, 1}, c{0.5, 0.5 + e};
  CHECK(mp.orient2d(a, b, c) == Sign::positive);
  CHECK(fl.orient2d(a, b, c) == Sign::positive);
  CHECK(eps.orient2d(a, b, c) == Sign::zero);
  // A tighter tolerance sees it again: c is 2^-51 relative off, above 1e-16.
  CHECK(EpsilonKernel(1e-16).orient2d(a, b, c) == Sign::positive);
  // d a hair outside the unit circle through (1,0), (0,1), (-1,0).
  const Point2 p{1, 0}, q{0, 1}, s{-1, 0}, d{0, -(1 + e)};
  CHECK(mp.incircle(p, q, s, d) == Sign::negative);
  CHECK(eps.incircle(p, q, s, d) == Sign::zero);
  // Coplanar up to 2^-50, and cospherical up to 2^-50.
  const Point3 x{0, 0, 0}, y{1, 0, 0}, z{0, 1, 0}, w{0.25, 0.25, e};
  CHECK(mp.orient3d(x, y, z, w) == Sign::negative);
  CHECK(eps.orient3d(x, y, z, w) == Sign::zero);
  const Point3 u{0, 0, -1}, v{1, 1, -1};
  CHECK(mp.insphere(x, y, z, u, Point3{1, 1, -(1 + e)}) != Sign::zero);
  CHECK(eps.insphere(x, y, z, u, Point3{1, 1, -(1 + e)}) == Sign::zero);
  CHECK(eps.insphere(x, y, z, u, v) == Sign::zero);  // exactly cospherical (cube corners)
  // The same translated far away and scaled: still zero, mp still non-zero.
  auto far2 = [](Point2 t) { return Point2{t[0] * 0x1p40 + 0x1p30, t[1] * 0x1p40 - 0x1p30}; };  // exact
  CHECK(mp.orient2d(far2(a), far2(b), far2(c)) == Sign::positive);
  CHECK(eps.orient2d(far2(a), far2(b), far2(c)) == Sign::zero);
}

TEST_CASE("epsilon kernel agrees with mp on well-separated random configurations", "[epsilon]") {
  const EpsilonKernel eps;
  const MpKernel mp;
  Rng r{22};
  for (int it = 0; it < 5000; ++it) {
    // Uniform points in a box of random size and position: degenerate with probability ~0.
    const int k = static_cast<int>(r.next() % 200) - 100;
    const double shift = static_cast<double>(r.next() % 5);
    const Config2 c = config2(r, false);
    const Config3 d = config3(r, false);
    auto s2 = [&](const Point2& p) { return scaled(p, k, shift); };
    auto s3 = [&](const Point3& p) { return scaled(p, k, shift); };
    REQUIRE(eps.orient2d(s2(c.a), s2(c.b), s2(c.c)) == mp.orient2d(s2(c.a), s2(c.b), s2(c.c)));
    REQUIRE(eps.incircle(s2(c.a), s2(c.b), s2(c.c), s2(c.d)) ==
            mp.incircle(s2(c.a), s2(c.b), s2(c.c), s2(c.d)));
    REQUIRE(eps.orient3d(s3(d.a), s3(d.b), s3(d.c), s3(d.d)) ==
            mp.orient3d(s3(d.a), s3(d.b), s3(d.c), s3(d.d)));
    REQUIRE(eps.insphere(s3(d.a), s3(d.b), s3(d.c), s3(d.d), s3(d.e)) ==
            mp.insphere(s3(d.a), s3(d.b), s3(d.c), s3(d.d), s3(d.e)));
  }
}

TEST_CASE("epsilon kernel: on near-degenerate inputs a non-zero answer is the exact sign",
          "[epsilon]") {
  const EpsilonKernel eps;
  const MpKernel mp;
  Rng r{23};
  std::size_t zero = 0, total = 0;
  for (int it = 0; it < 4000; ++it) {
    const Config2 c = config2(r, true);
    const Config3 d = config3(r, true);
    const Sign s[4] = {eps.orient2d(c.a, c.b, c.c), eps.incircle(c.a, c.b, c.c, c.d),
                       eps.orient3d(d.a, d.b, d.c, d.d), eps.insphere(d.a, d.b, d.c, d.d, d.e)};
    const Sign m[4] = {mp.orient2d(c.a, c.b, c.c), mp.incircle(c.a, c.b, c.c, c.d),
                       mp.orient3d(d.a, d.b, d.c, d.d), mp.insphere(d.a, d.b, d.c, d.d, d.e)};
    for (int i = 0; i < 4; ++i) {
      ++total;
      if (s[i] == Sign::zero) ++zero;
      else REQUIRE(s[i] == m[i]);
    }
  }
  CHECK(zero > total / 10);
}

TEST_CASE("epsilon kernel with tolerance 0 is the float kernel", "[epsilon]") {
  const EpsilonKernel eps(0.0);
  const FloatKernel fl;
  Rng r{24};
  for (int it = 0; it < 2000; ++it) {
    const Config2 c = config2(r, it % 2 == 0);
    const Config3 d = config3(r, it % 2 == 0);
    REQUIRE(eps.orient2d(c.a, c.b, c.c) == fl.orient2d(c.a, c.b, c.c));
    REQUIRE(eps.incircle(c.a, c.b, c.c, c.d) == fl.incircle(c.a, c.b, c.c, c.d));
    REQUIRE(eps.orient3d(d.a, d.b, d.c, d.d) == fl.orient3d(d.a, d.b, d.c, d.d));
    REQUIRE(eps.insphere(d.a, d.b, d.c, d.d, d.e) == fl.insphere(d.a, d.b, d.c, d.d, d.e));
  }
}
