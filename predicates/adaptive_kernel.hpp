// `adaptive`: Shewchuk's adaptive-precision predicates, written from the
// mathematics of J. R. Shewchuk, "Adaptive Precision Floating-Point Arithmetic
// and Fast Robust Geometric Predicates", DCG 18 (1997), section 4 (orient2d,
// orient3d, incircle, insphere; stages A, B, C, D). The first stage is inline
// and branch-light: Shewchuk's stage A for orient2d, a semi-static filter for
// orient3d (bound from the largest |coordinate difference| per axis, as in
// CGAL's and Geogram's filters; our own constants, derived below), and for
// incircle and insphere (bounds from the lifts they compute anyway). Everything
// after it is out of line.
//
// Stages (stage_names): 0 "filter", 1 "A", 2 "B", 3 "C", 4 "D", 5 "mp", 6 "static".
//   static: orient3d only, when fitted: |det| > one bound for the whole input
//           (Devillers & Pion 2003; error_bounds.md 3.5), tested before filter
//   filter: |det| > c * S^2 (incircle), c * mx my mz (orient3d), c * L^2 mz
//           (insphere; L the largest lift)
//   A:      |det| > errboundA * permanent (inline for orient2d, and again out
//           of line after the exponent guard, adaptive_kernel.cpp)
//   B:      exact expansion of the determinant of the rounded differences
//   C:      B + first-order correction by the differences' roundoff tails
//   D:      exact determinant (expansion arithmetic)
//   mp:     MpKernel, when the inputs are outside the proven exponent range.
// Every bound and every guard is derived in predicates/error_bounds.md.
//
// Exact for every finite double input inside the documented exponent range
// (error_bounds.md section 2); outside it the answer comes from MpKernel.
// Non-finite inputs are outside every contract (MpKernel is asked anyway).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string_view>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "predicates/determinants.hpp"
#include "predicates/kernel.hpp"

