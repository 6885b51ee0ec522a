// Stages A-D of the adaptive predicates and the mp fallback (Shewchuk 1997,
// section 4.3-4.4: orient2d / orient3d / incircle / insphere "adapt" schemes).
// Written from the paper's mathematics; error bounds and guards are derived in
// predicates/error_bounds.md, whose section numbers the comments cite.
//
// All arrays are fixed-size stack arrays whose capacities are the proven
// maximum expansion lengths (xp::Expansion<N>: N is computed by the type
// arithmetic of +, -, scale, *, so a capacity can never be too small).
#include "predicates/adaptive_kernel.hpp"

#include <bit>
#include <climits>
#include <cstdint>
#include <utility>

#include "predicates/expansion.hpp"
#include "predicates/mp_kernel.hpp"

namespace dlab::adaptive {
namespace {

using xp::Expansion;

// ---- Exponent guard (error_bounds.md section 2) -----------------------------------
// Exponent of the lowest set bit of a finite nonzero double: x is an integer
// multiple of 2^low_bit(x).
int low_bit(double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mant = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased == 0) return -1074 + std::countr_zero(mant);  // subnormal (mant != 0)
  mant |= std::uint64_t{1} << 52;
  return biased - 1075 + std::countr_zero(mant);
}

constexpr long grid_floor = -900;  // degree * grid >= -900: no bit is lost, bounds stay normal

// True when stages A-D are exact for these points: all coordinates finite, every
// product of `degree` coordinate differences is a multiple of 2^-900 (grid), and
// every coordinate difference is at most `hi` in magnitude (no overflow, Split safe).
template <int D, std::size_t N>
bool in_range(const std::array<const Point<D>*, N>& p, int degree, double hi) {
  int g = INT_MAX;
  double maxd = 0;
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      const double x = (*p[i])[j];
      if (!std::isfinite(x)) return false;
      if (x != 0) g = std::min(g, low_bit(x));
      maxd = std::max(maxd, std::fabs(x - (*p[N - 1])[j]));
    }
  if (!(maxd <= hi)) return false;  // also catches an infinite difference
  return g == INT_MAX || static_cast<long>(degree) * g >= grid_floor;
}

Staged decided(int s, unsigned char stage) { return {static_cast<Sign>(s), stage}; }
Staged decided(double det, unsigned char stage) { return {sign_of(det), stage}; }

// a*b - c*d exactly, zero components removed.
Expansion<4> prod_diff(double a, double b, double c, double d) {
  double x1, x0, y1, y0;
  xp::two_product(a, b, x1, x0);
  xp::two_product(c, d, y1, y0);
  double t[4];
  xp::two_two_diff(x1, x0, y1, y0, t[3], t[2], t[1], t[0]);
  Expansion<4> r;
  for (double v : t)
    if (v != 0.0) r.c[r.n++] = v;
  if (r.n == 0) r.c[r.n++] = 0.0;
  return r;
}

// ---- orient2d ---------------------------------------------------------------------
[[gnu::noinline]] Staged orient2d_d(const Expansion<4>& B, double acx, double acy, double bcx,
                                    double bcy, double acxt, double acyt, double bcxt,
                                    double bcyt) {
  // D = B + (acxt bcy - acyt bcx) + (acx bcyt - acy bcxt) + (acxt bcyt - acyt bcxt)  (4.1)
  const auto c1 = B + prod_diff(acxt, bcy, acyt, bcx);                 // <= 8
  const auto c2 = c1 + prod_diff(acx, bcyt, acy, bcxt);                // <= 12
  const auto d = c2 + prod_diff(acxt, bcyt, acyt, bcxt);               // <= 16
  static_assert(decltype(d)::capacity == 16);
  return decided(d.sign(), stage_d);
}

}  // namespace

