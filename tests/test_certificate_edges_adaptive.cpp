// Every certificate of the adaptive kernel at its edges (issue 17, section 1):
// the inline filters (orient2d stage A, error_bounds.md 4.6; incircle lift filter
// 3.3; orient3d per-call filter 3.4; insphere lift filter 3.1-3.2), the static
// orient3d filter fitted to the input (3.5), stage A of orient3d (4.2), and the
// exponent guards of the exact stages (2: grid, overflow, stage D's raw coordinates).
//
// Method. For each certificate the test computes, from error_bounds.md and not
// from the kernel, the value the kernel compares (the determinant in the
// documented evaluation order) and the documented bound (constants, floors,
// overflow factors, in the documented order of operations), and builds inputs
// whose |det| is the double just below, equal to and just above the bound (one
// ulp: configurations whose determinant is computed exactly or whose bound can be
// tuned by a free mantissa), at every binade of the inputs from subnormals to
// 2^1023, with both signs. It then asserts that the kernel's sign is mp's and that
// the stage that answered is the one the documented test selects: a certificate
// that answers one ulp below its bound, or one whose guard lets one more binade
// through, fails here. Exact-zero configurations take the guards' thresholds and
// one ulp beyond them. The constants themselves are checked against their
// derivation (error_bounds.md 3.1-3.4, 4.2-4.6), recomputed here.
#include <algorithm>
#include <array>
#include <bit>
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <climits>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <rapidcheck/catch.h>
#include <sstream>
#include <string>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/determinants.hpp"
#include "predicates/mp_kernel.hpp"
#include "tests/sanitized_build.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;
constexpr double inf = std::numeric_limits<double>::infinity();
const MpKernel mk;

// Position on the line of doubles: ord(nextafter(x, +inf)) = ord(x) + 1, ord(-x) = -ord(x).
std::int64_t ord(double x) {
  const auto b = std::bit_cast<std::int64_t>(x);
  return b < 0 ? -(b & std::numeric_limits<std::int64_t>::max()) : b;
}
double from_ord(std::int64_t o) {
  return o < 0 ? -std::bit_cast<double>(-o) : std::bit_cast<double>(o);
}

// Smallest x in [lo, hi] (doubles, lo <= hi) with key(x) >= 0 for a key that is
// nondecreasing there (hi if none): bisection on ord.
double first_at_least(double lo, double hi, const std::function<std::int64_t(double)>& key) {
  std::int64_t a = ord(lo), b = ord(hi);
  if (key(lo) >= 0) return lo;
  if (key(hi) < 0) return hi;
  while (b - a > 1) {
    const std::int64_t m = a + (b - a) / 2;
    (key(from_ord(m)) >= 0 ? b : a) = m;
  }
  return from_ord(b);
}

// Inputs whose |det| was one ulp below, at, and one ulp above a finite bound,
// where the stage under test ran (counted per certificate).
struct EdgeHits {
  std::array<int, 3> n{};
  void note(double det, double bound) {
    if (!(bound < inf) || bound <= 0) return;
    const std::int64_t d = ord(std::fabs(det)) - ord(bound);
    if (d >= -1 && d <= 1) ++n[static_cast<std::size_t>(d + 1)];
  }
  bool all() const { return n[0] > 0 && n[1] > 0 && n[2] > 0; }
};
std::string show(const EdgeHits& e) {
  return std::to_string(e.n[0]) + " / " + std::to_string(e.n[1]) + " / " + std::to_string(e.n[2]);
}

template <class... T>
std::string str(const T&... v) {
  std::ostringstream o;
  o.precision(17);
  (o << ... << v);
  return o.str();
}
std::string str_points(std::initializer_list<const double*> ps, int dim) {
  std::ostringstream o;
  o << std::hexfloat;
  for (const double* p : ps) {
    o << '(';
    for (int j = 0; j < dim; ++j) o << p[j] << (j + 1 < dim ? ", " : ")");
  }
  return o.str();
}

bool finite_all(std::initializer_list<double> v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// The documented floors and guard thresholds, as numbers (error_bounds.md 2, 3.2-3.4), so
// that the edges below are those of the document even if a constant in the kernel moves.
constexpr double o3_lo = 0x1p-320, ic_lo = 0x1p-480, is_lo = 0x1p-185;
constexpr double o2_hi = 0x1p490, o3_hi = 0x1p325, ic_hi = 0x1p245, is_hi = 0x1p195;

// ---- Section 2: the exponent guard of the exact stages, as documented -------------
// Lowest set bit of a finite nonzero double, by division (not the kernel's bit fiddling).
int lowest_bit(double x) {
  x = std::fabs(x);
  int e = std::max(std::ilogb(x) - 52, -1074);
  while (e < std::ilogb(x) && std::fmod(x, std::ldexp(1.0, e + 1)) == 0) ++e;
  return e;
}
template <std::size_t N, std::size_t D>
bool guard_passes(const std::array<std::array<double, D>, N>& p, int degree, double hi) {
  int g = INT_MAX;
  for (const auto& q : p)
    for (std::size_t j = 0; j < D; ++j) {
      if (!std::isfinite(q[j])) return false;
      if (q[j] != 0) g = std::min(g, lowest_bit(q[j]));
      if (!(std::fabs(q[j] - p[N - 1][j]) <= hi)) return false;
    }
  return g == INT_MAX || degree * g >= -900;
}

// ---- Section 3.4: the orient3d per-call filter, as documented ---------------------
struct DetBound {
  double det, bound;
  bool overflow;  // some intermediate of det is not finite
};
DetBound o3_filter_doc(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double p0 = bdx * cdy, p1 = cdx * ady, p2 = adx * bdy;  // s0's products
  const double q0 = bdy * cdx, q1 = cdy * adx, q2 = ady * bdx;  // s1's
  const double m0 = adz * p0, m1 = bdz * p1, m2 = cdz * p2, n0 = adz * q0, n1 = bdz * q1,
               n2 = cdz * q2;
  const double s0p = m0 + m1, s1p = n0 + n1, s0 = s0p + m2, s1 = s1p + n2, det = s0 - s1;
  auto mx = [](double u, double v, double w) {
    return std::max({std::fabs(u), std::fabs(v), std::fabs(w), o3_lo});
  };
  const double mxx = mx(adx, bdx, cdx), myy = mx(ady, bdy, cdy), mzz = mx(adz, bdz, cdz);
  const double bound = (adaptive::o3_ss / 8) * ((mxx * myy) * (8 * mzz));
  return {det, bound,
          !finite_all({p0, p1, p2, q0, q1, q2, m0, m1, m2, n0, n1, n2, s0p, s1p, s0, s1, det})};
}

// Section 3.5: the static bound for a kernel fitted to pts.
double static_bound_doc(const std::vector<Point3>& pts) {
  double g = 0;
  for (int j = 0; j < 3; ++j) {
    double lo = pts[0][j], hi = pts[0][j];
    for (const Point3& p : pts) lo = std::min(lo, p[j]), hi = std::max(hi, p[j]);
    g = std::max(g, hi - lo);
  }
  const double w = std::max(4 * g, o3_lo);
  return (adaptive::o3_ss / 8) * ((w * w) * (8 * w));
}

// ---- Section 3.3: the incircle lift filter, as documented --------------------------
DetBound ic_filter_doc(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], bdx = b[0] - d[0], bdy = b[1] - d[1],
               cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double ax2 = adx * adx, ay2 = ady * ady, bx2 = bdx * bdx, by2 = bdy * bdy,
               cx2 = cdx * cdx, cy2 = cdy * cdy;
  const double al = ax2 + ay2, bl = bx2 + by2, cl = cx2 + cy2;
  const double u0 = bdx * cdy, u1 = bdy * cdx, v0 = cdx * ady, v1 = cdy * adx, w0 = adx * bdy,
               w1 = ady * bdx;
  const double bc = u0 - u1, ca = v0 - v1, ab = w0 - w1;
  const double t0 = al * bc, t1 = bl * ca, t2 = cl * ab, part = t0 + t1, det = part + t2;
  const double s = std::max((al + bl) + cl, ic_lo);
  const double bound = adaptive::ic_lift_filter * (s * s);
  return {det, bound,
          !finite_all({ax2, ay2, bx2, by2, cx2, cy2, al, bl, cl, u0, u1, v0, v1, w0, w1, bc, ca,
                       ab, t0, t1, t2, part, det})};
}

// ---- Sections 3.1-3.2: the insphere lift filter, as documented ---------------------
DetBound is_filter_doc(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& e) {
  std::vector<double> all;  // every intermediate, for the overflow claim
  auto k = [&](double v) {
    all.push_back(v);
    return v;
  };
  const double aex = a[0] - e[0], aey = a[1] - e[1], aez = a[2] - e[2];
  const double bex = b[0] - e[0], bey = b[1] - e[1], bez = b[2] - e[2];
  const double cex = c[0] - e[0], cey = c[1] - e[1], cez = c[2] - e[2];
  const double dex = d[0] - e[0], dey = d[1] - e[1], dez = d[2] - e[2];
  auto minor2 = [&](double ux, double uy, double vx, double vy) {
    return k(k(ux * vy) - k(vx * uy));
  };
  const double ab = minor2(aex, aey, bex, bey), bc = minor2(bex, bey, cex, cey),
               cd = minor2(cex, cey, dex, dey), da = minor2(dex, dey, aex, aey),
               ac = minor2(aex, aey, cex, cey), bd = minor2(bex, bey, dex, dey);
  const double abc = k(k(k(aez * bc) - k(bez * ac)) + k(cez * ab));
  const double bcd = k(k(k(bez * cd) - k(cez * bd)) + k(dez * bc));
  const double cda = k(k(k(cez * da) + k(dez * ac)) + k(aez * cd));
  const double dab = k(k(k(dez * ab) + k(aez * bd)) + k(bez * da));
  auto lift = [&](double x, double y, double z) {
    return k(k(k(x * x) + k(y * y)) + k(z * z));
  };
  const double al = lift(aex, aey, aez), bl = lift(bex, bey, bez), cl = lift(cex, cey, cez),
               dl = lift(dex, dey, dez);
  const double det = k(k(k(dl * abc) - k(cl * dab)) + k(k(bl * cda) - k(al * bcd)));
  const double L = std::max({al, bl, cl, dl, is_lo * is_lo});
  const double mz =
      std::max({std::fabs(aez), std::fabs(bez), std::fabs(cez), std::fabs(dez), is_lo});
  const double bound = (adaptive::is_lift_filter / 128) * (((128 * L) * L) * mz);
  bool overflow = false;
  for (double v : all) overflow = overflow || !std::isfinite(v);
  return {det, bound, overflow};
}

