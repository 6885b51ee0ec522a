// Exact predicates for points with small integer coordinates, in plain doubles.
//
// Certificate. (1) Every coordinate x passes is_int: with a = |x| and c = 2^52,
// fl(fl(a + c) - c) == a. For a < 2^52, a + c lies in [2^52, 2^53], where
// doubles are spaced by 1, so fl(a + c) is an integer n (a rounded) and n - c
// is exact (Sterbenz): the test is "a is an integer". For a >= 2^52 (every
// such double is an integer) fl(a + c) and fl(n - c) are integers, so a pass
// still means "integer"; some of these are refused (only slower). Hence: a
// finite x that passes is an integer; every integer with |x| <= 2^52 passes;
// NaN never passes; +-inf passes (refused by (2)). Taking |x| first matters:
// without it, x in [-2^52, -2^51) puts x + c in [2^51, 2^52), where doubles
// are spaced by 1/2, and half-integers such as -2^51 - 7.5 passed (issue 17).
// (2) Every coordinate difference d = fl(a - e) used by the determinant has
// |d| <= B (B <= 2^52), and the reference point e (the one subtracted from all
// others) is finite. Then every difference is exact: an infinite a gives |d| =
// inf, refused by (2) (with e finite no difference is NaN, which a maximum
// could drop); for finite integers a, e, either
// e/2 <= a <= 2e (same sign; Sterbenz: a - e is exact) or |a - e| >= max(|a|,
// |e|) / 2, so |a|, |e| <= 2B + 1 <= 2^53 and the integer a - e, of magnitude
// <= B + 1, is a double. With exact integer differences bounded by B, every
// product and partial sum of the expansions below is an integer bounded by the
// figure listed; while that is <= 2^53 no operation rounds, so the computed
// determinant IS the exact determinant and its sign is exact -- zero included.
// No tolerance anywhere: an error-free evaluation, not a filter.
// Tests: tests/test_small_integer.cpp (each claim above, scalar and SSE2).
//
// This is what the symbolic perturbation needs on lattices (grids, cubes):
// there most in-circle / in-sphere tests are exactly zero, and proving a zero
// with expansion arithmetic costs thousands of instructions, against a few
// dozen here. `known == false` means "not certified: ask an exact kernel".
//
// incircle_sos / insphere_sos also finish the job when the determinant is
// zero: the symbolic perturbation of predicates/perturbed.hpp (sos::walk,
// Devillers & Teillaud 2011), on the same certificate. Relative to the query,
// every point is an integer vector with coordinates in [-B, B]; its
// lexicographic rank is that of an exact integer key (subtracting the query
// preserves the order), and the orientations the walk asks are, up to sign,
// the determinant's own exact minors and their sum (detail::first_by_decreasing_key).
//
// Sign conventions are Shewchuk's (predicates/kernel.hpp); the determinants are
// expanded as in predicates/adaptive_kernel.hpp (Shewchuk 1997, section 4).
// Bounds, with |difference| <= B (the largest intermediate of each):
//   orient2d   acx*bcy - acy*bcx                                 2 B^2
//   incircle   lifts 2 B^2, minors 2 B^2, det                    12 B^4
//   orient3d   minors 2 B^2, det                                 6 B^3
//   insphere   minors 2 B^2, 3x3 minors 6 B^3, lifts 3 B^2, det  72 B^5
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "predicates/point.hpp"
#include "predicates/sign.hpp"

