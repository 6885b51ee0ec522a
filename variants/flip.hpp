// `dlab flip`'s engine behind a kernel name: flip a given triangulation toward
// Delaunay (algorithms/flip_existing.hpp) with any kernel of the registry, the
// same way dlab::run() triangulates (variants/run.hpp): one translation unit
// per kernel (variants/flip_<kernel>.cpp), predicate calls counted, the integer
// kernel's snapping applied and reported, the result as a RunResult that
// variants/outcome.hpp classifies.
//
// Policy: as `dlab triangulate`'s default, exact kernels run symbolically
// perturbed (sos: a 2D result is then the unique perturbed Delaunay
// triangulation), the inexact baselines plain (strict).
//
// The caller checks first that `simplices` triangulate the points (the exact
// validator; `dlab flip` exits 2 otherwise). What a kernel then still rejects
// -- an inexact kernel seeing a simplex as flat, or snapping flattening one --
// is the run's failure (RunResult::Outcome::failed), as is exceeding the flip
// bound. Flips stuck in 3D (Joe 1991) are not a failure: the result is valid,
// its message says so, and the classification counts what is not Delaunay.
#pragma once
#include <cstdint>
#include <span>

#include "variants/run.hpp"

namespace dlab {

// RunOptions: kernel only (algorithm, policy, order and seed are ignored).
// Counters: flips by type, flips_total, unflippable_tests, passes,
// stuck_facets. inserted_points: every input point (all are given at once).
RunResult run_flip(const PointSet& points, std::span<const std::uint32_t> simplices, const RunOptions& o);

}  // namespace dlab
