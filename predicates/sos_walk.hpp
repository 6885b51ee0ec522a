// The symbolic perturbation's walk (Devillers & Teillaud, "Perturbations for
// Delaunay and weighted Delaunay 3D triangulations", CGTA 44 (2011)): once the
// lifted determinant of D+2 points is exactly zero, its perturbed sign is the
// first non-zero cofactor, taken from the lexicographically largest point
// down. predicates/perturbed.hpp derives the cofactors; this file holds the
// walk alone, so that a kernel can run it on its own representation of the
// points (integer_kernel.hpp: on grid indices, which order and orient as the
// points do).
#pragma once
#include <array>
#include <cstddef>

#include "predicates/point.hpp"
#include "predicates/sign.hpp"

namespace dlab {

// Lexicographic comparison, exact (plain comparisons of the coordinates).
// P: Point<D>, or any array of D ordered numbers (grid indices).
template <int D, class P = Point<D>>
constexpr bool lex_less(const P& a, const P& b) {
  for (int i = 0; i < D; ++i) {
    if (a[i] < b[i]) return true;
    if (b[i] < a[i]) return false;
  }
  return false;
}

namespace sos {

// Indices 0..N-1 sorted by decreasing rank, less(i, j) meaning that point i
// ranks below point j (stable).
template <std::size_t N, class Less>
constexpr std::array<int, N> by_decreasing(Less less) {
  std::array<int, N> idx{};
  for (std::size_t i = 0; i < N; ++i) idx[i] = static_cast<int>(i);
  for (std::size_t i = 1; i < N; ++i)  // insertion sort: N <= 5
    for (std::size_t j = i; j > 0 && less(idx[j - 1], idx[j]); --j) {
      const int t = idx[j];
      idx[j] = idx[j - 1];
      idx[j - 1] = t;
    }
  return idx;
}

// Indices 0..N-1 of pts sorted by decreasing lexicographic order (stable).
template <int D, std::size_t N, class P = Point<D>>
constexpr std::array<int, N> by_decreasing_rank(const std::array<const P*, N>& pts) {
  return by_decreasing<N>([&](int i, int j) { return lex_less<D, P>(*pts[i], *pts[j]); });
}

// The perturbed sign of the lifted determinant of D+2 points (the last one is
// the query) once its exact value is zero, given their indices by decreasing
// lexicographic rank. `orient` takes D+1 point pointers.
template <int D, class P, class Orient>
Sign walk_in_order(const std::array<const P*, D + 2>& pts, const std::array<int, D + 2>& order,
                   Orient&& orient) {
  constexpr int query = D + 1;
  for (int i : order) {
    std::array<const P*, D + 1> simplex{};
    for (int j = 0; j <= D; ++j) simplex[j] = pts[j];
    Sign s;
    if (i == query) {
      s = -orient(simplex);
    } else {
      simplex[i] = pts[query];
      s = orient(simplex);
    }
    if (s != Sign::zero) return s;
  }
  return Sign::zero;  // only when the preconditions fail (all points collinear/coplanar)
}
template <int D, class P = Point<D>, class Orient>
Sign walk(const std::array<const P*, D + 2>& pts, Orient&& orient) {
  return walk_in_order<D, P>(pts, by_decreasing_rank<D, D + 2, P>(pts), orient);
}

}  // namespace sos
}  // namespace dlab
