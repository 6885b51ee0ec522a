// algorithms/circumball.hpp: the enclosures of the smallest sphere through D
// points contain the exact centre and squared radius, checked in rational
// arithmetic against the centre solved independently (Cramer's rule on the
// equidistance equations, in 3D with the triangle's plane), on every scale
// from 2^-1050 to 2^1024, both signs, skinny triangles (one vertex an ulp off
// the line of the other two) and near-duplicate vertices.
// algorithms/box_ball.hpp: with those enclosures and prune_r2's slack, a
// point exactly on the sphere is never pruned (the fourth corner of a
// rectangle in an oblique plane; in 2D the segment's own ends).
// hyperplane_trace: the trace of a sphere on a line or plane encloses the
// exact projection of its centre and bounds R^2 - d^2, for spheres up to
// 2^45 times their distance to it, and keeps a point on both.
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "algorithms/box_ball.hpp"
#include "algorithms/circumball.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;

bool encloses(const Iv& x, const Q& v) {
  return x.bounded() && Q(x.lo) <= v && v <= Q(x.hi);
}

// The solution x of a x = rhs (Cramer's rule; a regular).
std::array<Q, 3> cramer3(const std::array<std::array<Q, 3>, 3>& a, const std::array<Q, 3>& rhs) {
  const auto det3 = [](const std::array<std::array<Q, 3>, 3>& m) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const Q d = det3(a);
  std::array<Q, 3> x;
  for (int k = 0; k < 3; ++k) {
    auto m = a;
    for (int r = 0; r < 3; ++r) m[r][k] = rhs[r];
    x[k] = det3(m) / d;
  }
  return x;
}

// The exact centre c of the smallest sphere through q (rational), from
// (c - q0).(qj - q0) = |qj - q0|^2 / 2 for j >= 1 and, in 3D, (c - q0).n = 0.
template <int D>
std::array<Q, D> exact_centre(const std::array<std::array<double, D>, D>& q) {
  std::array<std::array<Q, D>, D> a;  // rows: the equations' normals
  std::array<Q, D> rhs;
  for (int j = 1; j < D; ++j) {
    Q n2 = 0;
    for (int i = 0; i < D; ++i) {
      a[j - 1][i] = Q(q[j][i]) - Q(q[0][i]);
      n2 += a[j - 1][i] * a[j - 1][i];
    }
    rhs[j - 1] = n2 / 2;
  }
  if constexpr (D == 2) {
    // The centre lies on the segment: c - q0 = t (q1 - q0), t = 1/2.
    return {(Q(q[0][0]) + Q(q[1][0])) / 2, (Q(q[0][1]) + Q(q[1][1])) / 2};
  } else {
    const auto& u = a[0];
    const auto& v = a[1];
    a[2] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    rhs[2] = 0;
    const std::array<Q, 3> x = cramer3(a, rhs);
    return {Q(q[0][0]) + x[0], Q(q[0][1]) + x[1], Q(q[0][2]) + x[2]};
  }
}

bool collinear(const std::array<std::array<double, 3>, 3>& q) {
  std::array<Q, 3> u, v;
  for (int i = 0; i < 3; ++i) u[i] = Q(q[1][i]) - Q(q[0][i]), v[i] = Q(q[2][i]) - Q(q[0][i]);
  return u[1] * v[2] == u[2] * v[1] && u[2] * v[0] == u[0] * v[2] && u[0] * v[1] == u[1] * v[0];
}

// Checks circumball's enclosures of the points q; false if it gave up
// (unbounded), which it may only do for a degenerate or overflowing input.
template <int D>
bool check(const std::array<std::array<double, D>, D>& q) {
  std::array<IvPoint<D>, D> qi;
  for (int j = 0; j < D; ++j)
    for (int i = 0; i < D; ++i) qi[j][i] = Iv::exact(q[j][i]);
  IvPoint<D> n{};
  if constexpr (D == 3) {
    IvPoint<3> u, v;
    for (int i = 0; i < 3; ++i) u[i] = qi[1][i] - qi[0][i], v[i] = qi[2][i] - qi[0][i];
    n = cross(u, v);
  }
  const Circumball<D> b = circumball<D>(qi, n);
  for (int i = 0; i < D; ++i)
    if (!b.offset[i].bounded()) return false;
  if (!b.r2.bounded()) return false;
  const std::array<Q, D> c = exact_centre<D>(q);
  Q r2 = 0;
  for (int i = 0; i < D; ++i) {
    const Q off = c[i] - Q(q[0][i]);
    RC_ASSERT(encloses(b.offset[i], off));
    r2 += off * off;
  }
  RC_ASSERT(encloses(b.r2, r2));
  return true;
}