// ---- Section 4.6: orient2d's inline stage A, as documented -------------------------
DetBound o2_inline_doc(const Point2& a, const Point2& b, const Point2& c) {
  const double dl = (a[0] - c[0]) * (b[1] - c[1]), dr = (a[1] - c[1]) * (b[0] - c[0]);
  const double det = dl - dr;
  const double bound = adaptive::o2A * (1 + 0x1p-40) * std::fabs(dl + dr) + 0x1p-1072;
  return {det, bound, !finite_all({dl, dr, det, dl + dr})};
}

// ---- Section 4.2: orient3d's out-of-line stage A, as documented --------------------
struct DetPerm {
  double det, bound;
};
DetPerm o3_stage_a_doc(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const double bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const double cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy, cdxady = cdx * ady, adxcdy = adx * cdy,
               adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det =
      (adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy)) + cdz * (adxbdy - bdxady);
  const double perm = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
                      (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
                      (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz);
  return {det, adaptive::o3A * perm};
}

// Fails a RapidCheck property or a Catch2 test with the message (empty: passed).
#define EDGE_CHECK_RC(msg)                 \
  do {                                     \
    const std::string m_ = (msg);          \
    if (!m_.empty()) RC_FAIL(m_);          \
  } while (0)
#define EDGE_CHECK_CATCH(msg)              \
  do {                                     \
    const std::string m_ = (msg);          \
    INFO(m_);                              \
    REQUIRE(m_.empty());                   \
  } while (0)

const char* stage_name(unsigned char s) {
  return AdaptiveKernel::stage_names[s].data();
}

}  // namespace

// ======================================================================================
TEST_CASE("adaptive constants are the ones error_bounds.md derives", "[adaptive][edges]") {
  using namespace adaptive;
  // Stage constants, table of 4.2-4.4: (a + b eps) eps and (a + b eps) eps^2.
  CHECK(o2A == (3.0 + 16.0 * eps) * eps);
  CHECK(o3A == (7.0 + 56.0 * eps) * eps);
  CHECK(icA == (10.0 + 96.0 * eps) * eps);
  CHECK(isA == (16.0 + 224.0 * eps) * eps);
  CHECK(o2B == (2.0 + 12.0 * eps) * eps);
  CHECK(o3B == (3.0 + 28.0 * eps) * eps);
  CHECK(icB == (4.0 + 48.0 * eps) * eps);
  CHECK(isB == (5.0 + 96.0 * eps) * eps);  // not the paper's 72 (4.3)
  CHECK(o2C == (9.0 + 64.0 * eps) * eps * eps);
  CHECK(o3C == (26.0 + 288.0 * eps) * eps * eps);
  CHECK(icC == (44.0 + 576.0 * eps) * eps * eps);
  CHECK(isC == (80.0 + 4096.0 * eps) * eps * eps);
  CHECK(result_err == (3.0 + 8.0 * eps) * eps);
  // Inline orient2d (4.6).
  CHECK(o2_fast == o2A * (1 + 0x1p-40));
  CHECK(o2_fast_abs == 0x1p-1072);
  // Floors, overflow-related thresholds and guards (3.2-3.4, 2).
  CHECK(adaptive::o3_ss_lo == 0x1p-320);
  CHECK(adaptive::is_lo == 0x1p-185);
  CHECK(adaptive::ic_lift_lo == 0x1p-480);
  CHECK(adaptive::o2_hi == 0x1p490);
  CHECK(adaptive::o3_hi == 0x1p325);
  CHECK(adaptive::ic_hi == 0x1p245);
  CHECK(adaptive::is_hi == 0x1p195);

  // The filter constants against the calculus of 3.1, recomputed here in exact
  // rationals on the documented expression trees: each constant must be at least
  // (1+eps)^(r+1) (e_u + e_v) of its tree (r roundings in the bound).
  struct E {
    Q m, e;
  };
  const Q qe = Q(eps);
  const E dn{Q(1), qe};
  auto mul = [&](E x, E y) { return E{x.m * y.m * (1 + qe), qe * x.m * y.m + x.m * y.e + (y.m + y.e) * x.e}; };
  auto add = [&](E x, E y) { return E{(x.m + y.m) * (1 + qe), qe * (x.m + y.m) + x.e + y.e}; };
  auto need = [&](E u, E v, int r) {
    Q c = u.e + v.e;
    for (int i = 0; i <= r; ++i) c *= 1 + qe;
    return c;
  };
  const E mono = mul(dn, mul(dn, dn));
  const E half3 = add(add(mono, mono), mono);
  CHECK(Q(o3_ss) >= need(half3, half3, 3));
  CHECK(Q(o3_ss) <= need(half3, half3, 3) * (1 + Q(0x1p-39)));  // and no looser than derived
  const E m2 = add(mul(dn, dn), mul(dn, dn));
  const E lift3 = add(add(mul(dn, dn), mul(dn, dn)), mul(dn, dn));
  const E minor3 = add(add(mul(dn, m2), mul(dn, m2)), mul(dn, m2));
  const E ishalf = add(mul(lift3, minor3), mul(lift3, minor3));
  CHECK(Q(is_filter) >= need(ishalf, ishalf, 5));
  // 3.2: the lift filter pays (1+eps)^3 more (L = (1+eps) max computed lift).
  CHECK(Q(is_lift_filter) >= Q(is_filter) * (1 + qe) * (1 + qe) * (1 + qe));
  // 3.3: icA (1+eps)^7 / (3 (1-eps)^10).
  Q ic = Q(icA);
  for (int i = 0; i < 7; ++i) ic *= 1 + qe;
  for (int i = 0; i < 10; ++i) ic /= 1 - qe;
  CHECK(Q(ic_lift_filter) >= ic / 3);
  // Overflow factors (3.2, 3.4): every intermediate of det is below 72 (1+eps)^10 L^2 mz
  // (insphere) and 6 (1+eps)^5 mx my mz (orient3d); the factors must exceed them.
  CHECK(Q(2) * ishalf.m * (1 + qe) * (1 + qe) * (1 + qe) * (1 + qe) * (1 + qe) * (1 + qe) < 128);
  CHECK(Q(2) * half3.m * (1 + qe) * (1 + qe) * (1 + qe) < 8);
}

// ======================================================================================
// orient3d: a = (X, 0, Z), b = (0, Y, 0), c = (0, 0, t), d = 0 (then the axes permuted):
// every difference is exact, s1 = 0 and s0 = t (X Y), so with X, Y powers of two det
// = t X Y exactly (unless it underflows) and t puts det on any double near the bound.
namespace {

struct O3Case {
  int ex, ey, ez;   // X = 2^ex, Y = 2^ey, Z = zm 2^ez
  double zm;        // in [1, 2)
  int offset;       // det = the bound moved by offset ulps (|offset| <= 2), or x2, /2
  bool negative, swap_ab;
  int axes;         // permutation of the axes, 0..5
};

std::array<Point3, 4> o3_points(const O3Case& k, double t) {
  const double X = std::ldexp(1.0, k.ex), Y = std::ldexp(1.0, k.ey), Z = std::ldexp(k.zm, k.ez);
  std::array<Point3, 4> p = {{{X, 0, Z}, {0, Y, 0}, {0, 0, t}, {0, 0, 0}}};
  if (k.swap_ab) std::swap(p[0], p[1]);
  static constexpr int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for (Point3& q : p) q = {q[perms[k.axes][0]], q[perms[k.axes][1]], q[perms[k.axes][2]]};
  return p;
}

// det moved `offset` ulps from the bound (offset 3: twice the bound, -3: half).
double o3_target(double bound, int offset) {
  if (offset == 3) return 2 * bound;
  if (offset == -3) return bound / 2;
  return from_ord(ord(bound) + offset);
}

// t with |det| = target (the bound moved by offset), or the nearest the family reaches:
// t = target / (X Y) (the bound may depend on t slightly, through a fitted box), then
// ulp steps.
double o3_tune(const O3Case& k, const std::function<double(const std::array<Point3, 4>&)>& bound_of) {
  const double XY = std::ldexp(1.0, k.ex + k.ey), sign = k.negative ? -1.0 : 1.0;
  double t = std::ldexp(k.zm, k.ez);
  for (int i = 0; i < 3; ++i) {
    const double target = o3_target(bound_of(o3_points(k, sign * t)), k.offset);
    const double next = target / XY;
    if (!std::isfinite(next) || next == 0) break;
    t = next;
  }
  for (int i = 0; i < 6; ++i) {
    const auto p = o3_points(k, sign * t);
    const double target = o3_target(bound_of(p), k.offset);
    const double det = std::fabs(o3_filter_doc(p[0], p[1], p[2], p[3]).det);
    if (det == target || det == 0 || !std::isfinite(det) || !(target < inf)) break;
    t = det < target ? std::nextafter(t, inf) : std::nextafter(t, 0.0);
  }
  return sign * t;
}

// The per-call filter: the kernel answers in stage "filter" exactly when |det| > bound.
std::string check_o3_filter(const O3Case& k, EdgeHits& hits) {
  const double t = o3_tune(k, [](const std::array<Point3, 4>& p) {
    return o3_filter_doc(p[0], p[1], p[2], p[3]).bound;
  });
  const auto p = o3_points(k, t);
  const DetBound f = o3_filter_doc(p[0], p[1], p[2], p[3]);
  const AdaptiveKernel ak;
  const Staged s = ak.orient3d_staged(p[0], p[1], p[2], p[3]);
  const Sign exact = mk.orient3d(p[0], p[1], p[2], p[3]);
  const bool answers = f.det > f.bound || -f.det > f.bound;
  hits.note(f.det, f.bound);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 3) +
                            str(" det ", f.det, " bound ", f.bound, " stage ", stage_name(s.stage));
  if (s.sign != exact) return "orient3d sign differs from mp at " + where;
  if ((s.stage == adaptive::stage_filter) != answers)
    return "orient3d filter answered against its documented bound at " + where;
  if (f.overflow && s.stage == adaptive::stage_filter)
    return "orient3d filter answered on an overflowed determinant at " + where;
  // The kernel's exported bound is the documented one, bit for bit.
  for (const double kb : {adaptive::orient3d_filter(p[0], p[1], p[2], p[3]).bound,
                          adaptive::orient3d_filter_scalar(p[0], p[1], p[2], p[3]).bound})
    if (!(kb == f.bound || (std::isnan(kb) && std::isnan(f.bound))))
      return "orient3d filter bound (SSE2 or scalar) differs from error_bounds.md 3.4 at " + where;
  return "";
}

}  // namespace

