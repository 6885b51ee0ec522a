// Oracle properties (issue 3, design.md section 4): every exact kernel
// (adaptive, integer, mp) through dlab::run() gives a triangulation that
//   - passes the exact validator (algorithms/validate),
//   - equals CGAL's Delaunay_triangulation_2/3 (Epick) on the same points,
//     simplex for simplex (sos policy; `integer` on its snapped points),
//   - does not depend on the insertion order (input, random x 2 seeds, brio, hilbert);
// and the strict policy passes the validator. Inputs: random and degenerate
// generators in 2D and 3D (small integer lattices full of cocircular and
// cospherical ties, scaled and translated lattices, rotated lattices, exact
// cocircular / cospherical sets, collinear / coplanar sets with a few points
// off, k-ulp perturbations, near-duplicates, huge and tiny magnitudes).
// With `float`, a fixed seeded batch of near-degenerate inputs must show at
// least one failure (reported or caught by the validator), and never a crash.
// The validator itself is cross-checked against CGAL: CGAL's output passes it,
// and CGAL's output with one simplex removed, reversed or one edge flipped
// fails it for the right reason.
#include <rapidcheck/catch.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <ctime>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/mp_kernel.hpp"
#include "tests/cgal_oracle.hpp"
#include "variants/run.hpp"

