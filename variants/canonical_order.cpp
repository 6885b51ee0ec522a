#include "variants/canonical_order.hpp"

#include <algorithm>
#include <bit>
#include <utility>

#include "algorithms/canonical_simplices.hpp"
#include "algorithms/huge_pages.hpp"
#include "variants/for_ranges.hpp"

namespace dlab {
namespace {

// Bits of the smallest index that the first pass sorts on: 2^12 bins, whose
// simplices (about 1 700 at 10^6 points in 3D) then fit a core's cache.
constexpr int kBinBits = 12;

// The canonical simplices (each starting at its smallest index), sorted.  A
// radix sort on that smallest index, most significant digit first, then each
// index's few simplices sorted among themselves:
//  1. each simplex made canonical in place;
//  2. counted by bin (the index's top kBinBits bits) in fixed chunks of the
//     input, and moved to a second buffer bin by bin, each chunk to its own
//     place in each bin: no two threads write one counter;
//  3. each bin, now contiguous and small, counting-sorted on the whole index
//     back into the first buffer, and each index's simplices sorted (a bin
//     whose indices are sparse is sorted whole instead).
// Every pass but the prefix sums runs on `threads`; the moves write a few
// thousand sequential streams instead of one random line per simplex, as a
// counting sort on the whole index would.  Nothing depends on threads: the
// chunks are fixed, and each writes places of its own.  One buffer of the
// output's size besides the input.
template <int D>
void sort_dimension(std::vector<std::uint32_t>& flat, unsigned threads) {
  constexpr int V = D + 1;
  using S = IndexSimplex<D>;
  const std::size_t m = flat.size() / V;
  if (m == 0) return;
  auto load = [](const std::uint32_t* p) {
    S x;
    std::copy_n(p, V, x.begin());
    return x;
  };
  const std::size_t chunk = std::max<std::size_t>(std::size_t{1} << 16, (m + 255) / 256);
  const std::size_t chunks = (m + chunk - 1) / chunk;
  auto for_chunks = [&](auto&& f) { dlab::for_chunks(m, chunk, threads, f); };

  std::vector<std::uint32_t> chunk_top(chunks, 0);
  for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      const S s = canonical_simplex<D>(load(&flat[i * V]));
      std::copy_n(s.begin(), V, &flat[i * V]);
      chunk_top[c] = std::max(chunk_top[c], s[0]);  // the largest smallest index
    }
  });
  const std::uint32_t top = *std::max_element(chunk_top.begin(), chunk_top.end());
  const int shift = std::max(0, static_cast<int>(std::bit_width(top)) - kBinBits);
  const std::size_t bins = (std::size_t(top) >> shift) + 1;

  // at[c * bins + b]: where chunk c's next simplex of bin b goes.
  std::vector<std::size_t> at(chunks * bins, 0), bin_start(bins + 1, 0);
  for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) ++at[c * bins + (flat[i * V] >> shift)];
  });
  std::size_t sum = 0;
  for (std::size_t b = 0; b < bins; ++b) {
    bin_start[b] = sum;
    for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(at[c * bins + b], sum);
  }
  bin_start[bins] = sum;
  // The large array in huge pages (algorithms/huge_pages.hpp).
  std::vector<std::uint32_t> by_bin = huge_vector<std::uint32_t>(flat.size());
  for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i)
      std::copy_n(&flat[i * V], V, &by_bin[at[c * bins + (flat[i * V] >> shift)]++ * V]);
  });

  for_ranges(bins, threads, [&](std::size_t first, std::size_t last) {
    std::vector<std::size_t> next;
    std::vector<S> run;
    // Simplices [lo, hi) of `from`, sorted, to the same places in flat.
    auto sort_into_flat = [&](const std::vector<std::uint32_t>& from, std::size_t lo, std::size_t hi) {
      run.clear();
      for (std::size_t i = lo; i < hi; ++i) run.push_back(load(&from[i * V]));
      std::sort(run.begin(), run.end());
      for (std::size_t k = 0; k < run.size(); ++k) std::copy_n(run[k].begin(), V, &flat[(lo + k) * V]);
    };
    for (std::size_t b = first; b < last; ++b) {
      const std::size_t lo = bin_start[b], hi = bin_start[b + 1];
      if ((hi - lo) * 16 < (std::size_t{1} << shift)) {  // sparse (indices far above their count)
        sort_into_flat(by_bin, lo, hi);
        continue;
      }
      const std::uint32_t base = static_cast<std::uint32_t>(b << shift);
      next.assign((std::size_t{1} << shift) + 1, 0);
      for (std::size_t i = lo; i < hi; ++i) ++next[by_bin[i * V] - base + 1];
      next[0] = lo;
      for (std::size_t v = 1; v < next.size(); ++v) next[v] += next[v - 1];
      for (std::size_t i = lo; i < hi; ++i) std::copy_n(&by_bin[i * V], V, &flat[next[by_bin[i * V] - base]++ * V]);
      for (std::size_t i = lo, j; i < hi; i = j) {  // each index's simplices
        for (j = i + 1; j < hi && flat[j * V] == flat[i * V];) ++j;
        sort_into_flat(flat, i, j);
      }
    }
  }, 16);  // bins of about 1 700 simplices: ranges of 16 bins
}

}  // namespace

void map_indices(std::vector<std::uint32_t>& flat, const std::vector<std::uint32_t>& to, unsigned threads) {
  for_ranges(flat.size(), threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) flat[i] = to[flat[i]];
  });
}

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads) {
  if (dimension == 2)
    sort_dimension<2>(flat, threads);
  else
    sort_dimension<3>(flat, threads);
}

}  // namespace dlab