Staged orient2d_slow(const Point2& pa, const Point2& pb, const Point2& pc) {
  if (!in_range<2, 3>({&pa, &pb, &pc}, 2, o2_hi))
    return {MpKernel{}.orient2d(pa, pb, pc), stage_mp};
  const double acx = pa[0] - pc[0], bcx = pb[0] - pc[0];
  const double acy = pa[1] - pc[1], bcy = pb[1] - pc[1];
  const double dl = acx * bcy, dr = acy * bcx;
  double det = dl - dr;
  // Stage A. If the two products differ in sign (or one is zero) the sign is exact:
  // each rounded product has the sign of the exact one.
  double detsum;
  if (dl > 0) {
    if (dr <= 0) return decided(det, stage_a);
    detsum = dl + dr;
  } else if (dl < 0) {
    if (dr >= 0) return decided(det, stage_a);
    detsum = -dl - dr;
  } else {
    return decided(det, stage_a);
  }
  double bound = o2A * detsum;
  if (det > bound || -det > bound) return decided(det, stage_a);

  // Stage B: exact determinant of the rounded differences.
  const auto B = prod_diff(acx, bcy, acy, bcx);
  det = B.estimate();
  bound = o2B * detsum;
  if (det > bound || -det > bound) return decided(det, stage_b);

  const double acxt = xp::two_diff_tail(pa[0], pc[0], acx);
  const double bcxt = xp::two_diff_tail(pb[0], pc[0], bcx);
  const double acyt = xp::two_diff_tail(pa[1], pc[1], acy);
  const double bcyt = xp::two_diff_tail(pb[1], pc[1], bcy);
  if (acxt == 0 && acyt == 0 && bcxt == 0 && bcyt == 0) return decided(B.sign(), stage_b);

  // Stage C: first-order correction.
  bound = o2C * detsum + result_err * std::fabs(det);
  det += (acx * bcyt + bcy * acxt) - (acy * bcxt + bcx * acyt);
  if (det > bound || -det > bound) return decided(det, stage_c);

  return orient2d_d(B, acx, acy, bcx, bcy, acxt, acyt, bcxt, bcyt);
}

// ---- orient3d ---------------------------------------------------------------------
namespace {

[[gnu::noinline]] Staged orient3d_d(const Point3& a, const Point3& b, const Point3& c,
                                    const Point3& d) {
  const auto adx = xp::diff(a[0], d[0]), ady = xp::diff(a[1], d[1]), adz = xp::diff(a[2], d[2]);
  const auto bdx = xp::diff(b[0], d[0]), bdy = xp::diff(b[1], d[1]), bdz = xp::diff(b[2], d[2]);
  const auto cdx = xp::diff(c[0], d[0]), cdy = xp::diff(c[1], d[1]), cdz = xp::diff(c[2], d[2]);
  auto bc = bdx * cdy - bdy * cdx;  // <= 16
  auto ca = cdx * ady - cdy * adx;
  auto ab = adx * bdy - ady * bdx;
  bc.compress(), ca.compress(), ab.compress();  // same values, shorter
  const auto det = (bc * adz + ca * bdz) + ab * cdz;  // <= 192
  static_assert(decltype(det)::capacity == 192);
  return decided(det.sign(), stage_d);
}

}  // namespace

