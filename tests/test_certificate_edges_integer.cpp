// Issue 17, "every certificate is tested at its edges", for the integer-valued
// certificates. RapidCheck drives the inputs to the edges of each one and
// compares with GmpKernel / perturbed<GmpKernel> / exact rationals (GMP alone:
// MpKernel evaluates small integers with the integer kernel's own intdet):
//  - small-integer evaluation (predicates/small_integer.hpp) and its SoS keys:
//    reference coordinates at every binade edge from 2^-1074 to 2^1023, both
//    signs, moved by m 2^-k and by ulps, at +-2^52, +-2^51, +-2^53 and their
//    neighbours; differences at B - 1, B, B + 1 (and B +- 2^-k) for each
//    predicate's bound. A certified answer must be mp's; the certified domain
//    is exactly the documented one (every integer case with |x| <= 2^52 and
//    differences <= B is certified; nothing else is, bar integers beyond 2^52);
//  - the integer kernel's bit budgets (integer_kernel.hpp, wide_int.hpp): the
//    exact determinants at the corners of the index box for the B where a
//    budget's type changes width, and fitted kernels (integer_grid.hpp) on
//    binade-edge boxes, against mp on the snapped points;
//  - perturbed<K>::coplanar_incircle_exact for K = adaptive (small-integer path
//    included), integer and mp, against the circumcircle in exact rationals.
#include <algorithm>
#include <array>
#include <bit>
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <span>
#include <tuple>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "predicates/small_integer.hpp"

using namespace dlab;

namespace {

const GmpKernel mp;  // GMP alone: MpKernel shares intdet with the integer kernel
const perturbed<GmpKernel> pmp;
const perturbed<AdaptiveKernel> pad;

// The bounds small_integer.hpp documents, written out here so that a changed
// constant is seen even where it would still be exact.
constexpr double documented_o2 = 0x1p25, documented_ic = 0x1p12, documented_o3 = 0x1p16,
                 documented_is = 0x1p9, documented_reference = 0x1p52;

bool integral(double x) { return std::isfinite(x) && std::trunc(x) == x; }

// A binade edge s 2^e (e from -1074 to 1023), moved by m 2^-k, by m 2^(e-k)
// (k = 0..4, |m| <= 3), by up to two ulps, or not at all.
double binade_edge() {
  const int e = *rc::gen::inRange(-1074, 1024);
  const double x = std::ldexp(*rc::gen::arbitrary<bool>() ? -1.0 : 1.0, e);
  const int m = *rc::gen::inRange(-3, 4), k = *rc::gen::inRange(0, 5);
  switch (*rc::gen::inRange(0, 4)) {
    case 0: return x + std::ldexp(m, -k);
    case 1: return x + std::ldexp(m, std::max(e - k, -1074));
    case 2: {
      double y = x;
      for (int i = 0; i < std::abs(m) % 3; ++i) y = std::nextafter(y, m < 0 ? 0.0 : 2 * y);
      return y;
    }
    default: return x;
  }
}

// Reference coordinates: binade edges, the edges of the certificate itself
// (2^52: the reference bound and is_int's shift; 2^51: where spacing becomes
// 1/2; 2^53: where it becomes 2), the issue-17 witness, small integers.
double reference_coordinate() {
  static const std::vector<double> special{
      0x1p52, 0x1p52 + 1, 0x1p52 + 2, 0x1p52 - 0.5, 0x1p52 - 1, 0x1p52 - 1.5,
      0x1p51, 0x1p51 + 0.5, 0x1p51 - 0.5, 0x1p51 + 1, 0x1p51 + 8, 0x1p51 + 7.5,
      0x1p53, 0x1p53 - 1, 0x1p53 + 2, 0x1p53 + 4, 0, 1, 0.5};
  switch (*rc::gen::inRange(0, 3)) {
    case 0: return (*rc::gen::arbitrary<bool>() ? -1 : 1) * *rc::gen::elementOf(special);
    case 1: return binade_edge();
    default: return *rc::gen::inRange(-100, 101);
  }
}

// A coordinate difference for bound B. Modes: the edge (0, 1, B/2, B - 1, B,
// B + 1, moved by m 2^-k), the lattices {0, B} and {0, B/2, B} (exactly
// cocircular / cospherical sets: the SoS walk), any integer in [-B-1, B+1].
double difference(double B, int mode) {
  const double s = *rc::gen::arbitrary<bool>() ? -1 : 1;
  switch (mode) {
    case 0: {
      double d = *rc::gen::elementOf(std::vector<double>{0, 1, B / 2, B - 1, B, B + 1});
      if (*rc::gen::inRange(0, 4) == 0) d += std::ldexp(*rc::gen::inRange(-2, 3), -*rc::gen::inRange(0, 5));
      return s * d;
    }
    case 1: return s * B * *rc::gen::inRange(0, 2);
    case 2: return s * B / 2 * *rc::gen::inRange(0, 3);
    default: return *rc::gen::inRange(-static_cast<int>(B) - 1, static_cast<int>(B) + 2);
  }
}

// N points of dimension D, the last one the reference; the others are the
// reference plus differences (rounded like any input).
template <int D, int N>
std::array<Point<D>, N> edge_call(double B) {
  std::array<Point<D>, N> p;
  const bool shared = *rc::gen::arbitrary<bool>();  // one value on every axis
  const double r0 = reference_coordinate();
  for (int j = 0; j < D; ++j) p[N - 1][j] = shared ? r0 : reference_coordinate();
  const int mode = *rc::gen::inRange(0, 4);
  for (int i = 0; i + 1 < N; ++i)
    for (int j = 0; j < D; ++j) p[i][j] = p[N - 1][j] + difference(B, mode);
  return p;
}

// The documented certified domain, decided independently of the code:
// `strict`: every coordinate an integer of magnitude <= 2^52 and every
// difference to the reference at most B (there the certificate must answer);
// `loose`: the same with integers of any magnitude besides the reference (the
// certificate may refuse those; it must refuse everything outside).
template <int D, int N>
std::pair<bool, bool> domain(const std::array<Point<D>, N>& p, double B) {
  bool loose = true, strict = true;
  for (int j = 0; j < D; ++j) {
    const double r = p[N - 1][j];
    loose = loose && integral(r) && std::fabs(r) <= documented_reference;
    for (int i = 0; i + 1 < N; ++i) {
      const double x = p[i][j];
      if (!integral(x)) {
        loose = false;
        continue;
      }
      strict = strict && std::fabs(x) <= documented_reference;
      // Both integers and |r| <= 2^52 (else loose is false already): x - r is
      // exact whenever it is <= B, and large when it is not.
      loose = loose && std::fabs(x - r) <= B;
    }
  }
  return {loose, loose && strict};
}

struct Tally {
  int calls = 0, certified = 0, strict = 0, zeros = 0, walked = 0;
};

// Certificate (1) on every coordinate of a call, and the scalar and SSE2
// evaluations of all_int on the call itself.
template <int D, int N>
void check_all_int(const std::array<Point<D>, N>& p) {
  for (const auto& q : p)
    for (double x : q) {
      if (small_integer::is_int(x)) RC_ASSERT(!std::isfinite(x) || integral(x));
      if (integral(x) && std::fabs(x) <= 0x1p52) RC_ASSERT(small_integer::is_int(x));
    }
  const Point<D>* pts[N];
  for (int i = 0; i < N; ++i) pts[i] = &p[i];
  const bool scalar = small_integer::all_int_scalar<D, N>(pts);
#if defined(__SSE2__)
  RC_ASSERT((small_integer::all_int_sse2<D, N>(pts) == scalar));
#endif
  bool expected = true;
  for (const auto& q : p)
    for (double x : q) expected = expected && small_integer::is_int(x);
  for (double x : p[N - 1]) expected = expected && std::fabs(x) <= documented_reference;
  RC_ASSERT(scalar == expected);
}

template <class Answer>
void tally(Tally& t, const Answer& r, bool strict) {
  ++t.calls;
  t.certified += r.known;
  t.strict += strict;
  t.zeros += r.known && r.sign == Sign::zero;
}

}  // namespace

