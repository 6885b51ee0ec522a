// Flipping an existing triangulation toward Delaunay (Lawson 1977 in 2D;
// Joe 1989/1991 in 3D; survey section 2.1).  In 2D every locally non-Delaunay
// edge is flippable and the flips end in the Delaunay triangulation (Lawson);
// in 3D a non-Delaunay facet may be unflippable (Joe's 3-2 / 4-4 need edge
// degrees 3 / 4) and the process can stop short: that is detected -- a full
// pass over the remaining non-Delaunay facets flips nothing -- and reported
// as `stuck_facets`, never looped on.  The local test and the flips are those
// of incremental Lawson (algorithms/flips.hpp), perturbed by default, so a
// 2D run ends in the same triangulation as Bowyer-Watson and CGAL.
//
// Input: points and finite simplices (D+1 indices each, positively oriented)
// forming a triangulation of a convex point set; the hull facets get ghost
// simplices so that hull edges can flip too.  Bounded: at most
// flip_bound(n, exact) flips and as many passes.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/flips.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/mesh.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/perturbed.hpp"

namespace dlab {

struct FlipExistingResult {
  RunOutcome outcome = RunOutcome::ok;
  std::string message;                  // why it failed (bad input, bound exceeded)
  std::vector<std::uint32_t> simplices;  // the final triangulation (finite simplices)
  std::uint64_t flips = 0, passes = 0;
  std::uint64_t stuck_facets = 0;  // non-Delaunay facets left, none flippable (3D)
  std::int64_t bad_simplex = -1;   // input simplex (0-based) that made it "not a triangulation", if one did
  Counters counters;
};

namespace flip_existing_detail {

template <int D>
struct FacetRec {
  std::array<std::uint32_t, D> k;
  std::uint32_t enc;
  bool operator<(const FacetRec& o) const { return k < o.k || (k == o.k && enc < o.enc); }
};

template <int D>
FacetRec<D> facet_rec(const std::uint32_t* v, int f, std::uint32_t enc) {
  FacetRec<D> r;
  int c = 0;
  for (int j = 0; j <= D; ++j)
    if (j != f) r.k[c++] = v[j];
  std::sort(r.k.begin(), r.k.end());
  r.enc = enc;
  return r;
}

// Links facets with equal vertex sets; unpaired ones go to `single`.
template <int D>
std::string pair_facets(Mesh<D>& m, std::vector<FacetRec<D>>& fs, std::vector<FacetRec<D>>& single) {
  std::sort(fs.begin(), fs.end());
  for (std::size_t a = 0; a < fs.size();) {
    std::size_t b = a + 1;
    while (b < fs.size() && fs[b].k == fs[a].k) ++b;
    if (b - a > 2) return "a facet is shared by more than two simplices";
    if (b - a == 2)
      m.link(fs[a].enc, fs[a + 1].enc);
    else
      single.push_back(fs[a]);
    a = b;
  }
  return "";
}

// Builds the ghost-closed mesh from finite simplices; "" or what is wrong.
template <int D, class K>
std::string build(const K& k, std::span<const Point<D>> pts, std::span<const std::uint32_t> flat, Mesh<D>& m,
                  std::int64_t& bad) {
  constexpr int V = D + 1;
  const std::size_t n = flat.size() / V;
  if (n == 0) return "no simplices";
  m.clear();
  m.reserve(2 * n + 64);
  std::vector<FacetRec<D>> facets, hull, ghost_facets, open;
  for (std::size_t s = 0; s < n; ++s) {
    std::array<std::uint32_t, V> v;
    for (int j = 0; j < V; ++j) {
      v[j] = flat[s * V + j];
      if (v[j] >= pts.size()) {
        bad = static_cast<std::int64_t>(s);
        return "simplex " + std::to_string(s) + ": index out of range";
      }
    }
    Sign o;
    if constexpr (D == 2)
      o = orient_pos(k, pts[v[0]], pts[v[1]], pts[v[2]]);
    else
      o = orient_pos(k, pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
    if (o != Sign::positive) {
      bad = static_cast<std::int64_t>(s);
      return "simplex " + std::to_string(s) + (o == Sign::zero ? " is flat" : " is not positively oriented");
    }
    const std::uint32_t id = m.create(v.data());
    for (int f = 0; f < V; ++f) facets.push_back(facet_rec<D>(v.data(), f, Mesh<D>::encode(id, f)));
  }
  std::string err = pair_facets<D>(m, facets, hull);
  if (!err.empty()) return err;
  for (const FacetRec<D>& h : hull) {
    const std::uint32_t s = Mesh<D>::simplex_of(h.enc);
    const int f = Mesh<D>::facet_of(h.enc);
    std::array<std::uint32_t, V> g = m.simplex(s);
    // As build_initial_mesh: substitution then one transposition.
    g[f] = kGhost;
    if (f != D)
      std::swap(g[f], g[D]);
    else
      std::swap(g[0], g[1]);
    const std::uint32_t id = m.create(g.data());
    m.link(Mesh<D>::encode(id, D), h.enc);
    for (int f2 = 0; f2 < D; ++f2) ghost_facets.push_back(facet_rec<D>(g.data(), f2, Mesh<D>::encode(id, f2)));
  }
  err = pair_facets<D>(m, ghost_facets, open);
  if (!err.empty()) return err;
  if (!open.empty()) return "the boundary of the simplices is not a closed manifold";
  return m.check_structure();
}

}  // namespace flip_existing_detail

// Flips the triangulation `simplices` of `pts` toward Delaunay.
template <int D, class K = perturbed<AdaptiveKernel>>
FlipExistingResult flip_existing(std::span<const Point<D>> pts, std::span<const std::uint32_t> simplices,
                                 const K& k = K{}) {
  constexpr int V = D + 1;
  using R = typename Flipper<K, D>::Result;
  FlipExistingResult res;
  Mesh<D> m;
  const std::string err = flip_existing_detail::build<D>(k, pts, simplices, m, res.bad_simplex);
  if (!err.empty()) {
    res.outcome = RunOutcome::failed;
    res.message = "not a triangulation: " + err;
    return res;
  }
  Flipper<K, D> fl(k, m);
  fl.set_points(pts.data());
  const std::uint64_t bound = flip_bound(pts.size(), K::exact);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t s = 0; s < m.slots(); ++s) stack.push_back(s);
  for (;;) {
    ++res.passes;
    const std::uint64_t before = fl.counts.total();
    while (!stack.empty()) {
      const std::uint32_t s = stack.back();
      stack.pop_back();
      for (int f = 0; f < V && m.alive(s); ++f) {
        const R r = fl.try_flip(s, f);
        if (r == R::broken) {
          res.outcome = RunOutcome::failed;
          res.message = "a flip found an inconsistent mesh";
          return res;
        }
        if (r != R::flipped) continue;
        if (fl.counts.total() > bound) {
          res.outcome = RunOutcome::failed;
          res.message = "flip count exceeded its bound of " + std::to_string(bound);
          return res;
        }
        for (std::uint32_t c : fl.created()) stack.push_back(c);
        break;  // s is gone
      }
    }
    // Every facet once more: the non-Delaunay ones left were unflippable when
    // tested; a pass that flips none of them means the flips are stuck.
    std::uint64_t left = 0;
    for (std::uint32_t s = 0; s < m.slots(); ++s) {
      if (!m.alive(s)) continue;
      for (int f = 0; f < V; ++f) {
        const std::uint32_t enc = m.neighbour(s, f);
        const std::uint32_t t = Mesh<D>::simplex_of(enc);
        if (t < s) continue;  // each facet once
        if (fl.conflict(s, m.vertex(t, Mesh<D>::facet_of(enc))) || fl.conflict(t, m.vertex(s, f))) {
          ++left;
          stack.push_back(s);
        }
      }
    }
    if (left == 0) break;
    if (fl.counts.total() == before && res.passes > 1) {
      res.stuck_facets = left;
      break;
    }
    if (res.passes > bound) break;  // unreachable: each pass after the first flips
  }
  m.for_each_finite([&](std::uint32_t s) {
    for (int j = 0; j < V; ++j) res.simplices.push_back(m.vertex(s, j));
  });
  const FlipCounts& c = fl.counts;
  res.flips = c.total();
  if constexpr (D == 2)
    res.counters = {{"flips_2_2", c.f22}};
  else
    res.counters = {{"flips_2_3", c.f23},
                    {"flips_3_2", c.f32},
                    {"flips_4_4", c.f44},
                    {"hull_edge_removals", c.hull_removals}};
  res.counters.push_back({"flips_total", c.total()});
  res.counters.push_back({"unflippable_tests", c.unflippable});
  res.counters.push_back({"passes", res.passes});
  res.counters.push_back({"stuck_facets", res.stuck_facets});
  return res;
}

template <int D, class K = perturbed<AdaptiveKernel>>
FlipExistingResult flip_existing(const std::vector<Point<D>>& pts, const std::vector<std::uint32_t>& simplices,
                                 const K& k = K{}) {
  return flip_existing<D, K>(std::span<const Point<D>>(pts), std::span<const std::uint32_t>(simplices), k);
}

}  // namespace dlab