Staged orient3d_slow(const Point3& pa, const Point3& pb, const Point3& pc, const Point3& pd) {
  if (!in_range<3, 4>({&pa, &pb, &pc, &pd}, 3, o3_hi))
    return {MpKernel{}.orient3d(pa, pb, pc, pd), stage_mp};
  const double adx = pa[0] - pd[0], ady = pa[1] - pd[1], adz = pa[2] - pd[2];
  const double bdx = pb[0] - pd[0], bdy = pb[1] - pd[1], bdz = pb[2] - pd[2];
  const double cdx = pc[0] - pd[0], cdy = pc[1] - pd[1], cdz = pc[2] - pd[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  double det = (adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy)) + cdz * (adxbdy - bdxady);
  const double perm = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                      (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                      (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  double bound = o3A * perm;
  if (det > bound || -det > bound) return decided(det, stage_a);

  // Stage B.
  auto bc = prod_diff(bdx, cdy, cdx, bdy);
  auto ca = prod_diff(cdx, ady, adx, cdy);
  auto ab = prod_diff(adx, bdy, bdx, ady);
  bc.compress(), ca.compress(), ab.compress();  // same values, shorter
  const auto fin = (xp::scale(bc, adz) + xp::scale(ca, bdz)) + xp::scale(ab, cdz);  // <= 24
  static_assert(decltype(fin)::capacity == 24);
  det = fin.estimate();
  bound = o3B * perm;
  if (det > bound || -det > bound) return decided(det, stage_b);

  const double adxt = xp::two_diff_tail(pa[0], pd[0], adx);
  const double bdxt = xp::two_diff_tail(pb[0], pd[0], bdx);
  const double cdxt = xp::two_diff_tail(pc[0], pd[0], cdx);
  const double adyt = xp::two_diff_tail(pa[1], pd[1], ady);
  const double bdyt = xp::two_diff_tail(pb[1], pd[1], bdy);
  const double cdyt = xp::two_diff_tail(pc[1], pd[1], cdy);
  const double adzt = xp::two_diff_tail(pa[2], pd[2], adz);
  const double bdzt = xp::two_diff_tail(pb[2], pd[2], bdz);
  const double cdzt = xp::two_diff_tail(pc[2], pd[2], cdz);
  if (adxt == 0 && bdxt == 0 && cdxt == 0 && adyt == 0 && bdyt == 0 && cdyt == 0 &&
      adzt == 0 && bdzt == 0 && cdzt == 0)
    return decided(fin.sign(), stage_b);

  // Stage C: first-order correction (error_bounds.md 4.3).
  bound = o3C * perm + result_err * std::fabs(det);
  det += (adz * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
          adzt * (bdx * cdy - bdy * cdx)) +
         (bdz * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
          bdzt * (cdx * ady - cdy * adx)) +
         (cdz * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
          cdzt * (adx * bdy - ady * bdx));
  if (det > bound || -det > bound) return decided(det, stage_c);

  return orient3d_d(pa, pb, pc, pd);
}

// ---- incircle ---------------------------------------------------------------------
namespace {

[[gnu::noinline]] Staged incircle_d(const Point2& a, const Point2& b, const Point2& c,
                                    const Point2& d) {
  const auto adx = xp::diff(a[0], d[0]), ady = xp::diff(a[1], d[1]);
  const auto bdx = xp::diff(b[0], d[0]), bdy = xp::diff(b[1], d[1]);
  const auto cdx = xp::diff(c[0], d[0]), cdy = xp::diff(c[1], d[1]);
  auto alift = adx * adx + ady * ady;  // <= 16
  auto blift = bdx * bdx + bdy * bdy;
  auto clift = cdx * cdx + cdy * cdy;
  auto bc = bdx * cdy - bdy * cdx;  // <= 16
  auto ca = cdx * ady - cdy * adx;
  auto ab = adx * bdy - ady * bdx;
  for (auto* e : {&alift, &blift, &clift, &bc, &ca, &ab}) e->compress();  // same values, shorter
  const auto det = (alift * bc + blift * ca) + clift * ab;  // <= 3 * 512
  static_assert(decltype(det)::capacity == 1536);
  return decided(det.sign(), stage_d);
}

// x^2 + y^2 exactly (<= 4 components), compressed (value unchanged, usually 1-2 left).
Expansion<4> lift2(double x, double y) {
  auto l = xp::product(x, x) + xp::product(y, y);
  l.compress();
  return l;
}

// e (x^2 + y^2) exactly: <= 2 * 4 * 4 = 32 components. Multiplying by the
// compressed lift costs one scale-expansion per lift component, instead of
// four scalings by the coordinates.
Expansion<32> times_lift2(Expansion<4> e, double x, double y) {
  e.compress();
  auto r = e * lift2(x, y);
  r.compress();
  return r;
}

}  // namespace

Staged incircle_slow(const Point2& pa, const Point2& pb, const Point2& pc, const Point2& pd) {
  if (!in_range<2, 4>({&pa, &pb, &pc, &pd}, 4, ic_hi))
    return {MpKernel{}.incircle(pa, pb, pc, pd), stage_mp};
  const double adx = pa[0] - pd[0], ady = pa[1] - pd[1];
  const double bdx = pb[0] - pd[0], bdy = pb[1] - pd[1];
  const double cdx = pc[0] - pd[0], cdy = pc[1] - pd[1];
  const double bdxcdy = bdx * cdy, bdycdx = bdy * cdx;
  const double cdxady = cdx * ady, cdyadx = cdy * adx;
  const double adxbdy = adx * bdy, adybdx = ady * bdx;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  double det = (alift * (bdxcdy - bdycdx) + blift * (cdxady - cdyadx)) + clift * (adxbdy - adybdx);
  const double perm = (std::fabs(bdxcdy) + std::fabs(bdycdx)) * alift +
                      (std::fabs(cdxady) + std::fabs(cdyadx)) * blift +
                      (std::fabs(adxbdy) + std::fabs(adybdx)) * clift;
  double bound = icA * perm;
  if (det > bound || -det > bound) return decided(det, stage_a);

  // Stage B.
  const auto bc = prod_diff(bdx, cdy, bdy, cdx);
  const auto ca = prod_diff(cdx, ady, cdy, adx);
  const auto ab = prod_diff(adx, bdy, ady, bdx);
  const auto fin = (times_lift2(bc, adx, ady) + times_lift2(ca, bdx, bdy)) +
                   times_lift2(ab, cdx, cdy);  // <= 96
  static_assert(decltype(fin)::capacity == 96);
  det = fin.estimate();
  bound = icB * perm;
  if (det > bound || -det > bound) return decided(det, stage_b);

  const double adxt = xp::two_diff_tail(pa[0], pd[0], adx);
  const double adyt = xp::two_diff_tail(pa[1], pd[1], ady);
  const double bdxt = xp::two_diff_tail(pb[0], pd[0], bdx);
  const double bdyt = xp::two_diff_tail(pb[1], pd[1], bdy);
  const double cdxt = xp::two_diff_tail(pc[0], pd[0], cdx);
  const double cdyt = xp::two_diff_tail(pc[1], pd[1], cdy);
  if (adxt == 0 && bdxt == 0 && cdxt == 0 && adyt == 0 && bdyt == 0 && cdyt == 0)
    return decided(fin.sign(), stage_b);

  // Stage C: first-order correction (error_bounds.md 4.3).
  bound = icC * perm + result_err * std::fabs(det);
  det += ((adx * adx + ady * ady) * ((bdx * cdyt + cdy * bdxt) - (bdy * cdxt + cdx * bdyt)) +
          2.0 * (adx * adxt + ady * adyt) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) * ((cdx * adyt + ady * cdxt) - (cdy * adxt + adx * cdyt)) +
          2.0 * (bdx * bdxt + bdy * bdyt) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) * ((adx * bdyt + bdy * adxt) - (ady * bdxt + bdx * adyt)) +
          2.0 * (cdx * cdxt + cdy * cdyt) * (adx * bdy - ady * bdx));
  if (det > bound || -det > bound) return decided(det, stage_c);

  return incircle_d(pa, pb, pc, pd);
}

