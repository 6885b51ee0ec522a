// The combinators filtered<>, counted<>, checked<> and the FloatFilter:
//  - filtered<FloatFilter, MpKernel> (the validator's kernel) agrees with MpKernel on random
//    inputs over many exponent ranges, on exact degenerate sets moved by 1..3 ulps, on huge
//    and tiny (subnormal) magnitudes; every answer the filter gives is MpKernel's;
//  - the filter's error bound holds against the exact error (boost mpq) and its orient2d
//    constant matches a hand derivation;
//  - permutation properties (odd flips, even keeps) for every kernel present;
//  - counted<> counts without changing answers, copies share counters, stage names stable;
//  - checked<> records (or throws on) disagreements, and only real ones.
#include <algorithm>
#include <array>
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/checked.hpp"
#include "predicates/counted.hpp"
#include "predicates/filtered.hpp"
#include "predicates/float_filter.hpp"
#include "predicates/float_kernel.hpp"
#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;
using Filtered = filtered<FloatFilter, MpKernel>;

struct Rng {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  int range(int lo, int hi) { return lo + below(hi - lo + 1); }
  double unit() { return static_cast<double>(next() >> 11) * 0x1p-53 * 2 - 1; }  // [-1, 1)
};

double ulps(double x, int k) {
  const double dir = k > 0 ? std::numeric_limits<double>::infinity()
                           : -std::numeric_limits<double>::infinity();
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, dir);
  return x;
}

// N points of dimension D, drawn from one of several families; `family` picks it.
template <int D, std::size_t N>
std::array<Point<D>, N> sample(Rng& rng, int family) {
  std::array<Point<D>, N> p{};
  if (family == 3) {  // anisotropic: a degenerate family scaled by a different 2^k per axis
    p = sample<D, N>(rng, 1 + rng.below(2));
    for (int i = 0; i < D; ++i) {
      const int e = rng.range(-300, 300);
      // Predicates take finite coordinates: an axis that would overflow keeps its scale.
      bool finite = true;
      for (const auto& q : p) finite = finite && std::isfinite(std::ldexp(q[i], e));
      if (finite)
        for (auto& q : p) q[i] = std::ldexp(q[i], e);
    }
    return p;
  }
  switch (family) {
    case 0: {  // random, one exponent range per call, sometimes translated far away
      static constexpr int exps[] = {-1060, -1000, -600, -300, -100, -20, 0, 20, 100, 300, 600, 900};
      const int e = exps[rng.below(static_cast<int>(std::size(exps)))];
      const double shift = rng.below(3) == 0 ? std::ldexp(rng.unit(), e + 30) : 0.0;
      for (auto& q : p)
        for (auto& x : q) x = std::ldexp(rng.unit(), e) + shift;
      break;
    }
    case 1: {  // exactly affinely degenerate (collinear / coplanar): o + s v + t w, integers
      Point<D> o, v, w;
      for (int i = 0; i < D; ++i) {
        o[i] = rng.range(-1000, 1000);
        v[i] = rng.range(-9, 9);
        w[i] = rng.range(-9, 9);
      }
      for (auto& q : p) {
        const int s = rng.range(-50, 50), t = D == 3 ? rng.range(-50, 50) : 0;
        for (int i = 0; i < D; ++i) q[i] = o[i] + s * v[i] + t * w[i];
      }
      break;
    }
    default: {  // exactly cocircular / cospherical: Pythagorean points around an integer centre
      static constexpr int c2[][2] = {{3, 4}, {4, 3}, {5, 0}, {0, 5}, {7, 24}, {24, 7}, {15, 20}, {20, 15}, {25, 0}, {0, 25}};
      static constexpr int c3[][3] = {{1, 2, 2}, {2, 1, 2}, {2, 2, 1}, {3, 0, 0}, {0, 3, 0}, {0, 0, 3}};
      const int radius_scale = rng.below(2) ? 1 : 5;  // 2D: radius 5 or 25
      Point<D> o;
      for (auto& x : o) x = rng.range(-1000, 1000);
      for (auto& q : p) {
        if constexpr (D == 2) {
          const int k = radius_scale == 1 ? rng.below(4) : 4 + rng.below(6);
          const int sx = rng.below(2) ? 1 : -1, sy = rng.below(2) ? 1 : -1;
          q = {o[0] + sx * c2[k][0], o[1] + sy * c2[k][1]};
        } else {
          const int k = rng.below(6);
          const int sx = rng.below(2) ? 1 : -1, sy = rng.below(2) ? 1 : -1, sz = rng.below(2) ? 1 : -1;
          q = {o[0] + sx * c3[k][0], o[1] + sy * c3[k][1], o[2] + sz * c3[k][2]};
        }
      }
      break;
    }
  }
  if (family != 0) {
    // Scale by a power of two (exact), then sometimes move a few coordinates by 1..3 ulps.
    static constexpr int scales[] = {-1070, -1040, -500, -60, 0, 0, 0, 40, 500, 1000};
    const int e = scales[rng.below(static_cast<int>(std::size(scales)))];
    for (auto& q : p)
      for (auto& x : q) x = std::ldexp(x, e);
    if (rng.below(2))
      for (int m = rng.range(1, 2); m > 0; --m) {
        auto& x = p[rng.below(static_cast<int>(N))][rng.below(D)];
        x = ulps(x, rng.range(-3, 3));
      }
  }
  return p;
}

