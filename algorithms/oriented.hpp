// Predicates in the mesh's orientation convention (algorithms/mesh.hpp), on
// top of any kernel that answers in Shewchuk's convention (predicates/kernel.hpp).
//
//   orient_pos(v0..vD)     sign of det[v1-v0; ...; vD-v0]   (positive simplex > 0)
//                          2D: orient2d(a,b,c) has that sign already;
//                          3D: orient3d(a,b,c,d) = det[a-d; b-d; c-d] = -det[b-a; c-a; d-a]
//                          (row operations, then a cyclic row shift), hence the minus.
//   inside_pos(v0..vD, p)  positive iff p is strictly inside the circumsphere of
//                          the positively oriented simplex v0..vD:
//                          2D: incircle(a,b,c,p) (a,b,c counterclockwise);
//                          3D: insphere > 0 means inside only when orient3d > 0,
//                          and orient_pos > 0 means orient3d < 0: hence the minus.
//
// Hull rules for ghost simplices, as CGAL's Delaunay_triangulation_2/3 decide
// conflicts with infinite faces/cells (facts; code written here):
//   2D: the ghost of hull edge (a,b) conflicts with p iff p is strictly on the
//       outer side of line ab, or collinear with a, b and strictly between them.
//   3D: the ghost of hull triangle (a,b,c) conflicts with p iff p is strictly on
//       the outer side of plane abc, or coplanar and inside the circle abc
//       (symbolically perturbed with the `sos` policy: coplanar_incircle).
#pragma once
#include <concepts>

#include "predicates/kernel.hpp"
#include "predicates/perturbed.hpp"

namespace dlab {

template <class K>
Sign orient_pos(const K& k, const Point2& a, const Point2& b, const Point2& c) {
  return k.orient2d(a, b, c);
}
template <class K>
Sign orient_pos(const K& k, const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return -k.orient3d(a, b, c, d);
}

template <class K>
Sign inside_pos(const K& k, const Point2& a, const Point2& b, const Point2& c, const Point2& p) {
  return k.incircle(a, b, c, p);
}
template <class K>
Sign inside_pos(const K& k, const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& p) {
  return -k.insphere(a, b, c, d, p);
}

// Whether p lies strictly between a and b, given that the three are collinear:
// exact, coordinate comparisons only (along x, or along y if ab is vertical).
inline bool strictly_between(const Point2& a, const Point2& p, const Point2& b) {
  const int ax = a[0] != b[0] ? 0 : 1;
  return (a[ax] < p[ax] && p[ax] < b[ax]) || (b[ax] < p[ax] && p[ax] < a[ax]);
}

// 2D hull rule.  (a, b, ghost) is a ghost triangle: p in slot 2 gives a
// positive triangle iff p is outside.
template <class K>
bool ghost_conflict(const K& k, const Point2& a, const Point2& b, const Point2& p) {
  const Sign o = k.orient2d(a, b, p);
  if (o != Sign::zero) return o == Sign::positive;
  return strictly_between(a, p, b);
}

// A kernel that breaks coplanar in-circle ties symbolically (perturbed<K>)
// provides coplanar_incircle(a, b, c, p): positive iff p, coplanar with a, b, c,
// is inside their circle.
template <class K>
concept HasCoplanarIncircle = requires(const K& k, const Point3& p) {
  { k.coplanar_incircle(p, p, p, p) } -> std::convertible_to<Sign>;
};

// 3D hull rule.  (a, b, c, ghost) is a ghost tetrahedron; d is the vertex of
// the finite tetrahedron on the other side of abc (so a, b, c, d is negatively
// oriented in the mesh convention, i.e. orient3d(a,b,c,d) > 0).
template <class K>
bool ghost_conflict(const K& k, const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                    const Point3& p) {
  const Sign o = orient_pos(k, a, b, c, p);
  if (o != Sign::zero) return o == Sign::positive;
  if constexpr (HasCoplanarIncircle<K>) {
    // Exact for every exact K, the integer kernel included (on its 3D grid:
    // predicates/perturbed.hpp, coplanar_incircle_exact).
    return k.coplanar_incircle(a, b, c, p) == Sign::positive;
  } else {
    // Strict policy: the sphere through a, b, c, d meets the plane abc in the
    // circle abc, so for p on that plane "inside circle abc" equals "inside
    // sphere abcd"; orient3d(a,b,c,d) > 0 makes insphere > 0 mean inside.
    return k.insphere(a, b, c, d, p) == Sign::positive;
  }
}

}  // namespace dlab
