#include "variants/canonical_order.hpp"

#include <algorithm>

#include <tbb/global_control.h>
#include <tbb/parallel_sort.h>

#include "algorithms/canonical_simplices.hpp"

namespace dlab {
namespace {

template <int D>
void sort_dimension(std::vector<std::uint32_t>& flat, unsigned threads) {
  constexpr int V = D + 1;
  std::vector<IndexSimplex<D>> s(flat.size() / V);
  for (std::size_t i = 0; i < s.size(); ++i) {
    std::copy_n(flat.begin() + i * V, V, s[i].begin());
    s[i] = canonical_simplex<D>(s[i]);
  }
  if (threads > 1) {
    tbb::global_control allowed(tbb::global_control::max_allowed_parallelism, threads);
    tbb::parallel_sort(s.begin(), s.end());
  } else {
    std::sort(s.begin(), s.end());
  }
  for (std::size_t i = 0; i < s.size(); ++i) std::copy_n(s[i].begin(), V, flat.begin() + i * V);
}

}  // namespace

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads) {
  if (dimension == 2)
    sort_dimension<2>(flat, threads);
  else
    sort_dimension<3>(flat, threads);
}

}  // namespace dlab
