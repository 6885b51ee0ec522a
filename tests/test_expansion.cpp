// Expansion arithmetic (predicates/expansion.hpp; Shewchuk 1997, sections 2-3)
// checked against exact rational arithmetic (GMP through Boost.Multiprecision):
// every primitive is exact, every output is a nonoverlapping expansion in
// increasing magnitude, and its sum is the exact value.
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <random>
#include <rapidcheck/catch.h>
#include <vector>

#include "predicates/expansion.hpp"

using namespace dlab;
using Q = boost::multiprecision::mpq_rational;

namespace {

// Deterministic random double: 53-bit mantissa, sign, exponent in [elo, ehi].
struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double unit() { return static_cast<double>(g() >> 11) * 0x1p-53; }
  double dbl(int elo, int ehi) {
    const int e = elo + static_cast<int>(g() % static_cast<std::uint64_t>(ehi - elo + 1));
    const double m = 1.0 + unit();  // [1, 2)
    return ((g() & 1) ? -1.0 : 1.0) * std::ldexp(m, e);
  }
};

Q exact(const double* e, int n) {
  Q s = 0;
  for (int i = 0; i < n; ++i) s += Q(e[i]);
  return s;
}

// Independent bit inspection (no code shared with the kernel's guard).
int top_bit(double x) { return std::ilogb(x); }
int bottom_bit(double x) {
  int e = std::ilogb(x) - 52;
  double m = std::ldexp(x, -e);  // an integer with at most 53 bits
  while (std::fmod(m, 2.0) == 0.0) {
    m /= 2;
    ++e;
  }
  return e;
}

// Nonzero components, increasing magnitude, pairwise nonoverlapping.
bool nonoverlapping(const double* e, int n) {
  if (n == 1) return true;  // a single component (possibly zero)
  for (int i = 0; i < n; ++i)
    if (e[i] == 0.0) return false;
  for (int i = 0; i + 1 < n; ++i)
    if (!(top_bit(e[i]) < bottom_bit(e[i + 1]))) return false;
  return true;
}

// A random nonoverlapping expansion of up to `len` terms, built by growing.
std::vector<double> random_expansion(Rng& r, int len, int elo, int ehi) {
  std::vector<double> e{0.0}, h(len + 2);
  for (int i = 0; i < len; ++i) {
    const int n = xp::grow_expansion_zeroelim(static_cast<int>(e.size()), e.data(),
                                              r.dbl(elo, ehi), h.data());
    e.assign(h.begin(), h.begin() + n);
  }
  return e;
}

}  // namespace

TEST_CASE("two_sum, two_diff, two_product, two_square are exact", "[expansion]") {
  Rng r(1);
  for (int i = 0; i < 20000; ++i) {
    const int lo = -400 + static_cast<int>(i % 800);
    const double a = r.dbl(lo - 60, lo + 60), b = r.dbl(lo - 60, lo + 60);
    double x, y;
    xp::two_sum(a, b, x, y);
    REQUIRE(x == a + b);
    REQUIRE(Q(x) + Q(y) == Q(a) + Q(b));
    xp::fast_two_sum(std::fabs(a) >= std::fabs(b) ? a : b, std::fabs(a) >= std::fabs(b) ? b : a,
                     x, y);
    REQUIRE(Q(x) + Q(y) == Q(a) + Q(b));
    xp::two_diff(a, b, x, y);
    REQUIRE(x == a - b);
    REQUIRE(Q(x) + Q(y) == Q(a) - Q(b));
    REQUIRE(xp::two_diff_tail(a, b, x) == y);
    xp::two_product(a, b, x, y);
    REQUIRE(x == a * b);
    REQUIRE(Q(x) + Q(y) == Q(a) * Q(b));
    REQUIRE(std::fabs(y) <= std::ldexp(1.0, std::ilogb(x) - 53));  // half an ulp of x
    xp::two_square(a, x, y);
    REQUIRE(Q(x) + Q(y) == Q(a) * Q(a));
  }
}

TEST_CASE("split gives two halves of at most 26 significant bits", "[expansion]") {
  Rng r(2);
  for (int i = 0; i < 20000; ++i) {
    const double a = r.dbl(-300, 300);
    double hi, lo;
    xp::split(a, hi, lo);
    REQUIRE(Q(hi) + Q(lo) == Q(a));
    REQUIRE(top_bit(hi) - bottom_bit(hi) < 26);
    if (lo != 0) REQUIRE(top_bit(lo) - bottom_bit(lo) < 26);
  }
}

