// See mesh_formats.hpp: the output format by extension, and the dispatch.
#include <cerrno>
#include <cstring>
#include <fstream>
#include <iostream>
#include <iterator>

#include "cli/mesh_formats.hpp"
#include "cli/point_reader.hpp"

namespace dlab::io {
namespace {

bool ends_with_ci(std::string_view path, std::string_view ext) {
  if (path.size() < ext.size()) return false;
  for (std::size_t i = 0; i < ext.size(); ++i) {
    char c = path[path.size() - ext.size() + i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != ext[i]) return false;
  }
  return true;
}

}  // namespace

bool mesh_format_of(std::string_view path, MeshFormat& format) {
  if (ends_with_ci(path, ".node")) format = MeshFormat::tetgen_node;
  else if (ends_with_ci(path, ".vtu")) format = MeshFormat::vtu;
  else if (ends_with_ci(path, ".off")) format = MeshFormat::off;
  else return false;
  return true;
}

MeshFormat choose_mesh_format(std::string_view path, std::string_view name) {
  std::string choices;
  for (std::size_t i = 0; i < std::size(kMeshFormatNames); ++i) {
    if (!name.empty() && name == kMeshFormatNames[i]) return static_cast<MeshFormat>(i);
    choices += std::string(i ? ", " : "") + kMeshFormatNames[i];
  }
  if (!name.empty()) throw InputError("unknown format '" + std::string(name) + "' (choices: " + choices + ")");
  MeshFormat format{};
  if (!mesh_format_of(path, format))
    throw InputError("'" + std::string(path) +
                     "': no format by its extension (.node, .vtu or .off): name one with --format (" + choices + ")");
  return format;
}

bool is_vertex_list_file(std::string_view path) {
  return ends_with_ci(path, ".xyz") || ends_with_ci(path, ".off") || ends_with_ci(path, ".ply");
}

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError(path + ": cannot write: " + std::strerror(errno));
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();
  if (!out) throw InputError(path + ": cannot write: " + std::strerror(errno));
}

std::vector<std::string> write_mesh(const std::string& path, MeshFormat format,
                                    const PointSet& points,
                                    const std::vector<std::uint32_t>* simplices) {
  const std::string name = path == "-" ? "<stdout>" : path;
  std::string text;
  switch (format) {
    case MeshFormat::tetgen_node:
      if (path == "-") throw InputError("<stdout>: the node format writes several files: name BASE.node");
      return write_node_files(ends_with_ci(path, ".node") ? path.substr(0, path.size() - 5) : path, points,
                              simplices);
    case MeshFormat::vtu:
      text = vtu_text(points, simplices);
      break;
    case MeshFormat::off:
      if (simplices && points.dimension == 3)
        throw InputError(name + ": OFF holds triangles only: write 3D tetrahedra as .vtu or .node");
      text = off_text(points, simplices);
      break;
  }
  if (path != "-") {
    write_text_file(path, text);
    return {path};
  }
  std::cout.write(text.data(), static_cast<std::streamsize>(text.size()));
  std::cout.flush();
  if (!std::cout) throw InputError("<stdout>: cannot write");
  return {name};
  return {};
}

}  // namespace dlab::io
