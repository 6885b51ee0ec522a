// George's enclosing box (George 1997, section 2.2: "an enclosing triangulation
// T0 ... constructed by hand as a Delaunay triangulation of the enclosing box";
// section 6.1 step 1: "eight supplementary points ... mesh this box using five
// tetrahedra").  2D: 4 corners, 2 triangles.  3D: 8 corners, 5 tetrahedra (the
// central tetrahedron on the odd corners 1, 2, 4, 7 and one corner tetrahedron
// at each even corner 0, 3, 5, 6; corner b has coordinate hi on axis j iff bit
// j of b is set).  The box's own hull gets ghost simplices, so the mesh is
// closed like every other mesh here (the walk never leaves the box).
//
// The box is the bounding box grown by its largest side on every side, so every
// input point is strictly inside it.  Its corners must be exact doubles seen
// exactly by the kernel. With the integer kernel (George's own choice) they
// must be grid points: the driver fits the grid to the input and its box
// (variants/driver.hpp), and `snap_box_corners` moves the corners onto it.
#pragma once
#include <algorithm>
#include <concepts>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <vector>

#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"

namespace dlab {

// The 2^D box corners, or nothing if they do not fit in finite doubles.
template <int D>
std::optional<std::vector<Point<D>>> enclosing_box_corners(std::span<const Point<D>> pts) {
  std::array<double, D> lo, hi;
  lo.fill(pts[0][0]);
  hi.fill(pts[0][0]);
  for (int j = 0; j < D; ++j) lo[j] = hi[j] = pts[0][j];
  for (const Point<D>& p : pts)
    for (int j = 0; j < D; ++j) {
      lo[j] = std::min(lo[j], p[j]);
      hi[j] = std::max(hi[j], p[j]);
    }
  double w = 0;
  for (int j = 0; j < D; ++j) w = std::max(w, hi[j] - lo[j]);
  if (!(w > 0) || !std::isfinite(w)) return std::nullopt;
  std::vector<Point<D>> c(std::size_t(1) << D);
  for (std::size_t b = 0; b < c.size(); ++b)
    for (int j = 0; j < D; ++j) {
      const double x = (b >> j) & 1 ? hi[j] + w : lo[j] - w;
      if (!std::isfinite(x)) return std::nullopt;
      c[b][j] = x;
    }
  // Strictly outside the bounding box even after rounding (w > 0 is at least
  // one ulp of the larger coordinate only if not absorbed: check).
  for (int j = 0; j < D; ++j)
    if (!(c[0][j] < lo[j]) || !(c[c.size() - 1][j] > hi[j])) return std::nullopt;
  return c;
}

// The kernel's snapping function, looked up through the combinators
// (counted<perturbed<IntegerKernel>>: member `base`); identity if none.
template <class K, int D>
Point<D> snap_point(const K& k, const Point<D>& p) {
  if constexpr (requires { { k.snap(p) } -> std::same_as<Point<D>>; })
    return k.snap(p);
  else if constexpr (requires { k.base; })
    return snap_point<std::remove_cvref_t<decltype(k.base)>, D>(k.base, p);
  else
    return p;
}

// Corners on the kernel's grid, still strictly outside the points' bounding
// box (false if snapping pulled one onto or inside it). Snapping acts per
// coordinate, so the corners still span an axis-aligned box.
template <class K, int D>
bool snap_box_corners(const K& k, std::span<const Point<D>> pts, std::vector<Point<D>>& corners) {
  for (Point<D>& c : corners) c = snap_point<K, D>(k, c);
  for (const Point<D>& p : pts)
    for (int j = 0; j < D; ++j)
      if (!(corners.front()[j] < p[j]) || !(corners.back()[j] > p[j])) return false;
  return true;
}

// Builds the box triangulation on corner ids first + b (b = 0 .. 2^D - 1):
// finite simplices positively oriented by the kernel, ghosts on the box's
// faces, all linked.  Returns the finite simplices' ids.
template <class K, int D>
std::vector<std::uint32_t> build_box_mesh(const K& k, Mesh<D>& m, const Point<D>* pts, std::uint32_t first) {
  constexpr int V = D + 1;
  std::vector<std::array<std::uint32_t, V>> fin;
  if constexpr (D == 2) {
    fin = {{0, 1, 3}, {0, 3, 2}};  // corners 0=(lo,lo) 1=(hi,lo) 2=(lo,hi) 3=(hi,hi); diagonal 0-3
  } else {
    fin = {{1, 2, 4, 7}, {0, 1, 2, 4}, {3, 2, 1, 7}, {5, 4, 7, 1}, {6, 7, 4, 2}};
  }
  std::vector<std::uint32_t> all, finite;
  for (auto s : fin) {
    for (auto& v : s) v += first;
    Sign o;
    if constexpr (D == 2)
      o = orient_pos(k, pts[s[0]], pts[s[1]], pts[s[2]]);
    else
      o = orient_pos(k, pts[s[0]], pts[s[1]], pts[s[2]], pts[s[3]]);
    if (o == Sign::negative) std::swap(s[0], s[1]);
    const std::uint32_t id = m.create(s.data());
    all.push_back(id);
    finite.push_back(id);
  }
  // Hull facets: facets of the finite simplices seen once.
  for (std::size_t a = 0; a < fin.size(); ++a)
    for (int f = 0; f < V; ++f) {
      std::array<std::uint32_t, D> key;
      int n = 0;
      for (int i = 0; i < V; ++i)
        if (i != f) key[n++] = m.vertex(finite[a], i);
      std::sort(key.begin(), key.end());
      int seen = 0;
      for (std::size_t b = 0; b < fin.size(); ++b)
        for (int g = 0; g < V; ++g) {
          std::array<std::uint32_t, D> kb;
          int nb = 0;
          for (int i = 0; i < V; ++i)
            if (i != g) kb[nb++] = m.vertex(finite[b], i);
          std::sort(kb.begin(), kb.end());
          if (kb == key) ++seen;
        }
      if (seen != 1) continue;
      // As build_initial_mesh: the ghost replaces vertex f, then one
      // transposition brings it to slot D (or swaps two finite slots).
      std::array<std::uint32_t, V> g = m.simplex(finite[a]);
      g[f] = kGhost;
      if (f != D)
        std::swap(g[f], g[D]);
      else
        std::swap(g[0], g[1]);
      all.push_back(m.create(g.data()));
    }
  m.link_by_facets(all);
  return finite;
}

}  // namespace dlab