namespace dlab {

namespace adaptive {

inline constexpr double eps = 0x1p-53;  // half an ulp of 1: fl(x) = x(1 + d), |d| <= eps

// ---- Semi-static filter constants (error_bounds.md section 3) -------------------
// Forward error calculus on bounds: every computed node x^ carries (m, e) with
// |x^| <= m and |x^ - x| <= e, in units of the product of the per-axis maxima
// of its variables (x = the exact value on exact coordinate differences).
struct Eb {
  double m, e;
};
// A rounded coordinate difference d^ = fl(p - q): |d^| <= max, |d^ - d| <= eps |d^|.
inline constexpr Eb diff_node{1.0, eps};
constexpr Eb mul(Eb x, Eb y) {
  return {x.m * y.m * (1 + eps), eps * x.m * y.m + x.m * y.e + (y.m + y.e) * x.e};
}
constexpr double pow_int(double b, int n) {
  double r = 1;
  for (int i = 0; i < n; ++i) r *= b;
  return r;
}
constexpr Eb add(Eb x, Eb y) { return {(x.m + y.m) * (1 + eps), eps * (x.m + y.m) + x.e + y.e}; }
// The last operation z = fl(x +- y) is not counted: sign(fl(v)) = sign(v), and
// |x +- y| >= |z| / (1 + eps). The bound c * M1 * ... * Mr is itself computed
// with r roundings (each can lose a factor 1 + eps). 2^-40 covers the rounding
// of this constexpr evaluation; 2^-260 covers gradual-underflow crumbs allowed
// by the floors (error_bounds.md 3.2).
constexpr double filter_constant(Eb x, Eb y, int r) {
  double c = (x.e + y.e) * (1 + eps);
  for (int i = 0; i < r; ++i) c *= 1 + eps;
  return c * (1 + 0x1p-40) + 0x1p-260;
}
constexpr Eb minor2() { return add(mul(diff_node, diff_node), mul(diff_node, diff_node)); }
constexpr Eb lift2() { return add(mul(diff_node, diff_node), mul(diff_node, diff_node)); }
constexpr Eb lift3() { return add(lift2(), mul(diff_node, diff_node)); }
constexpr Eb minor3() { return add(add(mul(diff_node, minor2()), mul(diff_node, minor2())), mul(diff_node, minor2())); }

// orient2d: det = acx*bcy - acy*bcx;   bound = c * mx * my. (Derived for
// comparison only: orient2d uses stage A inline instead, see below.)
inline constexpr double o2_filter =
    filter_constant(mul(diff_node, diff_node), mul(diff_node, diff_node), 2);
// orient3d: det = (adz*m1 + bdz*m2) + cdz*m3;   bound = c * mx * my * mz. (Derived for
// comparison with the published constant; the inline filter evaluates det as
// o3_half() - o3_half() instead, constant o3_ss below.)
inline constexpr double o3_filter =
    filter_constant(add(mul(diff_node, minor2()), mul(diff_node, minor2())),
                    mul(diff_node, minor2()), 3);
// orient3d inline filter (error_bounds.md 3.4): det = s0 - s1, each s the sum
// (z(xy) + z(xy)) + z(xy) of three monomials; bound = o3_ss8 * ((mx' * my') * 8 mz'), three
// roundings, m' = max(m, o3_ss_lo) (floors against gradual underflow), the factor 8
// so that the bound overflows whenever an intermediate of det can.
constexpr Eb o3_monomial() { return mul(diff_node, mul(diff_node, diff_node)); }
constexpr Eb o3_half() { return add(add(o3_monomial(), o3_monomial()), o3_monomial()); }
inline constexpr double o3_ss = filter_constant(o3_half(), o3_half(), 3);
inline constexpr double o3_ss8 = o3_ss / 8, o3_ss_lo = 0x1p-320;
// Every computed node of det is at most 2 * o3_half().m * (1 + eps) (units mx' my' mz'),
// below 8 / (1 + eps)^2: an overflowed node forces (mx' my') 8 mz' (rounded) to +inf
// (a two-difference product x y is at most mx' my', which then overflows itself).
static_assert(2 * o3_half().m * (1 + eps) * (1 + eps) * (1 + eps) < 8);
// incircle: det = (L_a*m_a + L_b*m_b) + L_c*m_c;   bound = c * mx * my * M * M, M = max(mx, my).
// (Derived for comparison: incircle uses the cheaper lift filter ic_lift_filter below.)
inline constexpr double ic_filter =
    filter_constant(add(mul(lift2(), minor2()), mul(lift2(), minor2())), mul(lift2(), minor2()), 4);
// insphere: det = (L_d*M_d - L_c*M_c) + (L_b*M_b - L_a*M_a);   bound = c * mx*my*mz * M * M
// (the lift filter below uses the same constant in other units).
inline constexpr double is_filter =
    filter_constant(add(mul(lift3(), minor3()), mul(lift3(), minor3())),
                    add(mul(lift3(), minor3()), mul(lift3(), minor3())), 5);

// insphere lift filter (error_bounds.md 3.2): the calculus above in units where every
// squared difference is at most L (x and y in the minors each at most sqrt L) and every
// z in a minor at most mz gives |err| <= is_filter L^2 mz. The fast path bounds L by the
// largest computed lift (one more factor (1 + eps)^2: is_lift_filter) and floors L and
// mz (is_lo^2, is_lo: no harmful underflow, the bound stays normal). The bound is
// computed as is_lift128 * (((128 L') L') mz'): the factor 128 (exact) exceeds the
// 72 (1+eps)^k that bounds every intermediate of det in these units, so an overflow
// anywhere makes the bound +inf.
inline constexpr double is_lo = 0x1p-185, is_lo2 = is_lo * is_lo;
inline constexpr double is_lift_filter = is_filter * (1 + 0x1p-50);
inline constexpr double is_lift128 = is_lift_filter / 128;
constexpr Eb is_half() { return add(mul(lift3(), minor3()), mul(lift3(), minor3())); }
static_assert(2 * is_half().m * (1 + eps) * pow_int(1 + eps, 5) < 128);
// Exact-stage guard (error_bounds.md 2): every |coordinate difference| <= hi.
inline constexpr double o2_hi = 0x1p+490, o3_hi = 0x1p+325, ic_hi = 0x1p+245, is_hi = 0x1p+195;

// Published constants (design.md section 7 item 6) for comparison; ours are
// derived independently and checked in tests/test_adaptive_kernel.cpp.
inline constexpr double published_o2 = 8.8872057372592798e-16;
inline constexpr double published_o3 = 5.1107127829973299e-15;
inline constexpr double published_ic = 8.8878565762001373e-15;
inline constexpr double published_is = 1.2466136531027298e-13;

// ---- Stage constants (error_bounds.md section 4) ---------------------------------
// Stage X answers when |det_X| > (bound) with bound = XA * permanent (A),
// XB * permanent (B), XC * permanent + result_err * |det_C| (C).
inline constexpr double e2 = eps * eps;
inline constexpr double result_err = (3.0 + 8.0 * eps) * eps;
inline constexpr double o2A = (3.0 + 16.0 * eps) * eps, o2B = (2.0 + 12.0 * eps) * eps,
                        o2C = (9.0 + 64.0 * eps) * e2;
inline constexpr double o3A = (7.0 + 56.0 * eps) * eps, o3B = (3.0 + 28.0 * eps) * eps,
                        o3C = (26.0 + 288.0 * eps) * e2;
inline constexpr double icA = (10.0 + 96.0 * eps) * eps, icB = (4.0 + 48.0 * eps) * eps,
                        icC = (44.0 + 576.0 * eps) * e2;
// isB: the published (5 + 72 eps) eps holds only if the estimate's relative error is
// below 0.4 eps; (5 + 96 eps) eps holds with the paper's 2 eps (error_bounds.md 4.3,
// predicates/gappa/insphere_stage_b.g).
inline constexpr double isA = (16.0 + 224.0 * eps) * eps, isB = (5.0 + 96.0 * eps) * eps,
                        isC = (80.0 + 4096.0 * eps) * e2;  // our own stage-C formula (4.4)

// incircle filter from the lifts it computes anyway (error_bounds.md 3.3):
// |det| > ic_lift_filter * (S' * S'), S' = max((alift + blift) + clift, ic_lift_lo).
// Shewchuk's stage A bound icA * P^ with P^ <= (1+eps)^7 P and P <= S^2 / (3 (1-eps)^8);
// the bound c * (S * S) itself loses up to (1-eps)^2.
inline constexpr double ic_lift_filter =
    icA * pow_int(1 + eps, 7) / (3 * pow_int(1 - eps, 10)) * (1 + 0x1p-40);
inline constexpr double ic_lift_lo = 0x1p-480;

// Inline orient2d stage A (error_bounds.md 4.6).
inline constexpr double o2_fast = o2A * (1 + 0x1p-40), o2_fast_abs = 0x1p-1072;

// Out-of-line stages A..D and the mp fallback (adaptive_kernel.cpp).
Staged orient2d_slow(const Point2& a, const Point2& b, const Point2& c);
Staged incircle_slow(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
Staged orient3d_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d);
Staged insphere_slow(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                     const Point3& e);

inline constexpr unsigned char stage_filter = 0, stage_a = 1, stage_b = 2, stage_c = 3,
                               stage_d = 4, stage_mp = 5, stage_static = 6;

// The orient3d filter's determinant and bound (error_bounds.md 3.4), over the
// differences to d, with the monomials grouped by sign:
//   s0 = (adz (bdx cdy) + bdz (cdx ady)) + cdz (adx bdy)
//   s1 = (adz (bdy cdx) + bdz (cdy adx)) + cdz (ady bdx),     det = s0 - s1,
//   bound = o3_ss8 ((mx' my') 8 mz'),  m' = max(largest |difference| on the axis, 2^-320).
// Two evaluations with the same operations on the same operands (so the same
// results, bit for bit; tests/test_adaptive_kernel.cpp checks it): plain
// doubles, and SSE2 with the x and y of each point in one register (each
// packed operation rounds each lane as its scalar twin would). Each keeps the
// differences, so that the bound is only computed when the static filter
// (error_bounds.md 3.5) has not answered.
struct DetBound {
  double det, bound;
};
struct Orient3dScalar {
  double adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz, det;
  double bound() const {
    using std::fabs, std::max;
    const double mx = max(max(fabs(adx), fabs(bdx)), max(fabs(cdx), o3_ss_lo));
    const double my = max(max(fabs(ady), fabs(bdy)), max(fabs(cdy), o3_ss_lo));
    const double mz = max(max(fabs(adz), fabs(bdz)), max(fabs(cdz), o3_ss_lo));
    return o3_ss8 * ((mx * my) * (mz * 8));
  }
};
inline Orient3dScalar orient3d_parts_scalar(const Point3& a, const Point3& b, const Point3& c,
                                            const Point3& d) {
  Orient3dScalar f;
  f.adx = a[0] - d[0], f.ady = a[1] - d[1], f.adz = a[2] - d[2];
  f.bdx = b[0] - d[0], f.bdy = b[1] - d[1], f.bdz = b[2] - d[2];
  f.cdx = c[0] - d[0], f.cdy = c[1] - d[1], f.cdz = c[2] - d[2];
  const double s0 = (f.adz * (f.bdx * f.cdy) + f.bdz * (f.cdx * f.ady)) + f.cdz * (f.adx * f.bdy);
  const double s1 = (f.adz * (f.bdy * f.cdx) + f.bdz * (f.cdy * f.adx)) + f.cdz * (f.ady * f.bdx);
  f.det = s0 - s1;
  return f;
}
inline DetBound orient3d_filter_scalar(const Point3& a, const Point3& b, const Point3& c,
                                       const Point3& d) {
  const Orient3dScalar f = orient3d_parts_scalar(a, b, c, d);
  return {f.det, f.bound()};
}
#if defined(__SSE2__)
// Lanes (x, y) -> (y, x), and the high lane as a double (pshufd: no register copy).
inline __m128d swap_lanes(__m128d v) {
  return _mm_castsi128_pd(_mm_shuffle_epi32(_mm_castpd_si128(v), 0x4e));
}
inline double high_lane(__m128d v) {
  return _mm_cvtsd_f64(_mm_castsi128_pd(_mm_shuffle_epi32(_mm_castpd_si128(v), 0xee)));
}
struct Orient3dSse2 {
  __m128d ad, bd, cd, az, bz, cz;  // (x, y) differences; z differences in both lanes
  double det;
  double bound() const {
    const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
    const __m128d lo = _mm_set1_pd(o3_ss_lo);
    const __m128d mxy = _mm_max_pd(_mm_max_pd(_mm_and_pd(ad, abs_mask), _mm_and_pd(bd, abs_mask)),
                                   _mm_max_pd(_mm_and_pd(cd, abs_mask), lo));
    // 8 mz': exact scaling (an overflow gives +inf, which the bound keeps).
    const __m128d mz8 = _mm_mul_pd(
        _mm_max_pd(_mm_max_pd(_mm_and_pd(az, abs_mask), _mm_and_pd(bz, abs_mask)),
                   _mm_max_pd(_mm_and_pd(cz, abs_mask), lo)),
        _mm_set1_pd(8.0));
    return o3_ss8 * ((_mm_cvtsd_f64(mxy) * high_lane(mxy)) * _mm_cvtsd_f64(mz8));
  }
};
inline Orient3dSse2 orient3d_parts_sse2(const Point3& a, const Point3& b, const Point3& c,
                                        const Point3& d) {
  Orient3dSse2 f;
  const __m128d dxy = _mm_loadu_pd(d.data());
  f.ad = _mm_sub_pd(_mm_loadu_pd(a.data()), dxy);  // (adx, ady)
  f.bd = _mm_sub_pd(_mm_loadu_pd(b.data()), dxy);
  f.cd = _mm_sub_pd(_mm_loadu_pd(c.data()), dxy);
  f.az = _mm_set1_pd(a[2] - d[2]), f.bz = _mm_set1_pd(b[2] - d[2]), f.cz = _mm_set1_pd(c[2] - d[2]);
  // Lane 0 gathers s0's monomials, lane 1 s1's: (bdx cdy, bdy cdx), (cdx ady, cdy adx),
  // (adx bdy, ady bdx); IEEE products commute exactly.
  const __m128d p1 = _mm_mul_pd(f.bd, swap_lanes(f.cd));
  const __m128d p2 = _mm_mul_pd(f.cd, swap_lanes(f.ad));
  const __m128d p3 = _mm_mul_pd(f.ad, swap_lanes(f.bd));
  const __m128d s = _mm_add_pd(_mm_add_pd(_mm_mul_pd(f.az, p1), _mm_mul_pd(f.bz, p2)),
                               _mm_mul_pd(f.cz, p3));
  f.det = _mm_cvtsd_f64(s) - high_lane(s);
  return f;
}
inline DetBound orient3d_filter_sse2(const Point3& a, const Point3& b, const Point3& c,
                                     const Point3& d) {
  const Orient3dSse2 f = orient3d_parts_sse2(a, b, c, d);
  return {f.det, f.bound()};
}
#endif
inline auto orient3d_parts(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
#if defined(__SSE2__)
  return orient3d_parts_sse2(a, b, c, d);
#else
  return orient3d_parts_scalar(a, b, c, d);
#endif
}
inline DetBound orient3d_filter(const Point3& a, const Point3& b, const Point3& c,
                                const Point3& d) {
  const auto f = orient3d_parts(a, b, c, d);
  return {f.det, f.bound()};
}

// The insphere lift filter's determinant and bound (error_bounds.md 3.2), over the
// differences to e:
//   2x2 minors  ab = aex bey - bex aey, bc, cd, da, ac, bd (the same pattern),
//   3x3 minors  abc = (aez bc - bez ac) + cez ab,   bcd = (bez cd - cez bd) + dez bc,
//               cda = (cez da + dez ac) + aez cd,   dab = (dez ab + aez bd) + bez da,
//   lifts       alift = (aex^2 + aey^2) + aez^2, ...,
//   det = (dlift abc - clift dab) + (blift cda - alift bcd),
//   bound = is_lift128 (((128 L') L') mz'),  L' = max(largest lift, is_lo^2),
//           mz' = max(largest |z difference|, is_lo);
// 128 L' first, so that an overflow anywhere in det makes the bound +inf. As for
// orient3d, two evaluations with the same operations on the same operands (bit for
// bit the same det and bound; tests/test_adaptive_kernel.cpp checks it): plain
// doubles, and SSE2 with points a and c in one pair of lanes, b and d in the other.
inline DetBound insphere_filter_scalar(const Point3& a, const Point3& b, const Point3& c,
                                       const Point3& d, const Point3& e) {
  const double det = ::dlab::det::insphere<double>(a, b, c, d, e);  // the tree above
  using std::fabs, std::max;
  double L = is_lo2, mz = is_lo;  // the lifts are det's own (the same operations)
  for (const Point3* p : {&a, &b, &c, &d}) {
    const double x = (*p)[0] - e[0], y = (*p)[1] - e[1], z = (*p)[2] - e[2];
    L = max(L, (x * x + y * y) + z * z);
    mz = max(mz, fabs(z));
  }
  return {det, is_lift128 * (((L * 128) * L) * mz)};
}
#if defined(__SSE2__)
// Lanes (x, y) -> (x, -y): negating is exact, and u + v = u - (-v) bit for bit.
inline __m128d negate_high(__m128d v) { return _mm_xor_pd(v, _mm_set_pd(-0.0, 0.0)); }
inline DetBound insphere_filter_sse2(const Point3& a, const Point3& b, const Point3& c,
                                     const Point3& d, const Point3& e) {
  const __m128d exy = _mm_loadu_pd(e.data());
  const __m128d axy = _mm_sub_pd(_mm_loadu_pd(a.data()), exy), bxy = _mm_sub_pd(_mm_loadu_pd(b.data()), exy),
                cxy = _mm_sub_pd(_mm_loadu_pd(c.data()), exy), dxy = _mm_sub_pd(_mm_loadu_pd(d.data()), exy);
  const __m128d ez = _mm_set1_pd(e[2]);
  const __m128d x1 = _mm_unpacklo_pd(axy, cxy), y1 = _mm_unpackhi_pd(axy, cxy);  // (aex, cex), (aey, cey)
  const __m128d x2 = _mm_unpacklo_pd(bxy, dxy), y2 = _mm_unpackhi_pd(bxy, dxy);  // (bex, dex), (bey, dey)
  const __m128d z1 = _mm_sub_pd(_mm_set_pd(c[2], a[2]), ez);                      // (aez, cez)
  const __m128d z2 = _mm_sub_pd(_mm_set_pd(d[2], b[2]), ez);                      // (bez, dez)
  // 2x2 minors (IEEE products commute exactly).
  const __m128d m_ab_cd = _mm_sub_pd(_mm_mul_pd(x1, y2), _mm_mul_pd(x2, y1));
  const __m128d m_bc_da = _mm_sub_pd(_mm_mul_pd(x2, swap_lanes(y1)), _mm_mul_pd(swap_lanes(x1), y2));
  const __m128d m_ac_bd = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(x1, x2), _mm_unpackhi_pd(y1, y2)),
                                     _mm_mul_pd(_mm_unpackhi_pd(x1, x2), _mm_unpacklo_pd(y1, y2)));
  // 3x3 minors (abc, cda) and (bcd, dab).
  const __m128d acx2 = _mm_unpacklo_pd(m_ac_bd, m_ac_bd), bdx2 = _mm_unpackhi_pd(m_ac_bd, m_ac_bd);
  const __m128d z1s = swap_lanes(z1), z2s = swap_lanes(z2);  // (cez, aez), (dez, bez)
  const __m128d p = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(z1, m_bc_da), _mm_mul_pd(negate_high(z2), acx2)),
                               _mm_mul_pd(z1s, m_ab_cd));
  const __m128d q = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(z2, swap_lanes(m_ab_cd)), _mm_mul_pd(negate_high(z1s), bdx2)),
                               _mm_mul_pd(z2s, m_bc_da));
  // Lifts (alift, clift) and (blift, dlift); det's two halves in the two lanes.
  const __m128d l1 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x1, x1), _mm_mul_pd(y1, y1)), _mm_mul_pd(z1, z1));
  const __m128d l2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x2, x2), _mm_mul_pd(y2, y2)), _mm_mul_pd(z2, z2));
  const __m128d r = _mm_sub_pd(_mm_mul_pd(swap_lanes(l2), p), swap_lanes(_mm_mul_pd(l1, q)));
  const double det = _mm_cvtsd_f64(r) + high_lane(r);
  // Maxima (no NaN can arise from finite inputs: the order does not matter).
  const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  const __m128d lm = _mm_max_pd(l1, l2);
  const __m128d zm = _mm_max_pd(_mm_and_pd(z1, abs_mask), _mm_and_pd(z2, abs_mask));
  const double L = std::max(std::max(_mm_cvtsd_f64(lm), high_lane(lm)), is_lo2);
  const double mz = std::max(std::max(_mm_cvtsd_f64(zm), high_lane(zm)), is_lo);
  return {det, is_lift128 * (((L * 128) * L) * mz)};
}
#endif
inline DetBound insphere_filter(const Point3& a, const Point3& b, const Point3& c,
                                const Point3& d, const Point3& e) {
#if defined(__SSE2__)
  return insphere_filter_sse2(a, b, c, d, e);
#else
  return insphere_filter_scalar(a, b, c, d, e);
#endif
}

