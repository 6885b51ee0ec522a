// A uniform bucket grid over a point set, for the candidate search of the
// Tanemura–Ogawa–Ogita front (algorithms/tanemura.hpp; Tanemura, Ogawa, Ogita,
// J. Comput. Phys. 51 (1983) use the same device; Baker, Handbook of Grid
// Generation §16.2.3). About `per_cell` points per cell; cells are grouped in
// blocks of B^D cells, each block keeping the bounding box of its points, so
// that a search can skip empty or irrelevant regions cheaply.
//
// The grid only PRUNES: it tells which cells can hold a point of a region. The
// guarantee a search relies on:
//   every point x whose (real) scaled coordinates lie in [lo, hi] on each axis
//   is stored in a cell whose index lies in [cell_of(lo), cell_of(hi)].
// Proof: a point's cell is cell_of(fl(x*s)) with cell_of(t) =
// clamp(floor(fl(fl(t - origin) * inv)), 0, N-1). Every step (rounded *, -, by
// positive constants, floor, clamp) is monotone non-decreasing in t, and
// rounding is monotone, so lo <= x*s <= hi implies the same order of indices.
// Coordinates are scaled by a power of two s (max |coordinate| about 1), so no
// intermediate overflows; a possibly inexact (underflowed) scaled coordinate is
// widened by an ulp wherever an enclosure is needed (scaled_iv).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/interval.hpp"
#include "predicates/point.hpp"

namespace dlab {

template <int D>
class BucketGrid {
 public:
  static constexpr int B = D == 2 ? 4 : 2;  // block side, in cells

