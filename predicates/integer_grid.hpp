// The integer grid of George's kernel (George, "Improvements on Delaunay-based
// three-dimensional automatic mesh generator", FEAD 25 (1997), section 2.3:
// "the coordinates of the points are converted to integers" so that volumes
// are computed exactly).
//
// Grid: one step h = 2^e for every axis (isotropic: snapping scales all axes
// alike, so "Delaunay" keeps its meaning), grid points are the multiples of h,
// and each axis j has an index range [lo_j, hi_j] with hi_j - lo_j <= 2^B - 1:
// coordinate differences between grid points are integers of magnitude < 2^B
// times h. Snapping = round x/h to the nearest integer (ties away from zero),
// clamped to [lo_j, hi_j]; deterministic and idempotent.
//
// Why snapped values are exact doubles, for any step h = 2^e >= 2^-1074.
// Let x be a double. If ulp(x) >= h, x is already a multiple of h: snap(x) = x.
// Otherwise |x| < 2^53 h (ulp(x) = 2^(ilogb(x) - 52) < h), so the nearest
// multiple i h has |i| <= 2^53: a 53-bit integer times a power of two, which
// is a double (down to the subnormals, which are the multiples of 2^-1074).
// Also x/h, computed as x * 2^-e, is exact (power-of-two scaling; if it
// underflows it is far below 1/2 and rounds to index 0), and so are the box
// corners floor(lo/h) h, ceil(hi/h) h. So snap() returns the grid point itself,
// `--points-out` can write it and `mp` can check the very points used.
//
// Indices are absolute (multiples of h counted from 0): fit() starts at
// e = ilogb(max |coordinate|) - 61, so |index| < 2^62 fits int64, and raises e
// until every axis spans at most 2^B - 1 steps. The finer the grid (the larger
// B), the fewer bits snapping drops: a coordinate moves only if it has bits
// below h. With B = 62, h <= 2^-60 max |coordinate| for every point set (at
// e = ilogb(max) - 60 any span is below 2^62 - 2^10): the Kettner et al.
// points, say, do not move at all.
#pragma once
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

// What snapping did to a point set. Displacement is Euclidean, in input units
// (IntegerGrid::displacement: within 1 ulp in 2D, 3 in 3D, subnormal moves included).
struct SnapStats {
  std::size_t points = 0;
  std::size_t moved = 0;   // points with at least one coordinate changed
  std::size_t merged = 0;  // distinct inputs - distinct snapped points
  double max_displacement = 0;
};

template <int D>
class IntegerGrid {
 public:
  using Index = std::int64_t;
  using IPoint = std::array<Index, D>;

  // The unit grid (h = 1) centred on 0, covering |x| <= 2^(min(B,54)-1) - 1.
  IntegerGrid() : IntegerGrid(unit(62)) {}
  static IntegerGrid unit(int bits) {
    IntegerGrid g(bits, 0);
    const Index r = (Index{1} << (std::min(bits, 54) - 1)) - 1;
    g.lo_.fill(-r);
    g.hi_.fill(r);
    g.cache_bounds();
    return g;
  }

  // The finest grid of this form whose index box contains every finite
  // coordinate of pts (a unit grid when there is none). Non-finite coordinates
  // are ignored here and clamped by index().
  static IntegerGrid fit(std::span<const Point<D>> pts, int bits) {
    assert(bits >= 3 && bits <= 62);
    std::array<double, D> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    double r = 0;
    bool any = false;
    for (const auto& p : pts)
      for (int j = 0; j < D; ++j) {
        if (!std::isfinite(p[j])) continue;
        any = true;
        lo[j] = std::min(lo[j], p[j]);
        hi[j] = std::max(hi[j], p[j]);
        r = std::max(r, std::fabs(p[j]));
      }
    if (!any) return unit(bits);
    for (int j = 0; j < D; ++j)
      if (lo[j] > hi[j]) lo[j] = hi[j] = 0;  // an axis with no finite value
    const int e0 = r > 0 ? std::max(std::ilogb(r) - 61, -1074) : -1074;
    const Index span_max = (Index{1} << bits) - 1;
    // Bounded: at e = 1023 every |x/h| < 2, so the span is at most 4 <= 2^bits - 1.
    for (int e = e0; e <= 1023; ++e) {
      IntegerGrid g(bits, e);
      bool ok = true;
      for (int j = 0; j < D && ok; ++j) {
        g.lo_[j] = static_cast<Index>(std::floor(g.scaled(lo[j])));
        g.hi_[j] = static_cast<Index>(std::ceil(g.scaled(hi[j])));
        // No overflow: |x/h| < 2^62, and beyond 2^53 x/h is an integer, so
        // both ends lie within 2^62 - 2^10 of 0.
        ok = g.hi_[j] - g.lo_[j] <= span_max;
      }
      if (!ok) continue;
      // Keep the grid's extreme points finite doubles. Only a grid with
      // bits < 54 over values within h of DBL_MAX needs this; those values
      // are then clamped to the last finite grid point (not covered).
      // For e < 962, 2^62 h < DBL_MAX already.
      const Index top =
          e < 962 ? Index{1} << 62
                  : static_cast<Index>(std::floor(g.scaled(std::numeric_limits<double>::max())));
      for (int j = 0; j < D; ++j) {
        g.lo_[j] = std::max(g.lo_[j], -top);
        g.hi_[j] = std::min(g.hi_[j], top);
      }
      g.cache_bounds();
      return g;
    }
    return unit(bits);  // not reached
  }

