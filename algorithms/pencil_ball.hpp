// A sphere of Tanemura's pencil through a facet, in plain doubles with an
// a-priori error bound (algorithms/tanemura.hpp, ball_of): an enclosure of its
// centre and an upper bound of its squared radius. The same in interval
// arithmetic cost about 360 instructions a ball and 200 a search (3D uniform).
//
// The pencil: spheres through the triangle q0 q1 q2 (exact doubles), centred
// at X + t n for the point X of the circumcircle's axis L nearest q0 + y
// (algorithms/pencil_axis.hpp: |X - (q0 + y)| <= d) and the exact normal n,
// given as an enclosure [lo, hi] (algorithms/facet_normal.hpp or interval
// products). For a double T the sphere S_T has centre c = X + T n and
// squared radius |q0 - c|^2 (q0 is on every sphere of the pencil).
//
// Evaluation, per search: z = fl(q0 + y), m = hi, ρ = fl(hi - lo); per T:
// p = fl(T m), ĉ = fl(z + p), ŵ = fl(q0 - ĉ) (each per axis). Bounds (Higham,
// Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002, §2.2; u =
// 2^-53, u' = u / (1 - u) < 2^-52; round to nearest, a subnormal sum or
// difference is exact, an underflowing product errs by at most 2^-1075):
//   * |X_i - z_i| <= d + u'|z_i|;
//   * |n_i - m_i| <= hi - lo <= (1 + u') ρ_i;
//   * |p_i - T m_i| <= u'|p_i| + 2^-1075,  |ĉ_i - (z_i + p_i)| <= u'|ĉ_i|;
// hence
//   |c_i - ĉ_i| <= d + |T| (1 + u') ρ_i + u' (|z_i| + |p_i| + |ĉ_i|) + 2^-1075  =: δ_i,
// and, as |ŵ_i - (q0_i - ĉ_i)| <= u'|ŵ_i|,
//   |q0 - c|^2 <= Σ ((1 + u') |ŵ_i| + δ_i)^2  =: r2.
// δ and r2 are computed in doubles: sums and products of positive terms over
// at most a dozen roundings (with the per-search terms), so a relative slack
// of 2^-44 and an absolute one of 2^-1068 (underflows) cover them, as in
// algorithms/pencil_parameter.hpp.
//
// No answer (nullopt) on an overflow or a NaN (T far beyond the scaled
// coordinates' range): the caller then has no ball (no pruning).
#pragma once
#include <array>
#include <cmath>
#include <optional>

#include "algorithms/interval.hpp"

namespace dlab {

// The per-search terms.
struct PencilBase {
  std::array<double, 3> q0, z, m;
  std::array<double, 3> near;  // d + u'|z_i| + 2^-1075: bounds |X_i - z_i| (and the product's underflow)
  std::array<double, 3> tilt;  // (1 + u') ρ_i: bounds |n_i - m_i|
};

inline PencilBase pencil_base(const std::array<double, 3>& q0, const std::array<double, 3>& y, double d,
                              const std::array<Iv, 3>& n) {
  PencilBase b;
  for (int i = 0; i < 3; ++i) {
    b.q0[i] = q0[i];
    b.z[i] = q0[i] + y[i];
    b.m[i] = n[i].hi;
    b.near[i] = d + 0x1p-52 * std::fabs(b.z[i]) + 0x1p-1074;
    b.tilt[i] = (n[i].hi - n[i].lo) * (1 + 0x1p-52);
  }
  return b;
}

struct PencilBall {
  std::array<double, 3> centre;  // ĉ
  std::array<double, 3> delta;   // |c_i - ĉ_i| <= delta_i
  double r2;                     // >= |q0 - c|^2
};

inline std::optional<PencilBall> pencil_ball(const PencilBase& b, double T) {
  using std::fabs;
  constexpr double slack = 1 + 0x1p-44, tiny = 0x1p-1068;
  PencilBall s;
  const double at = fabs(T);
  double r2 = 0;
  for (int i = 0; i < 3; ++i) {
    const double p = T * b.m[i];
    s.centre[i] = b.z[i] + p;
    s.delta[i] = (b.near[i] + at * b.tilt[i] + 0x1p-52 * (fabs(p) + fabs(s.centre[i]))) * slack + tiny;
    const double a = fabs(b.q0[i] - s.centre[i]) * (1 + 0x1p-52) + s.delta[i];
    r2 += a * a;
  }
  s.r2 = r2 * slack + tiny;
  if (!(s.r2 < HUGE_VAL)) return std::nullopt;  // NaN too; then every delta_i is finite
  return s;
}

}  // namespace dlab