namespace {

using dlab::Point;
using dlab::Point2;
using dlab::Point3;
using dlab::PointSet;
using dlab::point_set;
using dlab::points_of;
using dlab::RunOptions;
using dlab::RunResult;
using Outcome = dlab::RunResult::Outcome;

// A comma-separated list from the environment, or the default (debugging only:
// DLAB_ORACLE_KERNELS=mp,integer, DLAB_ORACLE_ALGORITHMS=bowyer-watson).
std::vector<std::string> list_from_env(const char* name, std::vector<std::string> fallback) {
  const char* env = std::getenv(name);
  if (env == nullptr || *env == 0) return fallback;
  std::vector<std::string> out(1);
  for (const char* c = env; *c; ++c)
    if (*c == ',')
      out.emplace_back();
    else
      out.back() += *c;
  return out;
}
std::vector<std::string> exact_kernels() {
  return list_from_env("DLAB_ORACLE_KERNELS", {"adaptive", "integer", "mp"});
}
const std::vector<std::string> kExactKernels = exact_kernels();

std::string outcome_name(Outcome o) {
  switch (o) {
    case Outcome::ok:
      return "ok";
    case Outcome::lower_dimensional:
      return "lower_dimensional";
    case Outcome::failed:
      return "failed";
  }
  return "?";
}

// Algorithms other than Bowyer-Watson join these properties as soon as the
// registry has them (issues 4-6); Bowyer-Watson must always be there.
bool available(const std::string& algorithm, const std::string& kernel) {
  static std::map<std::pair<std::string, std::string>, bool> cache;
  const auto key = std::make_pair(algorithm, kernel);
  if (auto it = cache.find(key); it != cache.end()) return it->second;
  bool ok = true;
  try {
    RunOptions o;
    o.algorithm = algorithm;
    o.kernel = kernel;
    dlab::run(point_set<2>({{0, 0}, {1, 0}, {0, 1}}), o);
  } catch (const dlab::UsageError&) {
    ok = algorithm == "bowyer-watson";  // must exist: let the property fail on it
  }
  return cache[key] = ok;
}

// ---- point-set generators -----------------------------------------------

// Random integers in [-r, r]^D, with r small: duplicates, collinear and
// cocircular / cospherical subsets everywhere. Shrinks point by point.
template <int D>
rc::Gen<std::vector<Point<D>>> small_lattice(int max_n) {
  return rc::gen::mapcat(rc::gen::inRange(1, 7), [max_n](int r) {
    return rc::gen::map(rc::gen::container<std::vector<std::array<int, D>>>(
                            rc::gen::container<std::array<int, D>>(rc::gen::inRange(-r, r + 1))),
                        [max_n](const std::vector<std::array<int, D>>& v) {
                          std::vector<Point<D>> p(std::min(v.size(), static_cast<std::size_t>(max_n)));
                          for (std::size_t i = 0; i < p.size(); ++i)
                            for (int j = 0; j < D; ++j) p[i][j] = v[i][j];
                          return p;
                        });
  });
}

const char* const kFamilies[] = {
    "lattice",         "scaled-lattice", "uniform", "cospherical+inner", "rotated", "flat+off", "ulp-lattice",
    "near-duplicates", "huge",           "tiny"};

// One point set from a family; every family is exact-degenerate or near it.
template <int D>
std::vector<Point<D>> family_points(int family, std::size_t n, std::uint64_t seed,
                                    const std::vector<Point<D>>& lattice) {
  namespace gen = dlab::gen;
  switch (family) {
    case 0:
      return lattice;
    case 1: {  // times 2^e plus an offset: exact (integers below 2^8, e in [-40, 40])
      const int e = static_cast<int>(seed % 81) - 40;
      auto p = lattice;
      for (auto& q : p)
        for (double& c : q) c = std::ldexp(c, e) + 0.75;
      return p;
    }
    case 2:
      return gen::uniform<D>(n, seed);
    case 3: {
      auto p = gen::cospherical<D>(std::max<std::size_t>(n, 4), seed);
      const auto inner = gen::uniform<D>(n / 8, seed + 1, -0.5, 0.5);
      p.insert(p.end(), inner.begin(), inner.end());
      return p;
    }
    case 4:
      return gen::rotated_lattice<D>(n);
    case 5:
      if constexpr (D == 3)
        if (seed % 2) return gen::coplanar(n, seed % 4, seed);
      return gen::collinear<D>(n, seed % 4, seed);
    case 6: {
      auto p = gen::lattice<D>(n);
      gen::scale_to_unit<D>(p);
      return gen::perturb_ulps<D>(p, 1 + static_cast<std::int64_t>(seed % 3), seed);
    }
    case 7:
      return gen::near_duplicates<D>(n, seed, 3, static_cast<std::int64_t>(seed % 3));
    case 8:
      return gen::huge<D>(n, seed, 900 + static_cast<int>(seed % 100));
    default:
      return gen::tiny<D>(n, seed);
  }
}

// ---- the properties --------------------------------------------------------

// For one algorithm x exact kernel: valid, equal to CGAL, order-independent;
// the strict policy valid (george: with its exact sphere test; with the
// default floating one, valid only). `cgal_input` is CGAL's answer on the input points
// (recomputed here when the kernel snapped them).
template <int D>
void check_exact(const std::string& algorithm, const std::string& kernel, const PointSet& input,
                 const std::vector<dlab::oracle::Simplex<D>>& cgal_input) {
  RC_LOG() << algorithm << " x " << kernel << "\n";
  RunOptions o;
  o.algorithm = algorithm;
  o.kernel = kernel;
  o.policy = "sos";
  o.order = "brio";
  o.seed = 1;
  if (algorithm == "george") {
    // George's default sphere test is floating (George 1997 section 2.4): the
    // result must be valid, Delaunay or not. With the exact test, all below holds.
    for (const char* policy : {"sos", "strict"}) {
      RunOptions og = o;
      og.policy = policy;
      const RunResult rg = dlab::run(input, og);
      RC_ASSERT(rg.outcome != Outcome::failed);
      const dlab::ValidationReport repg = dlab::validate(rg.points, rg.simplices);
      RC_LOG() << "floating spheres, " << policy << ": " << repg.summary();
      RC_ASSERT(repg.valid());
    }
    o.exact_sphere = true;
  }
  const RunResult r = dlab::run(input, o);
  RC_LOG() << "outcome " << outcome_name(r.outcome) << ": " << r.message << "\n";
  RC_ASSERT(r.outcome != Outcome::failed);
  const auto& q = points_of<D>(r.points);
  RC_ASSERT(q.size() == input.size());
  const dlab::ValidationReport rep = dlab::validate(r.points, r.simplices);
  RC_LOG() << rep.summary();
  RC_ASSERT(rep.delaunay());

  const bool snapped = q != points_of<D>(input);
  const auto cgal = snapped ? dlab::oracle::cgal_delaunay(q) : cgal_input;
  const auto mine = dlab::oracle::canonical_simplices<D>(r.simplices);
  RC_ASSERT((r.outcome == Outcome::lower_dimensional) == cgal.empty());
  RC_ASSERT(mine.size() == cgal.size());
  RC_ASSERT(mine == cgal);

  for (const auto& [order, seed] :
       {std::pair<const char*, std::uint64_t>{"input", 0}, {"random", 7}, {"random", 8}, {"hilbert", 0}}) {
    RunOptions o2 = o;
    o2.order = order;
    o2.seed = seed;
    const RunResult r2 = dlab::run(input, o2);
    RC_LOG() << "order " << order << " seed " << seed << ": " << outcome_name(r2.outcome) << "\n";
    RC_ASSERT(r2.outcome == r.outcome);
    const dlab::ValidationReport rep2 = dlab::validate(r2.points, r2.simplices);
    RC_LOG() << rep2.summary();
    RC_ASSERT(rep2.delaunay());
    RC_ASSERT(dlab::oracle::canonical_simplices<D>(r2.simplices) == mine);
  }

  RunOptions os = o;
  os.policy = "strict";
  const RunResult rs = dlab::run(input, os);
  RC_ASSERT(rs.outcome != Outcome::failed);
  const dlab::ValidationReport reps = dlab::validate(rs.points, rs.simplices);
  RC_LOG() << "strict: " << reps.summary();
  RC_ASSERT(reps.delaunay());
}

template <int D>
void exact_property(const std::string& algorithm, std::size_t max_n) {
  const int family = *rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
  const auto n = *rc::gen::inRange(std::size_t{0}, max_n + 1);
  const auto seed = *rc::gen::inRange<std::uint64_t>(1, 1000000);
  const auto lattice = (family <= 1) ? *small_lattice<D>(static_cast<int>(max_n)) : std::vector<Point<D>>{};
  RC_TAG(kFamilies[family]);
  const auto pts = family_points<D>(family, n, seed, lattice);
  RC_LOG() << kFamilies[family] << " n=" << pts.size() << " seed=" << seed << "\n";
  const PointSet input = point_set<D>(pts);
  const auto cgal = dlab::oracle::cgal_delaunay(pts);
  RC_CLASSIFY(cgal.empty(), "lower-dimensional");
  for (const std::string& kernel : kExactKernels)
    if (available(algorithm, kernel)) check_exact<D>(algorithm, kernel, input, cgal);
}

// One property per registered algorithm (so that each one's verdict shows apart).
template <int D>
void exact_properties(std::size_t max_n) {
  for (const std::string& algorithm : list_from_env("DLAB_ORACLE_ALGORITHMS", dlab::algorithm_names()))
    rc::prop(std::to_string(D) + "D " + algorithm + ": valid, identical to CGAL, order-independent",
             [algorithm, max_n] { exact_property<D>(algorithm, max_n); });
}

// Local Delaunay flip of one interior edge (2D), for the validator cross-check.
bool flip_first_convex_edge(const std::vector<Point2>& p, std::vector<std::uint32_t>& t, bool& cocircular) {
  const dlab::MpKernel k;
  const std::size_t m = t.size() / 3;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::size_t> edge;  // directed edge -> triangle
  for (std::size_t s = 0; s < m; ++s)
    for (int i = 0; i < 3; ++i) edge[{t[3 * s + i], t[3 * s + (i + 1) % 3]}] = s;
  for (const auto& [e, s] : edge) {
    const auto it = edge.find({e.second, e.first});
    if (it == edge.end()) continue;
    const std::size_t u = it->second;
    const auto apex = [&](std::size_t tri) {
      for (int i = 0; i < 3; ++i)
        if (t[3 * tri + i] != e.first && t[3 * tri + i] != e.second) return t[3 * tri + i];
      return e.first;
    };
    const std::uint32_t a = e.first, b = e.second, c = apex(s), d = apex(u);
    // Triangles (a,b,c) and (b,a,d); the flip gives (c,d,b)... only if abcd is strictly convex.
    if (k.orient2d(p[c], p[d], p[b]) != dlab::Sign::positive ||
        k.orient2d(p[d], p[c], p[a]) != dlab::Sign::positive)
      continue;
    cocircular = k.incircle(p[a], p[b], p[c], p[d]) == dlab::Sign::zero;
    t[3 * s] = c, t[3 * s + 1] = d, t[3 * s + 2] = b;
    t[3 * u] = d, t[3 * u + 1] = c, t[3 * u + 2] = a;
    return true;
  }
  return false;
}

}  // namespace

