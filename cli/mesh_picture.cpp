// See mesh_picture.hpp.
#include "cli/mesh_picture.hpp"

#include <sstream>
#include <vector>

#include "cli/mesh_formats.hpp"

namespace dlab::cli {
namespace {

template <class T>
io::VtuArray array(const char* name, const std::vector<T>& v) {
  return {name, std::vector<std::uint32_t>(v.begin(), v.end())};
}

}  // namespace

MeshPicture mesh_picture(const PointSet& points, std::span<const std::uint32_t> simplices,
                         const SvgMeshOptions& svg, bool as_vtu) {
  MeshPicture pic;
  const MeshMarks marks = mesh_marks(points, simplices, pic.report);
  if (points.dimension == 2 && !as_vtu) {
    std::ostringstream out;
    write_svg_mesh(out, points.p2, simplices, marks, svg);
    pic.text = out.str();
    return pic;
  }
  io::VtuData data;
  std::vector<std::uint32_t> faulty(marks.inverted.size());
  for (std::size_t s = 0; s < faulty.size(); ++s)
    faulty[s] = marks.inverted[s] || marks.overlapping[s] || marks.non_delaunay_facets[s] > 0;
  data.cell = {array("faulty", faulty), array("inverted", marks.inverted),
               array("overlapping", marks.overlapping),
               array("non_delaunay_facets", marks.non_delaunay_facets)};
  data.point = {array("missing", marks.missing)};
  const std::vector<std::uint32_t> cells(simplices.begin(), simplices.end());
  pic.text = io::vtu_text(points, &cells, data);
  pic.extension = ".vtu";
  return pic;
}

}  // namespace dlab::cli
