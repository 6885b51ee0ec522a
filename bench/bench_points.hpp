// The point sets of the triangulation benchmarks: uniform in the unit box, and
// the regular grid (maximally degenerate: cocircular / cospherical everywhere).
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include "variants/run.hpp"

namespace dlab::bench {

// splitmix64 (Steele, Lea, Flood 2014): same sequence on every machine.
inline double uniform01(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

inline PointSet make_points(const std::string& set, int dim, std::size_t n) {
  PointSet ps;
  ps.dimension = dim;
  std::uint64_t state = 42;
  if (set == "uniform") {
    for (std::size_t i = 0; i < n; ++i) {
      if (dim == 2) ps.p2.push_back({uniform01(state), uniform01(state)});
      else ps.p3.push_back({uniform01(state), uniform01(state), uniform01(state)});
    }
  } else if (set == "grid") {
    const auto side = std::size_t(std::llround(std::pow(double(n), 1.0 / dim)));
    for (std::size_t i = 0; i < side; ++i)
      for (std::size_t j = 0; j < side; ++j) {
        if (dim == 2) ps.p2.push_back({double(i), double(j)});
        else
          for (std::size_t k = 0; k < side; ++k) ps.p3.push_back({double(i), double(j), double(k)});
      }
  } else {
    throw std::invalid_argument("unknown point set " + set);
  }
  return ps;
}

}  // namespace dlab::bench
