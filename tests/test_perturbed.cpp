// perturbed<MpKernel> against independent references:
//  - the definition: the sign of the lifted determinant with lift |p|^2 + eps^(N - rank(p))
//    (rank = lexicographic rank, largest point = dominant eps^1), evaluated in exact
//    rationals (boost mpq) for two small eps that must agree (Devillers & Teillaud 2011);
//  - CGAL's walk transcribed literally in CGAL's conventions (2 / 3 iterations, positively
//    oriented cell), to check that the general cofactor formula is CGAL's rule;
//  - permutation antisymmetry, never zero on distinct points, agreement with the exact
//    kernel when that is non-zero, invariance under scaling by 2^k and translation;
//  - coplanar in-circle on tilted planes built by integer similarities from 2D sets.
#include <algorithm>
#include <array>
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

using Q = boost::multiprecision::mpq_rational;

struct SplitMix {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  int below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }
  int range(int lo, int hi) { return lo + below(hi - lo + 1); }
};

// Exact determinant by Laplace expansion along the first row (n <= 5).
Q det(const std::vector<std::vector<Q>>& m) {
  const std::size_t n = m.size();
  if (n == 1) return m[0][0];
  Q sum = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (m[0][j] == 0) continue;
    std::vector<std::vector<Q>> minor;
    for (std::size_t i = 1; i < n; ++i) {
      std::vector<Q> row;
      for (std::size_t k = 0; k < n; ++k)
        if (k != j) row.push_back(m[i][k]);
      minor.push_back(row);
    }
    const Q t = m[0][j] * det(minor);
    if (j % 2 == 0)
      sum += t;
    else
      sum -= t;
  }
  return sum;
}

Sign sign_q(const Q& q) { return static_cast<Sign>(q.sign()); }

// Sign of det[(p_i, |p_i|^2 + eps^(n - rank_i), 1)] for the given eps, where rank is the
// lexicographic rank (std::array's operator<, independent of lex_less). With Shewchuk's
// conventions the row order (a, b, c, [d,] query) gives incircle / insphere directly for
// eps = 0 (checked below against the exact kernel).
template <int D>
Sign lifted_sign(const std::vector<Point<D>>& pts, const Q& eps) {
  const std::size_t n = pts.size();
  std::vector<std::vector<Q>> m;
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t rank = 0;
    for (std::size_t j = 0; j < n; ++j)
      if (pts[j] < pts[i]) ++rank;
    std::vector<Q> row;
    Q lift = 0;
    for (int k = 0; k < D; ++k) {
      row.emplace_back(pts[i][k]);
      lift += Q(pts[i][k]) * Q(pts[i][k]);
    }
    Q e = 1;
    for (std::size_t k = 0; k < n - rank; ++k) e *= eps;
    row.push_back(lift + e);
    row.emplace_back(1);
    m.push_back(row);
  }
  // det[(p, |p|^2, 1)] equals Shewchuk's det[(p - q, |p - q|^2)] (q = last point): add
  // -2 q.p + |q|^2 times the other columns to the lift column, subtract the last row,
  // expand along the last column (cofactor +1). Checked at eps = 0 in the first test.
  return sign_q(det(m));
}

template <int D>
Sign perturbed_limit(const std::vector<Point<D>>& pts) {
  const Q e1 = Q(1) / Q(boost::multiprecision::mpz_int(1) << 100);
  const Q e2 = e1 * e1;
  const Sign s1 = lifted_sign<D>(pts, e1), s2 = lifted_sign<D>(pts, e2);
  REQUIRE(s1 == s2);  // the sign has stabilised
  return s1;
}

// CGAL's Delaunay_triangulation_2 rule, literally (precondition: a, b, c ccw).
Sign cgal_walk_2(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const MpKernel k;
  const Sign s = k.incircle(a, b, c, d);
  if (s != Sign::zero) return s;
  std::array<const Point2*, 4> p{&a, &b, &c, &d};
  std::sort(p.begin(), p.end(), [](const Point2* x, const Point2* y) { return *x < *y; });
  for (int i = 3; i > 1; --i) {
    if (p[i] == &d) return Sign::negative;
    Sign o;
    if (p[i] == &c && (o = k.orient2d(a, b, d)) != Sign::zero) return o;
    if (p[i] == &b && (o = k.orient2d(a, d, c)) != Sign::zero) return o;
    if (p[i] == &a && (o = k.orient2d(d, b, c)) != Sign::zero) return o;
  }
  FAIL("CGAL's 2D walk did not decide in two iterations");
  return Sign::zero;
}

