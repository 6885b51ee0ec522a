// George's floating circumsphere test (George 1997, section 2.4: "the
// construction of a guest cavity relies in comparing the distance between the
// point and the centre of the examined element with the radius of the
// circumsphere associated with this element"): |p - c|^2 < r^2 in doubles,
// deliberately inexact: the approximate cavity of George's step 2, later
// corrected with exact volumes (algorithms/george.hpp, steps 3-6).
//
// The paper keeps the centres and radii in tables, filled when an element is
// created.  Here each test computes them from the element's vertices with the
// operations that would have filled such a table (circumsphere_of: the
// centre's offset u from vertex 0, then c = v0 + u and r^2 = |u|^2), so every
// answer is the table's bit for bit: an element's vertices never change while
// it lives.  The table cost 24 bytes per slot, and reading it cost more time
// than recomputing (papers/triangulation_costs.md, session 24).
// Degenerate or extreme inputs can make c or r^2 infinite or NaN; a NaN
// comparison answers "outside", an infinite radius "inside": either way the
// correction restores a valid cavity.
//
// Formulas (circumcentre relative to v0; a = v1 - v0, b = v2 - v0, c = v3 - v0):
//   2D: u = ( b_y|a|^2 - a_y|b|^2 , a_x|b|^2 - b_x|a|^2 ) / (2 (a_x b_y - a_y b_x))
//   3D: u = ( |a|^2 (b x c) + |b|^2 (c x a) + |c|^2 (a x b) ) / (2 a.(b x c))
// and r^2 = |u|^2.
#pragma once
#include <array>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "predicates/point.hpp"

namespace dlab {

template <int D>
struct Circumsphere {
  Point<D> centre{};
  double r2 = 0;
};

#if defined(__SSE2__)
// The 3D offset u with the same IEEE operations, in the same order, as the
// plain formula below, two lanes at a time (a packed operation rounds each
// lane as its scalar twin would; no fused multiply-add).  For a vector x
// kept as the pair (x0, x1) and x2: cross(x, y)'s first two components are
// (x1, x2) * (y2, y0) - (x2, x0) * (y1, y2), its third x0 y1 - x1 y0.
inline Point3 circumcentre_offset_sse2(const Point3& o, const Point3& p1, const Point3& p2, const Point3& p3) {
  struct Vec {
    __m128d xy, z;       // (x0, x1), (x2, x2)
    __m128d hi, lo, sw;  // (x1, x2), (x2, x0), (x1, x0)
  };
  const __m128d oxy = _mm_loadu_pd(o.data()), oz = _mm_set1_pd(o[2]);
  auto vec = [&](const Point3& q) {
    Vec x;
    x.xy = _mm_sub_pd(_mm_loadu_pd(q.data()), oxy);
    x.z = _mm_sub_pd(_mm_set1_pd(q[2]), oz);
    x.hi = _mm_unpackhi_pd(x.xy, x.z);
    x.lo = _mm_unpacklo_pd(x.z, x.xy);
    x.sw = _mm_shuffle_pd(x.xy, x.xy, 1);
    return x;
  };
  struct Cross {
    __m128d xy, z;  // z in the low lane
  };
  auto cross = [](const Vec& x, const Vec& y) {
    const __m128d m = _mm_mul_pd(x.xy, y.sw);  // (x0 y1, x1 y0)
    return Cross{_mm_sub_pd(_mm_mul_pd(x.hi, y.lo), _mm_mul_pd(x.lo, y.hi)),
                 _mm_sub_sd(m, _mm_unpackhi_pd(m, m))};
  };
  const Vec a = vec(p1), b = vec(p2), c = vec(p3);
  const Cross bc = cross(b, c), ca = cross(c, a), ab = cross(a, b);
  // (|a|^2, |b|^2) and (|c|^2, a.bc), each ((x0 y0 + x1 y1) + x2 y2).
  auto dot2 = [](__m128d x0, __m128d y0, __m128d x1, __m128d y1, __m128d x2, __m128d y2) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(x0, y0), _mm_mul_pd(x1, y1)), _mm_mul_pd(x2, y2));
  };
  const __m128d ab0 = _mm_unpacklo_pd(a.xy, b.xy), ab1 = _mm_unpackhi_pd(a.xy, b.xy),
                ab2 = _mm_unpacklo_pd(a.z, b.z);
  const __m128d a2b2 = dot2(ab0, ab0, ab1, ab1, ab2, ab2);
  const __m128d c2d = dot2(_mm_unpacklo_pd(c.xy, a.xy), _mm_unpacklo_pd(c.xy, bc.xy), _mm_unpackhi_pd(c.xy, a.xy),
                           _mm_unpackhi_pd(c.xy, bc.xy), _mm_unpacklo_pd(c.z, a.z), _mm_unpacklo_pd(c.z, bc.z));
  const __m128d a2 = _mm_unpacklo_pd(a2b2, a2b2), b2 = _mm_unpackhi_pd(a2b2, a2b2),
                c2 = _mm_unpacklo_pd(c2d, c2d);
  const __m128d dot = _mm_unpackhi_pd(c2d, c2d);
  const __m128d d = _mm_add_pd(dot, dot);  // 2 x: exact, as 2 * x
  auto num = [&](__m128d x, __m128d y, __m128d z) {
    return _mm_add_pd(_mm_add_pd(_mm_mul_pd(a2, x), _mm_mul_pd(b2, y)), _mm_mul_pd(c2, z));
  };
  Point3 u;
  _mm_storeu_pd(u.data(), _mm_div_pd(num(bc.xy, ca.xy, ab.xy), d));
  _mm_store_sd(&u[2], _mm_div_sd(num(bc.z, ca.z, ab.z), d));
  return u;
}
#endif

// The circumcentre relative to v0 (u above), one operation at a time.
template <int D>
Point<D> circumcentre_offset_plain(const std::array<const Point<D>*, D + 1>& v) {
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

template <int D>
Point<D> circumcentre_offset(const std::array<const Point<D>*, D + 1>& v) {
#if defined(__SSE2__)
  if constexpr (D == 3) return circumcentre_offset_sse2(*v[0], *v[1], *v[2], *v[3]);
#endif
  return circumcentre_offset_plain<D>(v);
}

// The sphere of centre c = v0 + u through v0, r^2 = |u|^2.
template <int D>
Circumsphere<D> circumsphere_of(const std::array<const Point<D>*, D + 1>& v) {
  const Point<D> u = circumcentre_offset<D>(v);
  Circumsphere<D> s;
  for (int j = 0; j < D; ++j) {
    s.centre[j] = (*v[0])[j] + u[j];
    s.r2 += u[j] * u[j];  // from 0: the first sum is exact, then left to right
  }
  return s;
}

// George's floating test: p strictly inside the circumsphere of v (the
// element's vertices in slot order).
template <int D>
bool inside_floating_sphere(const std::array<const Point<D>*, D + 1>& v, const Point<D>& p) {
  const Circumsphere<D> s = circumsphere_of<D>(v);
  double d2 = 0;
  for (int j = 0; j < D; ++j) {
    const double t = p[j] - s.centre[j];
    d2 += t * t;
  }
  return d2 < s.r2;
}

}  // namespace dlab
