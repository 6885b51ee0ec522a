// Non-Delaunay starting triangulations for flip-existing experiments
// (algorithms/flip_existing.hpp, `dlab flip --make-start`).
//
// Construction: the Delaunay triangulation of the points (Lawson, exact
// perturbed adaptive kernel, input order), then `flips` random flips applied
// whatever the in-circle / in-sphere test says -- 2D edge flips of convex
// quadrilaterals, 3D 2-3 flips of facets that segment pd crosses inside --
// each one kept only when every new simplex is positively oriented (exact
// test), so the result is always a valid triangulation of the same points and
// is non-Delaunay as soon as one flip was applied.  flips = 0 means n.
// Deterministic: splitmix64 from `seed`.  Lower-dimensional input: empty.
#pragma once
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

template <int D>
std::vector<std::uint32_t> non_delaunay_start(const std::vector<Point<D>>& pts, std::uint64_t seed,
                                              std::size_t flips = 0);

}  // namespace dlab