template <class P, std::size_t N>
bool distinct(const std::array<P, N>& p) {
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = i + 1; j < N; ++j)
      if (p[i] == p[j]) return false;
  return true;
}

int parity(const std::vector<int>& perm) {
  int inv = 0;
  for (std::size_t i = 0; i < perm.size(); ++i)
    for (std::size_t j = i + 1; j < perm.size(); ++j) inv += perm[i] > perm[j];
  return inv % 2 ? -1 : 1;
}

template <class K, std::size_t D, std::size_t N>
Sign ask(const K& k, const std::array<std::array<double, D>, N>& p) {
  if constexpr (D == 2 && N == 3) return k.orient2d(p[0], p[1], p[2]);
  if constexpr (D == 2 && N == 4) return k.incircle(p[0], p[1], p[2], p[3]);
  if constexpr (D == 3 && N == 4) return k.orient3d(p[0], p[1], p[2], p[3]);
  if constexpr (D == 3 && N == 5) return k.insphere(p[0], p[1], p[2], p[3], p[4]);
}

template <class K, std::size_t D, std::size_t N>
void check_permutations(const K& k, const std::array<std::array<double, D>, N>& p) {
  const Sign s = ask(k, p);
  std::vector<int> perm(N);
  for (std::size_t i = 0; i < N; ++i) perm[i] = static_cast<int>(i);
  while (std::next_permutation(perm.begin(), perm.end())) {
    std::array<std::array<double, D>, N> q;
    for (std::size_t i = 0; i < N; ++i) q[i] = p[perm[i]];
    const Sign t = ask(k, q);
    if (t != (parity(perm) > 0 ? s : -s)) {
      FAIL_CHECK("permutation property fails for " << K::name);
      return;
    }
  }
}

}  // namespace

TEST_CASE("filtered<FloatFilter, MpKernel> is exact; every filter answer is MpKernel's", "[filtered]") {
  const MpKernel mp;
  const FloatFilter ff;
  const Filtered k;
  Rng rng{11};
  std::array<int, 4> decided{}, asked{};
  for (int t = 0; t < 4000; ++t) {
    const int family = t % 4;
    const auto a = sample<2, 3>(rng, family);
    const auto b = sample<2, 4>(rng, family);
    const auto c = sample<3, 4>(rng, family);
    const auto d = sample<3, 5>(rng, family);
    const Sign s1 = mp.orient2d(a[0], a[1], a[2]);
    const Sign s2 = mp.incircle(b[0], b[1], b[2], b[3]);
    const Sign s3 = mp.orient3d(c[0], c[1], c[2], c[3]);
    const Sign s4 = mp.insphere(d[0], d[1], d[2], d[3], d[4]);
    REQUIRE(k.orient2d(a[0], a[1], a[2]) == s1);
    REQUIRE(k.incircle(b[0], b[1], b[2], b[3]) == s2);
    REQUIRE(k.orient3d(c[0], c[1], c[2], c[3]) == s3);
    REQUIRE(k.insphere(d[0], d[1], d[2], d[3], d[4]) == s4);
    const auto f1 = ff.orient2d(a[0], a[1], a[2]);
    const auto f2 = ff.incircle(b[0], b[1], b[2], b[3]);
    const auto f3 = ff.orient3d(c[0], c[1], c[2], c[3]);
    const auto f4 = ff.insphere(d[0], d[1], d[2], d[3], d[4]);
    if (f1) REQUIRE(*f1 == s1);
    if (f2) REQUIRE(*f2 == s2);
    if (f3) REQUIRE(*f3 == s3);
    if (f4) REQUIRE(*f4 == s4);
    asked[family] += 4;
    decided[family] += bool(f1) + bool(f2) + bool(f3) + bool(f4);
  }
  INFO("filter decided " << decided[0] << "/" << asked[0] << " random, " << decided[1] << "/"
                         << asked[1] << " flat, " << decided[2] << "/" << asked[2] << " cocircular, "
                         << decided[3] << "/" << asked[3] << " anisotropic");
  // Out-of-range exponents (about half of the random family's calls) decline by design.
  CHECK(decided[0] > asked[0] / 3);
  // Exact degeneracies (not moved by ulps) must reach the exact stage or the M = 0 shortcut.
  CHECK(decided[1] < asked[1]);
}

