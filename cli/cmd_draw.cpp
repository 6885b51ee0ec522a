// `dlab draw POINTS SIMPLICES -o FILE.svg|FILE.vtu [--circles] [--labels]`: a
// picture of a triangulation with its faults marked (cli/mesh_picture.hpp): an
// SVG of a 2D mesh, or a .vtu with per-cell fault flags for ParaView (3D, or
// 2D when FILE ends in .vtu). Every verdict -- non-Delaunay facet, inverted or
// flat simplex, overlap, missing point -- is an offence listed by the exact
// validator (algorithms/validate.hpp). Exit 0 if the mesh is a valid Delaunay
// triangulation, 1 if the picture shows faults, 2 on bad input or usage.
#include <fstream>
#include <iostream>
#include <string>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_picture.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"

namespace dlab::cli {

int cmd_draw(int argc, char** argv) {
  std::string points_path, input_format, simplices_path, out_path;
  SvgMeshOptions options;
  CommandLine cl(
      "draw", "usage: dlab draw POINTS SIMPLICES -o FILE.svg|FILE.vtu [--circles] [--labels]\n",
      "Draws a triangulation (SIMPLICES, as written by dlab triangulate) of POINTS with what the\n"
      "exact validator finds marked.\n"
      "2D, FILE.svg: non-Delaunay edges (red), inverted or flat triangles (purple), overlapping\n"
      "triangles and edges (orange), points that are not vertices (red rings); other failed checks\n"
      "are listed under the legend. -o - writes SVG to standard output.\n"
      "3D (or 2D with FILE.vtu): a VTK .vtu for ParaView with cell data faulty, inverted,\n"
      "overlapping (0/1) and non_delaunay_facets (0..d+1), point data missing (0/1): colour by\n"
      "'faulty' and apply a Threshold to see the faults.\n",
      "  dlab gen uniform --n 30 --seed 1 > p.txt\n"
      "  dlab triangulate p.txt --algo lawson --kernel float -o t.txt\n"
      "  dlab draw p.txt t.txt -o mesh.svg --labels && rsvg-convert mesh.svg -o mesh.png\n"
      "  dlab gen cospherical --dim 3 --n 200 > s.txt\n"
      "  dlab triangulate s.txt --kernel float -o s.tet; dlab draw s.txt s.tet -o faults.vtu\n",
      "Exit status: 0 valid Delaunay, 1 faults drawn, 2 bad input or usage.\n");
  CLI::App& app = cl.app();
  app.add_option("POINTS", points_path, "the points, as dlab triangulate reads them")->required();
  app.add_option("SIMPLICES", simplices_path, "d+1 zero-based indices into POINTS per line")->required();
  add_input_format(app, input_format, "POINTS");
  app.add_option("-o", out_path, "the picture: .svg (2D) or .vtu (2D or 3D); -: SVG on standard output")
      ->type_name("FILE")->required();
  app.add_flag("--circles", options.circles, "circumcircles of the positively oriented triangles (2D SVG, small inputs)");
  app.add_flag("--labels", options.labels, "vertex indices (2D SVG, small inputs)");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  PointSet points;
  std::vector<std::uint32_t> simplices;
  const bool as_vtu = out_path.size() >= 4 && out_path.compare(out_path.size() - 4, 4, ".vtu") == 0;
  try {
    if (points_path == "-" && simplices_path == "-")
      throw UsageError("POINTS and SIMPLICES cannot both be standard input");
    points = io::read_points(points_path, input_format);
    if (points.dimension == 3 && !as_vtu)
      throw io::InputError(io::display_name(points_path) +
                           ": 3D points: a 3D mesh is drawn as a .vtu file for ParaView: -o FILE.vtu");
    simplices = io::read_simplices(simplices_path, points.dimension, points.size());
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }
  const MeshPicture pic = mesh_picture(points, simplices, options, as_vtu);
  if (out_path == "-") {
    std::cout << pic.text << std::flush;
  } else {
    std::ofstream f(out_path, std::ios::binary);
    if (!(f << pic.text) || !f.flush()) {
      std::cerr << "dlab draw: cannot write '" << out_path << "'\n";
      return 2;
    }
  }
  return pic.report.delaunay() ? 0 : 1;
}

}  // namespace dlab::cli