TEST_CASE("oracle: exact kernels equal CGAL in 2D", "[oracle]") {
  exact_properties<2>(300);
}

TEST_CASE("oracle: exact kernels equal CGAL in 3D", "[oracle]") {
  exact_properties<3>(100);
}

TEST_CASE("oracle: the validator accepts CGAL and rejects it broken", "[oracle][validate]") {
  rc::prop("2D", [] {
    const int family = *rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    const auto lattice = *small_lattice<2>(150);
    const auto pts =
        family_points<2>(family, *rc::gen::inRange(3, 150), *rc::gen::inRange(1, 100000), lattice);
    RC_TAG(kFamilies[family]);
    const auto flat = dlab::oracle::flatten<2>(dlab::oracle::cgal_delaunay(pts));
    const std::span<const Point2> sp(pts);
    const auto rep = dlab::validate(sp, flat);
    RC_LOG() << rep.summary();
    RC_ASSERT(rep.delaunay());
    const std::size_t m = flat.size() / 3;
    if (m == 0) return;
    const auto s = *rc::gen::inRange<std::size_t>(0, m);
    auto removed = flat;
    removed.erase(removed.begin() + 3 * s, removed.begin() + 3 * s + 3);
    RC_ASSERT(!dlab::validate(sp, removed).valid());
    auto reversed = flat;
    std::swap(reversed[3 * s], reversed[3 * s + 1]);
    RC_ASSERT(dlab::validate(sp, reversed)[dlab::Check::orientation].count == 1);
    auto flipped = flat;
    bool cocircular = false;
    if (flip_first_convex_edge(pts, flipped, cocircular)) {
      const auto rf = dlab::validate(sp, flipped);
      RC_LOG() << "flipped: " << rf.summary();
      RC_ASSERT(rf.valid());
      RC_ASSERT(rf.delaunay() == cocircular);
    }
  });
  rc::prop("3D", [] {
    const int family = *rc::gen::elementOf(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9});
    const auto lattice = *small_lattice<3>(60);
    const auto pts =
        family_points<3>(family, *rc::gen::inRange(4, 60), *rc::gen::inRange(1, 100000), lattice);
    RC_TAG(kFamilies[family]);
    const auto flat = dlab::oracle::flatten<3>(dlab::oracle::cgal_delaunay(pts));
    const std::span<const Point3> sp(pts);
    const auto rep = dlab::validate(sp, flat);
    RC_LOG() << rep.summary();
    RC_ASSERT(rep.delaunay());
    const std::size_t m = flat.size() / 4;
    if (m == 0) return;
    const auto s = *rc::gen::inRange<std::size_t>(0, m);
    auto removed = flat;
    removed.erase(removed.begin() + 4 * s, removed.begin() + 4 * s + 4);
    RC_ASSERT(!dlab::validate(sp, removed).valid());
    auto reversed = flat;
    std::swap(reversed[4 * s], reversed[4 * s + 1]);
    RC_ASSERT(dlab::validate(sp, reversed)[dlab::Check::orientation].count == 1);
  });
}

