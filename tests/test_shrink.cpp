// `dlab shrink`'s parts (tests/test_cli.cmake runs the command and re-runs its
// output with dlab triangulate; tests/test_fuzz_campaign.sh does so for every
// shrunk failure file of a campaign):
//   - ddmin (Zeller and Hildebrandt, IEEE TSE 2002) on synthetic tests: exactly
//     the failure-inducing pair {3, 17} of 40 elements; results that fail and
//     are 1-minimal (every single removal checked to pass); a spent budget ends
//     it with a failing set;
//   - the floating-point steps at their boundaries: ties to even, rounding up
//     to 2^1024, subnormals, exact and inexact differences at 2^53;
//   - the coordinate passes keep only sets that still fail, and reach the
//     simplest set of synthetic tests whose answer is known (worked by hand);
//   - the child-process oracle on a real float failure: the shrunk set is
//     smaller and gives the same class when run again in this process (run +
//     classify, not the oracle), twice the same; a child that crashes
//     (DLAB_FUZZ_SELFTEST's crash) is a failure the shrinker survives and shrinks.
#include <catch2/catch.hpp>

#include <signal.h>

#include <cfloat>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/selftest.hpp"
#include "fuzz/shrink.hpp"
#include "fuzz/shrink_ddmin.hpp"
#include "fuzz/shrink_numbers.hpp"
#include "fuzz/shrink_oracle.hpp"
#include "variants/outcome.hpp"

namespace {

using namespace dlab;
using namespace dlab::fuzz;
using Subset = std::vector<std::size_t>;

bool contains(const Subset& s, std::size_t x) { return std::find(s.begin(), s.end(), x) != s.end(); }

// `r` fails and each one-element removal passes.
void check_one_minimal(const Subset& r, const SubsetTest& fails) {
  CHECK(fails(r));
  for (std::size_t i = 0; i < r.size(); ++i) {
    Subset less = r;
    less.erase(less.begin() + static_cast<std::ptrdiff_t>(i));
    INFO("without element " << r[i]);
    CHECK_FALSE(fails(less));
  }
}

PointSet set2(std::vector<Point2> p) {
  PointSet s;
  s.dimension = 2;
  s.p2 = std::move(p);
  return s;
}

// Case 24 of `dlab fuzz --kernel float,epsilon --algo lawson,bowyer-watson --gen mix
// --cases 2000` (seed 0): near-duplicates, n = 20; lawson x float is not Delaunay.
const std::vector<Point2> kLawsonFloatFailure = {
    {0x1.d74d6f5bc9035p-2, 0x1.c9e6033d61ee9p-3}, {0x1.d05cdf97733e1p-1, 0x1.620f3ed408d3cp-1},
    {0x1.75da8bf216ap-1, 0x1.3556b7e0111d4p-1},   {0x1.d05cdf97733e2p-1, 0x1.620f3ed408d3cp-1},
    {0x1.49b4c043f0da4p-1, 0x1.06f2daebfd71bp-1}, {0x1.537bd68ff2cep-4, 0x1.ddfca1ff600fp-1},
    {0x1.d05cdf97733dfp-1, 0x1.620f3ed408d39p-1}, {0x1.537bd68ff2cdep-4, 0x1.ddfca1ff600eep-1},
    {0x1.75da8bf2169fdp-1, 0x1.3556b7e0111d7p-1}, {0x1.75da8bf2169fcp-1, 0x1.3556b7e0111d4p-1},
    {0x1.d74d6f5bc9039p-2, 0x1.c9e6033d61eebp-3}, {0x1.d74d6f5bc9039p-2, 0x1.c9e6033d61eeep-3},
    {0x1.d74d6f5bc9038p-2, 0x1.c9e6033d61ee9p-3}, {0x1.75da8bf2169fep-1, 0x1.3556b7e0111d8p-1},
    {0x1.49b4c043f0da6p-1, 0x1.06f2daebfd71ap-1}, {0x1.d74d6f5bc903bp-2, 0x1.c9e6033d61eefp-3},
    {0x1.d05cdf97733ep-1, 0x1.620f3ed408d38p-1},  {0x1.537bd68ff2ce2p-4, 0x1.ddfca1ff600f2p-1},
    {0x1.537bd68ff2ce1p-4, 0x1.ddfca1ff600efp-1}, {0x1.d74d6f5bc9037p-2, 0x1.c9e6033d61eeap-3}};
constexpr std::uint64_t kLawsonOrderSeed = 7275081841566860385ULL;

}  // namespace

