// The campaign driver's parts that can be checked without processes
// (tests/test_fuzz_campaign.sh runs `dlab fuzz` end to end):
//   - case seeds are splitmix64's outputs (stepped independently here);
//   - the Wilson interval against published values (Newcombe 1998);
//   - records survive the JSON round trip, keys in the documented order;
//   - `differs`: a valid Delaunay triangulation of a cocircular set that is not
//     the perturbed one is caught; the same triangulation in another vertex
//     order is not;
//   - the reference shortcut: a valid Delaunay result without cospherical
//     facets equals the mp reference (checked on strict-policy results, which
//     are not the perturbed ones in general, so a wrong count would show);
//   - resume's scan of a results file: torn line, incomplete case, garbage.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "algorithms/canonical_simplices.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/campaign_files.hpp"
#include "fuzz/case_plan.hpp"
#include "fuzz/failures.hpp"
#include "fuzz/fuzz_outcome.hpp"
#include "fuzz/generators.hpp"
#include "fuzz/record.hpp"
#include "fuzz/reference.hpp"
#include "fuzz/summary.hpp"

namespace {

using namespace dlab;
using namespace dlab::fuzz;

PointSet set2(std::vector<Point2> p) {
  PointSet s;
  s.dimension = 2;
  s.p2 = std::move(p);
  return s;
}

template <int D>
bool same_triangulation(const RunResult& a, const RunResult& b) {
  return canonical_simplices<D>(a.simplices) == canonical_simplices<D>(b.simplices);
}

}  // namespace

TEST_CASE("fuzz: case seeds are the outputs of splitmix64 seeded with the campaign seed", "[fuzz]") {
  for (std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{7}, ~std::uint64_t{0}}) {
    std::uint64_t state = seed;  // splitmix64 stepped by hand (Steele, Lea, Flood 2014)
    for (std::uint64_t i = 0; i < 200; ++i) {
      std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
      z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      z ^= z >> 31;
      REQUIRE(case_seed(seed, i) == z);
    }
  }
}

TEST_CASE("fuzz: Wilson score intervals match Newcombe (1998), method 3", "[fuzz]") {
  // Newcombe, "Two-sided confidence intervals for the single proportion",
  // Statistics in Medicine 17 (1998), Table II, Wilson score without correction.
  struct Row {
    std::uint64_t x, n;
    double lo, hi;
  };
  for (const Row& r : {Row{81, 263, 0.2553, 0.3662}, Row{15, 148, 0.0624, 0.1605}, Row{0, 20, 0.0, 0.1611},
                       Row{1, 29, 0.0061, 0.1718}}) {
    const Interval ci = wilson_interval(r.x, r.n);
    CHECK(ci.lo == Approx(r.lo).margin(5e-5));
    CHECK(ci.hi == Approx(r.hi).margin(5e-5));
  }
  CHECK(wilson_interval(0, 10).lo == 0.0);  // exactly, not -1e-17
  CHECK(wilson_interval(10, 10).hi == 1.0);
}

