// Enclosures of the smallest sphere through D points (2D: two points, the
// disc on their segment; 3D: three, the sphere on the triangle's
// circumcircle), from enclosures of their scaled coordinates, for Tanemura's
// pruning (algorithms/tanemura.hpp): the centre of the pencil of spheres
// through a facet, and the trace of a sphere on a flat of points (through D
// of its points, or from the sphere itself: hyperplane_trace).
//
// With u = q1 - q0 (2D: the centre is q0 + u / 2) and in 3D v = q2 - q0 and
// n = u x v, the centre is q0 + ((|u|^2 v - |v|^2 u) x n) / (2 |n|^2), the
// circumcentre of a triangle in space (Schneider & Eberly, Geometric Tools for
// Computer Graphics, 2003, §13.1). Interval arithmetic throughout
// (algorithms/interval.hpp): an unbounded result (a degenerate triangle, an
// overflow) shows in offset or r2 as !bounded().
#pragma once
#include <array>

#include "algorithms/interval.hpp"

namespace dlab {

template <int D>
struct Circumball {
  std::array<Iv, D> offset;  // centre - q0
  Iv r2;                     // squared radius = |offset|^2
};

template <int D>
using IvPoint = std::array<Iv, D>;

inline IvPoint<3> cross(const IvPoint<3>& x, const IvPoint<3>& y) {
  return {x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]};
}

// q: the points; n and nn (3D only): enclosures of (q1 - q0) x (q2 - q0),
// which a caller may have computed more tightly (Tanemura's facet normal),
// and of its squared norm.
template <int D>
Circumball<D> circumball(const std::array<IvPoint<D>, D>& q, const IvPoint<D>& n, Iv nn) {
  Circumball<D> b;
  if constexpr (D == 2) {
    for (int i = 0; i < 2; ++i) b.offset[i] = (q[1][i] - q[0][i]) * Iv{0.5, 0.5};
  } else {
    IvPoint<3> u, v;
    for (int i = 0; i < 3; ++i) u[i] = q[1][i] - q[0][i], v[i] = q[2][i] - q[0][i];
    const Iv uu = sq(u[0]) + sq(u[1]) + sq(u[2]), vv = sq(v[0]) + sq(v[1]) + sq(v[2]);
    const auto vn = cross(v, n), nu = cross(n, u);
    const Iv two_nn = nn + nn;
    for (int i = 0; i < 3; ++i) b.offset[i] = (uu * vn[i] + vv * nu[i]) / two_nn;
  }
  b.r2 = Iv{0, 0};
  for (int i = 0; i < D; ++i) b.r2 = b.r2 + sq(b.offset[i]);
  return b;
}

template <int D>
Circumball<D> circumball(const std::array<IvPoint<D>, D>& q, const IvPoint<D>& n) {
  Iv nn{0, 0};
  for (int i = 0; i < D; ++i) nn = nn + sq(n[i]);
  return circumball<D>(q, n, nn);
}

// The trace of a sphere on a hyperplane: with the sphere's centre in c and
// its squared radius at most r2, and the hyperplane through `at` with a
// normal in n (nn: an enclosure of |n|^2), a point x of the hyperplane is
// inside the sphere iff |x - c'|^2 <= r2 - d^2, where c' = c - (s / |n|^2) n
// is c's projection and d^2 = s^2 / |n|^2 its squared distance, s = (c -
// at).n (Pythagoras, as x - c' is orthogonal to n). In interval arithmetic,
// so the result encloses c' and bounds the squared radius above (r2 below 0:
// the sphere misses the hyperplane). Far from the sphere's scale (R^2 much
// larger than the trace's) the subtraction keeps R^2's rounding, about
// 2^-51 R^2: callers compare the result with R^2 to see whether it is worth
// using.
template <int D>
struct Trace {
  std::array<Iv, D> centre;
  Iv r2;  // upper end: a bound of the trace's squared radius (unbounded: NaN or infinite)
};

template <int D>
Trace<D> hyperplane_trace(const IvPoint<D>& c, double r2, const IvPoint<D>& at, const IvPoint<D>& n, Iv nn) {
  Iv s{0, 0};
  for (int i = 0; i < D; ++i) s = s + (c[i] - at[i]) * n[i];
  const Iv k = s / nn;
  Trace<D> t;
  for (int i = 0; i < D; ++i) t.centre[i] = c[i] - k * n[i];
  t.r2 = Iv::exact(r2) - sq(s) / nn;
  return t;
}

}  // namespace dlab