// `float` on near-degenerate inputs: a fixed, seeded batch (the same on every
// run). Each run is classified; at least one must fail visibly, none may throw.
TEST_CASE("oracle: float fails visibly on near-degenerate input without crashing", "[oracle][float]") {
  namespace gen = dlab::gen;
  std::vector<PointSet> batch;
  batch.push_back(point_set<2>(gen::kettner_grid(16)));
  batch.push_back(point_set<2>(gen::kettner_grid(32)));
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    auto l2 = gen::lattice<2>(100 + 20 * seed);
    gen::scale_to_unit<2>(l2);
    batch.push_back(point_set<2>(gen::perturb_ulps<2>(l2, 1 + static_cast<std::int64_t>(seed % 3), seed)));
    auto c2 = gen::cospherical<2>(60, seed);
    batch.push_back(point_set<2>(gen::perturb_ulps<2>(c2, 1, seed)));
    auto l3 = gen::lattice<3>(64 + 20 * seed);
    gen::scale_to_unit<3>(l3);
    batch.push_back(point_set<3>(gen::perturb_ulps<3>(l3, 1 + static_cast<std::int64_t>(seed % 3), seed)));
    batch.push_back(point_set<3>(gen::perturb_ulps<3>(gen::cospherical<3>(40, seed), 1, seed)));
  }
  std::map<std::string, int> classes;
  int runs = 0;
  for (const std::string& algorithm : dlab::algorithm_names())
    for (const char* kernel : {"float", "epsilon"}) {
      if (!available(algorithm, kernel)) continue;
      for (const PointSet& ps : batch)
        for (const char* policy : {"sos", "strict"}) {
          RunOptions o;
          o.algorithm = algorithm;
          o.kernel = kernel;
          o.policy = policy;
          o.order = "input";
          RunResult r;
          REQUIRE_NOTHROW(r = dlab::run(ps, o));
          runs += std::string(kernel) == "float";
          std::string cls;
          if (r.outcome == Outcome::failed) {
            cls = "reported failure";
          } else {
            const auto rep = dlab::validate(r.points, r.simplices);
            cls = !rep.valid() ? "invalid mesh" : (!rep.delaunay() ? "not Delaunay" : "correct");
          }
          ++classes[algorithm + " " + kernel + " " + policy + ": " + cls];
        }
    }
  int failures = 0;
  std::string table;
  for (const auto& [cls, count] : classes) {
    table += "  " + cls + ": " + std::to_string(count) + "\n";
    if (cls.find(" float ") != std::string::npos && cls.find("correct") == std::string::npos)
      failures += count;
  }
  WARN("float and epsilon on " << batch.size() << " near-degenerate sets (" << runs << " float runs):\n"
                               << table);
  REQUIRE(runs > 0);
  CHECK(failures >= 1);
}

