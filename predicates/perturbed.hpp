// perturbed<K>: symbolic perturbation of the in-circle / in-sphere predicates,
// in the form CGAL's Delaunay_triangulation_2/3 use (Devillers & Teillaud,
// "Perturbations for Delaunay and weighted Delaunay 3D triangulations",
// CGTA 44 (2011)), so that the triangulation is unique and equal to CGAL's.
//
// The perturbation. Only the lifted coordinate is perturbed: point p of
// lexicographic rank r(p) (x, then y, then z; larger rank = larger point) is
// lifted to |p|^2 + eps^(N - r(p)), 0 < eps infinitesimal. Orientation is never
// perturbed. In-circle is the determinant with rows (p, |p|^2, 1); perturbing the
// lift of one row adds eps^k times that row's cofactor, so the perturbed sign is
// the first non-zero among: the exact sign, then the cofactors taken from the
// lexicographically LARGEST point (dominant eps power) downwards. With Shewchuk's
// conventions (predicates/kernel.hpp) the cofactor of row i is
//   query d (resp. e):        -orient(a, b, c)        (-orient3d(a, b, c, d) in 3D)
//   any other point X:         orient(...) of (a, b, c[, d]) with X replaced by the query.
// For a, b, c counterclockwise this is CGAL's walk (DT2::side_of_oriented_circle
// with perturb = true): "largest is the query -> outside; largest is c ->
// orient2d(a,b,d); b -> orient2d(a,d,c); a -> orient2d(d,b,c)". In 3D, CGAL's
// side_of_oriented_sphere is -insphere and its orientation is -orient3d, so
// CGAL's "p3 -> orientation(p0,p1,p2,p)" becomes orient3d(a,b,c,e) here, etc.
// The formula is a polynomial identity (each coefficient is a cofactor of one
// determinant), so it needs no precondition on the orientation of a, b, c[, d]
// and stays antisymmetric under permutations. (CGAL 5.5's 2D function answers
// "outside" for the query even when a, b, c are clockwise, which its
// triangulation never asks; on counterclockwise a, b, c the two agree.)
// The coefficients are the orientations of all D+2 subsets of D+1 points, so
// the answer is zero only if all the points lie on one line (plane): never for
// non-collinear a, b, c (non-coplanar a, b, c, d). For distinct points the
// walk decides within the first 2 points, as CGAL 5.5 asserts.
//
// coplanar_incircle(a, b, c, p): CGAL's coplanar_side_of_bounded_circle with
// perturbation, used on the 3D convex hull: an UNORIENTED answer (positive = p
// inside the circle through a, b, c), for p coplanar with non-collinear a, b, c.
// Exact part: any sphere through a, b, c meets their plane in their circle, so
// with s = a moved along a coordinate axis not parallel to the plane (s is a
// double, off the plane), p is inside the circle iff it is inside sphere abcs:
// sign = insphere(a, b, c, s, p) * orient3d(a, b, c, s), both exact (for K =
// adaptive the small-integer path answers with its exact sign here, not its
// perturbed one). A kernel that cannot represent s (integer: its box may be
// flat) provides projected_orient2d and coplanar_incircle_lifted, used instead
// of orient2d on the projections and of s. On zero, the 2D walk
// in the plane (coplanar_orientation as the plane's orientation), normalised by
// local = coplanar_orientation(a, b, c), over the three largest points; if
// nothing decides (impossible for distinct points) -local, as CGAL 5.5 does.
//
// collinear_between(p, q, r): q strictly between p and r, for collinear points:
// lexicographic order is monotone along a line, so p < q < r or r < q < p.
//
// K must be exact for the answers to mean anything (perturbing an inexact
// zero is meaningless); perturbed<K> never changes a non-zero answer of K.
//
// Lattices: for K = adaptive, when K's inline first stage (its filter) cannot
// decide, every predicate tries the error-free small-integer evaluation of
// predicates/small_integer.hpp (all coordinates integers, all differences
// small: the determinant computed in doubles is exact) before K's remaining
// stages. When it applies, its sign is the answer -- reported as K's stage 0
// ("filter") when non-zero -- and an exact zero is settled by the same walk on
// the same certificate (small_integer::incircle_sos / insphere_sos, counted as
// "perturbation"), without the expansion arithmetic that stages B-D would
// spend proving the zero (on a 3D grid a third of all in-sphere tests are such
// zeros). Same answers (both are exact signs; tests/test_small_integer.cpp
// compares with perturbed<MpKernel>). On other inputs the certificate fails at
// the reference point's x and y and K answers as before.
// Other kernels keep their own arithmetic (mp is the reference; integer answers
// for its snapped points, and takes the walk on its own grid indices where it
// can: K::insphere_sos_staged, integer_kernel.hpp), so kernel comparisons stay fair.
#pragma once
#include <array>
#include <cmath>
#include <limits>
#include <type_traits>
#include <utility>

