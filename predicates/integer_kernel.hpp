// `integer`: George's integer-coordinate kernel (George 1997, section 2.3:
// volumes computed exactly on coordinates converted to integers).
//
// Each double coordinate is mapped to its index on the kernel's grid
// (predicates/integer_grid.hpp: nearest grid point, clamped to the box), and
// the determinant is computed exactly in integers, unless a floating-point
// filter decides its sign first (as CGAL's Epeck filters before its exact
// numbers; see stage_names below). The answer is the exact sign for the
// snapped points, and it is consistent for every input (the
// snapping is a fixed function of the point). Snap first (`snap_all`) to
// triangulate exactly the points the kernel sees.
//
// Bit budget (B = bits per axis; every index difference d has |d| <= 2^B - 1,
// so |d| < 2^B; bounds below are strict, each term and partial sum included):
//   product d*d'                  < 2^(2B)
//   2x2 minor  d1 d2' - d2 d1'    < 2^(2B+1)
//   2D lift    dx^2 + dy^2        < 2^(2B+1)
//   3D lift    dx^2 + dy^2 + dz^2 < 3 2^(2B)    < 2^(2B+2)
//   orient2d   = one 2x2 minor    < 2^(2B+1)
//   incircle   = sum of 3 lift*minor            < 3 2^(4B+2) < 2^(4B+4)
//   orient3d   = sum of 3 d*minor (a 3x3 minor) < 3 2^(3B+1) < 2^(3B+3)
//   insphere   = sum of 4 lift*(3x3 minor)      < 4 2^(2B+2) 2^(3B+3) = 2^(5B+7)
//   coplanar in-circle (below) = sum of 3 (3D lift)*minor < 3 2^(2B+2) 2^(2B+1) < 2^(4B+5)
// Each stage is computed in IntFor<bound> (predicates/wide_int.hpp), the
// narrowest of int64 / __int128 / WideInt<N> holding it; static_asserts below
// restate each bound against its type's capacity.
//
// Choice of B. The default IntegerKernel uses B = 62 in 2D and in 3D, the
// largest B for which every stage still fits the next machine-friendly width
// (index differences in int64 need B <= 63; 3D lifts in __int128 and
// insphere in 320 bits need B <= 62; the finer the grid, the less snapping
// moves, see integer_grid.hpp). Types at B = 62:
//   orient2d 125 bits -> __int128;   incircle 252 bits -> WideInt<4> (256-bit)
//   orient3d 189 bits -> WideInt<3>; insphere 317 bits -> WideInt<5> (320-bit)
// IntegerKernel128 uses B = 30 (2D: incircle 124 bits) and B = 24 (3D:
// insphere 127 bits), the largest B for which every predicate fits __int128:
// coarser grids, cheaper arithmetic.
#pragma once
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/float_filter.hpp"
#include "predicates/integer_grid.hpp"
#include "predicates/kernel.hpp"
#include "predicates/small_integer.hpp"
#include "predicates/sos_walk.hpp"
#include "predicates/wide_int.hpp"

