// The integer kernel's own symbolic-perturbation walk (integer_kernel.hpp,
// incircle_sos_staged / insphere_sos_staged, intdet::reduced_walk): on grid
// points whose lifted determinant is exactly zero on the int64 path, the walk
// runs on the reduced grid indices. Checked against perturbed<GmpKernel>,
// whose walk orders and orients the points themselves with GMP:
//  - random lattice subsets, scaled by 2^g and translated (most tests zero);
//  - cospherical / cocircular sets at the int64 path's edge, in every order
//    (radius 2^(T-1) - 1: every reduced index below 2^T, walked; 2^(T-1) + 1:
//    past it, left to perturbed's walk), and far beyond it (indices near
//    2^43, where the walk's int64 orientations would overflow);
//  - reduced vectors whose order a key with narrower fields would swap;
//  - grid points with small integer coordinates, where small_integer's
//    evaluation stands in for the integer stage (integer_kernel.hpp,
//    grid_stage): the same signs and stages as the determinant's.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <span>
#include <vector>

#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

const perturbed<GmpKernel> pmp;  // GMP alone (MpKernel shares intdet with the integer kernel)
constexpr unsigned char walked = IntegerKernel::walk_stage;

// The integer kernel fitted to pts with the grid-points promise, as the
// driver makes it (variants/driver.hpp): every point must be a grid point.
template <int D>
IntegerKernel fitted(std::span<const Point<D>> pts) {
  IntegerKernel k = IntegerKernel::fit<D>(pts);
  k.fit_static_filter(pts);
  REQUIRE(k.grid_points_only(D));
  return k;
}

Staged own_walk(const IntegerKernel& k, const std::vector<Point3>& p) {
  return k.insphere_sos_staged(p[0], p[1], p[2], p[3], p[4]);
}
Staged own_walk(const IntegerKernel& k, const std::vector<Point2>& p) {
  return k.incircle_sos_staged(p[0], p[1], p[2], p[3]);
}
Sign reference(const std::vector<Point3>& p) { return pmp.insphere(p[0], p[1], p[2], p[3], p[4]); }
Sign reference(const std::vector<Point2>& p) { return pmp.incircle(p[0], p[1], p[2], p[3]); }
Sign perturbed_integer(const IntegerKernel& k, const std::vector<Point3>& p) {
  return perturbed<IntegerKernel>(k).insphere(p[0], p[1], p[2], p[3], p[4]);
}
Sign perturbed_integer(const IntegerKernel& k, const std::vector<Point2>& p) {
  return perturbed<IntegerKernel>(k).incircle(p[0], p[1], p[2], p[3]);
}

// Every ordering of p's points (the walk's order is their lexicographic rank,
// not their position), each checked against GMP; returns how many the
// kernel's own walk decided.
template <int D>
int check_all_orders(std::vector<Point<D>> p) {
  const IntegerKernel k = fitted<D>(p);
  int count = 0;
  std::vector<int> idx(p.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<int>(i);
  do {
    std::vector<Point<D>> q;
    for (int i : idx) q.push_back(p[static_cast<std::size_t>(i)]);
    const Staged s = own_walk(k, q);
    const Sign want = reference(q);
    CHECK(perturbed_integer(k, q) == want);
    if (s.stage == walked) {
      CHECK(s.sign == want);
      ++count;
    }
  } while (std::next_permutation(idx.begin(), idx.end()));
  return count;
}

// Five points of the sphere of radius r about the origin; the base (last) is
// (r, 0, 0), so the reduced differences are at most 2r and one of them is r.
std::vector<Point3> sphere_points(double r) {
  return {{-r, 0, 0}, {0, r, 0}, {0, -r, 0}, {0, 0, r}, {r, 0, 0}};
}
std::vector<Point2> circle_points(double r) { return {{-r, 0}, {0, r}, {0, -r}, {r, 0}}; }

// D + 2 points of {0,1,2}^D times 2^g, translated (a generator inside
// rc::prop): checked against GMP; returns whether the kernel's walk decided.
template <int D>
bool lattice_subset_case() {
  const int g = *rc::gen::inRange(0, 40);
  const double scale = std::ldexp(1.0, g), shift = std::ldexp(*rc::gen::inRange(-1000, 1000), g);
  std::vector<Point<D>> p(D + 2);
  for (Point<D>& x : p)
    for (double& c : x) c = shift + scale * *rc::gen::inRange(0, 3);
  const IntegerKernel k = fitted<D>(p);
  const Staged s = own_walk(k, p);
  const Sign want = reference(p);
  RC_ASSERT(perturbed_integer(k, p) == want);
  if (s.stage != walked) return false;
  RC_ASSERT(s.sign == want);
  return true;
}

// Five (four) points of {0..4}^D translated by a small integer (a generator
// inside rc::prop): small integers, which small_integer certifies. Every
// predicate's sign and stage, exact and perturbed, against GMP: a nonzero
// determinant from stage 0 or 1, an exact zero as zero from the exact
// predicate and walked by the perturbed one.
template <int D>
void small_integer_case() {
  const double shift = *rc::gen::inRange(-100, 100);
  std::vector<Point<D>> p(D + 2);
  for (Point<D>& x : p)
    for (double& c : x) c = shift + *rc::gen::inRange(0, 5);
  const IntegerKernel k = fitted<D>(p);
  const GmpKernel exact;
  Staged o, e, w;
  Sign want_o, want_e;
  if constexpr (D == 3) {
    o = k.orient3d_staged(p[0], p[1], p[2], p[3]);
    want_o = exact.orient3d(p[0], p[1], p[2], p[3]);
    e = k.insphere_staged(p[0], p[1], p[2], p[3], p[4]);
    want_e = exact.insphere(p[0], p[1], p[2], p[3], p[4]);
  } else {
    o = k.orient2d_staged(p[0], p[1], p[2]);
    want_o = exact.orient2d(p[0], p[1], p[2]);
    e = k.incircle_staged(p[0], p[1], p[2], p[3]);
    want_e = exact.incircle(p[0], p[1], p[2], p[3]);
  }
  w = own_walk(k, p);
  RC_ASSERT(o.sign == want_o);
  RC_ASSERT(o.stage <= 1);
  RC_ASSERT(e.sign == want_e);
  RC_ASSERT(e.stage <= 1);
  RC_ASSERT(w.sign == reference(p));
  if (want_e == Sign::zero) {
    RC_ASSERT(e.stage == 1);
    RC_ASSERT(w.stage == walked);
  } else {
    RC_ASSERT(w.stage == e.stage);
  }
}

}  // namespace

