#include "predicates/mp_kernel.hpp"

#include <algorithm>
#include <bit>
#include <boost/multiprecision/gmp.hpp>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <cstdint>

#include "predicates/determinants.hpp"
#include "predicates/integer_kernel.hpp"

namespace dlab {
namespace {

using Int = boost::multiprecision::mpz_int;

// x = mantissa * 2^exponent with an odd integer mantissa (|mantissa| < 2^53).
struct Dyadic {
  std::int64_t mantissa = 0;
  int exponent = INT_MAX;  // INT_MAX marks zero: it never sets the common scale
};

Dyadic split(double x) {
  if (x == 0) return {};
  // Predicates are defined on finite coordinates only (every reader rejects
  // the others); a non-finite one would make the conversion below undefined.
  if (!std::isfinite(x)) throw std::domain_error("mp kernel: a non-finite coordinate");
  int e = 0;
  const double f = std::frexp(x, &e);  // x = f 2^e, 0.5 <= |f| < 1, exact
  const auto m = static_cast<std::int64_t>(std::ldexp(f, 53));
  const int zeros = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
  return {m >> zeros, e - 53 + zeros};  // an exact shift: the bits dropped are zeros
}

// The coordinates of N points of dimension D as dyadics, and the smallest exponent.
template <int D, std::size_t N>
struct Scaled {
  std::array<std::array<Dyadic, D>, N> parts{};
  int emin = INT_MAX;
};

template <int D, std::size_t N>
Scaled<D, N> scale(const std::array<const Point<D>*, N>& pts) {
  Scaled<D, N> s;
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      s.parts[i][j] = split((*pts[i])[j]);
      s.emin = std::min(s.emin, s.parts[i][j].exponent);
    }
  return s;
}

// mantissa 2^(exponent - emin) as an int64 when its magnitude is below
// 2^kSmallBits; false otherwise.
template <int D, std::size_t N>
bool to_small(const Scaled<D, N>& s, std::array<std::array<std::int64_t, std::size_t(D)>, N>& out) {
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      const Dyadic& p = s.parts[i][j];
      if (p.mantissa == 0) {
        out[i][j] = 0;
        continue;
      }
      const int shift = p.exponent - s.emin;
      const int width = std::bit_width(static_cast<std::uint64_t>(p.mantissa < 0 ? -p.mantissa : p.mantissa));
      if (width + shift > MpKernel::kSmallBits) return false;  // |v| >= 2^61
      out[i][j] = p.mantissa * (std::int64_t{1} << shift);
    }
  return true;
}

template <int D, std::size_t N>
std::array<std::array<Int, D>, N> to_gmp(const Scaled<D, N>& s) {
  std::array<std::array<Int, D>, N> out;
  for (std::size_t i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) {
      const Dyadic& p = s.parts[i][j];
      out[i][j] = p.mantissa;
      if (p.mantissa != 0) out[i][j] <<= static_cast<unsigned>(p.exponent - s.emin);
    }
  return out;
}

Sign sign_of(const Int& v) { return static_cast<Sign>(v.sign()); }

// Budget<62>: differences below 2^62 (see mp_kernel.hpp).
constexpr int kB = MpKernel::kSmallBits + 1;

}  // namespace

Sign GmpKernel::orient2d(const Point2& a, const Point2& b, const Point2& c) const {
  const auto p = to_gmp(scale<2, 3>({&a, &b, &c}));
  return sign_of(det::orient2d<Int>(p[0], p[1], p[2]));
}

Sign GmpKernel::incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
  const auto p = to_gmp(scale<2, 4>({&a, &b, &c, &d}));
  return sign_of(det::incircle<Int>(p[0], p[1], p[2], p[3]));
}

Sign GmpKernel::orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
  const auto p = to_gmp(scale<3, 4>({&a, &b, &c, &d}));
  return sign_of(det::orient3d<Int>(p[0], p[1], p[2], p[3]));
}

Sign GmpKernel::insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                         const Point3& e) const {
  const auto p = to_gmp(scale<3, 5>({&a, &b, &c, &d, &e}));
  return sign_of(det::insphere<Int>(p[0], p[1], p[2], p[3], p[4]));
}

Sign MpKernel::orient2d(const Point2& a, const Point2& b, const Point2& c) const {
  const auto s = scale<2, 3>({&a, &b, &c});
  std::array<intdet::I2, 3> q;
  if (!to_small(s, q)) return GmpKernel{}.orient2d(a, b, c);
  return intdet::sign(intdet::orient2d<kB>(q[0], q[1], q[2]));
}

Sign MpKernel::incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
  const auto s = scale<2, 4>({&a, &b, &c, &d});
  std::array<intdet::I2, 4> q;
  if (!to_small(s, q)) return GmpKernel{}.incircle(a, b, c, d);
  return intdet::sign(intdet::incircle<kB>(q[0], q[1], q[2], q[3]));
}

Sign MpKernel::orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
  const auto s = scale<3, 4>({&a, &b, &c, &d});
  std::array<intdet::I3, 4> q;
  if (!to_small(s, q)) return GmpKernel{}.orient3d(a, b, c, d);
  return intdet::sign(intdet::orient3d<kB>(q[0], q[1], q[2], q[3]));
}

Sign MpKernel::insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                        const Point3& e) const {
  const auto s = scale<3, 5>({&a, &b, &c, &d, &e});
  std::array<intdet::I3, 5> q;
  if (!to_small(s, q)) return GmpKernel{}.insphere(a, b, c, d, e);
  return intdet::sign(intdet::insphere<kB>(q[0], q[1], q[2], q[3], q[4]));
}

}  // namespace dlab