TEST_CASE("shrink: ddmin finds exactly the failure-inducing pair {3, 17} of 40", "[shrink]") {
  std::size_t tests = 0;
  const SubsetTest fails = [&](const Subset& s) {
    ++tests;
    return contains(s, 3) && contains(s, 17);
  };
  const Subset r = ddmin(40, fails);
  CHECK(r == Subset{3, 17});
  check_one_minimal(r, fails);
  CHECK(tests < 200);  // Zeller and Hildebrandt: O(|c|^2) in the worst case, far fewer here
}

TEST_CASE("shrink: ddmin's results fail and are 1-minimal", "[shrink]") {
  SECTION("three of four needles") {
    const SubsetTest fails = [](const Subset& s) {
      return contains(s, 2) + contains(s, 9) + contains(s, 30) + contains(s, 41) >= 3;
    };
    const Subset r = ddmin(50, fails);
    CHECK(r.size() == 3);
    check_one_minimal(r, fails);
  }
  SECTION("a sum of at least 100 (many minimal sets)") {
    const SubsetTest fails = [](const Subset& s) { return std::accumulate(s.begin(), s.end(), std::size_t{0}) >= 100; };
    const Subset r = ddmin(30, fails);
    check_one_minimal(r, fails);
  }
  SECTION("one element, and a single failing element") {
    CHECK(ddmin(1, [](const Subset&) { return true; }) == Subset{0});
    CHECK(ddmin(64, [](const Subset& s) { return contains(s, 63); }) == Subset{63});
  }
}

TEST_CASE("shrink: ddmin ends when the budget is spent, with a failing set", "[shrink]") {
  std::size_t calls = 0;
  const auto truly_fails = [](const Subset& s) { return contains(s, 3) && contains(s, 17); };
  const Subset r = ddmin(1000, [&](const Subset& s) { return ++calls <= 4 && truly_fails(s); });
  CHECK(truly_fails(r));
  CHECK(r.size() > 2);
  CHECK(calls < 20000);  // the rounds are bounded whatever the test answers
}

TEST_CASE("shrink: significant bits, at the ends of the double range", "[shrink]") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(significant_bits(0.0) == 0);
  CHECK(significant_bits(-0.0) == 0);
  CHECK(significant_bits(1.0) == 1);
  CHECK(significant_bits(-3.0) == 2);
  CHECK(significant_bits(1 + 0x1p-52) == 53);
  CHECK(significant_bits(DBL_MAX) == 53);
  CHECK(significant_bits(0.1) == 52);  // 0x1.999999999999ap-4
  CHECK(significant_bits(tiny) == 1);
  CHECK(significant_bits(3 * tiny) == 2);
  CHECK(significant_bits(DBL_MIN - tiny) == 52);  // the largest subnormal
  CHECK(exponent_distance(0.0) == 0);
  CHECK(exponent_distance(1.0) == 1);    // 1/2 * 2^1
  CHECK(exponent_distance(0.75) == 0);   // 3/4 * 2^0
  CHECK(exponent_distance(tiny) == 1073);
}

TEST_CASE("shrink: rounding to fewer bits is to nearest, ties to even, exact or nothing", "[shrink]") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  CHECK(round_to_bits(1 + 0x1p-52, 52) == 1.0);                 // a tie, to the even 1
  CHECK(round_to_bits(1 + 3 * 0x1p-52, 52) == 1 + 4 * 0x1p-52);  // a tie, up to the even one
  CHECK(round_to_bits(1.5, 1) == 2.0);                          // a tie between 1 and 2
  CHECK(round_to_bits(1.25, 1) == 1.0);
  CHECK(round_to_bits(-1.5, 1) == -2.0);
  CHECK(round_to_bits(0.1, 1) == 0.125);
  CHECK(round_to_bits(0.0, 1) == 0.0);
  CHECK(round_to_bits(DBL_MAX, 53) == DBL_MAX);
  CHECK_FALSE(round_to_bits(DBL_MAX, 52).has_value());           // would be 2^1024
  CHECK(round_to_bits(std::nextafter(DBL_MAX, 0.0), 52) == std::nextafter(DBL_MAX, 0.0));  // even: stays
  CHECK(round_to_bits(3 * tiny, 1) == 4 * tiny);  // subnormals stay on their grid
  CHECK(round_to_bits(5 * tiny, 2) == 4 * tiny);  // 101b: a tie, to 100b
  CHECK(round_to_bits(7 * tiny, 2) == 8 * tiny);
}