namespace {

// The properties reach the certified domain, its zeros and the walk. (One
// rc::prop per test case: each is a Catch section, run in its own pass.)
void check_reach(const Tally& t) {
  INFO("calls " << t.calls << ", certified " << t.certified << ", strict " << t.strict
                << ", zeros " << t.zeros << ", walked " << t.walked);
  CHECK(t.certified >= t.calls / 10);
  CHECK(t.strict >= t.calls / 20);
  CHECK(t.zeros > 0);
}

}  // namespace

TEST_CASE("small_integer 2D at the edges of its certificate agrees with mp",
          "[certificate][small_integer][rc]") {
  Tally o2, ic;
  rc::prop("orient2d, incircle and incircle_sos", [&] {
    for (int batch = 0; batch < 40; ++batch) {
      const auto p = edge_call<2, 3>(documented_o2);
      check_all_int<2, 3>(p);
      const auto [loose, strict] = domain<2, 3>(p, documented_o2);
      const auto r = small_integer::orient2d(p[0], p[1], p[2]);
      const Sign exact = mp.orient2d(p[0], p[1], p[2]);
      if (r.known) RC_ASSERT(r.sign == exact);
      if (r.known) RC_ASSERT(loose);
      if (strict) RC_ASSERT(r.known);
      RC_ASSERT(pad.orient2d(p[0], p[1], p[2]) == exact);
      tally(o2, r, strict);
  
      const auto q = edge_call<2, 4>(documented_ic);
      check_all_int<2, 4>(q);
      const auto [qloose, qstrict] = domain<2, 4>(q, documented_ic);
      const auto c = small_integer::incircle(q[0], q[1], q[2], q[3]);
      const auto s = small_integer::incircle_sos(q[0], q[1], q[2], q[3]);
      const Sign qexact = mp.incircle(q[0], q[1], q[2], q[3]);
      const Sign perturbed_sign = pmp.incircle(q[0], q[1], q[2], q[3]);
      RC_ASSERT(c.known == s.known);
      if (c.known) RC_ASSERT(c.sign == qexact);
      if (s.known) {
        RC_ASSERT(s.sign == perturbed_sign);
        RC_ASSERT(s.by_perturbation == (qexact == Sign::zero));
      }
      if (c.known) RC_ASSERT(qloose);
      if (qstrict) RC_ASSERT(c.known);
      RC_ASSERT(pad.incircle(q[0], q[1], q[2], q[3]) == perturbed_sign);
      tally(ic, c, qstrict);
      ic.walked += s.known && s.by_perturbation;
    }
  });
  check_reach(o2);
  check_reach(ic);
  CHECK(ic.walked > 0);
}

TEST_CASE("small_integer 3D at the edges of its certificate agrees with mp",
          "[certificate][small_integer][rc]") {
  Tally o3, is;
  rc::prop("orient3d, insphere and insphere_sos", [&] {
    for (int batch = 0; batch < 40; ++batch) {
      const auto p = edge_call<3, 4>(documented_o3);
      check_all_int<3, 4>(p);
      const auto [loose, strict] = domain<3, 4>(p, documented_o3);
      const auto r = small_integer::orient3d(p[0], p[1], p[2], p[3]);
      const Sign exact = mp.orient3d(p[0], p[1], p[2], p[3]);
      if (r.known) RC_ASSERT(r.sign == exact);
      if (r.known) RC_ASSERT(loose);
      if (strict) RC_ASSERT(r.known);
      RC_ASSERT(pad.orient3d(p[0], p[1], p[2], p[3]) == exact);
      tally(o3, r, strict);
  
      const auto q = edge_call<3, 5>(documented_is);
      check_all_int<3, 5>(q);
      const auto [qloose, qstrict] = domain<3, 5>(q, documented_is);
      const auto c = small_integer::insphere(q[0], q[1], q[2], q[3], q[4]);
      const auto s = small_integer::insphere_sos(q[0], q[1], q[2], q[3], q[4]);
      const Sign qexact = mp.insphere(q[0], q[1], q[2], q[3], q[4]);
      const Sign perturbed_sign = pmp.insphere(q[0], q[1], q[2], q[3], q[4]);
      RC_ASSERT(c.known == s.known);
      if (c.known) RC_ASSERT(c.sign == qexact);
      if (s.known) {
        RC_ASSERT(s.sign == perturbed_sign);
        RC_ASSERT(s.by_perturbation == (qexact == Sign::zero));
      }
      if (c.known) RC_ASSERT(qloose);
      if (qstrict) RC_ASSERT(c.known);
      RC_ASSERT(pad.insphere(q[0], q[1], q[2], q[3], q[4]) == perturbed_sign);
      tally(is, c, qstrict);
      is.walked += s.known && s.by_perturbation;
    }
  });
  check_reach(o3);
  check_reach(is);
  CHECK(is.walked > 0);
}

namespace {

// Differences at B - 1, B, B + 1 on every axis of every point at once (the
// largest products and sums of the budget), signs chosen per entry, with the
// reference at +-2^52, +-2^51 or a binade edge. Returns the number certified.
template <int D, int N, class Small, class Exact>
int budget_corners(double B, Small&& small, Exact&& exact) {
  int certified = 0;
  for (int t = 0; t < 64; ++t) {
    std::array<Point<D>, N> p;
    const double r = *rc::gen::elementOf(std::vector<double>{0x1p52, -0x1p52, 0x1p51, -0x1p51,
                                                               0x1p52 - 0x1p26, 0, 7});
    p[N - 1].fill(r);
    const double m = B + *rc::gen::inRange(-1, 2);
    for (int i = 0; i + 1 < N; ++i)
      for (int j = 0; j < D; ++j) p[i][j] = r + (*rc::gen::arbitrary<bool>() ? m : -m);
    const auto ans = small(p);
    if (ans.known) RC_ASSERT(ans.sign == exact(p));
    const bool fits = m <= B && std::fabs(r) + m <= 0x1p52;
    RC_ASSERT(ans.known == fits || (!fits && std::fabs(r) + m > 0x1p52 && m <= B));
    certified += ans.known;
  }
  return certified;
}

}  // namespace

