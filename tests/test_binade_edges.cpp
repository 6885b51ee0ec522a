// The binade-edge generators of fuzz/binade_edges.hpp: every coordinate is the
// number the header says it is, checked in exact rational arithmetic (boost
// mpq, powers of two built from integer shifts) and on the bit patterns --
// never with the generator's own floating-point steps.
#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <set>

#include "fuzz/binade_edges.hpp"
#include "fuzz/generators.hpp"

using namespace dlab;
using namespace dlab::gen;

namespace {

using Q = boost::multiprecision::mpq_rational;
using Z = boost::multiprecision::mpz_int;

Q pow2(int e) {  // 2^e, exactly
  const Z one = 1;
  return e >= 0 ? Q(Z(one << e)) : Q(one, Z(one << -e));
}

bool is_integer(const Q& q) { return boost::multiprecision::denominator(q) == 1; }

// Side of the smallest m^D grid holding n points, computed here by brute force.
template <int D>
std::size_t side(std::size_t n) {
  std::size_t m = 0;
  while (std::pow(static_cast<double>(m), D) < static_cast<double>(n)) ++m;
  return m;
}

template <int D>
std::size_t distinct(std::vector<Point<D>> v) {
  std::sort(v.begin(), v.end());
  return static_cast<std::size_t>(std::unique(v.begin(), v.end()) - v.begin());
}

// Monotone integer image of a finite double (+0 and -0 both 0), from its bits.
std::int64_t ordinal(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits >= 0 ? bits : -(bits & INT64_MAX);
}

// Sorted distinct values of coordinate j.
template <int D>
std::vector<double> axis_values(const std::vector<Point<D>>& pts, int j) {
  std::set<double> s;
  for (const auto& p : pts) s.insert(p[j]);
  return {s.begin(), s.end()};
}

// The notable edges and a few more.
std::vector<int> edges() {
  std::vector<int> e = notable_edges();
  for (int x : {-1060, -1020, -600, 500, 1021}) e.push_back(x);
  return e;
}
const std::vector<int> kEdges = edges();

}  // namespace

TEST_CASE("binade-lattice: every coordinate is exactly s 2^E + i 2^S, i in [-m/2, m/2)", "[gen][binade]") {
  const auto check = [](auto dim_tag, std::size_t n, int exp, int step, auto signs) {
    constexpr int D = decltype(dim_tag)::value;
    INFO("D " << D << " n " << n << " exp " << exp << " step " << step);
    const auto pts = binade_lattice<D>(n, exp, step, signs);
    REQUIRE(pts.size() == n);
    CHECK(distinct<D>(pts) == n);
    const std::size_t m = side<D>(n);
    const auto half = static_cast<std::int64_t>(m / 2);
    for (std::size_t idx = 0; idx < n; ++idx) {
      std::size_t r = idx;
      for (int j = 0; j < D; ++j) {
        const auto i = static_cast<std::int64_t>(r % m) - half;  // x fastest
        r /= m;
        const double c = pts[idx][j];
        REQUIRE(std::isfinite(c));
        const Q want = signs[j] * pow2(exp) + Q(i) * pow2(step);
        REQUIRE(Q(c) == want);
        if (c == 0) REQUIRE_FALSE(std::signbit(c));
      }
    }
    // The edge and both of its sides are on every axis (m >= 3): |c| < 2^E, = 2^E,
    // > 2^E. (With step = exp the axis is (s + i) 2^E: +-2^E both, crossing 0.)
    if (m >= 3 && step < exp)
      for (int j = 0; j < D; ++j) {
        const auto v = axis_values<D>(pts, j);
        const auto below = std::count_if(v.begin(), v.end(), [&](double c) { return Q(std::fabs(c)) < pow2(exp); });
        const auto at = std::count_if(v.begin(), v.end(), [&](double c) { return Q(std::fabs(c)) == pow2(exp); });
        CHECK(below >= 1);
        CHECK(at == 1);
        CHECK(static_cast<std::size_t>(below + at) < v.size());
      }
  };
  using D2 = std::integral_constant<int, 2>;
  using D3 = std::integral_constant<int, 3>;
  for (int exp : kEdges) {
    const int finest = std::max(exp - 52, -1074);
    for (int step : {finest, std::min(exp, finest + 1), std::min(exp, finest + 2), exp}) {
      if (!(exp == 1023 && step >= 1022)) {  // those overflow (below)
        check(D2{}, 25, exp, step, AxisSigns<2>{1, 1});
        check(D2{}, 20, exp, step, AxisSigns<2>{-1, 1});
        check(D2{}, 9, exp, step, AxisSigns<2>{-1, -1});
        check(D3{}, 27, exp, step, AxisSigns<3>{-1, 1, -1});
        check(D3{}, 50, exp, step, AxisSigns<3>{1, -1, 1});
      }
    }
  }
  // The finest step is one ulp above the edge and two below (normal edges):
  // at 2^51 these are the half-integers of issue 17.
  const auto h = binade_lattice<2>(9, 51, -1, AxisSigns<2>{-1, -1});
  CHECK(h[0][0] == -2251799813685248.5);
  CHECK(h[1][0] == -2251799813685248.0);
  CHECK(h[2][0] == -2251799813685247.5);

  CHECK_THROWS_AS(binade_lattice<2>(9, 51, -2, AxisSigns<2>{1, 1}), std::invalid_argument);  // below ulp
  CHECK_THROWS_AS(binade_lattice<2>(9, 51, 52, AxisSigns<2>{1, 1}), std::invalid_argument);  // above exp
  CHECK_THROWS_AS(binade_lattice<2>(9, -1074, -1075, AxisSigns<2>{1, 1}), std::invalid_argument);
  CHECK_THROWS_AS(binade_lattice<2>(9, 1024, 1000, AxisSigns<2>{1, 1}), std::invalid_argument);
  GenOptions over;
  over.name = "binade-lattice";
  over.n = 100;
  over.exp = 1023, over.exp_set = true;
  over.step_exp = 1023, over.step_exp_set = true;
  CHECK_THROWS_AS(generate(over), std::invalid_argument);  // (1 + 5) 2^1023 overflows: refused
}

