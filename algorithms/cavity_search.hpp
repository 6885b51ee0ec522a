// The Bowyer–Watson cavity of a new point p (Bowyer 1981, Watson 1981; Baker,
// Handbook of Grid Generation ch. 16.2.2): the simplices in conflict with p,
// grown breadth-first by adjacency from a simplex known to be in conflict,
// marked with a per-insertion stamp (`in`; `out` marks simplices tested and
// found outside, so each is tested once); the boundary facets are recorded
// while searching (algorithms/cavity.hpp's BoundaryRecord).
//
// A finite simplex conflicts iff p is strictly inside its circumsphere (kernel
// incircle/insphere; with the sos policy the kernel is perturbed<...>, which
// never answers zero); a ghost simplex conflicts by the hull rules of
// algorithms/oriented.hpp, which in 3D also read the finite simplex across the
// ghost's finite facet.  With exact predicates the cavity is connected and
// star-shaped from p.
//
// Every simplex that joins the cavity is first acquired from the guard
// (algorithms/simplex_guard.hpp), which also keeps the stamps (and may keep
// them in neighbour words: those are read through guard.code); a refusal ends
// the search with false and leaves the mesh unchanged but for stamps.  The
// simplices across the cavity's boundary are read and stamped without it: the
// parallel algorithm's PartitionGuard lets a task read the neighbours of its
// own simplices (simplex_guard.hpp says why no other task writes them).
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/simplex_guard.hpp"

