// What tests read from a run: triangulations as canonical simplex lists (so that
// two can be compared with ==; the form is algorithms/canonical_simplices.hpp's)
// and named counters.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/canonical_simplices.hpp"
#include "variants/run.hpp"

namespace dlab::test {

template <int D>
using Simplex = IndexSimplex<D>;

template <int D>
Simplex<D> canonical(Simplex<D> s) {
  return canonical_simplex<D>(s);
}

using dlab::canonical_simplices;

// The named counter's value; a missing name throws (the test then fails, naming it).
inline std::uint64_t counter(const Counters& c, const std::string& name) {
  for (const auto& [k, v] : c)
    if (k == name) return v;
  throw std::out_of_range("no counter " + name);
}

}  // namespace dlab::test
