// The Voronoi diagram of a point set as the dual of its Delaunay triangulation,
// every cell bounded by an axis-parallel box (the picture's frame).
//
// Vertices: vertices[i], i < simplices, is the circumcentre of Delaunay simplex
// i, exactly rounded (circumcentre.hpp); vertices after those were made by
// cuts (convex_clip.hpp, floating point). Simplices whose centres are equal
// (cocircular / cospherical points: the symbolic perturbation's zero-length
// Voronoi edges) share the first one's vertex, and consecutive equal vertices
// of a cell are merged, so every cell is a valid polygon / polyhedron.
//
// Cells, one per distinct site that is a vertex of the triangulation (a later
// duplicate of a point has none; nor has a site whose cell misses the box):
//  * a site inside the triangulation (not on the hull): 2D, the cycle of the
//    circumcentres of its triangles in counterclockwise order; 3D, one face per
//    Delaunay edge st, the cycle of the circumcentres of the tetrahedra around
//    st, oriented with its normal toward t (the dual of the edge: e.g.
//    Edelsbrunner, "Geometry and Topology for Mesh Generation", 2001, ch. 1).
//    Where a centre lies outside the box, the cell is cut by the box's sides
//    and flagged clipped;
//  * a hull site (its cell is unbounded): the box cut by the bisector of each
//    Delaunay neighbour q, {x : (q - s).(x - (s + q)/2) <= 0}; flagged clipped.
// Without simplices (lower-dimensional input: collinear / coplanar points, or
// fewer than d+1) every distinct site is cut by the bisectors of all the
// others (O(n^2)).
// Faces are counterclockwise seen from outside the cell.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dlab::voronoi {

struct Cell {
  std::uint32_t site = 0;  // index into the input points
  bool clipped = false;    // cut by the box (always for hull sites)
  // 2D: one face, the polygon; 3D: the faces of the polyhedron. Indices into
  // Diagram::vertices.
  std::vector<std::vector<std::uint32_t>> faces;
};

template <int D>
struct Diagram {
  std::vector<Point<D>> vertices;
  std::size_t centres = 0;  // vertices[i < centres]: circumcentre of simplex i
  std::vector<Cell> cells;
};

// simplices: d+1 indices each, positively oriented, a Delaunay triangulation
// of points (the caller has validated it), or empty for lower-dimensional
// input. lo < hi on every axis.
Diagram<2> voronoi_cells(const std::vector<Point2>& points, const std::vector<std::uint32_t>& simplices,
                         const Point2& lo, const Point2& hi);
Diagram<3> voronoi_cells(const std::vector<Point3>& points, const std::vector<std::uint32_t>& simplices,
                         const Point3& lo, const Point3& hi);

}  // namespace dlab::voronoi
