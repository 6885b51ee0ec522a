// `dlab check INPUT SIMPLICES [--orientation positive|any]`: the exact
// validator (algorithms/validate.hpp) on a triangulation given as files.
// Prints the verdict and, for each failed check, its count and first offender.
// With --orientation any, each simplex may be given in either orientation: the
// negative ones are reoriented exactly first (orient_positively), and a simplex
// of zero volume is still an orientation failure. Exit 0 iff valid Delaunay, 1
// if not, 2 on bad input or usage.
#include <iostream>

#include "algorithms/validate.hpp"
#include "cli/args.hpp"
#include "cli/commands.hpp"
#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"

namespace dlab::cli {

int cmd_check(int argc, char** argv) {
  PointSet points;
  std::vector<std::uint32_t> simplices;
  bool any_orientation = false;
  try {
    const Args a = parse_args(argc, argv, 2, {"--orientation"}, {});
    if (a.positional.size() != 2)
      throw UsageError("usage: dlab check INPUT SIMPLICES [--orientation positive|any]");
    const std::string orientation = a.get("--orientation").value_or("positive");
    if (orientation != "positive" && orientation != "any")
      throw UsageError("--orientation must be positive or any, not '" + orientation + "'");
    any_orientation = orientation == "any";
    if (a.positional[0] == "-" && a.positional[1] == "-")
      throw UsageError("INPUT and SIMPLICES cannot both be standard input");
    points = io::read_points(a.positional[0]);
    simplices = io::read_simplices(a.positional[1], points.dimension, points.size());
  } catch (const UsageError& e) {
    std::cerr << "dlab check: " << e.what() << "\n";
    return 2;
  } catch (const io::InputError& e) {
    std::cerr << "dlab check: " << e.what() << "\n";
    return 2;
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
