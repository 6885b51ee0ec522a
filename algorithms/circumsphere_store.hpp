// Per-element circumcentre and circumradius in doubles, computed once when the
// element is created (George 1997, section 2.4: tables cent(1:3, 1:ne) and
// radii(1:ne); "the construction of a guest cavity relies in comparing the
// distance between the point and the centre of the examined element with the
// radius of the circumsphere associated with this element").
//
// Stored per mesh slot: the centre c and the squared radius r^2 (the same
// information as the radius; comparing squared lengths avoids a square root).
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

template <int D>
Circumsphere<D> circumsphere_of(const std::array<const Point<D>*, D + 1>& v) {
  Circumsphere<D> s;
  const Point<D>& o = *v[0];
  if constexpr (D == 2) {
    const double ax = (*v[1])[0] - o[0], ay = (*v[1])[1] - o[1];
    const double bx = (*v[2])[0] - o[0], by = (*v[2])[1] - o[1];
    const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
    const double d = 2 * (ax * by - ay * bx);
    const double ux = (by * a2 - ay * b2) / d, uy = (ax * b2 - bx * a2) / d;
    s.centre = {o[0] + ux, o[1] + uy};
    s.r2 = ux * ux + uy * uy;
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
    std::array<double, 3> u;
    for (int j = 0; j < 3; ++j) u[j] = (a2 * bc[j] + b2 * ca[j] + c2 * ab[j]) / d;
    s.centre = {o[0] + u[0], o[1] + u[1], o[2] + u[2]};
    s.r2 = dot(u, u);
  }
  return s;
}

// The table, indexed by mesh slot.  Entries of ghost or deleted slots are
// never read.
template <int D>
class CircumsphereStore {
 public:
  void clear() { s_.clear(); }
  void release() { std::vector<Circumsphere<D>>().swap(s_); }  // clear() and give the memory back
  void reserve(std::size_t n) { s_.reserve(n); }
  void set(std::uint32_t slot, const std::array<const Point<D>*, D + 1>& v) {
    if (slot >= s_.size()) s_.resize(std::size_t(slot) + 1);
    s_[slot] = circumsphere_of<D>(v);
  }
  const Circumsphere<D>& operator[](std::uint32_t slot) const { return s_[slot]; }
  // George's floating test: p strictly inside the stored sphere.
  bool inside(std::uint32_t slot, const Point<D>& p) const {
    const Circumsphere<D>& s = s_[slot];
    double d2 = 0;
    for (int j = 0; j < D; ++j) {
      const double t = p[j] - s.centre[j];
      d2 += t * t;
    }
    return d2 < s.r2;
  }
  std::size_t bytes_reserved() const { return s_.capacity() * sizeof(Circumsphere<D>); }

 private:
  std::vector<Circumsphere<D>> s_;
};

}  // namespace dlab
