// algorithms/facet_normal.hpp: the plain-double enclosure of a triangle's
// normal (q1 - q0) x (q2 - q0), checked in rational arithmetic:
//   * soundness at the bound's edge: random triangles whose coordinates
//     differ in exponent (every difference, product and sum rounds), on
//     scales 2^-450 to 2^450; the exact normal must lie in the enclosure, and
//     the largest error seen must exceed 0.55 of the half-width (the bound
//     0x1.01p-51 (|a| + |b|) at half its value fails), while every width
//     stays below 2^-49 (|u1 v2| + |u2 v1|) (the bound at twice its value
//     fails);
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
    REQUIRE_FALSE(facet_normal(tri(std::nan(""))));
  }
}