TEST_CASE("orient3d filter: exact at one ulp around its bound, in every binade",
          "[adaptive][edges]") {
  EdgeHits hits;
  // Sweep: every common binade of X = Y = Z from subnormal to 2^1023, both signs,
  // det one ulp below / at / above the bound and a binade away.
  for (int e = -1074; e <= 1023; ++e)
    for (int offset : {-3, -1, 0, 1, 3})
      for (bool neg : {false, true})
        EDGE_CHECK_CATCH(
            check_o3_filter({e, e, e, 1.0, offset, neg, (e & 1) != 0, ((e % 6) + 6) % 6}, hits));
  // The floors: each axis maximum alone below 2^-320 (the others at 1), at every binade.
  for (int axis = 0; axis < 3; ++axis)
    for (int e = -420; e <= -220; ++e)
      for (int offset : {-3, -1, 0, 1, 3})
        EDGE_CHECK_CATCH(check_o3_filter({axis == 0 ? e : 0, axis == 1 ? e : 0, axis == 2 ? e : 0,
                                          1.5, offset, (e & 1) != 0, false, axis * 2},
                                         hits));
  // Near overflow: X Y Z between 2^1019 and 2^1025, where (mx' my') 8 mz' overflows
  // first (error_bounds.md 3.4: the factor 8).
  for (int ez = 337; ez <= 344; ++ez)
    for (double zm : {1.0, 1.25, 1.5, 1.75})
      for (int offset : {-1, 0, 1})
        EDGE_CHECK_CATCH(check_o3_filter({340, 340, ez, zm, offset, (ez & 1) != 0, false, ez % 6}, hits));
  INFO("inputs with |det| one ulp below / at / above the bound: " << show(hits));
  CHECK(hits.all());

  rc::prop("random axis binades, mantissas, signs and axis orders", [] {
    EdgeHits h;
    const O3Case k{*rc::gen::inRange(-1074, 1024), *rc::gen::inRange(-1074, 1024),
                   *rc::gen::inRange(-1074, 1024),
                   1 + static_cast<double>(*rc::gen::inRange(0, 1 << 20)) * 0x1p-20,
                   *rc::gen::inRange(-3, 4), *rc::gen::arbitrary<bool>(),
                   *rc::gen::arbitrary<bool>(), *rc::gen::inRange(0, 6)};
    EDGE_CHECK_RC(check_o3_filter(k, h));
  });
}

// ======================================================================================
// The static filter (3.5): fitted to a box of width G, B_s = the 3.4 bound with every
// axis maximum max(fl(4 G), 2^-320). The call's points lie at the edge of the cover
// (1.01 G around the box: differences up to 3.02 G), det one ulp around B_s.
namespace {

std::string check_static(int e, int offset, bool neg, bool swap_ab, int axes, bool margin,
                         EdgeHits& hits) {
  // X = Y = 2^e, Z = 1.5 2^e; the fitted box is either the call's own points or a box
  // of width G = 2^e / 3.02 (rounded up) at 1.01 G from them, so that the call's
  // differences reach 3.02 G.
  const O3Case k{e, e, e, 1.5, offset, neg, swap_ab, axes};
  const double X = std::ldexp(1.0, e), Z = std::ldexp(1.5, e);
  auto fitted_points = [&](const std::array<Point3, 4>& p) {
    std::vector<Point3> pts(p.begin(), p.end());
    if (margin) {
      // G a hair above Z / 3.02 and the box 1.01 G (less a hair) from 0: the call
      // reaches 3.02 G on the far side.
      const double g = std::max(X, Z) / 3.02 * (1 + 1e-9);
      const double lo = 1.01 * g * (1 - 1e-12);
      pts = {{lo, lo, lo}, {lo + g, lo + g, lo + g}};
    }
    return pts;
  };
  const double t = o3_tune(k, [&](const std::array<Point3, 4>& p) {
    return static_bound_doc(fitted_points(p));
  });
  const auto p = o3_points(k, t);
  const std::vector<Point3> pts = fitted_points(p);
  if (margin) {  // the call is covered: within 1.01 G of the box on every axis
    const double g = pts[1][0] - pts[0][0];
    for (const Point3& q : p)
      for (int j = 0; j < 3; ++j)
        if (pts[0][j] - q[j] > 1.01 * g || q[j] - pts[1][j] > 1.01 * g)
          return str("test construction: point outside the cover, e = ", e);
  }
  AdaptiveKernel ak;
  ak.fit_static_filter(pts);
  const double bs = static_bound_doc(pts);
  const DetBound f = o3_filter_doc(p[0], p[1], p[2], p[3]);
  const Staged s = ak.orient3d_staged(p[0], p[1], p[2], p[3]);
  const Sign exact = mk.orient3d(p[0], p[1], p[2], p[3]);
  hits.note(f.det, bs);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 3) +
                            str(" det ", f.det, " static bound ", bs, " stage ", stage_name(s.stage));
  if (ak.orient3d_static_bound() != bs) return "static bound differs from error_bounds.md 3.5 at " + where;
  if (s.sign != exact) return "fitted orient3d sign differs from mp at " + where;
  const bool answers = f.det > bs || -f.det > bs;
  if ((s.stage == adaptive::stage_static) != answers)
    return "static filter answered against its documented bound at " + where;
  return "";
}

}  // namespace

TEST_CASE("static filter: exact at one ulp around its bound, at the edge of its cover",
          "[adaptive][edges][static]") {
  EdgeHits own, margin;
  for (int e = -1074; e <= 1023; e += (e > -380 && e < 360) ? 7 : 1)
    for (int offset : {-3, -1, 0, 1, 3})
      for (bool neg : {false, true}) {
        EDGE_CHECK_CATCH(check_static(e, offset, neg, (e & 1) != 0, (e & 7) % 6, false, own));
        if (e > -318 && e < 336)  // else the floor 2^-320 or an infinite bound puts t outside
          EDGE_CHECK_CATCH(check_static(e, offset, neg, (e & 2) != 0, (e & 7) % 6, true, margin));
      }
  INFO("fitted to the call: one ulp below / at / above B_s " << show(own));
  INFO("call at 1.01 G from the box: " << show(margin));
  CHECK(own.all());
  CHECK(margin.all());
  rc::prop("random binade, sign, axis order, cover", [] {
    EdgeHits h;
    const int e = *rc::gen::inRange(-1074, 1024);
    EDGE_CHECK_RC(check_static(e, *rc::gen::inRange(-3, 4), *rc::gen::arbitrary<bool>(),
                               *rc::gen::arbitrary<bool>(), *rc::gen::inRange(0, 6),
                               e > -318 && e < 336 && *rc::gen::arbitrary<bool>(), h));
  });
}

// ======================================================================================
// incircle lift filter (3.3): a = (r, r), b = (-r, r), c = (xi, 0), d = 0. The two
// first terms cancel exactly (alift = blift, bc = -ca), det = fl(clift * ab) =
// 2 fl(fl(xi^2) fl(r^2)); xi tunes det, the mantissa of r tunes the bound S'^2.
namespace {

std::array<Point2, 4> ic_points(double r, double xi, bool swap_ab, bool flip_axes) {
  std::array<Point2, 4> p = {{{r, r}, {-r, r}, {xi, 0}, {0, 0}}};
  if (swap_ab) std::swap(p[0], p[1]);
  if (flip_axes)
    for (Point2& q : p) q = {q[1], q[0]};
  return p;
}

std::string check_ic(double r, int offset, bool swap_ab, bool flip_axes, EdgeHits& hits) {
  auto key = [&](double xi) {
    const auto p = ic_points(r, xi, false, false);
    const DetBound f = ic_filter_doc(p[0], p[1], p[2], p[3]);
    if (!std::isfinite(f.det) || !(f.bound < inf)) return std::int64_t{1} << 40;
    return ord(std::fabs(f.det)) - ord(f.bound) - offset;
  };
  const double xi = first_at_least(std::numeric_limits<double>::denorm_min(),
                                   2 * std::fabs(r), key);  // det / bound grows up to xi = 2r
  const auto p = ic_points(r, xi, swap_ab, flip_axes);
  const DetBound f = ic_filter_doc(p[0], p[1], p[2], p[3]);
  const AdaptiveKernel ak;
  const Staged s = ak.incircle_staged(p[0], p[1], p[2], p[3]);
  const Sign exact = mk.incircle(p[0], p[1], p[2], p[3]);
  hits.note(f.det, f.bound);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 2) +
                            str(" det ", f.det, " bound ", f.bound, " stage ", stage_name(s.stage));
  if (s.sign != exact) return "incircle sign differs from mp at " + where;
  const bool answers = f.det > f.bound || -f.det > f.bound;
  if ((s.stage == adaptive::stage_filter) != answers)
    return "incircle lift filter answered against its documented bound at " + where;
  if (f.overflow && s.stage == adaptive::stage_filter)
    return "incircle lift filter answered on an overflowed determinant at " + where;
  // The kernel's bound (SSE2 where built) and its scalar twin are the documented one, bit for bit.
  for (const double kb : {adaptive::incircle_filter(p[0], p[1], p[2], p[3]).bound,
                          adaptive::incircle_filter_scalar(p[0], p[1], p[2], p[3]).bound})
    if (!(kb == f.bound || (std::isnan(kb) && std::isnan(f.bound))))
      return "incircle filter bound (SSE2 or scalar) differs from error_bounds.md 3.3 at " + where;
  return "";
}

}  // namespace

