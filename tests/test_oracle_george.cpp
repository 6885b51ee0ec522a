// George's corrected cavity with the exact sphere test (--exact-sphere, sos
// policy) equals CGAL's Delaunay_triangulation_2/3 simplex for simplex, for each
// orientation kernel (integer: on its snapped points), on random and degenerate
// generators and on random small integer grids (RapidCheck).  The cavity is then
// Bowyer–Watson's, decided by the perturbed insphere (predicates/perturbed.hpp).
#include <rapidcheck/catch.h>

#include <catch2/catch.hpp>
#include <span>
#include <string>
#include <vector>

#include "fuzz/generators.hpp"
#include "tests/cgal_oracle.hpp"
#include "variants/run.hpp"

using namespace dlab;

namespace {

RunResult george_exact(const PointSet& ps, const std::string& kernel, const std::string& order, std::uint64_t seed) {
  RunOptions o;
  o.algorithm = "george";
  o.kernel = kernel;
  o.order = order;
  o.seed = seed;
  o.exact_sphere = true;
  return run(ps, o);
}

// True iff r's simplices equal CGAL's on r's (snapped) points.
bool same_as_cgal(const RunResult& r) {
  if (r.dimension == 2)
    return oracle::canonical_simplices<2>(r.simplices) == oracle::cgal_delaunay(r.points.p2);
  return oracle::canonical_simplices<3>(r.simplices) == oracle::cgal_delaunay(r.points.p3);
}

}  // namespace

TEST_CASE("george --exact-sphere equals CGAL on the generators", "[george][oracle]") {
  const char* const names[] = {"uniform", "lattice", "rotated-lattice", "cocircular", "near-degenerate",
                               "near-duplicates", "huge", "tiny", "collinear"};
  for (const std::string kernel : {"integer", "adaptive", "mp"})
    for (int dim : {2, 3})
      for (const char* name : names) {
        gen::GenOptions g;
        g.name = name;
        g.dim = dim;
        g.n = dim == 2 ? 600 : 250;
        g.seed = 21;
        const PointSet ps = gen::generate(g);
        const RunResult r = george_exact(ps, kernel, "brio", 3);
        INFO(kernel << " " << dim << "D " << name << ": " << r.message);
        REQUIRE(r.outcome == RunResult::Outcome::ok);
        CHECK(same_as_cgal(r));
      }
}

TEST_CASE("george --exact-sphere equals CGAL: property on small integer grids", "[george][oracle]") {
  rc::prop("ties everywhere, any order", [](bool three, std::uint8_t nraw, std::uint8_t kraw) {
    const std::size_t n = 5 + nraw % 50;
    PointSet ps;
    ps.dimension = three ? 3 : 2;
    const int range = *rc::gen::inRange(1, 5);
    for (std::size_t i = 0; i < n; ++i) {
      if (three)
        ps.p3.push_back({double(*rc::gen::inRange(0, range)), double(*rc::gen::inRange(0, range)),
                         double(*rc::gen::inRange(0, range))});
      else
        ps.p2.push_back({double(*rc::gen::inRange(0, range)), double(*rc::gen::inRange(0, range))});
    }
    const char* const kernels[] = {"integer", "adaptive", "mp"};
    const RunResult r = george_exact(ps, kernels[kraw % 3], "random", n);
    if (r.outcome == RunResult::Outcome::lower_dimensional) return;
    RC_ASSERT(r.outcome == RunResult::Outcome::ok);
    RC_ASSERT(same_as_cgal(r));
  });
}
