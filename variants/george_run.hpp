// George's corrected cavity (algorithms/george.hpp) behind dlab::run(): picks the
// variant from RunOptions (exact_sphere, enclosing_box), runs it through the
// shared driver, and adds exact measurements of the result to its counters.
//
// Counters added here, after the run, with the exact validator
// (algorithms/validate.hpp), so that every `dlab triangulate --algo george`
// reports how far from Delaunay it ends (choice: computed on this registry
// path, not in the CLI, so tests and benchmarks see them too; not included in
// `seconds`):
//   valid                1 iff the result is a valid triangulation of the hull
//   non_delaunay_facets  interior facets that are not locally Delaunay
// With enclosing_box, what removing the box leaves missing from the hull:
//   hull_facets_missing      facets of the exact convex hull (from a ghost-vertex
//                            run on the same points) that are not boundary
//                            facets of the result (coplanar hull facets may be
//                            triangulated differently and count here too)
//   hull_volume_missing_ppm  hull volume not covered, parts per million
//                            (doubles: a statistic)
//   missing_vertices         distinct points left in no simplex
//   reflex_boundary_ridges   boundary ridges where the result is not convex
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <string_view>
#include <vector>

#include "algorithms/george.hpp"
#include "algorithms/validate.hpp"
#include "variants/driver.hpp"

namespace dlab {

template <class K, int D>
struct GeorgeExactSphere : George<K, D> {
  explicit GeorgeExactSphere(const K& k) : George<K, D>(k, GeorgeOptions{true, false}) {}
};
// With the enclosing box, the box corners are points George adds: the driver
// fits a snapping kernel's grid to them too (variants/driver.hpp).
template <class K, int D>
struct GeorgeBox : George<K, D> {
  explicit GeorgeBox(const K& k) : George<K, D>(k, GeorgeOptions{false, true}) {}
  static auto added_points(std::span<const Point<D>> input) { return enclosing_box_corners<D>(input); }
};
template <class K, int D>
struct GeorgeBoxExactSphere : George<K, D> {
  explicit GeorgeBoxExactSphere(const K& k) : George<K, D>(k, GeorgeOptions{true, true}) {}
  static auto added_points(std::span<const Point<D>> input) { return enclosing_box_corners<D>(input); }
};

namespace george_detail {

// Boundary facets (sorted vertex ids) of a flat simplex list.
template <int D>
std::vector<std::array<std::uint32_t, D>> boundary_facets(std::span<const std::uint32_t> flat) {
  std::map<std::array<std::uint32_t, D>, int> count;
  for (std::size_t s = 0; s + D < flat.size(); s += D + 1)
    for (int f = 0; f <= D; ++f) {
      std::array<std::uint32_t, D> k;
      int n = 0;
      for (int j = 0; j <= D; ++j)
        if (j != f) k[n++] = flat[s + j];
      std::sort(k.begin(), k.end());
      ++count[k];
    }
  std::vector<std::array<std::uint32_t, D>> out;
  for (const auto& [k, c] : count)
    if (c == 1) out.push_back(k);
  return out;
}

template <int D>
std::uint64_t hull_facets_missing(std::span<const std::uint32_t> hull_run,
                                  std::span<const std::uint32_t> box_run) {
  const auto hull = boundary_facets<D>(hull_run);
  const auto have = boundary_facets<D>(box_run);
  std::uint64_t missing = 0;
  for (const auto& f : hull)
    if (!std::binary_search(have.begin(), have.end(), f)) ++missing;
  return missing;
}

// Total volume (area) of a flat simplex list, in doubles (a statistic).
template <int D>
double total_volume(const std::vector<Point<D>>& p, std::span<const std::uint32_t> flat) {
  double v = 0;
  for (std::size_t s = 0; s + D < flat.size(); s += D + 1) {
    const Point<D>& o = p[flat[s]];
    if constexpr (D == 2) {
      const Point<D>&a = p[flat[s + 1]], &b = p[flat[s + 2]];
      v += ((a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])) / 2;
    } else {
      const Point<D>&a = p[flat[s + 1]], &b = p[flat[s + 2]], &c = p[flat[s + 3]];
      const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
      const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
      const double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
      v += (ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx)) / 6;
    }
  }
  return v;
}

template <int D>
std::uint64_t missing_ppm(const std::vector<Point<D>>& p, std::span<const std::uint32_t> hull_run,
                          std::span<const std::uint32_t> box_run) {
  const double h = total_volume<D>(p, hull_run), b = total_volume<D>(p, box_run);
  if (!(h > 0)) return 0;
  const double ppm = std::max(0.0, (h - b) / h * 1e6);
  return std::isfinite(ppm) ? static_cast<std::uint64_t>(std::llround(ppm)) : 0;
}

}  // namespace george_detail

template <class K>
RunResult run_george(PointSet&& points, const RunOptions& o) {
  RunResult r;
  if (o.enclosing_box)
    r = o.exact_sphere ? run_algorithm<GeorgeBoxExactSphere, K>(std::move(points), o)
                       : run_algorithm<GeorgeBox, K>(std::move(points), o);
  else
    r = o.exact_sphere ? run_algorithm<GeorgeExactSphere, K>(std::move(points), o)
                       : run_algorithm<George, K>(std::move(points), o);
  if (r.outcome != RunResult::Outcome::ok) return r;
  auto report = std::make_shared<const ValidationReport>(validate(r.points, r.simplices));
  const ValidationReport& rep = *report;
  r.validation = report;  // variants/outcome.hpp classifies the run with it
  r.counters.push_back({"valid", rep.valid() ? 1u : 0u});
  r.counters.push_back({"non_delaunay_facets", rep.non_delaunay_facets()});
  if (o.enclosing_box) {
    RunOptions g = o;
    g.enclosing_box = false;
    const RunResult hull = run_algorithm<George, K>(r.points, g);
    const std::uint64_t missing =
        r.dimension == 2 ? george_detail::hull_facets_missing<2>(hull.simplices, r.simplices)
                         : george_detail::hull_facets_missing<3>(hull.simplices, r.simplices);
    r.counters.push_back({"hull_facets_missing", missing});
    r.counters.push_back({"hull_volume_missing_ppm",
                          r.dimension == 2 ? george_detail::missing_ppm<2>(r.points.p2, hull.simplices, r.simplices)
                                           : george_detail::missing_ppm<3>(r.points.p3, hull.simplices, r.simplices)});
    r.counters.push_back({"missing_vertices", rep[Check::missing_vertex].count});
    r.counters.push_back({"reflex_boundary_ridges", rep[Check::boundary_convex].count});
  }
  return r;
}

}  // namespace dlab
