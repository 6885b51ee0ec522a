// Per-element circumcentre and circumradius in doubles, computed once when the
// element is created (George 1997, section 2.4: tables cent(1:3, 1:ne) and
// radii(1:ne); "the construction of a guest cavity relies in comparing the
// distance between the point and the centre of the examined element with the
// radius of the circumsphere associated with this element").
//
// Stored per mesh slot: the centre's offset u from the element's vertex 0
// (below), from which the test rebuilds the centre c = v0 + u and the squared
// radius r^2 = |u|^2 with the very operations that would have made a table of
// c and r^2 (circumsphere_of), so its answers are those of such a table bit
// for bit, at D doubles per slot instead of D + 1 (3D: 54 bytes per point
// less; comparing squared lengths avoids a square root).
// The floating test is |p - c|^2 < r^2, deliberately inexact: it is the
// approximate cavity of George's step 2, later corrected with exact volumes.
// Degenerate or extreme inputs can make c or r^2 infinite or NaN; a NaN
// comparison answers "outside", an infinite radius "inside": either way the
// correction (algorithms/george_correction.hpp) restores a valid cavity.
//
// Formulas (circumcentre relative to v0; a = v1 - v0, b = v2 - v0, c = v3 - v0):
//   2D: u = ( b_y|a|^2 - a_y|b|^2 , a_x|b|^2 - b_x|a|^2 ) / (2 (a_x b_y - a_y b_x))
//   3D: u = ( |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b) ) / (2 a.(b x c))
// and r^2 = |u|^2.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

template <int D>
struct Circumsphere {
  Point<D> centre{};
  double r2 = 0;
};

// The circumcentre relative to v0 (u above).
template <int D>
Point<D> circumcentre_offset(const std::array<const Point<D>*, D + 1>& v) {
  const Point<D>& o = *v[0];
  if constexpr (D == 2) {
    const double ax = (*v[1])[0] - o[0], ay = (*v[1])[1] - o[1];
    const double bx = (*v[2])[0] - o[0], by = (*v[2])[1] - o[1];
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    const double d = 2 * (ax * by - ay * bx);
    return {(by * a2 - ay * b2) / d, (ax * b2 - bx * a2) / d};
  } else {
    std::array<double, 3> a, b, c;
    for (int j = 0; j < 3; ++j) {
      a[j] = (*v[1])[j] - o[j];
      b[j] = (*v[2])[j] - o[j];
      c[j] = (*v[3])[j] - o[j];
    }
    auto cross = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
      return std::array<double, 3>{x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2],
                                   x[0] * y[1] - x[1] * y[0]};
    };
    auto dot = [](const std::array<double, 3>& x, const std::array<double, 3>& y) {
      return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
    };
    const auto bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
    const double a2 = dot(a, a), b2 = dot(b, b), c2 = dot(c, c);
    const double d = 2 * dot(a, bc);
    Point<D> u;
    for (int j = 0; j < 3; ++j) u[j] = (a2 * bc[j] + b2 * ca[j] + c2 * ab[j]) / d;
    return u;
  }
}

// The sphere of centre o + u through o.
template <int D>
Circumsphere<D> sphere_at_offset(const Point<D>& o, const Point<D>& u) {
  Circumsphere<D> s;
  for (int j = 0; j < D; ++j) {
    s.centre[j] = o[j] + u[j];
    s.r2 += u[j] * u[j];  // from 0: the first sum is exact, then left to right
  }
  return s;
}

template <int D>
Circumsphere<D> circumsphere_of(const std::array<const Point<D>*, D + 1>& v) {
  return sphere_at_offset<D>(*v[0], circumcentre_offset<D>(v));
}

// The table, indexed by mesh slot.  Entries of ghost or deleted slots are
// never read.
template <int D>
class CircumsphereStore {
 public:
  void clear() { u_.clear(); }
  void release() { std::vector<Point<D>>().swap(u_); }  // clear() and give the memory back
  void reserve(std::size_t n) { u_.reserve(n); }
  // The sphere of the element in `slot` with vertices v (in slot order).
  void set(std::uint32_t slot, const std::array<const Point<D>*, D + 1>& v) {
    if (slot >= u_.size()) u_.resize(std::size_t(slot) + 1);
    u_[slot] = circumcentre_offset<D>(v);
  }
  // George's floating test: p strictly inside the sphere stored for `slot`,
  // whose vertex 0 is v0 (as when it was set).
  bool inside(std::uint32_t slot, const Point<D>& v0, const Point<D>& p) const {
    const Circumsphere<D> s = sphere_at_offset<D>(v0, u_[slot]);
    double d2 = 0;
    for (int j = 0; j < D; ++j) {
      const double t = p[j] - s.centre[j];
      d2 += t * t;
    }
    return d2 < s.r2;
  }
  std::size_t bytes_reserved() const { return u_.capacity() * sizeof(Point<D>); }

 private:
  std::vector<Point<D>> u_;
};

}  // namespace dlab
