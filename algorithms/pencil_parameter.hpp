// An upper bound of the pencil parameter of Tanemura's pruning ball
// (algorithms/tanemura.hpp, ball_of), in plain doubles with an a-priori error
// bound instead of interval arithmetic (forty interval operations a ball were
// a fifth of Tanemura's instructions).
//
// The spheres through a facet have centres C + t n; the one through a point c
// has
//   t* = N* / (2 D*),  N* = |e|^2 + 2 e.g,  D* = n.e,
// with e = c - v (v a facet vertex), g = v - C and n the facet's normal. Here
// e = x - q for doubles x, q (scaled coordinates that are exact: the caller
// checks), and g, n are given as enclosures [lo, hi]. Computed with ĝ = g.hi,
// n̂ = n.hi, ẽ = fl(x - q), in this order:
//   N = fl(fl(ẽ0^2 + ẽ1^2) + ẽ2^2) + 2 fl(fl(ẽ0 ĝ0 + ẽ1 ĝ1) + ẽ2 ĝ2),
//   b = 2 fl(fl(n̂0 ẽ0 + n̂1 ẽ1) + n̂2 ẽ2),   t = fl(N / b)
// (2D: the same without index 2). Error bound (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., 2002, §2.2 and §3.1; u = 2^-53, γk = ku/(1-ku),
// u' = u/(1-u) < 2^-52; an underflowing product adds at most 2^-1075):
//   * |e - ẽ| <= u'|ẽ| (round to nearest; a subnormal difference is exact);
//     |g - ĝ| <= ρg = g.hi - g.lo, and |n - n̂| <= ρn likewise;
//   * |e^2 - ẽ^2| <= (2u' + u'^2) ẽ^2, and
//     |e g - ẽ ĝ| <= |e||g - ĝ| + |e - ẽ||ĝ| <= (1+u')^2 |ẽ| ρ̂g + u'|ẽ||ĝ|
//     (ρ̂ = fl(hi - lo) >= (hi - lo)/(1+u'));
//   * every term of N and b meets at most four roundings (a product, three
//     sums), so the evaluation adds at most γ4 times the sum of |terms|;
// hence, with sA = Σ ẽ^2, sB = Σ |ẽ||ĝ|, sG = Σ |ẽ| ρ̂g, sD = Σ |ẽ||n̂|,
// sN = Σ |ẽ| ρ̂n (γ4 + 2u' + u'^2 < 6.25u, 2 (γ4 + u') < 10.5u, γ3 + u' < 4.25u):
//   |N* - N| <= 0x1.9p-51 sA + 0x1.5p-50 sB + 2 (1 + 2^-51) sG + 2^-1072  =: ΔN,
//   |2D* - b| <= 2 (0x1.1p-51 sD + (1 + 2^-51) sN + 2^-1073)             =: Δb.
// Where |b| > Δb (b and 2D* share a sign, |2D*| >= |b| - Δb):
//   |t* - N/b| = |(N* - N) b - N (2D* - b)| / (|b| |2D*|) <= (ΔN + |N/b| Δb) / (|b| - Δb),
// and |N/b - t| <= u'|t| + 2^-1075, |N/b| <= (1+u')|t| + 2^-1075, so
//   |t* - t| <= (ΔN + (1+u')|t| Δb) / (|b| - Δb) + u'|t| + 2^-1074
// (the 2^-1075 Δb / (|b| - Δb) is below 2^-1075 where |b| > 2 Δb).
// The bounds themselves are computed in doubles: each is a sum of positive
// terms over at most a dozen roundings, so a relative slack of 2^-44 and an
// absolute one of 2^-1068 (for underflows) cover them; |b| - Δb is rounded
// down (Iv::lower_rel: it is normal, at least |b| / 2). The result is then
// fl(t + Δt) rounded up (Iv::upper_rel: sound for a normal sum; a subnormal
// sum is exact).
//
// No answer (nullopt) where the bound does not apply or does not help: an
// overflow or a NaN anywhere, |b| < 2^-900 (so that |b| - Δb is normal, and
// the absolute slacks add at most 2^-166 to T, where the tree's scaled
// coordinates are at most about 1), or |b| <= 2 Δb (c nearly on the facet's
// plane, where T would be far from t*).
// The caller then falls back to interval arithmetic.
#pragma once
#include <array>
#include <cmath>
#include <optional>

#include "algorithms/interval.hpp"

namespace dlab {

template <int D>
std::optional<double> pencil_parameter_upper(const std::array<double, D>& x, const std::array<double, D>& q,
                                             const std::array<Iv, D>& g, const std::array<Iv, D>& n) {
  using std::fabs;
  std::array<double, D> e;
  for (int i = 0; i < D; ++i) e[i] = x[i] - q[i];
  // The evaluation order of the header (sequential sums from index 0).
  double a = e[0] * e[0], c = e[0] * g[0].hi, d = n[0].hi * e[0];
  double sB = fabs(e[0]) * fabs(g[0].hi), sG = fabs(e[0]) * (g[0].hi - g[0].lo);
  double sD = fabs(e[0]) * fabs(n[0].hi), sN = fabs(e[0]) * (n[0].hi - n[0].lo);
  for (int i = 1; i < D; ++i) {
    a += e[i] * e[i];
    c += e[i] * g[i].hi;
    d += n[i].hi * e[i];
    sB += fabs(e[i]) * fabs(g[i].hi);
    sG += fabs(e[i]) * (g[i].hi - g[i].lo);
    sD += fabs(e[i]) * fabs(n[i].hi);
    sN += fabs(e[i]) * (n[i].hi - n[i].lo);
  }
  const double num = a + 2 * c, b = 2 * d;
  const double sA = a;  // Σ ẽ^2 is a itself (a sum of squares)
  constexpr double slack = 1 + 0x1p-44, tiny = 0x1p-1068;
  const double dn = (0x1.9p-51 * sA + 0x1.5p-50 * sB + 2 * (1 + 0x1p-51) * sG + 0x1p-1072) * slack + tiny;
  const double db = 2 * (0x1.1p-51 * sD + (1 + 0x1p-51) * sN + 0x1p-1073) * slack + tiny;
  const double ab = fabs(b);
  // Each test is false for NaN: every NaN or infinity gives no answer.
  if (!(ab >= 0x1p-900 && ab < HUGE_VAL && ab > 2 * db && dn < HUGE_VAL && fabs(num) < HUGE_VAL))
    return std::nullopt;
  const double t = num / b, at = fabs(t);
  const double dt = ((dn + (1 + 0x1p-52) * at * db) / Iv::lower_rel(ab - db) + 0x1p-52 * at + 0x1p-1074) * slack + tiny;
  const double up = Iv::upper_rel(t + dt);
  if (!(fabs(up) < HUGE_VAL)) return std::nullopt;
  return up;
}

}  // namespace dlab