// CGAL's Delaunay_triangulation_3 rule in CGAL's conventions: orientation = -orient3d,
// side_of_oriented_sphere = -insphere; precondition orientation(p0..p3) == POSITIVE.
// Returns CGAL's side_of_oriented_sphere.
Sign cgal_walk_3(const Point3& p0, const Point3& p1, const Point3& p2, const Point3& p3,
                 const Point3& p) {
  const MpKernel k;
  auto orientation = [&](const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
    return -k.orient3d(a, b, c, d);
  };
  REQUIRE(orientation(p0, p1, p2, p3) == Sign::positive);
  const Sign s = -k.insphere(p0, p1, p2, p3, p);
  if (s != Sign::zero) return s;
  std::array<const Point3*, 5> q{&p0, &p1, &p2, &p3, &p};
  std::sort(q.begin(), q.end(), [](const Point3* x, const Point3* y) { return *x < *y; });
  for (int i = 4; i > 2; --i) {  // CGAL 5.5: "2 iterations are enough"
    if (q[i] == &p) return Sign::negative;
    Sign o;
    if (q[i] == &p3 && (o = orientation(p0, p1, p2, p)) != Sign::zero) return o;
    if (q[i] == &p2 && (o = orientation(p0, p1, p, p3)) != Sign::zero) return o;
    if (q[i] == &p1 && (o = orientation(p0, p, p2, p3)) != Sign::zero) return o;
    if (q[i] == &p0 && (o = orientation(p, p1, p2, p3)) != Sign::zero) return o;
  }
  FAIL("CGAL's 3D walk did not decide in two iterations");
  return Sign::zero;
}

int permutation_parity(const std::vector<int>& perm) {
  int inversions = 0;
  for (std::size_t i = 0; i < perm.size(); ++i)
    for (std::size_t j = i + 1; j < perm.size(); ++j)
      if (perm[i] > perm[j]) ++inversions;
  return inversions % 2 == 0 ? 1 : -1;
}

// 2D sets with many exactly cocircular quadruples.
std::vector<Point2> cocircular_set(SplitMix& rng) {
  std::vector<Point2> s;
  const int which = rng.below(3);
  if (which == 0 || which == 1) {
    // Pythagorean triples on radius 5 or 25 (all sign/swap variants).
    const std::vector<std::array<int, 2>> base =
        which == 0 ? std::vector<std::array<int, 2>>{{3, 4}, {5, 0}}
                   : std::vector<std::array<int, 2>>{{7, 24}, {15, 20}, {25, 0}};
    for (auto [x, y] : base)
      for (int sx : {-1, 1})
        for (int sy : {-1, 1})
          for (int swap = 0; swap < 2; ++swap) {
            Point2 p = swap ? Point2{double(sy * y), double(sx * x)} : Point2{double(sx * x), double(sy * y)};
            if (std::find(s.begin(), s.end(), p) == s.end()) s.push_back(p);
          }
  } else {
    for (int x = 0; x < 4; ++x)
      for (int y = 0; y < 4; ++y) s.push_back({double(x), double(y)});
  }
  const double tx = rng.range(-40, 40), ty = rng.range(-40, 40);
  for (auto& p : s) p = {p[0] + tx, p[1] + ty};
  return s;
}

std::vector<Point3> cospherical_set(SplitMix& rng) {
  std::vector<Point3> s;
  const int which = rng.below(3);
  auto add_variants = [&](std::array<int, 3> v) {
    std::sort(v.begin(), v.end());
    do {
      for (int sx : {-1, 1})
        for (int sy : {-1, 1})
          for (int sz : {-1, 1}) {
            const Point3 p{double(sx * v[0]), double(sy * v[1]), double(sz * v[2])};
            if (std::find(s.begin(), s.end(), p) == s.end()) s.push_back(p);
          }
    } while (std::next_permutation(v.begin(), v.end()));
  };
  if (which == 0) {
    add_variants({1, 2, 2});  // radius 3
    add_variants({0, 0, 3});
  } else if (which == 1) {
    add_variants({1, 4, 8});  // radius 9
    add_variants({4, 4, 7});
  } else {
    for (int x = 0; x < 3; ++x)
      for (int y = 0; y < 3; ++y)
        for (int z = 0; z < 3; ++z) s.push_back({double(x), double(y), double(z)});
  }
  const double tx = rng.range(-20, 20), ty = rng.range(-20, 20), tz = rng.range(-20, 20);
  for (auto& p : s) p = {p[0] + tx, p[1] + ty, p[2] + tz};
  return s;
}