namespace dlab::small_integer {

struct Answer {
  bool known;  // the evaluation was certified exact
  Sign sign;
};

inline constexpr double two53 = 0x1p53;
inline constexpr double o2_bound = 0x1p25, ic_bound = 0x1p12, o3_bound = 0x1p16, is_bound = 0x1p9;
static_assert(2 * o2_bound * o2_bound <= two53);
static_assert(12 * ic_bound * ic_bound * ic_bound * ic_bound <= two53);
static_assert(6 * o3_bound * o3_bound * o3_bound <= two53);
static_assert(72 * is_bound * is_bound * is_bound * is_bound * is_bound <= two53);
static_assert(2 * is_bound + 1 <= two53 && 2 * o2_bound + 1 <= two53);  // (2) above

// Integer or infinite (certificate (1) above); -fno-fast-math keeps
// (a + c) - c from being simplified.
inline constexpr double int_shift = 0x1p52;
inline bool is_int(double x) {
  const double a = std::fabs(x);
  return (a + int_shift) - int_shift == a;
}

// Every coordinate of the N points passes is_int, and the last point (the
// reference) is finite, |x| <= 2^52. Two evaluations with the same operations:
// the scalar one and SSE2, two lanes at a time (each lane rounds as its scalar
// twin); all_int uses SSE2 where the target has it. Both leave after the
// reference's x and y when those fail (the common case off lattices).
template <int D, int N>
inline bool all_int_scalar(const Point<D>* const (&p)[N]) {
  bool ok = true;
  for (int j = 0; j < D; ++j) ok &= is_int((*p[N - 1])[j]) & (std::fabs((*p[N - 1])[j]) <= 0x1p52);
  if (!ok) return false;
  for (int i = 0; i < N - 1; ++i) {
    for (int j = 0; j < D; ++j) ok &= is_int((*p[i])[j]);
    if (!ok) return false;
  }
  return true;
}

#if defined(__SSE2__)
template <int D, int N>
inline bool all_int_sse2(const Point<D>* const (&p)[N]) {
  const __m128d c = _mm_set1_pd(int_shift);
  const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  auto integral = [&](__m128d v) {
    const __m128d a = _mm_and_pd(v, abs_mask);
    return _mm_cmpeq_pd(_mm_sub_pd(_mm_add_pd(a, c), c), a);
  };
  const __m128d ref = _mm_loadu_pd(p[N - 1]->data());  // (x, y) of the reference
  __m128d ok = _mm_cmple_pd(_mm_and_pd(ref, abs_mask), _mm_set1_pd(0x1p52));
  ok = _mm_and_pd(ok, integral(ref));
  // Off lattices (uniform points) the answer is known here: leave early.
  if (_mm_movemask_pd(ok) != 3) return false;
  for (int i = 0; i < N - 1; ++i) ok = _mm_and_pd(ok, integral(_mm_loadu_pd(p[i]->data())));
  if constexpr (D == 3) {
    // z coordinates two by two; the reference's z is also bounded.
    const __m128d rz = _mm_load_sd(&(*p[N - 1])[2]);
    ok = _mm_and_pd(ok, _mm_unpacklo_pd(_mm_cmple_sd(_mm_and_pd(rz, abs_mask), _mm_set1_pd(0x1p52)),
                                        _mm_cmple_sd(_mm_and_pd(rz, abs_mask), _mm_set1_pd(0x1p52))));
    for (int i = 0; i < N; i += 2) {
      const __m128d z = _mm_loadh_pd(_mm_load_sd(&(*p[i])[2]), &(*p[i + 1 < N ? i + 1 : i])[2]);
      ok = _mm_and_pd(ok, integral(z));
    }
  }
  return _mm_movemask_pd(ok) == 3;
}
#endif

template <int D, int N>
inline bool all_int(const Point<D>* const (&p)[N]) {
#if defined(__SSE2__)
  return all_int_sse2<D, N>(p);
#else
  return all_int_scalar<D, N>(p);
#endif
}

inline double amax(double a, double b) { return std::max(std::fabs(a), std::fabs(b)); }

inline Answer orient2d(const Point2& a, const Point2& b, const Point2& c) {
  if (!all_int<2, 3>({&a, &b, &c})) return {false, Sign::zero};
  const double acx = a[0] - c[0], bcx = b[0] - c[0];
  const double acy = a[1] - c[1], bcy = b[1] - c[1];
  if (!(std::max(amax(acx, bcx), amax(acy, bcy)) <= o2_bound)) return {false, Sign::zero};
  return {true, sign_of(acx * bcy - acy * bcx)};
}

inline Answer incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (!all_int<2, 4>({&a, &b, &c, &d})) return {false, Sign::zero};
  const double adx = a[0] - d[0], ady = a[1] - d[1];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1];
  if (!(std::max(std::max(amax(adx, ady), amax(bdx, bdy)), amax(cdx, cdy)) <= ic_bound))
    return {false, Sign::zero};
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double bc = bdx * cdy - bdy * cdx;
  const double ca = cdx * ady - cdy * adx;
  const double ab = adx * bdy - ady * bdx;
  return {true, sign_of((alift * bc + blift * ca) + clift * ab)};
}

