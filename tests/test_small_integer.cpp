// predicates/small_integer.hpp (error-free evaluation on small integer
// coordinates) and its use by perturbed<AdaptiveKernel>, against MpKernel:
//  - whenever the certificate holds (`known`), the sign is MpKernel's, at the
//    extreme corners of the bit budget (every difference = +-B, coordinates
//    near 2^51) as well as on random lattice points and exact cospherical sets;
//  - the certificate refuses what it must: non-integers (including the cases
//    where the rounded difference is an integer: 1e-300 - 3, (1 + 2^-52) - 513),
//    differences beyond B, infinities and NaN;
//  - perturbed<AdaptiveKernel> gives perturbed<MpKernel>'s answers on lattices,
//    and exact zeros are still counted as decided by the perturbation.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "predicates/small_integer.hpp"
#include "predicates/sos_walk.hpp"

using namespace dlab;

namespace {

const MpKernel mp;

// Coordinates base + k with k uniform in [-half, half].
struct Lattice {
  std::mt19937_64 gen;
  double base, half;
  double next() {
    const std::uint64_t span = static_cast<std::uint64_t>(2 * half) + 1;
    return base + (static_cast<double>(gen() % span) - half);
  }
  Point2 p2() { return {next(), next()}; }
  Point3 p3() { return {next(), next(), next()}; }
};

}  // namespace

TEST_CASE("small_integer: bit budgets at the corners", "[small_integer]") {
  using namespace small_integer;
  // All differences +-B with a cancelling structure, and the largest products.
  const double B3 = is_bound, Bo = o3_bound, Bc = ic_bound, B2 = o2_bound;
  for (double base : {0.0, 0x1p51, -0x1p51, 12345.0}) {
    const Point3 e{base, base, base};
    const Point3 a{base + B3, base + B3, base + B3}, b{base - B3, base + B3, base + B3},
        c{base + B3, base - B3, base + B3}, d{base + B3, base + B3, base - B3};
    const Answer r = insphere(a, b, c, d, e);
    REQUIRE(r.known);
    CHECK(r.sign == mp.insphere(a, b, c, d, e));
    // Differences 2B from the reference: refused.
    const Point3 f{base - B3, base - B3, base - B3};
    CHECK_FALSE(insphere(a, b, c, d, f).known);
    // One more unit: refused.
    const Point3 a2{base + B3 + 1, base, base};
    CHECK_FALSE(insphere(a2, b, c, d, e).known);

    const Point3 oa{base + Bo, base - Bo, base + Bo}, ob{base - Bo, base + Bo, base + Bo},
        oc{base + Bo, base + Bo, base - Bo};
    REQUIRE(orient3d(oa, ob, oc, e).known);
    CHECK(orient3d(oa, ob, oc, e).sign == mp.orient3d(oa, ob, oc, e));
    CHECK_FALSE(orient3d({base + Bo + 1, base, base}, ob, oc, e).known);

    const Point2 e2{base, base};
    const Point2 ia{base + Bc, base + Bc}, ib{base - Bc, base + Bc}, ic{base + Bc, base - Bc},
        id{base - Bc, base - Bc};
    REQUIRE(incircle(ia, ib, ic, e2).known);
    CHECK(incircle(ia, ib, ic, e2).sign == mp.incircle(ia, ib, ic, e2));
    CHECK_FALSE(incircle(ia, ib, ic, id).known);  // differences 2B from id
    const double h = Bc / 2;  // differences from jd up to 2h = B
    const Point2 ja{base + h, base}, jb{base, base + h}, jc{base - h, base}, jd{base, base - h};
    REQUIRE(incircle(ja, jb, jc, jd).known);
    CHECK(incircle(ja, jb, jc, jd).sign == Sign::zero);  // four points of one circle
    CHECK_FALSE(incircle({base + Bc + 1, base}, ib, ic, e2).known);

    const Point2 pa{base + B2, base - B2}, pb{base - B2, base + B2 - 2};  // even: see is_int
    REQUIRE(orient2d(pa, pb, e2).known);
    CHECK(orient2d(pa, pb, e2).sign == mp.orient2d(pa, pb, e2));
    CHECK_FALSE(orient2d({base + B2 + 1, base}, pb, e2).known);
  }
}

