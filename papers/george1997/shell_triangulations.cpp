// George 1997, Table 2 (section 5, edge removal): the number N_n of ways to
// re-mesh a convex shell of n tetrahedra around an edge, i.e. the number of
// triangulations of the n-gon M_1..M_n on which the shell's tetrahedra stand
// (P. L. George, "Improvements on Delaunay-based three-dimensional automatic
// mesh generator", Finite Elements in Analysis and Design 25 (1997) 297-317).
//
// Counted here by dlab's own flip code, not by a formula: start from the fan
// triangulation of n points in convex position (p_i = (i, i^2), on a parabola,
// exact in doubles), build the ghost-closed mesh (flip_existing_detail::build),
// and search the flip graph breadth-first: every interior edge whose two
// triangles form a convex quadrilateral (both new triangles positively oriented
// by the exact mp kernel) is flipped with the 2-2 substitution of
// algorithms/flips.hpp and FlipMesh<2>::replace; triangulations are told apart
// by their canonical simplex lists.  Lawson 1972: the flip graph of a planar
// point set is connected, so the search reaches every triangulation.
//
//   dlab_shell_triangulations NMAX     (3 <= NMAX <= 14; 13 takes about a second)
// prints, for n = 3..NMAX: n, the triangulations found, and the edges of the
// flip graph (each an unordered pair of triangulations one flip apart).
// tests/test_papers.sh checks both columns against closed formulas.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <set>
#include <span>
#include <string>
#include <vector>

#include "algorithms/canonical_simplices.hpp"
#include "algorithms/flip_existing.hpp"
#include "algorithms/flips.hpp"
#include "algorithms/mesh.hpp"
#include "predicates/mp_kernel.hpp"

namespace {

using namespace dlab;
using Key = std::vector<IndexSimplex<2>>;

Key key_of(const Mesh<2>& m) {
  std::vector<std::uint32_t> flat;
  m.for_each_finite([&](std::uint32_t s) {
    for (int j = 0; j < 3; ++j) flat.push_back(m.vertex(s, j));
  });
  return canonical_simplices<2>(flat);
}

struct Count {
  std::uint64_t triangulations = 0, flip_edges = 0;
};

// The ghost-closed mesh of a triangulation given by its canonical simplices.
Mesh<2> mesh_of(const MpKernel& k, const std::vector<Point2>& pts, const Key& key) {
  std::vector<std::uint32_t> flat;
  for (const auto& t : key) flat.insert(flat.end(), t.begin(), t.end());
  Mesh<2> m;
  std::int64_t bad = -1;
  const std::string err = flip_existing_detail::build<2>(k, std::span<const Point2>(pts), flat, m, bad);
  if (!err.empty()) {
    std::cerr << "dlab_shell_triangulations: " << pts.size() << " points: " << err << "\n";
    std::exit(1);
  }
  return m;
}

Count enumerate(int n) {
  const MpKernel k;
  std::vector<Point2> pts;
  for (int i = 0; i < n; ++i) pts.push_back({double(i), double(i) * double(i)});
  Key fan;
  for (int i = 1; i + 1 < n; ++i) fan.push_back(canonical_simplex<2>({0u, std::uint32_t(i), std::uint32_t(i + 1)}));
  std::sort(fan.begin(), fan.end());

  std::set<Key> seen = {fan};
  std::vector<Key> queue = {fan};
  std::uint64_t flips = 0;
  FlipMesh<2> fm;
  std::vector<std::uint32_t> created;
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const Mesh<2> cur = mesh_of(k, pts, queue[q]);
    for (std::uint32_t s = 0; s < cur.slots(); ++s) {
      if (!cur.alive(s) || cur.is_ghost(s)) continue;
      for (int f = 0; f < 3; ++f) {
        const std::uint32_t enc = cur.neighbour(s, f);
        const std::uint32_t t = Mesh<2>::simplex_of(enc);
        if (cur.is_ghost(t) || t < s) continue;  // a polygon side; or an edge seen from t
        const std::uint32_t d = cur.vertex(t, Mesh<2>::facet_of(enc));
        // The 2-2 flip of flips.hpp: s = p w u, t = d u w -> s[u->d], s[w->d].
        const Mesh<2>::Simplex nw[2] = {FlipMesh<2>::substitute(cur, s, (f + 1) % 3, d),
                                        FlipMesh<2>::substitute(cur, s, (f + 2) % 3, d)};
        bool convex = true;
        for (const auto& v : nw) convex = convex && k.orient2d(pts[v[0]], pts[v[1]], pts[v[2]]) == Sign::positive;
        if (!convex) continue;
        Mesh<2> next = cur;
        const std::uint32_t old[2] = {s, t};
        if (!fm.replace(next, old, 2, nw, 2, created)) {
          std::cerr << "dlab_shell_triangulations: a flip left the mesh inconsistent (n = " << n << ")\n";
          std::exit(1);
        }
        ++flips;
        Key key = key_of(next);
        if (seen.insert(key).second) queue.push_back(std::move(key));
      }
    }
  }
  // Every flip-graph edge was flipped once from each of its two ends.
  return {seen.size(), flips / 2};
}

}  // namespace

int main(int argc, char** argv) {
  const int nmax = argc == 2 ? std::atoi(argv[1]) : 0;
  if (nmax < 3 || nmax > 14) {
    std::cerr << "usage: dlab_shell_triangulations NMAX   (3 <= NMAX <= 14)\n";
    return 2;
  }
  std::cout << "n,triangulations,flip_graph_edges\n";
  for (int n = 3; n <= nmax; ++n) {
    const Count c = enumerate(n);
    std::cout << n << ',' << c.triangulations << ',' << c.flip_edges << '\n';
  }
  return 0;
}
