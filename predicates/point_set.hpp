// A point set of dimension 2 or 3, as the algorithms, the validator and the
// entry point dlab::run() (variants/run.hpp) take it.
#pragma once
#include <cstddef>
#include <utility>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

// Points of one dimension (2 or 3); only the matching vector is used.
struct PointSet {
  int dimension = 2;
  std::vector<Point2> p2;
  std::vector<Point3> p3;
  std::size_t size() const { return dimension == 2 ? p2.size() : p3.size(); }
};

// The vector of dimension D in `ps`.
template <int D>
std::vector<Point<D>>& points_of(PointSet& ps) {
  if constexpr (D == 2)
    return ps.p2;
  else
    return ps.p3;
}
template <int D>
const std::vector<Point<D>>& points_of(const PointSet& ps) {
  if constexpr (D == 2)
    return ps.p2;
  else
    return ps.p3;
}

// A point set of dimension D holding `pts`.
template <int D>
PointSet point_set(std::vector<Point<D>> pts) {
  PointSet ps;
  ps.dimension = D;
  points_of<D>(ps) = std::move(pts);
  return ps;
}

}  // namespace dlab