TEST_CASE("small_integer: refuses non-integers, infinities and NaN", "[small_integer]") {
  using namespace small_integer;
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Point3 e{3, 0, 0}, b{0, 1, 0}, c{0, 0, 1}, d{1, 1, 1};
  // fl(1e-300 - 3) = -3 and fl((1 + 2^-52) - 513) = -512 are integers, but inexact.
  CHECK_FALSE(insphere({1e-300, 0, 0}, b, c, d, e).known);
  CHECK_FALSE(insphere({1 + 0x1p-52, 0, 0}, b, c, d, {513, 0, 0}).known);
  CHECK_FALSE(orient3d({1e-300, 0, 0}, b, c, e).known);
  CHECK_FALSE(orient2d({1e-300, 0}, {0, 1}, {3, 0}).known);
  CHECK_FALSE(incircle({1e-300, 0}, {0, 1}, {1, 1}, {3, 0}).known);
  CHECK_FALSE(insphere({0.5, 0, 0}, b, c, d, e).known);
  for (double bad : {inf, -inf, nan}) {
    CHECK_FALSE(insphere({bad, 0, 0}, b, c, d, e).known);
    CHECK_FALSE(insphere(b, c, d, e, {bad, 0, 0}).known);
    CHECK_FALSE(insphere({bad, 0, 0}, b, c, d, {bad, 0, 0}).known);
    CHECK_FALSE(orient3d(b, c, d, {bad, 0, 0}).known);
    CHECK_FALSE(orient3d({bad, 0, 0}, c, d, {bad, 1, 0}).known);
    CHECK_FALSE(orient2d({0, 0}, {1, 0}, {bad, bad}).known);
    CHECK_FALSE(incircle({bad, 0}, {1, 0}, {0, 1}, {bad, 2}).known);
  }
  // Coordinates too large for the reference point, or differences too large.
  CHECK_FALSE(orient3d(b, c, d, {0x1p53, 0, 0}).known);
  CHECK_FALSE(orient3d({0x1p60, 0, 0}, c, d, {0x1p60 + 0x1p8, 0, 0}).known);
}

TEST_CASE("small_integer: random lattice points agree with mp", "[small_integer]") {
  Lattice lat{std::mt19937_64(7), 0, 3};
  int known = 0, zeros = 0;
  for (int t = 0; t < 4000; ++t) {
    // Alternate tight lattices (many exact zeros) and wide ones near the bounds.
    lat.half = t % 4 == 0 ? 255 : (t % 4 == 1 ? 2 : 1);
    lat.base = t % 3 == 0 ? 0x1p50 : (t % 3 == 1 ? -1000 : 0);
    const Point3 a = lat.p3(), b = lat.p3(), c = lat.p3(), d = lat.p3(), e = lat.p3();
    const auto s = small_integer::insphere(a, b, c, d, e);
    REQUIRE(s.known);  // |difference| <= 510 < 2^9
    REQUIRE(s.sign == mp.insphere(a, b, c, d, e));
    const auto o = small_integer::orient3d(a, b, c, d);
    REQUIRE(o.known);
    REQUIRE(o.sign == mp.orient3d(a, b, c, d));
    const Point2 p = lat.p2(), q = lat.p2(), r = lat.p2(), u = lat.p2();
    const auto ic = small_integer::incircle(p, q, r, u);
    REQUIRE(ic.known);
    REQUIRE(ic.sign == mp.incircle(p, q, r, u));
    const auto o2 = small_integer::orient2d(p, q, r);
    REQUIRE(o2.known);
    REQUIRE(o2.sign == mp.orient2d(p, q, r));
    known += 4;
    zeros += (s.sign == Sign::zero) + (ic.sign == Sign::zero);
  }
  CHECK(known == 16000);
  CHECK(zeros > 300);  // the tight lattices really are degenerate
}

