// algorithms/facet_normal.hpp: the plain-double enclosure of a triangle's
// normal (q1 - q0) x (q2 - q0), checked in rational arithmetic:
//   * soundness at the bound's edge: random triangles whose coordinates
//     differ in exponent (every difference, product and sum rounds), on
//     scales 2^-450 to 2^450; the exact normal must lie in the enclosure, and
//     the largest error seen must exceed 0.55 of the half-width (the bound
//     0x1.01p-51 (|a| + |b|) at half its value fails), while every width
//     stays below 2^-49 (|u1 v2| + |u2 v1|) (the bound at twice its value
//     fails);
//   * with exact differences (vertices within a factor two of each other),
//     the narrower bound 0x1.01p-53 (|a| + |b| + |m0|) at its
//     edge: on cancelling products (a = b up to a few ulps) the largest error
//     seen exceeds 0.95 of the half-width (halved, it fails), and every width
//     stays below 2^-51 (|a| + |b| + |m0|) (doubled, or the first bound used,
//     it fails); soundness where m0 rounds too (the |m0| term's absence is
//     not caught: lower_rel's step, at least an ulp of m0, covers it); a
//     difference that fails the exactness test gets the first bound;
//   * difference_known_exact accepts only exact differences, and every pair
//     within a factor two (Sterbenz);
//   * an exact zero stays an exact zero (axis-parallel facets);
//   * no answer for short operands (grid points: the exact interval
//     products are a point there), out-of-range differences and NaN.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "algorithms/facet_normal.hpp"
#include "tests/rational_vectors.hpp"

using namespace dlab;
using namespace dlab::rational_vectors;

namespace {

struct Exact {
  std::array<Q, 3> n;     // (q1 - q0) x (q2 - q0)
  std::array<Q, 3> size;  // |u_j v_k| + |u_k v_j|
};
Exact exact_normal(const Tri& q) {
  std::array<Q, 3> u, v;
  for (int i = 0; i < 3; ++i) u[i] = Q(q[1][i]) - Q(q[0][i]), v[i] = Q(q[2][i]) - Q(q[0][i]);
  Exact r;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const Q a = u[j] * v[k], b = u[k] * v[j];
    r.n[i] = a - b;
    r.size[i] = abs(a) + abs(b);
  }
  return r;
}

}  // namespace

TEST_CASE("facet_normal: the exact normal lies in the enclosure, near its edge") {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst = 0;  // the largest |n_i - centre| / half-width seen
  int answered = 0, total = 0;
  for (int scale = -450; scale <= 450; scale += 50) {
    for (int trial = 0; trial < 2000; ++trial) {
      Tri q;
      for (auto& p : q)
        for (double& x : p) x = std::ldexp(unit(rng), scale + int(rng() % 9) - 4);
      ++total;
      const std::optional<std::array<Iv, 3>> n = facet_normal(q);
      if (!n) continue;
      ++answered;
      const Exact ex = exact_normal(q);
      for (int i = 0; i < 3; ++i) {
        const Iv& e = (*n)[i];
        REQUIRE(Q(e.lo) <= ex.n[i]);
        REQUIRE(ex.n[i] <= Q(e.hi));
        REQUIRE(Q(e.hi) - Q(e.lo) <= ex.size[i] * Q(0x1p-49));
        const Q centre = (Q(e.lo) + Q(e.hi)) / 2, half = (Q(e.hi) - Q(e.lo)) / 2;
        if (half > 0) worst = std::max(worst, static_cast<double>(abs(ex.n[i] - centre) / half));
      }
    }
  }
  INFO("worst error / half-width " << worst);
  REQUIRE(answered > total * 9 / 10);
  REQUIRE(worst > 0.55);
}