TEST_CASE("filtered<FloatFilter, MpKernel> on small lattices moved by ulps (RapidCheck)",
          "[filtered]") {
  rc::prop("filtered == mp for all four predicates", [] {
    const int e = *rc::gen::inRange(-1070, 1000);
    const auto c = *rc::gen::container<std::vector<int>>(15, rc::gen::inRange(-8, 9));
    const auto m = *rc::gen::container<std::vector<int>>(15, rc::gen::inRange(-2, 3));
    double x[15];
    for (int i = 0; i < 15; ++i) x[i] = ulps(std::ldexp(static_cast<double>(c[i]), e), m[i]);
    const Point2 a{x[0], x[1]}, b{x[2], x[3]}, cc{x[4], x[5]}, d{x[6], x[7]};
    const Point3 p{x[0], x[1], x[2]}, q{x[3], x[4], x[5]}, r{x[6], x[7], x[8]}, s{x[9], x[10], x[11]},
        t{x[12], x[13], x[14]};
    const Filtered k;
    const MpKernel mp;
    RC_ASSERT(k.orient2d(a, b, cc) == mp.orient2d(a, b, cc));
    RC_ASSERT(k.incircle(a, b, cc, d) == mp.incircle(a, b, cc, d));
    RC_ASSERT(k.orient3d(p, q, r, s) == mp.orient3d(p, q, r, s));
    RC_ASSERT(k.insphere(p, q, r, s, t) == mp.insphere(p, q, r, s, t));
  });
}

TEST_CASE("FloatFilter decides almost every random call", "[filtered]") {
  const FloatFilter f;
  Rng rng{17};
  int decided = 0;
  const int n = 4000;
  for (int t = 0; t < n / 4; ++t) {
    Point3 p[5];
    for (auto& q : p)
      for (auto& x : q) x = rng.unit();
    decided += f.orient2d({p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]}).has_value();
    decided += f.incircle({p[0][0], p[0][1]}, {p[1][0], p[1][1]}, {p[2][0], p[2][1]},
                          {p[3][0], p[3][1]}).has_value();
    decided += f.orient3d(p[0], p[1], p[2], p[3]).has_value();
    decided += f.insphere(p[0], p[1], p[2], p[3], p[4]).has_value();
  }
  INFO("decided " << decided << " of " << n);
  CHECK(decided > n * 99 / 100);
}

TEST_CASE("FloatFilter error bound holds against the exact error", "[filtered]") {
  using namespace filter_bound;
  Rng rng{12};
  double worst = 0;  // largest |det~ - det| / bound seen
  auto ratio = [&](double approx, const Q& exact, double bound) {
    const Q err = abs(Q(approx) - exact);
    const double r = static_cast<double>(err / Q(bound));
    worst = std::max(worst, r);
    return r;
  };
  for (int t = 0; t < 3000; ++t) {
    const int family = 1 + t % 3;  // near-degenerate: the error matters most there
    const auto b = sample<2, 4>(rng, family);
    double mx = 0, my = 0;
    for (int i = 0; i < 3; ++i) {
      mx = std::max(mx, std::fabs(b[i][0] - b[3][0]));
      my = std::max(my, std::fabs(b[i][1] - b[3][1]));
    }
    if (classify(mx, incircle_spec) == Range::ok && classify(my, incircle_spec) == Range::ok) {
      const double mm = std::max(mx, my);
      const double bound = incircle_spec.c * mx * my * mm * mm;
      REQUIRE(ratio(det::incircle<double>(b[0], b[1], b[2], b[3]),
                    det::incircle<Q>(b[0], b[1], b[2], b[3]), bound) <= 1);
    }
    const auto d = sample<3, 5>(rng, family);
    double m[3] = {0, 0, 0};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 3; ++j) m[j] = std::max(m[j], std::fabs(d[i][j] - d[4][j]));
    if (classify(m[0], insphere_spec) == Range::ok && classify(m[1], insphere_spec) == Range::ok &&
        classify(m[2], insphere_spec) == Range::ok) {
      const double mm = std::max({m[0], m[1], m[2]});
      const double bound = insphere_spec.c * m[0] * m[1] * m[2] * mm * mm;
      REQUIRE(ratio(det::insphere<double>(d[0], d[1], d[2], d[3], d[4]),
                    det::insphere<Q>(d[0], d[1], d[2], d[3], d[4]), bound) <= 1);
    }
  }
  INFO("worst error / bound = " << worst);
  CHECK(worst <= 1);
}