TEST_CASE("perturbed<adaptive> on lattices equals perturbed<mp>", "[small_integer][perturbed]") {
  const perturbed<AdaptiveKernel> ad;
  const perturbed<MpKernel> pm;
  Lattice lat{std::mt19937_64(11), 0, 1};
  int perturbation = 0;
  for (int t = 0; t < 3000; ++t) {
    lat.base = t % 2 ? 0 : 1000;
    const Point3 a = lat.p3(), b = lat.p3(), c = lat.p3(), d = lat.p3(), e = lat.p3();
    REQUIRE(ad.insphere(a, b, c, d, e) == pm.insphere(a, b, c, d, e));
    REQUIRE(ad.orient3d(a, b, c, d) == pm.orient3d(a, b, c, d));
    const Staged st = ad.insphere_staged(a, b, c, d, e);
    REQUIRE(st.sign == ad.insphere(a, b, c, d, e));
    // A zero-volume query (coplanar, repeated points) stays outside the contract;
    // for distinct non-coplanar a, b, c, d the perturbation answers exactly the zeros.
    if (mp.orient3d(a, b, c, d) != Sign::zero) {
      const bool zero = mp.insphere(a, b, c, d, e) == Sign::zero;
      REQUIRE((st.stage == perturbed<AdaptiveKernel>::perturbation_stage) == zero);
      perturbation += zero;
    }
    if (mp.orient2d({a[0], a[1]}, {b[0], b[1]}, {c[0], c[1]}) != Sign::zero) {
      const Point3 pa{a[0], a[1], 5}, pb{b[0], b[1], 5}, pc{c[0], c[1], 5}, pp{d[0], d[1], 5};
      if (pp != pa && pp != pb && pp != pc)
        REQUIRE(ad.coplanar_incircle(pa, pb, pc, pp) == pm.coplanar_incircle(pa, pb, pc, pp));
    }
    const Point2 p = lat.p2(), q = lat.p2(), r = lat.p2(), u = lat.p2();
    REQUIRE(ad.incircle(p, q, r, u) == pm.incircle(p, q, r, u));
    REQUIRE(ad.orient2d(p, q, r) == pm.orient2d(p, q, r));
  }
  CHECK(perturbation > 50);
  // Off-lattice points still go through the adaptive stages (same answers).
  const Point3 a{0.5, 0, 0}, b{0, 0.5, 0}, c{0, 0, 0.5}, d{0, 0, 0}, e{0.5, 0.5, 0.5};
  CHECK(ad.insphere(a, b, c, d, e) == pm.insphere(a, b, c, d, e));
  CHECK(ad.insphere_staged(a, b, c, d, e).stage == perturbed<AdaptiveKernel>::perturbation_stage);
}

TEST_CASE("small_integer: the symbolic walk equals perturbed<mp>, ties included", "[small_integer]") {
  const perturbed<MpKernel> pm;
  Lattice lat{std::mt19937_64(5), 0, 1};
  int walked = 0;
  for (int t = 0; t < 4000; ++t) {
    lat.base = t % 3 == 0 ? -0x1p40 : 7;
    lat.half = t % 5 == 0 ? 255 : 1;
    std::array<Point3, 5> q{lat.p3(), lat.p3(), lat.p3(), lat.p3(), lat.p3()};
    if (t % 7 == 0) q[4] = q[t % 4];  // a repeated point: ties in the ranks
    const auto r = small_integer::insphere_sos(q[0], q[1], q[2], q[3], q[4]);
    REQUIRE(r.known);
    const auto rs = small_integer::insphere_sos_scalar(q[0], q[1], q[2], q[3], q[4]);
    REQUIRE((rs.known && rs.sign == r.sign && rs.by_perturbation == r.by_perturbation));
    REQUIRE(r.sign == pm.insphere(q[0], q[1], q[2], q[3], q[4]));
    REQUIRE(r.by_perturbation == (mp.insphere(q[0], q[1], q[2], q[3], q[4]) == Sign::zero));
    walked += r.by_perturbation;
    std::array<Point2, 4> p{lat.p2(), lat.p2(), lat.p2(), lat.p2()};
    if (t % 7 == 1) p[3] = p[t % 3];
    const auto s = small_integer::incircle_sos(p[0], p[1], p[2], p[3]);
    REQUIRE(s.known);
    const auto ss = small_integer::incircle_sos_scalar(p[0], p[1], p[2], p[3]);
    REQUIRE((ss.known && ss.sign == s.sign && ss.by_perturbation == s.by_perturbation));
    REQUIRE(s.sign == pm.incircle(p[0], p[1], p[2], p[3]));
    REQUIRE(s.by_perturbation == (mp.incircle(p[0], p[1], p[2], p[3]) == Sign::zero));
    walked += s.by_perturbation;
  }
  CHECK(walked > 500);
  // Not certified: off the lattice, or differences beyond the budget.
  CHECK_FALSE(small_integer::insphere_sos({0.5, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0, 0, 0}).known);
  CHECK_FALSE(small_integer::insphere_sos({513, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0, 0, 0}).known);
  CHECK(small_integer::insphere_sos({512, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}, {0, 0, 0}).known);
  CHECK_FALSE(small_integer::incircle_sos({4097, 0}, {0, 1}, {1, 1}, {0, 0}).known);
  CHECK(small_integer::incircle_sos({4096, 0}, {0, 1}, {1, 1}, {0, 0}).known);
}