namespace dlab {

// Exact determinants on integer grid indices; precondition: on every axis the
// indices of the points differ by at most 2^B - 1. Returns the exact value.
namespace intdet {

using I2 = std::array<std::int64_t, 2>;
using I3 = std::array<std::int64_t, 3>;

template <int B>
struct Budget {
  static_assert(B >= 3 && B <= 62, "differences and lifts must fit the types below");
  using Minor2 = IntFor<2 * B + 1>;   // 2x2 minors, 2D lifts, orient2d
  using Lift3 = IntFor<2 * B + 2>;    // 3D lifts
  using Minor3 = IntFor<3 * B + 3>;   // 3x3 minors, orient3d
  using InCircle = IntFor<4 * B + 4>;
  using InSphere = IntFor<5 * B + 7>;
  using CoplanarInCircle = IntFor<4 * B + 5>;
  static_assert(value_bits<std::int64_t> >= B);  // index differences
  static_assert(value_bits<Minor2> >= 2 * B + 1);
  static_assert(value_bits<Lift3> >= 2 * B + 2);
  static_assert(value_bits<Minor3> >= 3 * B + 3);
  static_assert(value_bits<InCircle> >= 4 * B + 4);
  static_assert(value_bits<InSphere> >= 5 * B + 7);
  static_assert(value_bits<CoplanarInCircle> >= 4 * B + 5);
};

template <class T>
T minor2(std::int64_t a0, std::int64_t a1, std::int64_t b0, std::int64_t b1) {
  return mul_in<T>(a0, b1) - mul_in<T>(a1, b0);
}

template <int B>
typename Budget<B>::Minor2 orient2d(const I2& a, const I2& b, const I2& c) {
  using T = typename Budget<B>::Minor2;
  return minor2<T>(a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]);
}

template <int B>
typename Budget<B>::InCircle incircle(const I2& a, const I2& b, const I2& c, const I2& d) {
  using T = typename Budget<B>::Minor2;
  using W = typename Budget<B>::InCircle;
  const std::int64_t adx = a[0] - d[0], ady = a[1] - d[1];
  const std::int64_t bdx = b[0] - d[0], bdy = b[1] - d[1];
  const std::int64_t cdx = c[0] - d[0], cdy = c[1] - d[1];
  const T alift = mul_in<T>(adx, adx) + mul_in<T>(ady, ady);
  const T blift = mul_in<T>(bdx, bdx) + mul_in<T>(bdy, bdy);
  const T clift = mul_in<T>(cdx, cdx) + mul_in<T>(cdy, cdy);
  const T bc = minor2<T>(bdx, bdy, cdx, cdy);
  const T ca = minor2<T>(cdx, cdy, adx, ady);
  const T ab = minor2<T>(adx, ady, bdx, bdy);
  return mul_in<W>(alift, bc) + mul_in<W>(blift, ca) + mul_in<W>(clift, ab);
}

// 3x3 minor with rows (x0,y0,z0),(x1,..),(x2,..) expanded along z:
// z0 M(1,2) - z1 M(0,2) + z2 M(0,1), written with the cyclic minors.
template <int B>
typename Budget<B>::Minor3 orient3d(const I3& a, const I3& b, const I3& c, const I3& d) {
  using T = typename Budget<B>::Minor2;
  using W = typename Budget<B>::Minor3;
  const std::int64_t adx = a[0] - d[0], ady = a[1] - d[1], adz = a[2] - d[2];
  const std::int64_t bdx = b[0] - d[0], bdy = b[1] - d[1], bdz = b[2] - d[2];
  const std::int64_t cdx = c[0] - d[0], cdy = c[1] - d[1], cdz = c[2] - d[2];
  const T bc = minor2<T>(bdx, bdy, cdx, cdy);
  const T ca = minor2<T>(cdx, cdy, adx, ady);
  const T ab = minor2<T>(adx, ady, bdx, bdy);
  return mul_in<W>(adz, bc) + mul_in<W>(bdz, ca) + mul_in<W>(cdz, ab);
}

template <int B>
typename Budget<B>::InSphere insphere(const I3& a, const I3& b, const I3& c, const I3& d,
                                      const I3& e) {
  using T = typename Budget<B>::Minor2;
  using L = typename Budget<B>::Lift3;
  using M = typename Budget<B>::Minor3;
  using W = typename Budget<B>::InSphere;
  std::int64_t x[4], y[4], z[4];
  const I3* p[4] = {&a, &b, &c, &d};
  for (int i = 0; i < 4; ++i) {
    x[i] = (*p[i])[0] - e[0];
    y[i] = (*p[i])[1] - e[1];
    z[i] = (*p[i])[2] - e[2];
  }
  // 2x2 minors of the x,y columns: m[i][j] = x_i y_j - x_j y_i.
  const T ab = minor2<T>(x[0], y[0], x[1], y[1]);
  const T bc = minor2<T>(x[1], y[1], x[2], y[2]);
  const T cd = minor2<T>(x[2], y[2], x[3], y[3]);
  const T da = minor2<T>(x[3], y[3], x[0], y[0]);
  const T ac = minor2<T>(x[0], y[0], x[2], y[2]);
  const T bd = minor2<T>(x[1], y[1], x[3], y[3]);
  // 3x3 minors of rows (i,j,k) over x,y,z: each a sum of three d*minor2 terms.
  const M abc = mul_in<M>(z[0], bc) - mul_in<M>(z[1], ac) + mul_in<M>(z[2], ab);
  const M bcd = mul_in<M>(z[1], cd) - mul_in<M>(z[2], bd) + mul_in<M>(z[3], bc);
  const M cda = mul_in<M>(z[2], da) + mul_in<M>(z[3], ac) + mul_in<M>(z[0], cd);
  const M dab = mul_in<M>(z[3], ab) + mul_in<M>(z[0], bd) + mul_in<M>(z[1], da);
  L lift[4];
  for (int i = 0; i < 4; ++i)
    lift[i] = mul_in<L>(x[i], x[i]) + mul_in<L>(y[i], y[i]) + mul_in<L>(z[i], z[i]);
  // Laplace expansion along the lifted column (as predicates/determinants.hpp).
  return (mul_in<W>(lift[3], abc) - mul_in<W>(lift[2], dab)) +
         (mul_in<W>(lift[1], cda) - mul_in<W>(lift[0], bcd));
}

// The two coordinates kept by the projection that drops `axis` (2: x, y;
// 0: y, z; 1: x, z -- perturbed<K>'s coplanar_orientation order).
inline std::array<int, 2> kept(int axis) {
  return axis == 2 ? std::array<int, 2>{0, 1} : (axis == 0 ? std::array<int, 2>{1, 2}
                                                          : std::array<int, 2>{0, 2});
}

template <int B>
typename Budget<B>::Minor2 projected_orient2d(const I3& a, const I3& b, const I3& c, int axis) {
  const auto [i, j] = kept(axis);
  return orient2d<B>({a[i], a[j]}, {b[i], b[j]}, {c[i], c[j]});
}

// For a, b, c, p in one plane whose projection dropping `axis` is
// non-degenerate: the in-circle determinant of the projections (a' - p', ...)
// with the 3D squared distances |a - p|^2, ... as lifts. On the plane the
// dropped coordinate is an affine function of the kept ones, so x -> |x - p|^2
// is a positive definite quadratic form q of x' - p', and the circle abc is
// the plane section {q = L} of the lifted surface, L affine (Guibas & Stolfi,
// ACM TOG 4 (1985), the lifting argument for in-circle, with q for the
// paraboloid). Hence the sign is positive iff p is inside the circle abc when
// a', b', c' are counterclockwise.
template <int B>
typename Budget<B>::CoplanarInCircle coplanar_incircle(const I3& a, const I3& b, const I3& c,
                                                       const I3& p, int axis) {
  using T = typename Budget<B>::Minor2;
  using L = typename Budget<B>::Lift3;
  using W = typename Budget<B>::CoplanarInCircle;
  const auto [i, j] = kept(axis);
  const I3* q[3] = {&a, &b, &c};
  std::int64_t u[3], v[3];
  L lift[3];
  for (int k = 0; k < 3; ++k) {
    const std::int64_t dx = (*q[k])[0] - p[0], dy = (*q[k])[1] - p[1], dz = (*q[k])[2] - p[2];
    u[k] = (*q[k])[i] - p[i];
    v[k] = (*q[k])[j] - p[j];
    lift[k] = mul_in<L>(dx, dx) + mul_in<L>(dy, dy) + mul_in<L>(dz, dz);
  }
  const T bc = minor2<T>(u[1], v[1], u[2], v[2]);
  const T ca = minor2<T>(u[2], v[2], u[0], v[0]);
  const T ab = minor2<T>(u[0], v[0], u[1], v[1]);
  return mul_in<W>(lift[0], bc) + mul_in<W>(lift[1], ca) + mul_in<W>(lift[2], ab);
}

template <class T>
Sign sign(const T& v) {
  return static_cast<Sign>(sign_int(v));
}

// The filter's input: q_i - base per axis (base = the last point), exact in
// int64 (|q_i - base| <= 2^B - 1 < 2^62), then rounded once by the conversion
// to double; the base itself becomes the origin.
template <std::size_t N, std::size_t D>
std::array<Point<D>, N> rounded_differences(const std::array<std::array<std::int64_t, D>, N>& q) {
  std::array<Point<D>, N> r;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t j = 0; j < D; ++j) r[i][j] = static_cast<double>(q[i][j] - q[N - 1][j]);
  return r;
}