TEST_CASE("FloatFilter constants: orient2d by hand", "[filtered]") {
  // acx, bcy: m = 1, e = u. Product: m = 1 + 2u, e = 2u(1) + 1*u + (1 + u)u = 4u + u^2.
  // Difference of two products: e = u (2 (1 + 2u)) + 2 (4u + u^2) = 10u + 6u^2.
  const double u = 0x1p-53;
  const double hand = 10 * u + 6 * u * u;
  CHECK(filter_bound::orient2d_spec.c >= hand);
  CHECK(filter_bound::orient2d_spec.c <= hand * (1 + 0x1p-39));
}

TEST_CASE("FloatFilter: exact zero shortcut and refusals", "[filtered]") {
  const FloatFilter f;
  // All x equal: every monomial has an x-difference factor, so exactly zero.
  CHECK(f.orient2d({3, 0}, {3, 1e300}, {3, -7}) == Sign::zero);
  CHECK(f.orient3d({0, 0, 1}, {1, 0, 1}, {0, 5, 1}, {2, 2, 1}) == Sign::zero);
  // Exactly cocircular unit square: the double determinant is 0, the filter must refuse.
  CHECK_FALSE(f.incircle({0, 0}, {1, 0}, {1, 1}, {0, 1}).has_value());
  // Out of range magnitudes refuse rather than risk underflow / overflow.
  CHECK_FALSE(f.orient2d({0, 0}, {1e-160, 0}, {0, 1e-160}).has_value());
  CHECK_FALSE(f.insphere({0, 0, 0}, {1e70, 0, 0}, {0, 1e70, 0}, {0, 0, 1e70}, {1, 1, 1}).has_value());
  // The guards' edges: M = lo decides, just below lo declines; M = hi decides, above declines.
  const double lo = filter_bound::orient2d_spec.lo, hi = filter_bound::orient2d_spec.hi;
  CHECK(f.orient2d({0, 0}, {lo, 0}, {0, lo}) == Sign::positive);
  CHECK_FALSE(f.orient2d({0, 0}, {lo / 2, 0}, {0, lo}).has_value());
  CHECK(f.orient2d({0, 0}, {hi, 0}, {0, hi}) == Sign::positive);
  CHECK_FALSE(f.orient2d({0, 0}, {2 * hi, 0}, {0, hi}).has_value());
  // A difference that overflows declines (and filtered<> still answers exactly).
  CHECK_FALSE(f.orient2d({-1e308, 0}, {1e308, 1}, {0, 2}).has_value());
  CHECK(Filtered{}.orient2d({-1e308, 0}, {1e308, 1}, {0, 2}) ==
        MpKernel{}.orient2d({-1e308, 0}, {1e308, 1}, {0, 2}));
  // Clear cases are decided.
  CHECK(f.orient2d({0, 0}, {1, 0}, {0, 1}) == Sign::positive);
  CHECK(f.insphere({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}, {0.2, 0.2, -0.2}) == Sign::positive);
}

