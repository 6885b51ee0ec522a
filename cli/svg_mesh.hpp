// An SVG picture of a 2D triangulation with its faults marked (`dlab draw`).
// The writer draws what it is told: which edges, triangles and points are
// faulty comes from the exact validator (algorithms/validate.hpp) through
// MeshMarks; nothing here decides a sign.
//
// Layout: the bounding box of the points maps to the drawing area with one
// scale for x and y, y pointing up; a legend with the counts goes below.
// Every number is written with a fixed "%.2f", so the same input gives the
// same bytes.
//
// Elements (for scripts and tests): one <polygon class="tri ..."> per simplex,
// in input order, with data-simplex="s"; class "tri inverted" for a simplex
// that is not positively oriented, "tri overlap" for one that overlaps
// another; one <line class="edge-bad non-delaunay|overlap" data-edge="a b">
// per marked edge (a < b, input indices); one <circle class="missing"
// data-point="i"> per input point that is not a vertex.
#pragma once
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "cli/mesh_marks.hpp"
#include "predicates/point.hpp"

namespace dlab::cli {

struct SvgMeshOptions {
  bool circles = false;  // circumcircles of the positively oriented triangles
  bool labels = false;   // vertex indices
};

void write_svg_mesh(std::ostream& out, std::span<const Point2> points,
                    std::span<const std::uint32_t> simplices, const MeshMarks& marks,
                    const SvgMeshOptions& options);

}  // namespace dlab::cli