TEST_CASE("small_integer: every difference at B - 1, B, B + 1 at once", "[certificate][small_integer][rc]") {
  int certified = 0;
  rc::prop("all four predicates at their budget's corners", [&] {
    certified += budget_corners<2, 3>(
        documented_o2, [](const auto& p) { return small_integer::orient2d(p[0], p[1], p[2]); },
        [](const auto& p) { return mp.orient2d(p[0], p[1], p[2]); });
    certified += budget_corners<2, 4>(
        documented_ic, [](const auto& p) { return small_integer::incircle(p[0], p[1], p[2], p[3]); },
        [](const auto& p) { return mp.incircle(p[0], p[1], p[2], p[3]); });
    certified += budget_corners<3, 4>(
        documented_o3, [](const auto& p) { return small_integer::orient3d(p[0], p[1], p[2], p[3]); },
        [](const auto& p) { return mp.orient3d(p[0], p[1], p[2], p[3]); });
    certified += budget_corners<3, 5>(
        documented_is,
        [](const auto& p) { return small_integer::insphere(p[0], p[1], p[2], p[3], p[4]); },
        [](const auto& p) { return mp.insphere(p[0], p[1], p[2], p[3], p[4]); });
  });
  CHECK(certified > 1000);
}

namespace {

// Lattice points of the circle (sphere) centred at (1/2, 0[, 0]) through
// (0, t[, 0]) and (1, -t[, 0]): (2x - 1)^2 + (2y)^2 [+ (2z)^2] = 1 + 4t^2, x < 0.
// With the query among them, those two are the lexicographically largest
// points and differ by 1 in x and by 2t > B + 1 in y: the SoS keys
// ((x + B)(2B + 1) + (y + B))... order them only with the full radix 2B + 1.
template <int D>
std::vector<Point<D>> symmetric_sphere(int t) {
  std::vector<Point<D>> out;
  const long n = 1 + 4L * t * t;
  for (long u = -3; u * u <= n; u -= 2)  // u = 2x - 1, x < 0
    for (long y = -t; y <= t; ++y) {
      const long rest = n - u * u - 4 * y * y;  // (2z)^2
      const double x = static_cast<double>((u + 1) / 2);
      if constexpr (D == 2) {
        if (rest == 0) out.push_back({x, double(y)});
      } else {
        const long z = std::lround(std::sqrt(static_cast<double>(rest / 4)));
        if (rest >= 0 && rest % 4 == 0 && z * z == rest / 4) {
          out.push_back({x, double(y), double(z)});
          if (z != 0) out.push_back({x, double(y), double(-z)});
        }
      }
    }
  return out;
}

}  // namespace

TEST_CASE("small_integer: the SoS keys order points a unit apart in x across the whole y range",
          "[certificate][small_integer]") {
  int walked = 0;
  for (const int t : {2049, 2050, 2052}) {  // 2t > ic_bound + 1 = 4097
    const auto pts = symmetric_sphere<2>(t);
    const Point2 p1{0, double(t)}, p2{1, double(-t)};
    for (const auto& c : pts)
      for (const auto& d : pts) {
        if (c == d) continue;
        const Point2 q[4] = {p1, p2, c, d};
        const auto r = small_integer::incircle_sos(q[0], q[1], q[2], q[3]);
        if (!r.known) continue;  // a difference beyond ic_bound
        REQUIRE(r.by_perturbation);  // exactly cocircular
        REQUIRE(r.sign == pmp.incircle(q[0], q[1], q[2], q[3]));
        const auto s = small_integer::incircle_sos(q[2], q[1], q[0], q[3]);
        REQUIRE(s.sign == pmp.incircle(q[2], q[1], q[0], q[3]));
        ++walked;
      }
  }
  for (const int t : {257, 258, 260}) {  // 2t > is_bound + 1 = 513
    const auto pts = symmetric_sphere<3>(t);
    const Point3 p1{0, double(t), 0}, p2{1, double(-t), 0};
    std::uint64_t h = 12345;  // a fixed LCG stream: triples of points
    for (int trial = 0; trial < 4000; ++trial) {
      std::size_t pick[3];
      for (auto& i : pick) {
        h = h * 6364136223846793005ULL + 1442695040888963407ULL;
        i = static_cast<std::size_t>(h >> 33) % pts.size();
      }
      const Point3 q[5] = {p1, p2, pts[pick[0]], pts[pick[1]], pts[pick[2]]};
      if (q[2] == q[3] || q[3] == q[4] || q[2] == q[4]) continue;
      const auto r = small_integer::insphere_sos(q[0], q[1], q[2], q[3], q[4]);
      if (!r.known) continue;  // a difference beyond is_bound
      REQUIRE(r.by_perturbation);  // exactly cospherical
      REQUIRE(r.sign == pmp.insphere(q[0], q[1], q[2], q[3], q[4]));
      ++walked;
    }
  }
  CHECK(walked > 100);
}

// ---- The integer kernel's bit budgets ----

namespace {

// Index values biased to the box's corners: lo, lo + 1, the middle, hi - 1, hi
// (hi = lo + 2^B - 1), or anywhere in the box.
template <int B>
std::int64_t box_index(std::int64_t lo) {
  const std::int64_t span = (std::int64_t{1} << B) - 1;
  switch (*rc::gen::inRange(0, 6)) {
    case 0: return lo;
    case 1: return lo + 1;
    case 2: return lo + span / 2;
    case 3: return lo + span - 1;
    case 4: return lo + span;
    default: return lo + *rc::gen::inRange<std::int64_t>(0, span + 1);
  }
}

template <int B, int D>
std::array<std::int64_t, D> box_point(const std::array<std::int64_t, D>& lo) {
  std::array<std::int64_t, D> p;
  for (int j = 0; j < D; ++j) p[j] = box_index<B>(lo[j]);
  return p;
}

template <std::size_t D>
std::array<double, D> as_point(const std::array<std::int64_t, D>& i) {
  std::array<double, D> p;
  for (std::size_t j = 0; j < D; ++j) p[j] = static_cast<double>(i[j]);  // exact: |i| < 2^53
  return p;
}

// intdet at width B against mp on the same integers (B <= 52: they are doubles).
template <int B>
void intdet_at_corners() {
  static_assert(B <= 52);
  const std::int64_t half = std::int64_t{1} << (B - 1);
  const std::int64_t lo = *rc::gen::elementOf(std::vector<std::int64_t>{0, -half, -2 * half + 1});
  const intdet::I2 a2 = box_point<B, 2>({lo, lo}), b2 = box_point<B, 2>({lo, lo}),
                   c2 = box_point<B, 2>({lo, lo}), d2 = box_point<B, 2>({lo, lo});
  RC_ASSERT(intdet::sign(intdet::orient2d<B>(a2, b2, c2)) ==
            mp.orient2d(as_point(a2), as_point(b2), as_point(c2)));
  RC_ASSERT(intdet::sign(intdet::incircle<B>(a2, b2, c2, d2)) ==
            mp.incircle(as_point(a2), as_point(b2), as_point(c2), as_point(d2)));
  const intdet::I3 l3{lo, lo, lo};
  const intdet::I3 a = box_point<B, 3>(l3), b = box_point<B, 3>(l3), c = box_point<B, 3>(l3),
                   d = box_point<B, 3>(l3), e = box_point<B, 3>(l3);
  const Point3 pa = as_point(a), pb = as_point(b), pc = as_point(c), pd = as_point(d),
               pe = as_point(e);
  RC_ASSERT(intdet::sign(intdet::orient3d<B>(a, b, c, d)) == mp.orient3d(pa, pb, pc, pd));
  RC_ASSERT(intdet::sign(intdet::insphere<B>(a, b, c, d, e)) == mp.insphere(pa, pb, pc, pd, pe));
  // The coplanar in-circle determinant on the plane z = a_z (dropping z it is
  // the 2D in-circle: the lifts' z terms vanish).
  const intdet::I3 fa{a[0], a[1], a[2]}, fb{b[0], b[1], a[2]}, fc{c[0], c[1], a[2]},
      fp{d[0], d[1], a[2]};
  auto xy = [](const intdet::I3& i) { return Point2{double(i[0]), double(i[1])}; };
  RC_ASSERT(intdet::sign(intdet::coplanar_incircle<B>(fa, fb, fc, fp, 2)) ==
            mp.incircle(xy(fa), xy(fb), xy(fc), xy(fp)));
}

}  // namespace

