// A minimal interval arithmetic on doubles, used ONLY to prune search regions
// (algorithms/kd_tree.hpp, algorithms/tanemura.hpp) and to filter the exact
// start-up computations (algorithms/tanemura_start.cpp) — never to decide a
// predicate.
//
// Soundness: with IEEE round-to-nearest, the rounded result of +, -, *, /,
// sqrt is within half an ulp of the exact one, so widening each rounded
// endpoint by one ulp outwards (std::nextafter) encloses the exact result
// (also for subnormal results: the spacing there is the smallest subnormal,
// and the rounding error is at most half of it). Overflow gives an infinite
// endpoint; inf - inf gives NaN: `bounded()` is then false and callers give up
// pruning (scan more), which is always safe.
#pragma once
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>

namespace dlab {

struct Iv {
  double lo = 0, hi = 0;

  // std::nextafter(x, -inf) / (x, +inf), inline (the libm call dominated the
  // search's profile): one step of the bit pattern away from / towards zero.
  static double down(double x) {
    if (!(x > -std::numeric_limits<double>::infinity())) return x;  // -inf, NaN
    if (x == 0) return -std::numeric_limits<double>::denorm_min();
    const std::uint64_t b = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0 ? b - 1 : b + 1);
  }
  static double up(double x) {
    if (!(x < std::numeric_limits<double>::infinity())) return x;  // +inf, NaN
    if (x == 0) return std::numeric_limits<double>::denorm_min();
    const std::uint64_t b = std::bit_cast<std::uint64_t>(x);
    return std::bit_cast<double>(x > 0 ? b + 1 : b - 1);
  }

  // The arithmetic below widens with lower_rel() / upper_rel() instead: no
  // branch, three instructions (down and up were a fifth of the search's
  // instructions on clustered 3D input). For x normal, with u = ulp(x) = the
  // spacing of the doubles on x's binade, |x| 2^-52 rounds to at least u (u is
  // a power of two >= 2^-1074 and rounding is monotone), so x - |x| 2^-52 is
  // at most x - u exactly and rounds to at most x - u, a double (for x < 0,
  // |x| + u is one): lower_rel(x) <= down(x). Rounding to nearest puts the
  // exact result within half a spacing of x, so lower_rel(x) is below it. That
  // suffices for a result that is normal, or exact: a sum or difference
  // (below the normal range a sum is exact: both terms are multiples of
  // 2^-1074, Hauser 1996), a product with a zero factor, a quotient with a
  // zero numerator; products, quotients and squares that may have underflowed
  // get 2^-1074 more (may_underflow). So exact zeros stay zeros: widened to
  // +-2^-1074 (as nextafter does) they made subnormal operands downstream,
  // and each costs a microcode assist of about a hundred cycles (half of
  // Tanemura's time on a 3D lattice). lower_rel(+inf) and upper_rel(-inf) are
  // NaN (unbounded), lower_rel(-inf) = -inf, upper_rel(+inf) = +inf, NaN stays
  // NaN. upper_rel is the mirror image.
  static double lower_rel(double x) { return x - std::fabs(x) * 0x1p-52; }
  static double upper_rel(double x) { return x + std::fabs(x) * 0x1p-52; }
  // fl(x * y) = p (or x / y) may have lost more than the relative step:
  // it is below the normal range and x, y are not zero.
  static bool may_underflow(double x, double y, double p) {
    return x != 0 && y != 0 && !(std::fabs(p) >= 0x1p-1022);
  }

  // Rounded results that are exact need no widening, so exact data (lattices,
  // axis-aligned facets) keep point intervals and prune exactly. Exactness is
  // decided by error-free transformations (Shewchuk 1997 section 2: Knuth's
  // Two-Sum; Dekker's Two-Product with Veltkamp's split), each valid in the
  // range checked here; outside it the result counts as inexact (widened).
  static bool sum_is_exact(double a, double b, double s) {  // s = fl(a + b)
    const double bv = s - a;
    return ((a - (s - bv)) + (b - bv)) == 0;  // NaN (overflow) compares false
  }
  static bool product_is_exact(double a, double b, double p) {  // p = fl(a * b)
    if ((a == 0 && std::isfinite(b)) || (b == 0 && std::isfinite(a))) return true;
    const double fa = std::fabs(a), fb = std::fabs(b), fp = std::fabs(p);
    // No overflow in the split (|x| < 2^995) and no underflow in the partial
    // products (|p| >= 2^-960 keeps al * bl, about 2^-54 |p|, normal).
    if (!(fa < 0x1p+995 && fb < 0x1p+995 && fp >= 0x1p-960 && fp < 0x1p+1000)) return false;
    const auto split = [](double x, double& hi, double& lo) {
      const double c = 134217729.0 * x;  // 2^27 + 1
      hi = c - (c - x);
      lo = x - hi;
    };
    double ah, al, bh, bl;
    split(a, ah, al);
    split(b, bh, bl);
    return (((ah * bh - p) + ah * bl + al * bh) + al * bl) == 0;
  }
  // Point-interval operations that stay points when exact (else widened).
  friend Iv tight_sub(Iv a, Iv b) {
    if (a.lo != a.hi || b.lo != b.hi) return a - b;
    const double s = a.lo - b.lo;
    return sum_is_exact(a.lo, -b.lo, s) ? Iv{s, s} : Iv{down(s), up(s)};
  }
  friend Iv tight_mul(Iv a, Iv b) {
    if (a.lo != a.hi || b.lo != b.hi) return a * b;
    const double p = a.lo * b.lo;
    return product_is_exact(a.lo, b.lo, p) ? Iv{p, p} : Iv{down(p), up(p)};
  }

