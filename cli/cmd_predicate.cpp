// `dlab predicate NAME K COORD...`: one predicate, one kernel, prints -1, 0 or 1
// (Shewchuk's sign conventions, predicates/kernel.hpp). Coordinates are read as
// in INPUT (decimal or C99 hexadecimal floats; NaN / infinity rejected).
#include <array>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/numbers.hpp"

namespace dlab::cli {
namespace {

// The predicate of N points in D dimensions: orient2d (3), incircle (4),
// orient3d (4), insphere (5); no other point is ever indexed.
template <int D, int N>
int evaluate(const std::string& kernel, const std::vector<double>& c) {
  std::vector<Point<D>> pts(N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) pts[i][j] = c[static_cast<std::size_t>(i * D + j)];
  return with_kernel<D>(kernel, std::span<const Point<D>>(pts), [&](const auto& k) {
    if constexpr (D == 2 && N == 3)
      return to_int(k.orient2d(pts[0], pts[1], pts[2]));
    else if constexpr (D == 2 && N == 4)
      return to_int(k.incircle(pts[0], pts[1], pts[2], pts[3]));
    else if constexpr (D == 3 && N == 4)
      return to_int(k.orient3d(pts[0], pts[1], pts[2], pts[3]));
    else {
      static_assert(D == 3 && N == 5);
      return to_int(k.insphere(pts[0], pts[1], pts[2], pts[3], pts[4]));
    }
  });
}

}  // namespace

int cmd_predicate(int argc, char** argv) {
  std::string name, kernel;
  std::vector<std::string> coords;
  CommandLine cl("predicate", "usage: dlab predicate NAME K COORD...\n",
                 "Evaluates one predicate with one kernel and prints its sign: -1, 0 or 1 (Shewchuk's\n"
                 "conventions: orient2d > 0 iff a, b, c are counterclockwise; incircle > 0 iff d is inside\n"
                 "the circle through the counterclockwise a, b, c; orient3d > 0 iff d is below the plane of\n"
                 "a, b, c seen counterclockwise from above; insphere > 0 iff e is inside the sphere of the\n"
                 "positively oriented a, b, c, d). COORD: the points' coordinates in order, read as INPUT is\n"
                 "(decimal or C99 hexadecimal floats; NaN, infinity, overflow and underflow rejected);\n"
                 "negative numbers are coordinates, not options.\n",
                 "  dlab predicate orient2d adaptive 0 0 1 0 0 1          # 1\n"
                 "  dlab predicate incircle mp 0 0 1 0 0 1 1 1            # 0: cocircular\n"
                 "  dlab predicate orient2d float 0x1.0000000000001p-1 0.5 12 12 24 24\n"
                 "  dlab predicate insphere integer 0 0 0 1 0 0 0 1 0 0 0 -1 0.2 0.2 -0.2\n",
                 "Exit status: 0 a sign printed, 2 bad usage or coordinate.\n");
  CLI::App& app = cl.app();
  // After NAME everything is positional: coordinates such as "-inf" or "-.5" too.
  app.positionals_at_end(true);
  app.add_option("NAME", name, "orient2d (3 points), incircle (4) in 2D; orient3d (4), insphere (5) in 3D")
      ->required();
  app.add_option("K", kernel, "the kernel: adaptive, integer, mp (exact); float, epsilon (inexact)")
      ->required();
  app.add_option("COORD", coords, "x y (2D) or x y z (3D) of each point in turn");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  try {
    int dim = 0, npts = 0;
    if (name == "orient2d") dim = 2, npts = 3;
    else if (name == "incircle") dim = 2, npts = 4;
    else if (name == "orient3d") dim = 3, npts = 4;
    else if (name == "insphere") dim = 3, npts = 5;
    else
      throw UsageError("unknown predicate '" + name +
                       "' (known: orient2d, incircle, orient3d, insphere)");
    const std::size_t want = static_cast<std::size_t>(dim * npts);
    if (coords.size() != want)
      throw UsageError(name + " takes " + std::to_string(want) + " coordinates (" +
                       std::to_string(npts) + " points), found " + std::to_string(coords.size()));
    std::vector<double> c;
    for (std::size_t i = 0; i < coords.size(); ++i) {
      const auto p = io::parse_double(coords[i]);
      if (p.status != io::ParseStatus::ok)
        throw UsageError("argument " + std::to_string(i + 1) + ": " + io::describe(p.status, coords[i]));
      c.push_back(p.value);
    }
    int s = 0;
    if (name == "orient2d") s = evaluate<2, 3>(kernel, c);
    else if (name == "incircle") s = evaluate<2, 4>(kernel, c);
    else if (name == "orient3d") s = evaluate<3, 4>(kernel, c);
    else s = evaluate<3, 5>(kernel, c);
    std::cout << s << "\n";
    return 0;
  } catch (const UsageError& e) {
    return cl.usage_error(e.what());
  }
}

}  // namespace dlab::cli