TEST_CASE("shrink: a difference is taken only when it is exact", "[shrink]") {
  const double big = 0x1p53 + 2;
  CHECK_FALSE(exact_difference(big, -1).has_value());  // 2^53 + 3 is not a double
  CHECK(exact_difference(big, -2) == 0x1p53 + 4);
  CHECK_FALSE(exact_difference(1, 0x1p-60).has_value());
  CHECK(exact_difference(1, 0x1p-53) == 1 - 0x1p-53);
  CHECK_FALSE(exact_difference(DBL_MAX, -DBL_MAX).has_value());  // overflows
  CHECK(exact_difference(0.1, 0.1) == 0.0);
}

TEST_CASE("shrink: the coordinate passes reach the simplest failing set of a synthetic test", "[shrink]") {
  SECTION("some point with x > 2.3: one point (4, 0)") {
    // ddmin keeps (5.123456789, 0.37); y is translated to 0; x snapped to 5, rounded to 1 bit: 4.
    const PointSet in = set2({{0.1, 7.5}, {0.2, -3}, {5.123456789, 0.37}, {0.7, 0.7}});
    std::size_t tests = 0;
    const ShrinkReport r = shrink(
        in,
        [&](const PointSet& p) {
          ++tests;
          for (const auto& q : p.p2)
            if (q[0] > 2.3) return true;
          return false;
        },
        ShrinkLimits{});
    CHECK(r.points.p2 == std::vector<Point2>{{4, 0}});
    CHECK(r.fixpoint);
    CHECK(r.tests == tests);
    CHECK(r.before.points == 4);
    CHECK(r.after == ShrinkSize{1, 1, 3});  // 4 = 1/2 2^3
  }
  SECTION("two x exactly 0.5 apart, far from the origin: translated to (0, 0), (0.5, 0)") {
    const PointSet in = set2({{0x1p40 + 3, 7.25}, {0x1p40 + 3.5, -1.75}, {5, 5}});
    const ShrinkReport r = shrink(
        in,
        [](const PointSet& p) {
          for (const auto& a : p.p2)
            for (const auto& b : p.p2)
              if (b[0] - a[0] == 0.5) return true;
          return false;
        },
        ShrinkLimits{});
    CHECK(r.points.p2 == std::vector<Point2>{{0, 0}, {0.5, 0}});
  }
  SECTION("3D: some point with z > 2.3") {
    PointSet in;
    in.dimension = 3;
    in.p3 = {{1, 2, 3}, {0.3, 9.75, 1}, {-7, 1, 0.1}};
    const ShrinkReport r = shrink(
        in,
        [](const PointSet& p) {
          for (const auto& q : p.p3)
            if (q[2] > 2.3) return true;
          return false;
        },
        ShrinkLimits{});
    // ddmin keeps (1, 2, 3); x and y are translated to 0; z = 11b rounds to 1 bit: 4 (a tie, to even).
    CHECK(r.points.p3 == std::vector<Point3>{{0, 0, 4}});
  }
}

