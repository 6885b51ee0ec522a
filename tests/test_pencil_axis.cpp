// algorithms/pencil_axis.hpp: the plain-double bound d of the distance from
// q0 + y to the axis of a triangle's circumcircle, checked in rational
// arithmetic against the exact distance:
//   * the bound's main term at its edge: small integers (every rounding
//     exact) and y off the axis along v x n (or n x u), where
//     (|r1| |v| + |r2| |u|) / |n| is the distance itself; d^2 must lie
//     within 2^-24 of it (the rounding terms, relative to r1 or r2 at least
//     2^-32 here);
//   * roundings: random triangles on scales 2^-500 to 2^500, slivers and
//     near-duplicate vertices, y from pencil_axis_point and y moved off it;
//   * no answer for a degenerate triangle, NaN, overflow or a sliver whose
//     bound exceeds 2^-20 of y.
// 2D (edge_axis_point): q0 + y within d of an edge's perpendicular bisector,
// with coordinates of mixed exponents on every scale; no answer on NaN or
// overflow.
// Mutations these tests catch are listed in papers/triangulation_costs.md
// ("Session 34").
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "algorithms/pencil_axis.hpp"
#include "tests/rational_vectors.hpp"

using namespace dlab;
using namespace dlab::rational_vectors;

namespace {

// The exact squared distance from q0 + y to the axis (the part of y - C in
// the triangle's plane, from the residuals: the header's w).
Q distance2(const Tri& q, const std::array<double, 3>& y) {
  QV u, v, yq;
  for (int i = 0; i < 3; ++i) {
    u[i] = Q(q[1][i]) - Q(q[0][i]);
    v[i] = Q(q[2][i]) - Q(q[0][i]);
    yq[i] = Q(y[i]);
  }
  const QV n = cross(u, v), vn = cross(v, n), nu = cross(n, u);
  const Q nn = dot(n, n);
  const Q r1 = dot(yq, u) - dot(u, u) / 2, r2 = dot(yq, v) - dot(v, v) / 2;
  QV w;
  for (int i = 0; i < 3; ++i) w[i] = (r1 * vn[i] + r2 * nu[i]) / nn;
  return dot(w, w);
}

// The normal's enclosures as Tanemura computes them and the enclosure of its
// squared norm.
struct Normal {
  std::array<Iv, 3> n;
  Iv nn{0, 0};
};
Normal normal_of(const Tri& q) {
  Normal r;
  r.n = search_normal(q);
  r.nn = norm2(r.n);
  return r;
}

// d is an upper bound of the exact distance (a rational comparison).
bool holds(const Tri& q, const std::array<double, 3>& y, double d) { return distance2(q, y) <= Q(d) * Q(d); }

}  // namespace

TEST_CASE("pencil_axis: the main term equals the distance off the axis along v x n and n x u") {
  // q0 = 0, u = (a, 0, 0), v = (b, c, 0): n = (0, 0, ac), the axis through
  // C = (a/2, (b^2 + c^2 - a b) / (2c), 0). With c a power of two, C and
  // y = C + s (c, -b, 0) (along v x n: r2 = 0) are exact doubles, and the
  // distance is |s| sqrt(b^2 + c^2). Along n x u = a^2 c (0, 1, 0) instead
  // (r1 = 0) the distance is |s|. |u| < |v| in some cases and > in others,
  // so swapping them in the bound fails.
  std::mt19937_64 rng(34);
  for (int trial = 0; trial < 2000; ++trial) {
    const double a = 2.0 * double(1 + rng() % 512), b = double(int(rng() % 1025) - 512);
    const double c = std::ldexp(1.0, int(rng() % 10));
    const double s = std::ldexp(double(1 + rng() % 63), int(rng() % 8)) * (rng() % 2 ? 1 : -1);
    const Tri q = {{{0, 0, 0}, {a, 0, 0}, {b, c, 0}}};
    const Normal nr = normal_of(q);
    const double cy = (b * b + c * c - a * b) / (2 * c);
    for (const bool along_vn : {true, false}) {
      const std::array<double, 3> y =
          along_vn ? std::array<double, 3>{a / 2 + s * c, cy - s * b, 0} : std::array<double, 3>{a / 2, cy + s, 0};
      const Q exact = along_vn ? Q(s) * Q(s) * (Q(b) * Q(b) + Q(c) * Q(c)) : Q(s) * Q(s);
      REQUIRE(distance2(q, y) == exact);  // the construction itself
      const std::optional<double> d = pencil_axis_distance(q, y, nr.nn);
      REQUIRE(d);
      REQUIRE(Q(*d) * Q(*d) >= exact);
      REQUIRE(Q(*d) * Q(*d) <= exact * Q(1 + 0x1p-24));
    }
  }
}

