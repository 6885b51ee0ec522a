// A picture of a mesh with its faults marked by the exact validator
// (mesh_marks.hpp), in the form that suits its dimension:
//   2D: SVG (svg_mesh.hpp): non-Delaunay edges, inverted and overlapping
//       triangles, missing points drawn;
//   3D: VTK XML .vtu (mesh_formats.hpp) for ParaView, the tetrahedra with cell
//       data "inverted" (0/1), "overlapping" (0/1), "non_delaunay_facets"
//       (0..4) and "faulty" (1 if any of them), and point data "missing" (0/1):
//       colour by "faulty" and threshold it to see the faults.
// Used by `dlab draw` and by the fuzzer for each failure it writes.
#pragma once
#include <cstdint>
#include <span>
#include <string>

#include "cli/svg_mesh.hpp"
#include "predicates/point.hpp"

namespace dlab::cli {

struct MeshPicture {
  std::string text;
  const char* extension = ".svg";  // ".svg" (2D) or ".vtu" (3D)
  ValidationReport report;         // the validator's verdict on the mesh
};

// `svg` applies to 2D only. A .vtu can be asked for in 2D too (as_vtu).
MeshPicture mesh_picture(const PointSet& points, std::span<const std::uint32_t> simplices,
                         const SvgMeshOptions& svg = {}, bool as_vtu = false);

}  // namespace dlab::cli
