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
// Every simplex read is first acquired from the guard
// (algorithms/simplex_guard.hpp), which also keeps the stamps; a refusal ends
// the search with false and leaves the mesh unchanged but for the stamps of
// acquired simplices.
#pragma once
#include <cstdint>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/simplex_guard.hpp"

namespace dlab {

enum class Conflict : unsigned char { no, yes, refused };

template <class K, int D, class Guard>
Conflict in_conflict(const K& k, const Mesh<D>& m, const Point<D>* pts, std::uint32_t t, const Point<D>& p,
                     Guard& guard) {
  const std::uint32_t* w = m.vertices(t);
  bool c;
  if constexpr (D == 2) {
    if (w[2] == kGhost)
      c = ghost_conflict(k, pts[w[0]], pts[w[1]], p);
    else
      c = inside_pos(k, pts[w[0]], pts[w[1]], pts[w[2]], p) == Sign::positive;
  } else {
    if (w[3] == kGhost) {
      const std::uint32_t enc = m.neighbour(t, 3);
      if (!guard.acquire(Mesh<3>::simplex_of(enc))) return Conflict::refused;
      const std::uint32_t d = m.vertex(Mesh<3>::simplex_of(enc), Mesh<3>::facet_of(enc));
      c = ghost_conflict(k, pts[w[0]], pts[w[1]], pts[w[2]], pts[d], p);
    } else {
      c = inside_pos(k, pts[w[0]], pts[w[1]], pts[w[2]], pts[w[3]], p) == Sign::positive;
    }
  }
  return c ? Conflict::yes : Conflict::no;
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
  guard.set_mark(m, start, in);
  cavity.push_back(start);
  for (std::size_t c = 0; c < cavity.size(); ++c) {
    const std::uint32_t s = cavity[c];
    for (int f = 0; f < V; ++f) {
      const std::uint32_t enc = m.neighbour(s, f);
      const std::uint32_t t = Mesh<D>::simplex_of(enc);
      if (!guard.acquire(t)) return false;
      const std::uint32_t mk = guard.mark(m, t);
      if (mk == in) continue;
      if (mk != out) {
        const Conflict cf = in_conflict<K, D>(k, m, pts, t, p, guard);
        if (cf == Conflict::refused) return false;
        if (cf == Conflict::yes) {
          guard.set_mark(m, t, in);
          cavity.push_back(t);
          continue;
        }
        guard.set_mark(m, t, out);
      }
      records.push_back(boundary_record<D>(m, s, f, i, enc));
    }
  }
  return true;
}

}  // namespace dlab
