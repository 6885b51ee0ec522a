// What tests read from a run: triangulations as canonical simplex lists (so that
// two can be compared with ==) and named counters.
//
// Canonical form of a simplex: its indices sorted ascending, then the last two
// swapped when the sorting permutation was odd, so that orientation is kept
// (an even permutation of a positively oriented simplex is positive). In 2D
// this is the rotation that puts the smallest index first. The list is sorted.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "variants/run.hpp"

namespace dlab::test {

template <int D>
using Simplex = std::array<std::uint32_t, D + 1>;

template <int D>
Simplex<D> canonical(Simplex<D> s) {
  bool odd = false;
  for (int a = 1; a <= D; ++a)
    for (int b = a; b > 0 && s[b - 1] > s[b]; --b) {
      std::swap(s[b - 1], s[b]);
      odd = !odd;
    }
  if (odd) std::swap(s[D - 1], s[D]);
  return s;
}

// Flat index list (d+1 per simplex) -> sorted list of canonical simplices.
template <int D>
std::vector<Simplex<D>> canonical_simplices(std::span<const std::uint32_t> flat) {
  std::vector<Simplex<D>> out(flat.size() / (D + 1));
  for (std::size_t s = 0; s < out.size(); ++s) {
    for (int j = 0; j <= D; ++j) out[s][j] = flat[s * (D + 1) + j];
    out[s] = canonical<D>(out[s]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The named counter's value; a missing name throws (the test then fails, naming it).
inline std::uint64_t counter(const Counters& c, const std::string& name) {
  for (const auto& [k, v] : c)
    if (k == name) return v;
  throw std::out_of_range("no counter " + name);
}

}  // namespace dlab::test
