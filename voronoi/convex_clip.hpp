// Convex polygons (2D) and polyhedra (3D) cut by halfspaces, in floating
// point: the Voronoi cells that the box bounds (voronoi_cells.hpp). Nothing
// here is exact and nothing here decides a sign for an algorithm: these are
// the constructions of a picture. Each vertex carries an id (the Delaunay
// simplex whose circumcentre it is, or kNewVertex for a vertex the cut made),
// so that the exactly rounded circumcentres survive a cut unchanged.
//
// A cut keeps {x : n.(x - m) <= 0}. A vertex within tol = 1e-12 |n| L of the
// plane (L: the scale given, the box's diagonal) counts as on it, so that a cut
// through a vertex adds no sliver; the new vertices on edges are
// x_i + (x_j - x_i) d_i / (d_i - d_j) (Sutherland and Hodgman, "Reentrant
// polygon clipping", CACM 17(1), 1974). The cap face of a polyhedron cut is
// the new vertices (and those on the plane) in angular order around their
// centroid, oriented with its normal n pointing out. Consecutive vertices at
// the same position are merged; faces left with fewer than 3 vertices go.
#pragma once
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dlab::voronoi {

inline constexpr std::int64_t kNewVertex = -1;

template <int D>
struct Vertex {
  Point<D> p;
  std::int64_t id = kNewVertex;
};

// Vertices in counterclockwise order.
using Polygon = std::vector<Vertex<2>>;

// Faces as vertex lists, counterclockwise seen from outside.
struct Polyhedron {
  std::vector<Vertex<3>> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
  bool empty() const { return faces.size() < 4; }
};

Polygon box_polygon(const Point2& lo, const Point2& hi);
Polyhedron box_polyhedron(const Point3& lo, const Point3& hi);

// Keeps the part with n.(x - m) <= 0; `scale` sets the tolerance above.
Polygon cut(const Polygon& poly, const Point2& n, const Point2& m, double scale);
Polyhedron cut(const Polyhedron& poly, const Point3& n, const Point3& m, double scale);

// The cuts by the box's sides (nothing changes where every vertex is inside).
Polygon cut_to_box(Polygon poly, const Point2& lo, const Point2& hi);
Polyhedron cut_to_box(Polyhedron poly, const Point3& lo, const Point3& hi);

// Consecutive vertices at equal positions (cyclically) become one; for a
// polyhedron also equal positions anywhere, and unused vertices go.
Polygon merge_equal(const Polygon& poly);
Polyhedron merge_equal(const Polyhedron& poly);

}  // namespace dlab::voronoi