// A coordinate m 2^e, m in (-1, 1) with a few random bits, e in [lo, hi].
double coordinate(int lo, int hi) {
  const auto m = *rc::gen::inRange<std::int64_t>(-(1 << 20), 1 << 20);
  return std::ldexp(static_cast<double>(m) / (1 << 20), *rc::gen::inRange(lo, hi + 1));
}

// D points whose coordinates have binades in [e - 8, e], e drawn from [lo, hi].
template <int D>
std::array<std::array<double, D>, D> points_near_binade(int lo, int hi) {
  const int e = *rc::gen::inRange(lo, hi);
  std::array<std::array<double, D>, D> q;
  for (auto& p : q)
    for (double& x : p) x = coordinate(e - 8, e);
  return q;
}

// Rectangles p, p + a, p + b, p + a + b with a . b = 0 are cocircular:
// a = (1, 2, 2) k, b = (2, 1, -2) l (a x b = (-6, 6, -3) k l), p and k, l
// random integers, the corners scaled by 2^e, e in [lo, hi] (exact: the
// integers are below 2^53).
struct Rectangle {
  std::array<std::array<double, 3>, 4> q;  // p, p + a, p + b, p + a + b
  double side;                             // max(k, l) 2^e
};
Rectangle random_rectangle(int lo, int hi) {
  const int e = *rc::gen::inRange(lo, hi);
  const auto k = static_cast<double>(*rc::gen::inRange(1, 1 << 20));
  const auto l = static_cast<double>(*rc::gen::inRange(1, 1 << 20));
  std::array<double, 3> p;
  for (double& x : p) x = static_cast<double>(*rc::gen::inRange(-(1 << 24), 1 << 24));
  const std::array<double, 3> a{k, 2 * k, 2 * k}, b{2 * l, l, -2 * l};
  Rectangle r;
  for (int i = 0; i < 3; ++i) {
    r.q[0][i] = std::ldexp(p[i], e);
    r.q[1][i] = std::ldexp(p[i] + a[i], e);
    r.q[2][i] = std::ldexp(p[i] + b[i], e);
    r.q[3][i] = std::ldexp(p[i] + a[i] + b[i], e);
  }
  r.side = std::ldexp(std::max(k, l), e);
  return r;
}

}  // namespace

TEST_CASE("circumball: enclosures contain the exact centre and radius (rational)", "[circumball]") {
  rc::prop("2D, every scale", [] {
    const auto q = points_near_binade<2>(-500, 500);
    RC_PRE(q[0] != q[1]);
    RC_ASSERT(check<2>(q));
  });
  rc::prop("3D, scales where the numerators, ~2^(5e), are normal doubles: bounded", [] {
    const auto q = points_near_binade<3>(-195, 195);
    RC_PRE(!collinear(q));
    RC_ASSERT(check<3>(q));
  });
  rc::prop("3D, every scale: sound where bounded", [] {
    check<3>(points_near_binade<3>(-1050, 1024));
  });
  rc::prop("3D skinny: the third vertex an ulp off the others' line", [] {
    const int e = *rc::gen::inRange(-195, 195);
    std::array<std::array<double, 3>, 3> q;
    for (int i = 0; i < 3; ++i) q[0][i] = coordinate(e - 4, e), q[1][i] = coordinate(e - 4, e);
    const int k = *rc::gen::inRange(1, 1000);
    for (int i = 0; i < 3; ++i) q[2][i] = q[0][i] + (q[1][i] - q[0][i]) * k / 1000;  // near the line
    const int axis = *rc::gen::inRange(0, 3);
    q[2][axis] = std::nextafter(q[2][axis], 1e300);
    check<3>(q);
  });
  rc::prop("3D near-duplicates: two vertices a few ulps apart", [] {
    const int e = *rc::gen::inRange(-195, 195);
    std::array<std::array<double, 3>, 3> q;
    for (int i = 0; i < 3; ++i) q[0][i] = coordinate(e - 4, e), q[2][i] = coordinate(e - 4, e);
    q[1] = q[0];
    for (double& x : q[1]) x = std::nextafter(std::nextafter(x, 1e300), 1e300);
    check<3>(q);
  });
}

TEST_CASE("circumball: a right triangle's centre is its hypotenuse's midpoint, tightly", "[circumball]") {
  {
    std::array<IvPoint<3>, 3> q{};
    q[1][0] = Iv::exact(2);
    q[2][1] = Iv::exact(2);
    const Circumball<3> b = circumball<3>(q, IvPoint<3>{Iv::exact(0), Iv::exact(0), Iv::exact(4)});
    CHECK(b.offset[0].lo <= 1);
    CHECK(b.offset[0].hi >= 1);
    CHECK(b.offset[0].hi - b.offset[0].lo < 1e-14);
    CHECK(b.r2.lo <= 2);
    CHECK(b.r2.hi >= 2);
  }
}