inline Answer orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  if (!all_int<3, 4>({&a, &b, &c, &d})) return {false, Sign::zero};
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double m = std::max(std::max(std::max(amax(adx, ady), amax(adz, bdx)),
                                     std::max(amax(bdy, bdz), amax(cdx, cdy))),
                            std::fabs(cdz));
  if (!(m <= o3_bound)) return {false, Sign::zero};
  const double det = (adz * (bdx * cdy - cdx * bdy) + bdz * (cdx * ady - adx * cdy)) +
                     cdz * (adx * bdy - bdx * ady);
  return {true, sign_of(det)};
}

inline Answer insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& e) {
  if (!all_int<3, 5>({&a, &b, &c, &d, &e})) return {false, Sign::zero};
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double m = std::max(std::max(std::max(amax(aex, aey), amax(aez, bex)),
                                     std::max(amax(bey, bez), amax(cex, cey))),
                            std::max(std::max(amax(cez, dex), amax(dey, dez)), 0.0));
  if (!(m <= is_bound)) return {false, Sign::zero};
  const double ab = aex * bey - bex * aey;
  const double bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey;
  const double da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey;
  const double bd = bex * dey - dex * bey;
  const double abc = (aez * bc - bez * ac) + cez * ab;
  const double bcd = (bez * cd - cez * bd) + dez * bc;
  const double cda = (cez * da + dez * ac) + aez * cd;
  const double dab = (dez * ab + aez * bd) + bez * da;
  const double alift = (aex * aex + aey * aey) + aez * aez;
  const double blift = (bex * bex + bey * bey) + bez * bez;
  const double clift = (cex * cex + cey * cey) + cez * cez;
  const double dlift = (dex * dex + dey * dey) + dez * dez;
  return {true, sign_of((dlift * abc - clift * dab) + (blift * cda - alift * bcd))};
}

struct SosAnswer {
  bool known;          // certified (the points are small integers)
  Sign sign;           // the perturbed sign (zero only for degenerate simplices)
  bool by_perturbation;  // the exact determinant was zero
};

// The key of an integer vector v in [-B, B]^D with W = 2B + 1, (v0 W + v1) W
// + v2 (2D: v0 W + v1), is exact (at most B (W^2 + W + 1) < 2^30 in
// magnitude) and increases with the lexicographic order: a larger first
// coordinate adds at least W^2 (2D: W), the others take at most 2B W + 2B =
// W^2 - 1 (2D: 2B = W - 1) away. B: ic_bound (2D), is_bound (3D).
inline constexpr double ic_key_base = 2 * ic_bound + 1, is_key_base = 2 * is_bound + 1;
static_assert(ic_bound * (ic_key_base + 1) <= 0x1p30 &&
              is_bound * (is_key_base * is_key_base + is_key_base + 1) <= 0x1p30);
inline double lex_key2(double x, double y) { return x * ic_key_base + y; }
inline double lex_key3(double x, double y, double z) { return (x * is_key_base + y) * is_key_base + z; }

