// Delta debugging's ddmin over a list of elements (the points of `dlab
// shrink`): A. Zeller and R. Hildebrandt, "Simplifying and isolating
// failure-inducing input", IEEE Transactions on Software Engineering 28(2),
// 2002, section 3 (the ddmin algorithm and its 1-minimality, Proposition 10).
//
// Given a failing list c (the caller checks that it fails), ddmin splits c into
// n parts (n = 2 at first) and tests
//   1. each part: the first that fails becomes c, with n = 2;
//   2. each complement (c without one part): the first that fails becomes c,
//      with n = max(n - 1, 2) (at n = 2 the complements are the parts: skipped);
//   3. else, while n < |c|, n = min(2n, |c|) (finer parts);
// and stops when n = |c| and no part or complement fails. The result then
// fails and is 1-minimal: removing any one element makes it pass (each of those
// complements was tested at n = |c|). The empty list is assumed to pass and is
// never tested.
//
// Termination: at most |c| reductions (each shrinks c), and between two of
// them at most log2 |c| + 1 refinements (each doubles n, up to |c|), whatever
// the test answers; a test that answers "passes" once the caller's budget is spent
// (fuzz/shrink.hpp) therefore ends it early, with a failing (not necessarily
// 1-minimal) list.
#pragma once
#include <cstddef>
#include <functional>
#include <vector>

namespace dlab::fuzz {

// fails(subset): true if the subset (ascending indices into 0..count-1) fails.
using SubsetTest = std::function<bool(const std::vector<std::size_t>& subset)>;

// The indices, ascending, of a failing subset of 0..count-1 found by ddmin.
std::vector<std::size_t> ddmin(std::size_t count, const SubsetTest& fails);

}  // namespace dlab::fuzz
