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
// Nodes on one hyperplane share one id (a line of points split by a node
// holding a point off it has several topmost flat nodes), and each point in
// a flat node knows its hyperplane, so that the search asks the kernel
// whether a point lies on a hyperplane (an exact zero: the adaptive kernel's
// slowest stage) only for the few points outside flat nodes.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "algorithms/kd_tree.hpp"
#include "predicates/kernel.hpp"

namespace dlab {

template <int D>
class ExactFlats {
 public:
  static constexpr std::uint32_t kNone = 0xFFFFFFFFu;

  // For the tree built on pts (ids as given to tree.build), with `simplex`
  // affinely independent for the kernel k.
  template <class K>
  void build(const K& k, const KdTree<D>& tree, std::span<const Point<D>> pts,
             const std::array<std::uint32_t, D + 1>& simplex);

  // The hyperplane holding every point of node k exactly, or kNone.
  std::uint32_t of_node(std::uint32_t k) const { return flat_of_[k]; }
  // The hyperplane of the flat node holding point id (an id given to build),
  // or kNone: the point may still lie on some hyperplane.
  std::uint32_t of_point(std::uint32_t id) const { return of_point_[id]; }
  // D points spanning it (ids into the points given to build).
  const std::array<std::uint32_t, D>& refs(std::uint32_t flat) const { return refs_[flat]; }
  std::size_t count() const { return refs_.size(); }
  std::size_t bytes() const {
    return flat_of_.capacity() * 4 + of_point_.capacity() * 4 + refs_.capacity() * sizeof(refs_[0]);
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

  std::vector<std::uint32_t> flat_of_;   // per node
  std::vector<std::uint32_t> of_point_;  // per point
  std::vector<std::array<std::uint32_t, D>> refs_;
};

template <int D>
template <class K>
void ExactFlats<D>::build(const K& k, const KdTree<D>& tree, std::span<const Point<D>> pts,
                          const std::array<std::uint32_t, D + 1>& simplex) {
  flat_of_.assign(tree.node_count(), kNone);
  of_point_.assign(pts.size(), kNone);
  refs_.clear();
  // Preorder: a parent comes before its children.
  for (std::uint32_t n = 0; n < tree.node_count(); ++n) {
    if (n != KdTree<D>::root()) {
      if (const std::uint32_t up = flat_of_[tree.parent(n)]; up != kNone) {
        flat_of_[n] = up;
        continue;
      }
    }
    const NodeFrame<D>* fr = tree.frame(n);
    const typename KdTree<D>::Node& node = tree.node(n);
    if (!fr || node.end - node.begin < static_cast<std::uint32_t>(D)) continue;
    // Refs: the extreme points along the frame's first row, and in 3D the
    // point farthest along its second (the frame's plane; doubles: a choice).
    const auto along = [&](std::uint32_t slot, int row) {
      double y = 0;
      for (int i = 0; i < D; ++i) y += fr->u[row][i] * tree.coords(slot)[i];
      return y;
    };
    std::uint32_t a = node.begin, b = node.begin;
    for (std::uint32_t s = node.begin; s < node.end; ++s) {
      if (along(s, 0) < along(a, 0)) a = s;
      if (along(s, 0) > along(b, 0)) b = s;
    }
    std::array<std::uint32_t, D> r{tree.id(a), tree.id(b)};
    if constexpr (D == 3) {
      const double mid = along(a, 1);
      std::uint32_t c = a;
      for (std::uint32_t s = node.begin; s < node.end; ++s)
        if (std::fabs(along(s, 1) - mid) > std::fabs(along(c, 1) - mid)) c = s;
      r[2] = tree.id(c);
    }
    bool spans = false;
    for (const std::uint32_t v : simplex) spans = spans || orientation(k, pts, r, pts[v]) != Sign::zero;
    if (!spans) continue;
    bool flat = true;
    for (std::uint32_t s = node.begin; s < node.end && flat; ++s)
      flat = orientation(k, pts, r, tree.coords(s)) == Sign::zero;
    if (!flat) continue;
    // The same hyperplane as one found before: its D points lie on it.
    std::uint32_t h = 0;
    for (; h < refs_.size(); ++h) {
      bool same = true;
      for (int j = 0; j < D && same; ++j) same = orientation(k, pts, refs_[h], pts[r[j]]) == Sign::zero;
      if (same) break;
    }
    if (h == refs_.size()) refs_.push_back(r);
    flat_of_[n] = h;
    for (std::uint32_t s = node.begin; s < node.end; ++s) of_point_[tree.id(s)] = h;
  }
}

}  // namespace dlab