#include "predicates/kernel.hpp"
#include "predicates/small_integer.hpp"
#include "predicates/sos_walk.hpp"
#include "predicates/stages.hpp"

namespace dlab {

struct AdaptiveKernel;  // predicates/adaptive_kernel.hpp

// Exact: q strictly between p and r, given that p, q, r are collinear.
template <int D>
constexpr bool collinear_between(const Point<D>& p, const Point<D>& q, const Point<D>& r) {
  return (lex_less<D>(p, q) && lex_less<D>(q, r)) || (lex_less<D>(r, q) && lex_less<D>(q, p));
}

template <class K>
struct perturbed {
  static constexpr bool exact = K::exact;
  static constexpr bool symbolic = true;  // answers are those of the perturbed points
  static constexpr std::string_view name = K::name;

  // Stages: those of K (or K's name), then "perturbation" (the exact answer was
  // zero and the symbolic walk decided).
  static constexpr std::size_t perturbation_stage = stage_count<K>();
  static constexpr std::array<std::string_view, stage_count<K>() + 1> stage_names = [] {
    std::array<std::string_view, stage_count<K>() + 1> out{};
    const auto base = stage_names_of<K>();
    for (std::size_t i = 0; i < base.size(); ++i) out[i] = base[i];
    out[base.size()] = "perturbation";
    return out;
  }();

  K base;

  perturbed() = default;
  explicit perturbed(const K& k) : base(k) {}