namespace detail {
// sos::walk on the certified points without an orientation of its own. With
// the query q at the origin (every point is taken relative to it), the walk's
// orientation with point i replaced by q is a minor that the determinant has
// already computed exactly, up to sign; the query's own term is -orient of
// the others, their minors' alternating sum (multilinearity: the rows a - d
// expand into a and -d, and no minor has d twice):
//   2D, orient2(p, q, r) = det[p - r; q - r]:
//     0: det[b; c] = bc,  1: det[c; a] = ca,  2: det[a; b] = ab,
//     3: -orient2(a, b, c) = -(ab + bc + ca);
//   3D, orient3(p, q, r, s) = det[p - s; q - s; r - s]:
//     0: -det[b; c; d] = -bcd,  1: det[c; d; a] = cda,  2: -det[d; a; b] = -dab,
//     3: det[a; b; c] = abc,    4: -orient3(a, b, c, d) = -(abc - bcd + cda - dab).
// The sums are exact: at most 6 B^2 (2D) and 24 B^3 (3D), below 2^53. The
// walk takes the points by decreasing lexicographic rank, the lower index
// first among equal ranks (sos::by_decreasing_rank), and answers the first
// non-zero term: that is the non-zero term of the largest key, the lower
// index on a tie (the keys: lex_key2, lex_key3).
template <int N>
Sign first_by_decreasing_key(const double (&key)[N], const double (&term)[N]) {
  int best = -1;
  for (int i = 0; i < N; ++i)
    if (term[i] != 0 && (best < 0 || key[i] > key[best])) best = i;
  return best < 0 ? Sign::zero : sign_of(term[best]);  // zero: a degenerate simplex
}
#if defined(__SSE2__)
// The same answer without branches, candidates in lanes: (k01, t01) and (k23,
// t23) hold points 0-3 two by two, and with Fifth the low lanes of (k4, t4) hold
// point 4. The keys of zero terms become -inf (every key is finite), the largest
// key is found, and of the points holding it (a tie: a repeated point) the lowest
// index answers; when every term is zero, every point holds -inf and term 0 is 0.
template <bool Fifth>
[[gnu::always_inline]] inline Sign first_by_decreasing_key_sse2(__m128d k01, __m128d t01, __m128d k23, __m128d t23,
                                                                __m128d k4 = _mm_setzero_pd(),
                                                                __m128d t4 = _mm_setzero_pd()) {
  const __m128d zero = _mm_setzero_pd(), none = _mm_set1_pd(-std::numeric_limits<double>::infinity());
  auto live = [&](__m128d key, __m128d t) {
    const __m128d nonzero = _mm_cmpneq_pd(t, zero);
    return _mm_or_pd(_mm_and_pd(nonzero, key), _mm_andnot_pd(nonzero, none));
  };
  const __m128d a = live(k01, t01), b = live(k23, t23);
  const __m128d c = live(_mm_unpacklo_pd(k4, k4), _mm_unpacklo_pd(t4, t4));
  __m128d top = _mm_max_pd(a, b);
  if constexpr (Fifth) top = _mm_max_pd(top, c);
  top = _mm_max_pd(top, _mm_shuffle_pd(top, top, 1));
  int holders = _mm_movemask_pd(_mm_cmpeq_pd(a, top)) | _mm_movemask_pd(_mm_cmpeq_pd(b, top)) << 2;
  if constexpr (Fifth) holders |= (_mm_movemask_pd(_mm_cmpeq_pd(c, top)) & 1) << 4;
  double term[5];
  _mm_storeu_pd(term, t01);
  _mm_storeu_pd(term + 2, t23);
  term[4] = _mm_cvtsd_f64(t4);
  return sign_of(term[__builtin_ctz(static_cast<unsigned>(holders))]);
}
#endif
}  // namespace detail
// The walk's terms (detail::first_by_decreasing_key) are exact.
static_assert(6 * ic_bound * ic_bound <= two53 && 24 * is_bound * is_bound * is_bound <= two53);

// Two evaluations, scalar and SSE2, as for insphere_sos below.
inline SosAnswer incircle_sos_scalar(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (!all_int<2, 4>({&a, &b, &c, &d})) return {false, Sign::zero, false};
  const double v[4][2] = {{a[0] - d[0], a[1] - d[1]}, {b[0] - d[0], b[1] - d[1]},
                          {c[0] - d[0], c[1] - d[1]}, {0, 0}};
  if (!(std::max(std::max(amax(v[0][0], v[0][1]), amax(v[1][0], v[1][1])),
                 amax(v[2][0], v[2][1])) <= ic_bound))
    return {false, Sign::zero, false};
  const double alift = v[0][0] * v[0][0] + v[0][1] * v[0][1];
  const double blift = v[1][0] * v[1][0] + v[1][1] * v[1][1];
  const double clift = v[2][0] * v[2][0] + v[2][1] * v[2][1];
  const double bc = v[1][0] * v[2][1] - v[1][1] * v[2][0];
  const double ca = v[2][0] * v[0][1] - v[2][1] * v[0][0];
  const double ab = v[0][0] * v[1][1] - v[0][1] * v[1][0];
  const Sign exact = sign_of((alift * bc + blift * ca) + clift * ab);
  if (exact != Sign::zero) return {true, exact, false};
  const double key[4] = {lex_key2(v[0][0], v[0][1]), lex_key2(v[1][0], v[1][1]),
                         lex_key2(v[2][0], v[2][1]), 0};
  const double term[4] = {bc, ca, ab, -((ab + bc) + ca)};
  return {true, detail::first_by_decreasing_key<4>(key, term), true};
}