// The largest B at which a determinant's every stage (the Budget bounds
// above) fits int64, whose value_bits is 63: 2B+1, 4B+4, 3B+3, 5B+7 <= 63.
inline constexpr int kInt64Orient2d = 31, kInt64InCircle = 14, kInt64Orient3d = 20, kInt64InSphere = 11;
static_assert(std::is_same_v<Budget<kInt64Orient2d>::Minor2, std::int64_t> &&
              !std::is_same_v<Budget<kInt64Orient2d + 1>::Minor2, std::int64_t>);
static_assert(std::is_same_v<Budget<kInt64InCircle>::InCircle, std::int64_t> &&
              !std::is_same_v<Budget<kInt64InCircle + 1>::InCircle, std::int64_t>);
static_assert(std::is_same_v<Budget<kInt64Orient3d>::Minor3, std::int64_t> &&
              !std::is_same_v<Budget<kInt64Orient3d + 1>::Minor3, std::int64_t>);
static_assert(std::is_same_v<Budget<kInt64InSphere>::InSphere, std::int64_t> &&
              !std::is_same_v<Budget<kInt64InSphere + 1>::InSphere, std::int64_t>);

// q's differences from its base (the last point, which becomes the origin),
// each divided by their largest common power of two 2^g (exact: each is a
// multiple of 2^g); `magnitudes` is the OR of the quotients' absolute values
// (0: every point is the base), below 2^k iff each of them is.
template <std::size_t N, std::size_t D>
struct Reduced {
  std::array<std::array<std::int64_t, D>, N> q;
  std::uint64_t magnitudes;
};
// One pass takes the differences and the OR of their absolute values: |x| has
// x's trailing zeros, so that OR's trailing zeros are g; and |x| >> g = |x >> g|
// for x a multiple of 2^g, so the quotients' OR is that OR shifted by g.
template <std::size_t N, std::size_t D>
Reduced<N, D> reduce(std::array<std::array<std::int64_t, D>, N> q) {
  std::uint64_t bits = 0;
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j) {
      const std::int64_t x = q[i][j] -= q[N - 1][j];  // |x| <= 2^B - 1 < 2^62
      bits |= static_cast<std::uint64_t>(x < 0 ? -x : x);
    }
  q[N - 1] = {};
  if (bits == 0) return {q, 0};
  const int g = std::countr_zero(bits);
  for (std::size_t i = 0; i + 1 < N; ++i)
    for (std::size_t j = 0; j < D; ++j) q[i][j] >>= g;
  return {q, bits >> g};
}