template <class P>
std::vector<P> pick_distinct(SplitMix& rng, const std::vector<P>& set, int n) {
  std::vector<int> idx;
  while (static_cast<int>(idx.size()) < n) {
    const int i = rng.below(static_cast<int>(set.size()));
    if (std::find(idx.begin(), idx.end(), i) == idx.end()) idx.push_back(i);
  }
  std::vector<P> out;
  for (int i : idx) out.push_back(set[i]);
  return out;
}

}  // namespace

TEST_CASE("lifted determinant sign convention matches the exact kernel", "[perturbed]") {
  const MpKernel k;
  SplitMix rng{1};
  for (int t = 0; t < 200; ++t) {
    std::vector<Point2> p2(4);
    for (auto& p : p2) p = {double(rng.range(-9, 9)), double(rng.range(-9, 9))};
    CHECK(lifted_sign<2>(p2, Q(0)) == k.incircle(p2[0], p2[1], p2[2], p2[3]));
    std::vector<Point3> p3(5);
    for (auto& p : p3) p = {double(rng.range(-5, 5)), double(rng.range(-5, 5)), double(rng.range(-5, 5))};
    CHECK(lifted_sign<3>(p3, Q(0)) == k.insphere(p3[0], p3[1], p3[2], p3[3], p3[4]));
  }
}

TEST_CASE("perturbed incircle: never zero, the eps-limit of the lifted determinant, CGAL's walk",
          "[perturbed]") {
  const MpKernel mp;
  const perturbed<MpKernel> k;
  SplitMix rng{2};
  int cocircular = 0, decided_by_perturbation = 0;
  for (int t = 0; t < 400; ++t) {
    const auto set = cocircular_set(rng);
    auto q = pick_distinct(rng, set, 4);
    if (mp.orient2d(q[0], q[1], q[2]) == Sign::zero) continue;  // precondition
    const Sign exact = mp.incircle(q[0], q[1], q[2], q[3]);
    const Sign s = k.incircle(q[0], q[1], q[2], q[3]);
    REQUIRE(s != Sign::zero);
    if (exact != Sign::zero) {
      CHECK(s == exact);
    } else {
      ++cocircular;
    }
    CHECK(s == perturbed_limit<2>(q));
    // CGAL's walk needs a, b, c counterclockwise: swap a and b otherwise (one
    // transposition flips the sign).
    if (mp.orient2d(q[0], q[1], q[2]) == Sign::positive)
      CHECK(s == cgal_walk_2(q[0], q[1], q[2], q[3]));
    else
      CHECK(s == -cgal_walk_2(q[1], q[0], q[2], q[3]));
    // All 24 permutations: odd flip, even keep (the perturbed determinant is a determinant).
    std::vector<int> perm{0, 1, 2, 3};
    do {
      const Sign ps = k.incircle(q[perm[0]], q[perm[1]], q[perm[2]], q[perm[3]]);
      CHECK(ps == (permutation_parity(perm) > 0 ? s : -s));
    } while (std::next_permutation(perm.begin(), perm.end()));
    const auto staged = k.incircle_staged(q[0], q[1], q[2], q[3]);
    CHECK(staged.sign == s);
    CHECK((staged.stage == perturbed<MpKernel>::perturbation_stage) == (exact == Sign::zero));
    if (staged.stage == perturbed<MpKernel>::perturbation_stage) ++decided_by_perturbation;
  }
  CHECK(cocircular > 50);  // the generator really produces degenerate cases
  CHECK(decided_by_perturbation == cocircular);
}