TEST_CASE("grow, sum and scale keep exact nonoverlapping expansions", "[expansion]") {
  Rng r(3);
  for (int i = 0; i < 3000; ++i) {
    const int c = -200 + static_cast<int>(i % 400);
    const auto e = random_expansion(r, 1 + static_cast<int>(i % 9), c - 80, c + 80);
    const auto f = random_expansion(r, 1 + static_cast<int>((i / 9) % 7), c - 80, c + 80);
    REQUIRE(nonoverlapping(e.data(), static_cast<int>(e.size())));
    const int en = static_cast<int>(e.size()), fn = static_cast<int>(f.size());

    std::vector<double> h(en + fn);
    const int hn = xp::fast_expansion_sum_zeroelim(en, e.data(), fn, f.data(), h.data());
    REQUIRE(hn <= en + fn);
    REQUIRE(nonoverlapping(h.data(), hn));
    REQUIRE(exact(h.data(), hn) == exact(e.data(), en) + exact(f.data(), fn));

    const double b = r.dbl(c / 4 - 20, c / 4 + 20);
    std::vector<double> s(2 * en);
    const int sn = xp::scale_expansion_zeroelim(en, e.data(), b, s.data());
    REQUIRE(sn <= 2 * en);
    REQUIRE(nonoverlapping(s.data(), sn));
    REQUIRE(exact(s.data(), sn) == exact(e.data(), en) * Q(b));

    // Compress in place: same value, nonoverlapping, largest component close to the value.
    std::vector<double> k = h;
    const int kn = xp::compress(hn, k.data(), k.data());
    REQUIRE(kn <= hn);
    REQUIRE(nonoverlapping(k.data(), kn));
    const Q v = exact(h.data(), hn);
    REQUIRE(exact(k.data(), kn) == v);
    if (v != 0) {
      const Q rel = abs((Q(k[kn - 1]) - v) / v);
      REQUIRE(rel <= Q(std::ldexp(1.0, -51)));
    }

    // Estimate within a few ulps, sign exact.
    const double est = xp::estimate(hn, h.data());
    REQUIRE(xp::sign(hn, h.data()) == (v > 0) - (v < 0));
    if (v != 0) REQUIRE(abs((Q(est) - v) / v) <= Q(std::ldexp(1.0, -50)));
  }
}

TEST_CASE("cancellation to zero gives the one-component zero expansion", "[expansion]") {
  Rng r(4);
  for (int i = 0; i < 200; ++i) {
    const auto e = random_expansion(r, 5, -30, 30);
    std::vector<double> f(e), h(2 * e.size());
    for (double& x : f) x = -x;
    const int n = xp::fast_expansion_sum_zeroelim(static_cast<int>(e.size()), e.data(),
                                                  static_cast<int>(f.size()), f.data(), h.data());
    REQUIRE(n == 1);
    REQUIRE(h[0] == 0.0);
    REQUIRE(xp::sign(n, h.data()) == 0);
  }
}

TEST_CASE("Expansion<N> products are exact and within their capacity", "[expansion]") {
  rc::prop("(a-b)(c-d)(e-f) exact", [](std::int32_t ma, std::int32_t mb, std::int32_t mc,
                                       std::int32_t md, std::int32_t me, std::int32_t mf) {
    // Mantissas scaled apart so the differences have roundoff tails.
    const double a = std::ldexp(static_cast<double>(ma), 30) + 0.75 * mb, b = std::ldexp(mb, -20);
    const double c = std::ldexp(static_cast<double>(mc), 10), d = std::ldexp(md, -40) + 1.0;
    const double e = std::ldexp(static_cast<double>(me), -5), f = std::ldexp(mf, 40);
    const auto x = xp::diff(a, b), y = xp::diff(c, d), z = xp::diff(e, f);
    const auto p = (x * y) * z;
    static_assert(decltype(p)::capacity == 2 * (2 * 2 * 2) * 2);
    RC_ASSERT(p.n <= decltype(p)::capacity);
    RC_ASSERT(nonoverlapping(p.c, p.n));
    RC_ASSERT(exact(p.c, p.n) == (Q(a) - Q(b)) * (Q(c) - Q(d)) * (Q(e) - Q(f)));
    const auto s = p - xp::scale(x * y, e) + xp::scale(x * y, f);  // == 0
    RC_ASSERT(s.sign() == 0);
  });
}
