// The CGAL oracle: CGAL's Delaunay_triangulation_2/3 over Epick (exact
// predicates, inexact constructions) on the same points, returned as the
// finite simplices in one canonical form, so that two triangulations can be
// compared with ==. Only cgal_oracle.cpp includes CGAL (it is slow to compile).
//
// (Canonical form: tests/run_readout.hpp.)
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "predicates/point.hpp"
#include "tests/run_readout.hpp"

namespace dlab::oracle {

using test::Simplex;
using test::canonical;
using test::canonical_simplices;

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