TEST_CASE("incircle lift filter: exact at one ulp around its bound, in every binade",
          "[adaptive][edges]") {
  EdgeHits hits, floored;
  // r from 2^-537 (every product subnormal) to 2^511 (S overflows); mantissas spread
  // the bound over the ulps of det. Below r ~ 2^-241, S < 2^-480: the floor decides.
  for (int e = -537; e <= 511; ++e)
    for (int offset : {-1, 0, 1})
      for (int i = 0; i < ((e < -242 && e > -252) ? 24 : 3); ++i) {
        const double r = std::ldexp(1 + i / 24.0 + 0x1p-30 * i, e);
        EdgeHits& h = (e < -242 && e > -260) ? floored : hits;
        EDGE_CHECK_CATCH(check_ic(r, offset, (e & 1) != 0, (e & 2) != 0, h));
      }
  INFO("one ulp below / at / above the bound: " << show(hits) << "; with S below the floor: "
                                                << show(floored));
  CHECK(hits.all());
  CHECK(floored.all());
  rc::prop("random binade, mantissa, offset, sign", [] {
    EdgeHits h;
    const double r = std::ldexp(1 + *rc::gen::inRange(0, 1 << 30) * 0x1p-30, *rc::gen::inRange(-540, 512));
    EDGE_CHECK_RC(check_ic(r, *rc::gen::inRange(-4, 5), *rc::gen::arbitrary<bool>(),
                           *rc::gen::arbitrary<bool>(), h));
  });
}

// ======================================================================================
// insphere lift filter (3.2): a = (r, 0, h), b = (-r, 0, h), c = (0, r, h), d = (xi, 0, 0),
// e = 0. The lifts of a, b, c are equal and cda = bcd, dab = 0, so det = fl(dlift abc)
// = -2 fl(fl(xi^2) fl(h fl(r^2))); xi tunes det, r and h tune L'^2 mz'.
namespace {

std::array<Point3, 5> is_points(double r, double h, double xi, bool flip) {
  std::array<Point3, 5> p = {{{r, 0, h}, {-r, 0, h}, {0, r, h}, {xi, 0, 0}, {0, 0, 0}}};
  if (flip) std::swap(p[0], p[1]);
  return p;
}

// offset 99: xi = r / 2, no tuning (for bounds that are +inf).
std::string check_is(double r, double h, int offset, bool flip, EdgeHits& hits) {
  auto key = [&](double xi) {
    const auto p = is_points(r, h, xi, false);
    const DetBound f = is_filter_doc(p[0], p[1], p[2], p[3], p[4]);
    if (!std::isfinite(f.det) || !(f.bound < inf)) return std::int64_t{1} << 40;
    return ord(std::fabs(f.det)) - ord(f.bound) - offset;
  };
  // det / bound grows while dlift is not the largest lift (then L' grows with xi^2).
  const double xi = offset == 99 ? r / 2
                                 : first_at_least(std::numeric_limits<double>::denorm_min(),
                                                  std::max({std::fabs(r), std::fabs(h), adaptive::is_lo}), key);
  const auto p = is_points(r, h, xi, flip);
  const DetBound f = is_filter_doc(p[0], p[1], p[2], p[3], p[4]);
  const AdaptiveKernel ak;
  const Staged s = ak.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
  const Sign exact = mk.insphere(p[0], p[1], p[2], p[3], p[4]);
  hits.note(f.det, f.bound);
  const std::string where =
      str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()}, 3) +
      str(" det ", f.det, " bound ", f.bound, " stage ", stage_name(s.stage));
  if (s.sign != exact) return "insphere sign differs from mp at " + where;
  const bool answers = f.det > f.bound || -f.det > f.bound;
  if ((s.stage == adaptive::stage_filter) != answers)
    return "insphere lift filter answered against its documented bound at " + where;
  if (f.overflow && s.stage == adaptive::stage_filter)
    return "insphere lift filter answered on an overflowed determinant at " + where;
  for (const double kb : {adaptive::insphere_filter(p[0], p[1], p[2], p[3], p[4]).bound,
                          adaptive::insphere_filter_scalar(p[0], p[1], p[2], p[3], p[4]).bound})
    if (!(kb == f.bound || (std::isnan(kb) && std::isnan(f.bound))))
      return "insphere filter bound (SSE2 or scalar) differs from error_bounds.md 3.2 at " + where;
  return "";
}

}  // namespace

TEST_CASE("insphere lift filter: exact at one ulp around its bound, in every binade",
          "[adaptive][edges]") {
  EdgeHits hits, floor_mz, floor_both;
  // r = h from 2^-430 to 2^300; then h alone below the floor 2^-185 (mz' = is_lo), and
  // both below (L' = is_lo^2 too).
  for (int e = -430; e <= 300; ++e)
    for (int offset : {-1, 0, 1})
      for (double m : {1.0, 1.3, 1.9})
        EDGE_CHECK_CATCH(check_is(std::ldexp(m, e), std::ldexp(m, e), offset, (e & 1) != 0, hits));
  for (int e = -260; e <= -170; ++e)
    for (int offset : {-1, 0, 1})
      for (double m : {1.0, 1.3, 1.9}) {
        EDGE_CHECK_CATCH(check_is(std::ldexp(m, -150), std::ldexp(m, e), offset, (e & 1) != 0,
                                  floor_mz));
        EDGE_CHECK_CATCH(check_is(std::ldexp(m, e - 2), std::ldexp(m, e), offset, (e & 1) != 0,
                                  floor_both));
      }
  // The overflow factor (3.2): L'^2 between 2^1016 and 2^1019, mz' small, det finite and
  // large. (128 L') L' overflows from L'^2 = 2^1017 on and the filter must not answer.
  for (int i = 0; i < 40; ++i)
    for (double h : {0x1p-190, 0x1p-60, 1.0, 8.0})
      EDGE_CHECK_CATCH(check_is(std::ldexp(1 + i / 40.0, 253), h, 99, (i & 1) != 0, hits));
  INFO("one ulp below / at / above: " << show(hits) << "; mz below its floor: " << show(floor_mz)
                                      << "; L and mz below theirs: " << show(floor_both));
  CHECK(hits.all());
  CHECK(floor_mz.all());
  CHECK(floor_both.all());
  rc::prop("random binades of r and h, mantissas, offset, sign", [] {
    EdgeHits hh;
    const double r = std::ldexp(1 + *rc::gen::inRange(0, 1 << 30) * 0x1p-30, *rc::gen::inRange(-440, 300));
    const double h = std::ldexp(1 + *rc::gen::inRange(0, 1 << 30) * 0x1p-30,
                                std::ilogb(r) + *rc::gen::inRange(-12, 13));
    EDGE_CHECK_RC(check_is(r, *rc::gen::arbitrary<bool>() ? h : -h, *rc::gen::inRange(-4, 5),
                           *rc::gen::arbitrary<bool>(), hh));
  });
}

// ======================================================================================
// orient2d inline stage A (4.6): a = (M, y), b = (1, 1) 2^s, c = 0: dl = M, dr = y, det =
// M - y exact (k ulps of M), P^ = M + y; the mantissa of M moves the bound across det.
// Subnormal products (s near -537): the additive 2^-1072 decides.
namespace {

// offset 9: M's mantissa near 2 (det about half the bound when k = 3).
std::string check_o2(int k, int s, int offset, bool swap_ab, EdgeHits& hits) {
  auto points = [&](double m) {
    const double y = m - k * std::ldexp(1.0, std::ilogb(m) - 52);
    std::array<Point2, 3> p = {{{std::ldexp(m, s), std::ldexp(y, s)},
                                {std::ldexp(1.0, s), std::ldexp(1.0, s)},
                                {0, 0}}};
    if (swap_ab) std::swap(p[0], p[1]);
    return p;
  };
  auto key = [&](double m) {
    const auto p = points(m);
    const DetBound f = o2_inline_doc(p[0], p[1], p[2]);
    // det is fixed by the binade of M; the bound grows with M: ord(bound) - ord(|det|).
    return ord(f.bound) - ord(std::fabs(f.det)) + offset;
  };
  const double m = offset == 9 ? 1.99 : first_at_least(1.0, std::nextafter(2.0, 0.0), key);
  const auto p = points(m);
  const DetBound f = o2_inline_doc(p[0], p[1], p[2]);
  const AdaptiveKernel ak;
  const Staged st = ak.orient2d_staged(p[0], p[1], p[2]);
  const Sign exact = mk.orient2d(p[0], p[1], p[2]);
  hits.note(f.det, f.bound);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data()}, 2) +
                            str(" det ", f.det, " bound ", f.bound, " stage ", stage_name(st.stage));
  if (st.sign != exact) return "orient2d sign differs from mp at " + where;
  const bool answers = f.det > f.bound || -f.det > f.bound;
  // Inline stage A answers, or the slow path runs: its stage A (bound o2A P^, slightly
  // smaller), B, ..., or mp when the guard of section 2 fails.
  if (answers && st.stage != adaptive::stage_a)
    return "orient2d inline stage A did not answer above its bound at " + where;
  if (!answers && st.stage == adaptive::stage_a) {
    // Only the out-of-line stage A may answer here: above o2A P^, guard passed.
    const double dl = (p[0][0] - p[2][0]) * (p[1][1] - p[2][1]);
    const double dr = (p[0][1] - p[2][1]) * (p[1][0] - p[2][0]);
    const bool opposite = (dl > 0 && dr <= 0) || (dl < 0 && dr >= 0) || dl == 0;
    const double slow = adaptive::o2A * std::fabs(dl + dr);
    const bool slow_answers = opposite || f.det > slow || -f.det > slow;
    if (!slow_answers || !guard_passes<3, 2>(p, 2, ::o2_hi))
      return "orient2d stage A answered at or below its documented bound at " + where;
  }
  return "";
}

}  // namespace