// The twins of insphere_sos and incircle_sos refuse a difference beyond B in
// every place (the SSE2 twins check them two by two) and a non-finite coordinate
// in every place, and certify B itself there.
namespace {
template <int D, int N, class Twins>
void twins_at_the_bound(std::array<Point<D>, N> q, double bound, Twins both) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (double shift : {0.0, 0x1p51, -1000.0}) {
    std::array<Point<D>, N> s = q;
    for (auto& p : s)
      for (auto& x : p) x += shift;
    REQUIRE(both(s));
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < D; ++j) {
        for (double bad : {inf, -inf, nan}) {
          std::array<Point<D>, N> r = s;
          r[i][j] = bad;
          CHECK_FALSE(both(r));
        }
        if (i == N - 1) continue;  // the reference point
        for (double sign : {1.0, -1.0}) {
          std::array<Point<D>, N> r = s;
          r[i][j] = s[N - 1][j] + sign * bound;
          CHECK(both(r));
          r[i][j] = s[N - 1][j] + sign * (bound + 1);
          CHECK_FALSE(both(r));
        }
      }
  }
}
template <class A>
bool same_answer(const A& s, const A& v) {
  REQUIRE(s.known == v.known);
  if (s.known) REQUIRE((s.sign == v.sign && s.by_perturbation == v.by_perturbation));
  return s.known;
}
}  // namespace

TEST_CASE("small_integer: the sos twins at the bound, place by place", "[small_integer]") {
  using namespace small_integer;
  twins_at_the_bound<3, 5>({Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}, Point3{1, 1, 1}, Point3{0, 0, 0}},
                           is_bound, [](const std::array<Point3, 5>& q) {
                             return same_answer(insphere_sos_scalar(q[0], q[1], q[2], q[3], q[4]),
                                                insphere_sos(q[0], q[1], q[2], q[3], q[4]));
                           });
  twins_at_the_bound<2, 4>({Point2{1, 0}, Point2{0, 1}, Point2{1, 1}, Point2{0, 0}}, ic_bound,
                           [](const std::array<Point2, 4>& q) {
                             return same_answer(incircle_sos_scalar(q[0], q[1], q[2], q[3]),
                                                incircle_sos(q[0], q[1], q[2], q[3]));
                           });
}

// The walk's keys (lex_key2, lex_key3) at the edges of their range [-B, B]^D:
// exact, and in the lexicographic order (lex_less, plain comparisons), on every
// pair of vectors with coordinates at the ends, next to them and near zero.
TEST_CASE("small_integer: the walk's keys order [-B, B]^D lexicographically", "[small_integer]") {
  const auto values = [](double b) { return std::array<double, 7>{-b, -b + 1, -1, 0, 1, b - 1, b}; };
  const auto v2 = values(small_integer::ic_bound);
  std::vector<Point2> p2;
  for (double x : v2)
    for (double y : v2) p2.push_back({x, y});
  int pairs = 0;
  for (const Point2& u : p2)
    for (const Point2& v : p2) {
      const double ku = small_integer::lex_key2(u[0], u[1]), kv = small_integer::lex_key2(v[0], v[1]);
      REQUIRE(ku == std::trunc(ku));
      REQUIRE((ku < kv) == lex_less<2>(u, v));
      REQUIRE((ku == kv) == (u == v));
      ++pairs;
    }
  const auto v3 = values(small_integer::is_bound);
  std::vector<Point3> p3;
  for (double x : v3)
    for (double y : v3)
      for (double z : v3) p3.push_back({x, y, z});
  for (const Point3& u : p3)
    for (const Point3& v : p3) {
      const double ku = small_integer::lex_key3(u[0], u[1], u[2]);
      const double kv = small_integer::lex_key3(v[0], v[1], v[2]);
      REQUIRE(ku == std::trunc(ku));
      REQUIRE((ku < kv) == lex_less<3>(u, v));
      REQUIRE((ku == kv) == (u == v));
      ++pairs;
    }
  CHECK(pairs == 49 * 49 + 343 * 343);
}