TEMPLATE_TEST_CASE("permutations: odd flip, even keep; exact kernels agree with mp", "[permutation]",
                   MpKernel, Filtered, perturbed<MpKernel>, AdaptiveKernel, perturbed<Filtered>,
                   counted<perturbed<Filtered>>) {
  const TestType k{};
  const MpKernel mp;
  Rng rng{13};
  for (int t = 0; t < 150; ++t) {
    const int family = t % 3;
    const auto a = sample<2, 3>(rng, family);
    const auto b = sample<2, 4>(rng, family);
    const auto c = sample<3, 4>(rng, family);
    const auto d = sample<3, 5>(rng, family);
    // Symbolic perturbation orders the points: it needs distinct points (duplicates
    // would take their rank from their argument position).
    constexpr bool symbolic = is_symbolic<TestType>();
    if (!symbolic || distinct(a)) check_permutations(k, a);
    if (!symbolic || distinct(b)) check_permutations(k, b);
    if (!symbolic || distinct(c)) check_permutations(k, c);
    if (!symbolic || distinct(d)) check_permutations(k, d);
    const Sign sb = mp.incircle(b[0], b[1], b[2], b[3]);
    const Sign sd = mp.insphere(d[0], d[1], d[2], d[3], d[4]);
    CHECK(ask(k, a) == mp.orient2d(a[0], a[1], a[2]));  // orientation: never perturbed
    CHECK(ask(k, c) == mp.orient3d(c[0], c[1], c[2], c[3]));
    if (sb != Sign::zero) CHECK(ask(k, b) == sb);
    if (sd != Sign::zero) CHECK(ask(k, d) == sd);
  }
}

TEST_CASE("permutations and mp agreement for the integer kernel on its snapped points",
          "[permutation][integer]") {
  const MpKernel mp;
  Rng rng{14};
  for (int t = 0; t < 150; ++t) {
    const int family = t % 3;
    auto b = sample<2, 4>(rng, family);
    auto d = sample<3, 5>(rng, family);
    std::vector<Point2> v2(b.begin(), b.end());
    std::vector<Point3> v3(d.begin(), d.end());
    IntegerKernel k;
    k.snap_all(v2);
    k.snap_all(v3);
    std::copy(v2.begin(), v2.end(), b.begin());
    std::copy(v3.begin(), v3.end(), d.begin());
    check_permutations(k, b);
    check_permutations(k, d);
    const std::array<Point2, 3> a{b[0], b[1], b[2]};
    const std::array<Point3, 4> c{d[0], d[1], d[2], d[3]};
    check_permutations(k, a);
    check_permutations(k, c);
    CHECK(ask(k, a) == mp.orient2d(a[0], a[1], a[2]));
    CHECK(ask(k, b) == mp.incircle(b[0], b[1], b[2], b[3]));
    CHECK(ask(k, c) == mp.orient3d(c[0], c[1], c[2], c[3]));
    CHECK(ask(k, d) == mp.insphere(d[0], d[1], d[2], d[3], d[4]));
  }
}

TEST_CASE("counted<K> counts calls and stages without changing answers", "[counted]") {
  using K = counted<Filtered>;
  const K k;
  const K copy = k;  // copies count into the same counters
  const Filtered plain;
  const Point2 a{0, 0}, b{1, 0}, c{1, 1}, d{0, 1};
  CHECK(k.incircle(a, b, c, d) == Sign::zero);        // cocircular: the filter refuses
  CHECK(copy.incircle(a, b, c, {0.5, 0.5}) == Sign::positive);  // clear: the filter decides
  CHECK(k.orient2d(a, b, c) == Sign::positive);
  CHECK(k.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1}) == Sign::positive);
  const Counters got = copy.counters();
  const Counters want{{"orient2d", 1},    {"orient2d.filter", 1}, {"orient2d.exact", 0},
                      {"incircle", 2},    {"incircle.filter", 1}, {"incircle.exact", 1},
                      {"orient3d", 1},    {"orient3d.filter", 1}, {"orient3d.exact", 0},
                      {"insphere", 0},    {"insphere.filter", 0}, {"insphere.exact", 0}};
  CHECK(got == want);

  // Random and degenerate inputs: same answers as the uncounted kernel; stages sum to calls.
  k.reset();
  Rng rng{15};
  for (int t = 0; t < 300; ++t) {
    const auto p = sample<2, 4>(rng, t % 3);
    const auto q = sample<3, 5>(rng, t % 3);
    REQUIRE(k.incircle(p[0], p[1], p[2], p[3]) == plain.incircle(p[0], p[1], p[2], p[3]));
    REQUIRE(k.insphere(q[0], q[1], q[2], q[3], q[4]) == plain.insphere(q[0], q[1], q[2], q[3], q[4]));
  }
  const Counters after = k.counters();
  CHECK(after[3] == std::pair<std::string, std::uint64_t>{"incircle", 300});
  CHECK(after[4].second + after[5].second == 300);
  CHECK(after[9] == std::pair<std::string, std::uint64_t>{"insphere", 300});
  CHECK(after[10].second + after[11].second == 300);
  CHECK(after[5].second > 0);   // some degenerate ones reached the exact stage
  CHECK(after[4].second > 0);
}

