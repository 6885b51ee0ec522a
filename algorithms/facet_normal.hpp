// An enclosure of a triangle's normal n = (q1 - q0) x (q2 - q0) in 3D, from
// plain doubles with an a-priori error bound, for Tanemura's searches
// (algorithms/tanemura.hpp, search). Exact interval products (tight_sub,
// tight_mul: algorithms/interval.hpp) cost about 700 instructions a search,
// 5 % of Tanemura's on uniform 3D input.
//
// For q exact doubles (the caller checks), computed as û = fl(q1 - q0),
// v̂ = fl(q2 - q0), a = fl(û1 v̂2), b = fl(û2 v̂1), m0 = fl(a - b) (n0; n1 and n2
// by rotating the indices). Error bound (Higham, Accuracy and Stability of
// Numerical Algorithms, 2nd ed., 2002, §2.2; u = 2^-53, u' = u / (1 - u)),
// with no underflow or overflow (below):
//   * |u_i - û_i| <= u'|û_i| (round to nearest), so
//     |u1 v2 - û1 v̂2| <= (2u' + u'^2) |û1 v̂2| <= (2u' + u'^2)(1 + u') |a|;
//   * |a - û1 v̂2| <= u'|a|, likewise b;
//   * |m0 - (a - b)| <= u'|m0| <= u'(1 + u)(|a| + |b|);
// hence |n0 - m0| <= (4u' + 3u'^2 + u u' + u'^3)(|a| + |b|), and
// 4u' + ... < 4.0001u, below 0x1.01p-51 = 4.0156u:
//   |n0 - m0| <= 0x1.01p-51 (|a| + |b|)   =: e0.
// e0 is computed in doubles, three roundings of positive terms (the sum, the
// product, a slack factor 1 + 2^-44 that covers them), with no underflow:
// every nonzero |û_i|, |v̂_i| lies in [2^-500, 2^500), so every nonzero
// product in [2^-1000, 2^1000). A zero product is exact (a zero factor), so
// where both are zero m0 = e0 = 0: a component that vanishes (an
// axis-parallel facet) stays an exact zero. The enclosure is
// [lower_rel(m0 - e0), upper_rel(m0 + e0)] (sound for a normal result; a
// subnormal difference is exact).
//
// No answer (nullopt): a nonzero |û_i| or |v̂_i| outside [2^-500, 2^500), a
// NaN, or short operands: when the significant bits of the longest û_i and
// the longest v̂_i add up to at most 53, every product is exact (lattices,
// grid points), and the exact interval products keep the normal a point,
// which prunes exactly. The caller then uses those.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>

#include "algorithms/interval.hpp"

namespace dlab {

// The bits of x's significand from its leading one to its last one (53 for
// a full significand; an upper bound for a subnormal x, 1 for zero).
inline int significant_bits(double x) {
  const std::uint64_t frac = std::bit_cast<std::uint64_t>(x) & ((std::uint64_t{1} << 52) - 1);
  return 53 - std::countr_zero(frac | (std::uint64_t{1} << 52));
}

inline std::optional<std::array<Iv, 3>> facet_normal(const std::array<std::array<double, 3>, 3>& q) {
  using std::fabs;
  std::array<double, 3> u, v;
  bool out_of_range = false;
  int bits_u = 0, bits_v = 0;
  for (int i = 0; i < 3; ++i) {
    u[i] = q[1][i] - q[0][i];
    v[i] = q[2][i] - q[0][i];
    for (const double x : {u[i], v[i]})
      out_of_range |= x != 0 && !(fabs(x) >= 0x1p-500 && fabs(x) < 0x1p500);  // NaN too
    bits_u = std::max(bits_u, significant_bits(u[i]));
    bits_v = std::max(bits_v, significant_bits(v[i]));
  }
  if (out_of_range || bits_u + bits_v <= 53) return std::nullopt;
  std::array<Iv, 3> n;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double a = u[j] * v[k], b = u[k] * v[j], m = a - b;
    const double e = ((fabs(a) + fabs(b)) * 0x1.01p-51) * (1 + 0x1p-44);
    n[i] = {Iv::lower_rel(m - e), Iv::upper_rel(m + e)};
  }
  return n;
}

}  // namespace dlab