// The incircle lift filter's determinant and bound (error_bounds.md 3.3), over the
// differences to d:
//   alift = adx^2 + ady^2, blift, clift;  bc = bdx cdy - bdy cdx, ca = cdx ady - cdy adx,
//   ab = adx bdy - ady bdx;  det = (alift bc + blift ca) + clift ab,
//   bound = ic_lift_filter (S' S'),  S' = max((alift + blift) + clift, ic_lift_lo)
// (S' S' first: it overflows whenever an intermediate of det can). Two evaluations,
// bit for bit the same: plain doubles, and SSE2 with the x and y of each point in one
// register.
inline DetBound incircle_filter_scalar(const Point2& a, const Point2& b, const Point2& c,
                                       const Point2& d) {
  const double det = ::dlab::det::incircle<double>(a, b, c, d);  // the tree above
  auto lift = [&](const Point2& p) {  // det's own lifts (the same operations)
    const double x = p[0] - d[0], y = p[1] - d[1];
    return x * x + y * y;
  };
  const double lifts = std::max((lift(a) + lift(b)) + lift(c), ic_lift_lo);
  return {det, ic_lift_filter * (lifts * lifts)};
}
#if defined(__SSE2__)
inline DetBound incircle_filter_sse2(const Point2& a, const Point2& b, const Point2& c,
                                     const Point2& d) {
  const __m128d dxy = _mm_loadu_pd(d.data());
  const __m128d ad = _mm_sub_pd(_mm_loadu_pd(a.data()), dxy);  // (adx, ady)
  const __m128d bd = _mm_sub_pd(_mm_loadu_pd(b.data()), dxy);
  const __m128d cd = _mm_sub_pd(_mm_loadu_pd(c.data()), dxy);
  const __m128d aa = _mm_mul_pd(ad, ad), bb = _mm_mul_pd(bd, bd), cc = _mm_mul_pd(cd, cd);
  const __m128d lab = _mm_add_pd(_mm_unpacklo_pd(aa, bb), _mm_unpackhi_pd(aa, bb));  // (alift, blift)
  const double clift = _mm_cvtsd_f64(cc) + high_lane(cc);
  // (bdx cdy, bdy cdx), (cdx ady, cdy adx), (adx bdy, ady bdx): IEEE products commute exactly.
  const __m128d pbc = _mm_mul_pd(bd, swap_lanes(cd)), pca = _mm_mul_pd(cd, swap_lanes(ad));
  const __m128d pab = _mm_mul_pd(ad, swap_lanes(bd));
  const __m128d m = _mm_sub_pd(_mm_unpacklo_pd(pbc, pca), _mm_unpackhi_pd(pbc, pca));  // (bc, ca)
  const double ab = _mm_cvtsd_f64(pab) - high_lane(pab);
  const __m128d t = _mm_mul_pd(lab, m);  // (alift bc, blift ca)
  const double det = (_mm_cvtsd_f64(t) + high_lane(t)) + clift * ab;
  const double lifts = std::max((_mm_cvtsd_f64(lab) + high_lane(lab)) + clift, ic_lift_lo);
  return {det, ic_lift_filter * (lifts * lifts)};
}
#endif
inline DetBound incircle_filter(const Point2& a, const Point2& b, const Point2& c,
                                const Point2& d) {
#if defined(__SSE2__)
  return incircle_filter_sse2(a, b, c, d);
#else
  return incircle_filter_scalar(a, b, c, d);
#endif
}