// The sign of det<B>(q) (q's base last), computed on reduce(q): the
// determinants are homogeneous in the differences, so the sign stays. Where
// every quotient is at most 2^Small - 1, det<Small> holds it in narrower
// types (Small = 24 in 3D, 30 in 2D: __int128), and where at most
// 2^Tiny - 1, det<Tiny> in int64 alone (Tiny <= the kInt64 bound of det): a
// lattice fitted to the grid has g about B - (its bits).
template <int B, int Small, int Tiny, std::size_t N, std::size_t D, class Det>
Sign reduced_sign(const Reduced<N, D>& r, Det det) {
  static_assert(Tiny <= Small && Small <= B);
  if (r.magnitudes == 0) return Sign::zero;  // every point is the base
  if constexpr (Tiny < Small)
    if (r.magnitudes < (std::uint64_t{1} << Tiny)) return sign(det.template operator()<Tiny>(r.q));
  if (r.magnitudes < (std::uint64_t{1} << Small)) return sign(det.template operator()<Small>(r.q));
  return sign(det.template operator()<B>(r.q));
}
template <int B, int Small, int Tiny, std::size_t N, std::size_t D, class Det>
Sign reduced_sign(const std::array<std::array<std::int64_t, D>, N>& indices, Det det) {
  return reduced_sign<B, Small, Tiny>(reduce(indices), det);
}

