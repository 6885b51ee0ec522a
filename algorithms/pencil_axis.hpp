// A point near the axis of a triangle's circumcircle in 3D (and of an edge's
// pencil of circles in 2D: edge_axis_point, at the end), in plain doubles
// with a bound proved once, for Tanemura's pencil of spheres through a facet
// (algorithms/tanemura.hpp, make_pencil). The interval circumcentre
// (algorithms/circumball.hpp) cost about 1 800 instructions a search, 13 % of
// Tanemura's on uniform 3D input.
//
// The pencil's centres form the axis L = {x : |x - q0| = |x - q1| = |x - q2|},
// the line through the circumcentre C along n = u x v (u = q1 - q0, v = q2 -
// q0). Any point X0 of L serves as the pencil's base (its spheres are those
// centred at X0 + t n), so no circumcentre is needed: only a point y (an
// offset from q0) with a bound d of its distance to L. With the residuals
//   r1 = y.u - |u|^2 / 2,   r2 = y.v - |v|^2 / 2
// (zero exactly on L: 2 x.u = |u|^2 is |x| = |x - u|), the part of y - C in
// the plane of u and v is w = (r1 (v x n) + r2 (n x u)) / |n|^2, as
// (v x n).u = (n x u).v = |n|^2 and (v x n).v = (n x u).u = 0; with
// |v x n| = |v||n| (v is orthogonal to n):
//   dist(q0 + y, L) = |w| <= (|r1| |v| + |r2| |u|) / |n|.
// y itself is any double vector (here the circumcentre's formula of
// circumball.hpp evaluated in doubles); only r1, r2, |u|, |v| and |n| need
// bounds.
//
// Error bound of r1 (r2 likewise) for q exact doubles (the caller checks),
// computed as û = fl(q1 - q0), a = fl(fl(y0 û0 + y1 û1) + y2 û2),
// s = fl(fl(û0^2 + û1^2) + û2^2), r̂1 = fl(a - fl(s / 2)) (Higham, Accuracy and
// Stability of Numerical Algorithms, 2nd ed., 2002, §2.2 and §3.1; u = 2^-53,
// u' = u / (1 - u), γ4 = 4u / (1 - 4u)):
//   * |u_i - û_i| <= u'|û_i| (round to nearest; a subnormal difference is
//     exact), so |y.u - y.û| <= u' Σ|y_i||û_i| and
//     ||u|^2 - |û|^2| <= (2u' + u'^2) Σ û_i^2;
//   * each of the six terms meets at most four roundings (a product, two
//     sums, the difference; the halving is exact unless it underflows), so
//     the evaluation adds at most γ4 (Σ|y_i||û_i| + Σ û_i^2 / 2);
//   * an underflowing product, square or halving adds at most 2^-1075 each
//     (sums of subnormals are exact, Hauser 1996), seven in all;
// hence, with P = Σ|y_i||û_i| and S = Σ û_i^2 (u' + γ4 < 5.0001u, below
// 0x1.41p-51 = 5.0156u; u' + u'^2/2 + γ4/2 < 3.0001u, below 0x1.81p-52 =
// 3.0078u):
//   |r1 - r̂1| <= 0x1.41p-51 P + 0x1.81p-52 S + 2^-1072   =: e1.
// |u| <= (1 + u') |û| (each component), and |n| >= sqrt(nn.lo) for the
// caller's enclosure nn of |n|^2 (from an enclosure of n itself).
// The bounds are computed in doubles: sums of positive terms over at most a
// dozen roundings, so a relative slack of 2^-44 and an absolute one of
// 2^-1068 cover them (as in algorithms/pencil_parameter.hpp), square roots
// rounded outwards (sqrt_up; the lower one by Iv::lower_rel, |n|^2 being
// normal here), and d rounded up (Iv::upper_rel, and 2^-1074 more for a
// subnormal quotient).
//
// No answer (nullopt) on an overflow or a NaN anywhere, |n|^2 < 2^-900 (a
// degenerate facet), or d > 2^-20 max|y_i| (a sliver, where the interval
// circumcentre is the better bound). The caller then uses circumball.hpp.
#pragma once
#include <array>
#include <cmath>
#include <optional>

#include "algorithms/interval.hpp"