namespace dlab {

template <class K, int D, class Guard>
bool in_conflict(const K& k, const Mesh<D>& m, const Point<D>* pts, std::uint32_t t, const Point<D>& p,
                 const Guard& guard) {
  const std::uint32_t* w = m.vertices(t);
  if constexpr (D == 2) {
    if (w[2] == kGhost) return ghost_conflict(k, pts[w[0]], pts[w[1]], p);
    return inside_pos(k, pts[w[0]], pts[w[1]], pts[w[2]], p) == Sign::positive;
  } else {
    if (w[3] == kGhost) {
      // The finite simplex across the ghost's hull facet shares its three
      // finite vertices, so it is no other task's (simplex_guard.hpp).
      const std::uint32_t enc = guard.code(m.neighbour(t, 3));
      const std::uint32_t d = m.vertex(Mesh<3>::simplex_of(enc), Mesh<3>::facet_of(enc));
      return ghost_conflict(k, pts[w[0]], pts[w[1]], pts[w[2]], pts[d], p);
    }
    return inside_pos(k, pts[w[0]], pts[w[1]], pts[w[2]], pts[w[3]], p) == Sign::positive;
  }
}

// The cavity of point i (p = pts[i]) from `start` (in conflict with p and
// already acquired), into `cavity` and `records`.  False: the guard refused.
template <class K, int D, class Guard>
bool search_cavity(const K& k, Mesh<D>& m, const Point<D>* pts, std::uint32_t i, std::uint32_t start,
                   std::uint32_t in, std::uint32_t out, std::vector<std::uint32_t>& cavity,
                   std::vector<BoundaryRecord<D>>& records, Guard& guard) {
  constexpr int V = D + 1;
  const Point<D>& p = pts[i];
  cavity.clear();
  records.clear();
  // When a simplex joins the cavity, its neighbours' blocks (and mark words)
  // are requested from memory: the breadth-first queue reaches them a few
  // simplices later, so their cache misses overlap instead of following one
  // another.  Bowyer-Watson on uniform 3D 10^6 points: 9-11 % less wall time
  // for 2.8 % more instructions (papers/triangulation_costs.md, session 40).
  auto prefetch_neighbours = [&](std::uint32_t s) {
#pragma GCC unroll 4
    for (int f = 0; f < V; ++f) {
      const std::uint32_t t = Mesh<D>::simplex_of(guard.code(m.neighbour(s, f)));
      __builtin_prefetch(m.vertices(t));
      guard.prefetch(t);
    }
  };
  guard.set_mark(m, start, in);
  cavity.push_back(start);
  prefetch_neighbours(start);
  for (std::size_t c = 0; c < cavity.size(); ++c) {
    const std::uint32_t s = cavity[c];
    // Unrolled: Bowyer-Watson on uniform 3D 10^5 points ran 2.5 % fewer
    // instructions (the 3D lattice 1.8 %, 2D with the float kernel 1.5 %).
#pragma GCC unroll 4
    for (int f = 0; f < V; ++f) {
      const std::uint32_t enc = guard.code(m.neighbour(s, f));
      const std::uint32_t t = Mesh<D>::simplex_of(enc);
      const std::uint32_t mk = guard.mark(m, t);
      if (mk == in) continue;
      if (mk != out) {
        if (in_conflict<K, D>(k, m, pts, t, p, guard)) {
          if (!guard.acquire(t)) return false;
          guard.set_mark(m, t, in);
          cavity.push_back(t);
          prefetch_neighbours(t);
          continue;
        }
        guard.set_mark(m, t, out);
      }
      records.push_back(boundary_record<D>(m, s, f, i, enc));
    }
  }
  return true;
}

// 2D, serial: the same cavity, found depth first with each triangle's edges
// taken counterclockwise from the one it was entered by, so the boundary
// records come out in counterclockwise order around the cavity: the Euler
// tour of the search tree, whose internal edges are skipped (the cavity of an
// exact kernel is star-shaped from p, so a disk whose boundary is one simple
// cycle; CGAL's Delaunay_triangulation_2 collects its hole the same way).
// Record r's edge then ends where record r+1's begins, which lets
// Restar<2>::star link the new triangles without a table.  Edge f of a
// counterclockwise triangle (v0, v1, v2) joins v[f+1] to v[f+2], so the edge
// after f is f+1 (mod 3, kAfter).  The stack holds the cavity edges still to cross,
// as neighbour codes (4s + f), the next one on top.  The guard as in
// search_cavity (the parallel Bowyer–Watson's PartitionGuard; NoGuard compiles away).
template <class K, class Guard>
bool search_cavity_ccw(const K& k, Mesh<2>& m, const Point<2>* pts, std::uint32_t i, std::uint32_t start,
                       std::uint32_t in, std::uint32_t out, std::vector<std::uint32_t>& cavity,
                       std::vector<BoundaryRecord<2>>& records, std::vector<std::uint32_t>& edges, Guard& guard) {
  const Point<2>& p = pts[i];
  cavity.clear();
  records.clear();
  // edges[0, top) is the stack (no push_back: g++ left it out of line here).
  std::size_t top = 0;
  auto push = [&](std::uint32_t e) {
    if (top == edges.size()) [[unlikely]] edges.resize(2 * top + 16);
    edges[top++] = e;
  };
  guard.set_mark(m, start, in);
  cavity.push_back(start);
  for (int f = 2; f >= 0; --f) push(Mesh<2>::encode(start, f));
  while (top != 0) {
    const std::uint32_t e = edges[--top];
    const std::uint32_t enc = guard.code(m.neighbour_enc(e));
    const std::uint32_t t = Mesh<2>::simplex_of(enc);
    const std::uint32_t mk = guard.mark(m, t);
    if (mk == in) continue;
    if (mk != out) {
      if (in_conflict<K, 2>(k, m, pts, t, p, guard)) {
        if (!guard.acquire(t)) return false;
        guard.set_mark(m, t, in);
        cavity.push_back(t);
        const int j = Mesh<2>::facet_of(enc);
        push(Mesh<2>::encode(t, kBefore[j]));  // crossed second
        push(Mesh<2>::encode(t, kAfter[j]));   // crossed first
        continue;
      }
      guard.set_mark(m, t, out);
    }
    records.push_back(boundary_record<2>(m, Mesh<2>::simplex_of(e), Mesh<2>::facet_of(e), i, enc));
  }
  return true;
}

}  // namespace dlab
