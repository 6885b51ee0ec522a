// `mp`: the ground truth. Every double is an exact dyadic m 2^e (m odd); all
// coordinates of one call are scaled by the same power of two so that the
// smallest e becomes 0, which makes every determinant an exact integer
// polynomial whose sign is the sign of the real determinant (each is
// homogeneous, and the scale is positive). Works for every finite double,
// subnormals included.
//
//   GmpKernel  evaluates every call in GMP integers (Boost.Multiprecision):
//              the definition of the signs, used by the tests that check the
//              integer kernel (which shares the fixed-width path below).
//   MpKernel   (`--kernel mp`) gives the same signs, but evaluates a call in
//              fixed-width integers when every scaled coordinate satisfies
//              |v| < 2^61: then every coordinate difference is below 2^62 in
//              magnitude, which is the integer kernel's bit budget B = 62
//              (predicates/integer_kernel.hpp: each intermediate proven to
//              fit its type). Other calls go to GmpKernel. No floating-point
//              arithmetic decides anything: the only certificate is the bit
//              count, tested at its edge in tests/test_mp_kernel.cpp.
#pragma once
#include "predicates/kernel.hpp"

namespace dlab {

struct GmpKernel {
  static constexpr bool exact = true;
  static constexpr std::string_view name = "gmp";

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const;
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const;
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const;
};

struct MpKernel {
  static constexpr bool exact = true;
  static constexpr std::string_view name = "mp";
  // The bound on the scaled coordinates of the fixed-width path (see above).
  static constexpr int kSmallBits = 61;

  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const;
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const;
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const;
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const;
};

}  // namespace dlab
