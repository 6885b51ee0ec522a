// The ground-truth kernel against hand-checked signs (Shewchuk's conventions)
// and against the exact rational values of tiny cases.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>

#include "predicates/mp_kernel.hpp"

using namespace dlab;

TEST_CASE("mp kernel follows Shewchuk's sign conventions", "[mp]") {
  const MpKernel k;
  const Point2 a{0, 0}, b{1, 0}, c{0, 1};
  CHECK(k.orient2d(a, b, c) == Sign::positive);   // counterclockwise
  CHECK(k.orient2d(b, a, c) == Sign::negative);
  CHECK(k.orient2d(a, b, {2, 0}) == Sign::zero);
  CHECK(k.incircle(a, b, c, {0.25, 0.25}) == Sign::positive);  // inside
  CHECK(k.incircle(a, b, c, {1, 1}) == Sign::zero);            // cocircular
  CHECK(k.incircle(a, b, c, {2, 2}) == Sign::negative);

  const Point3 p{0, 0, 0}, q{1, 0, 0}, r{0, 1, 0};
  CHECK(k.orient3d(p, q, r, {0, 0, -1}) == Sign::positive);  // below abc (ccw from above)
  CHECK(k.orient3d(p, q, r, {0, 0, 1}) == Sign::negative);
  CHECK(k.orient3d(p, q, r, {5, 7, 0}) == Sign::zero);
  const Point3 s{0, 0, -1};
  CHECK(k.insphere(p, q, r, s, {0.2, 0.2, -0.2}) == Sign::positive);
  CHECK(k.insphere(p, q, r, s, {1, 1, 0}) == Sign::zero);    // on the sphere through the cube corners
  CHECK(k.insphere(p, q, r, s, {3, 3, 3}) == Sign::negative);
}

TEST_CASE("mp kernel is exact across the whole double range", "[mp]") {
  const MpKernel k;
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  // Collinear at both ends of the exponent range at once: (0,0), (huge, tiny), (huge/2, tiny/2)
  // is not representable exactly (tiny/2 rounds), so use multiples of tiny.
  CHECK(k.orient2d({0, 0}, {huge, 2 * tiny}, {huge / 2, tiny}) == Sign::zero);
  CHECK(k.orient2d({0, 0}, {huge, 2 * tiny}, {huge / 2, 2 * tiny}) == Sign::positive);
  // 1 + 2^-52 versus 1: a difference invisible to a naive determinant of large values.
  const double e = std::ldexp(1.0, -52);
  CHECK(k.orient2d({1e300, 1e300}, {1e300 * (1 + e), 1e300 * (1 + e)}, {-1e300, -1e300}) ==
        Sign::zero);
  CHECK(k.orient2d({1, 1}, {1 + e, 1 + 2 * e}, {2, 2}) == Sign::negative);
}

// MpKernel's fixed-width path (|scaled coordinate| < 2^61, mp_kernel.hpp)
// against GmpKernel at the edge of its certificate: integer coordinates m 2^k
// (m odd, k >= 0; the point (1, 1) fixes the common scale at 2^0) whose bit
// counts straddle 61 (width 60, 61, 62, 63: the last two go to GMP), both
// signs, and nearly degenerate configurations (differences of opposite-signed
// coordinates reach 2^62 and beyond, so a path taken one bit too far wraps).
namespace {

double edge_coordinate() {
  const int width = *rc::gen::inRange(1, 54);              // bits of the odd mantissa
  const int total = *rc::gen::element(59, 60, 61, 61, 62, 62, 63);  // bit count of the value
  const std::uint64_t top = (std::uint64_t{1} << width) - 1;  // the largest: 2^total - ...
  const auto m = static_cast<double>(*rc::gen::arbitrary<bool>()
                                         ? top
                                         : (*rc::gen::inRange<std::uint64_t>(0, top / 2 + 1)) * 2 + 1);
  const double v = std::ldexp(m, std::max(0, total - width));
  return *rc::gen::arbitrary<bool>() ? -v : v;
}

template <int D>
Point<D> edge_point() {
  Point<D> p;
  for (auto& c : p) c = *rc::gen::inRange(0, 4) == 0 ? double(*rc::gen::inRange(-3, 4)) : edge_coordinate();
  return p;
}

}  // namespace

TEST_CASE("mp kernel: the fixed-width path agrees with GMP at its bit edge", "[mp]") {
  const MpKernel mp;
  const GmpKernel gmp;
  // The widest differences by hand: x = 2^62 - 2^9 has 62 bits (GMP's), x - (-x)
  // is 2^63 - 2^10, and the lift of that difference, 2 (2^63 - 2^10)^2, is
  // beyond 2^127: a fixed-width path taken at 62 bits would wrap.
  const double x = std::ldexp(1.0, 62) - 512, y = std::ldexp(1.0, 61) - 256;  // 62 and 61 bits
  for (const double v : {x, y}) {
    const Point2 a{v, v}, c{-v, -v};
    CHECK(mp.incircle(Point2{1, 0}, Point2{0, 1}, a, c) == gmp.incircle(Point2{1, 0}, Point2{0, 1}, a, c));
    CHECK(mp.incircle(Point2{1, 0}, a, Point2{0, 1}, c) == gmp.incircle(Point2{1, 0}, a, Point2{0, 1}, c));
    const Point3 a3{v, v, v}, c3{-v, -v, -v};
    CHECK(mp.insphere(Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}, a3, c3) ==
          gmp.insphere(Point3{1, 0, 0}, Point3{0, 1, 0}, Point3{0, 0, 1}, a3, c3));
    CHECK(mp.orient3d(a3, Point3{1, 0, 0}, Point3{0, 1, 0}, c3) ==
          gmp.orient3d(a3, Point3{1, 0, 0}, Point3{0, 1, 0}, c3));
  }
  rc::prop("2D", [&] {
    const Point2 one{1, 1}, a = edge_point<2>(), b = edge_point<2>();
    const Point2 c{-a[0], -a[1]};  // a, c symmetric about the origin: wide differences
    RC_ASSERT(mp.orient2d(a, b, one) == gmp.orient2d(a, b, one));
    RC_ASSERT(mp.orient2d(a, c, b) == gmp.orient2d(a, c, b));
    RC_ASSERT(mp.orient2d(a, c, Point2{0, 0}) == Sign::zero);  // collinear, exactly
    RC_ASSERT(mp.incircle(a, b, c, one) == gmp.incircle(a, b, c, one));
    RC_ASSERT(mp.incircle(a, c, b, Point2{b[1], b[0]}) == gmp.incircle(a, c, b, Point2{b[1], b[0]}));
  });
  rc::prop("3D", [&] {
    const Point3 one{1, 1, 1}, a = edge_point<3>(), b = edge_point<3>(), c = edge_point<3>();
    const Point3 d{-a[0], -a[1], -a[2]};
    RC_ASSERT(mp.orient3d(a, b, c, one) == gmp.orient3d(a, b, c, one));
    RC_ASSERT(mp.orient3d(a, d, b, c) == gmp.orient3d(a, d, b, c));
    RC_ASSERT(mp.insphere(a, b, c, d, one) == gmp.insphere(a, b, c, d, one));
    RC_ASSERT(mp.insphere(a, d, b, c, Point3{b[1], b[2], b[0]}) ==
              gmp.insphere(a, d, b, c, Point3{b[1], b[2], b[0]}));
  });
}