// ---- insphere ---------------------------------------------------------------------
namespace {

// Raw 3x3 determinant det[p; q; r] of the (x, y, z) rows, exactly: <= 24 components.
Expansion<24> det3(const Point3& p, const Point3& q, const Point3& r) {
  // Expansion along z: pz M(q,r) - qz M(p,r) + rz M(p,q),  M(u,v) = ux vy - uy vx.
  const auto qr = prod_diff(q[0], r[1], q[1], r[0]);
  const auto pr = prod_diff(p[0], r[1], p[1], r[0]);
  const auto pq = prod_diff(p[0], q[1], p[1], q[0]);
  return (xp::scale(qr, p[2]) - xp::scale(pr, q[2])) + xp::scale(pq, r[2]);
}

// Stage D of insphere on raw coordinates (error_bounds.md 4.5): the 5x5 determinant
// with rows (x, y, z, x^2+y^2+z^2, 1) equals the insphere determinant. Expanding
// along the lifted column: det5 = sum_i (-1)^(i+3) L_i O_i, with O_i the 4x4
// determinant of rows (x, y, z, 1) of the other four points, itself expanded
// along the ones column into raw 3x3 determinants.
[[gnu::noinline]] Staged insphere_d(const Point3& a, const Point3& b, const Point3& c,
                                    const Point3& d, const Point3& e) {
  const std::array<const Point3*, 5> p = {&a, &b, &c, &d, &e};
  // Stage D works on raw coordinates, so its guard bounds them too (2.3); the
  // grid condition was already checked on entry (insphere_slow).
  for (const Point3* q : p)
    for (double x : *q)
      if (!(std::fabs(x) <= is_hi)) return {MpKernel{}.insphere(a, b, c, d, e), stage_mp};

  constexpr int kTerm = 1152, kAll = 5 * kTerm;
  double acc0[kAll], acc1[kAll];
  double* acc = acc0;
  double* spare = acc1;
  int accn = 0;
  for (int i = 0; i < 5; ++i) {
    int rows[4], k = 0;
    for (int j = 0; j < 5; ++j)
      if (j != i) rows[k++] = j;
    const Point3 &r0 = *p[rows[0]], &r1 = *p[rows[1]], &r2 = *p[rows[2]], &r3 = *p[rows[3]];
    // O = -det3(r1,r2,r3) + det3(r0,r2,r3) - det3(r0,r1,r3) + det3(r0,r1,r2)   (<= 96)
    auto o = (det3(r0, r2, r3) - det3(r1, r2, r3)) + (det3(r0, r1, r2) - det3(r0, r1, r3));
    static_assert(decltype(o)::capacity == 96);
    o.compress();  // same value, shorter
    const Point3& q = *p[i];
    auto term = (xp::scale(xp::scale(o, q[0]), q[0]) + xp::scale(xp::scale(o, q[1]), q[1])) +
                xp::scale(xp::scale(o, q[2]), q[2]);
    static_assert(decltype(term)::capacity == kTerm);
    if ((i + 3) % 2 != 0) term.negate();
    if (i == 0) {
      for (int j = 0; j < term.n; ++j) acc[j] = term.c[j];
      accn = term.n;
    } else {
      accn = xp::fast_expansion_sum_zeroelim(accn, acc, term.n, term.c, spare);
      std::swap(acc, spare);
    }
  }
  return decided(xp::sign(accn, acc), stage_d);
}

// 24-component 3x3 minor times |p|^2 = px^2 + py^2 + pz^2 exactly: <= 2 * 24 * 6 = 288.
// The lift is formed exactly and compressed first (usually 1-2 components), so
// the product costs one scale-expansion per lift component. Compression keeps
// every value and only shortens expansions; capacities stay the proven maxima.
Expansion<288> times_lift3(const Expansion<24>& m, double x, double y, double z) {
  auto l = (xp::product(x, x) + xp::product(y, y)) + xp::product(z, z);
  l.compress();
  auto r = m * l;
  r.compress();
  return r;
}

// First-order change of the 2x2 minor u_x v_y - v_x u_y.
inline double dminor(double ux, double uy, double vx, double vy, double uxt, double uyt,
                     double vxt, double vyt) {
  return (uxt * vy + ux * vyt) - (vxt * uy + vx * uyt);
}

[[gnu::noinline]] Staged insphere_bcd(const Point3& pa, const Point3& pb, const Point3& pc,
                                      const Point3& pd, const Point3& pe, double perm) {
  const double aex = pa[0] - pe[0], aey = pa[1] - pe[1], aez = pa[2] - pe[2];
  const double bex = pb[0] - pe[0], bey = pb[1] - pe[1], bez = pb[2] - pe[2];
  const double cex = pc[0] - pe[0], cey = pc[1] - pe[1], cez = pc[2] - pe[2];
  const double dex = pd[0] - pe[0], dey = pd[1] - pe[1], dez = pd[2] - pe[2];

  // Stage B: exact determinant of the rounded differences (<= 1152 components).
  auto ab = prod_diff(aex, bey, bex, aey);
  auto bc = prod_diff(bex, cey, cex, bey);
  auto cd = prod_diff(cex, dey, dex, cey);
  auto da = prod_diff(dex, aey, aex, dey);
  auto ac = prod_diff(aex, cey, cex, aey);
  auto bd = prod_diff(bex, dey, dex, bey);
  ab.compress(), bc.compress(), cd.compress(), da.compress(), ac.compress(), bd.compress();
  auto abc = (xp::scale(bc, aez) - xp::scale(ac, bez)) + xp::scale(ab, cez);  // <= 24
  auto bcd = (xp::scale(cd, bez) - xp::scale(bd, cez)) + xp::scale(bc, dez);
  auto cda = (xp::scale(da, cez) + xp::scale(ac, dez)) + xp::scale(cd, aez);
  auto dab = (xp::scale(ab, dez) + xp::scale(bd, aez)) + xp::scale(da, bez);
  abc.compress(), bcd.compress(), cda.compress(), dab.compress();
  static_assert(decltype(abc)::capacity == 24);
  const auto fin = (times_lift3(abc, dex, dey, dez) - times_lift3(dab, cex, cey, cez)) +
                   (times_lift3(cda, bex, bey, bez) - times_lift3(bcd, aex, aey, aez));
  static_assert(decltype(fin)::capacity == 1152);
  double det = fin.estimate();
  double bound = isB * perm;
  if (det > bound || -det > bound) return decided(det, stage_b);

  const double aext = xp::two_diff_tail(pa[0], pe[0], aex);
  const double aeyt = xp::two_diff_tail(pa[1], pe[1], aey);
  const double aezt = xp::two_diff_tail(pa[2], pe[2], aez);
  const double bext = xp::two_diff_tail(pb[0], pe[0], bex);
  const double beyt = xp::two_diff_tail(pb[1], pe[1], bey);
  const double bezt = xp::two_diff_tail(pb[2], pe[2], bez);
  const double cext = xp::two_diff_tail(pc[0], pe[0], cex);
  const double ceyt = xp::two_diff_tail(pc[1], pe[1], cey);
  const double cezt = xp::two_diff_tail(pc[2], pe[2], cez);
  const double dext = xp::two_diff_tail(pd[0], pe[0], dex);
  const double deyt = xp::two_diff_tail(pd[1], pe[1], dey);
  const double dezt = xp::two_diff_tail(pd[2], pe[2], dez);
  if (aext == 0 && aeyt == 0 && aezt == 0 && bext == 0 && beyt == 0 && bezt == 0 &&
      cext == 0 && ceyt == 0 && cezt == 0 && dext == 0 && deyt == 0 && dezt == 0)
    return decided(fin.sign(), stage_b);

  // Stage C (error_bounds.md 4.4): det += sum over the four lifted rows of
  // L_p dM_p + dL_p M_p, with the float minors and their first-order changes.
  const double fab = aex * bey - bex * aey, fbc = bex * cey - cex * bey;
  const double fcd = cex * dey - dex * cey, fda = dex * aey - aex * dey;
  const double fac = aex * cey - cex * aey, fbd = bex * dey - dex * bey;
  const double dab2 = dminor(aex, aey, bex, bey, aext, aeyt, bext, beyt);
  const double dbc2 = dminor(bex, bey, cex, cey, bext, beyt, cext, ceyt);
  const double dcd2 = dminor(cex, cey, dex, dey, cext, ceyt, dext, deyt);
  const double dda2 = dminor(dex, dey, aex, aey, dext, deyt, aext, aeyt);
  const double dac2 = dminor(aex, aey, cex, cey, aext, aeyt, cext, ceyt);
  const double dbd2 = dminor(bex, bey, dex, dey, bext, beyt, dext, deyt);
  const double fabc = (aez * fbc - bez * fac) + cez * fab;
  const double fbcd = (bez * fcd - cez * fbd) + dez * fbc;
  const double fcda = (cez * fda + dez * fac) + aez * fcd;
  const double fdab = (dez * fab + aez * fbd) + bez * fda;
  const double dabc = ((aezt * fbc - bezt * fac) + cezt * fab) +
                      ((aez * dbc2 - bez * dac2) + cez * dab2);
  const double dbcd = ((bezt * fcd - cezt * fbd) + dezt * fbc) +
                      ((bez * dcd2 - cez * dbd2) + dez * dbc2);
  const double dcda = ((cezt * fda + dezt * fac) + aezt * fcd) +
                      ((cez * dda2 + dez * dac2) + aez * dcd2);
  const double ddab = ((dezt * fab + aezt * fbd) + bezt * fda) +
                      ((dez * dab2 + aez * dbd2) + bez * dda2);
  const double alift = (aex * aex + aey * aey) + aez * aez;
  const double blift = (bex * bex + bey * bey) + bez * bez;
  const double clift = (cex * cex + cey * cey) + cez * cez;
  const double dlift = (dex * dex + dey * dey) + dez * dez;
  const double dalift = 2.0 * ((aex * aext + aey * aeyt) + aez * aezt);
  const double dblift = 2.0 * ((bex * bext + bey * beyt) + bez * bezt);
  const double dclift = 2.0 * ((cex * cext + cey * ceyt) + cez * cezt);
  const double ddlift = 2.0 * ((dex * dext + dey * deyt) + dez * dezt);
  const double ta = alift * dbcd + dalift * fbcd;
  const double tb = blift * dcda + dblift * fcda;
  const double tc = clift * ddab + dclift * fdab;
  const double td = dlift * dabc + ddlift * fabc;
  bound = isC * perm + result_err * std::fabs(det);
  det += (td - tc) + (tb - ta);
  if (det > bound || -det > bound) return decided(det, stage_c);

  return insphere_d(pa, pb, pc, pd, pe);
}

}  // namespace