// The static orient3d bound (error_bounds.md 3.5) for points whose coordinate
// differences are all at most w: the filter's bound with every axis maximum = w.
inline double orient3d_static_bound(double w) {
  const double m = std::max(w, o3_ss_lo);
  return o3_ss8 * ((m * m) * (m * 8));
}

}  // namespace adaptive

struct AdaptiveKernel {
  static constexpr bool exact = true;
  static constexpr std::string_view name = "adaptive";
  // "static" answers before "filter" when the kernel is fitted; it is listed last so
  // that the other indices keep their order.
  static constexpr std::array<std::string_view, 7> stage_names = {"filter", "A", "B", "C",
                                                                  "D", "mp", "static"};

  // Static orient3d filter (Devillers & Pion, "Efficient exact geometric predicates
  // for Delaunay triangulations", ALENEX 2003; error_bounds.md 3.5). Unfitted (the
  // default), orient3d starts with the per-call filter. fit_static_filter(pts) sets one
  // bound for all calls: with G the largest width of pts' bounding box, every call
  // whose four points lie within 1.01 G of that box (on every axis) has coordinate
  // differences of at most 3.02 G <= 4 (1 - eps) G <= W = 4 * (G as computed), so
  // the per-call bound with every axis maximum W is valid for it. The caller promises that every orient3d
  // call meets this (variants/driver.hpp fits only algorithms that promise it).
  void fit_static_filter(std::span<const Point3> pts) {
    if (pts.empty()) return;
    double width = 0;
    for (int j = 0; j < 3; ++j) {
      double lo = pts[0][j], hi = pts[0][j];
      for (const Point3& p : pts) {
        if (!std::isfinite(p[j])) return;  // no promise can be made: stay unfitted
        lo = std::min(lo, p[j]), hi = std::max(hi, p[j]);
      }
      width = std::max(width, hi - lo);
    }
    o3_static_ = adaptive::orient3d_static_bound(4 * width);  // +inf if W^3 overflows
    fitted_ = true;
  }
  bool static_filter_fitted() const { return fitted_; }
  double orient3d_static_bound() const { return o3_static_; }
  // The same kernel without the static filter, for points the caller makes itself
  // (perturbed<K>'s off-plane point, predicates/perturbed.hpp).
  AdaptiveKernel without_static_filter() const { return AdaptiveKernel{}; }

