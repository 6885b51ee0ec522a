// algorithms/pencil_ball.hpp: the plain-double centre enclosure and radius
// bound of a sphere of Tanemura's pencil, checked in rational arithmetic
// against the exact sphere centred at X + T n (X: the point of the axis
// nearest q0 + y, n the exact normal):
//   * random triangles on scales 2^-300 to 2^300, the normal from
//     facet_normal (inexact, so |T| rho matters), y from pencil_axis_point
//     and moved off the axis (d matters), T of every size and sign;
//   * the rounding terms alone: triangles whose normal and axis point are
//     exact (d and rho about zero), so that only the roundings of T m and
//     z + T m separate the computed centre from the true one;
//   * 2D: random edges, y from edge_axis_point;
//   * no answer on overflow or NaN.
// Mutations these tests catch are listed in papers/triangulation_costs.md
// ("Session 35").
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <random>

#include "algorithms/pencil_axis.hpp"
#include "algorithms/pencil_ball.hpp"
#include "tests/rational_vectors.hpp"

using namespace dlab;
using namespace dlab::rational_vectors;

namespace {

// The exact pencil of q: n, and X, the point of the axis nearest q0 + y.
struct ExactPencil {
  QV n, x;
};
ExactPencil exact_pencil(const Tri& q, const std::array<double, 3>& y) {
  QV u, v, q0;
  for (int i = 0; i < 3; ++i) u[i] = Q(q[1][i]) - Q(q[0][i]), v[i] = Q(q[2][i]) - Q(q[0][i]), q0[i] = Q(q[0][i]);
  ExactPencil p;
  p.n = cross(u, v);
  const Q nn = dot(p.n, p.n);
  const QV vn = cross(v, p.n), nu = cross(p.n, u);
  QV c, off;
  for (int i = 0; i < 3; ++i) c[i] = q0[i] + (dot(u, u) * vn[i] + dot(v, v) * nu[i]) / (2 * nn);
  for (int i = 0; i < 3; ++i) off[i] = q0[i] + Q(y[i]) - c[i];
  const Q s = dot(off, p.n) / nn;
  for (int i = 0; i < 3; ++i) p.x[i] = c[i] + s * p.n[i];
  return p;
}

// Checks the ball of T against the exact sphere; false if there is none.
bool check_ball(const Tri& q, const ExactPencil& ex, const PencilBase<3>& base, double T) {
  const std::optional<PencilBall<3>> b = pencil_ball(base, T);
  if (!b) return false;
  Q r2{0};
  for (int i = 0; i < 3; ++i) {
    const Q c = ex.x[i] + Q(T) * ex.n[i];
    REQUIRE(abs(c - Q(b->centre[i])) <= Q(b->delta[i]));
    r2 += (Q(q[0][i]) - c) * (Q(q[0][i]) - c);
  }
  REQUIRE(r2 <= Q(b->r2));
  return true;
}

}  // namespace

TEST_CASE("pencil_ball: the exact sphere lies within the bounds, on every scale and for every T") {
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(-1, 1);
  int balls = 0;
  for (int scale = -300; scale <= 300; scale += 50) {
    for (int trial = 0; trial < 60; ++trial) {
      Tri q;
      for (auto& p : q)
        for (double& x : p) x = std::ldexp(unit(rng), scale + int(rng() % 5) - 2);
      const std::array<Iv, 3> n = search_normal(q);
      const std::optional<AxisPoint<3>> a = pencil_axis_point(q, n, norm2(n));
      if (!a) continue;
      // y on its own, and moved off the axis (so that d is what bounds X).
      std::array<double, 3> y = a->y;
      for (const bool moved : {false, true}) {
        if (moved)
          for (double& x : y) x *= 1 + 0x1p-30 * unit(rng);
        const std::optional<double> d = moved ? pencil_axis_distance(q, y, norm2(n)) : std::optional{a->d};
        REQUIRE(d);
        const ExactPencil ex = exact_pencil(q, y);
        const PencilBase<3> base = pencil_base<3>(q[0], y, *d, n);
        // T from tiny to 2^40 of the scale over |n| (n has the scale squared).
        for (int k = 0; k < 6; ++k) {
          const double T = std::ldexp(unit(rng), -scale + int(rng() % 90) - 50);
          REQUIRE(check_ball(q, ex, base, T));
          ++balls;
        }
        REQUIRE(check_ball(q, ex, base, 0.0));
      }
    }
  }
  REQUIRE(balls > 6000);
}

