// Tree nodes whose points lie EXACTLY on one hyperplane (a line in 2D, a
// plane in 3D), decided by the kernel, for Tanemura's search
// (algorithms/tanemura.hpp). A facet lying in that hyperplane has every such
// point at orientation exactly zero: none is a candidate (candidates are
// strictly on the open side), so the node is skipped without a look at its
// points.
//
// Why: on a plane of points with a few points off it (dlab gen coplanar) a
// facet in the plane looks for its apex among the off points, far away. With
// no candidate yet there is no ball, only the outer-side test, and the
// enclosure of n . (x - f0) of a point exactly on the facet's plane is [-e, e]
// in any rounded frame (algorithms/node_frame.hpp): it cannot show "not
// strictly outer", so such searches scanned every point between the facet and
// the apex (about 10^4 each, n = 20000; papers/triangulation_costs.md,
// session 11). Exact kernels only: an inexact kernel's zeros prove nothing.
//
// Which nodes: the framed ones (flat, oblique) and their descendants. A
// node's hyperplane is spanned by D of its points (refs), chosen in plain
// doubles; it is kept only if every point of the node has orientation zero
// against the refs and the refs span a hyperplane, which holds iff some
// vertex of the run's initial simplex (D + 1 affinely independent points)
// is off it: if the refs were dependent every orientation against them
// would be zero. A node inside a flat node shares its hyperplane (its
// points are a subset), so each point is tested once, at its topmost flat
// node.
//
// A node may also hold a few points off its hyperplane, its exceptions
// (kMaxExceptions and an eighth of its points at most; its descendants
// inherit theirs): a line with a few points beside it has them in every
// node on the way from the root. Its flat part is the rest, with a box of
// its own, and the search examines the exceptions one by one where the
// flat part is pruned.
//
// Nodes on one hyperplane share one id (a line of points split by a node
// holding a point off it has several topmost flat nodes), and each point in
// a flat node knows its hyperplane, so that the search asks the kernel
// whether a point lies on a hyperplane (an exact zero: the adaptive kernel's
// slowest stage) only for the few points outside flat nodes.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "algorithms/kd_tree.hpp"
#include "predicates/kernel.hpp"

namespace dlab {

template <int D>
class ExactFlats {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  static constexpr std::uint32_t kMaxExceptions = 4;

  // A node's flat part, where it holds exceptions: the box of the points on
  // the hyperplane (the tree's enclosures) and the exceptions' slots.
  struct Part {
    std::array<double, D> lo, hi;
    std::uint32_t begin, count;  // exceptions(): slots exc_[begin, begin + count)
  };

  // For the tree built on pts (ids as given to tree.build), with `simplex`
  // affinely independent for the kernel k.
  template <class K>
  void build(const K& k, const KdTree<D>& tree, std::span<const Point<D>> pts,
             const std::array<std::uint32_t, D + 1>& simplex);

  // The hyperplane holding every point of node k exactly but its
  // exceptions, or kNone.
  std::uint32_t of_node(std::uint32_t k) const { return flat_of_[k]; }
  // Node k's flat part, or null where it has no exceptions (of_node(k) != kNone).
  const Part* part(std::uint32_t k) const { return part_of_[k] == kNone ? nullptr : &parts_[part_of_[k]]; }
  std::span<const std::uint32_t> exceptions(const Part& p) const { return {exc_.data() + p.begin, p.count}; }
  // The hyperplane of the flat node holding point id (an id given to build),
  // or kNone: the point may still lie on some hyperplane. Only where count()
  // > 0 (the table is not allocated on sets without flats).
  std::uint32_t of_point(std::uint32_t id) const { return of_point_[id]; }
  // D points spanning it (ids into the points given to build).
  const std::array<std::uint32_t, D>& refs(std::uint32_t flat) const { return refs_[flat]; }
  std::size_t count() const { return refs_.size(); }
  std::size_t bytes() const {
    return (flat_of_.capacity() + of_point_.capacity() + part_of_.capacity() + exc_.capacity()) * 4 +
           refs_.capacity() * sizeof(refs_[0]) + parts_.capacity() * sizeof(Part);
  }

 private:
  template <class K>
  static Sign orientation(const K& k, std::span<const Point<D>> pts, const std::array<std::uint32_t, D>& r,
                          const Point<D>& x) {
    if constexpr (D == 2)
      return k.orient2d(pts[r[0]], pts[r[1]], x);
    else
      return k.orient3d(pts[r[0]], pts[r[1]], pts[r[2]], x);
  }