TEST_CASE("integer determinants at the box corners where a budget's type changes width",
          "[certificate][integer][rc]") {
  // A budget of f(B) bits is held by the narrowest of int64 / int128 / WideInt
  // (capacities 63, 127, 191, ...); the type is one width narrower at f(B) - 1
  // bits exactly where f(B) - 1 is a capacity: 2B + 2 at B = 31 (3D lifts),
  // 4B + 4 at B = 15, 31, 47 (incircle), 5B + 7 at B = 37 (insphere). There,
  // and at the kernels' own B = 24, 30 (B = 62 and 55: tests/test_integer_kernel.cpp).
  rc::prop("B = 15, 24, 30, 31, 37, 47 against mp", [] {
    intdet_at_corners<15>();
    intdet_at_corners<24>();
    intdet_at_corners<30>();
    intdet_at_corners<31>();
    intdet_at_corners<37>();
    intdet_at_corners<47>();
  });
}

namespace {

// Points at the corners of a box whose sides are binade edges (and a few ulps
// inside), the grid fitted to them, the predicates against mp on the snapped
// points; perturbed<K> against perturbed<mp>.
template <class K>
void fitted_kernel_at_edges() {
  constexpr int n = 8;
  std::vector<Point3> p3(n);
  std::vector<Point2> p2(n);
  double lo[3], hi[3];
  for (int j = 0; j < 3; ++j) {
    lo[j] = binade_edge();
    hi[j] = *rc::gen::arbitrary<bool>() ? binade_edge() : -lo[j];
    if (hi[j] < lo[j]) std::swap(lo[j], hi[j]);
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j) {
      const int c = *rc::gen::inRange(0, 4);
      double x = c == 0 ? lo[j] : (c == 1 ? hi[j] : (c == 2 ? lo[j] / 2 + hi[j] / 2 : lo[j]));
      if (c == 3) x = std::nextafter(hi[j], lo[j]);
      p3[i][j] = x;
      if (j < 2) p2[i][j] = x;
    }
  perturbed<K> k3, k2;
  k3.snap_all(p3);
  k2.snap_all(p2);
  for (int t = 0; t < 12; ++t) {
    const auto i = *rc::gen::container<std::array<int, 5>>(rc::gen::inRange(0, n));
    const Point3 &a = p3[i[0]], &b = p3[i[1]], &c = p3[i[2]], &d = p3[i[3]], &e = p3[i[4]];
    RC_ASSERT(k3.orient3d(a, b, c, d) == mp.orient3d(a, b, c, d));
    RC_ASSERT(k3.base.insphere(a, b, c, d, e) == mp.insphere(a, b, c, d, e));
    RC_ASSERT(k3.insphere(a, b, c, d, e) == pmp.insphere(a, b, c, d, e));
    const Point2 &u = p2[i[0]], &v = p2[i[1]], &w = p2[i[2]], &z = p2[i[3]];
    RC_ASSERT(k2.orient2d(u, v, w) == mp.orient2d(u, v, w));
    RC_ASSERT(k2.base.incircle(u, v, w, z) == mp.incircle(u, v, w, z));
    RC_ASSERT(k2.incircle(u, v, w, z) == pmp.incircle(u, v, w, z));
  }
}

}  // namespace

TEST_CASE("fitted integer kernels on binade-edge boxes agree with mp on the snapped points",
          "[certificate][integer][rc]") {
  rc::prop("B = 62 (IntegerKernel)", [] { fitted_kernel_at_edges<IntegerKernel>(); });
  rc::prop("B = 30 / 24 (IntegerKernel128)", [] { fitted_kernel_at_edges<IntegerKernel128>(); });
  rc::prop("B = 31 (3D lifts at a width edge)", [] {
    fitted_kernel_at_edges<BasicIntegerKernel<31, 31>>();
  });
}

// ---- the integer kernel's filter (integer_kernel.hpp: FloatFilter on the
// index differences, each rounded once to double) ----

namespace {

// On the unit grid (a default-constructed kernel, h = 1) the points are their
// own indices, and integers up to 2^53 - 1 in magnitude are doubles: their
// differences reach 2^54 - 2, and an odd one above 2^53 rounds on conversion.
// Exactly degenerate sets of such points, one coordinate moved by m (0 or
// +-2^[0, 24]): collinear and coplanar sets through the origin, and lattice
// points on a circle of radius 5k (the (3, 4, 5) triangle times k) and on a
// sphere of radius 3k ((1, 2, 2) times k), k odd and large enough for the
// differences 7k and 5k to exceed 2^53.
constexpr std::int64_t kMax = (std::int64_t{1} << 53) - 1;

std::int64_t odd_in(std::int64_t lo, std::int64_t hi) { return *rc::gen::inRange(lo, hi) | 1; }

std::int64_t nudge() {
  if (*rc::gen::inRange(0, 5) == 0) return 0;
  const std::int64_t m = std::int64_t{1} << *rc::gen::inRange(0, 25);
  return (*rc::gen::arbitrary<bool>() ? 1 : -1) * (m + *rc::gen::inRange<std::int64_t>(0, m));
}

// Moves one coordinate of one point by nudge(), towards zero (so it stays on the grid).
template <std::size_t N, std::size_t D>
void move_one(std::array<std::array<std::int64_t, D>, N>& q) {
  auto& x = q[*rc::gen::inRange<std::size_t>(0, N)][*rc::gen::inRange<std::size_t>(0, D)];
  const std::int64_t m = std::abs(nudge());
  x += x > 0 ? -m : m;
}

template <std::size_t N, std::size_t D>
std::array<Point<D>, N> as_doubles(const std::array<std::array<std::int64_t, D>, N>& q) {
  std::array<Point<D>, N> p;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < D; ++j) {
      RC_ASSERT(std::abs(q[i][j]) <= kMax);
      p[i][j] = static_cast<double>(q[i][j]);
    }
  return p;
}

// Whether some difference from the last point rounds when converted.
template <std::size_t N, std::size_t D>
bool rounds(const std::array<std::array<std::int64_t, D>, N>& q) {
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j) {
      const std::int64_t d = q[i][j] - q[N - 1][j];
      if (static_cast<std::int64_t>(static_cast<double>(d)) != d) return true;
    }
  return false;
}

