// The orientation experiment of Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom
// examples of robustness problems in geometric computations", CGTA 40 (2008), section 3:
// p = (0.5 + x 2^-53, 0.5 + y 2^-53), x, y in 0..255, q = (12, 12), r = (24, 24).
// orient2d(p, q, r) = (px - 24)(qy - 24) - (py - 24)(qx - 24) = 12 (py - px), so the exact
// sign is sign(y - x) -- checked here without any kernel. Every exact kernel must get all
// 65536 signs right; the plain float kernel gets many wrong (recorded, must be > 0).
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/counted.hpp"
#include "predicates/filtered.hpp"
#include "predicates/float_filter.hpp"
#include "predicates/float_kernel.hpp"
#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

constexpr int side = 256;
const Point2 q{12, 12}, r{24, 24};

Point2 kettner_point(int x, int y) {
  return {0.5 + std::ldexp(static_cast<double>(x), -53), 0.5 + std::ldexp(static_cast<double>(y), -53)};
}

Sign expected(int x, int y) { return y > x ? Sign::positive : (y < x ? Sign::negative : Sign::zero); }

// Number of (x, y) where k.orient2d(p, q, r) differs from sign(y - x).
template <class K>
int wrong_signs(const K& k) {
  int wrong = 0;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y) wrong += k.orient2d(kettner_point(x, y), q, r) != expected(x, y);
  return wrong;
}

}  // namespace

TEST_CASE("Kettner points are exact doubles and the exact sign is sign(y - x)", "[kettner]") {
  // The coordinates are representable: ulp(0.5) = 2^-53 and 0.5 + 255 2^-53 < 1.
  for (int x : {0, 1, 254, 255}) {
    const Point2 p = kettner_point(x, 0);
    CHECK(std::ldexp(p[0] - 0.5, 53) == x);
  }
  // 12 (py - px) = 12 (y - x) 2^-53 exactly; the mp kernel must agree everywhere.
  CHECK(wrong_signs(MpKernel{}) == 0);
}

TEST_CASE("Kettner experiment: exact kernels get all 65536 signs right", "[kettner]") {
  CHECK(wrong_signs(filtered<FloatFilter, MpKernel>{}) == 0);
  CHECK(wrong_signs(AdaptiveKernel{}) == 0);
  CHECK(wrong_signs(perturbed<filtered<FloatFilter, MpKernel>>{}) == 0);

  // Stages of the filtered kernel on this input: the near-collinear calls need the exact stage.
  const counted<filtered<FloatFilter, MpKernel>> k;
  CHECK(wrong_signs(k) == 0);
  const Counters c = k.counters();
  REQUIRE(c[0].first == "orient2d");
  CHECK(c[0].second == side * side);
  INFO("filter decided " << c[1].second << ", exact stage " << c[2].second);
  CHECK(c[2].second >= side);  // at least the exactly collinear x == y calls
  WARN("Kettner orient2d: filtered<FloatFilter,mp> filter decided " << c[1].second << " of "
       << side * side << ", exact stage " << c[2].second);
}

TEST_CASE("Kettner experiment: integer kernel, on its snapped points, agrees with mp", "[kettner][integer]") {
  std::vector<Point2> pts;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y) pts.push_back(kettner_point(x, y));
  pts.push_back(q);
  pts.push_back(r);
  IntegerKernel k;
  const SnapStats stats = k.snap_all(pts);
  (void)stats;
  const MpKernel mp;
  const Point2 sq = pts[side * side], sr = pts[side * side + 1];
  int disagreements = 0, wrong_vs_unsnapped = 0;
  for (int i = 0; i < side * side; ++i) {
    const Sign s = k.orient2d(pts[i], sq, sr);
    disagreements += s != mp.orient2d(pts[i], sq, sr);
    wrong_vs_unsnapped += s != expected(i / side, i % side);
  }
  CHECK(disagreements == 0);
  WARN("Kettner orient2d: integer kernel signs differing from the unsnapped exact signs "
       "(snapping moved the points): " << wrong_vs_unsnapped << " of " << side * side);
}

TEST_CASE("Kettner experiment: the float kernel gets many signs wrong", "[kettner]") {
  const FloatKernel fk;
  const int wrong_pqr = wrong_signs(fk);
  // The same three points in the two other cyclic orders (same exact sign).
  int wrong_qrp = 0, wrong_rpq = 0;
  for (int x = 0; x < side; ++x)
    for (int y = 0; y < side; ++y) {
      const Point2 p = kettner_point(x, y);
      wrong_qrp += fk.orient2d(q, r, p) != expected(x, y);
      wrong_rpq += fk.orient2d(r, p, q) != expected(x, y);
    }
  WARN("Kettner orient2d with plain doubles: wrong signs (p,q,r) " << wrong_pqr << ", (q,r,p) "
       << wrong_qrp << ", (r,p,q) " << wrong_rpq << " of " << side * side);
  CHECK(wrong_pqr > 0);
  CHECK(wrong_pqr + wrong_qrp + wrong_rpq > 1000);  // published: thousands
}