  // X_first_then(points, rest): the inline first stage, and rest(points) when it
  // cannot decide; X_rest: the stages after it; X_staged: both.
  // perturbed<AdaptiveKernel> puts its small-integer evaluation between the two
  // (predicates/perturbed.hpp).
  //
  // orient2d has no semi-static filter: Shewchuk's stage A (bound o2A times the
  // permanent |dl| + |dr|) is as cheap and sharper. Two refinements
  // (error_bounds.md 4.6): |dl + dr| replaces |dl| + |dr| (equal when the signs
  // agree; when they differ the sign of det is exact anyway), and the additive
  // 2^-1072 absorbs gradual-underflow crumbs (o2_fast carries the extra rounding).
  template <class Rest>
  static Staged orient2d_first_then(const Point2& a, const Point2& b, const Point2& c,
                                    Rest rest) {
    const double acx = a[0] - c[0], bcx = b[0] - c[0];
    const double acy = a[1] - c[1], bcy = b[1] - c[1];
    const double dl = acx * bcy, dr = acy * bcx;
    const double det = dl - dr;
    const double bound = adaptive::o2_fast * std::fabs(dl + dr) + adaptive::o2_fast_abs;
    if (det > bound) return {Sign::positive, adaptive::stage_a};
    if (-det > bound) return {Sign::negative, adaptive::stage_a};
    return rest(a, b, c);
  }