TEST_CASE("orient2d inline stage A: exact at one ulp around its bound, in every binade",
          "[adaptive][edges]") {
  EdgeHits hits, tiny;
  // Points scaled by 2^s: products 2^(2s). Below s ~ -510 the products are subnormal and
  // the additive 2^-1072 is the bound (det a few multiples of 2^-1074).
  for (int s = -560; s <= 511; ++s)
    for (int k : {3, 4, 5, 6})
      for (int offset : {-1, 0, 1, 9})
        for (bool swap_ab : {false, true})
          EDGE_CHECK_CATCH(check_o2(k, s, offset, swap_ab, 2 * s < -1000 ? tiny : hits));
  INFO("one ulp below / at / above the bound: " << show(hits) << "; subnormal products: "
                                                << show(tiny));
  CHECK(hits.all());
  CHECK(tiny.n[1] + tiny.n[2] > 0);
  rc::prop("random binade, k, offset, sign", [] {
    EdgeHits h;
    EDGE_CHECK_RC(check_o2(*rc::gen::inRange(1, 12), *rc::gen::inRange(-560, 512),
                           *rc::gen::inRange(-3, 4), *rc::gen::arbitrary<bool>(), h));
  });
}

// ======================================================================================
// Stage A of orient3d (4.2) at one ulp around o3A P^: a = (alpha, 0, 1), b = (1, y1, 0),
// c = (1, y2, w), d = 0 (scaled by 2^s): det = fl((y2 - y1) + w fl(alpha y1)) with
// y2 - y1 exact (j ulps of y1, below the bound) and the second term tuning det
// finely; P^ ~ y1 + y2.
// The filter's bound (~40 eps y) is above det (~14 eps y), so the out-of-line stage A
// decides; when it declines, stage B answers (no tails: every difference is exact).
namespace {

std::string check_o3_stage_a(double y1, int j, int s, int offset, bool flip, EdgeHits& hits) {
  const double y2 = y1 + j * std::ldexp(1.0, std::ilogb(y1) - 52), alpha = 0.75;
  auto points = [&](double w) {
    std::array<Point3, 4> p = {{{alpha, 0, 1}, {1, y1, 0}, {1, y2, w}, {0, 0, 0}}};
    for (Point3& q : p)
      for (double& x : q) x = std::ldexp(x, s);
    if (flip) std::swap(p[1], p[2]);
    return p;
  };
  auto key = [&](double w) {
    const auto p = points(w);
    const DetPerm a = o3_stage_a_doc(p[0], p[1], p[2], p[3]);
    return ord(std::fabs(a.det)) - ord(a.bound) - offset;
  };
  // w from 0 up to 2^-40: det sweeps from j ulps of y1 upwards.
  const double w = first_at_least(0x1p-300, 0x1p-40, key);
  const auto p = points(w);
  const DetPerm a = o3_stage_a_doc(p[0], p[1], p[2], p[3]);
  const DetBound f = o3_filter_doc(p[0], p[1], p[2], p[3]);
  const AdaptiveKernel ak;
  const Staged st = ak.orient3d_staged(p[0], p[1], p[2], p[3]);
  const Sign exact = mk.orient3d(p[0], p[1], p[2], p[3]);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 3) +
                            str(" det_A ", a.det, " bound_A ", a.bound, " stage ", stage_name(st.stage));
  if (st.sign != exact) return "orient3d sign differs from mp at " + where;
  const bool filter = f.det > f.bound || -f.det > f.bound;
  if (filter) return st.stage == adaptive::stage_filter ? "" : "filter did not answer at " + where;
  if (!guard_passes<4, 3>(p, 3, ::o3_hi))
    return st.stage == adaptive::stage_mp ? "" : "guard did not send to mp at " + where;
  hits.note(a.det, a.bound);
  const bool answers = a.det > a.bound || -a.det > a.bound;
  if ((st.stage == adaptive::stage_a) != answers)
    return "orient3d stage A answered against its documented bound at " + where;
  if (!answers && st.stage != adaptive::stage_b) return "stage B did not answer at " + where;
  return "";
}

}  // namespace

TEST_CASE("orient3d stage A: exact at one ulp around its bound, in every binade",
          "[adaptive][edges]") {
  EdgeHits hits;
  for (int s = -330; s <= 330; s += 2)
    for (int j : {3, 4, 5, 6})
      for (int offset : {-1, 0, 1})
        EDGE_CHECK_CATCH(check_o3_stage_a(1 + ((s + 331) % 97) / 97.0, j, s, offset, (s & 2) != 0, hits));
  INFO("one ulp below / at / above the bound: " << show(hits));
  CHECK(hits.all());
  rc::prop("random binade, y, offset, orientation", [] {
    EdgeHits h;
    EDGE_CHECK_RC(check_o3_stage_a(1 + *rc::gen::inRange(0, 1 << 30) * 0x1p-30,
                                   *rc::gen::inRange(1, 7), *rc::gen::inRange(-340, 340),
                                   *rc::gen::inRange(-3, 4), *rc::gen::arbitrary<bool>(), h));
  });
}

// ======================================================================================
// Stages B and C of orient3d (4.3, 4.4). B = the exact determinant of the rounded
// differences (computed here in rationals); stage B answers when its estimate clears
// o3B P^, stage C when B + K^ clears o3C P^ + result_err |B|. The estimate and K^ are
// not replicated bit for bit, so the edge is tested to a relative 2^-40: inputs with
// |B| at 0.6, 0.9, 0.999, 1.001 and 1.1 times the bound.
//  B: the stage-A family with d = (delta, 0, 0) 2^s: every x difference rounds (tail
//     -delta), B = (y2 - y1) + w alpha y1 exactly, tuned by w.
//  C: a = (1, 0, 0), b = (0, 1, 0), c = (0, 0, 1), d = (delta, 1/2, 1/2) (2^s): the
//     rounded differences lose a's tail only, whose first-order term vanishes (its minor
//     is 0), so B = D ~ delta; A and B decline, delta tunes |B| around the C bound.
namespace {

double q_to_double(const Q& q) { return static_cast<double>(q); }

std::string check_o3_stage_bc(bool for_c, double rho, int s, double y1, bool flip,
                              std::array<int, 2>& below_reached) {
  using namespace adaptive;
  const double alpha = 0.75, y2 = y1 + std::ldexp(1.0, std::ilogb(y1) - 52);
  auto points = [&](double v) {  // v: w (stage B) or delta (stage C)
    std::array<Point3, 4> p;
    if (for_c)
      p = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {v, 0.5, 0.5}}};
    else
      p = {{{alpha, 0, 1}, {1, y1, 0}, {1, y2, v}, {0x1p-70, 0, 0}}};
    for (Point3& q : p)
      for (double& x : q) x = std::ldexp(x, s);
    if (flip) std::swap(p[1], p[2]);
    return p;
  };
  auto exact_b = [](const std::array<Point3, 4>& p) {  // det of the rounded differences
    std::array<Point3, 3> r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r[i][j] = p[i][j] - p[3][j];
    return det::orient3d<Q>(r[0], r[1], r[2], Point3{0, 0, 0});
  };
  auto bound_of = [&](const std::array<Point3, 4>& p, double b) {
    // P^ in the documented order (4.2).
    const double adx = p[0][0] - p[3][0], ady = p[0][1] - p[3][1], adz = p[0][2] - p[3][2];
    const double bdx = p[1][0] - p[3][0], bdy = p[1][1] - p[3][1], bdz = p[1][2] - p[3][2];
    const double cdx = p[2][0] - p[3][0], cdy = p[2][1] - p[3][1], cdz = p[2][2] - p[3][2];
    const double P = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * std::fabs(adz) +
                     (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * std::fabs(bdz) +
                     (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * std::fabs(cdz);
    return for_c ? o3C * P + result_err * std::fabs(b) : o3B * P;
  };
  auto key = [&](double v) {
    const auto p = points(v);
    const double b = q_to_double(abs(exact_b(p)));
    return ord(b) - ord(rho * bound_of(p, b));
  };
  const double v = for_c ? first_at_least(0x1p-200, 0x1p-60, key)
                           : first_at_least(0x1p-300, 0x1p-40, key);
  const auto p = points(v);
  const Q B = exact_b(p);
  const double b = q_to_double(abs(B)), bound = bound_of(p, b);
  const Staged st = AdaptiveKernel{}.orient3d_staged(p[0], p[1], p[2], p[3]);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 3) +
                            str(" |B| / bound ", b / bound, " stage ", stage_name(st.stage));
  if (st.sign != mk.orient3d(p[0], p[1], p[2], p[3])) return "orient3d sign differs from mp at " + where;
  if (!guard_passes<4, 3>(p, 3, ::o3_hi)) return "";
  const unsigned char x = for_c ? stage_c : stage_b;
  if (st.stage < x) return "";  // an earlier stage answered (checked by the tests above)
  if (b > 0.5 * bound && b < 0.999 * bound) ++below_reached[for_c ? 1 : 0];
  if (st.stage == x && !(b > bound * (1 - 0x1p-40)))
    return str("orient3d stage ", stage_name(x), " answered below its documented bound at ", where);
  if (st.stage != x && b > bound * (1 + 0x1p-40))
    return str("orient3d stage ", stage_name(x), " did not answer above its documented bound at ", where);
  return "";
}

}  // namespace