// perturbed<K>'s walk (predicates/sos_walk.hpp) on the D+2 reduced vectors of
// r (the query last), every coordinate at most 2^Tiny - 1 in magnitude. Where
// the vectors are the points' grid indices (a translation and a positive
// scale of the points), their lexicographic order and each orientation's sign
// are the points', so the walk answers as it does on the points.
//  - The order: each coordinate plus 2^Tiny lies in [1, 2^(Tiny+1) - 1], so
//    the coordinates side by side in fields of Tiny + 1 bits, x highest, make
//    a key whose integer order is the lexicographic one (D (Tiny + 1) <= 45
//    bits, asserted).
//  - The orientations: of D+1 of the vectors, whose differences are at most
//    2^(Tiny+1) - 2: orient<Tiny+1>, in int64 (asserted).
template <int Tiny, std::size_t N, std::size_t D>
Sign reduced_walk(const Reduced<N, D>& r) {
  static_assert(N == D + 2 && D * (Tiny + 1) <= 45);
  using P = std::array<std::int64_t, D>;
  std::array<const P*, N> pts;
  std::array<std::int64_t, N> key;
  for (std::size_t i = 0; i < N; ++i) {
    pts[i] = &r.q[i];
    key[i] = 0;
    for (std::size_t j = 0; j < D; ++j) key[i] = (key[i] << (Tiny + 1)) + (r.q[i][j] + (std::int64_t{1} << Tiny));
  }
  const auto order = sos::by_decreasing<N>([&](int i, int j) { return key[i] < key[j]; });
  return sos::walk_in_order<int{D}, P>(pts, order, [](const std::array<const P*, D + 1>& t) {
    if constexpr (D == 2) {
      static_assert(std::is_same_v<typename Budget<Tiny + 1>::Minor2, std::int64_t>);
      return sign(orient2d<Tiny + 1>(*t[0], *t[1], *t[2]));
    } else {
      static_assert(std::is_same_v<typename Budget<Tiny + 1>::Minor3, std::int64_t>);
      return sign(orient3d<Tiny + 1>(*t[0], *t[1], *t[2], *t[3]));
    }
  });
}

}  // namespace intdet

template <int B2, int B3>
class BasicIntegerKernel {
 public:
  static constexpr bool exact = true;
  static constexpr std::string_view name = "integer";
  static constexpr int bits2 = B2, bits3 = B3;

  // Unit grids (h = 1) until fitted.
  BasicIntegerKernel() : g2_(IntegerGrid<2>::unit(B2)), g3_(IntegerGrid<3>::unit(B3)) {}

  // A kernel whose D-dimensional grid covers pts (the other one stays unit).
  template <int D>
  static BasicIntegerKernel fit(std::span<const Point<D>> pts) {
    BasicIntegerKernel k;
    if constexpr (D == 2) {
      k.g2_ = IntegerGrid<2>::fit(pts, B2);
      k.fitted2_ = true;
    } else {
      static_assert(D == 3);
      k.g3_ = IntegerGrid<3>::fit(pts, B3);
      k.fitted3_ = true;
    }
    return k;
  }

  const IntegerGrid<2>& grid2() const { return g2_; }
  const IntegerGrid<3>& grid3() const { return g3_; }

  Point2 snap(const Point2& p) const { return g2_.snap(p); }
  Point3 snap(const Point3& p) const { return g3_.snap(p); }

  // The SnappingKernel hook: snaps in place on this kernel's grid, fitting the
  // grid to pts first if it was not fitted yet. Returns the statistics and
  // keeps them in last_snap().
  SnapStats snap_all(std::vector<Point2>& pts) {
    if (!fitted2_) {
      g2_ = IntegerGrid<2>::fit(pts, B2);
      fitted2_ = true;
      grid_points_only2_ = false;  // checked on the old grid
    }
    return last_ = g2_.snap_all(pts);
  }
  SnapStats snap_all(std::vector<Point3>& pts) {
    if (!fitted3_) {
      g3_ = IntegerGrid<3>::fit(pts, B3);
      fitted3_ = true;
      grid_points_only3_ = false;  // checked on the old grid
    }
    return last_ = g3_.snap_all(pts);
  }
  const SnapStats& last_snap() const { return last_; }

  // fit_static_filter(pts): the caller promises that every point it will ask
  // about is one of pts (variants/driver.hpp, as for AdaptiveKernel). Where
  // each of them is a grid point (snap(p) == p, as after snap_all), its
  // coordinates are exactly h times its indices (integer_grid.hpp), so each
  // determinant of them is h^degree > 0 times the integer one and has its
  // sign. Otherwise the kernel stays as it was.
  void fit_static_filter(std::span<const Point2> pts) { grid_points_only2_ = on_grid(g2_, pts); }
  void fit_static_filter(std::span<const Point3> pts) {
    grid_points_only3_ = on_grid(g3_, pts);
    if (grid_points_only3_) first_.fit_static_filter(pts);
  }
  bool grid_points_only(int dim) const { return dim == 2 ? grid_points_only2_ : grid_points_only3_; }
  // The same kernel without that promise (for points a caller makes itself).
  BasicIntegerKernel without_static_filter() const {
    BasicIntegerKernel k = *this;
    k.grid_points_only2_ = k.grid_points_only3_ = false;
    k.first_ = AdaptiveKernel{};
    return k;
  }

