// The CGAL oracle: CGAL's Delaunay_triangulation_2/3 over Epick (exact
// predicates, inexact constructions) on the same points, returned as the
// finite simplices in one canonical form, so that two triangulations can be
// compared with ==. Only cgal_oracle.cpp includes CGAL (it is slow to compile).
//
// Canonical form of a simplex: its indices sorted ascending, then the last two
// swapped when the sorting permutation was odd, so that orientation is kept
// (an even permutation of a positively oriented simplex is positive). In 2D
// this is the rotation that puts the smallest index first. The list is sorted.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "predicates/point.hpp"

namespace dlab::oracle {

template <int D>
using Simplex = std::array<std::uint32_t, D + 1>;

template <int D>
Simplex<D> canonical(Simplex<D> s) {
  bool odd = false;
  for (int a = 1; a <= D; ++a)
    for (int b = a; b > 0 && s[b - 1] > s[b]; --b) {
      const std::uint32_t t = s[b - 1];
      s[b - 1] = s[b];
      s[b] = t;
      odd = !odd;
    }
  if (odd) {
    const std::uint32_t t = s[D - 1];
    s[D - 1] = s[D];
    s[D] = t;
  }
  return s;
}

// Flat index list (d+1 per simplex) -> sorted list of canonical simplices.
template <int D>
std::vector<Simplex<D>> canonical_simplices(std::span<const std::uint32_t> flat) {
  std::vector<Simplex<D>> out(flat.size() / (D + 1));
  for (std::size_t s = 0; s < out.size(); ++s) {
    for (int j = 0; j <= D; ++j) out[s][j] = flat[s * (D + 1) + j];
    out[s] = canonical<D>(out[s]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// CGAL's Delaunay triangulation (with its symbolic perturbation, so unique):
// finite simplices as canonical index tuples, sorted, every index the first
// occurrence of its point. Lower-dimensional input gives an empty list.
std::vector<Simplex<2>> cgal_delaunay(const std::vector<Point2>& points);
std::vector<Simplex<3>> cgal_delaunay(const std::vector<Point3>& points);

// The same as one flat index list, each simplex positively oriented.
template <int D>
std::vector<std::uint32_t> flatten(const std::vector<Simplex<D>>& simplices) {
  std::vector<std::uint32_t> flat;
  flat.reserve(simplices.size() * (D + 1));
  for (const auto& s : simplices) flat.insert(flat.end(), s.begin(), s.end());
  return flat;
}

}  // namespace dlab::oracle