  std::vector<std::array<std::uint32_t, D>> refs_;  // per hyperplane
  std::vector<std::uint32_t> flat_of_;   // per node
  std::vector<std::uint32_t> of_point_;  // per point
  std::vector<std::uint32_t> part_of_;   // per node: index in parts_, or kNone
  std::vector<Part> parts_;
  std::vector<std::uint32_t> exc_;
  // Records node n (of `tree`) as lying on hyperplane h but for the
  // exceptions exc (slots, sorted), with the flat part's box.
  void set_flat(const KdTree<D>& tree, std::uint32_t n, std::uint32_t h, const std::vector<std::uint32_t>& exc);
};

template <int D>
template <class K>
void ExactFlats<D>::build(const K& k, const KdTree<D>& tree, std::span<const Point<D>> pts,
                          const std::array<std::uint32_t, D + 1>& simplex) {
  flat_of_.assign(tree.node_count(), kNone);
  part_of_.assign(tree.node_count(), kNone);
  of_point_.clear();
  refs_.clear();
  parts_.clear();
  exc_.clear();
  std::vector<std::uint32_t> exc;
  std::vector<double> offsets;
  // Preorder: a parent comes before its children.
  for (std::uint32_t n = 0; n < tree.node_count(); ++n) {
    const typename KdTree<D>::Node& node = tree.node(n);
    if (n != KdTree<D>::root()) {
      if (const std::uint32_t up = tree.parent(n); flat_of_[up] != kNone) {
        exc.clear();
        if (const Part* p = part(up))
          for (const std::uint32_t s : exceptions(*p))
            if (s >= node.begin && s < node.end) exc.push_back(s);
        set_flat(tree, n, flat_of_[up], exc);
        continue;
      }
    }
    const NodeFrame<D>* fr = tree.frame(n);
    if (!fr || node.end - node.begin < static_cast<std::uint32_t>(D)) continue;
    // Refs: the extreme points along the frame's first row, and in 3D the
    // point farthest along its second (the frame's plane; doubles: a choice).
    const auto along = [&](std::uint32_t slot, int row) {
      double y = 0;
      for (int i = 0; i < D; ++i) y += fr->u[row][i] * tree.coords(slot)[i];
      return y;
    };
    // Refs among the slots that `keep` accepts.
    const auto choose = [&](auto keep) {
      std::uint32_t a = kNone, b = kNone;
      for (std::uint32_t s = node.begin; s < node.end; ++s) {
        if (!keep(s)) continue;
        if (a == kNone || along(s, 0) < along(a, 0)) a = s;
        if (b == kNone || along(s, 0) > along(b, 0)) b = s;
      }
      if (a == kNone) a = b = node.begin;  // none kept (NaN offsets): equal refs span nothing
      std::array<std::uint32_t, D> r{tree.id(a), tree.id(b)};
      if constexpr (D == 3) {
        const double mid = along(a, 1);
        std::uint32_t c = a;
        for (std::uint32_t s = node.begin; s < node.end; ++s)
          if (keep(s) && std::fabs(along(s, 1) - mid) > std::fabs(along(c, 1) - mid)) c = s;
        r[2] = tree.id(c);
      }
      return r;
    };
    // Whether refs r span a hyperplane holding all of the node's points but
    // kMaxExceptions at most (then in exc), and an eighth of them at most
    // (a small node's points would be "flat but for a few" by chance).
    const auto holds = [&](const std::array<std::uint32_t, D>& r) {
      bool spans = false;
      for (const std::uint32_t v : simplex) spans = spans || orientation(k, pts, r, pts[v]) != Sign::zero;
      if (!spans) return false;
      exc.clear();
      for (std::uint32_t s = node.begin; s < node.end && exc.size() <= kMaxExceptions; ++s)
        if (orientation(k, pts, r, tree.coords(s)) != Sign::zero) exc.push_back(s);
      return exc.size() <= kMaxExceptions && 8 * exc.size() <= node.end - node.begin;
    };
    std::array<std::uint32_t, D> r = choose([](std::uint32_t) { return true; });
    if (!holds(r)) {
      // An exception may be an extreme point: then refs among the points
      // nearest the median along the frame's normal (the last row).
      offsets.clear();
      for (std::uint32_t s = node.begin; s < node.end; ++s) offsets.push_back(along(s, D - 1));
      auto mid = offsets.begin() + static_cast<std::ptrdiff_t>(offsets.size() / 2);
      std::nth_element(offsets.begin(), mid, offsets.end());
      const double median = *mid;
      for (double& x : offsets) x = std::fabs(x - median);
      std::nth_element(offsets.begin(), mid, offsets.end());
      const double spread = 4 * *mid + 0x1p-40 * std::fabs(median);
      r = choose([&](std::uint32_t s) { return std::fabs(along(s, D - 1) - median) <= spread; });
      if (!holds(r)) continue;
    }
    // The same hyperplane as one found before: its D points lie on it.
    std::uint32_t h = 0;
    for (; h < refs_.size(); ++h) {
      bool same = true;
      for (int j = 0; j < D && same; ++j) same = orientation(k, pts, refs_[h], pts[r[j]]) == Sign::zero;
      if (same) break;
    }
    if (h == refs_.size()) refs_.push_back(r);
    if (of_point_.empty()) of_point_.assign(pts.size(), kNone);
    set_flat(tree, n, h, exc);
    for (std::uint32_t s = node.begin, e = 0; s < node.end; ++s) {
      if (e < exc.size() && exc[e] == s) {
        ++e;
        continue;
      }
      of_point_[tree.id(s)] = h;
    }
  }
}

template <int D>
void ExactFlats<D>::set_flat(const KdTree<D>& tree, std::uint32_t n, std::uint32_t h,
                             const std::vector<std::uint32_t>& exc) {
  flat_of_[n] = h;
  if (exc.empty()) return;
  const typename KdTree<D>::Node& node = tree.node(n);
  Part p{};
  p.lo.fill(std::numeric_limits<double>::infinity());
  p.hi.fill(-std::numeric_limits<double>::infinity());
  for (std::uint32_t s = node.begin, e = 0; s < node.end; ++s) {
    if (e < exc.size() && exc[e] == s) {
      ++e;
      continue;
    }
    for (int i = 0; i < D; ++i) {
      const Iv v = tree.scaled_iv(tree.coords(s)[i], i);
      p.lo[i] = std::min(p.lo[i], v.lo);
      p.hi[i] = std::max(p.hi[i], v.hi);
    }
  }
  p.begin = static_cast<std::uint32_t>(exc_.size());
  p.count = static_cast<std::uint32_t>(exc.size());
  exc_.insert(exc_.end(), exc.begin(), exc.end());
  part_of_[n] = static_cast<std::uint32_t>(parts_.size());
  parts_.push_back(p);
}

}  // namespace dlab