// N points s_i u (+ r_i v): a line (2D) or plane (3D) through the origin,
// u_j, v_j odd, |s_i|, |r_i| in [lim / 2, lim]: differences across the
// origin are odd as often as not and reach 2 kMax.
template <std::size_t N, std::size_t D>
std::array<std::array<std::int64_t, D>, N> flat_set() {
  const auto odd = [] { return *rc::gen::elementOf(std::vector<std::int64_t>{-7, -5, -3, 3, 5, 7}); };
  const std::int64_t lim = kMax / (D == 2 ? 7 : 14);  // |s u_j + r v_j| <= kMax
  const auto big = [&] { return (*rc::gen::arbitrary<bool>() ? 1 : -1) * *rc::gen::inRange(lim / 2, lim + 1); };
  std::array<std::int64_t, D> u, v{};
  for (std::size_t j = 0; j < D; ++j) u[j] = odd(), v[j] = odd();
  std::array<std::array<std::int64_t, D>, N> q;
  for (auto& p : q) {
    const std::int64_t s = big(), r = D == 3 ? big() : 0;
    for (std::size_t j = 0; j < D; ++j) p[j] = s * u[j] + r * v[j];
  }
  return q;
}

// N distinct lattice points on the circle (2D) or sphere (3D) about the origin.
template <std::size_t N, std::size_t D>
std::array<std::array<std::int64_t, D>, N> round_set() {
  std::vector<std::array<std::int64_t, D>> all;
  const std::int64_t k = D == 2 ? odd_in(kMax / 7 + 1, kMax / 5) : odd_in(kMax / 5 + 1, kMax / 3);
  const std::vector<std::array<std::int64_t, 3>> base =
      D == 2 ? std::vector<std::array<std::int64_t, 3>>{{3, 4, 0}, {4, 3, 0}, {5, 0, 0}, {0, 5, 0}}
             : std::vector<std::array<std::int64_t, 3>>{{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
  for (const auto& b : base)
    for (int signs = 0; signs < 8; ++signs) {
      std::array<std::int64_t, D> p;
      for (std::size_t j = 0; j < D; ++j) p[j] = (signs >> j & 1 ? -1 : 1) * b[j] * k;
      if (std::find(all.begin(), all.end(), p) == all.end()) all.push_back(p);
    }
  const auto pick = *rc::gen::unique<std::vector<std::size_t>>(N, rc::gen::inRange<std::size_t>(0, all.size()));
  std::array<std::array<std::int64_t, D>, N> q;
  for (std::size_t i = 0; i < N; ++i) q[i] = all[pick[i]];
  // On the sphere only 3k - (-2k) exceeds 2^53: a point (+-3k, 0, 0) as the
  // base (the filter takes differences from the last point), where there is one.
  for (std::size_t i = 0; i < N; ++i)
    if (std::count(q[i].begin(), q[i].end(), 0) == D - 1) std::swap(q[i], q[N - 1]);
  return q;
}

struct FilterTally {
  int calls = 0, filtered = 0, exact = 0, filtered_rounded = 0;
  void add(const Staged& s, bool rounded) {
    ++calls;
    (s.stage == 0 ? filtered : exact) += 1;
    filtered_rounded += s.stage == 0 && rounded;
  }
};

void check_filter_reach(const char* name, const FilterTally& t) {
  INFO(name << ": ""calls " << t.calls << ", filtered " << t.filtered << " (" << t.filtered_rounded
                << " with a rounded difference), exact " << t.exact);
  CHECK(t.filtered >= t.calls / 10);
  CHECK(t.exact >= t.calls / 10);
  CHECK(t.filtered_rounded >= t.calls / 100);
}

}  // namespace

// The kernel fitted to the call's points (fit_static_filter: every point a
// grid point, so the filter may take the coordinates as they are).
template <std::size_t N, std::size_t D>
BasicIntegerKernel<62, 62> promised(const std::array<Point<D>, N>& p) {
  BasicIntegerKernel<62, 62> k;
  k.fit_static_filter(std::span<const Point<D>>(p.data(), N));
  RC_ASSERT(k.grid_points_only(D));
  return k;
}

// One call on the points q (its base last): the kernel's stages against its
// integer determinants alone and GMP, and the kernel promised q (on grid
// points) against the kernel without the promise.
template <std::size_t N, std::size_t D, class StagedF, class ExactF, class MpF>
void check_call(const std::array<std::array<std::int64_t, D>, N>& q, StagedF staged, ExactF exact, MpF by_mp,
                FilterTally& tally, FilterTally& on_grid) {
  const auto p = as_doubles(q);
  const auto call = [&](const auto& k, auto f) { return std::apply([&](const auto&... x) { return (k.*f)(x...); }, p); };
  const IntegerKernel unit;  // unit grids
  const Staged s = call(unit, staged);
  RC_ASSERT(s.sign == call(unit, exact));
  RC_ASSERT(s.sign == call(mp, by_mp));
  tally.add(s, rounds(q));
  const Staged g = call(promised(p), staged);
  RC_ASSERT(g.sign == s.sign);
  on_grid.add(g, rounds(q));
}

TEST_CASE("the integer kernel's filter at its edges agrees with its integer determinants and mp",
          "[certificate][integer][rc]") {
  using K = IntegerKernel;
  FilterTally o2, ic, o3, is, on_grid;
  rc::prop("orient2d, incircle, orient3d, insphere on moved degenerate sets", [&] {
    for (int batch = 0; batch < 10; ++batch) {
      auto l = flat_set<3, 2>();
      move_one(l);
      check_call(l, &K::orient2d_staged, &K::orient2d_exact, &GmpKernel::orient2d, o2, on_grid);
      auto c = round_set<4, 2>();
      move_one(c);
      check_call(c, &K::incircle_staged, &K::incircle_exact, &GmpKernel::incircle, ic, on_grid);
      auto f = flat_set<4, 3>();
      move_one(f);
      check_call(f, &K::orient3d_staged, &K::orient3d_exact, &GmpKernel::orient3d, o3, on_grid);
      auto r = round_set<5, 3>();
      move_one(r);
      check_call(r, &K::insphere_staged, &K::insphere_exact, &GmpKernel::insphere, is, on_grid);
    }
  });
  check_filter_reach("orient2d", o2);
  check_filter_reach("incircle", ic);
  check_filter_reach("orient3d", o3);
  check_filter_reach("insphere", is);
  check_filter_reach("on grid points", on_grid);
}

TEST_CASE("every grid index of a double is itself a double (one rounding in the filter)",
          "[certificate][integer][rc]") {
  rc::prop("indices of binade-edge coordinates on grids fitted to binade-edge boxes", [] {
    std::vector<Point3> box{{binade_edge(), binade_edge(), binade_edge()},
                            {binade_edge(), binade_edge(), binade_edge()}};
    const auto k = IntegerKernel::fit<3>(std::span<const Point3>(box));
    for (int t = 0; t < 20; ++t)
      for (int j = 0; j < 3; ++j) {
        const std::int64_t i = k.grid3().index(binade_edge(), j);
        RC_ASSERT(static_cast<std::int64_t>(static_cast<double>(i)) == i);
      }
  });
}

namespace {

// Points base + 2^g c_i, the c_i's coordinates 0, +-1 or at the edge of the
// narrow budget 2^Small - 1 (and a bit or two past it), as doubles: exact,
// |base| <= 2^51 and |2^g c| <= 2^52.
template <std::size_t N, std::size_t D, int Small>
std::array<std::array<std::int64_t, D>, N> narrow_edge_points() {
  const int g = *rc::gen::inRange(0, 52 - (Small + 2) + 1);
  const std::vector<std::int64_t> m{0, 1, (std::int64_t{1} << Small) - 1, std::int64_t{1} << Small,
                                    (std::int64_t{1} << (Small + 1)) + 1, (std::int64_t{1} << (Small + 2)) - 1};
  const std::size_t cap = *rc::gen::inRange<std::size_t>(3, m.size() + 1);  // within the budget at 3
  std::array<std::array<std::int64_t, D>, N> q;
  for (std::size_t j = 0; j < D; ++j) q[N - 1][j] = *rc::gen::inRange(-(std::int64_t{1} << 51), std::int64_t{1} << 51);
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j)
      q[i][j] = q[N - 1][j] + (*rc::gen::arbitrary<bool>() ? 1 : -1) * (m[*rc::gen::inRange<std::size_t>(0, cap)] << g);
  return q;
}

}  // namespace

