// The files of `dlab voronoi` (voronoi/voronoi_cells.hpp):
//  * SVG (2D): the box, every cell outlined (clipped ones shaded), every site
//    a dot; y up, one scale, coordinates with %.2f in a 800-pixel frame.
//  * VTK XML UnstructuredGrid (.vtu), ASCII (Kitware, "VTK File Formats"):
//    Points = the diagram's vertices (2D: z = 0) as shortest round-trip
//    decimals; 2D cells VTK_POLYGON (7), 3D cells VTK_POLYHEDRON (42) with the
//    "faces" array (per cell: number of faces, then per face its number of
//    points and the point ids) and "faceoffsets" (where each cell's faces end)
//    beside connectivity / offsets / types. CellData: site (UInt32, the input
//    index), clipped (UInt8). PointData: simplex (Int64, the Delaunay simplex
//    whose circumcentre the point is, -1 for a point a cut made).
#pragma once
#include <string>

#include "voronoi/voronoi_cells.hpp"

namespace dlab::cli {

std::string voronoi_svg(const voronoi::Diagram<2>& d, const std::vector<Point2>& sites,
                        const Point2& lo, const Point2& hi);
template <int D>
std::string voronoi_vtu(const voronoi::Diagram<D>& d);

}  // namespace dlab::cli
