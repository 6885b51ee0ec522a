// `float`: the plain double-precision determinants, no error control.
// The baseline that fails (Kettner et al., "Classroom examples of robustness
// problems in geometric computations", CGTA 40 (2008)).
#pragma once
#include "predicates/kernel.hpp"
#include "predicates/determinants.hpp"

namespace dlab {

struct FloatKernel {
  static constexpr bool exact = false;
  static constexpr std::string_view name = "float";

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const {
    return sign_of(det::orient2d<double>(a, b, c));
  }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return sign_of(det::incircle<double>(a, b, c, d));
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    return sign_of(det::orient3d<double>(a, b, c, d));
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const {
    return sign_of(det::insphere<double>(a, b, c, d, e));
  }
};

}  // namespace dlab