namespace {

// Which path reduced_sign takes for q: 0 int64 (det<Tiny>), 1 narrow
// (det<Small>), 2 wide (det<B>), -1 none (every point is the base).
template <std::size_t N, std::size_t D>
int reduced_path(const std::array<std::array<std::int64_t, D>, N>& q, int tiny, int small) {
  std::int64_t most = 0, bits = 0;
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j) {
      const std::int64_t x = q[i][j] - q[N - 1][j];
      bits |= x, most = std::max(most, std::abs(x));
    }
  if (bits == 0) return -1;
  most >>= std::countr_zero(static_cast<std::uint64_t>(bits));
  return most < (std::int64_t{1} << tiny) ? 0 : (most < (std::int64_t{1} << small) ? 1 : 2);
}

// The path of reduce()'s magnitude, as reduced_path numbers them.
int width_path(std::uint64_t magnitudes, int tiny, int small) {
  if (magnitudes == 0) return -1;
  const int width = std::bit_width(magnitudes);
  return width <= tiny ? 0 : (width <= small ? 1 : 2);
}

}  // namespace

TEST_CASE("the integer stage's int64 and narrow paths at their budgets' edges agree with mp",
          "[certificate][integer][rc]") {
  // intdet::reduced_sign divides the differences by their largest common power
  // of two and takes det<Tiny> (int64) where every quotient is at most
  // 2^Tiny - 1, det<Small> (__int128) where at most 2^Small - 1: corners of
  // each box and just past it, times 2^g.
  std::array<int, 3> paths{};
  const auto o2det = []<int B>(const auto& q) { return intdet::orient2d<B>(q[0], q[1], q[2]); };
  const auto icdet = []<int B>(const auto& q) { return intdet::incircle<B>(q[0], q[1], q[2], q[3]); };
  const auto o3det = []<int B>(const auto& q) { return intdet::orient3d<B>(q[0], q[1], q[2], q[3]); };
  const auto isdet = []<int B>(const auto& q) { return intdet::insphere<B>(q[0], q[1], q[2], q[3], q[4]); };
  constexpr int tic = intdet::kInt64InCircle, to3 = intdet::kInt64Orient3d, tis = intdet::kInt64InSphere;
  rc::prop("orient2d (Small = Tiny = 30), incircle (30, 14), orient3d (24, 20), insphere (24, 11)", [&] {
    const bool at_tiny = *rc::gen::arbitrary<bool>();
    const auto o2 = narrow_edge_points<3, 2, 30>();
    const auto a = as_doubles(o2);
    RC_ASSERT((intdet::reduced_sign<62, 30, 30>(o2, o2det)) == mp.orient2d(a[0], a[1], a[2]));
    const auto ic = at_tiny ? narrow_edge_points<4, 2, tic>() : narrow_edge_points<4, 2, 30>();
    const auto b = as_doubles(ic);
    RC_ASSERT((intdet::reduced_sign<62, 30, tic>(ic, icdet)) == mp.incircle(b[0], b[1], b[2], b[3]));
    const auto o3 = at_tiny ? narrow_edge_points<4, 3, to3>() : narrow_edge_points<4, 3, 24>();
    const auto c = as_doubles(o3);
    RC_ASSERT((intdet::reduced_sign<62, 24, to3>(o3, o3det)) == mp.orient3d(c[0], c[1], c[2], c[3]));
    const auto is = at_tiny ? narrow_edge_points<5, 3, tis>() : narrow_edge_points<5, 3, 24>();
    const auto d = as_doubles(is);
    RC_ASSERT((intdet::reduced_sign<62, 24, tis>(is, isdet)) == mp.insphere(d[0], d[1], d[2], d[3], d[4]));
    for (const int path : {reduced_path(o3, to3, 24), reduced_path(is, tis, 24)})
      if (path >= 0) ++paths[static_cast<std::size_t>(path)];
    // reduce()'s magnitude is the largest quotient's bit length, which picks the path.
    RC_ASSERT(reduced_path(ic, tic, 30) == width_path(intdet::reduce(ic).magnitudes, tic, 30));
    RC_ASSERT(reduced_path(o3, to3, 24) == width_path(intdet::reduce(o3).magnitudes, to3, 24));
    RC_ASSERT(reduced_path(is, tis, 24) == width_path(intdet::reduce(is).magnitudes, tis, 24));
  });
  CHECK(paths[0] > 10);
  CHECK(paths[1] > 10);
  CHECK(paths[2] > 10);
}

namespace {

// Regular-simplex corners of side 2M around a base (2^g M (+-1, ...) from it):
// the configurations that reach the largest |det| on {-M, 0, M}^D (found by
// search over that set): orient3d 4 M^3 (base and three corners), incircle
// 8 M^4, insphere 48 M^5 (base and four corners).
template <std::size_t N, std::size_t D>
std::array<std::array<std::int64_t, D>, N> corners(std::int64_t m, int g, std::int64_t base) {
  static constexpr int c3[4][3] = {{-1, -1, -1}, {-1, 1, 1}, {1, -1, 1}, {1, 1, -1}};
  static constexpr int o3[3][3] = {{-1, -1, -1}, {-1, -1, 1}, {-1, 1, -1}};
  static constexpr int c2[3][2] = {{-1, -1}, {-1, 1}, {1, -1}};
  std::array<std::array<std::int64_t, D>, N> q;
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j) {
      const int unit = D == 2 ? c2[i][j] : (N == 4 ? o3[i][j] : c3[i][j]);
      q[i][j] = base + unit * (m << g);
    }
  q[N - 1].fill(base);
  return q;
}

using BigInt = boost::multiprecision::mpz_int;

// |det| of the corners, from its closed form, against the capacity 2^bits.
bool fits(BigInt coefficient, std::int64_t m, int degree, int bits) {
  return boost::multiprecision::abs(coefficient * boost::multiprecision::pow(BigInt(m), degree)) <
         boost::multiprecision::pow(BigInt(2), bits);
}

}  // namespace

