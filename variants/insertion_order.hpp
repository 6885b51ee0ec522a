// Insertion orders: input, random (seeded shuffle), BRIO, Hilbert.
//
//  - hilbert: points sorted along a Hilbert curve over the bounding cube
//    (about 16 cells per point along each axis, at most 2^24 (2D) / 2^18 (3D); key by Skilling's transpose
//    algorithm, "Programming the Hilbert curve", AIP Conf. Proc. 707 (2004)),
//    ties by input index.
//  - brio: biased randomized insertion order (Amenta, Choi, Rote, "Incremental
//    constructions con BRIO", SoCG 2003): shuffle, then split into rounds whose
//    sizes grow by a factor 8 (the first 1/8 recursively, the last 7/8 as the
//    final round; design.md section 7 item 7), each round sorted along the
//    Hilbert curve.
//  - random: a seeded Fisher–Yates shuffle.
// Deterministic on every machine: splitmix64 (Steele, Lea, Flood 2014) drives
// the shuffle, keys come from IEEE double arithmetic without contraction, and
// sorting breaks ties by index.
#pragma once
#include <algorithm>
#include <cstdint>
#include <new>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "algorithms/huge_pages.hpp"
#include "predicates/point.hpp"
#include "variants/for_ranges.hpp"

namespace dlab {

enum class InsertionOrder { input, random, brio, hilbert };

// Throws UsageError (variants/run.hpp) for an unknown name.
InsertionOrder parse_insertion_order(std::string_view name);

// A permutation of 0..n-1: position i holds the input index inserted i-th.
// threads > 1: the Hilbert keys and their sorts run on that many oneTBB
// threads (for --threads); the permutation is the same for every value.
std::vector<std::uint32_t> insertion_order(std::span<const Point2> pts, InsertionOrder order,
                                           std::uint64_t seed, unsigned threads = 1);
std::vector<std::uint32_t> insertion_order(std::span<const Point3> pts, InsertionOrder order,
                                           std::uint64_t seed, unsigned threads = 1);

// Sorts idx[first, last) by keys[idx[i]], stably (each BRIO round, the
// Hilbert order), on `threads` oneTBB threads; the same result for every
// value.
void sort_indices_by_key(std::vector<std::uint32_t>& idx, std::size_t first, std::size_t last,
                         std::span<const std::uint64_t> keys, unsigned threads = 1);

// Puts `v` in insertion order: v[i] becomes the old v[order[i]] (order from
// insertion_order, or anything indexed so: PackedIndices); with `back`, undoes
// it. Out of place when memory allows: independent loads and stores, many cache
// misses in flight, into a buffer that nothing fills first, on `threads`
// oneTBB threads, then copied back into v's own pages. Otherwise, or with
// `in_place`, along the permutation's cycles, whose chained misses made it 3x
// slower than the run's own ordering work on 10^6 points, but which needs only
// `done` (one bit per element; allocates nothing once it has v's size).
template <class T, class Order>
void apply_order(std::vector<T>& v, const Order& order, bool back, std::vector<bool>& done, bool in_place = false,
                 unsigned threads = 1) {
  if (!in_place) {
    try {
      const HugeBuffer<T> out = huge_buffer<T>(v.size());
      for_ranges(v.size(), threads, [&](std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) {
          if (back)
            out[order[i]] = v[i];
          else
            out[i] = v[order[i]];
        }
      });
      for_ranges(v.size(), threads,
                 [&](std::size_t first, std::size_t last) { std::copy(out.get() + first, out.get() + last, v.data() + first); });
      return;
    } catch (const std::bad_alloc&) {
    }
  }
  done.assign(v.size(), false);
  for (std::uint32_t i = 0; i < v.size(); ++i) {
    if (done[i]) continue;
    T carried = v[i];
    std::uint32_t j = i;
    done[i] = true;
    if (!back) {  // gather: v[j] = old v[order[j]] along the cycle
      for (std::uint32_t k = order[j]; k != i; j = k, k = order[k]) {
        v[j] = v[k];
        done[k] = true;
      }
      v[j] = carried;
    } else {  // scatter: old v[j] goes to order[j]
      for (std::uint32_t k = order[j]; k != i; k = order[k]) {
        std::swap(carried, v[k]);
        done[k] = true;
      }
      v[i] = carried;
    }
  }
}

// Hilbert index of grid coordinates x[0..n-1] (each < 2^bits), n * bits <= 64
// (x may be overwritten): 2D and 3D by table look-ups, other n by Skilling's
// transform, whose index hilbert_key_skilling gives for every n (the reference
// the tables are checked against).
std::uint64_t hilbert_key(std::uint32_t* x, int n, int bits);
std::uint64_t hilbert_key_skilling(std::uint32_t* x, int n, int bits);

}  // namespace dlab