namespace dlab {

template <int D>
struct AxisPoint {
  std::array<double, D> y;  // q0 + y lies within d of the axis
  double d;
};

// A bound of the distance from q0 + y to the axis, for any y (the header's
// d). q: the triangle (exact doubles); n, nn: enclosures of (q1 - q0) x (q2 -
// q0) and of its squared norm. nullopt on an overflow, a NaN or
// nn.lo < 2^-900.
inline std::optional<double> pencil_axis_distance(const std::array<std::array<double, 3>, 3>& q,
                                                  const std::array<double, 3>& y, Iv nn) {
  using std::fabs;
  // The residuals and their bounds, in the order of the header.
  const auto residual = [&](int j, double& bound, double& length) {
    std::array<double, 3> w;
    for (int i = 0; i < 3; ++i) w[i] = q[j][i] - q[0][i];
    const double ww = (w[0] * w[0] + w[1] * w[1]) + w[2] * w[2];
    const double dot = (y[0] * w[0] + y[1] * w[1]) + y[2] * w[2];
    const double p = (fabs(y[0]) * fabs(w[0]) + fabs(y[1]) * fabs(w[1])) + fabs(y[2]) * fabs(w[2]);
    bound = (0x1.41p-51 * p + 0x1.81p-52 * ww + 0x1p-1072) * (1 + 0x1p-44) + 0x1p-1068;
    length = sqrt_up((ww * (1 + 0x1p-50)) * (1 + 0x1p-44) + 0x1p-1068);  // >= |w| (exact)
    return dot - ww / 2;
  };
  double e1, e2, lu, lv;
  const double r1 = residual(1, e1, lu), r2 = residual(2, e2, lv);
  // Each test is false for NaN.
  if (!(nn.lo >= 0x1p-900 && nn.lo < HUGE_VAL)) return std::nullopt;
  const double ln = Iv::lower_rel(std::sqrt(nn.lo));
  const double num = ((fabs(r1) + e1) * lv + (fabs(r2) + e2) * lu) * (1 + 0x1p-44) + 0x1p-1068;
  const double d = Iv::upper_rel(num / ln) + 0x1p-1074;
  if (!(d < HUGE_VAL)) return std::nullopt;
  return d;
}

// A point y near the axis (the circumcentre's formula of circumball.hpp
// evaluated in doubles, from the upper ends of n) and its distance bound.
inline std::optional<AxisPoint<3>> pencil_axis_point(const std::array<std::array<double, 3>, 3>& q,
                                                  const std::array<Iv, 3>& n, Iv nn) {
  std::array<double, 3> u, v, m;
  for (int i = 0; i < 3; ++i) u[i] = q[1][i] - q[0][i], v[i] = q[2][i] - q[0][i], m[i] = n[i].hi;
  const double uu = (u[0] * u[0] + u[1] * u[1]) + u[2] * u[2];
  const double vv = (v[0] * v[0] + v[1] * v[1]) + v[2] * v[2];
  const double mm = (m[0] * m[0] + m[1] * m[1]) + m[2] * m[2];
  const std::array<double, 3> vm = {v[1] * m[2] - v[2] * m[1], v[2] * m[0] - v[0] * m[2], v[0] * m[1] - v[1] * m[0]};
  const std::array<double, 3> mu = {m[1] * u[2] - m[2] * u[1], m[2] * u[0] - m[0] * u[2], m[0] * u[1] - m[1] * u[0]};
  const double inv = 0.5 / mm;
  AxisPoint<3> a;
  double ymax = 0;
  for (int i = 0; i < 3; ++i) {
    a.y[i] = (uu * vm[i] + vv * mu[i]) * inv;
    ymax = std::fmax(ymax, std::fabs(a.y[i]));
  }
  const std::optional<double> d = pencil_axis_distance(q, a.y, nn);
  if (!d || !(ymax < HUGE_VAL && *d <= 0x1p-20 * ymax)) return std::nullopt;
  a.d = *d;
  return a;
}

// 2D: the pencil of circles through an edge q0 q1 (exact doubles) has its
// centres on the perpendicular bisector, through X = q0 + u/2 (u = q1 - q0).
// With û = fl(q1 - q0), y = û/2 errs by |u_i - û_i|/2 <= u'|û_i|/2 per axis
// (and the halving by 2^-1075 where it underflows), so
//   |X - (q0 + y)| <= 2^-54 (1 + 2u)(|û0| + |û1|) + 2^-1074,
// below d = fl(fl(|û0| + |û1|) 2^-52) + 2^-1073 (four times the main term:
// plenty for the sum's rounding and an underflow of the product; the
// distance itself is 2^-1000 of the edge or less). nullopt on overflow or NaN.
inline std::optional<AxisPoint<2>> edge_axis_point(const std::array<std::array<double, 2>, 2>& q) {
  AxisPoint<2> a;
  double s = 0;
  for (int i = 0; i < 2; ++i) {
    const double u = q[1][i] - q[0][i];
    a.y[i] = u / 2;
    s += std::fabs(u);
  }
  a.d = s * 0x1p-52 + 0x1p-1073;
  if (!(a.d < HUGE_VAL)) return std::nullopt;  // NaN too
  return a;
}

}  // namespace dlab
