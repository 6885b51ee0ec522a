// The outcome classification (variants/outcome.hpp), the driver's count of
// inserted points (variants/driver.hpp) and `dlab flip`'s engine
// (variants/flip.hpp), on hand-built meshes whose verdict is known by
// construction: the kite 0 (0,0), 1 (4,0), 2 (2,1), 3 (2,-1), whose Delaunay
// triangulation uses the short diagonal 2-3 (|23| = 2 < |01| = 4, and 0, 1 lie
// outside the circle on 2-3's triangles), and broken versions of it.
#include <catch2/catch.hpp>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/triangulation_result.hpp"
#include "predicates/float_kernel.hpp"
#include "variants/driver.hpp"
#include "variants/flip.hpp"
#include "variants/outcome.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

PointSet kite() {
  PointSet p;
  p.dimension = 2;
  p.p2 = {{0, 0}, {4, 0}, {2, 1}, {2, -1}};
  return p;
}
const std::vector<std::uint32_t> kDelaunay = {0, 3, 2, 3, 1, 2};  // short diagonal 2-3
const std::vector<std::uint32_t> kLong = {0, 1, 2, 0, 3, 1};      // long diagonal 0-1

RunResult result_with(const std::vector<std::uint32_t>& simplices) {
  RunResult r;
  r.dimension = 2;
  r.points = kite();
  r.simplices = simplices;
  return r;
}

}  // namespace

TEST_CASE("each class has one name and one exit status", "[outcome]") {
  CHECK(outcome_name(OutcomeClass::ok) == "ok");
  CHECK(outcome_name(OutcomeClass::lower_dimensional) == "lower-dimensional");
  CHECK(outcome_name(OutcomeClass::not_delaunay) == "not-delaunay");
  CHECK(outcome_name(OutcomeClass::invalid) == "invalid");
  CHECK(outcome_name(OutcomeClass::reported) == "reported");
  CHECK(exit_status(OutcomeClass::ok) == 0);
  CHECK(exit_status(OutcomeClass::lower_dimensional) == 0);
  CHECK(exit_status(OutcomeClass::not_delaunay) == 1);
  CHECK(exit_status(OutcomeClass::invalid) == 1);
  CHECK(exit_status(OutcomeClass::reported) == 1);
}

TEST_CASE("which pairs promise a Delaunay triangulation", "[outcome]") {
  RunOptions o;
  for (const char* k : {"adaptive", "integer", "mp"}) {
    o.kernel = k;
    o.algorithm = "bowyer-watson";
    CHECK(pair_is_exact(o));
    o.algorithm = "george";  // the floating sphere test
    CHECK_FALSE(pair_is_exact(o));
    o.exact_sphere = true;
    CHECK(pair_is_exact(o));
    o.enclosing_box = true;  // the box's removal may leave the hull uncovered
    CHECK_FALSE(pair_is_exact(o));
    o.exact_sphere = o.enclosing_box = false;
  }
  for (const char* k : {"float", "epsilon"}) {
    o.kernel = k;
    o.algorithm = "lawson";
    CHECK_FALSE(pair_is_exact(o));
  }
}

