// The front of an advancing-front Delaunay construction (Tanemura, Ogawa,
// Ogita 1983; Baker §16.2.3): a hash table of facets (D vertex ids) that have
// a simplex on exactly one side so far, each stored ORIENTED so that its open
// (outer) side is the positive side: orient_pos(f[0..D-1], p) > 0.
//
// Open addressing, linear probing, keyed by the sorted ids; deletion by
// backward shift (no tombstones), so a table whose closed facets are erased
// stays as small as the front. With `keep_closed` (inexact kernels) closed
// facets stay as `closed` entries, so that a facet met a third time is caught.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "algorithms/huge_pages.hpp"

namespace dlab {

template <int D>
class FacetTable {
 public:
  using Facet = std::array<std::uint32_t, D>;
  enum class State : std::uint8_t { empty, open, closed };
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  // 16 bytes in 3D: the open side is kept as the parity of the oriented
  // facet's permutation of the key (a rotation keeps the orientation, a
  // swap reverses it). 28 bytes with the oriented ids, and the table's
  // probes were a fifth of Tanemura's time on 10^5 uniform 3D points
  // (perf), most of it cache misses.
  struct Slot {
    Facet key{};  // sorted ids
    State state = State::empty;
    bool odd = false;  // oriented(): key with its first two ids swapped
    Facet oriented() const {  // the open side is the positive side
      Facet f = key;
      if (odd) std::swap(f[0], f[1]);
      return f;
    }
  };
  // The parity of f as a permutation of sorted(f) (distinct ids).
  static bool odd(const Facet& f) {
    bool p = false;
    for (int i = 0; i < D; ++i)
      for (int j = i + 1; j < D; ++j) p ^= f[i] > f[j];
    return p;
  }

  FacetTable() { slots_.resize(1024); }

  // A sorting network of min / max (conditional moves: std::sort's insertion
  // sort mispredicted on every other call).
  static Facet sorted(Facet f) {
    const auto order = [&f](int i, int j) {
      const std::uint32_t a = std::min(f[i], f[j]), b = std::max(f[i], f[j]);
      f[i] = a;
      f[j] = b;
    };
    if constexpr (D == 2) {
      order(0, 1);
    } else if constexpr (D == 3) {
      order(0, 1);
      order(1, 2);
      order(0, 1);
    } else {
      std::sort(f.begin(), f.end());
    }
    return f;
  }
  // Same orientation: equal up to an even permutation (2D: equal; 3D: a
  // rotation). For a slot's facet and another with the same ids: slot.odd
  // == odd(b).
  static bool same_orientation(const Facet& a, const Facet& b) {
    if constexpr (D == 2) {
      return a == b;
    } else {
      for (int r = 0; r < 3; ++r)
        if (a[0] == b[r] && a[1] == b[(r + 1) % 3] && a[2] == b[(r + 2) % 3]) return true;
      return false;
    }
  }

  std::size_t find(const Facet& key) const {
    std::size_t h = hash(key);
    for (;;) {
      const Slot& s = slots_[h];
      if (s.state == State::empty) return npos;
      if (same_ids(s.key, key)) return h;
      h = (h + 1) & (slots_.size() - 1);
    }
  }
  // Starts loading key's first slot into the cache (probes are cache
  // misses: the front is searched in FIFO order, its facets hashed apart).
  void prefetch(const Facet& key) const { __builtin_prefetch(&slots_[hash(key)]); }
  Slot& at(std::size_t i) { return slots_[i]; }
  const Slot& at(std::size_t i) const { return slots_[i]; }

  // Inserts an absent key.
  void insert(const Facet& key, const Facet& oriented, State st) {
    if (2 * (used_ + 1) > slots_.size()) grow();
    std::size_t h = hash(key);
    while (slots_[h].state != State::empty) h = (h + 1) & (slots_.size() - 1);
    slots_[h] = Slot{key, st, odd(oriented)};
    ++used_;
    max_used_ = std::max(max_used_, used_);
  }

  // Backward-shift deletion (Knuth vol. 3, 6.4 Algorithm R).
  void erase(std::size_t i) {
    const std::size_t mask = slots_.size() - 1;
    std::size_t j = i;
    for (;;) {
      j = (j + 1) & mask;
      if (slots_[j].state == State::empty) break;
      const std::size_t k = hash(slots_[j].key);
      // Move j to i unless k lies cyclically in (i, j].
      const bool in_range = (i <= j) ? (i < k && k <= j) : (i < k || k <= j);
      if (!in_range) {
        slots_[i] = slots_[j];
        i = j;
      }
    }
    slots_[i].state = State::empty;
    --used_;
  }

  std::size_t size() const { return used_; }
  std::size_t max_size() const { return max_used_; }
  std::size_t bytes() const { return slots_.capacity() * sizeof(Slot); }

 private:
  static bool same_ids(const Facet& a, const Facet& b) {  // == on std::array called memcmp
    bool same = true;
    for (int i = 0; i < D; ++i) same &= a[i] == b[i];
    return same;
  }
  std::size_t hash(const Facet& key) const {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (std::uint32_t v : key) {
      h ^= v;
      h *= 0xBF58476D1CE4E5B9ull;
      h ^= h >> 31;
    }
    return static_cast<std::size_t>(h) & (slots_.size() - 1);
  }
  void grow() {
    std::vector<Slot> old = huge_vector<Slot>(slots_.size() * 2);  // algorithms/huge_pages.hpp
    old.swap(slots_);
    used_ = 0;
    for (const Slot& s : old)
      if (s.state != State::empty) {
        std::size_t h = hash(s.key);
        while (slots_[h].state != State::empty) h = (h + 1) & (slots_.size() - 1);
        slots_[h] = s;
        ++used_;
      }
  }

  std::vector<Slot> slots_;
  std::size_t used_ = 0, max_used_ = 0;
};

}  // namespace dlab