TEST_CASE("counted<> names for unstaged, perturbed and adaptive kernels", "[counted]") {
  auto names = [](const Counters& c) {
    std::vector<std::string> n;
    for (const auto& [name, value] : c) n.push_back(name);
    return n;
  };
  CHECK(names(counted<MpKernel>{}.counters()) ==
        std::vector<std::string>{"orient2d", "incircle", "orient3d", "insphere"});
  const counted<perturbed<MpKernel>> pm;
  CHECK(names(pm.counters()) ==
        std::vector<std::string>{"orient2d", "orient2d.mp", "orient2d.perturbation",
                                 "incircle", "incircle.mp", "incircle.perturbation",
                                 "orient3d", "orient3d.mp", "orient3d.perturbation",
                                 "insphere", "insphere.mp", "insphere.perturbation",
                                 "coplanar_orientation", "coplanar_incircle"});
  // The perturbation stage counts exactly the exact-zero in-circle tests.
  // Unit square: c = (1,1) is the largest point, so the answer is orient2d(a, b, d) > 0.
  CHECK(pm.incircle({0, 0}, {1, 0}, {1, 1}, {0, 1}) == Sign::positive);
  CHECK(pm.incircle({0, 0}, {1, 0}, {0, 1}, {0.25, 0.25}) == Sign::positive);
  CHECK(pm.coplanar_incircle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}) == Sign::positive);
  const Counters c = pm.counters();
  CHECK(c[3].second == 2);
  CHECK(c[4].second == 1);  // mp decided one
  CHECK(c[5].second == 1);  // the perturbation decided the other
  CHECK(c[13].second == 1);
  const counted<AdaptiveKernel> ad;
  CHECK(names(ad.counters())[1] == "orient2d.filter");
  CHECK(ad.counters().size() == 4 * (1 + AdaptiveKernel::stage_names.size()));
  // counted<> forwards snapping, so a counted integer kernel snaps as the kernel does.
  static_assert(SnappingKernel<counted<IntegerKernel>, 2>);
  static_assert(SnappingKernel<counted<perturbed<IntegerKernel>>, 3>);
  static_assert(!SnappingKernel<counted<perturbed<MpKernel>>, 2>);
  static_assert(Kernel2<counted<perturbed<Filtered>>> && Kernel3<counted<perturbed<Filtered>>>);
}

TEST_CASE("checked<> records only real disagreements and can throw", "[checked]") {
  // Kettner et al.'s near-collinear points: float gets some of these wrong.
  checked<FloatKernel, MpKernel> k;
  const checked<FloatKernel, MpKernel> copy = k;
  const MpKernel mp;
  const FloatKernel fl;
  const Point2 q{12, 12}, r{24, 24};
  for (int x = 0; x < 64; ++x)
    for (int y = 0; y < 64; ++y) {
      const Point2 p{0.5 + std::ldexp(x, -53), 0.5 + std::ldexp(y, -53)};
      CHECK(copy.orient2d(p, q, r) == fl.orient2d(p, q, r));  // answers are the first kernel's
    }
  CHECK(k.checks() == 64 * 64);
  REQUIRE(k.disagreements() > 0);
  for (const Disagreement& d : k.log->kept) {
    REQUIRE(d.coords.size() == 6);
    const Point2 a{d.coords[0], d.coords[1]}, b{d.coords[2], d.coords[3]}, c{d.coords[4], d.coords[5]};
    CHECK(d.first == fl.orient2d(a, b, c));
    CHECK(d.second == mp.orient2d(a, b, c));
    CHECK(d.first != d.second);
  }
  // Two exact kernels never disagree.
  checked<MpKernel, Filtered> exact;
  Rng rng{16};
  for (int t = 0; t < 300; ++t) {
    const auto p = sample<3, 5>(rng, t % 3);
    exact.insphere(p[0], p[1], p[2], p[3], p[4]);
    exact.orient3d(p[0], p[1], p[2], p[3]);
  }
  CHECK(exact.checks() == 600);
  CHECK(exact.disagreements() == 0);
  // Throwing policy.
  checked<FloatKernel, MpKernel> strict{{}, {}, checked<FloatKernel, MpKernel>::Policy::throw_on_disagreement};
  const Disagreement& first = k.log->kept.front();
  CHECK_THROWS_AS(strict.orient2d({first.coords[0], first.coords[1]}, {first.coords[2], first.coords[3]},
                                  {first.coords[4], first.coords[5]}),
                  KernelDisagreement);
  CHECK(first.describe().rfind("orient2d 0x", 0) == 0);
}