  // ---- 2D ----
  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<K>
  {
    return orient2d_base(a, b, c).sign;
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const
    requires Kernel2<K>
  {
    return incircle_staged(a, b, c, d).sign;
  }
  // The symbolic part alone (valid when the exact in-circle is zero).
  Sign incircle_perturbation(const Point2& a, const Point2& b, const Point2& c,
                             const Point2& d) const
    requires Kernel2<K>
  {
    return sos::walk<2>({&a, &b, &c, &d}, [this](const std::array<const Point2*, 3>& t) {
      return orient2d_base(*t[0], *t[1], *t[2]).sign;
    });
  }

  // ---- 3D ----
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const
    requires Kernel3<K>
  {
    return orient3d_base(a, b, c, d).sign;
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const
    requires Kernel3<K>
  {
    return insphere_staged(a, b, c, d, e).sign;
  }
  Sign insphere_perturbation(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                             const Point3& e) const
    requires Kernel3<K>
  {
    return sos::walk<3>({&a, &b, &c, &d, &e}, [this](const std::array<const Point3*, 4>& t) {
      return orient3d_base(*t[0], *t[1], *t[2], *t[3]).sign;
    });
  }

  // Orientation of p, q, r inside their plane: the 2D orientation of the
  // projection onto the first of the xy, yz, xz planes where it is not zero
  // (CGAL's coplanar_orientation order). For points of one plane the first
  // non-degenerate projection is the same for every non-collinear triple, so
  // the answers are consistent within the plane. Zero iff p, q, r collinear.
  Sign coplanar_orientation(const Point3& p, const Point3& q, const Point3& r) const
    requires Kernel3<K> && Kernel2<K>
  {
    return coplanar_orientation_axis(p, q, r).first;
  }

  // Exact (unperturbed) unoriented in-circle for coplanar points: positive when
  // p is inside the circle through a, b, c (a, b, c not collinear).
  Sign coplanar_incircle_exact(const Point3& a, const Point3& b, const Point3& c,
                               const Point3& p) const
    requires Kernel3<K> && Kernel2<K>
  {
    const auto [o, axis] = coplanar_orientation_axis(a, b, c);
    if (o == Sign::zero) return Sign::zero;  // a, b, c collinear: precondition violated
    if constexpr (projecting) return base.coplanar_incircle_lifted(a, b, c, p, axis) * o;
    // The projection along `axis` is non-degenerate, so the plane's normal has a
    // non-zero component on `axis` and s = a + t e_axis (t != 0) is off the plane.
    const Point3 s = off_plane(a, b, c, p, axis);
    const perturbed k = without_static_filter();  // s is made here: see below
    return k.insphere_base(a, b, c, s, p).sign * k.orient3d_base(a, b, c, s).sign;
  }

  // Perturbed unoriented in-circle (CGAL's coplanar_side_of_bounded_circle with
  // perturb = true): never zero for p distinct from non-collinear a, b, c.
  Sign coplanar_incircle(const Point3& a, const Point3& b, const Point3& c, const Point3& p) const
    requires Kernel3<K> && Kernel2<K>
  {
    const Sign s = coplanar_incircle_exact(a, b, c, p);
    if (s != Sign::zero) return s;
    const Sign local = coplanar_orientation(a, b, c);
    const std::array<const Point3*, 4> pts{&a, &b, &c, &p};
    const auto order = sos::by_decreasing_rank<3, 4>(pts);
    for (int k = 0; k < 3; ++k) {  // the three largest points, as CGAL
      Sign o = Sign::zero;
      switch (order[k]) {
        case 3: return Sign::negative;  // p itself: outside
        case 2: o = coplanar_orientation(a, b, p); break;
        case 1: o = coplanar_orientation(a, p, c); break;
        case 0: o = coplanar_orientation(p, b, c); break;
      }
      if (o != Sign::zero) return o * local;
    }
    return -local;  // unreachable for distinct points; CGAL 5.5's value
  }

  // A kernel fitted to the input (a static filter, AdaptiveKernel::fit_static_filter)
  // only covers points near it; the off-plane point made above may be farther, so
  // that call goes to K without its static filter.
  perturbed without_static_filter() const {
    if constexpr (requires { base.without_static_filter(); })
      return perturbed(base.without_static_filter());
    else
      return *this;
  }

  // Snapping kernels (integer) snap as K does; the perturbation then orders
  // the snapped points.
  template <class Points>
  auto snap_all(Points& pts)
    requires requires(K& k) { k.snap_all(pts); }
  {
    return base.snap_all(pts);
  }

  // ---- staged interface (for counted<>) ----
  Staged orient2d_staged(const Point2& a, const Point2& b, const Point2& c) const
    requires Kernel2<K>
  {
    return orient2d_base(a, b, c);
  }
  Staged incircle_staged(const Point2& a, const Point2& b, const Point2& c,
                         const Point2& d) const
    requires Kernel2<K>
  {
    Staged s;
    if constexpr (lattice) {  // exact sign and perturbation in one go (small_integer.hpp)
      s = base.incircle_first_then(a, b, c, d,
                                 [](const auto&... p) { return incircle_lattice(p...); });
    } else if constexpr (walks_itself2) {
      s = base.incircle_sos_staged(a, b, c, d);
    } else {
      s = dlab::incircle_staged(base, a, b, c, d);
    }
    if (s.sign != Sign::zero) return s;
    return {incircle_perturbation(a, b, c, d), static_cast<unsigned char>(perturbation_stage)};
  }
  Staged orient3d_staged(const Point3& a, const Point3& b, const Point3& c,
                         const Point3& d) const
    requires Kernel3<K>
  {
    return orient3d_base(a, b, c, d);
  }
  Staged insphere_staged(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const
    requires Kernel3<K>
  {
    Staged s;
    if constexpr (lattice) {
      s = base.insphere_first_then(a, b, c, d, e,
                                 [](const auto&... p) { return insphere_lattice(p...); });
    } else if constexpr (walks_itself3) {
      s = base.insphere_sos_staged(a, b, c, d, e);
    } else {
      s = dlab::insphere_staged(base, a, b, c, d, e);
    }
    if (s.sign != Sign::zero) return s;
    return {insphere_perturbation(a, b, c, d, e), static_cast<unsigned char>(perturbation_stage)};
  }

 private:
  // Kernels exact for every double input, for which the small-integer
  // evaluation may answer in K's place (see the top of this file).
  static constexpr bool lattice = std::is_same_v<K, AdaptiveKernel>;
  // Kernels that take the walk on their own representation of the points
  // where they can (integer: on grid indices, see integer_kernel.hpp): their
  // stage walk_stage is the walk's answer, and any zero they return is exact.
  static constexpr bool walks_itself2 = requires(const K& k, const Point2& p) {
    { k.incircle_sos_staged(p, p, p, p) } -> std::same_as<Staged>;
  };
  static constexpr bool walks_itself3 = requires(const K& k, const Point3& p) {
    { k.insphere_sos_staged(p, p, p, p, p) } -> std::same_as<Staged>;
  };
  static_assert([] {
    if constexpr (walks_itself2 || walks_itself3) return K::walk_stage == perturbation_stage;
    return true;
  }());
  // Kernels with their own coplanar predicates (integer: see integer_kernel.hpp).
  static constexpr bool projecting = requires(const K& k, const Point3& p) {
    { k.projected_orient2d(p, p, p, 0) } -> std::same_as<Sign>;
    { k.coplanar_incircle_lifted(p, p, p, p, 0) } -> std::same_as<Sign>;
  };

  // When K's first stage cannot decide: the small-integer evaluation, then K's
  // remaining stages. Out of line, so that the inline path stays K's first stage
  // alone. A non-zero small-integer sign is reported as K's stage 0, a sign settled
  // by the walk (*_sos) as the perturbation stage.
  [[gnu::noinline]] static Staged orient2d_lattice(const Point2& a, const Point2& b,
                                                   const Point2& c) {
    if (small_integer::is_int(c[0])) {
      const small_integer::Answer r = small_integer::orient2d(a, b, c);
      if (r.known) return {r.sign, 0};
    }
    return K::orient2d_rest(a, b, c);
  }
  [[gnu::noinline]] static Staged incircle_lattice(const Point2& a, const Point2& b,
                                                   const Point2& c, const Point2& d) {
    if (small_integer::is_int(d[0])) {
      const small_integer::SosAnswer r = small_integer::incircle_sos(a, b, c, d);
      if (r.known) return sos_staged(r);
    }
    return K::incircle_rest(a, b, c, d);
  }
  [[gnu::noinline]] static Staged orient3d_lattice(const Point3& a, const Point3& b,
                                                   const Point3& c, const Point3& d) {
    if (small_integer::is_int(d[0])) {
      const small_integer::Answer r = small_integer::orient3d(a, b, c, d);
      if (r.known) return {r.sign, 0};
    }
    return K::orient3d_rest(a, b, c, d);
  }
  [[gnu::noinline]] static Staged insphere_lattice(const Point3& a, const Point3& b,
                                                   const Point3& c, const Point3& d,
                                                   const Point3& e) {
    if (small_integer::is_int(e[0])) {
      const small_integer::SosAnswer r = small_integer::insphere_sos(a, b, c, d, e);
      if (r.known) return sos_staged(r);
    }
    return K::insphere_rest(a, b, c, d, e);
  }
  [[gnu::noinline]] static Staged insphere_lattice_exact(const Point3& a, const Point3& b,
                                                         const Point3& c, const Point3& d,
                                                         const Point3& e) {
    if (small_integer::is_int(e[0])) {
      const small_integer::Answer r = small_integer::insphere(a, b, c, d, e);
      if (r.known) return {r.sign, 0};
    }
    return K::insphere_rest(a, b, c, d, e);
  }
  static Staged sos_staged(const small_integer::SosAnswer& r) {
    return {r.sign, static_cast<unsigned char>(r.by_perturbation ? perturbation_stage : 0)};
  }

  // K's exact sign and stage, from the small-integer evaluation when it applies.
  Staged orient2d_base(const Point2& a, const Point2& b, const Point2& c) const {
    if constexpr (lattice)
      return base.orient2d_first_then(a, b, c,
                                  [](const auto&... p) { return orient2d_lattice(p...); });
    return dlab::orient2d_staged(base, a, b, c);
  }
  Staged orient3d_base(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    if constexpr (lattice)
      return base.orient3d_first_then(a, b, c, d,
                                      [](const auto&... p) { return orient3d_lattice(p...); });
    return dlab::orient3d_staged(base, a, b, c, d);
  }
  // The exact in-sphere sign (zero included): small_integer::insphere, not
  // insphere_sos, whose answer on a zero is already the perturbed one.
  Staged insphere_base(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                       const Point3& e) const {
    if constexpr (lattice)
      return base.insphere_first_then(a, b, c, d, e,
                                  [](const auto&... p) { return insphere_lattice_exact(p...); });
    return dlab::insphere_staged(base, a, b, c, d, e);
  }

  // {orientation, axis dropped by the projection}: xy drops z (2), yz drops x (0),
  // xz drops y (1).
  std::pair<Sign, int> coplanar_orientation_axis(const Point3& p, const Point3& q,
                                                 const Point3& r) const {
    if constexpr (projecting) {
      for (const int axis : {2, 0, 1})
        if (const Sign o = base.projected_orient2d(p, q, r, axis); o != Sign::zero) return {o, axis};
      return {Sign::zero, 1};
    }
    Sign o = orient2d_base({p[0], p[1]}, {q[0], q[1]}, {r[0], r[1]}).sign;
    if (o != Sign::zero) return {o, 2};
    o = orient2d_base({p[1], p[2]}, {q[1], q[2]}, {r[1], r[2]}).sign;
    if (o != Sign::zero) return {o, 0};
    return {orient2d_base({p[0], p[2]}, {q[0], q[2]}, {r[0], r[2]}).sign, 1};
  }

  // a with coordinate `axis` replaced by a different finite double, preferably
  // about as far as the points' spread (better conditioned for filters).
  static Point3 off_plane(const Point3& a, const Point3& b, const Point3& c, const Point3& p,
                          int axis) {
    double w = 0;
    for (const Point3* q : {&b, &c, &p})
      for (int i = 0; i < 3; ++i) w = std::fmax(w, std::fabs((*q)[i] - a[i]));
    const double x = a[axis];
    const double inf = std::numeric_limits<double>::infinity();
    for (const double t : {x + w, x - w, std::nextafter(x, inf), std::nextafter(x, -inf)})
      if (std::isfinite(t) && t != x) {
        Point3 s = a;
        s[axis] = t;
        return s;
      }
    return a;  // unreachable for finite a: one of the nextafter values is finite
  }
};

}  // namespace dlab
