// `dlab draw POINTS SIMPLICES -o FILE.svg [--circles] [--labels]`: an SVG
// picture of a 2D triangulation with its faults marked. Every verdict --
// non-Delaunay edge, inverted or flat triangle, overlap, missing point -- is an
// offence listed by the exact validator (algorithms/validate.hpp); this file
// only turns offences into edges, triangles and points to mark (svg_mesh.hpp).
// Exit 0 if the mesh is a valid Delaunay triangulation, 1 if the picture shows
// faults, 2 on bad input or usage (3D included: its pictures are .vtu files).
#include <algorithm>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include "algorithms/validate.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"
#include "cli/svg_mesh.hpp"

namespace dlab::cli {
namespace {

const char* const kDrawUsage =
    "usage: dlab draw POINTS SIMPLICES -o FILE.svg [--circles] [--labels]\n"
    "Draws a 2D triangulation (SIMPLICES, as written by dlab triangulate) of POINTS as SVG, with\n"
    "what the exact validator finds marked: non-Delaunay edges (red), inverted or flat triangles\n"
    "(purple), overlapping triangles and edges (orange), points that are not vertices (red rings);\n"
    "other failed checks are listed under the legend. -o - writes to standard output.\n"
    "  --circles  circumcircles of the positively oriented triangles (for small inputs)\n"
    "  --labels   vertex indices (for small inputs)\n"
    "Exit status: 0 valid Delaunay, 1 faults drawn, 2 bad input or usage (3D: not drawn here).\n"
    "Example:\n"
    "  dlab gen uniform --n 30 --seed 1 > p.txt\n"
    "  dlab triangulate p.txt --algo lawson --kernel float -o t.txt\n"
    "  dlab draw p.txt t.txt -o mesh.svg --labels && rsvg-convert mesh.svg -o mesh.png\n";

std::array<std::uint32_t, 2> edge(std::span<const std::uint32_t> simplices, std::int64_t s, int facet) {
  const std::uint32_t a = simplices[3 * s + (facet + 1) % 3], b = simplices[3 * s + (facet + 2) % 3];
  return {std::min(a, b), std::max(a, b)};
}

// The validator's offences as marks; "other" gets one line per failed check
// that the picture does not show.
MeshMarks marks_of(const ValidationReport& rep, const std::vector<Offence>& offences,
                   std::span<const std::uint32_t> simplices, std::size_t points) {
  const std::size_t m = simplices.size() / 3;
  MeshMarks k;
  k.inverted.assign(m, 0);
  k.overlapping.assign(m, 0);
  k.missing.assign(points, 0);
  // The simplices on each edge (combinatorial: both sides of an overlap edge).
  std::map<std::array<std::uint32_t, 2>, std::vector<std::size_t>> on_edge;
  for (std::size_t s = 0; s < m; ++s)
    for (int i = 0; i < 3; ++i) on_edge[edge(simplices, static_cast<std::int64_t>(s), i)].push_back(s);
  for (const Offence& o : offences) {
    switch (o.check) {
      case Check::not_delaunay:
        k.non_delaunay_edges.push_back(edge(simplices, o.simplex, o.facet));
        break;
      case Check::facet_same_side:
      case Check::non_manifold_facet: {
        const auto e = edge(simplices, o.simplex, o.facet);
        k.overlap_edges.push_back(e);
        for (std::size_t s : on_edge[e]) k.overlapping[s] = 1;
        break;
      }
      case Check::cover_degree:
      case Check::duplicate_simplex:
        if (o.simplex >= 0) k.overlapping[static_cast<std::size_t>(o.simplex)] = 1;
        break;
      case Check::orientation:
        k.inverted[static_cast<std::size_t>(o.simplex)] = 1;
        break;
      case Check::missing_vertex:
        k.missing[static_cast<std::size_t>(o.point)] = 1;
        break;
      default:
        break;
    }
  }
  for (auto* list : {&k.non_delaunay_edges, &k.overlap_edges}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  for (Check c : {Check::index_range, Check::duplicate_reference, Check::boundary_manifold,
                  Check::boundary_convex, Check::disconnected}) {
    const CheckResult& r = rep[c];
    if (r.count == 0) continue;
    std::string line = std::string(check_name(c)) + ": " + std::to_string(r.count) + " (first:";
    if (r.simplex >= 0) line += " simplex " + std::to_string(r.simplex);
    if (r.point >= 0) line += " point " + std::to_string(r.point);
    k.other.push_back(line + ")");
  }
  k.other.push_back(rep.delaunay() ? "exact validator: valid Delaunay"
                    : rep.valid()  ? "exact validator: valid, not Delaunay"
                                   : "exact validator: invalid");
  return k;
}

}  // namespace

int cmd_draw(int argc, char** argv) {
  for (int i = 2; i < argc; ++i)
    if (std::string_view(argv[i]) == "--help") {
      std::cout << kDrawUsage;
      return 0;
    }
  PointSet points;
  std::vector<std::uint32_t> simplices;
  SvgMeshOptions options;
  std::string out_path;
  try {
    const Args a = parse_args(argc, argv, 2, {"-o"}, {"--circles", "--labels"});
    if (a.positional.size() != 2 || !a.get("-o"))
      throw UsageError("usage: dlab draw POINTS SIMPLICES -o FILE.svg [--circles] [--labels]");
    if (a.positional[0] == "-" && a.positional[1] == "-")
      throw UsageError("POINTS and SIMPLICES cannot both be standard input");
    out_path = *a.get("-o");
    options.circles = a.has("--circles");
    options.labels = a.has("--labels");
    points = io::read_points(a.positional[0]);
    if (points.dimension != 2)
      throw io::InputError(io::display_name(a.positional[0]) +
                           ": 3D points: dlab draw draws 2D meshes; 3D pictures are .vtu files for "
                           "ParaView, which dlab draw does not write");
    simplices = io::read_simplices(a.positional[1], points.dimension, points.size());
  } catch (const UsageError& e) {
    std::cerr << "dlab draw: " << e.what() << "\n";
    return 2;
  } catch (const io::InputError& e) {
    std::cerr << "dlab draw: " << e.what() << "\n";
    return 2;
  }
  std::vector<Offence> offences;
  const ValidationReport rep = validate(points, simplices, offences);
  const MeshMarks marks = marks_of(rep, offences, simplices, points.size());
  std::ostringstream svg;
  write_svg_mesh(svg, points.p2, simplices, marks, options);
  if (out_path == "-") {
    std::cout << svg.str() << std::flush;
  } else {
    std::ofstream f(out_path, std::ios::binary);
    if (!(f << svg.str()) || !f.flush()) {
      std::cerr << "dlab draw: cannot write '" << out_path << "'\n";
      return 2;
    }
  }
  return rep.delaunay() ? 0 : 1;
}

}  // namespace dlab::cli