TEST_CASE("perturbed insphere: never zero, the eps-limit of the lifted determinant, CGAL's walk",
          "[perturbed]") {
  const MpKernel mp;
  const perturbed<MpKernel> k;
  SplitMix rng{3};
  int cospherical = 0;
  for (int t = 0; t < 250; ++t) {
    const auto set = cospherical_set(rng);
    auto q = pick_distinct(rng, set, 5);
    if (mp.orient3d(q[0], q[1], q[2], q[3]) == Sign::zero) continue;
    const Sign exact = mp.insphere(q[0], q[1], q[2], q[3], q[4]);
    const Sign s = k.insphere(q[0], q[1], q[2], q[3], q[4]);
    REQUIRE(s != Sign::zero);
    if (exact != Sign::zero)
      CHECK(s == exact);
    else
      ++cospherical;
    CHECK(s == perturbed_limit<3>(q));
    // CGAL: cell positively oriented in CGAL's sense means orient3d < 0.
    if (mp.orient3d(q[0], q[1], q[2], q[3]) == Sign::negative)
      CHECK(s == -cgal_walk_3(q[0], q[1], q[2], q[3], q[4]));
    else
      CHECK(s == cgal_walk_3(q[1], q[0], q[2], q[3], q[4]));  // swap: +1 flip, -insphere: +1
    std::vector<int> perm{0, 1, 2, 3, 4};
    do {
      const Sign ps = k.insphere(q[perm[0]], q[perm[1]], q[perm[2]], q[perm[3]], q[perm[4]]);
      CHECK(ps == (permutation_parity(perm) > 0 ? s : -s));
    } while (std::next_permutation(perm.begin(), perm.end()));
  }
  CHECK(cospherical > 40);
}

TEST_CASE("perturbed predicates are invariant under scaling by 2^k and translation", "[perturbed]") {
  const perturbed<MpKernel> k;
  SplitMix rng{4};
  for (int t = 0; t < 60; ++t) {
    const auto q2 = pick_distinct(rng, cocircular_set(rng), 4);
    const auto q3 = pick_distinct(rng, cospherical_set(rng), 5);
    const Sign s2 = k.incircle(q2[0], q2[1], q2[2], q2[3]);
    const Sign s3 = k.insphere(q3[0], q3[1], q3[2], q3[3], q3[4]);
    for (int e : {-1060, -1000, -60, 60, 900, 1000}) {
      auto m2 = q2;
      for (auto& p : m2)
        for (auto& x : p) x = std::ldexp(x, e);
      auto m3 = q3;
      for (auto& p : m3)
        for (auto& x : p) x = std::ldexp(x, e);
      CHECK(k.incircle(m2[0], m2[1], m2[2], m2[3]) == s2);
      CHECK(k.insphere(m3[0], m3[1], m3[2], m3[3], m3[4]) == s3);
    }
  }
}

TEST_CASE("orientation is never perturbed", "[perturbed]") {
  const perturbed<MpKernel> k;
  CHECK(k.orient2d({0, 0}, {1, 1}, {2, 2}) == Sign::zero);
  CHECK(k.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}) == Sign::zero);
  CHECK(k.orient2d({0, 0}, {1, 0}, {0, 1}) == Sign::positive);
}

TEST_CASE("collinear_between", "[perturbed]") {
  CHECK(collinear_between<2>({0, 0}, {1, 1}, {2, 2}));
  CHECK(collinear_between<2>({2, 2}, {1, 1}, {0, 0}));
  CHECK_FALSE(collinear_between<2>({0, 0}, {2, 2}, {1, 1}));
  CHECK_FALSE(collinear_between<2>({0, 0}, {0, 0}, {1, 1}));  // strictly
  CHECK(collinear_between<2>({3, -1}, {3, 0}, {3, 5}));       // vertical line: y decides
  CHECK_FALSE(collinear_between<2>({3, -1}, {3, 7}, {3, 5}));
  CHECK(collinear_between<3>({0, 0, 0}, {0, 0, 1}, {0, 0, 2}));
  const double u = std::ldexp(1.0, -52);
  CHECK(collinear_between<2>({1, 1}, {1 + u, 1 - u}, {1 + 2 * u, 1 - 2 * u}));
}

namespace {

// An integer similarity of the plane into 3D: (u, v) -> o + u e1 + v e2 with e1 . e2 = 0,
// |e1| = |e2|; it maps circles to circles, so the unoriented 2D in-circle of the preimages
// is the coplanar in-circle of the images.
struct Embedding {
  Point3 o, e1, e2;
  Point3 operator()(const Point2& p) const {
    Point3 r;
    for (int i = 0; i < 3; ++i) r[i] = o[i] + p[0] * e1[i] + p[1] * e2[i];
    return r;
  }
};

const std::vector<Embedding> embeddings{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},     // horizontal
    {{5, -3, 2}, {1, 2, 2}, {2, 1, -2}},   // tilted, |e| = 3
    {{-7, 1, 4}, {2, 3, 6}, {3, -6, 2}},   // tilted, |e| = 7
    {{1, 2, 3}, {3, 4, 0}, {0, 0, 5}},     // vertical: xy projection degenerate
    {{4, 0, -1}, {0, 3, 4}, {0, 4, -3}},   // plane x = 4: xy and... only yz works
    {{0, 6, 0}, {0, 0, 1}, {1, 0, 0}},     // plane y = 6: only xz works
};

}  // namespace