TEST_CASE("orient3d stages B and C: exact around their bounds, in every binade",
          "[adaptive][edges]") {
  std::array<int, 2> below{};  // inputs at 0.5-0.999 of the B (C) bound that reached it
  for (int s = -150; s <= 300; s += 5)
    for (double rho : {0.6, 0.9, 0.999, 1.001, 1.1})
      for (bool c : {false, true})
        EDGE_CHECK_CATCH(check_o3_stage_bc(c, rho, s, 1 + ((s + 151) % 89) / 89.0, (s & 1) != 0, below));
  INFO("inputs between half the bound and the bound that reached stage B: " << below[0]
                                                                           << ", stage C: " << below[1]);
  CHECK(below[0] > 0);
  CHECK(below[1] > 0);
}

// ======================================================================================
// Stages A and B of incircle and insphere (4.2, 4.3), on the lift-filter families above:
// incircle a = (r, r), b = (-r, r), c = (xi, 0), d = (delta, 0); insphere a = (r, 0, h),
// b = (-r, 0, h), c = (0, r, h), d = (xi, 0, 0), e = (delta, 0, 0). With delta = 0 every
// difference is exact: det_A ~ 2 xi^2 R against P^ ~ 4 R r xi (incircle), so xi tunes
// det_A / (cA P^) to one ulp around 1 and stage B answers when A declines (no tails).
// With delta = 2^-80 r every x difference rounds away delta: B (exact, in rationals)
// is tuned to rho times cB P^, and stage C answers when B declines.
namespace {

// Stage A of incircle and insphere in the documented order (4.2): det and P^.
DetPerm ic_stage_a_doc(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a[0] - d[0], ady = a[1] - d[1], bdx = b[0] - d[0], bdy = b[1] - d[1],
               cdx = c[0] - d[0], cdy = c[1] - d[1];
  const double bdxcdy = bdx * cdy, bdycdx = bdy * cdx, cdxady = cdx * ady, cdyadx = cdy * adx,
               adxbdy = adx * bdy, adybdx = ady * bdx;
  const double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
  const double det = (al * (bdxcdy - bdycdx) + bl * (cdxady - cdyadx)) + cl * (adxbdy - adybdx);
  const double perm = (std::fabs(bdxcdy) + std::fabs(bdycdx)) * al +
                      (std::fabs(cdxady) + std::fabs(cdyadx)) * bl +
                      (std::fabs(adxbdy) + std::fabs(adybdx)) * cl;
  return {det, perm};
}
DetPerm is_stage_a_doc(const std::array<Point3, 5>& p) {
  double x[4], y[4], z[4];
  for (int i = 0; i < 4; ++i)
    x[i] = p[i][0] - p[4][0], y[i] = p[i][1] - p[4][1], z[i] = p[i][2] - p[4][2];
  auto pr = [&](int i, int j) { return x[i] * y[j]; };  // the twelve products
  const double ab = pr(0, 1) - pr(1, 0), bc = pr(1, 2) - pr(2, 1), cd = pr(2, 3) - pr(3, 2),
               da = pr(3, 0) - pr(0, 3), ac = pr(0, 2) - pr(2, 0), bd = pr(1, 3) - pr(3, 1);
  const double abc = (z[0] * bc - z[1] * ac) + z[2] * ab, bcd = (z[1] * cd - z[2] * bd) + z[3] * bc,
               cda = (z[2] * da + z[3] * ac) + z[0] * cd, dab = (z[3] * ab + z[0] * bd) + z[1] * da;
  double l[4];
  for (int i = 0; i < 4; ++i) l[i] = (x[i] * x[i] + y[i] * y[i]) + z[i] * z[i];
  const double det = (l[3] * abc - l[2] * dab) + (l[1] * cda - l[0] * bcd);
  auto pp = [&](int i, int j) { return std::fabs(pr(i, j)) + std::fabs(pr(j, i)); };
  const double pab = pp(0, 1), pbc = pp(1, 2), pcd = pp(2, 3), pda = pp(3, 0), pac = pp(0, 2),
               pbd = pp(1, 3);
  const double az = std::fabs(z[0]), bz = std::fabs(z[1]), cz = std::fabs(z[2]), dz = std::fabs(z[3]);
  const double pabc = (az * pbc + bz * pac) + cz * pab, pbcd = (bz * pcd + cz * pbd) + dz * pbc,
               pcda = (cz * pda + dz * pac) + az * pcd, pdab = (dz * pab + az * pbd) + bz * pda;
  const double perm = (l[3] * pabc + l[2] * pdab) + (l[1] * pcda + l[0] * pbcd);
  return {det, perm};
}

// One input of a family: stage X in {A, B} and the documented values.
struct StageCall {
  Staged st;
  Sign exact;
  bool guard, earlier;  // guard of section 2 passed; the inline filter answered
  double det_a, perm;   // stage A's det and P^ (documented order)
  Q b;                  // exact determinant of the rounded differences
  std::string where;
};

StageCall ic_call(double r, double xi, double delta, bool flip) {
  std::array<Point2, 4> p = {{{r, r}, {-r, r}, {xi, 0}, {delta, 0}}};
  if (flip) std::swap(p[0], p[1]);
  const DetBound f = ic_filter_doc(p[0], p[1], p[2], p[3]);
  const DetPerm a = ic_stage_a_doc(p[0], p[1], p[2], p[3]);
  std::array<Point2, 3> q;
  for (int i = 0; i < 3; ++i) q[i] = {p[i][0] - p[3][0], p[i][1] - p[3][1]};
  return {AdaptiveKernel{}.incircle_staged(p[0], p[1], p[2], p[3]), mk.incircle(p[0], p[1], p[2], p[3]),
          guard_passes<4, 2>(p, 4, ::ic_hi), f.det > f.bound || -f.det > f.bound, a.det, a.bound,
          det::incircle<Q>(q[0], q[1], q[2], Point2{0, 0}),
          str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 2)};
}
StageCall is_call(double r, double xi, double delta, bool flip) {
  std::array<Point3, 5> p = {{{r, 0, r}, {-r, 0, r}, {0, r, r}, {xi, 0, 0}, {delta, 0, 0}}};
  if (flip) std::swap(p[0], p[1]);
  const DetBound f = is_filter_doc(p[0], p[1], p[2], p[3], p[4]);
  const DetPerm a = is_stage_a_doc(p);
  std::array<Point3, 4> q;
  for (int i = 0; i < 4; ++i) q[i] = {p[i][0] - p[4][0], p[i][1] - p[4][1], p[i][2] - p[4][2]};
  return {AdaptiveKernel{}.insphere_staged(p[0], p[1], p[2], p[3], p[4]),
          mk.insphere(p[0], p[1], p[2], p[3], p[4]), guard_passes<5, 3>(p, 5, ::is_hi),
          f.det > f.bound || -f.det > f.bound, a.det, a.bound,
          det::insphere<Q>(q[0], q[1], q[2], q[3], Point3{0, 0, 0}),
          str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()}, 3)};
}

// Stage A (delta = 0): det_A one ulp around cA P^; stage B (delta != 0): |B| at rho cB P^.
std::string check_lift_stage(bool insphere, bool stage_b_edge, double r, double target, bool flip,
                             EdgeHits& hits, int& below_reached) {
  using namespace adaptive;
  const double cA = insphere ? isA : icA, cB = insphere ? isB : icB;
  const double delta = stage_b_edge ? std::ldexp(r, -80) : 0;
  auto call = [&](double xi) { return insphere ? is_call(r, xi, delta, flip) : ic_call(r, xi, delta, flip); };
  auto key = [&](double xi) {
    const StageCall c = call(xi);
    if (stage_b_edge) {
      const double b = std::fabs(static_cast<double>(c.b));
      return ord(b) - ord(target * (cB * c.perm));
    }
    return ord(std::fabs(c.det_a)) - ord(cA * c.perm) - static_cast<std::int64_t>(target);
  };
  const double xi = first_at_least(std::ldexp(r, -60), std::ldexp(r, -30), key);
  const StageCall c = call(xi);
  const std::string where = c.where + str(" stage ", stage_name(c.st.stage));
  if (c.st.sign != c.exact) return "sign differs from mp at " + where;
  if (c.earlier || !c.guard) return "";  // the filter answered (or mp): not this edge
  const double ba = cA * c.perm;
  const bool a_answers = c.det_a > ba || -c.det_a > ba;
  if (!stage_b_edge) {
    hits.note(c.det_a, ba);
    if ((c.st.stage == stage_a) != a_answers)
      return "stage A answered against its documented bound at " + where;
    return "";
  }
  if (a_answers) return c.st.stage == stage_a ? "" : "stage A did not answer at " + where;
  const double b = std::fabs(static_cast<double>(c.b)), bb = cB * c.perm;
  if (b > 0.5 * bb && b < 0.999 * bb) ++below_reached;
  if (c.st.stage == stage_b && !(b > bb * (1 - 0x1p-40)))
    return "stage B answered below its documented bound at " + where;
  if (c.st.stage != stage_b && b > bb * (1 + 0x1p-40))
    return "stage B did not answer above its documented bound at " + where;
  return "";
}

}  // namespace

TEST_CASE("incircle and insphere stages A and B: exact around their bounds",
          "[adaptive][edges]") {
  for (bool insphere : {false, true}) {
    EdgeHits hits;
    int below = 0;
    // Under ASan every fifth of these binades (tests/sanitized_build.hpp).
    for (int e = -170; e <= 190; e += test::kSanitizedBuild ? 15 : 3)
      for (int i = 0; i < 3; ++i) {
        const double r = std::ldexp(1 + i / 3.0 + 0x1p-40 * e, e);
        for (int offset : {-1, 0, 1})
          EDGE_CHECK_CATCH(check_lift_stage(insphere, false, r, offset, (e & 1) != 0, hits, below));
        for (double rho : {0.6, 0.9, 0.999, 1.001, 1.1})
          EDGE_CHECK_CATCH(check_lift_stage(insphere, true, r, rho, (e & 2) != 0, hits, below));
      }
    INFO((insphere ? "insphere" : "incircle") << ": stage A one ulp below / at / above " << show(hits)
                                              << "; stage B reached at 0.5-0.999 of its bound " << below);
    CHECK(hits.all());
    CHECK(below > 0);
  }
}

