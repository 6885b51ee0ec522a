// The reference of tests/test_binade_triangulations.cpp -- mp x Bowyer-Watson
// with the sos policy -- is CGAL's Delaunay triangulation on the binade-edge
// sets too (issue 17): the witnesses, every listed edge on both signs,
// half-integers around 2^51..2^53, and the largest / smallest doubles.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "fuzz/binade_edges.hpp"
#include "fuzz/generators.hpp"
#include "tests/cgal_oracle.hpp"
#include "variants/run.hpp"

namespace {

using dlab::PointSet;

template <int D>
void check_with_cgal(const PointSet& ps, const std::string& what) {
  dlab::RunOptions o;
  o.algorithm = "bowyer-watson";
  o.kernel = "mp";
  const dlab::RunResult r = dlab::run(ps, o);
  INFO(what << ": " << r.message);
  REQUIRE(r.outcome != dlab::RunResult::Outcome::failed);
  if constexpr (D == 2)
    CHECK(dlab::oracle::canonical_simplices<2>(r.simplices) == dlab::oracle::cgal_delaunay(ps.p2));
  else
    CHECK(dlab::oracle::canonical_simplices<3>(r.simplices) == dlab::oracle::cgal_delaunay(ps.p3));
}

}  // namespace

TEST_CASE("oracle: mp x Bowyer-Watson equals CGAL on binade-edge sets", "[oracle][binade]") {
  PointSet square;
  square.p2 = {{-2251799813685256.0, 1}, {-2251799813685256.0, 0}, {-2251799813685255.5, 0}, {-2251799813685255.5, 1}};
  check_with_cgal<2>(square, "issue 17 square");
  CHECK(dlab::oracle::cgal_delaunay(square.p2) == std::vector<dlab::oracle::Simplex<2>>{{0, 1, 2}, {0, 2, 3}});

  const auto check = [](const dlab::gen::GenOptions& g) {
    const std::string what = g.name + " dim " + std::to_string(g.dim) +
                             (g.exp_set ? " exp " + std::to_string(g.exp) : "") + " sign " + g.sign + " seed " +
                             std::to_string(g.seed);
    const PointSet ps = dlab::gen::generate(g);
    if (g.dim == 2)
      check_with_cgal<2>(ps, what);
    else
      check_with_cgal<3>(ps, what);
  };
  for (int dim : {2, 3}) {
    dlab::gen::GenOptions g;
    g.dim = dim;
    g.n = dim == 2 ? 25 : 27;
    g.seed = 3;
    for (int exp : dlab::gen::notable_edges())
      for (const char* sign : {"positive", "negative", "mixed"})
        for (const char* name : {"binade-lattice", "binade-doubles"}) {
          g.name = name;
          g.sign = sign;
          g.exp = exp, g.exp_set = true;
          check(g);
        }
    g.exp_set = false;
    for (std::uint64_t seed = 0; seed < 6; ++seed)
      for (const char* name : {"half-integers", "extreme-doubles"}) {
        g.name = name;
        g.seed = seed;
        g.sign = "mixed";
        check(g);
      }
  }
}