Staged insphere_slow(const Point3& pa, const Point3& pb, const Point3& pc, const Point3& pd,
                     const Point3& pe) {
  if (!in_range<3, 5>({&pa, &pb, &pc, &pd, &pe}, 5, is_hi))
    return {MpKernel{}.insphere(pa, pb, pc, pd, pe), stage_mp};
  const double aex = pa[0] - pe[0], aey = pa[1] - pe[1], aez = pa[2] - pe[2];
  const double bex = pb[0] - pe[0], bey = pb[1] - pe[1], bez = pb[2] - pe[2];
  const double cex = pc[0] - pe[0], cey = pc[1] - pe[1], cez = pc[2] - pe[2];
  const double dex = pd[0] - pe[0], dey = pd[1] - pe[1], dez = pd[2] - pe[2];
  const double aexbey = aex * bey, bexaey = bex * aey;
  const double bexcey = bex * cey, cexbey = cex * bey;
  const double cexdey = cex * dey, dexcey = dex * cey;
  const double dexaey = dex * aey, aexdey = aex * dey;
  const double aexcey = aex * cey, cexaey = cex * aey;
  const double bexdey = bex * dey, dexbey = dex * bey;
  const double ab = aexbey - bexaey, bc = bexcey - cexbey, cd = cexdey - dexcey;
  const double da = dexaey - aexdey, ac = aexcey - cexaey, bd = bexdey - dexbey;
  const double abc = (aez * bc - bez * ac) + cez * ab;
  const double bcd = (bez * cd - cez * bd) + dez * bc;
  const double cda = (cez * da + dez * ac) + aez * cd;
  const double dab = (dez * ab + aez * bd) + bez * da;
  const double alift = (aex * aex + aey * aey) + aez * aez;
  const double blift = (bex * bex + bey * bey) + bez * bez;
  const double clift = (cex * cex + cey * cey) + cez * cez;
  const double dlift = (dex * dex + dey * dey) + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  // Permanent: the same expression on absolute values (4.2).
  const double pab = std::fabs(aexbey) + std::fabs(bexaey);
  const double pbc = std::fabs(bexcey) + std::fabs(cexbey);
  const double pcd = std::fabs(cexdey) + std::fabs(dexcey);
  const double pda = std::fabs(dexaey) + std::fabs(aexdey);
  const double pac = std::fabs(aexcey) + std::fabs(cexaey);
  const double pbd = std::fabs(bexdey) + std::fabs(dexbey);
  const double aezp = std::fabs(aez), bezp = std::fabs(bez), cezp = std::fabs(cez),
               dezp = std::fabs(dez);
  const double pabc = (aezp * pbc + bezp * pac) + cezp * pab;
  const double pbcd = (bezp * pcd + cezp * pbd) + dezp * pbc;
  const double pcda = (cezp * pda + dezp * pac) + aezp * pcd;
  const double pdab = (dezp * pab + aezp * pbd) + bezp * pda;
  const double perm = (dlift * pabc + clift * pdab) + (blift * pcda + alift * pbcd);
  const double bound = isA * perm;
  if (det > bound || -det > bound) return decided(det, stage_a);
  return insphere_bcd(pa, pb, pc, pd, pe, perm);
}

}  // namespace dlab::adaptive
