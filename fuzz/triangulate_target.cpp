// See triangulate_target.hpp.
#include "fuzz/triangulate_target.hpp"

#include <cstdio>
#include <cstdlib>
#include <span>

#include "fuzz/all_pairs_check.hpp"
#include "fuzz/byte_decoder.hpp"

namespace dlab::fuzz {
namespace {

void print_points(std::FILE* f, const PointSet& ps) {
  if (ps.dimension == 2)
    for (const auto& p : ps.p2) std::fprintf(f, "%a %a\n", p[0], p[1]);
  else
    for (const auto& p : ps.p3) std::fprintf(f, "%a %a %a\n", p[0], p[1], p[2]);
}

}  // namespace

int fuzz_triangulate(const std::uint8_t* data, std::size_t size, int dim, const char* target) {
  static const bool print = [] {
    const char* v = std::getenv("DLAB_FUZZ_PRINT_POINTS");
    return v && *v && *v != '0';
  }();
  const DecodedInput in = decode_points(std::span<const std::uint8_t>(data, size), dim);
  if (print) {
    std::printf("# %s: %zu points, --order %s --seed %llu\n", target, in.points.size(), in.order.c_str(),
                static_cast<unsigned long long>(in.seed));
    print_points(stdout, in.points);
    std::fflush(stdout);
  }
  if (const auto f = check_all_pairs(in.points, in.order, in.seed)) {
    std::fprintf(stderr, "%s: an exact pair broke its promise\n  pair: %s\n  %s\n  points (%zu):\n", target,
                 f->pair.c_str(), f->what.c_str(), in.points.size());
    print_points(stderr, in.points);
    std::fflush(stderr);
    std::abort();
  }
  return 0;
}

}  // namespace dlab::fuzz