  // A floating-point filter (stage 0, "filter") answers before the integer
  // determinant (stage 1, "integer"), as CGAL's Epeck filters first:
  // - on grid points (the promise above): AdaptiveKernel's first stage on the
  //   coordinates (its static orient3d filter fitted to the same points), an
  //   exact sign of their determinant where it answers; and where it does
  //   not, on small integer coordinates, small_integer's error-free
  //   evaluation as the integer stage (grid_stage below);
  // - elsewhere: FloatFilter (predicates/float_filter.hpp) on the index
  //   differences rounded to double, with the base point at the origin. Its
  //   bound assumes of each coordinate difference only |computed - exact| <=
  //   u |computed|, which one rounding of an exact integer gives; the
  //   differences from the origin are the inputs themselves, exactly. So a
  //   sign it decides is the integer determinant's (a zero only when every
  //   difference on an axis is 0). Every nonzero |difference| lies in [1,
  //   2^62), inside each of its range guards: it never declines for range.
  static constexpr std::array<std::string_view, 2> stage_names{"filter", "integer"};
  //
  // incircle_sos_staged / insphere_sos_staged, for perturbed<K>
  // (predicates/perturbed.hpp): the same stages, and where the integer stage
  // finds an exact zero on grid points on its int64 path, the symbolic
  // perturbation's walk on the same reduced indices (intdet::reduced_walk),
  // reported as stage walk_stage (perturbed<K>'s "perturbation"). On
  // lattices a third of the in-sphere tests are such zeros; walking on the
  // points instead re-derives the indices for each orientation. Any other
  // zero is exact and left to perturbed<K>'s own walk.
  static constexpr unsigned char walk_stage = stage_names.size();
  // The budgets of the integer stage's narrow path (intdet::reduced_sign).
  static constexpr int kSmall2 = B2 < 30 ? B2 : 30, kSmall3 = B3 < 24 ? B3 : 24;
  // Their int64 paths, per determinant (intdet::kInt64*).
  static constexpr int kTinyO2 = std::min(kSmall2, intdet::kInt64Orient2d),
                       kTinyIC = std::min(kSmall2, intdet::kInt64InCircle),
                       kTinyO3 = std::min(kSmall3, intdet::kInt64Orient3d),
                       kTinyIS = std::min(kSmall3, intdet::kInt64InSphere);
  static_assert([] {
    for (const auto& s : {filter_bound::orient2d_spec, filter_bound::incircle_spec,
                          filter_bound::orient3d_spec, filter_bound::insphere_spec})
      if (!(s.lo <= 1 && 0x1p62 <= s.hi)) return false;
    return true;
  }());

