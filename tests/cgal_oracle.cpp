// The only translation unit that includes CGAL (see cgal_oracle.hpp).
// Duplicates are removed before insertion so that every vertex carries the
// index of the first occurrence of its point (CGAL keeps one vertex per point,
// and which copy's info survives a range insertion is not specified).
#include "tests/cgal_oracle.hpp"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <map>
#include <utility>

namespace dlab::oracle {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, K>;
using Tds2 = CGAL::Triangulation_data_structure_2<Vb2>;
using Dt2 = CGAL::Delaunay_triangulation_2<K, Tds2>;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, K>;
using Tds3 = CGAL::Triangulation_data_structure_3<Vb3>;
using Dt3 = CGAL::Delaunay_triangulation_3<K, Tds3>;

// First occurrences only (std::map treats -0.0 and +0.0 as the same key).
template <int D>
std::vector<std::uint32_t> distinct_indices(const std::vector<Point<D>>& points) {
  std::map<Point<D>, std::uint32_t> seen;
  std::vector<std::uint32_t> keep;
  for (std::uint32_t i = 0; i < points.size(); ++i)
    if (seen.emplace(points[i], i).second) keep.push_back(i);
  return keep;
}

}  // namespace

std::vector<Simplex<2>> cgal_delaunay(const std::vector<Point2>& points) {
  std::vector<std::pair<K::Point_2, std::uint32_t>> in;
  for (std::uint32_t i : distinct_indices<2>(points))
    in.emplace_back(K::Point_2(points[i][0], points[i][1]), i);
  Dt2 dt;
  dt.insert(in.begin(), in.end());
  std::vector<Simplex<2>> out;
  if (dt.dimension() < 2) return out;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.push_back(canonical<2>({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<Simplex<3>> cgal_delaunay(const std::vector<Point3>& points) {
  std::vector<std::pair<K::Point_3, std::uint32_t>> in;
  for (std::uint32_t i : distinct_indices<3>(points))
    in.emplace_back(K::Point_3(points[i][0], points[i][1], points[i][2]), i);
  Dt3 dt;
  dt.insert(in.begin(), in.end());
  std::vector<Simplex<3>> out;
  if (dt.dimension() < 3) return out;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    out.push_back(canonical<3>(
        {c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()}));
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace dlab::oracle