TEST_CASE("fuzz: a record's JSON line reads back, keys in order, zero counters left out", "[fuzz]") {
  PairRecord r;
  r.case_index = 81731;
  r.seed = ~std::uint64_t{0};
  r.gen = "near-degenerate";
  r.gen_args = "--base lattice --ulps 3";
  r.n = 20;
  r.dim = 3;
  r.algo = "george+exact-sphere";
  r.kernel = "float";
  r.exact = false;
  r.outcome = "reported";
  r.kind = message_kind("walk exceeded 1200 steps at point 7");
  r.detail = "quote \" backslash \\ newline \n tab \t bell \x07 end";
  r.counters = {{"walk_steps", 12}, {"flips", 0}};
  r.predicates = {{"orient3d", 5}};
  r.seconds = 0.125;
  CHECK(r.kind == "walk exceeded # steps at point #");
  const std::string line = to_json_line(r);
  CHECK(line.find('\n') == std::string::npos);
  CHECK(line.rfind("{\"case\":81731,\"seed\":18446744073709551615,\"gen\":\"near-degenerate\",\"gen_args\":", 0) == 0);
  CHECK(line.find("\"counters\":{\"walk_steps\":12},\"predicates\":{\"orient3d\":5},\"seconds\":0.125}") !=
        std::string::npos);
  const PairRecord b = parse_json_line(line);
  CHECK(b.case_index == r.case_index);
  CHECK(b.seed == r.seed);
  CHECK(b.gen == r.gen);
  CHECK(b.gen_args == r.gen_args);
  CHECK(b.n == r.n);
  CHECK(b.dim == r.dim);
  CHECK(b.algo == r.algo);
  CHECK(b.kernel == r.kernel);
  CHECK(b.exact == r.exact);
  CHECK(b.outcome == r.outcome);
  CHECK(b.kind == r.kind);
  CHECK(b.detail == r.detail);
  CHECK(b.counters == Counters{{"walk_steps", 12}});
  CHECK(b.predicates == r.predicates);
  CHECK(b.seconds == r.seconds);
  CHECK_THROWS(parse_json_line(line.substr(0, line.size() - 1)));
  CHECK_THROWS(parse_json_line("{\"case\":1}"));
}