TEST_CASE("facet_normal: exact differences, the narrower bound at its edge") {
  std::mt19937_64 rng(36);
  std::uniform_int_distribution<std::int64_t> r22(0, (std::int64_t{1} << 22) - 1);
  std::uniform_real_distribution<double> unit(0.5, 1);
  // 1 + r 2^-48, r < 2^22 odd: 49 significant bits, so u_j v_k = 1 +
  // O(2^-25) rounds (its part r r' 2^-96 < 2^-52 decides by how much).
  const auto near_one = [&] { return 1 + std::ldexp(double(r22(rng) | 1), -48); };
  // narrow: every width checked against 2^-51 (|a| + |b| + |m0|), for
  // components whose m0 is tiny (lower_rel's step, 1 to 2 ulps of m0, would
  // exceed that elsewhere).
  const auto check = [](const Tri& q, double& worst, bool narrow) {
    for (int i = 0; i < 3; ++i)
      for (int j = 1; j < 3; ++j) REQUIRE(Q(q[j][i] - q[0][i]) == Q(q[j][i]) - Q(q[0][i]));  // exact
    const std::optional<std::array<Iv, 3>> n = facet_normal(q);
    REQUIRE(n);
    const Exact ex = exact_normal(q);
    for (int i = 0; i < 3; ++i) {
      const Iv& e = (*n)[i];
      REQUIRE(Q(e.lo) <= ex.n[i]);
      REQUIRE(ex.n[i] <= Q(e.hi));
      const Q size = ex.size[i] + abs(ex.n[i]);
      if (narrow) REQUIRE(Q(e.hi) - Q(e.lo) <= size * Q(0x1p-51));
      const Q centre = (Q(e.lo) + Q(e.hi)) / 2, half = (Q(e.hi) - Q(e.lo)) / 2;
      if (half > 0) worst = std::max(worst, static_cast<double>(abs(ex.n[i] - centre) / half));
    }
  };
  // q0 = (4, 4, 4) and q_j = q0 + r_j, r_j in [1, 2) of 49 significant
  // bits or in [2^-30, 1) of 21: every coordinate exact and within a factor two
  // of q0's (the Sterbenz test that facet_normal applies), then scaled by s.
  const auto translated = [](const std::array<double, 3>& r1, const std::array<double, 3>& r2, double s) {
    Tri q;
    for (int i = 0; i < 3; ++i) q[0][i] = 4 * s, q[1][i] = (4 + r1[i]) * s, q[2][i] = (4 + r2[i]) * s;
    return q;
  };
  SECTION("cancelling products: the two roundings add up to the bound") {
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      // Every u_j v_k = 1 + O(2^-25): m0 = a - b is exact (Sterbenz),
      // |n_i - m0| = |err a - err b| up to 2u, against the bound's 1.0039 u
      // (|a| + |b| + |m0|), about 2.008u; m0 is tiny, so every component's
      // width is checked.
      const double s = std::ldexp(1.0, int(rng() % 500) - 250);
      const Tri q = translated({near_one(), near_one(), near_one()}, {near_one(), near_one(), near_one()}, s);
      check(q, worst, true);
    }
    INFO("worst error / half-width " << worst);
    REQUIRE(worst > 0.95);
  }
  SECTION("a small second product: m0 rounds as much as a") {
    // Soundness near the bound; the |m0| term's absence would not show:
    // the enclosure's outward step (lower_rel, upper_rel), at least an ulp
    // of m0, also covers m0's own rounding.
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      // n2 = u0 v1 - u1 v0 with u1 v0 about 2^-k: m0 = a - b rounds.
      const double t = std::ldexp(1 + std::ldexp(double(r22(rng) >> 2 | 1), -20), -int(rng() % 30) - 1);
      const Tri q = translated({near_one(), t, near_one()}, {near_one(), near_one(), near_one()}, 1);
      check(q, worst, false);
    }
    INFO("worst error / half-width " << worst);
    REQUIRE(worst > 0.9);
  }
  SECTION("one difference beyond the test: the first bound, in every component") {
    // q_j,i moved by 8: its difference, about 9, is exact but fails the
    // test (|d| > |q0_i| = 4), so the first bound applies, also to the
    // component n_i without axis i, which still cancels: its width exceeds
    // 2^-50 (|a| + |b|) (the narrower bound's would be below a quarter).
    for (int trial = 0; trial < 2000; ++trial) {
      Tri q = translated({near_one(), near_one(), near_one()}, {near_one(), near_one(), near_one()}, 1);
      const int j = 1 + int(rng() % 2), i = int(rng() % 3);
      q[j][i] += 8;
      REQUIRE_FALSE(difference_known_exact(q[j][i], q[0][i], q[j][i] - q[0][i]));
      const std::optional<std::array<Iv, 3>> n = facet_normal(q);
      REQUIRE(n);
      const Exact ex = exact_normal(q);
      for (int l = 0; l < 3; ++l) REQUIRE((Q((*n)[l].lo) <= ex.n[l] && ex.n[l] <= Q((*n)[l].hi)));
      REQUIRE(Q((*n)[i].hi) - Q((*n)[i].lo) >= ex.size[i] * Q(0x1p-50));
    }
  }
  SECTION("vertices within a factor two of each other (Sterbenz), far from the origin") {
    double worst = 0;
    for (int trial = 0; trial < 20000; ++trial) {
      Tri q;
      const double base = std::ldexp(1.0, int(rng() % 200) - 100);
      for (int i = 0; i < 3; ++i) q[0][i] = base * (1 + unit(rng) / 4);
      for (int j = 1; j < 3; ++j)
        for (int i = 0; i < 3; ++i) q[j][i] = q[0][i] * (1 + std::ldexp(unit(rng) - 0.75, -int(rng() % 12)));
      check(q, worst, false);
    }
    INFO("worst error / half-width " << worst);
    REQUIRE(worst > 0.8);
  }
}