#if defined(__SSE2__)
// The same values two at a time (a and b in one pair of lanes); exact under the
// certificate, so each is the scalar twin's (tests/test_small_integer.cpp).
inline SosAnswer incircle_sos_sse2(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (!all_int<2, 4>({&a, &b, &c, &d})) return {false, Sign::zero, false};
  const __m128d dxy = _mm_loadu_pd(d.data());
  const __m128d axy = _mm_sub_pd(_mm_loadu_pd(a.data()), dxy), bxy = _mm_sub_pd(_mm_loadu_pd(b.data()), dxy),
                cxy = _mm_sub_pd(_mm_loadu_pd(c.data()), dxy);
  // Every |difference| <= B (no NaN: all_int leaves integers, infinities and a finite d).
  const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  const __m128d m = _mm_max_pd(_mm_max_pd(_mm_and_pd(axy, abs_mask), _mm_and_pd(bxy, abs_mask)),
                               _mm_and_pd(cxy, abs_mask));
  if (_mm_movemask_pd(_mm_cmple_pd(m, _mm_set1_pd(ic_bound))) != 3) return {false, Sign::zero, false};
  const __m128d x = _mm_unpacklo_pd(axy, bxy), y = _mm_unpackhi_pd(axy, bxy);  // (adx, bdx), (ady, bdy)
  const __m128d ab_bc = _mm_sub_pd(_mm_mul_pd(x, _mm_unpackhi_pd(bxy, cxy)),
                                   _mm_mul_pd(y, _mm_unpacklo_pd(bxy, cxy)));  // (ab, bc)
  const __m128d cross = _mm_mul_pd(cxy, _mm_shuffle_pd(axy, axy, 1));       // (cdx ady, cdy adx)
  const __m128d ca = _mm_sub_sd(cross, _mm_unpackhi_pd(cross, cross));
  const __m128d bc_ca = _mm_shuffle_pd(ab_bc, ca, 1);
  const __m128d lifts = _mm_add_pd(_mm_mul_pd(x, x), _mm_mul_pd(y, y));  // (alift, blift)
  const __m128d cc = _mm_mul_pd(cxy, cxy);
  const double clift = _mm_cvtsd_f64(cc) + _mm_cvtsd_f64(_mm_unpackhi_pd(cc, cc));
  const __m128d v = _mm_mul_pd(lifts, bc_ca);  // (alift bc, blift ca)
  const double ab = _mm_cvtsd_f64(ab_bc), bc = _mm_cvtsd_f64(bc_ca), cav = _mm_cvtsd_f64(ca);
  const Sign exact = sign_of((_mm_cvtsd_f64(v) + _mm_cvtsd_f64(_mm_unpackhi_pd(v, v))) + clift * ab);
  if (exact != Sign::zero) return {true, exact, false};
  const __m128d kab = _mm_add_pd(_mm_mul_pd(x, _mm_set1_pd(ic_key_base)), y);  // (key a, key b)
  const double kc = lex_key2(_mm_cvtsd_f64(cxy), _mm_cvtsd_f64(_mm_unpackhi_pd(cxy, cxy)));
  // Terms (bc, ca), (ab, d's); d's key is 0.
  return {true,
          detail::first_by_decreasing_key_sse2<false>(kab, bc_ca, _mm_set_sd(kc),
                                                      _mm_set_pd(-((ab + bc) + cav), ab)),
          true};
}
#endif

inline SosAnswer incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
#if defined(__SSE2__)
  return incircle_sos_sse2(a, b, c, d);
