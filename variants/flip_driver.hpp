// The template behind each variants/flip_<kernel>.cpp (see variants/flip.hpp).
#pragma once
#include <chrono>
#include <span>
#include <string>
#include <vector>

#include "algorithms/flip_existing.hpp"
#include "predicates/counted.hpp"
#include "predicates/kernel.hpp"
#include "predicates/perturbed.hpp"
#include "variants/flip.hpp"

namespace dlab {

namespace flip_detail {

template <class K, int D>
void flip_dimension(std::vector<Point<D>>& pts, std::span<const std::uint32_t> simplices, RunResult& r) {
  K base{};
  if constexpr (SnappingKernel<K, D>) {
    const auto st = base.snap_all(pts);
    r.snapping = {{"points_moved", st.moved}, {"points_merged", st.merged}};
    r.max_snap_displacement = st.max_displacement;
  }
  using Run = std::conditional_t<K::exact, counted<perturbed<K>>, counted<K>>;
  Run k = [&] {
    if constexpr (K::exact)
      return Run(perturbed<K>(base));
    else
      return Run(base);
  }();
  const auto t0 = std::chrono::steady_clock::now();
  FlipExistingResult f = flip_existing<D, Run>(std::span<const Point<D>>(pts), simplices, k);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.predicates = k.counters();
  r.counters = std::move(f.counters);
  r.simplices = std::move(f.simplices);
  if (f.outcome != RunResult::Outcome::ok) {
    r.outcome = RunResult::Outcome::failed;
    // A mesh the exact validator accepted that this kernel cannot build on.
    r.message = f.message.rfind("not a triangulation", 0) == 0
                    ? "the " + std::string(K::name) + " kernel sees the given mesh" +
                          (SnappingKernel<K, D> ? " (snapped)" : "") + " as " + f.message
                    : f.message;
  } else if (f.stuck_facets) {
    r.message = "flips stuck after " + std::to_string(f.flips) + " flips: " + std::to_string(f.stuck_facets) +
                " non-Delaunay facets left, none flippable";
  }
}

}  // namespace flip_detail

template <class K>
RunResult run_flip_with(const PointSet& points, std::span<const std::uint32_t> simplices) {
  RunResult r;
  r.dimension = points.dimension;
  r.points = points;
  r.inserted_points = points.size();
  if (simplices.empty()) {  // the caller's validator accepts that only for lower-dimensional points
    r.outcome = RunResult::Outcome::lower_dimensional;
    r.message = "fewer than " + std::to_string(points.dimension + 1) +
                " affinely independent points: no simplices given, none returned";
    r.inserted_points = 0;
    return r;
  }
  if (points.dimension == 2)
    flip_detail::flip_dimension<K, 2>(r.points.p2, simplices, r);
  else
    flip_detail::flip_dimension<K, 3>(r.points.p3, simplices, r);
  return r;
}

}  // namespace dlab