TEST_CASE("fuzz: differs catches a Delaunay triangulation that is not the perturbed one", "[fuzz]") {
  // A square: both diagonals give a Delaunay triangulation; the perturbation picks one.
  const PointSet square = set2({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  Reference ref(square);
  const RunResult& perturbed = ref.result();
  REQUIRE(perturbed.simplices.size() == 6);
  const auto chosen = canonical_simplices<2>(perturbed.simplices);
  // The other diagonal, written by hand, each triangle counterclockwise.
  RunResult other;
  other.dimension = 2;
  const bool diagonal_02 = chosen == canonical_simplices<2>(std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  other.simplices = diagonal_02 ? std::vector<std::uint32_t>{0, 1, 3, 1, 2, 3} : std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3};
  // Independent of the code under test: the validator finds both valid Delaunay, one cospherical facet each.
  for (const RunResult* t : {&perturbed, static_cast<const RunResult*>(&other)}) {
    const ValidationReport rep = validate(square, t->simplices);
    REQUIRE(rep.delaunay());
    CHECK(rep.cospherical_facets == 1);
  }
  Outcome ok;
  const Outcome d = compare_with_reference(ok, other, perturbed);
  CHECK(d.kind == OutcomeClass::differs);
  CHECK(d.count == 2);
  CHECK(outcome_name(d.kind) == "differs");
  // The perturbed triangulation itself, each triangle rotated and listed in reverse: ok.
  RunResult same = other;
  same.simplices.clear();
  for (std::size_t s = perturbed.simplices.size(); s >= 3; s -= 3)
    for (int j : {1, 2, 0}) same.simplices.push_back(perturbed.simplices[s - 3 + j]);
  CHECK(compare_with_reference(ok, same, perturbed).kind == OutcomeClass::ok);
  // Failures pass through unchanged.
  Outcome bad;
  bad.kind = OutcomeClass::not_delaunay;
  CHECK(compare_with_reference(bad, other, perturbed).kind == OutcomeClass::not_delaunay);
}

TEST_CASE("fuzz: a valid Delaunay result without cospherical facets is the perturbed reference", "[fuzz]") {
  // Strict-policy results are *a* Delaunay triangulation, not the perturbed one
  // in general: where the validator counts no cospherical facet they must equal
  // the reference (the campaign then skips it); where it counts some, at least
  // one differs in this sample (so the count is not vacuous).
  int unique = 0, degenerate = 0, differing = 0;
  for (int dim : {2, 3})
    for (const char* g : {"lattice", "near-degenerate", "uniform", "near-duplicates", "collinear", "rotated-lattice"})
      for (std::uint64_t seed = 1; seed <= 12; ++seed) {
        gen::GenOptions o;
        o.name = g;
        o.dim = dim;
        o.n = 5 + seed * 2;
        o.seed = seed;
        o.base = "lattice";
        const PointSet pts = gen::generate(o);
        RunOptions ro;
        ro.kernel = "adaptive";
        ro.policy = "strict";
        ro.order = "random";
        ro.seed = seed;
        const RunResult r = run(pts, ro);
        if (r.outcome != RunResult::Outcome::ok) continue;
        const ValidationReport rep = validate(pts, r.simplices);
        REQUIRE(rep.delaunay());
        Reference ref(pts);
        const bool same = dim == 2 ? same_triangulation<2>(r, ref.result()) : same_triangulation<3>(r, ref.result());
        if (rep.cospherical_facets == 0) {
          ++unique;
          INFO(g << " dim " << dim << " seed " << seed);
          CHECK(same);
        } else {
          ++degenerate;
          differing += same ? 0 : 1;
        }
      }
  CHECK(unique > 20);
  CHECK(degenerate > 20);
  CHECK(differing > 0);
}

TEST_CASE("fuzz: the reference equals Bowyer-Watson x mp under sos (the CGAL-identical one)", "[fuzz]") {
  int degenerate = 0;
  for (int dim : {2, 3})
    for (const char* g : {"lattice", "cocircular", "near-degenerate", "near-duplicates", "collinear",
                          "rotated-lattice", "half-integers", "tiny", "huge"})
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        gen::GenOptions o;
        o.name = g;
        o.dim = dim;
        o.n = 6 + seed * 4;
        o.seed = seed;
        const PointSet pts = gen::generate(o);
        RunOptions mp;
        mp.kernel = "mp";
        const RunResult a = run_reference(pts), b = run(pts, mp);
        INFO(g << " dim " << dim << " seed " << seed);
        CHECK(a.outcome == b.outcome);
        CHECK((dim == 2 ? same_triangulation<2>(a, b) : same_triangulation<3>(a, b)));
        if (a.outcome == RunResult::Outcome::ok && validate(pts, a.simplices).cospherical_facets > 0) ++degenerate;
      }
  CHECK(degenerate > 30);  // the perturbation decided something
}

TEST_CASE("fuzz: resume scans whole cases and drops a torn or incomplete last one", "[fuzz]") {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("dlab_fuzz_scan_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string path = (dir / "results.jsonl").string();
  CampaignSpec spec;
  spec.shard = 2;
  spec.shards = 3;  // cases 1, 4, 7, ...
  PairRecord r;
  const auto line = [&](std::uint64_t c) {
    r.case_index = c;
    return to_json_line(r) + "\n";
  };
  const std::string two_cases = line(1) + line(1) + line(4) + line(4);
  const auto write = [&](const std::string& s) { std::ofstream(path, std::ios::binary) << s; };

  write(two_cases + line(7) + line(7).substr(0, 30));  // case 7 torn in its second line
  ResultsScan s = scan_results(path, spec, 2);
  CHECK(s.cases == 2);
  CHECK(s.bytes == two_cases.size());
  CHECK(s.dropped_lines == 2);

  write(two_cases + line(7));  // case 7 incomplete but not torn
  s = scan_results(path, spec, 2);
  CHECK(s.cases == 2);
  CHECK(s.dropped_lines == 1);

  write(line(1) + "garbage\n" + line(4) + line(4));
  CHECK_THROWS_AS(scan_results(path, spec, 2), UsageError);
  write(line(1) + line(1) + line(7) + line(7));  // case 4 missing: another shard's file?
  CHECK_THROWS_AS(scan_results(path, spec, 2), UsageError);
  fs::remove_all(dir);
}

TEST_CASE("fuzz: failure signatures name files apart", "[fuzz]") {
  const Signature a{"george+exact-sphere", "float", 2, "reported", "walk exceeded # steps"};
  const Signature b{"george+exact-sphere", "float", 2, "reported", "walk exceeded # steps!"};
  CHECK(a.file_stem().rfind("george+exact-sphere.float.2d.reported.walk-exceeded-steps-", 0) == 0);
  CHECK(a.file_stem() != b.file_stem());
  CHECK(Signature{"lawson", "float", 3, "not-delaunay", ""}.file_stem() == "lawson.float.3d.not-delaunay");
}
