// Point location by the visibility walk, remembering stochastic variant
// (Devillers, Pion, Teillaud, "Walking in a triangulation", IJFCS 13 (2002)):
// from the current simplex, test its facets in an order starting at a random
// offset, skip the facet just crossed, and step across the first facet whose
// supporting hyperplane separates the simplex from p.  When no facet does, p is
// in the closed simplex.  A ghost simplex is entered only through its finite
// facet and only when p is strictly beyond it, so the walk then stops there:
// p is outside the hull and that ghost is in conflict with p.  When the walk
// starts in a ghost simplex it tests the finite facet once, and steps into the
// hull unless p is strictly beyond it.
//
// Each call is bounded by `max_steps`: with an exact kernel on a Delaunay
// triangulation the walk terminates (Edelsbrunner 1989 for the visibility walk;
// the stochastic variant terminates on any triangulation with probability 1),
// so hitting the bound is a bug there; with an inexact kernel it means the
// signs were inconsistent and the caller reports a failure.
#pragma once
#include <cstdint>

#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"

namespace dlab {

struct Located {
  enum class End : unsigned char { inside, outside, step_bound } end = End::inside;
  std::uint32_t simplex = 0;  // finite simplex containing p (inside), conflicting ghost (outside)
  std::uint32_t steps = 0;    // simplices crossed
  int zeros = 0;              // facets with a zero orientation in the final simplex (inside)
};

// A tiny deterministic generator for the walk's random offsets.
struct WalkRng {
  std::uint32_t state = 0x9E3779B9u;
  int next(int n) {
    state = state * 1664525u + 1013904223u;  // Numerical Recipes LCG; high bits used
    return static_cast<int>((state >> 16) % static_cast<std::uint32_t>(n));
  }
};

// Orientation of simplex s with its vertex in slot f replaced by p.
template <class K, int D>
Sign orient_with(const K& k, const Mesh<D>& m, const Point<D>* pts, std::uint32_t s, int f,
                 const Point<D>& p) {
  const std::uint32_t* w = m.vertices(s);
  auto at = [&](int i) -> const Point<D>& { return i == f ? p : pts[w[i]]; };
  if constexpr (D == 2)
    return orient_pos(k, at(0), at(1), at(2));
  else
    return orient_pos(k, at(0), at(1), at(2), at(3));
}

template <class K, int D>
Located visibility_walk(const K& k, const Mesh<D>& m, const Point<D>* pts, std::uint32_t start,
                        const Point<D>& p, std::uint64_t max_steps, WalkRng& rng) {
  constexpr int V = D + 1;
  Located r;
  std::uint32_t s = start;
  int from = -1;  // facet of s through which the walk entered
  if (m.is_ghost(s)) {
    if (orient_with<K, D>(k, m, pts, s, D, p) == Sign::positive) {
      r.end = Located::End::outside;
      r.simplex = s;
      return r;
    }
    const std::uint32_t enc = m.neighbour(s, D);
    s = Mesh<D>::simplex_of(enc);
    from = Mesh<D>::facet_of(enc);
    ++r.steps;
  }
  for (;;) {
  next_simplex:
    if (r.steps > max_steps) {
      r.end = Located::End::step_bound;
      r.simplex = s;
      return r;
    }
    const int offset = rng.next(V);
    int zeros = 0;
    for (int j = 0; j < V; ++j) {
      const int f = offset + j < V ? offset + j : offset + j - V;
      if (f == from) continue;
      const Sign o = orient_with<K, D>(k, m, pts, s, f, p);
      if (o == Sign::negative) {
        const std::uint32_t enc = m.neighbour(s, f);
        s = Mesh<D>::simplex_of(enc);
        from = Mesh<D>::facet_of(enc);
        ++r.steps;
        if (m.is_ghost(s)) {
          // Entered through the finite facet (the only facet a ghost shares
          // with a finite simplex), with p strictly beyond it.
          r.end = Located::End::outside;
          r.simplex = s;
          return r;
        }
        goto next_simplex;
      }
      if (o == Sign::zero) ++zeros;
    }
    r.end = Located::End::inside;
    r.simplex = s;
    r.zeros = zeros;
    return r;
  }
}

}  // namespace dlab
