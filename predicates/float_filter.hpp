// FloatFilter: a semi-static forward-error filter over doubles. Each predicate
// returns the sign of the double determinant (the same expression tree as
// FloatKernel, predicates/determinants.hpp) when a rigorous bound on its error
// proves the sign, and std::nullopt ("cannot decide") otherwise. It is the
// `Fast` half of filtered<FloatFilter, Exact> (predicates/filtered.hpp).
//
// The bound (standard forward error analysis, Higham, "Accuracy and Stability
// of Numerical Algorithms", ch. 2-3; the semi-static form of Meyer & Pion's FPG
// and of CGAL's static filters). u = 2^-53, round to nearest, no FMA
// (-ffp-contract=off). Mx, My, Mz = the largest |computed coordinate
// difference| per axis in the call (the differences the determinant uses).
// For every computed quantity x~ we carry m (|x~| <= m) and e (|x~ - x| <= e,
// x the exact value from the exact inputs), as polynomials in the M's:
//   difference  d~ = fl(p - q):  m = M,                e = u M   (|fl(t) - t| <= u |fl(t)|;
//                                                       a subnormal difference is exact)
//   sum/diff    z~ = fl(x~ +- y~): m = (mx + my)(1+u),  e = u (mx + my) + ex + ey
//                                                       (a subnormal sum is exact)
//   product     z~ = fl(x~ y~):   m = mx my (1+2u),    e = 2u mx my + mx ey + (my + ey) ex
// In a product the second u covers underflow: the absolute error of a rounded
// product is <= u|z| + 2^-1075, and 2^-1075 <= u * (every monomial of degree
// k <= deg) as long as every M >= lo with lo^deg >= 2^-1022 (checked below).
// Every monomial of these determinants' expansions (and so of e) has at least
// one factor of each axis and total degree deg, hence is <= Mx My [Mz] Mmax^(deg-D).
// Evaluating the rules with every M = 1 (struct Bound below runs the very
// expression tree of determinants.hpp) therefore gives the constant c with
//   |det~ - det| <= c * Mx My [Mz] Mmax^(deg - D).
// The constant is inflated by 2^-40 relative to cover the rounding of its own
// constexpr evaluation (<= 200 positive operations) and of the run-time product
// c*Mx*My*... (<= 5 roundings, each partial product normal: c lo^deg >= 2^-1022).
// Guards: M == 0 on some axis means every difference on that axis is exactly
// zero (fl(p - q) == 0 iff p == q), so the determinant is exactly zero; M outside
// [lo, hi] (or NaN/inf) declines. hi keeps every intermediate finite:
// m_det * hi^deg < 2^1020.
#pragma once
#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "predicates/determinants.hpp"
#include "predicates/kernel.hpp"

namespace dlab {

namespace filter_bound {

constexpr double u = 0x1p-53;

// m and e in units where every |coordinate difference| <= 1. A raw coordinate
// (converted from double) may only be subtracted from another raw coordinate.
struct Bound {
  double m = 0, e = 0;
  bool raw = false;
  constexpr Bound() = default;
  constexpr Bound(double, double m_, double e_) : m(m_), e(e_) {}
  constexpr explicit Bound(double) : raw(true) {}
};

constexpr Bound operator+(const Bound& x, const Bound& y) {
  if (x.raw || y.raw) throw "a raw coordinate may only appear in a difference";
  const double s = x.m + y.m;
  return {0, s * (1 + u), u * s + x.e + y.e};
}
constexpr Bound operator-(const Bound& x, const Bound& y) {
  if (x.raw && y.raw) return {0, 1, u};  // a coordinate difference
  return x + y;                          // same bounds as a sum
}
constexpr Bound operator*(const Bound& x, const Bound& y) {
  if (x.raw || y.raw) throw "a raw coordinate may only appear in a difference";
  const double p = x.m * y.m;
  return {0, p * (1 + 2 * u), 2 * u * p + x.m * y.e + (y.m + y.e) * x.e};
}

constexpr double inflate(double c) { return c * (1 + 0x1p-40); }
constexpr double pow2(int k) {
  double r = 1;
  for (int i = 0; i < (k < 0 ? -k : k); ++i) r = k < 0 ? r / 2 : r * 2;
  return r;
}
constexpr double ipow(double x, int k) {
  double r = 1;
  for (int i = 0; i < k; ++i) r *= x;
  return r;
}

constexpr Point2 o2{0, 0};
constexpr Point3 o3{0, 0, 0};
constexpr Bound orient2d_b = det::orient2d<Bound>(o2, o2, o2);
constexpr Bound incircle_b = det::incircle<Bound>(o2, o2, o2, o2);
constexpr Bound orient3d_b = det::orient3d<Bound>(o3, o3, o3, o3);
constexpr Bound insphere_b = det::insphere<Bound>(o3, o3, o3, o3, o3);

// Per predicate: degree, lower and upper guard on every M, error constant.
struct Spec {
  int degree;
  double lo, hi, c;
};
constexpr Spec orient2d_spec{2, pow2(-480), pow2(500), inflate(orient2d_b.e)};
constexpr Spec incircle_spec{4, pow2(-240), pow2(250), inflate(incircle_b.e)};
constexpr Spec orient3d_spec{3, pow2(-320), pow2(330), inflate(orient3d_b.e)};
constexpr Spec insphere_spec{5, pow2(-192), pow2(200), inflate(insphere_b.e)};

// lo^deg >= 2^-1022 makes 2^-1075 <= u * (any monomial); c lo^deg >= 2^-1022 keeps the
// run-time bound c*Mx*My*... (every partial product included) normal; hi keeps the
// determinant and every intermediate finite.
constexpr bool guards_hold(const Spec& s, const Bound& b) {
  return ipow(s.lo, s.degree) >= pow2(-1022) && s.c * ipow(s.lo, s.degree) >= pow2(-1022) &&
         b.m * ipow(s.hi, s.degree) < pow2(1020);
}
static_assert(guards_hold(orient2d_spec, orient2d_b));
static_assert(guards_hold(incircle_spec, incircle_b));
static_assert(guards_hold(orient3d_spec, orient3d_b));
static_assert(guards_hold(insphere_spec, insphere_b));
// Sanity: the constants are a small multiple of u (about deg + a few roundings).
static_assert(orient2d_spec.c > 2 * u && orient2d_spec.c < 16 * u);
static_assert(incircle_spec.c > 8 * u && incircle_spec.c < 256 * u);
static_assert(orient3d_spec.c > 6 * u && orient3d_spec.c < 256 * u);
static_assert(insphere_spec.c > 16 * u && insphere_spec.c < 4096 * u);

// Decision: 0 axis-extent means exact zero; outside [lo, hi] declines.
enum class Range { zero, ok, out };
inline Range classify(double m, const Spec& s) {
  if (m == 0) return Range::zero;
  return (m >= s.lo && m <= s.hi) ? Range::ok : Range::out;  // NaN -> out
}

}  // namespace filter_bound

struct FloatFilter {
  static constexpr std::string_view name = "float-filter";

