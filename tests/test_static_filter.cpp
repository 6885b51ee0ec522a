// The static orient3d filter of the adaptive kernel (predicates/adaptive_kernel.hpp,
// error_bounds.md 3.5) and the promise the driver fits it on (variants/driver.hpp):
// - fitted, its answers agree with mp on points anywhere within the covered margin
//   (1.01 G around the fitted points' box), many of them near its bound; the bound
//   is at least the per-call bound over the largest covered difference and not
//   much more; unfitted, empty, unbounded or NaN fits never answer;
// - perturbed<K>'s off-plane point, which can leave the margin, bypasses it;
// - every algorithm passes its kernel no point outside the margin, checked call by
//   call on degenerate and random sets by a kernel that records every 3D call
//   outside it; the driver fits the filter on that promise, and only on it
//   (predicate counters, with a Bowyer-Watson that does not promise).
#include <algorithm>
#include <array>
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "algorithms/bowyer_watson.hpp"
#include "algorithms/george.hpp"
#include "algorithms/george_box.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/tanemura.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/determinants.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "variants/driver.hpp"
#include "tests/run_readout.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;

struct Rng {
  std::mt19937_64 g;
  explicit Rng(std::uint64_t seed) : g(seed) {}
  double unit() { return static_cast<double>(g() >> 11) * 0x1p-53; }
  int range(int lo, int hi) { return lo + static_cast<int>(g() % static_cast<std::uint64_t>(hi - lo + 1)); }
};

// The fitted points' box and its largest width G, computed here.
struct Box {
  std::array<double, 3> lo{}, hi{};
  double g = 0;
  explicit Box(std::span<const Point3> pts) {
    lo = hi = pts[0];
    for (const Point3& p : pts)
      for (int j = 0; j < 3; ++j) lo[j] = std::min(lo[j], p[j]), hi[j] = std::max(hi[j], p[j]);
    for (int j = 0; j < 3; ++j) g = std::max(g, hi[j] - lo[j]);
  }
  bool covers(const Point3& p) const {  // within 1.01 G of the box on every axis
    for (int j = 0; j < 3; ++j)
      if (lo[j] - p[j] > 1.01 * g || p[j] - hi[j] > 1.01 * g) return false;  // (not hi + 1.01 G:
    return true;                                                             // that can round to p)
  }
};

// The adaptive kernel, counting the 3D calls with a point outside the margin of
// the points it was fitted to. without_static_filter() (what perturbed<K> uses
// for its own off-plane point) gives the unfitted kernel, which is not checked.
struct Confined {
  static constexpr bool exact = true;
  static constexpr std::string_view name = "adaptive-confined";
  AdaptiveKernel k;
  std::shared_ptr<Box> box;  // null: not fitted, nothing to check
  std::shared_ptr<std::size_t> outside = std::make_shared<std::size_t>(0);

  void fit_static_filter(std::span<const Point3> pts) {
    k.fit_static_filter(pts);
    box = std::make_shared<Box>(pts);
  }
  Confined without_static_filter() const { return Confined{k.without_static_filter(), nullptr, outside}; }
  void check(std::initializer_list<const Point3*> ps) const {
    if (box)
      for (const Point3* p : ps)
        if (!box->covers(*p)) ++*outside;
  }
  Sign orient2d(const Point2& a, const Point2& b, const Point2& c) const { return k.orient2d(a, b, c); }
  Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) const {
    return k.incircle(a, b, c, d);
  }
  Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) const {
    check({&a, &b, &c, &d});
    return k.orient3d(a, b, c, d);
  }
  Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                const Point3& e) const {
    check({&a, &b, &c, &d, &e});
    return k.insphere(a, b, c, d, e);
  }
};

int sgn(const Q& q) { return (q > 0) - (q < 0); }

