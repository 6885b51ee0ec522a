// Mesh file formats of other tools, chosen by the file name's extension
// (`dlab convert`, and INPUT of every command for the vertex lists).
//  Writers (points, and optionally SIMPLICES as in simplex_io.hpp):
//   * Triangle (2D) / TetGen (3D): BASE.node, BASE.ele, and BASE.neigh (2D:
//     neighbour i is the triangle across the edge opposite vertex i, -1 on the
//     hull) or BASE.face (3D: the hull facets, oriented outward). Indices start
//     at 0, as Triangle and TetGen accept when the .node file starts at 0.
//     Formats: J.R. Shewchuk, Triangle's documentation (.node/.ele/.neigh);
//     H. Si, TetGen user manual, section 5 (.node/.ele/.face).
//   * VTK XML UnstructuredGrid (.vtu), ASCII: Float64 points (2D points get
//     z = 0), cells VTK_TRIANGLE (5) / VTK_TETRA (10), or VTK_VERTEX (1) per
//     point without SIMPLICES. Kitware, "VTK File Formats" (XML formats).
//   * OFF (.off): 3 coordinates per vertex (2D: z = 0), triangles only.
//     Geomview's OFF documentation.
//  Coordinates are written as shortest round-trip decimals: read back exactly.
//  Readers of vertex lists (one point set; every other element is ignored):
//   * .xyz: "x y z" per line ('#' comments, blank lines);
//   * .off: the vertices of an OFF file (Geomview: "OFF", counts, vertices);
//   * .ply: the x, y[, z] properties of the vertex element of an ASCII PLY
//     file (Turk, "The PLY polygon file format"); binary PLY is refused.
//  A vertex list whose every z is 0 (and a PLY vertex without z) is read as 2D.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "variants/run.hpp"

namespace dlab::io {

enum class MeshFormat { tetgen_node, vtu, off };

// The format of an output path by its extension (any case), or nullopt-like
// `false` when none matches.
bool mesh_format_of(std::string_view path, MeshFormat& format);

// The formats by name, as --format takes them (in MeshFormat's order).
inline constexpr const char* kMeshFormatNames[] = {"node", "vtu", "off"};
// The format named `name` (--format) when it is not empty, else the one of
// the path's extension; InputError naming the choices when neither names one.
MeshFormat choose_mesh_format(std::string_view path, std::string_view name);

// Writes `points` (and the simplices, d+1 zero-based indices each, when given)
// to `path` in `format`; "-" is standard output (vtu and off: one file). The
// node writer writes BASE.node and its sibling files, BASE being the path
// without its .node extension (or the whole path when it has another one).
// Returns the paths written. Throws InputError "PATH: cannot write" or, for
// OFF with 3D simplices, "PATH: OFF holds triangles only ...".
std::vector<std::string> write_mesh(const std::string& path, MeshFormat format,
                                    const PointSet& points,
                                    const std::vector<std::uint32_t>* simplices);

// The writers behind write_mesh. `simplices` may be null (points only).
// write_node_files: BASE.node [+ BASE.ele + BASE.neigh (2D) / BASE.face (3D)].
std::vector<std::string> write_node_files(const std::string& base, const PointSet& points,
                                          const std::vector<std::uint32_t>* simplices);
// Integer arrays attached to the cells or the points of a .vtu (ParaView
// colours by them): CellData / PointData, each a named UInt32 DataArray with
// one value per cell / point.
struct VtuArray {
  std::string name;
  std::vector<std::uint32_t> values;
};
struct VtuData {
  std::vector<VtuArray> cell, point;
};
std::string vtu_text(const PointSet& points, const std::vector<std::uint32_t>* simplices,
                     const VtuData& data = {});
// The XML declaration, VTKFile and UnstructuredGrid openings and the Piece
// tag of a .vtu with one piece: what every .vtu writer starts with.
std::string vtu_piece_header(std::size_t points, std::size_t cells);
std::string off_text(const PointSet& points, const std::vector<std::uint32_t>* simplices);
// Writes text to path; InputError "PATH: cannot write: reason".
void write_text_file(const std::string& path, const std::string& text);

// The facets of the simplices: for simplex s and vertex i, the simplex across
// the facet opposite vertex i, or -1 when that facet lies on the hull.
std::vector<std::int64_t> simplex_neighbours(const std::vector<std::uint32_t>& simplices,
                                             int dimension);

// Vertex lists: true if the path ends in .xyz, .off or .ply (any case).
bool is_vertex_list_file(std::string_view path);
// Parses one (ext: ".xyz", ".off" or ".ply"; read_points() in point_reader.hpp
// reads files); InputError "FILE:LINE: problem" on bad input.
PointSet parse_vertex_list(std::string_view text, const std::string& name, std::string_view ext);

}  // namespace dlab::io