  std::optional<Sign> orient2d(const Point2& a, const Point2& b, const Point2& c) const {
    using namespace filter_bound;
    const double mx = std::max(std::fabs(a[0] - c[0]), std::fabs(b[0] - c[0]));
    const double my = std::max(std::fabs(a[1] - c[1]), std::fabs(b[1] - c[1]));
    return decide2(det::orient2d<double>(a, b, c), mx, my, orient2d_spec);
  }

  std::optional<Sign> incircle(const Point2& a, const Point2& b, const Point2& c,
                               const Point2& d) const {
    using namespace filter_bound;
    const double mx =
        std::max({std::fabs(a[0] - d[0]), std::fabs(b[0] - d[0]), std::fabs(c[0] - d[0])});
    const double my =
        std::max({std::fabs(a[1] - d[1]), std::fabs(b[1] - d[1]), std::fabs(c[1] - d[1])});
    return decide2(det::incircle<double>(a, b, c, d), mx, my, incircle_spec);
  }

  std::optional<Sign> orient3d(const Point3& a, const Point3& b, const Point3& c,
                               const Point3& d) const {
    using namespace filter_bound;
    double m[3];
    for (int i = 0; i < 3; ++i)
      m[i] = std::max({std::fabs(a[i] - d[i]), std::fabs(b[i] - d[i]), std::fabs(c[i] - d[i])});
    return decide3(det::orient3d<double>(a, b, c, d), m, orient3d_spec);
  }

  std::optional<Sign> insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                               const Point3& e) const {
    using namespace filter_bound;
    double m[3];
    for (int i = 0; i < 3; ++i)
      m[i] = std::max({std::fabs(a[i] - e[i]), std::fabs(b[i] - e[i]), std::fabs(c[i] - e[i]),
                       std::fabs(d[i] - e[i])});
    return decide3(det::insphere<double>(a, b, c, d, e), m, insphere_spec);
  }

 private:
  static std::optional<Sign> decide2(double det, double mx, double my,
                                     const filter_bound::Spec& s) {
    using filter_bound::Range;
    const Range rx = filter_bound::classify(mx, s), ry = filter_bound::classify(my, s);
    if (rx == Range::zero || ry == Range::zero) return Sign::zero;
    if (rx == Range::out || ry == Range::out) return std::nullopt;
    const double mmax = std::max(mx, my);
    double bound = s.c * mx * my;
    for (int i = 2; i < s.degree; ++i) bound *= mmax;
    if (det > bound) return Sign::positive;
    if (-det > bound) return Sign::negative;
    return std::nullopt;
  }

  static std::optional<Sign> decide3(double det, const double (&m)[3],
                                     const filter_bound::Spec& s) {
    using filter_bound::Range;
    bool out = false;
    for (int i = 0; i < 3; ++i) {
      const Range r = filter_bound::classify(m[i], s);
      if (r == Range::zero) return Sign::zero;
      out = out || r == Range::out;
    }
    if (out) return std::nullopt;
    const double mmax = std::max({m[0], m[1], m[2]});
    double bound = s.c * m[0] * m[1] * m[2];
    for (int i = 3; i < s.degree; ++i) bound *= mmax;
    if (det > bound) return Sign::positive;
    if (-det > bound) return Sign::negative;
    return std::nullopt;
  }
};

}  // namespace dlab