// A random point within reach times G of the box (reach times the width on each axis
// of positive width).
Point3 near_box(Rng& r, const Box& b, double reach) {
  Point3 p;
  for (int j = 0; j < 3; ++j) {
    const double t = (r.unit() * (1 + 2 * reach)) - reach;  // in [-reach, 1 + reach)
    p[j] = b.lo[j] + t * (b.hi[j] - b.lo[j]);
    if (b.hi[j] == b.lo[j]) p[j] = b.lo[j] + (r.unit() - 0.5) * 2 * reach * b.g;
  }
  return p;
}

}  // namespace

TEST_CASE("static filter: fitted answers are exact, near its bound too", "[static]") {
  Rng r(31);
  int answered = 0, near = 0;
  for (int rep = 0; rep < 60; ++rep) {
    // A box of random size and place (flat on one axis now and then).
    const int e = r.range(-30, 30);
    const double scale = std::ldexp(1.0, e), off = std::ldexp(1.0, e + r.range(-10, 30));
    std::vector<Point3> pts(50);
    for (Point3& p : pts)
      for (int j = 0; j < 3; ++j) p[j] = off + scale * r.unit() * (rep % 7 == 0 && j == 2 ? 1e-6 : 1);
    AdaptiveKernel k;
    k.fit_static_filter(pts);
    REQUIRE(k.static_filter_fitted());
    const Box box(pts);
    // The bound covers the per-call bound over differences up to 3.02 G, within
    // the factor (4 / 3.02)^3 of it (W = 4 G).
    const double W = 3.02 * box.g, B = k.orient3d_static_bound();
    CHECK(B >= adaptive::o3_ss * W * W * W);
    INFO("B / (o3_ss (3.02 G)^3) = " << B / (adaptive::o3_ss * W * W * W));
    CHECK(B <= adaptive::o3_ss * W * W * W * 2.33);
    for (int i = 0; i < 300; ++i) {
      const Point3 a = near_box(r, box, 1.0), b = near_box(r, box, 1.0), c = near_box(r, box, 1.0);
      // d anywhere in the margin, or near the plane abc: moved off it by +-2^e ulps,
      // e in 0..14, which spans the static bound's edge at every scale tried here.
      Point3 d = near_box(r, box, 1.0);
      if (i % 2) {
        const double s = r.unit(), t = r.unit();
        for (int j = 0; j < 3; ++j) d[j] = a[j] + s * (b[j] - a[j]) + t * (c[j] - a[j]);
        const int j = r.range(0, 2);
        if (d[j] != 0)
          d[j] += (i % 4 == 1 ? 1 : -1) * std::ldexp(1.0, std::ilogb(d[j]) - 52 + r.range(0, 14));
        if (!box.covers(d)) d = near_box(r, box, 1.0);
      }
      REQUIRE(box.covers(a));
      REQUIRE(box.covers(d));
      const Staged s = k.orient3d_staged(a, b, c, d);
      const int exact = sgn(det::orient3d<Q>(a, b, c, d));
      INFO("rep " << rep << " call " << i);
      REQUIRE(static_cast<int>(s.sign) == exact);
      const double det = adaptive::orient3d_filter_scalar(a, b, c, d).det;
      if (s.stage == adaptive::stage_static) {
        ++answered;
        REQUIRE(std::fabs(det) > B);
      }
      near += std::fabs(det) <= B && std::fabs(det) > B / 100;
    }
  }
  CHECK(answered > 5000);
  CHECK(near > 100);  // the edge of the bound was reached (and answered exactly)
}