TEST_CASE("on small-integer grid points the integer stage answers as the integer determinant would",
          "[integer][perturbed][rc]") {
  // Cospherical (cocircular) small integers: the exact predicate's zero is
  // the integer stage's, and every order is walked to GMP's perturbed sign.
  for (const double r : {1.0, 3.0, 200.0}) {
    const std::vector<Point3> s3 = sphere_points(r);
    const std::vector<Point2> s2 = circle_points(r);
    const IntegerKernel k3 = fitted<3>(s3), k2 = fitted<2>(s2);
    const Staged z3 = k3.insphere_staged(s3[0], s3[1], s3[2], s3[3], s3[4]);
    const Staged z2 = k2.incircle_staged(s2[0], s2[1], s2[2], s2[3]);
    CHECK((z3.sign == Sign::zero && z3.stage == 1));
    CHECK((z2.sign == Sign::zero && z2.stage == 1));
    CHECK(check_all_orders<3>(s3) == 120);
    CHECK(check_all_orders<2>(s2) == 24);
  }
  // A unimodular orientation (det -1) of 16-bit coordinates: past the static
  // filter's bound, so the small-integer stage gives the nonzero sign.
  const std::vector<Point3> u{{65535, 65534, 65535}, {65534, 65533, 65534}, {0, 0, 1}, {0, 0, 0}};
  const Staged o = fitted<3>(u).orient3d_staged(u[0], u[1], u[2], u[3]);
  CHECK(GmpKernel{}.orient3d(u[0], u[1], u[2], u[3]) == Sign::negative);
  CHECK(o.sign == Sign::negative);
  CHECK(o.stage == 1);
}

TEST_CASE("the integer kernel on 3D small-integer grid points answers as GMP, stage for stage",
          "[integer][perturbed][rc]") {
  rc::prop("3D: 5 points of {0..4}^3, translated", [] { small_integer_case<3>(); });
}

TEST_CASE("the integer kernel on 2D small-integer grid points answers as GMP, stage for stage",
          "[integer][perturbed][rc]") {
  rc::prop("2D: 4 points of {0..4}^2, translated", [] { small_integer_case<2>(); });
}

// (One property per test case: Catch runs the case once per rc::prop section.)
TEST_CASE("the integer kernel's walk answers as perturbed<GMP> on 3D lattice subsets",
          "[integer][perturbed][rc]") {
  int walked3 = 0, total3 = 0;
  rc::prop("3D: 5 points of {0,1,2}^3 times 2^g, translated", [&] {
    walked3 += lattice_subset_case<3>();
    ++total3;
  });
  // Degenerate often enough that the walk itself is exercised.
  CHECK(walked3 > total3 / 20);
}