TEST_CASE("classify: ok, not-delaunay, invalid and reported on the kite", "[outcome]") {
  const PointSet in = kite();
  SECTION("the Delaunay triangulation is ok, silent") {
    const Outcome o = classify(in, result_with(kDelaunay), false);
    CHECK(o.kind == OutcomeClass::ok);
    CHECK(o.validated);
    CHECK(o.detail.empty());
  }
  SECTION("the long diagonal is not-delaunay: one facet") {
    const Outcome o = classify(in, result_with(kLong), false);
    CHECK(o.kind == OutcomeClass::not_delaunay);
    CHECK(o.count == 1);
    CHECK(o.detail.rfind("1 facet not locally Delaunay (first: simplex ", 0) == 0);
    CHECK(outcome_line("triangulate", o, "lawson, float kernel") ==
          "dlab triangulate: not-delaunay: " + o.detail + " (lawson, float kernel)");
  }
  SECTION("clockwise triangles are invalid: orientation") {
    const Outcome o = classify(in, result_with({0, 2, 3, 3, 2, 1}), false);
    CHECK(o.kind == OutcomeClass::invalid);
    CHECK(o.check == "orientation");
    CHECK(o.first_check == Check::orientation);
    CHECK(o.count == 2);
    CHECK(o.detail.rfind("orientation: 2 simplices not positively oriented (first: simplex 0)", 0) == 0);
  }
  SECTION("a missing triangle leaves a point out: missing-point") {
    const Outcome o = classify(in, result_with({0, 3, 2}), false);
    CHECK(o.kind == OutcomeClass::invalid);
    CHECK(o.check == "missing-point");
    CHECK(o.detail.rfind("missing-point: 1 distinct point in no simplex (first: point 1)", 0) == 0);
  }
  SECTION("overlapping triangles: overlap") {
    const Outcome o = classify(in, result_with({0, 3, 2, 3, 1, 2, 0, 1, 2}), false);
    CHECK(o.kind == OutcomeClass::invalid);
    CHECK(o.check == "overlap");
  }
  SECTION("a listed duplicate index: indices") {
    PointSet dup = kite();
    dup.p2.push_back({4, 0});  // point 4 repeats point 1
    RunResult r = result_with({0, 3, 2, 3, 4, 2});
    r.points = dup;
    const Outcome o = classify(dup, r, false);
    CHECK(o.kind == OutcomeClass::invalid);
    CHECK(o.check == "indices");
  }
  SECTION("the algorithm's failure is reported, its message on one line, not validated") {
    RunResult r = result_with({});
    r.outcome = RunResult::Outcome::failed;
    r.message = "walk exceeded\nits bound";
    const Outcome o = classify(in, r, false);
    CHECK(o.kind == OutcomeClass::reported);
    CHECK_FALSE(o.validated);
    CHECK(o.detail == "walk exceeded its bound");
  }
}

TEST_CASE("classify: lower-dimensional input keeps the algorithm's reason", "[outcome]") {
  PointSet line;
  line.dimension = 2;
  line.p2 = {{0, 0}, {1, 1}, {2, 2}};
  RunResult r;
  r.points = line;
  r.outcome = RunResult::Outcome::lower_dimensional;
  r.message = "all 3 points are collinear";
  const Outcome o = classify(line, r, true);
  CHECK(o.kind == OutcomeClass::lower_dimensional);
  CHECK(o.detail == "all 3 points are collinear");
  CHECK_FALSE(o.bug());
  // An algorithm that calls full-dimensional input flat and returns nothing
  // leaves every point out: invalid, not lower-dimensional.
  RunResult flat = result_with({});
  flat.outcome = RunResult::Outcome::lower_dimensional;
  CHECK(classify(kite(), flat, false).kind == OutcomeClass::invalid);
}

TEST_CASE("classify: an exact pair is trusted unless asked, and any failure of it is a bug", "[outcome]") {
  const PointSet in = kite();
  const RunResult wrong = result_with(kLong);
  const Outcome trusted = classify(in, wrong, true, Validate::unless_exact);
  CHECK(trusted.kind == OutcomeClass::ok);
  CHECK_FALSE(trusted.validated);
  const Outcome judged = classify(in, wrong, true, Validate::always);
  CHECK(judged.kind == OutcomeClass::not_delaunay);
  CHECK(judged.bug());
  const std::string line = outcome_line("triangulate", judged, "bowyer-watson, adaptive kernel");
  const std::string suffix = "(bowyer-watson, adaptive kernel); a bug: the pair is exact";
  REQUIRE(line.size() > suffix.size());
  CHECK(line.substr(line.size() - suffix.size()) == suffix);
  // An inexact pair is judged whatever `when` says, and its failures are no bug.
  const Outcome inexact = classify(in, wrong, false, Validate::unless_exact);
  CHECK(inexact.kind == OutcomeClass::not_delaunay);
  CHECK_FALSE(inexact.bug());
}

TEST_CASE("classify reuses a report the run attached", "[outcome]") {
  // A report saying not-delaunay on a result that is in fact Delaunay: the
  // classification must come from the attached report, not a new validation.
  RunResult r = result_with(kDelaunay);
  auto rep = std::make_shared<ValidationReport>(validate(kite(), kLong));
  r.validation = rep;
  CHECK(classify(kite(), r, true, Validate::unless_exact).kind == OutcomeClass::not_delaunay);
}