// Certificate (1) of predicates/small_integer.hpp, claim by claim, against
// std::trunc (an independent integer test): in every binade from the smallest
// subnormal to 2^1023, both signs, at the binade's edges, one and two ulps
// inside, and at the half-way points between integers where they exist.
TEST_CASE("small_integer: is_int is exact on both signs in every binade", "[small_integer]") {
  using small_integer::is_int;
  const double inf = std::numeric_limits<double>::infinity();
  int half_integers = 0;
  auto check = [&](double x) {
    const bool integer = std::trunc(x) == x;
    // A pass means an integer; every integer up to 2^52 passes.
    if (is_int(x)) REQUIRE(integer);
    if (integer && std::fabs(x) <= 0x1p52) REQUIRE(is_int(x));
    // The scalar and SSE2 evaluations of all_int agree (the reference point
    // is the first one here, bounded by 2^52, the second may be anything).
    const Point2 p{x, 0}, ref{0, 0}, q{x, x};
    const Point2* const pts[2] = {&p, &ref};
    const Point2* const refs[2] = {&ref, &q};
    const bool scalar = small_integer::all_int_scalar<2, 2>(pts);
    REQUIRE(scalar == is_int(x));
    REQUIRE(small_integer::all_int_scalar<2, 2>(refs) == (is_int(x) && std::fabs(x) <= 0x1p52));
#if defined(__SSE2__)
    REQUIRE(small_integer::all_int_sse2<2, 2>(pts) == scalar);
    REQUIRE(small_integer::all_int_sse2<2, 2>(refs) ==
            small_integer::all_int_scalar<2, 2>(refs));
    const Point3 p3{0, 0, x}, r3{0, 0, 0};
    const Point3* const pts3[2] = {&p3, &r3};
    REQUIRE(small_integer::all_int_sse2<3, 2>(pts3) == small_integer::all_int_scalar<3, 2>(pts3));
#endif
  };
  for (int e = -1074; e <= 1023; ++e) {
    const double edge = std::ldexp(1.0, e);
    for (double s : {1.0, -1.0}) {
      const double x = s * edge;
      for (double y : {x, std::nextafter(x, 0.0), std::nextafter(x, 2 * x),
                       std::nextafter(std::nextafter(x, 2 * x), 2 * x),
                       std::nextafter(std::nextafter(x, 0.0), 0.0)})
        check(y);
      // Half-integers exist up to 2^52: x + 1/2 and the largest one in the binade.
      if (e >= 1 && e <= 51) {
        const double h = x + s * 0.5, top = s * (2 * edge - 0.5);
        REQUIRE(std::trunc(h) != h);
        REQUIRE(std::trunc(top) != top);
        check(h);
        check(top);
        check(x + s * 1.0);
        half_integers += 2;
      }
    }
  }
  CHECK(half_integers == 2 * 2 * 51);
  for (double x : {0.0, -0.0, inf, -inf}) CHECK(is_int(x));
  CHECK_FALSE(is_int(std::numeric_limits<double>::quiet_NaN()));
}

// Issue 17's witness: half-integers in [-2^52, -2^51) used to pass the
// certificate, and the SoS keys truncated them.
TEST_CASE("small_integer: the binade [-2^52, -2^51) witness", "[small_integer]") {
  const perturbed<AdaptiveKernel> ad;
  const perturbed<MpKernel> pm;
  const double x0 = -2251799813685256.0, x1 = -2251799813685255.5;  // -(2^51 + 8), -(2^51 + 7.5)
  const Point2 p[4] = {{x0, 1}, {x0, 0}, {x1, 0}, {x1, 1}};
  CHECK_FALSE(small_integer::incircle_sos(p[0], p[1], p[2], p[3]).known);
  CHECK_FALSE(small_integer::orient2d(p[0], p[1], p[2]).known);
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 4; ++l) {
          if (i == j || i == k || i == l || j == k || j == l || k == l) continue;
          REQUIRE(ad.incircle(p[i], p[j], p[k], p[l]) == pm.incircle(p[i], p[j], p[k], p[l]));
          REQUIRE(ad.orient2d(p[i], p[j], p[k]) == pm.orient2d(p[i], p[j], p[k]));
        }
  // The same in 3D: a unit cube of half-integers in the binade.
  Point3 c[8];
  for (int i = 0; i < 8; ++i) c[i] = {i & 1 ? x1 : x0, i & 2 ? x1 - 1 : x0 + 1, i & 4 ? 2.0 : 1.0};
  for (int t = 0; t < 8 * 7 * 6 * 5; ++t) {
    const int a = t % 8, b = (a + 1 + t / 8 % 7) % 8;
    const int i2 = (t / 56) % 8, i3 = (t / 3) % 8, i4 = (t / 5) % 8;
    REQUIRE(ad.insphere(c[a], c[b], c[i2], c[i3], c[i4]) ==
            pm.insphere(c[a], c[b], c[i2], c[i3], c[i4]));
    REQUIRE(ad.orient3d(c[a], c[b], c[i2], c[i3]) == pm.orient3d(c[a], c[b], c[i2], c[i3]));
  }
}
