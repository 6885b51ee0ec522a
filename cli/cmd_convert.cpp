// `dlab convert POINTS OUT [--simplices SIMPLICES] [--format FMT] [--input-format FMT]`:
// a point set, and optionally a triangulation of it, into another tool's mesh
// format chosen by OUT's extension or --format (mesh_formats.hpp). Exit 0 on
// success, 2 on bad input or usage.
#include <iostream>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_formats.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"

namespace dlab::cli {

int cmd_convert(int argc, char** argv) {
  std::string points_path, out, simplices_path, format, input_format;
  CommandLine cl(
      "convert",
      "usage: dlab convert POINTS OUT [--simplices SIMPLICES] [--format FMT] [--input-format FMT]\n",
      "Writes POINTS (and the triangulation SIMPLICES of them, d+1 zero-based indices per line,\n"
      "as `dlab triangulate -o` writes) in the format of OUT's extension, or of --format:\n"
      "  BASE.node  Triangle (2D) / TetGen (3D): BASE.node, and with SIMPLICES also BASE.ele and\n"
      "             BASE.neigh (2D: neighbour i across the edge opposite vertex i, -1 on the hull)\n"
      "             or BASE.face (3D: the hull facets, oriented outward); numbered from 0\n"
      "  .vtu       VTK XML unstructured grid, ASCII, for ParaView: Float64 points (2D: z = 0),\n"
      "             triangles (VTK type 5) or tetrahedra (10); without SIMPLICES one vertex cell\n"
      "             (type 1) per point\n"
      "  .off       OFF: vertices (2D: z = 0) and triangles; 2D triangulations only\n"
      "Coordinates are written as shortest round-trip decimals: reading them gives the same doubles.\n",
      "  dlab gen uniform --n 100 -o pts.txt && dlab triangulate pts.txt -o tri.txt\n"
      "  dlab convert pts.txt mesh.vtu --simplices tri.txt     # open mesh.vtu in ParaView\n"
      "  dlab convert pts.txt mesh.node --simplices tri.txt    # mesh.node, mesh.ele, mesh.neigh\n"
      "  dlab convert bunny.ply bunny.node && tetgen bunny.node  # TetGen's own tetrahedralization\n"
      "  dlab convert surface.off pts.vtu                      # vertices only\n"
      "  dlab convert pts.txt - --format vtu --simplices tri.txt > mesh.xml  # to standard output\n"
      "  dlab convert cloud.asc pts.node --input-format xyz     # an .xyz file by another name\n",
      "Exit status: 0 success, 2 bad input or usage.\n");
  CLI::App& app = cl.app();
  app.add_option("POINTS", points_path,
                 "any INPUT of dlab triangulate: plain text, .node, or the vertex list of a .xyz\n"
                 "(x y z per line), .off or ASCII .ply file; a vertex list whose every z is 0 is 2D")
      ->required();
  app.add_option("OUT", out, "the file to write: BASE.node, .vtu or .off; - (vtu, off): standard output")
      ->required();
  app.add_option("--format", format, "node, vtu or off, whatever OUT's extension (default: by the extension)")
      ->type_name("FMT");
  add_input_format(app, input_format, "POINTS");
  app.add_option("--simplices", simplices_path, "a triangulation of POINTS, written with them")
      ->type_name("SIMPLICES");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  try {
    const io::MeshFormat out_format = io::choose_mesh_format(out, format);
    const bool with_simplices = !simplices_path.empty();
    if (points_path == "-" && simplices_path == "-")
      throw UsageError("POINTS and SIMPLICES cannot both be standard input");
    const PointSet points = io::read_points(points_path, input_format);
    std::vector<std::uint32_t> simplices;
    if (with_simplices) simplices = io::read_simplices(simplices_path, points.dimension, points.size());
    for (const std::string& path : io::write_mesh(out, out_format, points, with_simplices ? &simplices : nullptr))
      std::cerr << "wrote " << path << "\n";
    return 0;
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace dlab::cli