TEST_CASE("difference_known_exact: exact differences only, and all of Sterbenz's range") {
  // Pairs at the test's edges: x = k y (1 + small) for k around 1/2, 1, 2
  // and beyond, a few ulps either way, both signs, every binade from the
  // subnormals up; and independent pairs.
  std::mt19937_64 rng(3636);
  std::uniform_real_distribution<double> unit(0.5, 1);
  int accepted = 0, inexact_near = 0;
  const auto check = [&](double x, double y) {
    const double d = x - y;
    if (!std::isfinite(d)) return;  // overflow (not a difference facet_normal takes)
    const bool exact = Q(d) == Q(x) - Q(y);
    if (difference_known_exact(x, y, d)) {
      REQUIRE(exact);
      ++accepted;
    }
    // Sterbenz: y / 2 <= x <= 2y (one sign) must be accepted.
    const Q qx = abs(Q(x)), qy = abs(Q(y));
    if ((x > 0) == (y > 0) && x != 0 && y != 0 && qy <= 2 * qx && qx <= 2 * qy)
      REQUIRE(difference_known_exact(x, y, d));
    // Inexact, yet within twice the minimum: a looser test fails here.
    if (!exact && abs(Q(d)) <= 2 * std::min(qx, qy)) ++inexact_near;
  };
  for (int trial = 0; trial < 20000; ++trial) {
    const double y = std::ldexp(unit(rng), int(rng() % 2100) - 1075) * (rng() % 2 ? 1 : -1);
    for (const double k : {-1.0, 0.5, 1.0, 2.0, 2.25, 3.0, 1e3}) {
      double x = k * y * (1 + std::ldexp(unit(rng), -int(rng() % 60)) * (rng() % 2 ? 1 : -1));
      for (int step = int(rng() % 4); step > 0; --step) x = std::nextafter(x, rng() % 2 ? 2 * x : 0.0);
      if (std::isfinite(x)) check(x, y), check(y, x);
    }
    check(std::ldexp(unit(rng), int(rng() % 200) - 100), y);
  }
  INFO("accepted " << accepted << ", inexact within twice the minimum " << inexact_near);
  REQUIRE(accepted > 20000);
  REQUIRE(inexact_near > 1000);
}

TEST_CASE("facet_normal: exact zeros, short operands and the range") {
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> unit(0.5, 1);
  SECTION("an axis-parallel facet: the vanishing components are exact zeros") {
    for (int trial = 0; trial < 100; ++trial) {
      Tri q;
      for (auto& p : q) p = {unit(rng), std::ldexp(unit(rng), -3), 0.3};
      const std::optional<std::array<Iv, 3>> n = facet_normal(q);
      REQUIRE(n);
      for (int i = 0; i < 2; ++i) REQUIRE(((*n)[i].lo == 0 && (*n)[i].hi == 0));
      const Q n2 = exact_normal(q).n[2];
      REQUIRE((Q((*n)[2].lo) <= n2 && n2 <= Q((*n)[2].hi)));
    }
  }
  SECTION("short operands: no answer up to 53 significant bits in all") {
    // u's longest component has 26 bits, v's b bits (q0 = 0: exact
    // differences): up to b = 27 every product is exact, and no answer.
    for (const auto& [bits_v, answers] : {std::pair{27, false}, std::pair{28, true}}) {
      const double long_u = std::ldexp(double((1 << 25) + 1), -25);  // 26 bits
      const double long_v = std::ldexp(double((std::uint64_t{1} << (bits_v - 1)) + 1), -bits_v);
      const Tri q = {{{0, 0, 0}, {long_u, 0.5, 0.25}, {0.75, long_v, 0.125}}};
      REQUIRE(significant_bits(long_u) == 26);
      REQUIRE(significant_bits(long_v) == bits_v);
      const std::optional<std::array<Iv, 3>> n = facet_normal(q);
      REQUIRE(n.has_value() == answers);
      if (n) {
        const Exact ex = exact_normal(q);
        for (int i = 0; i < 3; ++i) REQUIRE((Q((*n)[i].lo) <= ex.n[i] && ex.n[i] <= Q((*n)[i].hi)));
      }
    }
    // Grid points: small integers.
    const Tri grid = {{{1, 2, 3}, {4, -5, 6}, {7, 8, -9}}};
    REQUIRE_FALSE(facet_normal(grid));
  }
  SECTION("differences outside [2^-500, 2^500), and NaN: no answer") {
    const double l = 1 + 0x1p-40;  // long significands, so that only the range decides
    const auto tri = [&](double d) { return Tri{{{0, 0, 0}, {d * l, 0.75 * l, 0}, {0.5 * l, d, 0.25 * l}}}; };
    REQUIRE(facet_normal(tri(0x1p-500)));
    REQUIRE_FALSE(facet_normal(tri(0x1p-501)));
    REQUIRE(facet_normal(tri(0x1p499)));
    REQUIRE_FALSE(facet_normal(tri(0x1p500)));
    REQUIRE_FALSE(facet_normal(Tri{{{0, 0, 0}, {0x1p500, 0.75 * l, 0}, {0.5 * l, 0.25 * l, 0.125 * l}}}));
    REQUIRE_FALSE(facet_normal(tri(std::nan(""))));
  }
}
