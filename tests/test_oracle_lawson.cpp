// Lawson (incremental flips, sos policy) equals CGAL's Delaunay_triangulation_2/3
// simplex for simplex, for every exact kernel (integer: on its snapped points),
// on random and degenerate generators, in several insertion orders, and on
// random small integer grids (RapidCheck); the result also passes the exact
// validator.  Flip-existing in 2D from a non-Delaunay start reaches CGAL's
// triangulation too.
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/flip_existing.hpp"
#include "algorithms/validate.hpp"
#include "fuzz/generators.hpp"
#include "fuzz/non_delaunay.hpp"
#include "tests/cgal_oracle.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

RunResult lawson(const PointSet& ps, const std::string& kernel, const std::string& order, std::uint64_t seed) {
  RunOptions o;
  o.algorithm = "lawson";
  o.kernel = kernel;
  o.order = order;
  o.seed = seed;
  return run(ps, o);
}

bool same_as_cgal(const RunResult& r) {
  if (r.dimension == 2)
    return oracle::canonical_simplices<2>(r.simplices) == oracle::cgal_delaunay(r.points.p2);
  return oracle::canonical_simplices<3>(r.simplices) == oracle::cgal_delaunay(r.points.p3);
}

}  // namespace

TEST_CASE("lawson equals CGAL on the generators, every exact kernel and order", "[lawson][oracle]") {
  // Every generator that exists in the dimension (coplanar and cospherical
  // sets put many 3D points on hull facet planes: hull insertions by flips).
  for (const std::string kernel : {"integer", "adaptive", "mp"})
    for (int dim : {2, 3})
      for (const std::string& name : gen::generator_names()) {
        if (name == "kettner-grid") continue;  // 2D, a fixed 256^2 grid whatever n: too slow under mp here
        gen::GenOptions g;
        g.name = name;
        g.dim = dim;
        g.n = dim == 2 ? 500 : 200;
        g.seed = 23;
        PointSet ps;
        try {
          ps = gen::generate(g);
        } catch (const std::invalid_argument&) {
          continue;  // a 2D-only generator asked for 3D
        }
        for (const char* order : {"brio", "random", "input"}) {
          const RunResult r = lawson(ps, kernel, order, 5);
          INFO(kernel << " " << dim << "D " << name << " " << order << ": " << r.message);
          REQUIRE(r.outcome == RunResult::Outcome::ok);
          CHECK(same_as_cgal(r));
          if (std::string(order) == "brio") CHECK(validate(r.points, r.simplices).delaunay());
        }
      }
}

TEST_CASE("lawson equals CGAL: property on small integer grids", "[lawson][oracle]") {
  rc::prop("ties everywhere, any order", [](bool three, std::uint8_t nraw, std::uint8_t kraw) {
    const int n = 5 + nraw % 40;
    const int side = 2 + kraw % 4;
    PointSet ps;
    ps.dimension = three ? 3 : 2;
    const auto vals = *rc::gen::container<std::vector<int>>(n * ps.dimension, rc::gen::inRange(0, side));
    for (int i = 0; i < n; ++i) {
      if (three)
        ps.p3.push_back({double(vals[3 * i]), double(vals[3 * i + 1]), double(vals[3 * i + 2])});
      else
        ps.p2.push_back({double(vals[2 * i]), double(vals[2 * i + 1])});
    }
    const RunResult r = lawson(ps, "adaptive", "random", nraw);
    if (r.outcome == RunResult::Outcome::lower_dimensional) return;
    RC_ASSERT(r.outcome == RunResult::Outcome::ok);
    RC_ASSERT(same_as_cgal(r));
  });
}

TEST_CASE("2D flip-existing from a non-Delaunay start reaches CGAL's triangulation", "[lawson][oracle]") {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    gen::GenOptions g;
    g.name = seed == 1 ? "lattice" : "uniform";
    g.dim = 2;
    g.n = 300;
    g.seed = seed;
    const PointSet ps = gen::generate(g);
    const std::vector<std::uint32_t> start = non_delaunay_start<2>(ps.p2, seed);
    const FlipExistingResult r = flip_existing<2>(ps.p2, start);
    REQUIRE(r.outcome == RunResult::Outcome::ok);
    CHECK(r.stuck_facets == 0);
    CHECK(oracle::canonical_simplices<2>(r.simplices) == oracle::cgal_delaunay(ps.p2));
  }
}
