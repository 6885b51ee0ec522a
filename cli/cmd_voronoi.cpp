// `dlab voronoi POINTS [SIMPLICES] -o OUT.svg|OUT.vtu [--box ...] [--algo A]
// [--kernel K] [--policy P] [--order O] [--seed N]`: the Voronoi dual of the
// Delaunay triangulation of POINTS (triangulated here, or SIMPLICES checked by
// the exact validator), cells bounded by a box (voronoi/voronoi_cells.hpp),
// written as SVG (2D) or .vtu (cli/voronoi_output.hpp). Exit 0 written, 1 the
// triangulation failed (inexact kernels), 2 bad input or usage.
#include <algorithm>
#include <iostream>

#include "algorithms/validate.hpp"
#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"
#include "cli/outcome_report.hpp"
#include "cli/point_reader.hpp"
#include "cli/run_choices.hpp"
#include "cli/simplex_io.hpp"
#include "cli/voronoi_output.hpp"
#include "variants/outcome.hpp"

namespace dlab::cli {
namespace {

struct VoronoiOptions {
  std::string points, input_format, simplices, out, box;
  RunOptions run;
};

// The options, in one place (CLI11 through cli_app.hpp).
std::optional<int> parse_voronoi_options(int argc, char** argv, VoronoiOptions& o, CommandLine& cl) {
  CLI::App& app = cl.app();
  app.add_option("POINTS", o.points, "the sites (as dlab triangulate reads them; '-': standard input)")
      ->required();
  app.add_option("SIMPLICES", o.simplices,
                 "their Delaunay triangulation (d+1 indices per line, positively oriented),\n"
                 "checked by the exact validator; absent: POINTS is triangulated here");
  app.add_option("-o", o.out, "OUT.svg (2D) or OUT.vtu (2D or 3D)")->required()->type_name("FILE");
  add_input_format(app, o.input_format, "POINTS");
  app.add_option("--box", o.box,
                 "xmin,ymin,xmax,ymax (2D) or x0,y0,z0,x1,y1,z1 (3D). Default: the sites'\n"
                 "bounding box enlarged by 10 % of its extent on each side (an extent of 0\n"
                 "takes the largest one's, or 1)")
      ->type_name("B");
  app.add_option("--algo", o.run.algorithm, "bowyer-watson (default), lawson, tanemura, george")->type_name("A");
  app.add_option("--kernel", o.run.kernel, "adaptive (default), integer, mp; float, epsilon (inexact: exit 1 on failure)")->type_name("K");
  add_choice(app, "--policy", o.run.policy, kPolicies, "sos or strict");
  add_choice(app, "--order", o.run.order, kOrders, "insertion order");
  add_unsigned(app, "--seed", o.run.seed, UINT64_MAX, "seed of the order");
  auto rc = cl.parse(argc, argv, 2);
  // As dlab triangulate: sos for the exact kernels, the inexact baselines run plain.
  if (!rc && app.count("--policy") == 0 && !kernel_is_exact(o.run.kernel)) o.run.policy = "strict";
  return rc;
}

// --box as numbers, or the default box around the sites.
template <int D>
void box_of(const std::string& text, const std::vector<Point<D>>& pts, Point<D>& lo, Point<D>& hi) {
  if (!text.empty()) {
    std::vector<double> v;
    std::size_t pos = 0;
    while (pos <= text.size()) {
      std::size_t end = std::min(text.find(',', pos), text.size());
      const io::ParsedDouble p = io::parse_double(text.substr(pos, end - pos));
      if (p.status != io::ParseStatus::ok) throw UsageError("--box: " + io::describe(p.status, text.substr(pos, end - pos)));
      v.push_back(p.value);
      pos = end + 1;
    }
    if (v.size() != 2 * D)
      throw UsageError("--box needs " + std::to_string(2 * D) + " numbers for " + std::to_string(D) +
                       "D points, not " + std::to_string(v.size()));
    for (int k = 0; k < D; ++k) {
      lo[k] = v[k];
      hi[k] = v[D + k];
      if (!(lo[k] < hi[k])) throw UsageError("--box: the minimum must be below the maximum on every axis");
    }
    return;
  }
  lo = hi = pts.empty() ? Point<D>{} : pts[0];
  for (const auto& p : pts)
    for (int k = 0; k < D; ++k) lo[k] = std::min(lo[k], p[k]), hi[k] = std::max(hi[k], p[k]);
  double largest = 0;
  for (int k = 0; k < D; ++k) largest = std::max(largest, hi[k] - lo[k]);
  if (largest == 0) largest = 1;
  for (int k = 0; k < D; ++k) {
    const double e = hi[k] - lo[k] > 0 ? hi[k] - lo[k] : largest;
    lo[k] -= e / 10;
    hi[k] += e / 10;
  }
}

bool ends_with(const std::string& s, const char* suffix) {
  const std::string t = suffix;
  return s.size() >= t.size() && s.compare(s.size() - t.size(), t.size(), t) == 0;
}

// The line of SIMPLICES holding simplex k (comments and blank lines skipped,
// as io::parse_simplices does).
std::size_t line_of_simplex(const std::string& text, std::int64_t k) {
  std::size_t pos = 0, line = 0;
  std::int64_t seen = -1;
  while (pos < text.size()) {
    std::size_t end = std::min(text.find('\n', pos), text.size());
    std::string l = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    l = l.substr(0, l.find('#'));
    if (l.find_first_not_of(" \t\r,") != std::string::npos && ++seen == k) return line;
  }
  return line;
}

template <int D>
int write_diagram(const VoronoiOptions& o, const PointSet& points, const std::vector<std::uint32_t>& simplices,
                  CommandLine& cl) {
  const auto& pts = points_of<D>(points);
  Point<D> lo, hi;
  try {
    box_of<D>(o.box, pts, lo, hi);
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
  const voronoi::Diagram<D> d = voronoi::voronoi_cells(pts, simplices, lo, hi);
  const bool svg = ends_with(o.out, ".svg");
  try {
    if constexpr (D == 2)
      io::write_text_file(o.out, svg ? voronoi_svg(d, pts, lo, hi) : voronoi_vtu(d));
    else
      io::write_text_file(o.out, voronoi_vtu(d));
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }
  return 0;
}

}  // namespace

int cmd_voronoi(int argc, char** argv) {
  VoronoiOptions o;
  CommandLine cl("voronoi",
                 "usage: dlab voronoi POINTS [SIMPLICES] -o OUT.svg|OUT.vtu [--box B] [--algo A] [--kernel K]\n"
                 "                    [--policy sos|strict] [--order O] [--seed N]\n",
                 "Writes the Voronoi diagram of POINTS, the dual of their Delaunay triangulation, every cell\n"
                 "bounded by a box. Vertices are circumcentres computed from exact determinants (GMP) and\n"
                 "rounded once to the nearest double. An interior site's cell is the cycle (3D: one face\n"
                 "per Delaunay edge) of the centres around it; a hull site's cell is unbounded: the box cut\n"
                 "by the bisectors of its Delaunay neighbours, in floating point, flagged clipped (as is an\n"
                 "interior cell cut by the box). Cocircular / cospherical sites give repeated centres\n"
                 "(zero-length Voronoi edges under the symbolic perturbation): equal centres are one\n"
                 "vertex and consecutive equal vertices are merged, so every cell is a valid polygon or\n"
                 "polyhedron. A later duplicate of a point, and a site whose cell misses --box, get no cell.\n"
                 "OUT.svg (2D): cells outlined (clipped ones shaded), sites dotted. OUT.vtu: VTK_POLYGON\n"
                 "(2D) or VTK_POLYHEDRON (3D) cells, one per site, cell data site and clipped; point data\n"
                 "simplex (the Delaunay simplex whose circumcentre the point is, -1 for a cut's vertex).\n",
                 "  dlab gen uniform --n 50 --seed 1 > p.txt && dlab voronoi p.txt -o cells.svg\n"
                 "  dlab gen uniform --dim 3 --n 200 > q.txt && dlab triangulate q.txt -o q.tet\n"
                 "  dlab voronoi q.txt q.tet -o cells.vtu --box 0,0,0,1,1,1\n",
                 "Exit status: 0 written, 1 the triangulation failed (inexact kernels), 2 bad input\n"
                 "(SIMPLICES that are not a Delaunay triangulation: FILE:LINE and the reason) or usage.\n");
  if (auto rc = parse_voronoi_options(argc, argv, o, cl)) return *rc;
  PointSet points;
  std::vector<std::uint32_t> simplices;
  try {
    const bool vtu = ends_with(o.out, ".vtu"), svg = ends_with(o.out, ".svg");
    if (!vtu && !svg) throw UsageError("-o must end in .svg or .vtu, not '" + o.out + "'");
    if (o.points == "-" && o.simplices == "-") throw UsageError("POINTS and SIMPLICES cannot both be standard input");
    points = io::read_points(o.points, o.input_format);
    if (points.dimension == 3 && svg)
      throw io::InputError(io::display_name(o.points) + ": 3D points: the diagram is written as -o OUT.vtu");
    if (!o.simplices.empty()) {
      const std::string text = io::read_file(o.simplices);
      const std::string name = io::display_name(o.simplices);
      simplices = io::parse_simplices(text, name, points.dimension, points.size());
      const ValidationReport rep = validate(points, simplices);
      if (!rep.delaunay()) {
        for (int c = 0; c < kCheckCount; ++c) {
          const CheckResult& r = rep.checks[c];
          if (r.count == 0) continue;
          const std::string what = std::string(check_name(static_cast<Check>(c)));
          if (r.simplex >= 0)
            throw io::InputError(name + ":" + std::to_string(line_of_simplex(text, r.simplex)) +
                                 ": not a Delaunay triangulation: " + what);
          throw io::InputError(name + ": not a Delaunay triangulation: " + what +
                               (r.point >= 0 ? " (point " + std::to_string(r.point) + ")" : ""));
        }
        throw io::InputError(name + ": not a Delaunay triangulation");
      }
    } else {
      check_run_choices(o.run);
      const RunResult res = run(points, o.run);
      const Outcome outcome = classify(points, res, pair_is_exact(o.run), Validate::unless_exact);
      if (outcome.kind != OutcomeClass::ok && outcome.kind != OutcomeClass::lower_dimensional) {
        print_outcome("voronoi", outcome, describe_pair(o.run));
        return 1;
      }
      points = res.points;  // snapped by the integer kernel
      simplices = res.simplices;
    }
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }
  return points.dimension == 2 ? write_diagram<2>(o, points, simplices, cl)
                               : write_diagram<3>(o, points, simplices, cl);
}

}  // namespace dlab::cli
