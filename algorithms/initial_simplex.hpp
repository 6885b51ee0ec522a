// The first D+1 affinely independent points of a sequence, and the initial
// mesh built on them: one finite simplex and its D+1 ghost neighbours, so that
// the mesh is closed from the start (the ghost-vertex construction of CGAL's
// Triangulation_3 and of Shewchuk's Pyramid/Triangle, re-derived here).
//
// If no such D+1 points exist the input is lower-dimensional and there is no
// D-simplex to return: fewer than D+1 distinct points, all points collinear
// (D = 2 or 3) or all points coplanar (D = 3).  `why` then says which.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/triangulation_result.hpp"
#include "predicates/mp_kernel.hpp"

namespace dlab {

template <int D>
struct InitialSimplex {
  bool found = false;
  std::array<std::uint32_t, D + 1> ids{};  // positions in the sequence, positively oriented
  std::string why;                         // when !found
};

// Exact collinearity of three 3D points: all three 2x2 minors of
// [b-a; c-a] vanish.  A floating filter (Shewchuk's bound for orient2d,
// |err| <= (3 + 16 eps) eps (|t1| + |t2|), taken as 4e-16 here with an underflow
// guard) settles almost every call; the rest go to the exact mp kernel.
inline bool collinear3(const Point3& a, const Point3& b, const Point3& c) {
  static const MpKernel mp;
  for (int x = 0; x < 3; ++x) {
    const int y = (x + 1) % 3;
    const Point2 pa{a[x], a[y]}, pb{b[x], b[y]}, pc{c[x], c[y]};
    const double t1 = (pa[0] - pc[0]) * (pb[1] - pc[1]);
    const double t2 = (pa[1] - pc[1]) * (pb[0] - pc[0]);
    const double bound = 4e-16 * (std::fabs(t1) + std::fabs(t2));
    const double det = t1 - t2;
    if (std::isfinite(det) && bound > 1e-280 && std::fabs(det) > bound) return false;
    if (mp.orient2d(pa, pb, pc) != Sign::zero) return false;
  }
  return true;
}

// Scans pts in order; `orient` decides orientation (the run's kernel).
template <int D, class K>
InitialSimplex<D> find_initial_simplex(const K& k, std::span<const Point<D>> pts) {
  InitialSimplex<D> r;
  const std::size_t n = pts.size();
  if (n == 0) {
    r.why = "no points";
    return r;
  }
  std::size_t i1 = 1;
  while (i1 < n && pts[i1] == pts[0]) ++i1;
  if (i1 == n) {
    r.why = "fewer than " + std::to_string(D + 1) + " distinct points (all " + std::to_string(n) +
            " points are equal)";
    return r;
  }
  std::size_t i2 = i1 + 1;
  if constexpr (D == 2) {
    while (i2 < n && k.orient2d(pts[0], pts[i1], pts[i2]) == Sign::zero) ++i2;
  } else {
    while (i2 < n && collinear3(pts[0], pts[i1], pts[i2])) ++i2;
  }
  if (i2 == n) {
    r.why = "all " + std::to_string(n) + " points are collinear (or there are only two distinct " +
            "points): no " + (D == 2 ? std::string("triangle") : std::string("tetrahedron")) + " exists";
    return r;
  }
  if constexpr (D == 2) {
    r.ids = {std::uint32_t(0), std::uint32_t(i1), std::uint32_t(i2)};
    if (orient_pos(k, pts[0], pts[i1], pts[i2]) == Sign::negative) std::swap(r.ids[1], r.ids[2]);
  } else {
    std::size_t i3 = i2 + 1;
    while (i3 < n && k.orient3d(pts[0], pts[i1], pts[i2], pts[i3]) == Sign::zero) ++i3;
    if (i3 == n) {
      r.why = "all " + std::to_string(n) + " points are coplanar: no tetrahedron exists";
      return r;
    }
    r.ids = {std::uint32_t(0), std::uint32_t(i1), std::uint32_t(i2), std::uint32_t(i3)};
    if (orient_pos(k, pts[0], pts[i1], pts[i2], pts[i3]) == Sign::negative) std::swap(r.ids[2], r.ids[3]);
  }
  r.found = true;
  return r;
}

// The first simplex of a run, or, when there is none, the run's outcome in
// `res`: lower-dimensional, or failed when an inexact kernel sees flat what the
// exact one does not (overflow, cancellation).
template <int D, class K>
InitialSimplex<D> initial_simplex_or_outcome(const K& k, std::span<const Point<D>> pts,
                                             TriangulationResult& res) {
  InitialSimplex<D> init = find_initial_simplex<D>(k, pts);
  if (init.found) return init;
  res.outcome = RunOutcome::lower_dimensional;
  res.message = init.why;
  if constexpr (!K::exact) {
    if (find_initial_simplex<D>(MpKernel{}, pts).found) {
      res.outcome = RunOutcome::failed;
      res.message = "the " + std::string(K::name) + " kernel sees the input as lower-dimensional (" +
                    init.why + "), but it is not";
    }
  }
  return init;
}

// Builds the initial closed mesh on a positively oriented simplex `ids`: the
// finite simplex and, for each of its facets, a ghost simplex on the outside.
// Returns the id of the finite simplex.
template <int D>
std::uint32_t build_initial_mesh(Mesh<D>& m, const std::array<std::uint32_t, D + 1>& ids) {
  constexpr int V = D + 1;
  std::vector<std::uint32_t> all;
  all.push_back(m.create(ids.data()));
  for (int j = 0; j < V; ++j) {
    // Vertex j replaced by a point q beyond facet j gives a negative simplex;
    // one transposition that brings the ghost (q's slot) to slot D, or swaps
    // two finite slots when j == D already, makes "q in slot D" positive.
    std::array<std::uint32_t, V> g = ids;
    g[j] = kGhost;
    if (j != D)
      std::swap(g[j], g[D]);
    else
      std::swap(g[0], g[1]);
    all.push_back(m.create(g.data()));
  }
  m.link_by_facets(all);
  return all[0];
}

// The start of an incremental run over pts (both Bowyer–Watsons): `m`
// emptied, reserved for the whole run and built on the initial simplex.
// Returns the finite simplex and the initial simplex's vertices (the points
// processed first), or nothing when there is no initial simplex (the outcome
// is then in `res`).
template <int D>
struct IncrementalStart {
  std::uint32_t simplex;
  std::array<std::uint32_t, D + 1> ids;
};
template <int D, class K>
std::optional<IncrementalStart<D>> start_incremental_mesh(const K& k, std::span<const Point<D>> pts, Mesh<D>& m,
                                                          TriangulationResult& res) {
  m.clear();
  const InitialSimplex<D> init = initial_simplex_or_outcome<D>(k, pts, res);
  if (!init.found) return std::nullopt;
  // Simplices including ghosts: exactly 2n - 2 in 2D (a triangulated sphere
  // on n + 1 vertices); in 3D about 6.75n for uniform points (measured; Dwyer
  // 1991 gives 6.77n in a ball), so 7n avoids a reallocation (which would
  // double the peak memory) on most inputs.
  const std::size_t n = pts.size();
  m.reserve(D == 2 ? 2 * n + 16 : 7 * n + 64);
  return IncrementalStart<D>{build_initial_mesh<D>(m, init.ids), init.ids};
}

}  // namespace dlab