  // Builds the grid on pts[ids[k]] (distinct points).
  void build(std::span<const Point<D>> pts, const std::vector<std::uint32_t>& ids, double per_cell) {
    const std::size_t n = ids.size();
    Point<D> lo, hi;
    for (int i = 0; i < D; ++i) lo[i] = hi[i] = n ? pts[ids[0]][i] : 0.0;
    for (std::uint32_t id : ids)
      for (int i = 0; i < D; ++i) {
        lo[i] = std::min(lo[i], pts[id][i]);
        hi[i] = std::max(hi[i], pts[id][i]);
      }
    double big = 0;
    for (int i = 0; i < D; ++i) big = std::max({big, std::fabs(lo[i]), std::fabs(hi[i])});
    int e = 0;
    if (big > 0) std::frexp(big, &e);
    // big * scale_ in [0.5, 1), or as close as a representable power of two
    // allows (subnormal inputs: 2^1074 overflows; 2^1000 brings them to 2^-74).
    scale_ = std::ldexp(1.0, std::clamp(-e, -1000, 1000));
    // Target cell count, shared among the axes with a non-zero extent.
    const double cells = std::max(1.0, static_cast<double>(n) / per_cell);
    double logsum = 0;
    int active = 0;
    for (int i = 0; i < D; ++i) {
      origin_[i] = lo[i] * scale_;
      top_[i] = hi[i] * scale_;
      ext_[i] = top_[i] - origin_[i];
      if (ext_[i] > 0) {
        logsum += std::log(ext_[i]);
        ++active;
      }
    }
    const double logh = active ? (logsum - std::log(cells)) / active : 0.0;
    std::size_t total = 1;
    for (int i = 0; i < D; ++i) {
      double ni = ext_[i] > 0 ? std::floor(std::exp(std::log(ext_[i]) - logh)) : 1.0;
      if (!(ni >= 1)) ni = 1;  // also NaN
      ni = std::min(ni, D == 2 ? 65536.0 : 2048.0);
      n_[i] = static_cast<int>(ni);
    }
    // Flat sets (one tiny extent) can push the others up: keep the total near the target.
    for (int guard = 0; guard < 64; ++guard) {
      double prod = 1;
      for (int i = 0; i < D; ++i) prod *= n_[i];
      if (prod <= 4 * cells + 64) break;
      int big_axis = 0;
      for (int i = 1; i < D; ++i)
        if (n_[i] > n_[big_axis]) big_axis = i;
      n_[big_axis] = std::max(1, n_[big_axis] / 2);
    }
    for (int i = 0; i < D; ++i) {
      inv_[i] = ext_[i] > 0 ? n_[i] / ext_[i] : 0.0;
      total *= static_cast<std::size_t>(n_[i]);
      nb_[i] = (n_[i] + B - 1) / B;
    }
    // Counting sort of the points by cell.
    start_.assign(total + 1, 0);
    std::vector<std::uint32_t> cell(n);
    for (std::size_t k = 0; k < n; ++k) {
      cell[k] = cell_index(pts[ids[k]]);
      ++start_[cell[k] + 1];
    }
    for (std::size_t c = 0; c < total; ++c) start_[c + 1] += start_[c];
    items_.resize(n);
    coords_.resize(n);
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t pos = fill[cell[k]]++;
      items_[pos] = ids[k];
      coords_[pos] = pts[ids[k]];
    }
    // Blocks: bounding boxes (scaled, widened by an ulp: enclosures).
    std::size_t nblocks = 1;
    for (int i = 0; i < D; ++i) nblocks *= static_cast<std::size_t>(nb_[i]);
    blo_.assign(nblocks, {});
    bhi_.assign(nblocks, {});
    bcount_.assign(nblocks, 0);
    for (std::size_t c = 0; c < total; ++c) {
      const std::array<int, D> ci = unflatten(c);
      std::size_t b = 0;
      for (int i = D - 1; i >= 0; --i) b = b * nb_[i] + ci[i] / B;
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        for (int i = 0; i < D; ++i) {
          const Iv v = scaled_iv(coords_[k][i]);
          if (bcount_[b] == 0 && k == start_[c]) {
            blo_[b][i] = v.lo;
            bhi_[b][i] = v.hi;
          } else {
            blo_[b][i] = std::min(blo_[b][i], v.lo);
            bhi_[b][i] = std::max(bhi_[b][i], v.hi);
          }
        }
      }
      bcount_[b] += start_[c + 1] - start_[c];
    }
    bool first = true;
    for (std::size_t b = 0; b < nblocks; ++b)
      if (bcount_[b] != 0)
        for (int i = 0; i < D; ++i) {
          alo_[i] = first ? blo_[b][i] : std::min(alo_[i], blo_[b][i]);
          ahi_[i] = first ? bhi_[b][i] : std::max(ahi_[i], bhi_[b][i]);
          if (i == D - 1) first = false;
        }
  }

  // An enclosure of x * scale (exact unless it underflows).
  Iv scaled_iv(double x) const {
    const double v = x * scale_;
    if (std::fabs(v) >= 0x1p-1000 || (v == 0.0 && x == 0.0)) return Iv::exact(v);
    return {Iv::down(v), Iv::up(v)};
  }
  // Cell index along one axis of a scaled coordinate (monotone).
  int cell_of_scaled(int axis, double t) const {
    const double f = std::floor((t - origin_[axis]) * inv_[axis]);
    if (!(f >= 0)) return 0;  // also NaN
    if (f >= n_[axis] - 1) return n_[axis] - 1;
    return static_cast<int>(f);
  }
  std::uint32_t cell_index(const Point<D>& p) const {
    std::uint32_t c = 0;
    for (int i = D - 1; i >= 0; --i) c = c * n_[i] + cell_of_scaled(i, p[i] * scale_);
    return c;
  }
  std::array<int, D> unflatten(std::size_t c) const {
    std::array<int, D> ci{};
    for (int i = 0; i < D; ++i) {
      ci[i] = static_cast<int>(c % n_[i]);
      c /= n_[i];
    }
    return ci;
  }
  std::uint32_t flatten(const std::array<int, D>& ci) const {
    std::uint32_t c = 0;
    for (int i = D - 1; i >= 0; --i) c = c * n_[i] + ci[i];
    return c;
  }

  int cells(int axis) const { return n_[axis]; }
  int max_cells() const { return *std::max_element(n_.begin(), n_.end()); }
  int blocks(int axis) const { return nb_[axis]; }
  std::size_t cell_count() const { return start_.size() - 1; }
  std::size_t block_count() const { return bcount_.size(); }
  std::uint32_t block_points(std::size_t b) const { return bcount_[b]; }
  // Enclosure of all points (union of the block boxes).
  const std::array<double, D>& all_lo() const { return alo_; }
  const std::array<double, D>& all_hi() const { return ahi_; }
  const std::array<double, D>& block_lo(std::size_t b) const { return blo_[b]; }
  const std::array<double, D>& block_hi(std::size_t b) const { return bhi_[b]; }
  std::uint32_t begin(std::uint32_t c) const { return start_[c]; }
  std::uint32_t end(std::uint32_t c) const { return start_[c + 1]; }
  std::uint32_t id(std::uint32_t k) const { return items_[k]; }
  const Point<D>& coords(std::uint32_t k) const { return coords_[k]; }
  std::size_t bytes() const {
    return start_.capacity() * 4 + items_.capacity() * 4 + coords_.capacity() * sizeof(Point<D>) +
           bcount_.capacity() * (4 + 2 * sizeof(std::array<double, D>));
  }

 private:
  double scale_ = 1;
  std::array<double, D> origin_{}, top_{}, ext_{}, inv_{};
  std::array<int, D> n_{}, nb_{};
  std::vector<std::uint32_t> start_, items_;
  std::vector<Point<D>> coords_;
  std::vector<std::array<double, D>> blo_, bhi_;
  std::vector<std::uint32_t> bcount_;
  std::array<double, D> alo_{}, ahi_{};
};

}  // namespace dlab
