// The coordinate passes of `dlab shrink` (fuzz/shrink.hpp), run after ddmin
// has removed points. Each offers simpler versions of the point set and keeps
// one only if it is smaller by ShrinkSize and the same failure persists
// (Simplifier::offer), so every kept step shrinks ShrinkSize, a triple of
// natural numbers compared lexicographically: no sequence of passes can cycle.
//  - translate_toward_origin: per axis, subtract an offset t from every
//    coordinate, kept only when every difference is exact (exact_difference),
//    t tried in this order: the axis's minimum (the set then starts at 0); the
//    centre of its range rounded to a multiple of the largest power of two not
//    above the range (a power-of-two-aligned offset); the centre rounded to the
//    grid every coordinate of the axis lies on (its finest last 1 bit);
//  - snap_whole_set: every coordinate to the nearest integer; then every
//    coordinate rounded to b significant bits, b bisected in 1..(most bits of a
//    coordinate) for the fewest bits that still fail (the fewest if failing is
//    monotone in b; a kept set in any case);
//  - simplify_each_coordinate: each coordinate in turn to 0, else to the
//    nearest integer, else to fewer significant bits, bisected as above.
// A pass offers at most 3 candidates per axis, 1 + 6 for the whole set, and
// 2 + 6 per coordinate (bisection over 1..53 takes at most 6 steps).
#pragma once
#include <compare>
#include <cstdint>
#include <functional>

#include "variants/run.hpp"

namespace dlab::fuzz {

// The size dlab shrink reports and reduces, compared in this order.
struct ShrinkSize {
  std::uint64_t points = 0;
  std::uint64_t bits = 0;       // significant_bits summed over every coordinate
  std::uint64_t exponents = 0;  // exponent_distance summed: smaller magnitudes at equal bits
  auto operator<=>(const ShrinkSize&) const = default;
};
ShrinkSize size_of(const PointSet& s);

// fails(points): true if `points` shows the same failure.
using PointTest = std::function<bool(const PointSet&)>;

// The current point set, which fails, and the test of other sets.
class Simplifier {
 public:
  Simplifier(PointSet failing, PointTest fails);
  const PointSet& points() const { return points_; }
  const ShrinkSize& size() const { return size_; }
  // Runs the test on `candidate` (keeps nothing).
  bool fails(const PointSet& candidate) const { return fails_(candidate); }
  // Makes `failing` (a set the test found failing) the current set.
  void keep(PointSet failing);
  // Keeps `candidate` if it is smaller than points() and fails; returns whether it did.
  bool offer(PointSet candidate);

 private:
  PointSet points_;
  ShrinkSize size_;
  PointTest fails_;
};

// Each returns true if it kept a candidate.
bool translate_toward_origin(Simplifier& s);
bool snap_whole_set(Simplifier& s);
bool simplify_each_coordinate(Simplifier& s);

}  // namespace dlab::fuzz
