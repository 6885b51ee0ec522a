// RunOptions::canonical: a run's simplices in canonical order
// (algorithms/canonical_simplices.hpp), sorted on `threads` oneTBB threads
// when threads > 1 (the parallel Bowyer–Watson's output: one more step that
// must not stay serial); the order itself never depends on threads.
#pragma once
#include <cstdint>
#include <vector>

namespace dlab {

void sort_canonically(std::vector<std::uint32_t>& flat, int dimension, unsigned threads);

}  // namespace dlab