#else
  return incircle_sos_scalar(a, b, c, d);
#endif
}

// Two evaluations, scalar and SSE2; insphere_sos uses SSE2 where the target has
// it. Inline: its call made perturbed<AdaptiveKernel>::insphere_lattice save and
// restore five registers.
[[gnu::always_inline]] inline SosAnswer insphere_sos_scalar(const Point3& a, const Point3& b, const Point3& c,
                                                            const Point3& d, const Point3& e) {
  if (!all_int<3, 5>({&a, &b, &c, &d, &e})) return {false, Sign::zero, false};
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  const double m = std::max(std::max(std::max(amax(aex, aey), amax(aez, bex)),
                                     std::max(amax(bey, bez), amax(cex, cey))),
                            std::max(amax(cez, dex), amax(dey, dez)));
  if (!(m <= is_bound)) return {false, Sign::zero, false};
  const double ab = aex * bey - bex * aey;
  const double bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey;
  const double da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey;
  const double bd = bex * dey - dex * bey;
  const double abc = (aez * bc - bez * ac) + cez * ab;
  const double bcd = (bez * cd - cez * bd) + dez * bc;
  const double cda = (cez * da + dez * ac) + aez * cd;
  const double dab = (dez * ab + aez * bd) + bez * da;
  const double alift = (aex * aex + aey * aey) + aez * aez;
  const double blift = (bex * bex + bey * bey) + bez * bez;
  const double clift = (cex * cex + cey * cey) + cez * cez;
  const double dlift = (dex * dex + dey * dey) + dez * dez;
  const Sign exact = sign_of((dlift * abc - clift * dab) + (blift * cda - alift * bcd));
  if (exact != Sign::zero) return {true, exact, false};
  const double key[5] = {lex_key3(aex, aey, aez), lex_key3(bex, bey, bez), lex_key3(cex, cey, cez),
                         lex_key3(dex, dey, dez), 0};
  const double term[5] = {-bcd, cda, -dab, abc, -((abc - bcd) + (cda - dab))};
  return {true, detail::first_by_decreasing_key<5>(key, term), true};
}