  static Iv exact(double x) { return {x, x}; }
  bool bounded() const { return std::isfinite(lo) && std::isfinite(hi) && lo <= hi; }
  bool contains_zero() const { return !(lo > 0) && !(hi < 0); }  // also true for NaN
  // The enclosure of a op b from its four corner results, each rounded once:
  // widened by the relative step, and by 2^-1074 more when a corner may have
  // underflowed (products and quotients alike).
  static Iv from_corners(Iv a, Iv b, double p1, double p2, double p3, double p4) {
    const double mn = std::min(std::min(p1, p2), std::min(p3, p4));
    const double mx = std::max(std::max(p1, p2), std::max(p3, p4));
    Iv r{lower_rel(mn), upper_rel(mx)};
    if (!(std::fabs(mn) >= 0x1p-1022) || !(std::fabs(mx) >= 0x1p-1022))
      if (may_underflow(a.lo, b.lo, p1) || may_underflow(a.lo, b.hi, p2) || may_underflow(a.hi, b.lo, p3) ||
          may_underflow(a.hi, b.hi, p4))
        r = {r.lo - 0x1p-1074, r.hi + 0x1p-1074};
    return r;
  }

  friend Iv operator+(Iv a, Iv b) { return {lower_rel(a.lo + b.lo), upper_rel(a.hi + b.hi)}; }
  friend Iv operator-(Iv a, Iv b) { return {lower_rel(a.lo - b.hi), upper_rel(a.hi - b.lo)}; }
  // Products and quotients: the relative step, and 2^-1074 more at both ends
  // when one of the four may have underflowed (rare: then the smallest or the
  // largest is below the normal range; rounding is monotone, so these are the
  // rounded extremes of the exact ones).
  friend Iv operator*(Iv a, Iv b) {
    const double p1 = a.lo * b.lo, p2 = a.lo * b.hi, p3 = a.hi * b.lo, p4 = a.hi * b.hi;
    // A NaN product (0 * inf, or a NaN bound) makes the sum NaN; so does inf - inf,
    // from infinite products only: unbounded either way.
    if (std::isnan(p1 + p2 + p3 + p4))
      return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    return from_corners(a, b, p1, p2, p3, p4);
  }
  // Division by an interval that excludes zero (else NaN: unbounded).
  friend Iv operator/(Iv a, Iv b) {
    if (b.contains_zero())
      return {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
    const double p1 = a.lo / b.lo, p2 = a.lo / b.hi, p3 = a.hi / b.lo, p4 = a.hi / b.hi;
    return from_corners(a, b, p1, p2, p3, p4);
  }
  // Square: non-negative enclosure.
  // No sign branch (it mispredicted): the least |x| on [lo, hi] is
  // max(lo, -hi, 0). A NaN or infinite bound makes 0 (lo + hi) NaN, and so
  // the upper end (unbounded; std::max alone could drop a NaN). Squares
  // below the normal range get 2^-1074 more, as products do.
  friend Iv sq(Iv a) {
    const double big = std::max(std::fabs(a.lo), std::fabs(a.hi));
    const double small = std::max(std::max(a.lo, -a.hi), 0.0);
    const double s2 = small * small, b2 = big * big;
    Iv r{lower_rel(s2), upper_rel(b2) + 0.0 * (a.lo + a.hi)};
    if (!(s2 >= 0x1p-1022) || !(b2 >= 0x1p-1022)) {
      if (may_underflow(small, small, s2)) r.lo -= 0x1p-1074;
      if (may_underflow(big, big, b2)) r.hi += 0x1p-1074;
    }
    r.lo = std::max(0.0, r.lo);
    return r;
  }
};

// Upper bound of sqrt(x) for x >= 0 (sqrt is correctly rounded).
inline double sqrt_up(double x) { return Iv::up(std::sqrt(std::max(0.0, x))); }

}  // namespace dlab