TEST_CASE("shrink: every set kept fails, and the budget bounds the tests", "[shrink]") {
  const PointSet in = set2(kLawsonFloatFailure);
  // Fails while some two points are closer than 2^-40 (near-duplicates): a
  // property the coordinate passes easily destroy.
  const PointTest close_pair = [](const PointSet& p) {
    for (std::size_t i = 0; i < p.p2.size(); ++i)
      for (std::size_t j = i + 1; j < p.p2.size(); ++j)
        if (std::hypot(p.p2[i][0] - p.p2[j][0], p.p2[i][1] - p.p2[j][1]) < 0x1p-40) return true;
    return false;
  };
  const ShrinkReport r = shrink(in, close_pair, ShrinkLimits{});
  CHECK(close_pair(r.points));
  CHECK(r.points.size() == 2);
  CHECK(r.after < r.before);
  ShrinkLimits few;
  few.max_tests = 5;
  const ShrinkReport b = shrink(in, close_pair, few);
  CHECK(b.tests == 5);
  CHECK(b.budget_spent);
  CHECK_FALSE(b.fixpoint);
  CHECK(close_pair(b.points));
}

TEST_CASE("shrink: the same failure is the same class and, unless any kind will do, the same kind", "[shrink]") {
  const Observed hull{"invalid", "hull-coverage", "1 reflex boundary ridge"};
  CHECK(FailureClass{"invalid", "hull-coverage"}.matches(hull));
  CHECK_FALSE(FailureClass{"invalid", "orientation"}.matches(hull));
  CHECK_FALSE(FailureClass{"reported", "hull-coverage"}.matches(hull));
  CHECK(FailureClass{"invalid", std::nullopt}.matches(hull));
  CHECK_FALSE(FailureClass{"not-delaunay", std::nullopt}.matches(hull));
  CHECK(FailureClass{"invalid", std::nullopt}.describe() == "invalid (any kind)");
  CHECK(FailureClass{"not-delaunay", ""}.describe() == "not-delaunay");
}

TEST_CASE("shrink: a real float failure, in child processes, shrinks and still fails", "[shrink]") {
  const Pair pair = make_pair("lawson", "float");
  const ChildOracle oracle(pair, kLawsonOrderSeed, Limits{});
  const PointSet in = set2(kLawsonFloatFailure);
  const Observed first = oracle.observe(in);
  REQUIRE(first.outcome == "not-delaunay");
  const FailureClass target{first.outcome, first.kind};
  const PointTest same = [&](const PointSet& p) { return target.matches(oracle.observe(p)); };
  ShrinkLimits lim;
  lim.max_tests = 1000;
  const ShrinkReport r = shrink(in, same, lim);
  CHECK(r.fixpoint);
  CHECK(r.points.size() < in.size());
  CHECK(r.after.bits < r.before.bits);
  // Run again here, without the oracle: dlab::run and the exact validator.
  const RunResult res = dlab::run(r.points, pair.options(kLawsonOrderSeed));
  CHECK(classify(r.points, res, false, Validate::always).kind == OutcomeClass::not_delaunay);
  // Deterministic: the same tests, the same answer.
  const ShrinkReport again = shrink(in, same, lim);
  CHECK(again.points.p2 == r.points.p2);
  CHECK(again.tests == r.tests);
}

TEST_CASE("shrink: a crashing child is a failure the shrinker survives and shrinks", "[shrink]") {
  // Catch2's SIGABRT handler would run in the children (fork keeps it): the default, as in dlab.
  struct DefaultAbort {
    struct sigaction saved {};
    DefaultAbort() {
      struct sigaction dfl {};
      dfl.sa_handler = SIG_DFL;
      sigaction(SIGABRT, &dfl, &saved);
    }
    ~DefaultAbort() { sigaction(SIGABRT, &saved, nullptr); }
  } default_abort;
  const Pair pair = make_pair("bowyer-watson", "float");
  const ChildOracle oracle(pair, 0, Limits{}, parse_selftest("crash@0:float"));
  const Observed o = oracle.observe(set2(kLawsonFloatFailure));
  REQUIRE(o.outcome == "crash");
  CHECK(o.kind == "SIGABRT");
  const FailureClass target{o.outcome, o.kind};
  const ShrinkReport r =
      shrink(set2(kLawsonFloatFailure), [&](const PointSet& p) { return target.matches(oracle.observe(p)); },
             ShrinkLimits{});
  CHECK(r.points.p2 == std::vector<Point2>{{0, 0}});  // every set crashes: one point, at the origin
  CHECK(r.fixpoint);
}