#if defined(__SSE2__)
// The same minors, lifts, keys and terms two at a time, laid out as the insphere
// filter lays them (predicates/adaptive_kernel.hpp): a and c in one pair of lanes,
// b and d in the other. Under the certificate every operation is exact, so each
// value is the scalar twin's, whatever the order (tests/test_small_integer.cpp).
[[gnu::always_inline]] inline SosAnswer insphere_sos_sse2(const Point3& a, const Point3& b, const Point3& c,
                                                          const Point3& d, const Point3& e) {
  if (!all_int<3, 5>({&a, &b, &c, &d, &e})) return {false, Sign::zero, false};
  const __m128d exy = _mm_loadu_pd(e.data()), ez = _mm_set1_pd(e[2]);
  const __m128d axy = _mm_sub_pd(_mm_loadu_pd(a.data()), exy), bxy = _mm_sub_pd(_mm_loadu_pd(b.data()), exy),
                cxy = _mm_sub_pd(_mm_loadu_pd(c.data()), exy), dxy = _mm_sub_pd(_mm_loadu_pd(d.data()), exy);
  const __m128d z1 = _mm_sub_pd(_mm_set_pd(c[2], a[2]), ez);  // (aez, cez)
  const __m128d z2 = _mm_sub_pd(_mm_set_pd(d[2], b[2]), ez);  // (bez, dez)
  // Every |difference| <= B (no NaN: all_int leaves integers, infinities and a finite e).
  const __m128d abs_mask = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
  __m128d m = _mm_max_pd(_mm_and_pd(axy, abs_mask), _mm_and_pd(bxy, abs_mask));
  m = _mm_max_pd(m, _mm_max_pd(_mm_and_pd(cxy, abs_mask), _mm_and_pd(dxy, abs_mask)));
  m = _mm_max_pd(m, _mm_max_pd(_mm_and_pd(z1, abs_mask), _mm_and_pd(z2, abs_mask)));
  if (_mm_movemask_pd(_mm_cmple_pd(m, _mm_set1_pd(is_bound))) != 3) return {false, Sign::zero, false};
  const __m128d x1 = _mm_unpacklo_pd(axy, cxy), y1 = _mm_unpackhi_pd(axy, cxy);  // (aex, cex), (aey, cey)
  const __m128d x2 = _mm_unpacklo_pd(bxy, dxy), y2 = _mm_unpackhi_pd(bxy, dxy);  // (bex, dex), (bey, dey)
  auto swap = [](__m128d v) { return _mm_shuffle_pd(v, v, 1); };
  const __m128d neg_high = _mm_set_pd(-0.0, 0.0);  // (x, y) -> (x, -y) by XOR
  const __m128d ab_cd = _mm_sub_pd(_mm_mul_pd(x1, y2), _mm_mul_pd(x2, y1));
  const __m128d bc_da = _mm_sub_pd(_mm_mul_pd(x2, swap(y1)), _mm_mul_pd(swap(x1), y2));
  const __m128d ac_bd = _mm_sub_pd(_mm_mul_pd(_mm_unpacklo_pd(x1, x2), _mm_unpackhi_pd(y1, y2)),
                                   _mm_mul_pd(_mm_unpackhi_pd(x1, x2), _mm_unpacklo_pd(y1, y2)));
  const __m128d ac = _mm_unpacklo_pd(ac_bd, ac_bd), bd = _mm_unpackhi_pd(ac_bd, ac_bd);
  const __m128d p = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(z1, bc_da), _mm_mul_pd(_mm_xor_pd(z2, neg_high), ac)),
                               _mm_mul_pd(swap(z1), ab_cd));  // (abc, cda)
  const __m128d q = _mm_add_pd(_mm_sub_pd(_mm_mul_pd(z2, swap(ab_cd)), _mm_mul_pd(_mm_xor_pd(swap(z1), neg_high), bd)),
                               _mm_mul_pd(swap(z2), bc_da));  // (bcd, dab)
  const __m128d l1 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x1, x1), _mm_mul_pd(y1, y1)), _mm_mul_pd(z1, z1));
  const __m128d l2 = _mm_add_pd(_mm_add_pd(_mm_mul_pd(x2, x2), _mm_mul_pd(y2, y2)), _mm_mul_pd(z2, z2));
  // (dlift abc - clift dab, blift cda - alift bcd)
  const __m128d r = _mm_sub_pd(_mm_mul_pd(swap(l2), p), swap(_mm_mul_pd(l1, q)));
  const Sign exact = sign_of(_mm_cvtsd_f64(r) + _mm_cvtsd_f64(swap(r)));
  if (exact != Sign::zero) return {true, exact, false};
  const __m128d w = _mm_set1_pd(is_key_base);
  const __m128d k1 = _mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(x1, w), y1), w), z1);  // (key a, key c)
  const __m128d k2 = _mm_add_pd(_mm_mul_pd(_mm_add_pd(_mm_mul_pd(x2, w), y2), w), z2);  // (key b, key d)
  const __m128d nq = _mm_xor_pd(q, _mm_set1_pd(-0.0));  // (-bcd, -dab)
  const __m128d pq = _mm_sub_pd(p, q);                  // (abc - bcd, cda - dab)
  const double last = -(_mm_cvtsd_f64(pq) + _mm_cvtsd_f64(swap(pq)));
  // Terms (-bcd, cda), (-dab, abc), and e's, of key 0.
  return {true,
          detail::first_by_decreasing_key_sse2<true>(_mm_unpacklo_pd(k1, k2), _mm_move_sd(p, nq),
                                                     _mm_unpackhi_pd(k1, k2), _mm_shuffle_pd(nq, p, 1),
                                                     _mm_setzero_pd(), _mm_set_sd(last)),
          true};
}
#endif

[[gnu::always_inline]] inline SosAnswer insphere_sos(const Point3& a, const Point3& b, const Point3& c,
                                                     const Point3& d, const Point3& e) {
#if defined(__SSE2__)
  return insphere_sos_sse2(a, b, c, d, e);
#else
  return insphere_sos_scalar(a, b, c, d, e);
#endif
}

}  // namespace dlab::small_integer
