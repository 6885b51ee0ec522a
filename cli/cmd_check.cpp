// `dlab check INPUT SIMPLICES [--orientation positive|any]`: the exact
// validator (algorithms/validate.hpp) on a triangulation given as files.
// Prints the verdict and, for each failed check, its count and first offender.
// With --orientation any, each simplex may be given in either orientation: the
// negative ones are reoriented exactly first (orient_positively), and a simplex
// of zero volume is still an orientation failure. Exit 0 iff valid Delaunay, 1
// if not, 2 on bad input or usage.
#include <iostream>

#include "algorithms/validate.hpp"
#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"

namespace dlab::cli {

int cmd_check(int argc, char** argv) {
  std::string input, input_format, simplices_path, orientation = "positive";
  CommandLine cl("check", "usage: dlab check INPUT SIMPLICES [--orientation positive|any]\n",
                 "Checks exactly that SIMPLICES is a triangulation of INPUT (every simplex positively\n"
                 "oriented, no overlap, the hull covered, every distinct point a vertex) and that it is\n"
                 "Delaunay (no point inside a simplex's circumsphere). Prints the verdict and, for each\n"
                 "failed check, its count and its first offender.\n",
                 "  dlab gen uniform --n 100 > p.txt && dlab triangulate p.txt -o t.txt\n"
                 "  dlab check p.txt t.txt\n"
                 "  dlab check p.txt scipy_simplices.txt --orientation any\n",
                 "Exit status: 0 valid Delaunay, 1 not (invalid or not Delaunay), 2 bad input or usage.\n");
  CLI::App& app = cl.app();
  app.add_option("INPUT", input, "the points (as dlab triangulate reads them; '-': standard input)")
      ->required();
  app.add_option("SIMPLICES", simplices_path,
                 "the triangulation: d+1 zero-based indices into INPUT per line ('-': standard input)")
      ->required();
  add_input_format(app, input_format, "INPUT");
  add_choice(app, "--orientation", orientation, {"positive", "any"},
             "any: simplices may also be given negatively oriented (scipy's are mixed); they are\n"
             "reoriented exactly first, and a flat simplex still fails");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  const bool any_orientation = orientation == "any";
  PointSet points;
  std::vector<std::uint32_t> simplices;
  try {
    if (input == "-" && simplices_path == "-")
      throw UsageError("INPUT and SIMPLICES cannot both be standard input");
    points = io::read_points(input, input_format);
    simplices = io::read_simplices(simplices_path, points.dimension, points.size());
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  } catch (const io::InputError& e) {
    return cl.usage_error(e.what());
  }
  const std::size_t reoriented = any_orientation ? orient_positively(points, simplices) : 0;
  const ValidationReport rep = validate(points, simplices);
  std::cout << points.size() << " points (" << rep.distinct_points << " distinct), "
            << simplices.size() / static_cast<std::size_t>(points.dimension + 1) << " simplices, "
            << "dimension " << points.dimension << "\n";
  if (any_orientation)
    std::cout << reoriented << " simplices given negatively oriented (checked with their first two "
              << "vertices swapped)\n";
  const std::string summary = rep.summary();
  std::cout << summary << (summary.empty() || summary.back() != '\n' ? "\n" : "");
  return rep.delaunay() ? 0 : 1;
}

}  // namespace dlab::cli