TEST_CASE("binade-doubles: consecutive doubles across the edge, spacing halving below it", "[gen][binade]") {
  for (int exp : kEdges)
    for (int s : {1, -1}) {
      INFO("exp " << exp << " sign " << s);
      const std::size_t n = 49;  // 7 x 7
      const auto pts = binade_doubles<2>(n, exp, AxisSigns<2>{s, -s});
      REQUIRE(pts.size() == n);
      CHECK(distinct<2>(pts) == n);
      for (int j = 0; j < 2; ++j) {
        const auto v = axis_values<2>(pts, j);
        REQUIRE(v.size() == 7);
        for (std::size_t i = 0; i + 1 < v.size(); ++i) CHECK(ordinal(v[i + 1]) - ordinal(v[i]) == 1);
        for (double c : v)
          if (c == 0) CHECK_FALSE(std::signbit(c));
        const double edge = (j == 0 ? s : -s) * std::ldexp(1.0, exp);
        REQUIRE(v[3] == edge);  // index floor(7/2)
        // Gap on the small-magnitude side and on the large one, exactly.
        const Q small = Q(v[3]) - Q(v[3 - (edge > 0 ? 1 : -1)]);
        const Q large = Q(v[3 + (edge > 0 ? 1 : -1)]) - Q(v[3]);
        const Q ulp_above = pow2(std::max(exp - 52, -1074)), ulp_below = pow2(std::max(exp - 53, -1074));
        CHECK(abs(small) == (exp >= -1021 ? ulp_below : ulp_above));
        CHECK(abs(large) == ulp_above);
      }
    }
  // 3D: the same construction on every axis.
  const auto p3 = binade_doubles<3>(64, 52, AxisSigns<3>{-1, -1, 1});
  CHECK(distinct<3>(p3) == 64);
  CHECK(axis_values<3>(p3, 2) == std::vector<double>{0x1p52 - 1, 0x1p52 - 0.5, 0x1p52, 0x1p52 + 1});
  CHECK(axis_values<3>(p3, 0) == std::vector<double>{-0x1p52 - 2, -0x1p52 - 1, -0x1p52, -0x1p52 + 0.5});
}

TEST_CASE("half-integers: distinct grid points, consecutive multiples of 1/2 around 2^51..2^53 or 0",
          "[gen][binade]") {
  // Offset of x from centre c in steps of the local spacing of multiples of 1/2
  // that are doubles: max(1/2, ulp) on each side of c (exact; not an integer if
  // x is not on the axis).
  const auto offset = [](double x, double c) -> Q {
    if (c == 0) return Q(x) * 2;
    const int e = std::ilogb(c);  // c = +-2^e
    const Q gap_large = std::max(Q(1, 2), pow2(e - 52)), gap_small = std::max(Q(1, 2), pow2(e - 53));
    const Q d = (Q(x) - Q(c)) * (c > 0 ? 1 : -1);  // towards larger magnitude: positive
    return (d >= 0 ? d / gap_large : d / gap_small) * (c > 0 ? 1 : -1);
  };
  const double centres2[][2] = {{-0x1p51, 0}, {0x1p51, -0x1p52}, {-0x1p53, 0x1p52}, {0x1p53, 0}};
  for (const auto& c : centres2)
    for (std::size_t n : {4u, 13u, 200u})
      for (std::uint64_t seed : {1u, 2u, 3u}) {
        INFO("centres " << c[0] << " " << c[1] << " n " << n << " seed " << seed);
        const auto pts = half_integers<2>(n, seed, {c[0], c[1]});
        REQUIRE(pts.size() == n);
        CHECK(distinct<2>(pts) == n);
        const std::size_t m = std::max<std::size_t>(2, side<2>(2 * n));
        const auto lo = -static_cast<std::int64_t>(m / 2), hi = static_cast<std::int64_t>(m) + lo - 1;
        for (const auto& p : pts)
          for (int j = 0; j < 2; ++j) {
            REQUIRE(is_integer(Q(p[j]) * 2));  // a multiple of 1/2
            const Q k = offset(p[j], c[j]);
            REQUIRE(is_integer(k));
            CHECK(k >= lo);
            CHECK(k <= hi);
          }
      }
  // Issue 17's class is there: non-integers in (-2^52, -2^51).
  const auto w = half_integers<3>(40, 5, {-0x1p51, -0x1p51, -0x1p51});
  std::size_t halves = 0;
  for (const auto& p : w)
    for (double x : p) halves += x < -0x1p51 && x != std::floor(x);
  CHECK(halves > 0);
  CHECK(distinct<3>(w) == 40);
  CHECK_THROWS_AS(half_integers<2>(4, 1, {0x1p50, 0}), std::invalid_argument);
}

