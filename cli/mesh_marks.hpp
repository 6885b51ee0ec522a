// What a picture of a mesh marks (`dlab draw`, the fuzzer's failure pictures):
// every mark is an offence listed by the exact validator
// (algorithms/validate.hpp, the overload with offences); nothing here decides
// a sign. 2D pictures mark edges (svg_mesh.hpp), 3D ones flag cells
// (mesh_picture.hpp: a .vtu with cell data for ParaView).
#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "predicates/point.hpp"

namespace dlab::cli {

struct MeshMarks {
  // 2D: the edges of non-Delaunay facets and of overlaps (a < b, input
  // indices, sorted, each once).
  std::vector<std::array<std::uint32_t, 2>> non_delaunay_edges;
  std::vector<std::array<std::uint32_t, 2>> overlap_edges;
  // Per simplex.
  std::vector<std::uint8_t> inverted;             // not positively oriented (or flat)
  std::vector<std::uint8_t> overlapping;          // overlaps another (either side of the facet)
  std::vector<std::uint32_t> non_delaunay_facets;  // its facets that are not locally Delaunay
  // Per point.
  std::vector<std::uint8_t> missing;  // not a vertex
  // Further failed checks, one line each, then the validator's verdict.
  std::vector<std::string> other;
};

// Validates `simplices` of `points` (d+1 indices each) and turns the offences
// into marks; `report` receives the validator's report.
MeshMarks mesh_marks(const PointSet& points, std::span<const std::uint32_t> simplices,
                     ValidationReport& report);

}  // namespace dlab::cli
