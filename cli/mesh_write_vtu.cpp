// See mesh_formats.hpp: VTK XML UnstructuredGrid, ASCII (Kitware, "VTK File
// Formats", XML file formats). Cell types: VTK_VERTEX = 1, VTK_TRIANGLE = 5,
// VTK_TETRA = 10; VTK_TETRA's positive orientation (v3 on the side of
// (v1-v0) x (v2-v0)) is SIMPLICES' det[v1-v0; v2-v0; v3-v0] > 0. CellData and
// PointData precede Points and Cells in a Piece, as that document orders them.
#include <stdexcept>
#include <string>

#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

// "      <CellData>...</CellData>\n", or nothing without arrays.
std::string data_block(const char* tag, const std::vector<VtuArray>& arrays, std::size_t count) {
  if (arrays.empty()) return {};
  std::string s = std::string("      <") + tag + ">\n";
  for (const VtuArray& a : arrays) {
    if (a.values.size() != count)
      throw std::logic_error("vtu_text: array '" + a.name + "' has the wrong length");
    s += "        <DataArray type=\"UInt32\" Name=\"" + a.name + "\" format=\"ascii\">\n";
    for (std::uint32_t v : a.values) s += std::to_string(v) + '\n';
    s += "        </DataArray>\n";
  }
  return s + "      </" + tag + ">\n";
}

}  // namespace

std::string vtu_piece_header(std::size_t points, std::size_t cells) {
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
         "    <Piece NumberOfPoints=\"" + std::to_string(points) + "\" NumberOfCells=\"" +
         std::to_string(cells) + "\">\n";
}

std::string vtu_text(const PointSet& points, const std::vector<std::uint32_t>* simplices,
                     const VtuData& data) {
  const std::size_t n = points.size();
  const std::size_t k = simplices ? static_cast<std::size_t>(points.dimension) + 1 : 1;
  const std::size_t cells = simplices ? simplices->size() / k : n;
  const int type = !simplices ? 1 : points.dimension == 2 ? 5 : 10;
  std::string s =
      vtu_piece_header(n, cells) + data_block("PointData", data.point, n) + data_block("CellData", data.cell, cells) +
      "      <Points>\n"
      "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = points.dimension == 2 ? (c < 2 ? points.p2[i][c] : 0.0) : points.p3[i][c];
      s += format_decimal(x);
      s += c == 2 ? '\n' : ' ';
    }
  }
  s += "        </DataArray>\n      </Points>\n      <Cells>\n"
       "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) {
    for (std::size_t j = 0; j < k; ++j) {
      s += std::to_string(simplices ? (*simplices)[c * k + j] : c);
      s += j + 1 == k ? '\n' : ' ';
    }
  }
  s += "        </DataArray>\n"
       "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) s += std::to_string((c + 1) * k) + '\n';
  s += "        </DataArray>\n"
       "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (std::size_t c = 0; c < cells; ++c) s += std::to_string(type) + '\n';
  s += "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return s;
}

}  // namespace dlab::io
