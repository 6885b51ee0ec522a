// algorithms/pencil_parameter.hpp: the plain-double upper bound T of the
// pencil parameter t* = (|e|^2 + 2 e.g) / (2 n.e), e = x - q, checked in
// rational arithmetic against t* for every choice of g and n at the corners
// of their enclosures:
//   * the enclosures' widths at the edge of the bound: small integers (every
//     rounding exact) with widths that make the error of N and of b exactly
//     the bound's terms, where the bound is within 2% of the largest error;
//   * point enclosures of small integers, where only the quotient rounds;
//   * roundings: random doubles with N and n.e cancelling, on every scale
//     from 2^-1060 (subnormal differences, underflowing products) to 2^500;
//   * no answer on overflow, NaN, |b| < 2^-900 or |b| <= 2 Δb.
// Mutations of the bound that these tests catch: either width term halved;
// ΔN's or Δb's rounding terms dropped; |b| - Δb replaced by |b|; the guard
// |b| > 2 Δb weakened to |b| > Δb; the absolute terms dropped. Not caught:
// the rounding terms halved (γk are worst cases; the largest error seen
// under cancellation was a third of the bound), and u'|t| or the upward
// rounding of t + Δt dropped (b's rounding term, at least 4u|t|, covers them
// in every case here).
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>

#include "algorithms/pencil_parameter.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;

template <int D>
struct Case {
  std::array<double, D> x{}, q{};
  std::array<Iv, D> g{}, n{};
};

// The largest t* over g, n at the corners of their enclosures (t* is a
// rational function of each coordinate of g and n of degree one in the
// numerator or the denominator, monotone between poles; the cases below keep
// n.e away from zero, so its extremes are at corners), or nullopt when some
// corner gives n.e = 0.
template <int D>
std::optional<Q> largest_exact(const Case<D>& c) {
  std::optional<Q> best;
  for (unsigned m = 0; m < (1u << (2 * D)); ++m) {
    Q num = 0, den = 0;
    for (int i = 0; i < D; ++i) {
      const Q e = Q(c.x[i]) - Q(c.q[i]);
      const Q g = Q((m >> i) & 1 ? c.g[i].lo : c.g[i].hi);
      const Q n = Q((m >> (D + i)) & 1 ? c.n[i].lo : c.n[i].hi);
      num += e * e + 2 * e * g;
      den += n * e;
    }
    if (den == 0) return std::nullopt;
    const Q t = num / (2 * den);
    if (!best || t > *best) best = t;
  }
  return best;
}

// N / b from the upper ends, exactly (the value the double evaluation rounds).
template <int D>
Q centre_exact(const Case<D>& c) {
  Q num = 0, den = 0;
  for (int i = 0; i < D; ++i) {
    const Q e = Q(c.x[i]) - Q(c.q[i]);
    num += e * e + 2 * e * Q(c.g[i].hi);
    den += Q(c.n[i].hi) * e;
  }
  return num / (2 * den);
}

// x, q, g and n of integers in [-bound, bound], point enclosures.
template <int D>
Case<D> small_integer_case(std::mt19937_64& rng, int bound) {
  std::uniform_int_distribution<int> small(-bound, bound);
  Case<D> c;
  for (int i = 0; i < D; ++i) {
    c.x[i] = small(rng);
    c.q[i] = small(rng);
    c.g[i] = Iv::exact(small(rng));
    c.n[i] = Iv::exact(small(rng));
  }
  return c;
}

}  // namespace

TEST_CASE("pencil parameter: the widths' terms are tight on exact data", "[pencil_parameter]") {
  // Integers x, q, g.hi, n.hi in [-8, 8]: e, N and b are exact, so T - N/b is
  // the bound Δt but for the slacks. Widths: g's such that |N* - N| reaches
  // ΔN = 2 Σ|e| ρg where every e has one sign (the corner g = g.lo), from
  // dominant to small; n's a fraction beta of |b|/2 spread over the axes, so
  // that Δb = beta |b|. Where t > 0 the largest error is then the bound
  // (ΔN + |t| Δb) / (|b| - Δb) itself.
  std::mt19937_64 rng(20261128);
  double worst_ratio = 0;  // largest (t* - N/b) / (T - N/b) seen
  int answered = 0, tries = 0;
  // beta > 1/2: Δb > |b| / 2, where the bound does not apply: no answer.
  for (double beta : {0.25, 0.45, 0.49, 0.499, 0.6, 0.9}) {
    for (int trial = 0; trial < 400; ++trial) {
      Case<3> c = small_integer_case<3>(rng, 8);
      double b = 0, se = 0;
      for (int i = 0; i < 3; ++i) b += 2 * c.n[i].hi * (c.x[i] - c.q[i]), se += std::fabs(c.x[i] - c.q[i]);
      if (b == 0) continue;
      // Δb = 2 Σ|e| ρn = beta |b| with ρn the same on every axis: ρn = beta |b| / (2 se),
      // rounded down to a dyadic of 20 bits so that n.hi - ρn is exact.
      const double rho_n = std::ldexp(std::floor(std::ldexp(beta * std::fabs(b) / (2 * se), 20)), -20);
      const double rho_g = std::ldexp(1.0, 6 - trial % 12);  // sG from dominant to small
      for (int i = 0; i < 3; ++i) {
        c.n[i].lo = c.n[i].hi - rho_n;
        c.g[i].lo = c.g[i].hi - rho_g;
      }
      const std::optional<double> T = pencil_parameter_upper<3>(c.x, c.q, c.g, c.n);
      if (beta > 0.5) {
        CHECK(!T);
        continue;
      }
      ++tries;
      if (!T) continue;
      ++answered;
      const std::optional<Q> top = largest_exact<3>(c);
      REQUIRE(top);
      INFO("trial " << trial << " beta " << beta);
      REQUIRE(Q(*T) >= *top);
      const Q mid = centre_exact<3>(c);
      if (Q(*T) > mid && *top > mid)
        worst_ratio = std::max(worst_ratio, static_cast<double>((*top - mid) / (Q(*T) - mid)));
    }
  }
  CHECK(answered > tries * 9 / 10);
  // The bound is reached to within 2%: halving ΔN's width term or Δb's, or
  // dividing by |b| instead of |b| - Δb, makes T smaller than t* above.
  CHECK(worst_ratio > 0.98);
  CHECK(worst_ratio <= 1.0);
}

