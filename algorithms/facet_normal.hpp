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
// with no underflow or overflow in the differences and products (below):
//   * |u_i - û_i| <= u'|û_i| (round to nearest), so
//     |u1 v2 - û1 v̂2| <= (2u' + u'^2) |û1 v̂2| <= (2u' + u'^2)(1 + u') |a|;
//   * |a - û1 v̂2| <= u'|a|, likewise b;
//   * |m0 - (a - b)| <= u'|m0| <= u'(1 + u)(|a| + |b|);
// hence |n0 - m0| <= (4u' + 3u'^2 + u u' + u'^3)(|a| + |b|), and
// 4u' + ... < 4.0001u, below 0x1.01p-51 = 4.0156u:
//   |n0 - m0| <= 0x1.01p-51 (|a| + |b|)   =: e0.
// Where the six differences are exact, only the products and the
// subtraction round, each by at most u times its result (Higham Thm 2.3,
// fl(x) = x / (1 + δ)), so
//   |n0 - m0| <= u (|a| + |b| + |m0|) <= 0x1.01p-53 (|a| + |b| + |m0|) =: e0,
// about half the first bound (a sphere through a few-ulp-close cospherical
// set prunes with the normal's width: session 36, papers/triangulation_costs.md).
// The differences are taken as exact where |fl(x - y)| <= min(|x|, |y|) for
// each (x, y) = (q1_i, q0_i), (q2_i, q0_i), a sufficient condition: for x, y
// of one sign, x - y inexact means (Sterbenz's lemma) x > 2y > 0, say, so
// x - y > y and fl(x - y) >= y, with equality only for x - y within half an
// ulp of y, i.e. x in (2y, 2y + ulp(y) / 2], which holds no double; for
// signs that differ, fl(|x| + |y|) >= max(|x|, |y|), equal to the minimum
// only if |x| = |y|, and then the sum is 2|x|. Most small facets pass: their
// coordinates lie within a factor two of each other.
// e0 is computed in doubles from positive terms, each rounding within u of
// the exact result or, below the normal range, within 2^-1075 of it. The
// constants' margins (4.0156u against 4.0001u, 1.0039u against u) exceed
// both: every nonzero |û_i|, |v̂_i| lies in [2^-500, 2^500), so every nonzero
// product in [2^-1000, 2^1000), and the margin is at least 2^-62 2^-1000.
// A zero product is exact (a zero factor), so where both are zero
// m0 = e0 = 0: a component that vanishes (an axis-parallel facet) stays an
// exact zero. The enclosure is [lower_rel(m0 - e0), upper_rel(m0 + e0)]
// (sound for a normal result; a subnormal difference is exact).
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

// The bits of the significand from its leading one to its last one, of a
// double's bit pattern (53 for a full significand; an upper bound for a
// subnormal, 1 for zero). Of several patterns ORed: the most among them (the
// OR's lowest set bit is the lowest of any).
inline int significant_bits_of(std::uint64_t bits) {
  const std::uint64_t frac = bits & ((std::uint64_t{1} << 52) - 1);
  return 53 - std::countr_zero(frac | (std::uint64_t{1} << 52));
}
inline int significant_bits(double x) { return significant_bits_of(std::bit_cast<std::uint64_t>(x)); }

// x = 0 or 2^-500 <= |x| < 2^500 (not NaN): the bit patterns of non-negative
// doubles, +inf and NaN above the finite ones, are in the order of their
// values; the shift drops the sign.
inline bool zero_or_moderate(double x) {
  const std::uint64_t b = std::bit_cast<std::uint64_t>(x) << 1;
  constexpr std::uint64_t lo = std::bit_cast<std::uint64_t>(0x1p-500) << 1;
  constexpr std::uint64_t hi = std::bit_cast<std::uint64_t>(0x1p500) << 1;
  return (b == 0) | (b - lo < hi - lo);
}

// d = fl(x - y) is x - y exactly if |d| <= min(|x|, |y|) (see above).
inline bool difference_known_exact(double x, double y, double d) {
  return std::fabs(d) <= std::min(std::fabs(x), std::fabs(y));
}

inline std::optional<std::array<Iv, 3>> facet_normal(const std::array<std::array<double, 3>, 3>& q) {
  using std::fabs;
  std::array<double, 3> u, v;
  bool in_range = true, exact_differences = true;
  std::uint64_t bits_u = 0, bits_v = 0;  // the patterns ORed (significant_bits_of)
  for (int i = 0; i < 3; ++i) {
    u[i] = q[1][i] - q[0][i];
    v[i] = q[2][i] - q[0][i];
    in_range &= zero_or_moderate(u[i]) & zero_or_moderate(v[i]);
    exact_differences &= difference_known_exact(q[1][i], q[0][i], u[i]);
    exact_differences &= difference_known_exact(q[2][i], q[0][i], v[i]);
    bits_u |= std::bit_cast<std::uint64_t>(u[i]);
    bits_v |= std::bit_cast<std::uint64_t>(v[i]);
  }
  if (!in_range || significant_bits_of(bits_u) + significant_bits_of(bits_v) <= 53) return std::nullopt;
  std::array<Iv, 3> n;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double a = u[j] * v[k], b = u[k] * v[j], m = a - b;
    const double e = exact_differences ? ((fabs(a) + fabs(b)) + fabs(m)) * 0x1.01p-53
                                       : (fabs(a) + fabs(b)) * 0x1.01p-51;
    n[i] = {Iv::lower_rel(m - e), Iv::upper_rel(m + e)};
  }
  return n;
}

}  // namespace dlab