  template <class Rest>
  static Staged incircle_first_then(const Point2& a, const Point2& b, const Point2& c,
                                    const Point2& d, Rest rest) {
    const auto [det, bound] = adaptive::incircle_filter(a, b, c, d);
    if (det > bound) return {Sign::positive, adaptive::stage_filter};
    if (-det > bound) return {Sign::negative, adaptive::stage_filter};
    return rest(a, b, c, d);
  }

  // orient3d: the static filter when fitted, then the per-axis filter of
  // error_bounds.md 3.4, whose bound is computed only here. If an intermediate of det
  // overflowed, either bound is +inf (or det NaN): the tests fail.
  template <class Rest>
  Staged orient3d_first_then(const Point3& a, const Point3& b, const Point3& c,
                             const Point3& d, Rest rest) const {
    const auto f = adaptive::orient3d_parts(a, b, c, d);
    // [[unlikely]] only places the static tests out of line: with them inline, g++ 12
    // laid out the unfitted path so that it measured 17-18 ns per call instead of
    // 6.5 (bench_predicates --dlab_tight=orient3d/adaptive); the fitted path measures
    // the same either way.
    if (fitted_) [[unlikely]] {
      if (f.det > o3_static_) return {Sign::positive, adaptive::stage_static};
      if (-f.det > o3_static_) return {Sign::negative, adaptive::stage_static};
    }
    const double bound = f.bound();
    if (f.det > bound) return {Sign::positive, adaptive::stage_filter};
    if (-f.det > bound) return {Sign::negative, adaptive::stage_filter};
    return rest(a, b, c, d);
  }