TEST_CASE("pencil parameter: point enclosures, only the quotient rounded", "[pencil_parameter]") {
  // Small integers and point enclosures: N and b are exact, t* = N / b, and
  // only fl(N / b) errs (half the time downwards), and n.e = 0 gives no
  // answer. (The bound's u'|t| and the upward rounding of t + Δt are there for
  // the quotient's and the sum's roundings; its rounding term for b, at
  // least 4u |t|, leaves room for both here and in every case above, so
  // dropping them is not caught.)
  std::mt19937_64 rng(53);
  int rounded_down = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Case<2> c = small_integer_case<2>(rng, 1000);
    const std::optional<double> T = pencil_parameter_upper<2>(c.x, c.q, c.g, c.n);
    const std::optional<Q> top = largest_exact<2>(c);
    if (!top) {
      CHECK(!T);  // n.e = 0
      continue;
    }
    REQUIRE(T);
    REQUIRE(Q(*T) >= *top);
    rounded_down += Q(static_cast<double>(*top)) < *top;
  }
  CHECK(rounded_down > 500);
}

namespace {

// A double with a random 53-bit significand and binary exponent in [lo, hi].
double random_double(std::mt19937_64& rng, int lo, int hi) {
  std::uniform_int_distribution<int> ex(lo, hi);
  const double m = 1.0 + std::ldexp(static_cast<double>(rng() >> 12), -52);
  return ((rng() & 1) ? -1.0 : 1.0) * std::ldexp(m, ex(rng));
}

// An enclosure of v: a point, or v widened by k ulps on each side (k random in 1..4).
Iv around(std::mt19937_64& rng, double v) {
  switch (rng() % 3) {
    case 0:
      return Iv::exact(v);
    default: {
      double lo = v, hi = v;
      for (int k = static_cast<int>(rng() % 4); k >= 0; --k) lo = Iv::down(lo), hi = Iv::up(hi);
      return {lo, hi};
    }
  }
}

// x, q near each other at scale 2^s (e about 2^(s - d)), g nearly -e/2 (so N
// cancels) or random, n nearly orthogonal to e (so n.e cancels to 2^-20 to
// 2^-53 of its terms) or random.
template <int D>
Case<D> cancelling_case(std::mt19937_64& rng, int s, int d) {
  Case<D> c;
  std::array<double, D> e{};
  for (int i = 0; i < D; ++i) {
    c.q[i] = random_double(rng, s - 2, s);
    c.x[i] = c.q[i] + random_double(rng, s - d - 2, s - d);
    e[i] = c.x[i] - c.q[i];
  }
  const bool cancel_n = rng() % 2, cancel_g = rng() % 2;
  for (int i = 0; i < D; ++i) {
    const double gi = cancel_g ? -e[i] / 2 * (1 + std::ldexp(static_cast<double>(rng() % 64), -50))
                               : random_double(rng, s - d - 2, s - d + 2);
    c.g[i] = around(rng, gi);
  }
  // n: random, then (cancel_n) its component along e nearly removed.
  std::array<double, D> n{};
  double ee = 0, ne = 0;
  // |n| about 2^-850 / |e| where e is tiny, so that |b| >= 2^-900 still.
  const int ne_exp = std::max(0, -850 - (s - d));
  for (int i = 0; i < D; ++i) n[i] = random_double(rng, ne_exp - 2, ne_exp + 2), ee += e[i] * e[i], ne += n[i] * e[i];
  if (cancel_n && ee > 0 && std::isfinite(ne / ee))
    for (int i = 0; i < D; ++i) n[i] -= (ne / ee) * e[i] * (1 - std::ldexp(1.0, -20 - static_cast<int>(rng() % 34)));
  for (int i = 0; i < D; ++i) c.n[i] = around(rng, n[i]);
  return c;
}

template <int D>
void check_cancelling(int s_lo, int s_hi) {
  std::mt19937_64 rng(7 + D);
  int answered = 0, total = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const int s = s_lo + static_cast<int>(rng() % static_cast<unsigned>(s_hi - s_lo + 1));
    const int d = static_cast<int>(rng() % 40);
    const Case<D> c = cancelling_case<D>(rng, s, d);
    const std::optional<double> T = pencil_parameter_upper<D>(c.x, c.q, c.g, c.n);
    ++total;
    if (!T) continue;
    const std::optional<Q> top = largest_exact<D>(c);
    REQUIRE(top);  // an answer promises that n.e keeps its sign over the enclosures
    ++answered;
    INFO("D " << D << " trial " << trial << " s " << s << " d " << d);
    REQUIRE(Q(*T) >= *top);
  }
  INFO("answered " << answered << " of " << total);
  CHECK(answered > total / 4);
}

}  // namespace