TEST_CASE("describe_pair names George's variants", "[outcome]") {
  RunOptions o;
  o.algorithm = "george";
  o.kernel = "integer";
  o.enclosing_box = true;
  CHECK(describe_pair(o) == "george --enclosing-box, integer kernel");
}

namespace {

// An algorithm that inserts the first kStop points of its sequence (making
// the second copy of a repeated point a duplicate of the first) and then fails.
constexpr std::uint32_t kStop = 5;
template <class K, int D>
struct FailAfter {
  explicit FailAfter(const K& k) : k_(k) {}
  TriangulationResult run(std::span<const Point<D>> pts) {
    TriangulationResult t;
    t.merged_into.assign(pts.size(), kNotProcessed);
    for (std::uint32_t i = 0; i < kStop && i < pts.size(); ++i) {
      t.merged_into[i] = i;
      for (std::uint32_t j = 0; j < i; ++j)
        if (pts[j] == pts[i]) {
          t.merged_into[i] = j;
          break;
        }
    }
    t.outcome = RunResult::Outcome::failed;
    t.message = "stopped on purpose";
    return t;
  }
  const K& kernel() const { return k_; }
  K k_;
};

// An algorithm that throws after looking at the (2D) points it is given.
std::vector<Point2> seen_before_throw;
template <class K, int D>
struct ThrowMidRun {
  explicit ThrowMidRun(const K& k) : k_(k) {}
  TriangulationResult run(std::span<const Point<D>> pts) {
    if constexpr (D == 2) seen_before_throw.assign(pts.begin(), pts.end());
    throw std::runtime_error("thrown on purpose");
  }
  const K& kernel() const { return k_; }
  K k_;
};

}  // namespace

TEST_CASE("a run that takes the points gives them back in order, or leaves them as they were after a throw",
          "[outcome][driver]") {
  PointSet original;
  original.dimension = 2;
  for (int i = 0; i < 200; ++i) original.p2.push_back({double((i * 37) % 101), double((i * 53) % 97)});
  RunOptions o;
  o.kernel = "float";
  o.policy = "strict";
  o.order = "brio";
  PointSet p = original;
  CHECK_THROWS_AS((run_algorithm<ThrowMidRun, FloatKernel>(std::move(p), o)), std::runtime_error);
  CHECK(seen_before_throw.size() == original.p2.size());
  CHECK(seen_before_throw != original.p2);  // the algorithm saw them in BRIO order
  CHECK(p.p2 == original.p2);                              // and they were put back
  o.kernel = "adaptive";
  o.policy = "sos";
  PointSet q = original;
  const RunResult r = run(std::move(q), o);
  CHECK(r.outcome == RunResult::Outcome::ok);
  CHECK(r.points.p2 == original.p2);
}

TEST_CASE("stats of a failed run: points inserted before the failure, apart from the distinct points",
          "[outcome][driver]") {
  PointSet p;
  p.dimension = 2;
  // 9 points, 8 distinct (point 1 repeats point 0, inside the first 5).
  p.p2 = {{0, 0}, {0, 0}, {1, 0}, {0, 1}, {1, 1}, {2, 0}, {2, 1}, {2, 2}, {3, 3}};
  RunOptions o;
  o.kernel = "float";
  o.policy = "strict";
  o.order = "input";
  const RunResult r = run_algorithm<FailAfter, FloatKernel>(p, o);
  CHECK(r.outcome == RunResult::Outcome::failed);
  CHECK(r.inserted_points == kStop);
  CHECK(r.distinct_points == 8);
}

TEST_CASE("run_flip: every kernel flips the kite's long diagonal away", "[outcome][flip]") {
  for (const char* k : {"adaptive", "integer", "mp", "float", "epsilon"}) {
    RunOptions o;
    o.kernel = k;
    const RunResult r = run_flip(kite(), kLong, o);
    INFO(k);
    CHECK(r.outcome == RunResult::Outcome::ok);
    const Outcome c = classify(kite(), r, true, Validate::always);
    CHECK(c.kind == OutcomeClass::ok);
    bool flips = false;
    for (const auto& [key, v] : r.counters) flips = flips || (key == "flips_total" && v == 1);
    CHECK(flips);
    CHECK(!r.predicates.empty());
  }
  RunOptions bad;
  bad.kernel = "quad";
  CHECK_THROWS_AS(run_flip(kite(), kLong, bad), UsageError);
}
