// Space cut into B boxes at the quantiles of a point set, as a kd-tree cuts
// it: the points along axes[0] into c_0 slabs with equal shares, each slab
// along axes[1] into c_1, and so on, B = c_0 c_1 ... with c_0 >= c_1 >= ...
// (B's prime factors, largest first, each to the level with the fewest
// pieces).  The boxes are half-open, lo <= x < hi on every axis (+-inf at the
// outside), and tile space: every point lies in exactly one, the one box_of
// finds.  Equal coordinates go to one side of a cut, so a share may be empty.
// The parallel Bowyer–Watson's rounds (algorithms/parallel_bowyer_watson.hpp;
// HXT's partitions, Marot, Pellerin, Remacle, IJNME 2019, section 4).
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "predicates/point.hpp"

namespace dlab {

template <int D>
struct KdBoxes {
  std::array<int, D> axes{};            // the axis each level cuts
  std::array<std::size_t, D> pieces{};  // each box of the level above cut into this many
  std::vector<std::array<double, D>> lo, hi;
  std::vector<std::vector<std::uint32_t>> shares;  // each box's points, in the order given

  std::size_t size() const { return lo.size(); }

  // The box holding p: a descent, level by level.  The boxes cut from one box
  // of the level above are consecutive, and all of one piece share its bounds
  // on that level's axis.
  std::size_t box_of(const Point<D>& p) const {
    std::size_t first = 0, count = size();
    for (int level = 0; level < D; ++level) {
      const std::size_t c = pieces[level];
      if (c == 1) continue;
      const std::size_t stride = count / c;
      const int a = axes[level];
      std::size_t t = 0;
      while (t + 1 < c && p[a] >= hi[first + t * stride][a]) ++t;
      first += t * stride;
      count = stride;
    }
    return first;
  }
};

// `boxes` boxes with equal shares of `points` (indices into pts).
template <int D>
KdBoxes<D> cut_at_quantiles(const Point<D>* pts, std::vector<std::uint32_t> points, const std::array<int, D>& axes,
                            std::size_t boxes) {
  KdBoxes<D> k;
  k.axes = axes;
  std::vector<std::size_t> primes;
  std::size_t rest = std::max<std::size_t>(boxes, 1);
  for (std::size_t p = 2; p * p <= rest;)
    if (rest % p == 0)
      primes.push_back(p), rest /= p;
    else
      ++p;
  if (rest > 1) primes.push_back(rest);
  k.pieces.fill(1);
  for (auto p = primes.rbegin(); p != primes.rend(); ++p)
    *std::min_element(k.pieces.begin(), k.pieces.end()) *= *p;  // the first of the fewest: the widest
  k.lo.assign(1, {});
  k.hi.assign(1, {});
  k.lo[0].fill(-std::numeric_limits<double>::infinity());
  k.hi[0].fill(std::numeric_limits<double>::infinity());
  k.shares.assign(1, std::move(points));
  std::vector<double> x;
  for (int level = 0; level < D; ++level) {
    const int a = axes[level];
    const std::size_t c = k.pieces[level];
    if (c == 1) continue;
    KdBoxes<D> finer;
    for (std::size_t b = 0; b < k.size(); ++b) {
      const std::size_t first = finer.size();
      finer.lo.resize(first + c, k.lo[b]);
      finer.hi.resize(first + c, k.hi[b]);
      finer.shares.resize(first + c);
      const std::vector<std::uint32_t>& share = k.shares[b];
      x.resize(share.size());
      for (std::size_t j = 0; j < x.size(); ++j) x[j] = pts[share[j]][a];
      auto from = x.begin();
      for (std::size_t t = 1; t < c; ++t) {
        const auto q = x.begin() + static_cast<std::ptrdiff_t>(t * x.size() / c);
        if (!x.empty()) std::nth_element(from, q, x.end());
        // An empty box stays whole in its first piece; the others are empty.
        finer.hi[first + t - 1][a] = finer.lo[first + t][a] = x.empty() ? k.hi[b][a] : *q;
        from = q;
      }
      for (std::uint32_t i : share) {
        std::size_t t = first;
        while (t + 1 < first + c && pts[i][a] >= finer.hi[t][a]) ++t;
        finer.shares[t].push_back(i);
      }
    }
    k.lo.swap(finer.lo);
    k.hi.swap(finer.hi);
    k.shares.swap(finer.shares);
  }
  return k;
}

}  // namespace dlab