TEST_CASE("each path of the integer stage takes one binade less than would overflow its type",
          "[certificate][integer]") {
  // reduced_sign's int64 paths (kInt64*) and its __int128 narrow path (Small
  // = 24 in 3D, 30 in 2D) at M = 2^T - 1 (inside) and 2^(T+1) - 1 (outside):
  // the largest determinant of the next binade does not fit the path's type,
  // so a test that admitted it would evaluate it wrongly; both are answered
  // right. (In-circle's corner value still fits int64 one binade out, 8 M^4 <
  // 2^63 at M = 2^15 - 1, so its edge shows two binades out.)
  const auto o3det = []<int B>(const auto& q) { return intdet::orient3d<B>(q[0], q[1], q[2], q[3]); };
  const auto icdet = []<int B>(const auto& q) { return intdet::incircle<B>(q[0], q[1], q[2], q[3]); };
  const auto isdet = []<int B>(const auto& q) { return intdet::insphere<B>(q[0], q[1], q[2], q[3], q[4]); };
  constexpr int tic = intdet::kInt64InCircle, to3 = intdet::kInt64Orient3d, tis = intdet::kInt64InSphere;
  const std::int64_t base = std::int64_t{1} << 40;
  for (const int g : {0, 7}) {
    for (const std::int64_t m : {(std::int64_t{1} << tis) - 1, (std::int64_t{1} << (tis + 1)) - 1,
                                 (std::int64_t{1} << 24) - 1, (std::int64_t{1} << 25) - 1}) {
      const auto q = corners<5, 3>(m, g, base);
      const auto p = as_doubles(q);
      CHECK((intdet::reduced_sign<62, 24, tis>(q, isdet)) == mp.insphere(p[0], p[1], p[2], p[3], p[4]));
    }
    for (const std::int64_t m : {(std::int64_t{1} << to3) - 1, (std::int64_t{1} << (to3 + 1)) - 1}) {
      const auto q = corners<4, 3>(m, g, base);
      const auto p = as_doubles(q);
      CHECK((intdet::reduced_sign<62, 24, to3>(q, o3det)) == mp.orient3d(p[0], p[1], p[2], p[3]));
    }
    for (const std::int64_t m : {(std::int64_t{1} << tic) - 1, (std::int64_t{1} << (tic + 2)) - 1}) {
      const auto q = corners<4, 2>(m, g, base);
      const auto p = as_doubles(q);
      CHECK((intdet::reduced_sign<62, 30, tic>(q, icdet)) == mp.incircle(p[0], p[1], p[2], p[3]));
    }
  }
  // The closed forms' sizes: inside each path's type at 2^T - 1, outside at the next binade.
  CHECK(fits(48, (std::int64_t{1} << tis) - 1, 5, 63));
  CHECK_FALSE(fits(48, (std::int64_t{1} << (tis + 1)) - 1, 5, 63));
  CHECK(fits(48, (std::int64_t{1} << 24) - 1, 5, 127));
  CHECK_FALSE(fits(48, (std::int64_t{1} << 25) - 1, 5, 127));
  CHECK(fits(4, (std::int64_t{1} << to3) - 1, 3, 63));
  CHECK_FALSE(fits(4, (std::int64_t{1} << (to3 + 1)) - 1, 3, 63));
  CHECK(fits(8, (std::int64_t{1} << (tic + 1)) - 1, 4, 63));
  CHECK_FALSE(fits(8, (std::int64_t{1} << (tic + 2)) - 1, 4, 63));
  // And the closed forms are the determinants (wide path, exact).
  const auto q = corners<5, 3>(3, 0, 0);
  CHECK(intdet::insphere<11>(q[0], q[1], q[2], q[3], q[4]) == -48 * 243);
  const auto r = corners<4, 3>(3, 0, 0);
  CHECK(std::abs(static_cast<long long>(intdet::orient3d<20>(r[0], r[1], r[2], r[3]))) == 4 * 27);
  const auto c = corners<4, 2>(3, 0, 0);
  CHECK(std::abs(static_cast<long long>(intdet::incircle<14>(c[0], c[1], c[2], c[3]))) == 8 * 81);
}

TEST_CASE("the integer kernel takes coordinates as they are only for grid points",
          "[certificate][integer]") {
  // (1, 0.4) snaps to (1, 0) on the unit grid: collinear with (0, 0), (2, 0)
  // for the kernel, though the double determinant is positive.
  const std::array<Point2, 3> off{{{0, 0}, {2, 0}, {1, 0.4}}};
  IntegerKernel k;
  k.fit_static_filter(std::span<const Point2>(off));
  CHECK_FALSE(k.grid_points_only(2));
  CHECK(k.orient2d(off[0], off[1], off[2]) == Sign::zero);
  const std::array<Point3, 4> off3{{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 0.4}}};
  k.fit_static_filter(std::span<const Point3>(off3));
  CHECK_FALSE(k.grid_points_only(3));
  CHECK(k.orient3d(off3[0], off3[1], off3[2], off3[3]) == Sign::zero);
  // Fitting the grid anew (snap_all) forgets a promise checked on the unit grid.
  std::vector<Point2> on{{0, 0}, {2, 0}, {1, 1}};
  IntegerKernel fresh;
  fresh.fit_static_filter(std::span<const Point2>(on));
  CHECK(fresh.grid_points_only(2));
  fresh.snap_all(on);
  CHECK_FALSE(fresh.grid_points_only(2));
  // without_static_filter() drops the promise.
  k.fit_static_filter(std::span<const Point2>(on));
  CHECK(k.grid_points_only(2));
  CHECK_FALSE(k.without_static_filter().grid_points_only(2));
}

// ---- perturbed<K>::coplanar_incircle_exact ----

