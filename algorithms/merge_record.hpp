// Which vertex each point became (TriangulationResult::merged_into) in an
// incremental run that processes the initial simplex's vertices first, then
// every other point in index order until it ends or fails.  During the run
// only the merged points (duplicates) are listed; the array of n words is
// built when asked for, after the mesh is gone, so that it is not part of the
// peak memory (4 bytes per point; papers/triangulation_costs.md, session 19).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "algorithms/triangulation_result.hpp"

namespace dlab {

template <int D>
class MergeRecord {
 public:
  // A run over n points; `initial`: the vertices processed first.
  void start(std::size_t n, const std::array<std::uint32_t, D + 1>& initial) {
    n_ = n;
    end_ = n;
    initial_ = initial;
    merges_.clear();
  }
  // A run over n points with no vertex processed first.
  void start(std::size_t n) {
    std::array<std::uint32_t, D + 1> none;
    none.fill(kNotProcessed);
    start(n, none);
  }
  bool is_initial(std::uint32_t i) const { return std::find(initial_.begin(), initial_.end(), i) != initial_.end(); }
  void merge(std::uint32_t i, std::uint32_t vertex) { merges_.push_back({i, vertex}); }
  // The run ended before point i: it and the later ones were not processed.
  void stop_before(std::uint32_t i) { end_ = i; }

  std::vector<std::uint32_t> merged_into() const {
    std::vector<std::uint32_t> m(n_, kNotProcessed);
    for (std::size_t i = 0; i < end_; ++i) m[i] = static_cast<std::uint32_t>(i);
    for (std::uint32_t i : initial_)
      if (i != kNotProcessed) m[i] = i;
    for (const auto& [i, vertex] : merges_) m[i] = vertex;
    return m;
  }

 private:
  std::size_t n_ = 0, end_ = 0;
  std::array<std::uint32_t, D + 1> initial_{};
  std::vector<std::array<std::uint32_t, 2>> merges_;  // (point, vertex)
};

}  // namespace dlab