  int bits() const { return bits_; }
  int exponent() const { return e_; }
  double step() const { return h_; }
  Index lo(int axis) const { return lo_[axis]; }
  Index hi(int axis) const { return hi_[axis]; }
  double lower(int axis) const { return value(lo_[axis]); }
  double upper(int axis) const { return value(hi_[axis]); }

  // The grid coordinate of index i: exact for the indices of snapped doubles
  // and of the box corners (see above); other indices may round.
  double value(Index i) const { return static_cast<double>(i) * h_; }

  // Nearest grid index on one axis (ties away from zero), clamped to the box;
  // NaN maps to the low end. Deterministic for every double.
  Index index(double x, int axis) const {
    const double t = scaled(x);  // exact x / h
    if (!(t > lo_d_[axis])) return lo_[axis];
    if (!(t < hi_d_[axis])) return hi_[axis];
    // |t| < 2^62 here: truncate, then round the exact fraction (t - trunc(t) is
    // exact: Sterbenz for |t| >= 1, t itself below; 0 once |t| >= 2^52).
    Index i = static_cast<Index>(t);
    const double f = t - static_cast<double>(i);
    if (f >= 0.5) ++i;
    else if (f <= -0.5) --i;
    return i;  // within [lo, hi]: both are integers and lo < t < hi
  }
  IPoint index(const Point<D>& p) const {
    IPoint r;
    for (int j = 0; j < D; ++j) r[j] = index(p[j], j);
    return r;
  }

  // The index of a grid point p of the box (snap(p) == p): p / h on each
  // axis, an integer below 2^62 in magnitude and computed exactly.
  IPoint grid_index(const Point<D>& p) const {
    IPoint r;
    for (int j = 0; j < D; ++j) r[j] = static_cast<Index>(scaled(p[j]));
    return r;
  }

  Point<D> snap(const Point<D>& p) const {
    Point<D> s;
    for (int j = 0; j < D; ++j) s[j] = value(index(p[j], j));
    return s;
  }

  bool covers(const Point<D>& p) const {
    for (int j = 0; j < D; ++j)
      if (!(lower(j) <= p[j] && p[j] <= upper(j))) return false;
    return true;
  }

  // |s - p|, Euclidean, for p and its snapped point s. For a coordinate the grid
  // covers, the difference s_j - p_j is exact: if |p_j| < h/2, s_j = 0 and it
  // is -p_j; otherwise ulp(p_j) = 2^k with h <= 2 |p_j| < 2^(k+54), and the
  // difference is a multiple of 2^k (h is one) of magnitude <= h/2 < 2^(k+53),
  // a double. std::hypot neither underflows nor overflows in its squares, so a
  // subnormal snapped to zero moves by its own value, not by sqrt(0) from an
  // underflowed square. glibc's two-argument hypot is within 1 ulp (its
  // libm-test-ulps); 3D nests two: the inner error, at most 2^-52 relative,
  // moves the outer result by less than 2^-52 r < 2 ulp(r), and the outer
  // rounding adds 1 ulp, so 3D is within 3 ulps (libstdc++'s three-argument
  // hypot has no documented bound). Tested in tests/test_integer_kernel.cpp.
  static double displacement(const Point<D>& p, const Point<D>& s) {
    if constexpr (D == 2)
      return std::hypot(s[0] - p[0], s[1] - p[1]);
    else
      return std::hypot(std::hypot(s[0] - p[0], s[1] - p[1]), s[2] - p[2]);
  }

  // Snaps every point in place and says what moved and what merged.
  SnapStats snap_all(std::vector<Point<D>>& pts) const {
    SnapStats st;
    st.points = pts.size();
    // The input, copied when the first point moves (the points before it are
    // their own snaps): where none moves, none merges, and no copy is sorted.
    std::vector<Point<D>> before;
    for (auto& p : pts) {
      const Point<D> s = snap(p);
      if (s != p) {
        if (st.moved++ == 0) before = pts;
        st.max_displacement = std::max(st.max_displacement, displacement(p, s));
      }
      p = s;
    }
    if (st.moved == 0) return st;
    std::vector<Point<D>> after = pts;
    st.merged = distinct(before) - distinct(after);
    return st;
  }

 private:
  IntegerGrid(int bits, int e) {
    bits_ = bits;
    e_ = e;
    h_ = std::ldexp(1.0, e);
    // x * 2^-e as two exact power-of-two factors (2^-e alone overflows for e < -1023).
    s1_ = std::ldexp(1.0, -e <= 1023 ? -e : 1023);
    s2_ = std::ldexp(1.0, -e <= 1023 ? 0 : -e - 1023);
  }
  double scaled(double x) const { return x * s1_ * s2_; }
  void cache_bounds() {  // exact: the bounds are integers below 2^62 from doubles
    for (int j = 0; j < D; ++j) {
      lo_d_[j] = static_cast<double>(lo_[j]);
      hi_d_[j] = static_cast<double>(hi_[j]);
    }
  }

  // Number of distinct points (numeric equality: -0 == +0); finite inputs.
  static std::size_t distinct(std::vector<Point<D>>& v) {
    std::sort(v.begin(), v.end());
    return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
  }

  int bits_ = 55;
  int e_ = 0;
  double h_ = 1, s1_ = 1, s2_ = 1;
  IPoint lo_{}, hi_{};
  std::array<double, D> lo_d_{}, hi_d_{};  // lo_, hi_ as doubles
};

}  // namespace dlab