TEST_CASE("box_ball: a point exactly on the smallest sphere is kept", "[circumball]") {
  rc::prop("3D: the fourth corner of a rectangle (cocircular)", [] {
    const auto q = random_rectangle(-200, 160).q;
    const int corner = *rc::gen::inRange(0, 4);  // any corner may be the one tested
    std::array<IvPoint<3>, 3> qi;
    for (int j = 0, m = 0; j < 4; ++j)
      if (j != corner) {
        for (int i = 0; i < 3; ++i) qi[m][i] = Iv::exact(q[j][i]);
        ++m;
      }
    IvPoint<3> u, v;
    for (int i = 0; i < 3; ++i) u[i] = qi[1][i] - qi[0][i], v[i] = qi[2][i] - qi[0][i];
    const Circumball<3> cb = circumball<3>(qi, cross(u, v));
    std::array<Iv, 3> centre;
    for (int i = 0; i < 3; ++i) centre[i] = qi[0][i] + cb.offset[i];
    RC_ASSERT(cb.r2.bounded());
    RC_ASSERT(box_may_meet_ball<3>(q[corner], q[corner], centre, prune_r2(cb.r2.hi)));
  });
  rc::prop("2D: the segment's ends", [] {
    const int e = *rc::gen::inRange(-500, 500);
    std::array<IvPoint<2>, 2> qi;
    std::array<std::array<double, 2>, 2> q;
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) qi[j][i] = Iv::exact(q[j][i] = coordinate(e - 8, e));
    const Circumball<2> cb = circumball<2>(qi, IvPoint<2>{});
    std::array<Iv, 2> centre;
    for (int i = 0; i < 2; ++i) centre[i] = qi[0][i] + cb.offset[i];
    for (int j = 0; j < 2; ++j) RC_ASSERT(box_may_meet_ball<2>(q[j], q[j], centre, prune_r2(cb.r2.hi)));
  });
}

namespace {

// The nearest doubles below and above v: an enclosure of a rational.
Iv outward(const Q& v) {
  double lo = v.convert_to<double>(), hi = lo;
  while (Q(lo) > v) lo = std::nextafter(lo, -1e308);
  while (Q(hi) < v) hi = std::nextafter(hi, 1e308);
  return {lo, hi};
}

template <int D>
Q dot(const std::array<Q, D>& a, const std::array<Q, D>& b) {
  Q s = 0;
  for (int i = 0; i < D; ++i) s += a[i] * b[i];
  return s;
}

// hyperplane_trace of the sphere (c, r2) on the hyperplane through `at`
// with normal n, both given exactly; checked against the exact projection
// and Q(r2) - d^2. False where unbounded.
template <int D>
bool check_trace(const std::array<double, D>& c, double r2, const std::array<double, D>& at,
                 const std::array<Q, D>& n_exact, const IvPoint<D>& n) {
  IvPoint<D> ci, ai;
  for (int i = 0; i < D; ++i) ci[i] = Iv::exact(c[i]), ai[i] = Iv::exact(at[i]);
  Iv nn{0, 0};
  for (int i = 0; i < D; ++i) nn = nn + sq(n[i]);
  const Trace<D> t = hyperplane_trace<D>(ci, r2, ai, n, nn);
  std::array<Q, D> rel;
  for (int i = 0; i < D; ++i) rel[i] = Q(c[i]) - Q(at[i]);
  const Q k = dot<D>(rel, n_exact) / dot<D>(n_exact, n_exact);
  for (int i = 0; i < D; ++i)
    if (!t.centre[i].bounded()) return false;
  if (!t.r2.bounded()) return false;
  for (int i = 0; i < D; ++i) RC_ASSERT(encloses(t.centre[i], Q(c[i]) - k * n_exact[i]));
  RC_ASSERT(Q(t.r2.hi) >= Q(r2) - k * k * dot<D>(n_exact, n_exact));
  return true;
}

// The exact circumcentre of four points in space (Cramer's rule on
// 2 (qj - q0) . (c - q0) = |qj - q0|^2).
std::array<Q, 3> exact_circumcentre(const std::array<std::array<Q, 3>, 4>& q) {
  std::array<std::array<Q, 3>, 3> a;
  std::array<Q, 3> rhs;
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 3; ++i) a[j][i] = 2 * (q[j + 1][i] - q[0][i]);
    rhs[j] = 0;
    for (int i = 0; i < 3; ++i) rhs[j] += (q[j + 1][i] - q[0][i]) * (q[j + 1][i] - q[0][i]);
  }
  const std::array<Q, 3> x = cramer3(a, rhs);
  return {q[0][0] + x[0], q[0][1] + x[1], q[0][2] + x[2]};
}

}  // namespace

