// Triangulations as canonical simplex lists, so that two can be compared with ==
// (the fuzzer's `differs` check, the tests).
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
#include <utility>
#include <vector>

namespace dlab {

template <int D>
using IndexSimplex = std::array<std::uint32_t, D + 1>;

template <int D>
IndexSimplex<D> canonical_simplex(IndexSimplex<D> s) {
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
std::vector<IndexSimplex<D>> canonical_simplices(std::span<const std::uint32_t> flat) {
  std::vector<IndexSimplex<D>> out(flat.size() / (D + 1));
  for (std::size_t s = 0; s < out.size(); ++s) {
    for (int j = 0; j <= D; ++j) out[s][j] = flat[s * (D + 1) + j];
    out[s] = canonical_simplex<D>(out[s]);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace dlab