TEST_CASE("pencil parameter: an upper bound under cancellation, on every scale", "[pencil_parameter]") {
  check_cancelling<3>(-4, 4);
  check_cancelling<2>(-4, 4);
  check_cancelling<3>(-1000, -960);  // differences and products near and below the normal range
  check_cancelling<2>(-1000, -960);
  check_cancelling<3>(400, 500);
}

TEST_CASE("pencil parameter: underflowing products", "[pencil_parameter]") {
  // e subnormal (about 2^-1060), so e^2 underflows to zero and 2 e g rounds to
  // a multiple of 2^-1074 (up or down); n large enough that |b| >= 2^-900.
  // Only the absolute slacks cover these roundings: N/b is about 2^-180, and
  // its error up to 2^-1075 / 2^-890, far more than an ulp of it.
  std::mt19937_64 rng(1060);
  for (int trial = 0; trial < 500; ++trial) {
    Case<3> c;
    for (int i = 0; i < 3; ++i) {
      c.x[i] = random_double(rng, -1062, -1058);
      c.q[i] = 0;
      c.g[i] = Iv::exact(random_double(rng, -14, -10));
      c.n[i] = Iv::exact(random_double(rng, 168, 172));
    }
    const std::optional<double> T = pencil_parameter_upper<3>(c.x, c.q, c.g, c.n);
    if (!T) continue;
    INFO("trial " << trial);
    REQUIRE(Q(*T) >= *largest_exact<3>(c));
  }
}

TEST_CASE("pencil parameter: no answer where the bound does not apply", "[pencil_parameter]") {
  const std::array<Iv, 3> g{Iv::exact(0.25), Iv::exact(-0.5), Iv::exact(0.125)};
  const std::array<Iv, 3> n{Iv::exact(1), Iv::exact(2), Iv::exact(-1)};
  const std::array<double, 3> q{0, 0, 0};
  // A plain case answers, and T >= t*.
  const std::array<double, 3> x{0.5, 0.25, 0.125};
  const std::optional<double> T = pencil_parameter_upper<3>(x, q, g, n);
  REQUIRE(T);
  REQUIRE(Q(*T) >= *largest_exact<3>(Case<3>{x, q, g, n}));
  // n.e = 0 exactly: b = 0.
  CHECK(!pencil_parameter_upper<3>({1, 0, 1}, q, g, n));
  // |b| below 2^-900, and just above.
  CHECK(!pencil_parameter_upper<3>({0x1p-902, 0, 0}, q, g, n));
  CHECK(pencil_parameter_upper<3>({0x1p-900, 0, 0}, q, g, n));
  // |b| <= 2 Δb: n's enclosure too wide for its sign along e.
  const std::array<Iv, 3> wide{Iv{-1, 1}, Iv::exact(2), Iv::exact(-1)};
  CHECK(!pencil_parameter_upper<3>({1, 0, 0}, q, g, wide));
  // Overflow: e^2 beyond the doubles.
  CHECK(!pencil_parameter_upper<3>({0x1p+600, 0, 0}, q, g, n));
  // b overflows.
  const std::array<Iv, 3> big{Iv::exact(0x1p+1000), Iv::exact(0), Iv::exact(0)};
  CHECK(!pencil_parameter_upper<3>({0x1p+30, 0, 0}, q, g, big));
  // NaN and infinite enclosures.
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  CHECK(!pencil_parameter_upper<3>(x, q, {Iv{nan, nan}, g[1], g[2]}, n));
  CHECK(!pencil_parameter_upper<3>(x, q, g, {Iv{-inf, 1}, n[1], n[2]}));
  CHECK(!pencil_parameter_upper<3>(x, q, {Iv{0, inf}, g[1], g[2]}, n));
}
