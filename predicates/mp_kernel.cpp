#include "predicates/mp_kernel.hpp"

#include <algorithm>
#include <boost/multiprecision/gmp.hpp>
#include <climits>
#include <cmath>
#include <cstdint>

#include "predicates/determinants.hpp"

namespace dlab {
namespace {

using Int = boost::multiprecision::mpz_int;

// x = mantissa * 2^exponent with an integer mantissa (|mantissa| < 2^53).
struct Dyadic {
  std::int64_t mantissa = 0;
  int exponent = INT_MAX;  // INT_MAX marks zero: it never sets the common scale
};

Dyadic split(double x) {
  if (x == 0) return {};
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f 2^e, 0.5 <= |f| < 1, exact
  return {static_cast<std::int64_t>(std::ldexp(f, 53)), e - 53};
}

// Converts the coordinates of N points of dimension D to exact integers, all
// scaled by the same 2^-emin.
template <int D, std::size_t N>
std::array<std::array<Int, D>, N> to_integers(const std::array<const Point<D>*, N>& pts) {
  std::array<std::array<Dyadic, D>, N> parts{};
  int emin = INT_MAX;
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      parts[i][j] = split((*pts[i])[j]);
      emin = std::min(emin, parts[i][j].exponent);
    }
  std::array<std::array<Int, D>, N> out;
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      const Dyadic& p = parts[i][j];
      out[i][j] = p.mantissa;
      if (p.mantissa != 0) out[i][j] <<= static_cast<unsigned>(p.exponent - emin);
    }
  return out;
}

Sign sign_of(const Int& v) { return static_cast<Sign>(v.sign()); }

}  // namespace

Sign MpKernel::orient2d(const Point2& a, const Point2& b, const Point2& c) const {
  const auto p = to_integers<2, 3>({&a, &b, &c});
  return sign_of(det::orient2d<Int>(p[0], p[1], p[2]));
}

Sign MpKernel::incircle(const Point2& a, const Point2& b, const Point2& c,
                        const Point2& d) const {
  const auto p = to_integers<2, 4>({&a, &b, &c, &d});
  return sign_of(det::incircle<Int>(p[0], p[1], p[2], p[3]));
}

Sign MpKernel::orient3d(const Point3& a, const Point3& b, const Point3& c,
                        const Point3& d) const {
  const auto p = to_integers<3, 4>({&a, &b, &c, &d});
  return sign_of(det::orient3d<Int>(p[0], p[1], p[2], p[3]));
}

Sign MpKernel::insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                        const Point3& e) const {
  const auto p = to_integers<3, 5>({&a, &b, &c, &d, &e});
  return sign_of(det::insphere<Int>(p[0], p[1], p[2], p[3], p[4]));
}

}  // namespace dlab