TEST_CASE("pencil_ball: 2D, the exact circle lies within the bounds") {
  // The pencil of circles through an edge: centres X + T n on the
  // perpendicular bisector, X its point nearest q0 + y (edge_axis_point),
  // n = (-u1, u0) enclosed as Tanemura's search does (interval differences).
  std::mt19937_64 rng(353);
  std::uniform_real_distribution<double> unit(-1, 1);
  int balls = 0;
  for (int scale = -300; scale <= 300; scale += 50) {
    for (int trial = 0; trial < 200; ++trial) {
      std::array<std::array<double, 2>, 2> q;
      for (auto& p : q)
        for (double& x : p) x = std::ldexp(unit(rng), scale + int(rng() % 5) - 2);
      const std::optional<AxisPoint<2>> a = edge_axis_point(q);
      REQUIRE(a);
      const Iv ux = tight_sub(Iv::exact(q[1][0]), Iv::exact(q[0][0]));
      const Iv uy = tight_sub(Iv::exact(q[1][1]), Iv::exact(q[0][1]));
      const std::array<Iv, 2> n = {tight_sub(Iv{0, 0}, uy), ux};
      const std::array<Q, 2> u = {Q(q[1][0]) - Q(q[0][0]), Q(q[1][1]) - Q(q[0][1])};
      const std::array<Q, 2> nq = {-u[1], u[0]};
      const Q nn = nq[0] * nq[0] + nq[1] * nq[1];
      if (nn == 0) continue;
      // X = q0 + u/2 + s n with s = (y - u/2).n / |n|^2.
      const Q s = ((Q(a->y[0]) - u[0] / 2) * nq[0] + (Q(a->y[1]) - u[1] / 2) * nq[1]) / nn;
      const PencilBase<2> base = pencil_base<2>(q[0], a->y, a->d, n);
      for (int k = 0; k < 6; ++k) {
        const double T = k == 0 ? 0.0 : std::ldexp(unit(rng), -scale + int(rng() % 90) - 50);
        const std::optional<PencilBall<2>> b = pencil_ball(base, T);
        REQUIRE(b);
        Q r2{0};
        for (int i = 0; i < 2; ++i) {
          const Q c = Q(q[0][i]) + u[i] / 2 + (s + Q(T)) * nq[i];
          REQUIRE(abs(c - Q(b->centre[i])) <= Q(b->delta[i]));
          r2 += (Q(q[0][i]) - c) * (Q(q[0][i]) - c);
        }
        REQUIRE(r2 <= Q(b->r2));
        ++balls;
      }
    }
  }
  REQUIRE(balls > 10000);
}

TEST_CASE("pencil_ball: the rounding terms alone bound the error of an exact pencil") {
  // q0 = (a, b, c), q1 = q0 + (2s, 0, 0), q2 = q0 + (0, 2t, 0) with small
  // integers: n = (0, 0, 4st) is exact (rho = 0) and q0 + y with y = (s, t, 0)
  // is on the axis (d = 0); so each delta is the roundings of q0 + y, T m and
  // z + T m, with T a full 53-bit double.
  std::mt19937_64 rng(3535);
  std::uniform_real_distribution<double> unit(-1, 1);
  for (int trial = 0; trial < 3000; ++trial) {
    const double s = double(1 + rng() % 1000), t = double(1 + rng() % 1000);
    std::array<double, 3> q0;
    for (double& x : q0) x = std::ldexp(std::round(std::ldexp(unit(rng) * 1000, 30)), -30);  // q0 + 2s exact
    const Tri q = {{q0, {q0[0] + 2 * s, q0[1], q0[2]}, {q0[0], q0[1] + 2 * t, q0[2]}}};
    const std::array<Iv, 3> n = {Iv::exact(0), Iv::exact(0), Iv::exact(4 * s * t)};
    const std::array<double, 3> y = {s, t, 0};
    const ExactPencil ex = exact_pencil(q, y);
    for (int i = 0; i < 3; ++i) REQUIRE(ex.x[i] == Q(q0[i]) + Q(y[i]));  // q0 + y is on the axis: d = 0
    const PencilBase<3> base = pencil_base<3>(q0, y, 0.0, n);
    REQUIRE(check_ball(q, ex, base, unit(rng) * std::ldexp(1.0, int(rng() % 20) - 10)));
  }
}

TEST_CASE("pencil_ball: no answer on overflow or NaN") {
  const Tri q = {{{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}};
  const std::array<Iv, 3> n = {Iv::exact(0), Iv::exact(0), Iv::exact(4)};
  const PencilBase<3> base = pencil_base<3>(q[0], {1, 1, 0}, 0x1p-60, n);
  REQUIRE(pencil_ball(base, 0x1p500));
  REQUIRE_FALSE(pencil_ball(base, 0x1p1020));
  REQUIRE_FALSE(pencil_ball(base, std::numeric_limits<double>::quiet_NaN()));
  REQUIRE_FALSE(pencil_ball(base, std::numeric_limits<double>::infinity()));
}
