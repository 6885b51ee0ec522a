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

// A sorting network (3 comparators for 3 keys, 5 for 4: Knuth, TAOCP vol. 3,
// 5.3.4), each comparator without a branch, counting its exchanges: their
// parity is the sorting permutation's (the indices are distinct).  With the
// insertion sort's data-dependent branches this was 25 ns a tetrahedron, the
// largest pass of the canonical output order (papers/triangulation_costs.md,
// session 45).
template <int D>
IndexSimplex<D> canonical_simplex(IndexSimplex<D> s) {
  static_assert(D == 2 || D == 3);
  std::uint32_t odd = 0;
  auto exchange = [&](int i, int j) {
    const std::uint32_t a = s[i], b = s[j], x = a > b;
    s[i] = x ? b : a;
    s[j] = x ? a : b;
    odd ^= x;
  };
  if constexpr (D == 2) {
    exchange(0, 1), exchange(1, 2), exchange(0, 1);
  } else {
    exchange(0, 1), exchange(2, 3), exchange(0, 2), exchange(1, 3), exchange(1, 2);
  }
  const std::uint32_t a = s[D - 1], b = s[D];
  s[D - 1] = odd ? b : a;
  s[D] = odd ? a : b;
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