TEST_CASE("pencil_axis: the bound holds under rounding, on every scale, for slivers and near-duplicates") {
  std::mt19937_64 rng(3434);
  std::uniform_real_distribution<double> unit(-1, 1);
  int answered = 0, moved = 0, total = 0;  // total: 6 300 triangles
  for (int scale = -500; scale <= 500; scale += 50) {
    for (int trial = 0; trial < 300; ++trial) {
      Tri q;
      for (auto& p : q)
        for (double& x : p) x = std::ldexp(unit(rng), scale);
      switch (trial % 4) {
        case 1:  // a sliver: q2 near the line q0 q1
          for (int i = 0; i < 3; ++i)
            q[2][i] = q[0][i] + 0.37 * (q[1][i] - q[0][i]) + std::ldexp(unit(rng), scale - 30);
          break;
        case 2:  // near-duplicate vertices
          for (int i = 0; i < 3; ++i) q[1][i] = q[0][i] + std::ldexp(unit(rng), scale - 40);
          break;
        case 3:  // far from the origin: differences round
          for (auto& p : q)
            for (double& x : p) x += std::ldexp(1.0, scale + 20);
          break;
        default:
          break;
      }
      ++total;
      const Normal nr = normal_of(q);
      const std::optional<AxisPoint<3>> a = pencil_axis_point(q, nr.n, nr.nn);
      // In range (scaled coordinates are about 1 in Tanemura), every
      // triangle but the slivers answers; out of it (products overflow or
      // |n|^2 < 2^-900) none does.
      if (std::abs(scale) <= 150 && trial % 4 != 1) REQUIRE(a);
      if (std::abs(scale) >= 250) REQUIRE_FALSE(a);
      if (!a) continue;
      ++answered;
      REQUIRE(holds(q, a->y, a->d));
      // y anywhere: moved off the axis by a few ulps, or far.
      std::array<double, 3> y = a->y;
      for (double& x : y) x = rng() % 2 ? std::nextafter(x, 2 * x + 1) : x * (1 + 0x1p-30 * unit(rng));
      if (const std::optional<double> d = pencil_axis_distance(q, y, nr.nn)) {
        ++moved;
        REQUIRE(holds(q, y, *d));
      }
    }
  }
  REQUIRE(answered > total / 3);
  REQUIRE(moved == answered);
}