TEST_CASE("extreme-doubles: the largest finite doubles, the smallest subnormals and 0", "[gen][binade]") {
  for (std::size_t n : {1u, 5u, 60u, 400u})
    for (std::uint64_t seed : {1u, 9u}) {
      INFO("n " << n << " seed " << seed);
      const auto p2 = extreme_doubles<2>(n, seed);
      const auto p3 = extreme_doubles<3>(n, seed);
      REQUIRE(p2.size() == n);
      REQUIRE(p3.size() == n);
      CHECK(distinct<2>(p2) == n);
      CHECK(distinct<3>(p3) == n);
      // k: the smallest with (4k+1)^D >= 2n, by brute force.
      const auto k_for = [n](int D) {
        std::uint64_t k = 1;
        while (std::pow(4.0 * static_cast<double>(k) + 1, D) < 2.0 * static_cast<double>(n)) ++k;
        return k;
      };
      const auto check = [](double c, std::uint64_t k) {
        const auto bits = std::bit_cast<std::uint64_t>(c) & ~(std::uint64_t{1} << 63);
        const std::uint64_t max_bits = 0x7FEFFFFFFFFFFFFFULL;  // DBL_MAX
        CHECK((bits <= k || (bits <= max_bits && bits > max_bits - k)));
        if (c == 0) CHECK_FALSE(std::signbit(c));
      };
      for (const auto& p : p2)
        for (double c : p) check(c, k_for(2));
      for (const auto& p : p3)
        for (double c : p) check(c, k_for(3));
    }
  // Enough points: every class on every axis.
  const auto big = extreme_doubles<2>(400, 3);
  const double max = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  for (int j = 0; j < 2; ++j) {
    const auto v = axis_values<2>(big, j);
    for (double want : {-max, -tiny, 0.0, tiny, max})
      CHECK(std::find(v.begin(), v.end(), want) != v.end());
  }
}

TEST_CASE("binade generators by name: seeded parameters, options, the fuzzer's mix", "[gen][binade]") {
  GenOptions o;
  o.name = "binade-lattice";
  o.n = 30;
  o.dim = 3;
  o.seed = 11;
  o.exp = 51, o.exp_set = true;
  o.step_exp = -1, o.step_exp_set = true;
  o.sign = "negative";
  const PointSet a = generate(o);
  CHECK(a.p3 == binade_lattice<3>(30, 51, -1, AxisSigns<3>{-1, -1, -1}));
  o.sign = "sideways";
  CHECK_THROWS_AS(generate(o), std::invalid_argument);
  // Unset parameters are seeded: across seeds the edge moves, is always a power
  // of two, and is a notable edge about half the time.
  std::set<double> edges;
  int notable = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    GenOptions g;
    g.name = "binade-doubles";
    g.n = 9;
    g.seed = seed;
    const PointSet ps = generate(g);
    REQUIRE(ps.size() == 9);
    const double edge = std::fabs(ps.p2[4][0]);  // index 4 = (1,1): the edge on both axes
    const int e = std::ilogb(edge);
    CHECK(edge == std::ldexp(1.0, e));
    edges.insert(edge);
    notable += std::find(notable_edges().begin(), notable_edges().end(), e) != notable_edges().end();
  }
  CHECK(notable >= 10);
  CHECK(notable <= 30);
  CHECK(edges.size() >= 20);
  GenOptions hi;
  hi.name = "half-integers";
  hi.exp = 50, hi.exp_set = true;
  CHECK_THROWS_AS(generate(hi), std::invalid_argument);

  const auto all = generator_names(), mix = degenerate_generator_names();
  for (const char* name : {"binade-lattice", "binade-doubles", "half-integers", "extreme-doubles"}) {
    CHECK(std::find(all.begin(), all.end(), name) != all.end());
    CHECK(std::find(mix.begin(), mix.end(), name) != mix.end());
  }
  for (const auto& name : mix) CHECK(std::find(all.begin(), all.end(), name) != all.end());
  CHECK(std::find(mix.begin(), mix.end(), "uniform") == mix.end());
  // generator_has_dimension agrees with generate().
  for (const auto& name : all)
    for (int dim : {2, 3}) {
      GenOptions g;
      g.name = name;
      g.dim = dim;
      g.n = 20;
      g.side = 4;
      INFO(name << " " << dim);
      if (generator_has_dimension(name, dim))
        CHECK_NOTHROW(generate(g));
      else
        CHECK_THROWS_AS(generate(g), std::invalid_argument);
    }
}