TEST_CASE("hyperplane_trace: encloses the exact trace (rational)", "[circumball]") {
  // Spheres from 2^-10 to 2^45 times their distance to the hyperplane
  // (squared), so that R^2 - d^2 runs from about R^2 down to where it
  // cancels to R^2's rounding, at every scale.
  rc::prop("3D: oblique planes through three points", [] {
    const int e = *rc::gen::inRange(-150, 150);
    std::array<std::array<double, 3>, 3> q;
    for (auto& p : q)
      for (double& x : p) x = coordinate(e - 8, e);
    RC_PRE(!collinear(q));
    std::array<Q, 3> u, v;
    IvPoint<3> ui, vi;
    for (int i = 0; i < 3; ++i) {
      u[i] = Q(q[1][i]) - Q(q[0][i]), v[i] = Q(q[2][i]) - Q(q[0][i]);
      ui[i] = Iv::exact(q[1][i]) - Iv::exact(q[0][i]), vi[i] = Iv::exact(q[2][i]) - Iv::exact(q[0][i]);
    }
    const std::array<Q, 3> n{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    std::array<double, 3> c;
    for (double& x : c) x = coordinate(e - 8, e);
    std::array<Q, 3> rel;
    for (int i = 0; i < 3; ++i) rel[i] = Q(c[i]) - Q(q[0][i]);
    const Q d2 = dot<3>(rel, n) * dot<3>(rel, n) / dot<3>(n, n);
    const double r2 = d2.convert_to<double>() * (1 + std::ldexp(1.0, -*rc::gen::inRange(-10, 46)));
    RC_ASSERT(check_trace<3>(c, r2, q[0], n, cross(ui, vi)));
  });
  rc::prop("2D: lines through two points", [] {
    const int e = *rc::gen::inRange(-200, 200);
    std::array<double, 2> a, b, c;
    for (double& x : a) x = coordinate(e - 8, e);
    for (double& x : b) x = coordinate(e - 8, e);
    for (double& x : c) x = coordinate(e - 8, e);
    RC_PRE(a != b);
    const std::array<Q, 2> n{Q(a[1]) - Q(b[1]), Q(b[0]) - Q(a[0])};
    const IvPoint<2> ni{Iv::exact(a[1]) - Iv::exact(b[1]), Iv::exact(b[0]) - Iv::exact(a[0])};
    const std::array<Q, 2> rel{Q(c[0]) - Q(a[0]), Q(c[1]) - Q(a[1])};
    const Q d2 = dot<2>(rel, n) * dot<2>(rel, n) / dot<2>(n, n);
    const double r2 = d2.convert_to<double>() * (1 + std::ldexp(1.0, -*rc::gen::inRange(-10, 46)));
    RC_ASSERT(check_trace<2>(c, r2, a, n, ni));
  });
}

TEST_CASE("hyperplane_trace: a point on the sphere and the plane is kept", "[circumball]") {
  // The rectangle p, p + a, p + b, p + a + b (a . b = 0) in an oblique plane
  // and a point o off it at a height from 2^-20 to 2^10 of the rectangle's
  // size: the sphere through p, p + a, p + b and o passes through p + a + b,
  // which its trace must keep. The centre is enclosed by the nearest doubles
  // around the exact one, the squared radius bounded above the same way.
  rc::prop("3D", [] {
    const Rectangle r = random_rectangle(-150, 150);
    const std::array<double, 3> nrm{-6, 6, -3};  // |nrm| = 9
    const double h = std::ldexp(r.side, -*rc::gen::inRange(-10, 21)) / 9;
    std::array<std::array<Q, 3>, 4> q;  // p, p + a, p + b, o
    IvPoint<3> n, at;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) q[j][i] = Q(r.q[j][i]);
      q[3][i] = Q(r.q[0][i]) + Q(h) * nrm[i];
      at[i] = Iv::exact(r.q[0][i]);
      n[i] = Iv::exact(nrm[i]);
    }
    const std::array<Q, 3> c = exact_circumcentre(q);
    IvPoint<3> ci;
    Q r2 = 0;
    for (int i = 0; i < 3; ++i) {
      ci[i] = outward(c[i]);
      r2 += (c[i] - q[0][i]) * (c[i] - q[0][i]);
    }
    const Trace<3> t = hyperplane_trace<3>(ci, outward(r2).hi, at, n, Iv::exact(81));
    RC_ASSERT(t.r2.bounded());
    RC_ASSERT(box_may_meet_ball<3>(r.q[3], r.q[3], t.centre, prune_r2(t.r2.hi)));
  });
}