TEST_CASE("coplanar in-circle on tilted planes", "[perturbed]") {
  const MpKernel mp;
  const perturbed<MpKernel> k;
  SplitMix rng{5};
  int degenerate = 0;
  for (int t = 0; t < 600; ++t) {
    const Embedding& f = embeddings[t % embeddings.size()];
    std::vector<Point2> q2;
    if (rng.below(3) == 0) {
      for (int i = 0; i < 4; ++i) q2.push_back({double(rng.range(-30, 30)), double(rng.range(-30, 30))});
    } else {
      q2 = pick_distinct(rng, cocircular_set(rng), 4);
    }
    const Sign o2 = mp.orient2d(q2[0], q2[1], q2[2]);
    if (o2 == Sign::zero || q2[3] == q2[0] || q2[3] == q2[1] || q2[3] == q2[2]) continue;
    std::vector<Point3> q3;
    for (const auto& p : q2) q3.push_back(f(p));
    REQUIRE(mp.orient3d(q3[0], q3[1], q3[2], q3[3]) == Sign::zero);  // really coplanar
    const Sign expected_exact = mp.incircle(q2[0], q2[1], q2[2], q2[3]) * o2;
    CHECK(k.coplanar_incircle_exact(q3[0], q3[1], q3[2], q3[3]) == expected_exact);
    // The plane's orientation is the 2D orientation up to one fixed sign per plane.
    const Sign flip = k.coplanar_orientation(q3[0], q3[1], q3[2]) * o2;
    CHECK(flip != Sign::zero);
    const Sign s = k.coplanar_incircle(q3[0], q3[1], q3[2], q3[3]);
    REQUIRE(s != Sign::zero);
    if (expected_exact != Sign::zero) {
      CHECK(s == expected_exact);
    } else {
      ++degenerate;
      // The perturbation in the plane: lift the 2D preimages with eps ranked by the
      // 3D lexicographic order of the images; unoriented = oriented * orientation.
      const Q eps = Q(1) / Q(boost::multiprecision::mpz_int(1) << 100);
      std::vector<std::vector<Q>> m;
      for (int i = 0; i < 4; ++i) {
        int rank = 0;
        for (int j = 0; j < 4; ++j)
          if (q3[j] < q3[i]) ++rank;
        Q e = 1;
        for (int r = 0; r < 4 - rank; ++r) e *= eps;
        m.push_back({Q(q2[i][0]), Q(q2[i][1]),
                     Q(q2[i][0]) * Q(q2[i][0]) + Q(q2[i][1]) * Q(q2[i][1]) + e, Q(1)});
      }
      CHECK(s == sign_q(det(m)) * o2);
    }
    // Unoriented: invariant under every permutation of a, b, c.
    CHECK(k.coplanar_incircle(q3[1], q3[0], q3[2], q3[3]) == s);
    CHECK(k.coplanar_incircle(q3[2], q3[0], q3[1], q3[3]) == s);
    CHECK(k.coplanar_incircle(q3[0], q3[2], q3[1], q3[3]) == s);
  }
  CHECK(degenerate > 100);
}

TEST_CASE("coplanar in-circle at extreme magnitudes", "[perturbed]") {
  const perturbed<MpKernel> k;
  SplitMix rng{6};
  for (int t = 0; t < 100; ++t) {
    const Embedding& f = embeddings[t % embeddings.size()];
    const auto q2 = pick_distinct(rng, cocircular_set(rng), 4);
    std::vector<Point3> q3;
    for (const auto& p : q2) q3.push_back(f(p));
    if (k.coplanar_orientation(q3[0], q3[1], q3[2]) == Sign::zero) continue;
    const Sign s = k.coplanar_incircle(q3[0], q3[1], q3[2], q3[3]);
    for (int e : {-1070, -900, 900, 1000}) {
      auto m = q3;
      for (auto& p : m)
        for (auto& x : p) x = std::ldexp(x, e);
      CHECK(k.coplanar_incircle(m[0], m[1], m[2], m[3]) == s);
    }
  }
}
