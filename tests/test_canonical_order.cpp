// The canonical order of a run's simplices (variants/canonical_order.cpp: a
// radix sort on each simplex's smallest index, in bins, on T threads) against
// an independent one: every simplex through canonical_simplex, then std::sort
// of the whole list (algorithms/canonical_simplices.hpp).  The lists are not
// triangulations, only index lists with the shapes that reach each path of
// the sort: several chunks of the input (2^16 simplices each), index ranges
// whose width crosses the bins' 12 bits, sparse bins, many simplices sharing
// their smallest index, and duplicates.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <vector>

#include "algorithms/canonical_simplices.hpp"
#include "variants/canonical_order.hpp"

using namespace dlab;

namespace {

// Simplices with distinct indices drawn from [0, top] (a simplex with a
// repeated index would have no canonical orientation to speak of).
template <int D>
std::vector<std::uint32_t> random_simplices(std::mt19937_64& rng, std::size_t m, std::uint32_t top) {
  std::uniform_int_distribution<std::uint32_t> u(0, top);
  std::vector<std::uint32_t> flat;
  for (std::size_t s = 0; s < m; ++s) {
    IndexSimplex<D> x;
    for (int j = 0; j <= D; ++j) {
      do x[j] = u(rng);
      while (std::find(x.begin(), x.begin() + j, x[j]) != x.begin() + j);
    }
    flat.insert(flat.end(), x.begin(), x.end());
  }
  return flat;
}

template <int D>
std::vector<std::uint32_t> independent_order(const std::vector<std::uint32_t>& flat) {
  std::vector<std::uint32_t> out;
  for (const IndexSimplex<D>& s : canonical_simplices<D>(flat)) out.insert(out.end(), s.begin(), s.end());
  return out;
}

template <int D>
void check_every_thread_count(const std::vector<std::uint32_t>& flat) {
  const std::vector<std::uint32_t> expected = independent_order<D>(flat);
  for (unsigned threads : {0u, 1u, 2u, 3u, 8u}) {
    std::vector<std::uint32_t> sorted = flat;
    sort_canonically(sorted, D, threads);
    INFO(D << "D, " << flat.size() / (D + 1) << " simplices, " << threads << " threads");
    const bool same = sorted == expected;  // (not printed: up to 600 000 indices)
    CHECK(same);
  }
}

}  // namespace

// Would catch: a chunk's or a bin's place computed wrong (simplices lost,
// doubled or out of order), a simplex not made canonical (orientation lost),
// ties on the smallest index left unsorted or cut into pieces.
TEST_CASE("canonical order: the radix sort equals an independent sort", "[canonical_order]") {
  std::mt19937_64 rng(20261128);
  for (std::uint32_t top : {7u, 4095u, 4096u, 100000u, (1u << 20) + 3u, 0xfffffffeu}) {
    check_every_thread_count<2>(random_simplices<2>(rng, 3000, top));
    check_every_thread_count<3>(random_simplices<3>(rng, 3000, top));
  }
  // More than one chunk, dense and sparse.
  check_every_thread_count<3>(random_simplices<3>(rng, 150000, 30000));
  check_every_thread_count<2>(random_simplices<2>(rng, 140000, 1u << 26));
}

TEST_CASE("canonical order: duplicates, one shared smallest index, empty", "[canonical_order]") {
  std::mt19937_64 rng(7);
  std::vector<std::uint32_t> flat = random_simplices<3>(rng, 2000, 500);
  const std::vector<std::uint32_t> copy = flat;
  flat.insert(flat.end(), copy.begin(), copy.end());  // every simplex twice
  check_every_thread_count<3>(flat);
  // A fan: 5 000 triangles around index 0, the other two indices descending.
  std::vector<std::uint32_t> fan;
  for (std::uint32_t i = 5000; i > 0; --i) fan.insert(fan.end(), {i + 1, 0, i + 7000});
  check_every_thread_count<2>(fan);
  check_every_thread_count<2>({});
  check_every_thread_count<3>({4, 2, 9, 1});
}

// canonical_simplex against its definition, on every order of D + 1 distinct
// indices (small, and at the top of the range): the result is the input's
// indices, an even permutation of them (the orientation kept; parity counted
// here by inversions, not by the network's exchanges), ascending but for the
// last two.  Would catch: a comparator of the network missing or misplaced
// (some order unsorted), an exchange not counted (half the orders flipped).
template <int D>
void check_canonical_simplex(IndexSimplex<D> values) {
  std::sort(values.begin(), values.end());
  auto inversions = [](const IndexSimplex<D>& s) {
    int n = 0;
    for (int i = 0; i <= D; ++i)
      for (int j = i + 1; j <= D; ++j) n += s[i] > s[j];
    return n;
  };
  IndexSimplex<D> in = values;
  do {
    const IndexSimplex<D> out = canonical_simplex<D>(in);
    IndexSimplex<D> sorted_out = out;
    std::sort(sorted_out.begin(), sorted_out.end());
    INFO(D << "D input " << in[0] << " " << in[1] << " " << in[2]);
    CHECK(sorted_out == values);
    // in -> out is even iff the two inversion counts have the same parity.
    CHECK(inversions(in) % 2 == inversions(out) % 2);
    for (int i = 0; i + 1 < D; ++i) CHECK(out[i] < out[i + 1]);
    CHECK(out[D - 2] < out[D]);
  } while (std::next_permutation(in.begin(), in.end()));
}

TEST_CASE("canonical order: each simplex sorted, its orientation kept", "[canonical_order]") {
  check_canonical_simplex<2>({0, 1, 2});
  check_canonical_simplex<2>({5, 0xfffffffeu, 0xffffffffu});
  check_canonical_simplex<3>({0, 1, 2, 3});
  check_canonical_simplex<3>({7, 1u << 31, 0xfffffffeu, 0xffffffffu});
}