  Staged orient2d_staged(const Point2& a, const Point2& b, const Point2& c) const {
    constexpr auto det = []<int B>(const auto& q) { return intdet::orient2d<B>(q[0], q[1], q[2]); };
    if (grid_points_only2_)
      return first_then([&](auto rest) { return AdaptiveKernel::orient2d_first_then(a, b, c, rest); },
                        [&](const auto&... x) { return grid_stage<B2, kSmall2, kTinyO2, false>(g2_, det, x...); });
    return filter_then<B2, kSmall2, kTinyO2>(
        [](const auto&... x) { return FloatFilter{}.orient2d(x...); }, det, g2_.index(a), g2_.index(b),
        g2_.index(c));
  }
  Staged incircle_staged(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return incircle_stages<false>(a, b, c, d);
  }
  Staged incircle_sos_staged(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return incircle_stages<true>(a, b, c, d);
  }
  Staged orient3d_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    constexpr auto det = []<int B>(const auto& q) { return intdet::orient3d<B>(q[0], q[1], q[2], q[3]); };
    if (grid_points_only3_)
      return first_then([&](auto rest) { return first_.orient3d_first_then(a, b, c, d, rest); },
                        [&](const auto&... x) { return grid_stage<B3, kSmall3, kTinyO3, false>(g3_, det, x...); });
    return filter_then<B3, kSmall3, kTinyO3>(
        [](const auto&... x) { return FloatFilter{}.orient3d(x...); }, det, g3_.index(a), g3_.index(b),
        g3_.index(c), g3_.index(d));
  }
  Staged insphere_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const {
    return insphere_stages<false>(a, b, c, d, e);
  }
  Staged insphere_sos_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             const Point3& e) const {
    return insphere_stages<true>(a, b, c, d, e);
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

  // The integer determinants alone (stage 1 without the filter), for tests.
  Sign orient2d_exact(const Point2& a, const Point2& b, const Point2& c) const {
    return intdet::sign(intdet::orient2d<B2>(g2_.index(a), g2_.index(b), g2_.index(c)));
  }
  Sign incircle_exact(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return intdet::sign(
        intdet::incircle<B2>(g2_.index(a), g2_.index(b), g2_.index(c), g2_.index(d)));
  }
  Sign orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return intdet::sign(
        intdet::orient3d<B3>(g3_.index(a), g3_.index(b), g3_.index(c), g3_.index(d)));
  }
  Sign insphere_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                      const Point3& e) const {
    return intdet::sign(intdet::insphere<B3>(g3_.index(a), g3_.index(b), g3_.index(c),
                                             g3_.index(d), g3_.index(e)));
  }

  // Coplanar predicates on the 3D grid, which perturbed<K> uses instead of its
  // generic ones (predicates/perturbed.hpp): those ask orient2d about the
  // projections, which this kernel would answer on its 2D grid, and insphere
  // about a point made off the plane, which the 3D box may not hold (points of
  // the plane z = c get a box of height 0; snapping clamps to it).
  Sign projected_orient2d(const Point3& p, const Point3& q, const Point3& r, int axis) const {
    return intdet::sign(
        intdet::projected_orient2d<B3>(g3_.index(p), g3_.index(q), g3_.index(r), axis));
  }
  Sign coplanar_incircle_lifted(const Point3& a, const Point3& b, const Point3& c,
                                const Point3& p, int axis) const {
    return intdet::sign(intdet::coplanar_incircle<B3>(g3_.index(a), g3_.index(b), g3_.index(c),
                                                      g3_.index(p), axis));
  }

 private:
  template <bool Walk>
  Staged incircle_stages(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    constexpr auto det = []<int B>(const auto& q) { return intdet::incircle<B>(q[0], q[1], q[2], q[3]); };
    if (grid_points_only2_)
      return first_then([&](auto rest) { return AdaptiveKernel::incircle_first_then(a, b, c, d, rest); },
                        [&](const auto&... x) { return grid_stage<B2, kSmall2, kTinyIC, Walk>(g2_, det, x...); });
    return filter_then<B2, kSmall2, kTinyIC>(
        [](const auto&... x) { return FloatFilter{}.incircle(x...); }, det, g2_.index(a), g2_.index(b),
        g2_.index(c), g2_.index(d));
  }
  template <bool Walk>
  Staged insphere_stages(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const {
    constexpr auto det = []<int B>(const auto& q) { return intdet::insphere<B>(q[0], q[1], q[2], q[3], q[4]); };
    if (grid_points_only3_)
      return first_then([&](auto rest) { return AdaptiveKernel::insphere_first_then(a, b, c, d, e, rest); },
                        [&](const auto&... x) { return grid_stage<B3, kSmall3, kTinyIS, Walk>(g3_, det, x...); });
    return filter_then<B3, kSmall3, kTinyIS>(
        [](const auto&... x) { return FloatFilter{}.insphere(x...); }, det, g3_.index(a), g3_.index(b),
        g3_.index(c), g3_.index(d), g3_.index(e));
  }

  // The integer stage on grid points x (the base last). Where they are small
  // integers (lattices), small_integer's error-free evaluation answers in its
  // place at a fraction of its cost, with the same answer stage for stage: the
  // coordinates are h = 2^e > 0 times the indices on every axis
  // (integer_grid.hpp), so each determinant's sign, each orientation the
  // walk asks and the points' lexicographic order are the indices'; a nonzero
  // sign is the integer stage's, a zero is walked (Walk) or exact.
  template <int B, int Small, int Tiny, bool Walk, class Grid, class Det, class... P>
  static Staged grid_stage(const Grid& g, Det det, const P&... x) {
    if (const std::optional<Staged> s = small_integer_stage<Walk>(x...)) return *s;
    return integer_stage<B, Small, Tiny, Walk>(det, g.grid_index(x)...);
  }
  // small_integer's answer as the stage that would have given it; nullopt
  // where it does not certify the points. Out of line, as the integer stage.
  static std::optional<Staged> certified(const small_integer::Answer& r) {
    return r.known ? std::optional<Staged>(Staged{r.sign, 1}) : std::nullopt;
  }
  static std::optional<Staged> certified(const small_integer::SosAnswer& r) {
    if (!r.known) return std::nullopt;
    return Staged{r.sign, static_cast<unsigned char>(r.by_perturbation ? walk_stage : 1)};
  }
  template <bool Walk>
  [[gnu::noinline]] static std::optional<Staged> small_integer_stage(const Point2& a, const Point2& b,
                                                                     const Point2& c) {
    static_assert(!Walk);
    if (!small_integer::is_int(c[0])) return std::nullopt;
    return certified(small_integer::orient2d(a, b, c));
  }
  template <bool Walk>
  [[gnu::noinline]] static std::optional<Staged> small_integer_stage(const Point2& a, const Point2& b,
                                                                     const Point2& c, const Point2& d) {
    if (!small_integer::is_int(d[0])) return std::nullopt;
    if constexpr (Walk) return certified(small_integer::incircle_sos(a, b, c, d));
    return certified(small_integer::incircle(a, b, c, d));
  }
  template <bool Walk>
  [[gnu::noinline]] static std::optional<Staged> small_integer_stage(const Point3& a, const Point3& b,
                                                                     const Point3& c, const Point3& d) {
    static_assert(!Walk);
    if (!small_integer::is_int(d[0])) return std::nullopt;
    return certified(small_integer::orient3d(a, b, c, d));
  }
  template <bool Walk>
  [[gnu::noinline]] static std::optional<Staged> small_integer_stage(const Point3& a, const Point3& b,
                                                                     const Point3& c, const Point3& d,
                                                                     const Point3& e) {
    if (!small_integer::is_int(e[0])) return std::nullopt;
    if constexpr (Walk) return certified(small_integer::insphere_sos(a, b, c, d, e));
    return certified(small_integer::insphere(a, b, c, d, e));
  }

  // The integer stage on indices q (the base last). With Walk, an exact zero
  // on the int64 path goes on to the walk on the same reduced indices.
  template <int B, int Small, int Tiny, bool Walk = false, class Det, class... I>
  static Staged integer_stage(Det det, const I&... q) {
    const auto r = intdet::reduce(std::array{q...});
    const Sign s = intdet::reduced_sign<B, Small, Tiny>(r, det);
    if constexpr (Walk)
      if (s == Sign::zero && r.magnitudes != 0 && r.magnitudes < (std::uint64_t{1} << Tiny))
        return {intdet::reduced_walk<Tiny>(r), walk_stage};
    return {s, 1};
  }
  // first(rest): AdaptiveKernel's first stage on grid points, calling rest
  // (the integer stage, on their indices) where it cannot decide.
  template <class First, class Rest>
  static Staged first_then(First first, Rest rest) {
    bool integer = false;
    const Staged s = first([&](const auto&... x) {
      integer = true;
      return rest(x...);
    });
    return {s.sign, static_cast<unsigned char>(integer ? s.stage : 0)};
  }
  // FloatFilter on the rounded index differences, then the integer stage.
  template <int B, int Small, int Tiny, class Filter, class Det, class... I>
  static Staged filter_then(Filter filter, Det det, const I&... q) {
    const std::array indices{q...};
    if (const auto s = std::apply(filter, intdet::rounded_differences(indices))) return {*s, 0};
    return {intdet::reduced_sign<B, Small, Tiny>(indices, det), 1};
  }

  template <class Grid, class P>
  static bool on_grid(const Grid& g, std::span<const P> pts) {
    for (const P& p : pts)
      if (g.snap(p) != p) return false;
    return true;
  }

  IntegerGrid<2> g2_;
  IntegerGrid<3> g3_;
  bool fitted2_ = false, fitted3_ = false;
  bool grid_points_only2_ = false, grid_points_only3_ = false;
  AdaptiveKernel first_;  // the first stages on grid points, fitted with the promise
  SnapStats last_;
};

// The default: the finest grid the 320-bit budget allows (B = 62 in 2D and 3D).
using IntegerKernel = BasicIntegerKernel<62, 62>;
// Every predicate in __int128 (B = 30 in 2D, 24 in 3D).
using IntegerKernel128 = BasicIntegerKernel<30, 24>;

}  // namespace dlab
