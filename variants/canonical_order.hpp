// RunOptions::canonical: a run's simplices in canonical order
// (algorithms/canonical_simplices.hpp: each simplex starting at its smallest
// index, the list sorted), by a counting sort on that index; the per-index
// sorts run on `threads` oneTBB threads when threads > 1 (the parallel
// Bowyer–Watson's output).  The order never depends on threads.
#pragma once
#include <cstdint>
#include <vector>

namespace dlab {

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads);

}  // namespace dlab