TEST_CASE("oracle: float never crashes (random near-degenerate sets)", "[oracle][float]") {
  rc::prop("2D float: an outcome, classified", [] {
    const auto n = *rc::gen::inRange<std::size_t>(3, 150);
    const auto seed = *rc::gen::inRange<std::uint64_t>(1, 100000);
    auto l = dlab::gen::lattice<2>(n);
    dlab::gen::scale_to_unit<2>(l);
    const auto pts = dlab::gen::perturb_ulps<2>(l, 1 + static_cast<std::int64_t>(seed % 4), seed);
    RunOptions o;
    o.kernel = "float";
    o.order = "input";
    const RunResult r = dlab::run(point_set<2>(pts), o);
    if (r.outcome == Outcome::failed) {
      RC_TAG("reported failure");
      return;
    }
    const auto rep = dlab::validate(r.points, r.simplices);
    RC_TAG(!rep.valid() ? "invalid mesh" : (!rep.delaunay() ? "not Delaunay" : "correct"));
    // Whatever it returns, the indices are in range (the validator did not skip).
    RC_ASSERT(!rep.skipped);
  });
}

// Not run by default: the validator's speed on CGAL's triangulations of 10^6
// uniform points (./dlab_oracle_tests "[.perf]"); wall and process CPU seconds.
template <int D>
void time_validator(std::size_t n) {
  using clock = std::chrono::steady_clock;
  const auto p = dlab::gen::uniform<D>(n, 1);
  const auto t0 = clock::now();
  const std::clock_t c0 = std::clock();
  const auto flat = dlab::oracle::flatten<D>(dlab::oracle::cgal_delaunay(p));
  const auto t1 = clock::now();
  const std::clock_t c1 = std::clock();
  const auto rep = dlab::validate(std::span<const Point<D>>(p), flat);
  const auto t2 = clock::now();
  const std::clock_t c2 = std::clock();
  const auto cpu = [](std::clock_t a, std::clock_t b) { return double(b - a) / CLOCKS_PER_SEC; };
  WARN(D << "D, " << n << " points, " << rep.simplices << " simplices: CGAL "
         << std::chrono::duration<double>(t1 - t0).count() << " s wall / " << cpu(c0, c1)
         << " s cpu; validate " << std::chrono::duration<double>(t2 - t1).count() << " s wall / "
         << cpu(c1, c2) << " s cpu; " << rep.summary());
  CHECK(rep.delaunay());
}

TEST_CASE("oracle: validator speed on 10^6 points", "[.perf]") {
  time_validator<2>(1000000);
  time_validator<3>(1000000);
}