namespace {

using Q = boost::multiprecision::mpq_rational;

// Unoriented in-circle from the definition: the circumcentre o of a, b, c in
// exact rationals (o - a = (|u|^2 v x w + |v|^2 w x u) / (2 |w|^2), u = b - a,
// v = c - a, w = u x v), then sign(|a - o|^2 - |p - o|^2): positive inside.
Sign circumcircle_side(const Point3& a, const Point3& b, const Point3& c, const Point3& p) {
  using V = std::array<Q, 3>;
  auto sub = [](const Point3& x, const Point3& y) {
    return V{Q(x[0]) - Q(y[0]), Q(x[1]) - Q(y[1]), Q(x[2]) - Q(y[2])};
  };
  auto cross = [](const V& x, const V& y) {
    return V{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
  };
  auto dot = [](const V& x, const V& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const V u = sub(b, a), v = sub(c, a), w = cross(u, v);
  const Q ww = dot(w, w);
  RC_ASSERT(ww != 0);  // a, b, c not collinear
  const V vw = cross(v, w), wu = cross(w, u);
  V o;  // relative to a
  for (int i = 0; i < 3; ++i) o[i] = (dot(u, u) * vw[i] + dot(v, v) * wu[i]) / (2 * ww);
  V po = sub(p, a);
  for (int i = 0; i < 3; ++i) po[i] -= o[i];
  const Q diff = dot(o, o) - dot(po, po);
  return diff > 0 ? Sign::positive : (diff < 0 ? Sign::negative : Sign::zero);
}

// Integer similarities of the plane into 3D, (u, v) -> u e1 + v e2 with
// e1 . e2 = 0, |e1| = |e2|: axis-parallel planes (where the integer kernel's
// box is flat) and tilted ones.
const std::vector<std::array<Point3, 2>> planes{
    {{{1, 0, 0}, {0, 1, 0}}}, {{{0, 1, 0}, {0, 0, 1}}}, {{{0, 0, 1}, {1, 0, 0}}},
    {{{1, 2, 2}, {2, 1, -2}}}, {{{2, 3, 6}, {3, -6, 2}}}, {{{3, 4, 0}, {0, 0, 5}}},
    {{{0, 3, 4}, {0, 4, -3}}}};

// Lattice points on x^2 + y^2 = 5^2, 5^4, 65^2 and points off those circles.
Point2 circle_point(int r) {
  static const std::vector<std::array<int, 2>> base{{5, 0}, {3, 4}, {4, 3}};
  static const std::vector<std::array<int, 2>> base25{{25, 0}, {15, 20}, {20, 15}, {7, 24}, {24, 7}};
  static const std::vector<std::array<int, 2>> base65{{65, 0}, {16, 63}, {63, 16}, {25, 60},
                                                      {60, 25}, {33, 56}, {56, 33}, {39, 52}, {52, 39}};
  const auto& set = r == 0 ? base : (r == 1 ? base25 : base65);
  auto q = *rc::gen::elementOf(set);
  if (*rc::gen::arbitrary<bool>()) std::swap(q[0], q[1]);
  return {double(*rc::gen::arbitrary<bool>() ? q[0] : -q[0]),
          double(*rc::gen::arbitrary<bool>() ? q[1] : -q[1])};
}

bool collinear(const Point3& a, const Point3& b, const Point3& c) {
  for (const auto& [i, j] : {std::array<int, 2>{0, 1}, {1, 2}, {0, 2}})
    if (mp.orient2d({a[i], a[j]}, {b[i], b[j]}, {c[i], c[j]}) != Sign::zero) return false;
  return true;
}

// The small-integer path where issue 17 found the defect: the in-sphere with
// the off-plane point perturbed<K> builds (s = a moved along the first axis
// whose projection is non-degenerate by the points' spread) is certified and
// its exact value is zero, so insphere_sos answers with its perturbed sign.
bool reaches_small_integer_walk(const std::array<Point3, 4>& q) {
  int axis = 1;
  for (const auto& [i, j, drop] : {std::array<int, 3>{0, 1, 2}, {1, 2, 0}, {0, 2, 1}})
    if (mp.orient2d({q[0][i], q[0][j]}, {q[1][i], q[1][j]}, {q[2][i], q[2][j]}) != Sign::zero) {
      axis = drop;
      break;
    }
  double w = 0;
  for (int k = 1; k < 4; ++k)
    for (int i = 0; i < 3; ++i) w = std::fmax(w, std::fabs(q[k][i] - q[0][i]));
  Point3 s = q[0];
  s[axis] += w;
  const auto r = small_integer::insphere_sos(q[0], q[1], q[2], s, q[3]);
  return r.known && r.by_perturbation;
}

struct CoplanarTally {
  int calls = 0, zeros = 0, small_integer_walk = 0;
};

template <class K>
void check_coplanar(const perturbed<K>& k, const std::array<Point3, 4>& q) {
  const Sign exact = circumcircle_side(q[0], q[1], q[2], q[3]);
  RC_ASSERT(k.coplanar_incircle_exact(q[0], q[1], q[2], q[3]) == exact);
  if (q[3] != q[0] && q[3] != q[1] && q[3] != q[2]) {
    const Sign s = k.coplanar_incircle(q[0], q[1], q[2], q[3]);
    RC_ASSERT(s == pmp.coplanar_incircle(q[0], q[1], q[2], q[3]));
    if (exact != Sign::zero) RC_ASSERT(s == exact);
  }
}

}  // namespace

TEST_CASE("coplanar_incircle_exact is exact for the adaptive, integer and mp kernels",
          "[certificate][perturbed][rc]") {
  CoplanarTally tally;
  rc::prop("cocircular coplanar points, lattices and binade-edge scales", [&] {
    for (int batch = 0; batch < 10; ++batch) {
      const auto& f = *rc::gen::elementOf(planes);
      const int r = *rc::gen::inRange(0, 3);
      std::array<Point2, 4> q2;
      for (auto& p : q2) p = circle_point(r);
      if (*rc::gen::inRange(0, 3) == 0) q2[3] = {q2[3][0] + *rc::gen::inRange(-2, 3), q2[3][1]};
      if (mp.orient2d(q2[0], q2[1], q2[2]) == Sign::zero) continue;  // a, b, c on a line
      // Scale by 2^s (halves and sixteenths included), translate by +-2^40,
      // +-2^51, +-2^52 or +-1024 where every sum stays exact.
      const int s = *rc::gen::elementOf(std::vector<int>{0, 0, 0, -1, -4, 30, -1000, 900});
      double shift = (*rc::gen::arbitrary<bool>() ? -1 : 1) *
                     *rc::gen::elementOf(std::vector<double>{0, 0x1p51, 0x1p52, 0x1p40, 1024});
      std::array<Point3, 4> q;
      for (int pass = 0; pass < 2; ++pass) {  // no shift where a sum would round
        bool exact = true;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 3; ++j) {
            const double x = std::ldexp(q2[i][0] * f[0][j] + q2[i][1] * f[1][j], s);
            q[i][j] = x + shift;
            exact = exact && q[i][j] - shift == x && q[i][j] - x == shift;
          }
        if (exact) break;
        shift = 0;
      }
      RC_ASSERT(mp.orient3d(q[0], q[1], q[2], q[3]) == Sign::zero);  // the sums were exact
      ++tally.calls;
      tally.zeros += circumcircle_side(q[0], q[1], q[2], q[3]) == Sign::zero;
      tally.small_integer_walk += reaches_small_integer_walk(q);
      check_coplanar(pmp, q);
      check_coplanar(pad, q);
      AdaptiveKernel fitted;
      fitted.fit_static_filter(std::span<const Point3>(q.data(), q.size()));
      check_coplanar(perturbed<AdaptiveKernel>(fitted), q);
      // The integer kernels work on their snapped points (B = 62 moves none of these).
      std::vector<Point3> v(q.begin(), q.end());
      perturbed<IntegerKernel> ki;
      ki.snap_all(v);
      RC_ASSERT(std::equal(v.begin(), v.end(), q.begin()));
      check_coplanar(ki, q);
      std::vector<Point3> w(q.begin(), q.end());
      perturbed<IntegerKernel128> k128;
      k128.snap_all(w);
      if (mp.orient3d(w[0], w[1], w[2], w[3]) == Sign::zero && !collinear(w[0], w[1], w[2]))
        check_coplanar(k128, {w[0], w[1], w[2], w[3]});
    }
  });
  INFO("calls " << tally.calls << ", zeros " << tally.zeros << ", small-integer walk "
                << tally.small_integer_walk);
  CHECK(tally.zeros > tally.calls / 4);
  CHECK(tally.small_integer_walk > tally.calls / 10);
}
