#include "variants/canonical_order.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include "algorithms/canonical_simplices.hpp"
#include "algorithms/huge_pages.hpp"

namespace dlab {
namespace {

// Runs f(first, last) over [0, n), on `threads` oneTBB threads when > 1.
template <class F>
void for_ranges(std::size_t n, unsigned threads, F&& f) {
  if (threads <= 1) return f(std::size_t{0}, n);
  tbb::global_control allowed(tbb::global_control::max_allowed_parallelism, threads);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 14),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

// The canonical simplices (each starting at its smallest index), sorted: a
// counting sort on that smallest index (linear: indices are below the number
// of points), then each index's few simplices sorted among themselves.  One
// buffer of the output's size besides the input, as a comparison sort of
// canonical copies needs.
template <int D>
void sort_dimension(std::vector<std::uint32_t>& flat, unsigned threads) {
  constexpr int V = D + 1;
  using S = IndexSimplex<D>;
  const std::size_t m = flat.size() / V;
  auto at = [&](const std::vector<std::uint32_t>& v, std::size_t i) {
    S x;
    std::copy_n(v.begin() + i * V, V, x.begin());
    return x;
  };
  auto least = [&](std::size_t i) { return *std::min_element(flat.begin() + i * V, flat.begin() + (i + 1) * V); };
  std::uint32_t top = 0;
  for (std::size_t i = 0; i < m; ++i) top = std::max(top, least(i));
  // The large arrays in huge pages (algorithms/huge_pages.hpp).
  std::vector<std::size_t> start = huge_vector<std::size_t>(std::size_t(top) + 2);
  for (std::size_t i = 0; i < m; ++i) ++start[std::size_t(least(i)) + 1];
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<std::size_t> next;
  reserve_huge(next, start.size() - 1);
  next.assign(start.begin(), start.end() - 1);
  std::vector<std::uint32_t> out = huge_vector<std::uint32_t>(flat.size());
  for (std::size_t i = 0; i < m; ++i) {
    const S c = canonical_simplex<D>(at(flat, i));
    std::copy_n(c.begin(), V, out.begin() + next[c[0]]++ * V);
  }
  for_ranges(start.size() - 1, threads, [&](std::size_t first, std::size_t last) {
    std::vector<S> bucket;
    for (std::size_t v = first; v < last; ++v) {
      bucket.clear();
      for (std::size_t i = start[v]; i < start[v + 1]; ++i) bucket.push_back(at(out, i));
      std::sort(bucket.begin(), bucket.end());
      for (std::size_t k = 0; k < bucket.size(); ++k) std::copy_n(bucket[k].begin(), V, out.begin() + (start[v] + k) * V);
    }
  });
  flat.swap(out);
}

}  // namespace

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads) {
  if (dimension == 2)
    sort_dimension<2>(flat, threads);
  else
    sort_dimension<3>(flat, threads);
}

}  // namespace dlab
