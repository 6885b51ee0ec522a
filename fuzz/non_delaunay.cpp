// See non_delaunay.hpp.
#include "fuzz/non_delaunay.hpp"

#include <span>

#include "algorithms/flips.hpp"
#include "algorithms/lawson.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/perturbed.hpp"

namespace dlab {

namespace {

std::uint64_t splitmix(std::uint64_t& x) {
  std::uint64_t z = (x += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

}  // namespace

template <int D>
std::vector<std::uint32_t> non_delaunay_start(const std::vector<Point<D>>& pts, std::uint64_t seed,
                                              std::size_t flips) {
  using K = perturbed<AdaptiveKernel>;
  constexpr int V = D + 1;
  using Simplex = typename Mesh<D>::Simplex;
  Lawson<K, D> dt;
  dt.keep_mesh();
  const TriangulationResult t = dt.run(std::span<const Point<D>>(pts));
  if (t.outcome != RunOutcome::ok) return {};
  Mesh<D> m = dt.mesh();
  const K k;
  auto positive = [&](const Simplex& v) {
    if (v[D] == kGhost) return false;  // keep the hull: finite simplices only
    if constexpr (D == 2)
      return orient_pos(k, pts[v[0]], pts[v[1]], pts[v[2]]) == Sign::positive;
    else
      return orient_pos(k, pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]) == Sign::positive;
  };
  if (flips == 0) flips = pts.size();
  FlipMesh<D> fm;
  std::vector<std::uint32_t> created;
  std::uint64_t x = seed;
  std::size_t done = 0;
  // Bounded: at most 20 attempts per wanted flip.
  for (std::size_t attempt = 0; attempt < 20 * flips && done < flips; ++attempt) {
    const std::uint32_t s = static_cast<std::uint32_t>(splitmix(x) % m.slots());
    if (!m.alive(s) || m.is_ghost(s)) continue;
    const int f = static_cast<int>(splitmix(x) % V);
    const std::uint32_t enc = m.neighbour(s, f);
    const std::uint32_t tt = Mesh<D>::simplex_of(enc);
    if (m.is_ghost(tt)) continue;
    const std::uint32_t d = m.vertex(tt, Mesh<D>::facet_of(enc));
    Simplex nw[D];
    bool ok = true;
    int c = 0;
    for (int j = 0; j < V && ok; ++j) {
      if (j == f) continue;
      nw[c] = FlipMesh<D>::substitute(m, s, j, d);
      ok = positive(nw[c]);
      ++c;
    }
    if (!ok) continue;
    const std::uint32_t old[2] = {s, tt};
    if (!fm.replace(m, old, 2, nw, D, created)) return {};  // cannot happen on a valid mesh
    ++done;
  }
  std::vector<std::uint32_t> out;
  m.for_each_finite([&](std::uint32_t s) {
    for (int j = 0; j < V; ++j) out.push_back(m.vertex(s, j));
  });
  return out;
}

template std::vector<std::uint32_t> non_delaunay_start<2>(const std::vector<Point2>&, std::uint64_t, std::size_t);
template std::vector<std::uint32_t> non_delaunay_start<3>(const std::vector<Point3>&, std::uint64_t, std::size_t);

}  // namespace dlab
