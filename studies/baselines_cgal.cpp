// cgal-epick and cgal-epeck: CGAL's Delaunay_triangulation_2/3 in process, the
// only translation unit of the studies that includes CGAL (it compiles slowly).
//
// Timed: the range insertion of all points with their input index as vertex
// info, CGAL's usual way (it spatially sorts the range, then inserts point by
// point); not the construction of the range nor the traversal of the cells
// afterwards. Duplicates are inserted too: CGAL keeps one vertex per point,
// with the info of whichever copy came first in its sorted order, and
// run_baseline() maps that to the first occurrence.
#include "studies/baselines_tools.hpp"

#if DLAB_HAVE_CGAL
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#endif

#include <utility>
#include <vector>

namespace dlab::baselines {

#if DLAB_HAVE_CGAL
namespace {

template <class K>
BaselineRun triangulate_2(const std::vector<Point2>& points) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
  using Dt = CGAL::Delaunay_triangulation_2<K, CGAL::Triangulation_data_structure_2<Vb>>;
  std::vector<std::pair<typename K::Point_2, std::uint32_t>> in;
  in.reserve(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i)
    in.emplace_back(typename K::Point_2(points[i][0], points[i][1]), i);
  Dt dt;
  BaselineRun run;
  const double w0 = wall_seconds_now(), c0 = process_cpu_seconds();
  dt.insert(in.begin(), in.end());
  run.cpu_seconds = process_cpu_seconds() - c0;
  run.wall_seconds = wall_seconds_now() - w0;
  run.outcome = "ok-so-far";
  if (dt.dimension() < 2) return run;  // no face: the validator says lower-dimensional
  run.simplices.reserve(3 * dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for (int j = 0; j < 3; ++j) run.simplices.push_back(f->vertex(j)->info());
  return run;
}

template <class K>
BaselineRun triangulate_3(const std::vector<Point3>& points) {
  using Vb = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
  using Dt = CGAL::Delaunay_triangulation_3<K, CGAL::Triangulation_data_structure_3<Vb>>;
  std::vector<std::pair<typename K::Point_3, std::uint32_t>> in;
  in.reserve(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i)
    in.emplace_back(typename K::Point_3(points[i][0], points[i][1], points[i][2]), i);
  Dt dt;
  BaselineRun run;
  const double w0 = wall_seconds_now(), c0 = process_cpu_seconds();
  dt.insert(in.begin(), in.end());
  run.cpu_seconds = process_cpu_seconds() - c0;
  run.wall_seconds = wall_seconds_now() - w0;
  run.outcome = "ok-so-far";
  if (dt.dimension() < 3) return run;
  run.simplices.reserve(4 * dt.number_of_finite_cells());
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for (int j = 0; j < 4; ++j) run.simplices.push_back(c->vertex(j)->info());
  return run;
}

template <class K>
BaselineRun triangulate(const PointSet& points) {
  return points.dimension == 2 ? triangulate_2<K>(points.p2) : triangulate_3<K>(points.p3);
}

}  // namespace

BaselineRun run_cgal(const PointSet& points, bool exact) {
  return exact ? triangulate<CGAL::Exact_predicates_exact_constructions_kernel>(points)
               : triangulate<CGAL::Exact_predicates_inexact_constructions_kernel>(points);
}

std::optional<std::string> cgal_unavailable() { return std::nullopt; }

#else

BaselineRun run_cgal(const PointSet&, bool) {
  BaselineRun run;
  run.skipped = true;
  run.message = *cgal_unavailable();
  return run;
}

std::optional<std::string> cgal_unavailable() {
  return std::string("dlab was built without CGAL (find_package(CGAL) failed)");
}

#endif

}  // namespace dlab::baselines