TEST_CASE("static filter: off unless fitted to a finite, non-empty set", "[static]") {
  const AdaptiveKernel unfitted;
  CHECK_FALSE(unfitted.static_filter_fitted());
  CHECK(unfitted.orient3d_static_bound() == std::numeric_limits<double>::infinity());
  const Point3 a{1, 0, 0}, b{0, 1, 0}, c{0, 0, 1}, o{0, 0, 0};
  CHECK(unfitted.orient3d_staged(a, b, c, o).stage == adaptive::stage_filter);

  AdaptiveKernel empty;
  empty.fit_static_filter({});
  CHECK_FALSE(empty.static_filter_fitted());

  AdaptiveKernel nan;
  const std::vector<Point3> with_nan = {{0, 0, 0}, {std::nan(""), 1, 1}};
  nan.fit_static_filter(with_nan);
  CHECK_FALSE(nan.static_filter_fitted());

  // A box whose W^3 overflows: the bound is +inf and never answers, exactly.
  AdaptiveKernel huge;
  const std::vector<Point3> far = {{-1e300, 0, 0}, {1e300, 1, 1}};
  huge.fit_static_filter(far);
  CHECK(huge.orient3d_static_bound() == std::numeric_limits<double>::infinity());
  const Point3 p{1e300, 1e300, 0}, q{-1e300, 1e300, 0}, s{0, -1e300, 1e300};
  const Staged st = huge.orient3d_staged(p, q, s, o);
  CHECK(st.stage != adaptive::stage_static);
  CHECK(st.sign == MpKernel{}.orient3d(p, q, s, o));

  // One point repeated: G = 0, and a call on it is an exact zero.
  AdaptiveKernel point;
  const std::vector<Point3> same = {{3, 4, 5}, {3, 4, 5}};
  point.fit_static_filter(same);
  CHECK(point.static_filter_fitted());
  CHECK(point.orient3d(same[0], same[0], same[0], same[0]) == Sign::zero);
}

TEST_CASE("perturbed: its off-plane point bypasses a fitted static filter", "[static]") {
  // Four coplanar points on x = 1024 whose spread (2^-60) is absorbed by x: the
  // off-plane point is then nextafter(1024) = 1024 + 2^-42, and the fifth point
  // at 1024 - 2^-43 makes G = 2^-43: that point is 2 G from the box, outside the
  // margin. perturbed<K> must ask K without its static filter there.
  const double x = 1024, u = 0x1p-60;
  const Point3 a{x, 0, 0}, b{x, 3 * u, 0}, c{x, 0, 3 * u}, p{x, u, u};
  const std::vector<Point3> pts = {a, b, c, p, {x - 0x1p-43, 0, 0}};
  Confined k;
  k.fit_static_filter(pts);
  REQUIRE(Box(pts).g == 0x1p-43);
  const perturbed<Confined> pk(k);
  const perturbed<MpKernel> pm;
  CHECK(pk.coplanar_incircle(a, b, c, p) == pm.coplanar_incircle(a, b, c, p));
  CHECK(pk.coplanar_incircle(a, b, c, p) == Sign::positive);  // p inside the circle abc
  CHECK(*k.outside == 0);
}

namespace {

std::vector<std::vector<Point3>> promise_sets() {
  std::vector<std::vector<Point3>> sets;
  std::vector<Point3> lattice;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      for (int l = 0; l < 4; ++l) lattice.push_back({double(i), double(j), double(l)});
  sets.push_back(lattice);                                  // cospherical, coplanar hull faces
  sets.push_back(gen::cospherical<3>(120, 1));
  sets.push_back(gen::coplanar(150, 4, 2));
  sets.push_back(gen::near_duplicates<3>(200, 3));
  sets.push_back(gen::perturb_ulps<3>(lattice, 2, 4));     // near-degenerate
  std::vector<Point3> uni(400);
  Rng r(5);
  for (Point3& q : uni) q = {r.unit(), r.unit(), r.unit()};
  sets.push_back(uni);
  return sets;
}

// Runs Algo with a confined (perturbed) adaptive kernel fitted as the driver fits
// it, and requires no call outside the margin and, unless the algorithm keeps
// only part of the hull (George's box), a valid Delaunay result.
template <class Algo, class... Options>
void keeps_promise(const std::vector<Point3>& pts, std::span<const Point3> fit_to,
                   bool whole_hull, Options... options) {
  Confined k;
  k.fit_static_filter(fit_to);
  Algo algo(perturbed<Confined>(k), options...);
  const TriangulationResult t = algo.run(std::span<const Point3>(pts));
  REQUIRE(t.outcome == RunResult::Outcome::ok);
  CHECK(*k.outside == 0);
  if (whole_hull) CHECK(validate(std::span<const Point3>(pts), t.simplices).delaunay());
}

// Bowyer-Watson without the promise: the driver must leave its kernel unfitted.
template <class K, int D>
struct NoPromise : BowyerWatson<K, D> {
  using BowyerWatson<K, D>::BowyerWatson;
  static constexpr bool kernel_sees_given_points_only = false;
};

}  // namespace