// ======================================================================================
// Stage C of orient2d, incircle and insphere, and stage B of orient2d (4.3, 4.4). For C:
// integer points whose rounded differences to the last point are exactly degenerate
// (B = 0) while the last point, moved by delta along x, is not: every x difference
// rounds delta away, and D = K + O(delta^2) is the first-order term stage C computes.
// So det_C = D to a relative 2^-50, and the bound is cC P^ (no result_err: det_B = 0).
// orient2d B: a = (M, y), b = (1, 1), c = (delta, 0) with y = M - k ulps: B = M - y,
// bound o2B (M + y), tuned by the mantissa of M; stage C answers when B declines.
namespace {

std::string check_stage_c(int pred, double rho, int s, bool flip, int& below_reached) {
  using namespace adaptive;
  auto sc = [&](double x) { return std::ldexp(x, s); };
  struct Out {
    Q D;
    double perm;
    Staged st;
    Sign exact;
    bool guard;
    std::string where;
  };
  auto run_at = [&](double delta) {
    Out o;
    if (pred == 2) {  // orient2d: a, b, c collinear with the origin after rounding
      std::array<Point2, 3> p = {{{sc(1), sc(1)}, {sc(2), sc(2)}, {sc(delta), 0}}};
      if (flip) std::swap(p[0], p[1]);
      o.D = det::orient2d<Q>(p[0], p[1], p[2]);
      const double acx = p[0][0] - p[2][0], acy = p[0][1] - p[2][1], bcx = p[1][0] - p[2][0],
                   bcy = p[1][1] - p[2][1];
      o.perm = std::fabs(acx * bcy) + std::fabs(acy * bcx);
      o.st = AdaptiveKernel{}.orient2d_staged(p[0], p[1], p[2]);
      o.exact = mk.orient2d(p[0], p[1], p[2]);
      o.guard = guard_passes<3, 2>(p, 2, ::o2_hi);
      o.where = str_points({p[0].data(), p[1].data(), p[2].data()}, 2);
    } else if (pred == 4) {  // incircle: (2, 0), (3, 3), (-1, 1) and 0 on one circle
      std::array<Point2, 4> p = {{{sc(2), 0}, {sc(3), sc(3)}, {sc(-1), sc(1)}, {sc(delta), 0}}};
      if (flip) std::swap(p[0], p[1]);
      o.D = det::incircle<Q>(p[0], p[1], p[2], p[3]);
      o.perm = ic_stage_a_doc(p[0], p[1], p[2], p[3]).bound;
      o.st = AdaptiveKernel{}.incircle_staged(p[0], p[1], p[2], p[3]);
      o.exact = mk.incircle(p[0], p[1], p[2], p[3]);
      o.guard = guard_passes<4, 2>(p, 4, ::ic_hi);
      o.where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 2);
    } else {  // insphere: on the sphere of centre (1, 2, 2) through 0
      std::array<Point3, 5> p = {{{sc(2), sc(4), 0},
                                  {sc(3), 0, sc(1)},
                                  {sc(-1), 0, sc(1)},
                                  {sc(2), 0, sc(4)},
                                  {sc(delta), 0, 0}}};
      if (flip) std::swap(p[0], p[1]);
      o.D = det::insphere<Q>(p[0], p[1], p[2], p[3], p[4]);
      o.perm = is_stage_a_doc(p).bound;
      o.st = AdaptiveKernel{}.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
      o.exact = mk.insphere(p[0], p[1], p[2], p[3], p[4]);
      o.guard = guard_passes<5, 3>(p, 5, ::is_hi);
      o.where = str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()}, 3);
    }
    return o;
  };
  const double cC = pred == 2 ? o2C : pred == 4 ? icC : isC;
  auto key = [&](double delta) {
    const Out o = run_at(delta);
    return ord(std::fabs(static_cast<double>(o.D))) - ord(rho * (cC * o.perm));
  };
  const Out o = run_at(first_at_least(0x1p-200, 0x1p-56, key));
  const std::string where = o.where + str(" stage ", stage_name(o.st.stage));
  if (o.st.sign != o.exact) return "sign differs from mp at " + where;
  if (!o.guard || o.st.stage < stage_c) return "";  // mp, or an earlier stage answered
  const double d = std::fabs(static_cast<double>(o.D)), bound = cC * o.perm;
  if (d > 0.5 * bound && d < 0.999 * bound) ++below_reached;
  if (o.st.stage == stage_c && !(d > bound * (1 - 0x1p-40)))
    return "stage C answered below its documented bound at " + where;
  if (o.st.stage != stage_c && d > bound * (1 + 0x1p-40))
    return "stage C did not answer above its documented bound at " + where;
  return "";
}

std::string check_o2_stage_b(int k, double rho, int s, bool flip, int& below_reached) {
  using namespace adaptive;
  auto points = [&](double m) {
    const double y = m - k * std::ldexp(1.0, std::ilogb(m) - 52);
    std::array<Point2, 3> p = {{{std::ldexp(m, s), std::ldexp(y, s)},
                                {std::ldexp(1.0, s), std::ldexp(1.0, s)},
                                {std::ldexp(0x1p-80, s), 0}}};
    if (flip) std::swap(p[0], p[1]);
    return p;
  };
  auto parts = [&](const std::array<Point2, 3>& p) {  // |B| exactly, and o2B P^
    const double acx = p[0][0] - p[2][0], acy = p[0][1] - p[2][1], bcx = p[1][0] - p[2][0],
                 bcy = p[1][1] - p[2][1];
    const double b = std::fabs(static_cast<double>(Q(acx) * Q(bcy) - Q(acy) * Q(bcx)));
    return std::pair<double, double>{b, o2B * (std::fabs(acx * bcy) + std::fabs(acy * bcx))};
  };
  auto key = [&](double m) {
    const auto [b, bound] = parts(points(m));
    return ord(rho * bound) - ord(b);  // grows with m (b is fixed by the binade)
  };
  const auto p = points(first_at_least(1.0, std::nextafter(2.0, 0.0), key));
  const auto [b, bound] = parts(p);
  const Staged st = AdaptiveKernel{}.orient2d_staged(p[0], p[1], p[2]);
  const std::string where = str_points({p[0].data(), p[1].data(), p[2].data()}, 2) +
                            str(" |B| / bound ", b / bound, " stage ", stage_name(st.stage));
  if (st.sign != mk.orient2d(p[0], p[1], p[2])) return "orient2d sign differs from mp at " + where;
  if (!guard_passes<3, 2>(p, 2, ::o2_hi) || st.stage < stage_b) return "";
  if (b > 0.5 * bound && b < 0.999 * bound) ++below_reached;
  if (st.stage == stage_b && !(b > bound * (1 - 0x1p-40)))
    return "orient2d stage B answered below its documented bound at " + where;
  if (st.stage != stage_b && b > bound * (1 + 0x1p-40))
    return "orient2d stage B did not answer above its documented bound at " + where;
  return "";
}

}  // namespace

TEST_CASE("stage C of orient2d, incircle, insphere and stage B of orient2d: exact around "
          "their bounds", "[adaptive][edges]") {
  std::array<int, 3> below_c{};
  int below_b = 0;
  for (int s = -150; s <= 150; s += test::kSanitizedBuild ? 15 : 3)  // as above
    for (double rho : {0.6, 0.9, 0.999, 1.001, 1.1}) {
      for (int k = 0; k < 3; ++k)
        EDGE_CHECK_CATCH(check_stage_c(k == 0 ? 2 : k == 1 ? 4 : 5, rho, s, (s & 1) != 0, below_c[k]));
      for (int kk : {2, 3})
        EDGE_CHECK_CATCH(check_o2_stage_b(kk, rho, s, (s & 2) != 0, below_b));
    }
  INFO("reached at 0.5-0.999 of the bound: C of orient2d " << below_c[0] << ", incircle "
       << below_c[1] << ", insphere " << below_c[2] << "; B of orient2d " << below_b);
  CHECK(below_c[0] > 0);
  CHECK(below_c[1] > 0);
  CHECK(below_c[2] > 0);
  CHECK(below_b > 0);
}

// ======================================================================================
// Section 2: the guards at their thresholds and one step beyond. Each configuration is
// exactly degenerate (det = 0): the filter declines, and the exact stages answer zero
// (stage B: no tails) when the guard passes, mp when it fails.
namespace {

// Lattice points u * (small integers): a zero determinant for each predicate.
struct Zero {
  std::array<Point2, 4> p2;
  std::array<Point3, 5> p3;
};
Zero zero_config(double u, double v) {  // u: x, y spacing; v: z spacing
  Zero z;
  z.p2 = {{{u, 0}, {0, u}, {-u, 0}, {0, -u}}};                          // cocircular, collinear: none
  z.p3 = {{{u, 0, 0}, {0, u, 0}, {-u, 0, 0}, {0, 0, v}, {0, -u, 0}}};   // v = u: cospherical
  return z;
}

std::string check_guards(double u, bool flip) {
  const double s = flip ? -1.0 : 1.0;
  const AdaptiveKernel ak;
  std::string err;
  auto expect = [&](const char* what, Staged st, Sign exact, bool pass, const std::string& where) {
    if (st.sign != exact) err += str(what, ": sign differs from mp at ", where, "\n");
    if ((st.stage == adaptive::stage_mp) == pass)
      err += str(what, ": guard decided against section 2 (", stage_name(st.stage), ") at ", where, "\n");
  };
  // orient2d: three collinear points.
  {
    const std::array<Point2, 3> p = {{{s * u, u}, {s * u / 2, u / 2}, {0, 0}}};
    expect("orient2d", ak.orient2d_staged(p[0], p[1], p[2]), mk.orient2d(p[0], p[1], p[2]),
           guard_passes<3, 2>(p, 2, ::o2_hi), str_points({p[0].data(), p[1].data(), p[2].data()}, 2));
  }
  // incircle: four cocircular points.
  {
    const Zero z = zero_config(s * u, u);
    const auto& p = z.p2;
    expect("incircle", ak.incircle_staged(p[0], p[1], p[2], p[3]),
           mk.incircle(p[0], p[1], p[2], p[3]), guard_passes<4, 2>(p, 4, ::ic_hi),
           str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 2));
  }
  // orient3d: four coplanar points (z = 0).
  {
    const std::array<Point3, 4> p = {{{s * u, 0, 0}, {0, u, 0}, {u, s * u, 0}, {0, 0, 0}}};
    expect("orient3d", ak.orient3d_staged(p[0], p[1], p[2], p[3]),
           mk.orient3d(p[0], p[1], p[2], p[3]), guard_passes<4, 3>(p, 3, ::o3_hi),
           str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data()}, 3));
  }
  // insphere: five cospherical points.
  {
    const Zero z = zero_config(s * u, u);
    const auto& p = z.p3;
    expect("insphere", ak.insphere_staged(p[0], p[1], p[2], p[3], p[4]),
           mk.insphere(p[0], p[1], p[2], p[3], p[4]), guard_passes<5, 3>(p, 5, ::is_hi),
           str_points({p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()}, 3));
  }
  return err;
}

