// Uses the installed dlab libraries the way a research code would: the exact
// predicates, dlab::run() and the exact validator. Every input here has a
// known answer (tests/install_consumer/expected.txt, written by hand):
//  * the unit square and its centre: the centre lies strictly inside the
//    circumcircle of any three corners, so the only Delaunay triangulation is
//    the fan of the four triangles (centre, side);
//  * the unit tetrahedron and an interior point: the only triangulation that
//    uses every point is the star of four tetrahedra around it;
//  * predicates on points whose determinants are small exact binary numbers
//    (one just off the diagonal by one ulp of 0.5).
#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "cli/point_reader.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/run.hpp"

namespace {

// Each simplex as its sorted vertex set, the list sorted: "0 1 4 | 0 3 4 | ...".
std::string vertex_sets(const std::vector<std::uint32_t>& s, int d) {
  std::vector<std::vector<std::uint32_t>> sets;
  for (std::size_t i = 0; i + d < s.size(); i += d + 1) {
    std::vector<std::uint32_t> v(s.begin() + i, s.begin() + i + d + 1);
    std::sort(v.begin(), v.end());
    sets.push_back(v);
  }
  std::sort(sets.begin(), sets.end());
  std::ostringstream out;
  for (std::size_t i = 0; i < sets.size(); ++i) {
    if (i) out << " | ";
    for (std::size_t j = 0; j < sets[i].size(); ++j) out << (j ? " " : "") << sets[i][j];
  }
  return out.str();
}

// det[v1-v0; ...; vd-v0] > 0 for every simplex, in plain doubles: exact for
// these coordinates (multiples of 1/8 below 2: every product and sum fits).
bool positively_oriented(const dlab::PointSet& ps, const std::vector<std::uint32_t>& s) {
  const int d = ps.dimension;
  for (std::size_t i = 0; i + d < s.size(); i += d + 1) {
    double m[3][3] = {};
    for (int r = 0; r < d; ++r)
      for (int c = 0; c < d; ++c)
        m[r][c] = d == 2 ? ps.p2[s[i + 1 + r]][c] - ps.p2[s[i]][c] : ps.p3[s[i + 1 + r]][c] - ps.p3[s[i]][c];
    const double det = d == 2 ? m[0][0] * m[1][1] - m[0][1] * m[1][0]
                              : m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                                    m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                                    m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    if (!(det > 0)) return false;
  }
  return true;
}

void triangulate(const dlab::PointSet& ps, const std::string& algo, const std::string& kernel) {
  dlab::RunOptions o;
  o.algorithm = algo;
  o.kernel = kernel;
  const dlab::RunResult r = dlab::run(ps, o);
  const dlab::ValidationReport v = dlab::validate(ps, r.simplices);
  std::cout << algo << " " << kernel << " " << ps.dimension << "d: " << vertex_sets(r.simplices, ps.dimension)
            << (positively_oriented(ps, r.simplices) ? " ; oriented" : " ; NOT oriented")
            << (v.delaunay() ? " ; delaunay" : " ; NOT delaunay") << "\n";
}

template <class K>
void predicates(const char* name) {
  const K k{};
  using dlab::to_int;
  const double above = std::nextafter(0.5, 1.0), below = std::nextafter(0.5, 0.0);
  std::cout << name << " orient2d " << to_int(k.orient2d({0, 0}, {1, 1}, {0.5, above})) << " "
            << to_int(k.orient2d({0, 0}, {1, 1}, {0.5, below})) << " " << to_int(k.orient2d({0, 0}, {1, 1}, {0.5, 0.5}))
            << " incircle " << to_int(k.incircle({0, 0}, {1, 0}, {1, 1}, {0, 1})) << " "
            << to_int(k.incircle({0, 0}, {1, 0}, {1, 1}, {0.5, 0.5})) << " "
            << to_int(k.incircle({0, 0}, {1, 0}, {1, 1}, {2, 2})) << " orient3d "
            << to_int(k.orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -1})) << " insphere "
            << to_int(k.insphere({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {0.25, 0.25, 0.25})) << " "
            << to_int(k.insphere({0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {1, 1, 1})) << "\n";
}

}  // namespace

int main() {
  predicates<dlab::AdaptiveKernel>("adaptive");
  predicates<dlab::MpKernel>("mp");

  const dlab::PointSet square = dlab::point_set<2>({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5, 0.5}});
  const dlab::PointSet tet =
      dlab::point_set<3>({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0.125, 0.125, 0.125}});
  for (const std::string& algo : dlab::algorithm_names()) triangulate(square, algo, "adaptive");
  for (const std::string& algo : dlab::algorithm_names()) triangulate(tet, algo, "adaptive");
  for (const char* kernel : {"integer", "mp"}) {
    triangulate(square, "bowyer-watson", kernel);
    triangulate(tet, "bowyer-watson", kernel);
  }

  // The validator on two wrong answers: the square without its centre, and a
  // rhombus split along its long diagonal, whose far vertex (2,1) lies inside
  // the circumcircle of (0,0) (2,-1) (4,0) (centre (2,1.5), radius 2.5).
  const dlab::ValidationReport missing = dlab::validate(square, std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  std::cout << "square without centre: valid " << missing.valid() << ", missing vertices "
            << missing[dlab::Check::missing_vertex].count << "\n";
  const dlab::PointSet rhombus = dlab::point_set<2>({{0, 0}, {2, -1}, {4, 0}, {2, 1}});
  const dlab::ValidationReport long_diagonal = dlab::validate(rhombus, std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  std::cout << "rhombus, long diagonal: valid " << long_diagonal.valid() << ", delaunay " << long_diagonal.delaunay()
            << ", non-Delaunay edges " << long_diagonal.non_delaunay_facets() << "\n";

  // A generated point set, and one read from text as `dlab triangulate` reads INPUT.
  const dlab::PointSet uniform = dlab::point_set<2>(dlab::gen::uniform<2>(200, 7));
  const dlab::RunResult r = dlab::run(uniform, {});
  const dlab::ValidationReport v = dlab::validate(uniform, r.simplices);
  // Euler: a triangulation of n points with h on the hull has 2n - 2 - h triangles.
  std::cout << "uniform 200: delaunay " << v.delaunay() << ", 2n-2-h triangles "
            << (r.simplices.size() / 3 == 2 * 200 - 2 - v.boundary_facets) << "\n";
  const dlab::PointSet text = dlab::io::parse_points("# a comment\n0 0\n1, 0\n0x1p-1 0.5\n", "inline", false);
  std::cout << "parsed: dimension " << text.dimension << ", points " << text.size() << ", third "
            << text.p2[2][0] << " " << text.p2[2][1] << "\n";
  return 0;
}