TEST_CASE("the integer kernel's walk answers as perturbed<GMP> on 2D lattice subsets",
          "[integer][perturbed][rc]") {
  int walked2 = 0;
  rc::prop("2D: 4 points of {0,1,2}^2 times 2^g, translated", [&] { walked2 += lattice_subset_case<2>(); });
  CHECK(walked2 > 10);
}

TEST_CASE("the integer kernel's walk at the edge of its int64 path", "[integer][perturbed]") {
  // insphere's int64 path takes reduced magnitudes below 2^11
  // (kInt64InSphere), incircle's below 2^14 (kInt64InCircle). With the
  // radius r odd nothing divides out, and the largest difference is 2r.
  constexpr double t3 = 1 << intdet::kInt64InSphere, t2 = 1 << intdet::kInt64InCircle;
  // r = 2^(T-1) - 1: the magnitudes' OR is 2^T - 1, inside: every order walked.
  CHECK(check_all_orders<3>(sphere_points(t3 / 2 - 1)) == 120);
  CHECK(check_all_orders<2>(circle_points(t2 / 2 - 1)) == 24);
  // r = 2^(T-1) + 1: 2r = 2^T + 2, outside: the kernel returns the exact zero
  // (stage "integer") and perturbed<K>'s own walk decides. In 3D the orders
  // whose base (last) is (0, 0, r), the one point without its antipode among
  // the five, have differences of at most r alone: those 24 are walked.
  const std::vector<Point3> s3 = sphere_points(t3 / 2 + 1);
  const std::vector<Point2> s2 = circle_points(t2 / 2 + 1);
  const Staged z3 = own_walk(fitted<3>(s3), s3), z2 = own_walk(fitted<2>(s2), s2);
  CHECK((z3.sign == Sign::zero && z3.stage == 1));
  CHECK((z2.sign == Sign::zero && z2.stage == 1));
  CHECK(check_all_orders<3>(s3) == 24);
  CHECK(check_all_orders<2>(s2) == 0);
  // Far outside (r = 2^42 + 1, where the walk's int64 orientations would
  // overflow): still GMP's answers.
  CHECK(check_all_orders<3>(sphere_points(0x1p42 + 1)) == 0);
  CHECK(check_all_orders<2>(circle_points(0x1p42 + 1)) == 0);
}

TEST_CASE("reduced_walk orders the reduced vectors as lex_less does, at the path's extremes",
          "[integer][perturbed][rc]") {
  // The two largest points share x = 2^T - 1 and have y one apart, the larger
  // y with z = -(2^T - 1), the other with a large positive z: lex_less ranks
  // them by y alone, so a key whose z field spilled into y's would swap them.
  // The other two points and the order of the four are random; the query is
  // the origin. Reference: sos::walk with lex_less on the same vectors.
  constexpr int T = intdet::kInt64InSphere;
  constexpr std::int64_t m = (std::int64_t{1} << T) - 1;
  using P = std::array<std::int64_t, 3>;
  rc::prop("3D, T = kInt64InSphere", [&] {
    const std::int64_t y = *rc::gen::inRange<std::int64_t>(-m, m);
    std::array<P, 4> v{P{m, y + 1, -m}, P{m, y, *rc::gen::inRange<std::int64_t>(2, m + 1)}};
    for (int i = 2; i < 4; ++i)
      v[static_cast<std::size_t>(i)] = {*rc::gen::inRange<std::int64_t>(-m, m), *rc::gen::inRange<std::int64_t>(-m, m + 1),
                                        *rc::gen::inRange<std::int64_t>(-m, m + 1)};
    const auto perm = *rc::gen::elementOf(std::vector<std::array<int, 4>>{
        {0, 1, 2, 3}, {1, 0, 2, 3}, {2, 0, 3, 1}, {3, 2, 1, 0}, {1, 3, 0, 2}, {2, 3, 1, 0}});
    intdet::Reduced<5, 3> r{};
    for (int i = 0; i < 4; ++i) r.q[static_cast<std::size_t>(i)] = v[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])];
    for (const auto& w : r.q)
      for (std::int64_t x : w) r.magnitudes |= static_cast<std::uint64_t>(x < 0 ? -x : x);
    std::array<const P*, 5> pts;
    for (int i = 0; i < 5; ++i) pts[static_cast<std::size_t>(i)] = &r.q[static_cast<std::size_t>(i)];
    const Sign want = sos::walk<3, P>(pts, [](const std::array<const P*, 4>& t) {
      return intdet::sign(intdet::orient3d<T + 1>(*t[0], *t[1], *t[2], *t[3]));
    });
    RC_ASSERT(intdet::reduced_walk<T>(r) == want);
  });
}
