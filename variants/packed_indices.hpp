// Indices below a bound n kept in ceil(log2 n) bits each instead of 32: the
// driver's insertion order while the mesh is at its peak (10^6 points: 20
// bits, 2.5 MB instead of 4; issue 15, "bytes per point <= 250").
#pragma once
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace dlab {

class PackedIndices {
 public:
  PackedIndices() = default;
  // Every value must be below `bound`.
  PackedIndices(std::span<const std::uint32_t> values, std::uint64_t bound)
      : size_(values.size()), width_(width_for(bound)), words_((size_ * width_ + 63) / 64 + 1, 0) {
    for (std::size_t i = 0; i < size_; ++i) {
      const std::uint64_t bit = std::uint64_t(i) * width_;
      const std::uint64_t v = values[i];
      words_[bit / 64] |= v << (bit % 64);
      if (bit % 64 + width_ > 64) words_[bit / 64 + 1] |= v >> (64 - bit % 64);
    }
  }

  std::uint32_t operator[](std::size_t i) const {
    const std::uint64_t bit = std::uint64_t(i) * width_;
    std::uint64_t v = words_[bit / 64] >> (bit % 64);
    if (bit % 64 + width_ > 64) v |= words_[bit / 64 + 1] << (64 - bit % 64);
    return static_cast<std::uint32_t>(v & ((std::uint64_t(1) << width_) - 1));
  }
  std::size_t size() const { return size_; }
  int width() const { return width_; }
  std::size_t bytes() const { return words_.size() * sizeof(std::uint64_t); }

  // Bits that hold every value below bound: ceil(log2 bound), at least 1.
  static int width_for(std::uint64_t bound) { return bound <= 2 ? 1 : std::bit_width(bound - 1); }

 private:
  std::size_t size_ = 0;
  int width_ = 1;
  std::vector<std::uint64_t> words_;
};

}  // namespace dlab