// Stage D of insphere on raw coordinates (2.3): five points on the plane x = X (D = 0,
// every x difference 0) whose y differences have tails, so stages A-C cannot decide;
// stage D answers when |X| <= 2^195, mp beyond.
std::string check_stage_d_guard(double X) {
  const std::array<Point3, 5> p = {{{X, 0x1p-60, 1},
                                    {X, 3, 0x1p-70},
                                    {X, -1, 2},
                                    {X, 0x1.8p-61, -1},
                                    {X, 1, 0.5}}};
  const Staged st = AdaptiveKernel{}.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
  const std::string where = str(std::hexfloat, X, " stage ", stage_name(st.stage));
  if (st.sign != mk.insphere(p[0], p[1], p[2], p[3], p[4])) return "sign differs from mp at X = " + where;
  const bool raw_ok = std::fabs(X) <= is_hi;
  if (raw_ok && st.stage != adaptive::stage_d) return "stage D did not run at X = " + where;
  if (!raw_ok && st.stage != adaptive::stage_mp) return "stage D's raw guard let X = " + where;
  return "";
}

}  // namespace

TEST_CASE("exponent guards: exact at their thresholds and one step beyond", "[adaptive][edges]") {
  // Grid: k g >= -900, so the lowest admitted bit is 2^-450, 2^-300, 2^-225, 2^-180
  // for degree 2, 3, 4, 5; the first refused one is one binade lower.
  for (int g : {-449, -450, -451, -299, -300, -301, -224, -225, -226, -179, -180, -181}) {
    for (bool flip : {false, true}) {
      INFO("grid 2^" << g);
      EDGE_CHECK_CATCH(check_guards(std::ldexp(1.0, g), flip));
      EDGE_CHECK_CATCH(check_guards(std::ldexp(3.0, g), flip));  // lowest bit g, not a power of 2
    }
  }
  // Overflow: the largest |difference| at H, one ulp above and below, and a binade above,
  // for H = 2^490, 2^325, 2^245, 2^195 (the configurations' largest difference is u for
  // orient2d and orient3d, 2u for incircle and insphere).
  for (double H : {o2_hi, o3_hi, ic_hi, is_hi})
    for (double span : {1.0, 2.0})
      for (double u : {H / span, std::nextafter(H / span, inf), std::nextafter(H / span, 0.0), 2 * H / span})
        for (bool flip : {false, true}) {
          INFO("H " << H << " u " << u);
          EDGE_CHECK_CATCH(check_guards(u, flip));
        }
  // Stage D's raw-coordinate guard.
  for (double X : {0x1p195, std::nextafter(0x1p195, inf), std::nextafter(0x1p195, 0.0), 0x1p196,
                   -0x1p195, -std::nextafter(0x1p195, inf), 0x1p100})
    EDGE_CHECK_CATCH(check_stage_d_guard(X));
  rc::prop("guards at random binades", [] {
    const double u = std::ldexp(1 + *rc::gen::inRange(0, 1 << 20) * 0x1p-20, *rc::gen::inRange(-600, 520));
    EDGE_CHECK_RC(check_guards(u, *rc::gen::arbitrary<bool>()));
  });
}

// ======================================================================================
// Overflow claims (3.2-3.4): when an intermediate of the filter's determinant is not
// finite, the filter does not answer. Entries +-h, +-2h (h near the overflow
// threshold of each filter), the sign checked against mp.
TEST_CASE("inline filters never answer on an overflowed determinant", "[adaptive][edges]") {
  int o3_over = 0, is_over = 0, is_over_finite_l2mz = 0, ic_over = 0;
  rc::prop("entries from {0, +-h, +-2h}", [&] {
    const auto coef = rc::gen::inRange(-2, 3);
    const double m = 1 + *rc::gen::inRange(0, 1 << 20) * 0x1p-20;
    const AdaptiveKernel ak;
    {  // orient3d: monomials near 2^1021..2^1024.
      const double h = std::ldexp(m, *rc::gen::inRange(338, 343));
      std::array<Point3, 4> p{};
      for (int i = 0; i < 3; ++i)
        for (double& x : p[i]) x = *coef * h;
      const DetBound f = o3_filter_doc(p[0], p[1], p[2], p[3]);
      const Staged st = ak.orient3d_staged(p[0], p[1], p[2], p[3]);
      RC_ASSERT(st.sign == mk.orient3d(p[0], p[1], p[2], p[3]));
      if (f.overflow) {
        ++o3_over;
        RC_ASSERT(st.stage != adaptive::stage_filter);
      }
    }
    {  // incircle: degree 4, h near 2^254.
      const double h = std::ldexp(m, *rc::gen::inRange(251, 257));
      std::array<Point2, 4> p{};
      for (int i = 0; i < 3; ++i)
        for (double& x : p[i]) x = *coef * h;
      const DetBound f = ic_filter_doc(p[0], p[1], p[2], p[3]);
      const Staged st = ak.incircle_staged(p[0], p[1], p[2], p[3]);
      RC_ASSERT(st.sign == mk.incircle(p[0], p[1], p[2], p[3]));
      if (f.overflow) {
        ++ic_over;
        RC_ASSERT(st.stage != adaptive::stage_filter);
      }
    }
    {  // insphere: a, b, c at about 120 degrees in (x, y), of norm rho ~ 2^204, with
       // |z| = zeta < rho, and d of norm ~ rho: dlift abc reaches ~2.6 L^2 mz, so det
       // can overflow while L^2 mz (without the factor 128) does not.
      const double rho = std::ldexp(1 + *rc::gen::inRange(0, 1 << 20) * 0x1p-20, *rc::gen::inRange(203, 206));
      const double zeta = std::ldexp(rho, -*rc::gen::inRange(1, 7)) * (1 + *rc::gen::inRange(0, 1 << 10) * 0x1p-10);
      const double th = *rc::gen::inRange(0, 6283) * 1e-3;
      std::array<Point3, 5> p{};
      for (int i = 0; i < 3; ++i) {
        const double t = th + i * 2.0943951023931957 + (*rc::gen::inRange(-150, 151)) * 1e-3;
        p[i] = {rho * std::cos(t), rho * std::sin(t), (*rc::gen::arbitrary<bool>() ? 1 : -1) * zeta};
      }
      const double td = *rc::gen::inRange(0, 6283) * 1e-3, rd = rho * (0.9 + *rc::gen::inRange(0, 200) * 1e-3);
      p[3] = {rd * std::cos(td), rd * std::sin(td), zeta * (*rc::gen::inRange(-1000, 1001)) * 1e-3};
      const DetBound f = is_filter_doc(p[0], p[1], p[2], p[3], p[4]);
      const Staged st = ak.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
      RC_ASSERT(st.sign == mk.insphere(p[0], p[1], p[2], p[3], p[4]));
      if (f.overflow) {
        ++is_over;
        RC_ASSERT(st.stage != adaptive::stage_filter);
        double L = 0, mz = 0;
        for (int i = 0; i < 4; ++i) {
          L = std::max(L, (p[i][0] * p[i][0] + p[i][1] * p[i][1]) + p[i][2] * p[i][2]);
          mz = std::max(mz, std::fabs(p[i][2]));
        }
        if (std::isfinite((L * L) * mz) && std::isinf(f.det)) ++is_over_finite_l2mz;
      }
    }
  });
  {  // A fixed witness of the last case (found by a search over the same family).
    const std::array<Point3, 5> p = {{{0x1.3af19196b068fp+205, -0x1.0a02e227b8178p+200, 0x1.dc562bacde353p+201},
                                      {-0x1.b796e921b98abp+203, 0x1.2743ba18cfa7ep+205, -0x1.dc562bacde353p+201},
                                      {-0x1.8c2f8b8bc3bdbp+204, -0x1.e9f87cc3aa6cdp+204, 0x1.dc562bacde353p+201},
                                      {-0x1.44a05ac2c5ddfp+203, 0x1.3b329487516fep+205, 0x1.57708d0b38583p+201},
                                      {0, 0, 0}}};
    const DetBound f = is_filter_doc(p[0], p[1], p[2], p[3], p[4]);
    double L = 0, mz = 0;
    for (int i = 0; i < 4; ++i) {
      L = std::max(L, (p[i][0] * p[i][0] + p[i][1] * p[i][1]) + p[i][2] * p[i][2]);
      mz = std::max(mz, std::fabs(p[i][2]));
    }
    REQUIRE(std::isinf(f.det));
    REQUIRE(std::isfinite(adaptive::is_lift_filter * ((L * L) * mz)));
    const Staged st = AdaptiveKernel{}.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
    CHECK(st.stage != adaptive::stage_filter);
    CHECK(st.sign == mk.insphere(p[0], p[1], p[2], p[3], p[4]));
    ++is_over_finite_l2mz;
  }
  INFO("overflowed: orient3d " << o3_over << ", incircle " << ic_over << ", insphere " << is_over
                               << " (with L^2 mz finite and det infinite: " << is_over_finite_l2mz << ")");
  CHECK(o3_over > 0);
  CHECK(ic_over > 0);
  CHECK(is_over_finite_l2mz > 0);
}
