// RunOptions::canonical: a run's simplices in canonical order
// (algorithms/canonical_simplices.hpp: each simplex starting at its smallest
// index, the list sorted), by a radix sort on that index, on `threads` oneTBB
// threads when threads > 1 (the parallel Bowyer–Watson's output).  The order
// never depends on threads.
#pragma once
#include <cstdint>
#include <vector>

namespace dlab {

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads);

// Every index i of flat becomes to[i] (a run's insertion ids become input
// ids), on `threads` oneTBB threads when threads > 1.
void map_indices(std::vector<std::uint32_t>& flat, const std::vector<std::uint32_t>& to, unsigned threads);

}  // namespace dlab
