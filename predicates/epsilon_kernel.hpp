// `epsilon`: plain double determinants with a tolerance, the second inexact
// baseline. Baker (Handbook of Grid Generation, 16.2.2) admits a simplex to the
// Bowyer-Watson cavity only if d(P,Q) < R - mu, "mu chosen sufficiently large
// to ensure strict inclusion"; here the tolerance is put on every determinant:
// |det| <= mu answers zero.
//
// How mu scales. With L the largest |coordinate difference| to the last point
// of the call (over all points and axes) and tol the relative tolerance,
//   mu = tol L^degree,  degree 2 (orient2d), 4 (incircle), 3 (orient3d), 5 (insphere),
// the degree of the determinant. Scaling every coordinate by s scales det and
// mu alike by s^degree, translating changes neither (up to rounding): the
// answers do not depend on the units. For s a power of two this holds exactly
// in floating point (every rounding commutes with power-of-two scaling) while
// nothing overflows or leaves the normal range (L between about 2^-200 and
// 2^200 for insphere). L is one length for all axes, so the test is nearly
// rotation invariant and reads geometrically: orient2d = |ab| dist(c, ab), so
// zero means dist(c, ab) <= tol L^2 / |ab| — for a well-shaped triangle, c
// within about tol L of the line (likewise planes, circles, spheres): Baker's
// mu as a fraction of the configuration's size. Inf / NaN answer zero.
//
// Default tol = 1e-12. The rounding error of the double evaluation
// (determinants.hpp) is, to first order, at most k eps P with eps = 2^-53, P
// the sum of |terms| (P <= 2 L^2, 12 L^4, 6 L^3, 72 L^5) and k the rounding
// depth (3, 6, 5, 9): about 6.7e-16, 8e-15, 3.3e-15, 7.2e-14 times L^degree
// (Shewchuk 1997 section 4.2 does this analysis exactly for his forms). All
// are well below tol, so a non-zero answer is the exact sign: only answers
// near zero are lost. With tol below those bounds the kernel degrades towards
// `float`.
#pragma once
#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "predicates/determinants.hpp"
#include "predicates/kernel.hpp"

namespace dlab {

struct EpsilonKernel {
  static constexpr bool exact = false;
  static constexpr std::string_view name = "epsilon";
  static constexpr double default_tolerance = 1e-12;

  double tolerance = default_tolerance;  // the relative tolerance tol

  EpsilonKernel() = default;
  explicit EpsilonKernel(double tol) : tolerance(tol) {}

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const {
    const double l = spread<2>({&a, &b}, c);
    return decide(det::orient2d<double>(a, b, c), tolerance * (l * l));
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    const double l = spread<2>({&a, &b, &c}, d), l2 = l * l;
    return decide(det::incircle<double>(a, b, c, d), tolerance * (l2 * l2));
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    const double l = spread<3>({&a, &b, &c}, d);
    return decide(det::orient3d<double>(a, b, c, d), tolerance * (l * l * l));
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const {
    const double l = spread<3>({&a, &b, &c, &d}, e), l2 = l * l;
    return decide(det::insphere<double>(a, b, c, d, e), tolerance * (l2 * l2 * l));
  }

 private:
  // L: the largest |coordinate difference| between the points and `last`.
  template <int D>
  static double spread(std::initializer_list<const Point<D>*> pts, const Point<D>& last) {
    double l = 0;
    for (const Point<D>* p : pts)
      for (int j = 0; j < D; ++j) l = std::max(l, std::fabs((*p)[j] - last[j]));
    return l;
  }
  static Sign decide(double det, double mu) {
    if (!(std::fabs(det) > mu)) return Sign::zero;  // also NaN, and inf <= inf
    return sign_of(det);
  }
};

}  // namespace dlab
