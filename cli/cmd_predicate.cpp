// `dlab predicate NAME K COORD...`: one predicate, one kernel, prints -1, 0 or 1
// (Shewchuk's sign conventions, predicates/kernel.hpp). Coordinates are read as
// in INPUT (decimal or C99 hexadecimal floats; NaN / infinity rejected).
#include <array>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.hpp"
#include "cli/kernels.hpp"
#include "cli/numbers.hpp"

namespace dlab::cli {
namespace {

template <int D, int N>
int evaluate(const std::string& name, const std::string& kernel, const std::vector<double>& c) {
  std::vector<Point<D>> pts(N);
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < D; ++j) pts[i][j] = c[static_cast<std::size_t>(i * D + j)];
  return with_kernel<D>(kernel, std::span<const Point<D>>(pts), [&](const auto& k) {
    if constexpr (D == 2) {
      return to_int(name == "orient2d" ? k.orient2d(pts[0], pts[1], pts[2])
                                       : k.incircle(pts[0], pts[1], pts[2], pts[3]));
    } else {
      return to_int(name == "orient3d" ? k.orient3d(pts[0], pts[1], pts[2], pts[3])
                                       : k.insphere(pts[0], pts[1], pts[2], pts[3], pts[4]));
    }
  });
}

}  // namespace

int cmd_predicate(int argc, char** argv) {
  try {
    if (argc < 4)
      throw UsageError("usage: dlab predicate NAME K COORD...  (NAME: orient2d incircle orient3d insphere)");
    const std::string name = argv[2], kernel = argv[3];
    int dim = 0, npts = 0;
    if (name == "orient2d") dim = 2, npts = 3;
    else if (name == "incircle") dim = 2, npts = 4;
    else if (name == "orient3d") dim = 3, npts = 4;
    else if (name == "insphere") dim = 3, npts = 5;
    else
      throw UsageError("unknown predicate '" + name +
                       "' (known: orient2d, incircle, orient3d, insphere)");
    const int want = dim * npts, got = argc - 4;
    if (got != want)
      throw UsageError(name + " takes " + std::to_string(want) + " coordinates (" +
                       std::to_string(npts) + " points), found " + std::to_string(got));
    std::vector<double> c;
    for (int i = 4; i < argc; ++i) {
      const auto p = io::parse_double(argv[i]);
      if (p.status != io::ParseStatus::ok)
        throw UsageError("argument " + std::to_string(i - 3) + ": " + io::describe(p.status, argv[i]));
      c.push_back(p.value);
    }
    int s = 0;
    if (name == "orient2d") s = evaluate<2, 3>(name, kernel, c);
    else if (name == "incircle") s = evaluate<2, 4>(name, kernel, c);
    else if (name == "orient3d") s = evaluate<3, 4>(name, kernel, c);
    else s = evaluate<3, 5>(name, kernel, c);
    std::cout << s << "\n";
    return 0;
  } catch (const UsageError& e) {
    std::cerr << "dlab predicate: " << e.what() << "\n";
    return 2;
  }
}

}  // namespace dlab::cli