TEST_CASE("every algorithm passes its kernel only the given points", "[static]") {
  using K = perturbed<Confined>;
  STATIC_REQUIRE(driver_detail::SeesGivenPointsOnly<BowyerWatson<K, 3>>);
  STATIC_REQUIRE(driver_detail::SeesGivenPointsOnly<Lawson<K, 3>>);
  STATIC_REQUIRE(driver_detail::SeesGivenPointsOnly<George<K, 3>>);
  STATIC_REQUIRE(driver_detail::SeesGivenPointsOnly<Tanemura<K, 3>>);
  STATIC_REQUIRE_FALSE(driver_detail::SeesGivenPointsOnly<NoPromise<K, 3>>);
  for (const auto& pts : promise_sets()) {
    INFO(pts.size() << " points");
    keeps_promise<BowyerWatson<K, 3>>(pts, pts, true);
    keeps_promise<Lawson<K, 3>>(pts, pts, true);
    keeps_promise<Tanemura<K, 3>>(pts, pts, true);
    keeps_promise<George<K, 3>>(pts, pts, true, GeorgeOptions{true, false});  // exact spheres
    // George's enclosing box: the driver fits to the input and the corners (the
    // result lacks the hull elements removed with the box: George's own tests).
    std::vector<Point3> with_corners = pts;
    const auto corners = enclosing_box_corners<3>(std::span<const Point3>(pts));
    REQUIRE(corners);
    with_corners.insert(with_corners.end(), corners->begin(), corners->end());
    keeps_promise<George<K, 3>>(pts, with_corners, false, GeorgeOptions{true, true});
  }
}

TEST_CASE("the driver fits the static filter only on the promise", "[static]") {
  // Through dlab::run: the static stage answers most orient3d calls of every
  // algorithm, and every result is the same set of cells as mp's.
  std::vector<Point3> pts(300);
  Rng r(6);
  for (Point3& q : pts) q = {r.unit(), r.unit(), r.unit()};
  PointSet ps;
  ps.dimension = 3;
  ps.p3 = pts;
  RunOptions o;
  o.kernel = "mp";
  const auto want = test::canonical_simplices<3>(run(ps, o).simplices);
  for (const char* algo_name : {"bowyer-watson", "lawson", "george", "tanemura"}) {
    o.algorithm = algo_name;
    o.kernel = "adaptive";
    const RunResult got = run(ps, o);
    const std::uint64_t calls = test::counter(got.predicates, "orient3d");
    const std::uint64_t by_static = test::counter(got.predicates, "orient3d.static");
    INFO(algo_name << ": " << by_static << " of " << calls << " orient3d calls answered static");
    CHECK(calls > 0);
    CHECK(by_static > calls / 2);
    CHECK(test::canonical_simplices<3>(got.simplices) == want);
  }
  // The same input without the promise: never the static stage.
  RunOptions bw;
  const RunResult unfitted = run_algorithm<NoPromise, AdaptiveKernel>(point_set<3>(pts), bw);
  CHECK(test::counter(unfitted.predicates, "orient3d") > 0);
  CHECK(test::counter(unfitted.predicates, "orient3d.static") == 0);
  CHECK(test::canonical_simplices<3>(unfitted.simplices) == want);
}
