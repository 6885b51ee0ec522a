// `mp`: the ground truth. Every double is converted exactly to a GMP integer
// (through Boost.Multiprecision) after scaling all coordinates of one call by
// the same power of two, so that the smallest exponent becomes 2^0; every
// determinant is then an exact integer polynomial whose sign is the sign of the
// real determinant (each is homogeneous, and the scale is positive).
// Works for every finite double, subnormals included. Slow on purpose.
#pragma once
#include "predicates/kernel.hpp"

namespace dlab {

struct MpKernel {
  static constexpr bool exact = true;
  static constexpr std::string_view name = "mp";

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const;
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const;
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const;
};

}  // namespace dlab