TEST_CASE("pencil_axis: no answer where the bound does not apply") {
  const std::array<Iv, 3> n1 = {Iv::exact(0), Iv::exact(0), Iv::exact(1)};
  SECTION("a degenerate triangle: |n|^2 below 2^-900") {
    const Tri q = {{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}};
    const Normal nr = normal_of(q);
    REQUIRE_FALSE(pencil_axis_point(q, nr.n, nr.nn));
    const Iv small = Iv::exact(0x1p-901), edge = Iv::exact(0x1p-900);
    REQUIRE_FALSE(pencil_axis_distance(q, {0.5, 0, 0}, small));
    REQUIRE(pencil_axis_distance(q, {0.5, 0, 0}, edge));
  }
  SECTION("NaN and overflow") {
    const Tri nan_q = {{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}};
    REQUIRE_FALSE(pencil_axis_distance(nan_q, {0.5, 0.5, 0}, Iv::exact(1)));
    const Tri big = {{{0, 0, 0}, {0x1p600, 0, 0}, {0, 0x1p600, 0}}};
    REQUIRE_FALSE(pencil_axis_distance(big, {0x1p599, 0x1p599, 0}, Iv::exact(1)));
    REQUIRE_FALSE(pencil_axis_point(big, n1, Iv::exact(1)));
  }
  SECTION("a sliver whose bound exceeds 2^-20 of y") {
    // The normal given far from the true one: y is then far from the axis.
    const Tri q = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
    const std::array<Iv, 3> tilted = {Iv::exact(0.5), Iv::exact(0), Iv::exact(1)};
    REQUIRE_FALSE(pencil_axis_point(q, tilted, Iv::exact(1)));
    const Normal nr = normal_of(q);
    const std::optional<AxisPoint<3>> a = pencil_axis_point(q, nr.n, nr.nn);
    REQUIRE(a);
    REQUIRE(a->y == std::array<double, 3>{0.5, 0.5, 0});
    REQUIRE(a->d < 0x1p-48);
    // Tilted by e (n = (e, 0, 1)), d / max|y_i| is about 2^-19 (e / 2^-10)^2:
    // 2^-19.83 at e = 0.75 2^-10 (no answer), 2^-20.47 at e = 0.6 2^-10
    // (an answer): the guard moved by a binade either way fails one.
    for (const auto& [e, answers] : {std::pair{0.75 * 0x1p-10, false}, std::pair{0.6 * 0x1p-10, true}}) {
      const std::array<Iv, 3> n = {Iv::exact(e), Iv::exact(0), Iv::exact(1)};
      REQUIRE(pencil_axis_point(q, n, Iv::exact(1)).has_value() == answers);
    }
  }
}

TEST_CASE("pencil_axis: 2D, q0 + y lies within d of the edge's perpendicular bisector") {
  // The bisector's nearest point to q0 + y is X = q0 + u/2 moved along n =
  // (-u1, u0); the distance is |(y - u/2) . u| / |u|. Coordinates of mixed
  // exponents (so that q1 - q0 rounds), on scales 2^-1070 to 2^1000.
  std::mt19937_64 rng(352);
  std::uniform_real_distribution<double> unit(-1, 1);
  double worst = 0;  // the largest distance / d seen
  for (int scale = -1070; scale <= 1000; scale += 30) {
    for (int trial = 0; trial < 200; ++trial) {
      std::array<std::array<double, 2>, 2> q;
      for (auto& p : q)
        for (double& x : p) x = std::ldexp(unit(rng), std::min(1020, scale + int(rng() % 9) - 4));
      const std::optional<AxisPoint<2>> a = edge_axis_point(q);
      REQUIRE(a);
      Q along{0}, uu{0};
      for (int i = 0; i < 2; ++i) {
        const Q u = Q(q[1][i]) - Q(q[0][i]);
        along += (Q(a->y[i]) - u / 2) * u;
        uu += u * u;
      }
      if (uu == 0) continue;
      const Q dist2 = along * along / uu;
      REQUIRE(dist2 <= Q(a->d) * Q(a->d));
      if (a->d > 0x1p-1000) worst = std::max(worst, std::sqrt(static_cast<double>(dist2 / (Q(a->d) * Q(a->d)))));
    }
  }
  INFO("worst distance / d " << worst);
  // The header's main term, 2^-54 (|û0| + |û1|), is a quarter of d: the
  // largest distance seen must come near it (d at an eighth fails).
  REQUIRE(worst > 0.2);
  const std::array<std::array<double, 2>, 2> nan_edge = {{{0, 0}, {std::nan(""), 1}}};
  REQUIRE_FALSE(edge_axis_point(nan_edge));
  const std::array<std::array<double, 2>, 2> huge_edge = {{{-0x1p1023, 0}, {0x1p1023, 0}}};
  REQUIRE_FALSE(edge_axis_point(huge_edge));
}