  template <class Rest>
  static Staged insphere_first_then(const Point3& a, const Point3& b, const Point3& c,
                                    const Point3& d, const Point3& e, Rest rest) {
    const auto [det, bound] = adaptive::insphere_filter(a, b, c, d, e);
    if (det > bound) return {Sign::positive, adaptive::stage_filter};
    if (-det > bound) return {Sign::negative, adaptive::stage_filter};
    return rest(a, b, c, d, e);
  }

  // The stages after the first (out of line), and the whole predicate.
  static Staged orient2d_rest(const Point2& a, const Point2& b, const Point2& c) {
    return adaptive::orient2d_slow(a, b, c);
  }
  static Staged incircle_rest(const Point2& a, const Point2& b, const Point2& c,
                              const Point2& d) {
    return adaptive::incircle_slow(a, b, c, d);
  }
  static Staged orient3d_rest(const Point3& a, const Point3& b, const Point3& c,
                              const Point3& d) {
    return adaptive::orient3d_slow(a, b, c, d);
  }
  static Staged insphere_rest(const Point3& a, const Point3& b, const Point3& c,
                              const Point3& d, const Point3& e) {
    return adaptive::insphere_slow(a, b, c, d, e);
  }
  // (A lambda, not the function's address: the fast path then compiles exactly as
  // when the stages were one function -- one instruction fewer per orient3d call.)
  static Staged orient2d_staged(const Point2& a, const Point2& b, const Point2& c) {
    return orient2d_first_then(a, b, c, [](const auto&... p) { return orient2d_rest(p...); });
  }
  static Staged incircle_staged(const Point2& a, const Point2& b, const Point2& c,
                                const Point2& d) {
    return incircle_first_then(a, b, c, d, [](const auto&... p) { return incircle_rest(p...); });
  }
  Staged orient3d_staged(const Point3& a, const Point3& b, const Point3& c,
                         const Point3& d) const {
    return orient3d_first_then(a, b, c, d, [](const auto&... p) { return orient3d_rest(p...); });
  }
  static Staged insphere_staged(const Point3& a, const Point3& b, const Point3& c,
                                const Point3& d, const Point3& e) {
    return insphere_first_then(a, b, c, d, e,
                               [](const auto&... p) { return insphere_rest(p...); });
  }

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const {
    return orient2d_staged(a, b, c).sign;
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return incircle_staged(a, b, c, d).sign;
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return orient3d_staged(a, b, c, d).sign;
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const {
    return insphere_staged(a, b, c, d, e).sign;
  }

 private:
  bool fitted_ = false;
  double o3_static_ = std::numeric_limits<double>::infinity();
};

}  // namespace dlab
