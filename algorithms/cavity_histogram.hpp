// How many insertions had a cavity of each size: power-of-two buckets of the
// number of simplices the insertion removed (1, 2-3, 4-7, ..., 64 and more),
// so that a study can plot the distribution and not only its mean and maximum.
#pragma once
#include <array>
#include <bit>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace dlab {

class CavityHistogram {
 public:
  static constexpr int kBuckets = 7;

  void add(std::uint64_t simplices) {
    if (simplices == 0) return;  // no cavity (a duplicate point): not an insertion
    const int b = std::bit_width(simplices) - 1;  // floor(log2): 1 -> 0, 2..3 -> 1, 4..7 -> 2, ...
    ++counts_[b < kBuckets ? b : kBuckets - 1];
  }

  void add(const CavityHistogram& other) {
    for (int b = 0; b < kBuckets; ++b) counts_[b] += other.counts_[b];
  }

  // "cavity_size_1", "cavity_size_2_3", ..., "cavity_size_64_up".
  static std::string name(int b) {
    const std::uint64_t lo = std::uint64_t{1} << b;
    if (b == kBuckets - 1) return "cavity_size_" + std::to_string(lo) + "_up";
    if (b == 0) return "cavity_size_1";
    return "cavity_size_" + std::to_string(lo) + "_" + std::to_string(2 * lo - 1);
  }

  void append_to(std::vector<std::pair<std::string, std::uint64_t>>& counters) const {
    for (int b = 0; b < kBuckets; ++b) counters.emplace_back(name(b), counts_[b]);
  }

 private:
  std::array<std::uint64_t, kBuckets> counts_{};
};

}  // namespace dlab
