// A sphere of Tanemura's pencil through a facet, in plain doubles with an
// a-priori error bound (algorithms/tanemura.hpp, ball_of): an enclosure of its
// centre and an upper bound of its squared radius. The same in interval
// arithmetic cost about 360 instructions a ball and 200 a search (3D uniform).
//
// The pencil: the spheres through the facet's vertices (exact doubles), in 3D
// a triangle q0 q1 q2, in 2D an edge q0 q1, centred at X + t n for the point
// X of their centres' line L (the axis of the triangle's circumcircle, the
// edge's perpendicular bisector) nearest q0 + y, |X - (q0 + y)| <= d
// (algorithms/pencil_axis.hpp in 3D; in 2D y = û/2, with û = fl(q1 - q0)),
// and the exact normal n, given as an enclosure [lo, hi]
// (algorithms/facet_normal.hpp or interval products). For a double T the
// sphere S_T has centre c = X + T n and squared radius |q0 - c|^2 (q0 is on
// every sphere of the pencil).
//
// Evaluation, per search: m = fl(lo/2 + hi/2) (any double between lo and
// hi), ρ = fl(max(hi - m, m - lo)); per T: p = fl(T m), w = fl(y + p) (the
// centre relative to q0), ĉ = fl(q0 + w), each per axis. Bounds (Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002, §2.2; u =
// 2^-53, u' = u / (1 - u) < 2^-52; round to nearest, a subnormal sum or
// difference is exact, an underflowing product errs by at most 2^-1075):
//   * c - q0 = (X - q0) + T n, and |X_i - q0_i - y_i| <= d;
//   * |n_i - m_i| <= max(hi - m, m - lo) <= (1 + u') ρ_i;
//   * |p_i - T m_i| <= u'|p_i| + 2^-1075,  |w_i - (y_i + p_i)| <= u'|w_i|;
// hence
//   |(c - q0)_i - w_i| <= d + |T| (1 + u') ρ_i + u' (|p_i| + |w_i|) + 2^-1075  =: ε_i,
//   |q0 - c|^2 <= Σ (|w_i| + ε_i)^2  =: r2,
// and, as |ĉ_i - (q0_i + w_i)| <= u'|ĉ_i|,
//   |c_i - ĉ_i| <= ε_i + u'|ĉ_i|  =: δ_i.
// The radius is bounded relative to q0, so its error scales with the ball,
// not with the coordinates.
// ε and δ are computed in doubles: sums and products of positive terms over
// at most a dozen roundings (with the per-search terms), so a relative slack
// of 2^-44 and an absolute one of 2^-1068 (underflows) cover them, as in
// algorithms/pencil_parameter.hpp. Each term of r2 meets at most five
// roundings (|w_i| + ε_i, the square, two sums, the slack), so its slack is
// 2^-48 > 5u: the pruning adds 2^-44 of r2 anyway (box_ball.hpp, prune_r2),
// and a second 2^-44 here let 13 % more points through on the
// near-degenerate 3D set, whose points lie within a few ulps of a sphere.
//
// No answer (nullopt) on an overflow or a NaN (T far beyond the scaled
// coordinates' range): the caller then has no ball (no pruning).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "algorithms/interval.hpp"

namespace dlab {

// The per-search terms.
template <int D>
struct PencilBase {
  std::array<double, D> q0, y, m;
  double near;                 // d + 2^-1074 (and the product's underflow, 2^-1075)
  std::array<double, D> tilt;  // (1 + u') ρ_i: bounds |n_i - m_i|
};

template <int D>
PencilBase<D> pencil_base(const std::array<double, D>& q0, const std::array<double, D>& y, double d,
                          const std::array<Iv, D>& n) {
  PencilBase<D> b;
  b.q0 = q0;
  b.y = y;
  b.near = d + 0x1p-1074;
  for (int i = 0; i < D; ++i) {
    b.m[i] = std::clamp(n[i].lo / 2 + n[i].hi / 2, n[i].lo, n[i].hi);  // NaN: NaN
    b.tilt[i] = std::max(n[i].hi - b.m[i], b.m[i] - n[i].lo) * (1 + 0x1p-52);
  }
  return b;
}

template <int D>
struct PencilBall {
  std::array<double, D> centre;  // ĉ
  std::array<double, D> delta;   // |c_i - ĉ_i| <= delta_i
  double r2;                     // >= |q0 - c|^2
};

template <int D>
std::optional<PencilBall<D>> pencil_ball(const PencilBase<D>& b, double T) {
  using std::fabs;
  constexpr double slack = 1 + 0x1p-44, tiny = 0x1p-1068;
  PencilBall<D> s;
  const double at = fabs(T);
  double r2 = 0;
  for (int i = 0; i < D; ++i) {
    const double p = T * b.m[i], w = b.y[i] + p;
    s.centre[i] = b.q0[i] + w;
    const double eps = (b.near + at * b.tilt[i] + 0x1p-52 * (fabs(p) + fabs(w))) * slack + tiny;
    s.delta[i] = (eps + 0x1p-52 * fabs(s.centre[i])) * slack;
    const double a = fabs(w) + eps;
    r2 += a * a;
  }
  s.r2 = r2 * (1 + 0x1p-48) + tiny;
  if (!(s.r2 < HUGE_VAL)) return std::nullopt;  // NaN too; then every delta_i is finite
  return s;
}

}  // namespace dlab
