// A bounding-box kd-tree over a point set, for the candidate search of the
// Tanemura–Ogawa–Ogita front (algorithms/tanemura.hpp). Each node splits its
// points on its widest axis (Bentley, CACM 18 (1975); Friedman, Bentley,
// Finkel, ACM TOMS 3 (1977)), at the rank that gives every leaf kLeaf - 1 or
// kLeaf points once n >= 20 (split_count); every node keeps the bounding box
// of its own points.
//
// Why not a uniform bucket grid (Tanemura, Ogawa, Ogita 1983; Baker §16.2.3):
// its cells follow the bounding box, not the points, so two outliers (the
// Kettner grid: 65 536 points within 2^-45 of (0.5, 0.5), plus (12, 12) and
// (24, 24)), a slanted line or tight clusters put thousands of points in one
// cell, and every facet near them examined them all. Splits by rank keep each
// leaf at kLeaf points whatever the distribution.
//
// The tree only PRUNES; the guarantee a search relies on:
//   every point of a node has its (real) scaled coordinates inside the node's
//   box [lo, hi] on each axis.
// The boxes are unions of the enclosures scaled_iv() of the points' scaled
// coordinates: translated by an origin where that is exact (see build),
// then scaled by a power of two (max |coordinate| about 1), exact unless the
// product underflows, and then widened by an ulp.
// A node whose points are flat and oblique (a line or plane) also keeps
// their box in a frame of their own (algorithms/node_frame.hpp), fitted
// bottom-up: a node is tried only if one of its children is flat.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/huge_pages.hpp"
#include "algorithms/interval.hpp"
#include "algorithms/node_frame.hpp"
#include "predicates/point.hpp"

namespace dlab {

template <int D>
class KdTree {
 public:
  // Leaves of 5 or 6 points from n = 20 on (split_count).  Leaves of 4-5 points
  // took fewer instructions than 2-3 or 9-10 (3D clustered n = 5000, session
  // 10; uniform 2D 10^5 and 3D 2*10^4 with the climb's stop, session 29);
  // leaves of 6 and 5 took the same at 10^5 and 10^6 (session 46).
  static constexpr std::uint32_t kLeaf = 6;
  static constexpr std::uint32_t kNoNode = 0xFFFFFFFFu;

  struct Node {
    std::array<double, D> lo, hi;  // box of the node's points (scaled enclosures)
    std::uint32_t begin, end;      // the node's points: slots [begin, end)
    std::uint32_t right;           // right child (the left one is the next node); kNoNode: leaf
    std::uint32_t parent;          // the parent (kNoParent for the root), | kFramed if the node has a frame
  };
  // The frame flag lives in the parent field, on the node's own cache line: a
  // separate table read on every visit cost 5-8 % of Tanemura's time on
  // uniform input, where few nodes have one.
  static constexpr std::uint32_t kFramed = 0x80000000u;
  static constexpr std::uint32_t kNoParent = 0x7FFFFFFFu;

  // A point and its id: the tree keeps its points in these, in its order
  // (a node's are slots [begin, end)), and its splits move them, so that a
  // comparison reads nothing else (indirect ids were most of the build's
  // time at 10^6).
  struct Slot {
    Point<D> x;
    std::uint32_t id;
  };

  // Builds the tree on pts[ids[k]] (distinct points, at least one).
  void build(std::span<const Point<D>> pts, const std::vector<std::uint32_t>& ids) {
    std::vector<Slot> slots;
    reserve_huge(slots, ids.size());
    for (const std::uint32_t id : ids) slots.push_back({pts[id], id});
    build(std::move(slots), pts.size());
  }
  // The same on the points of `slots` (distinct, in any order), whose ids
  // are below id_count.
  void build(std::vector<Slot>&& slots, std::size_t id_count) {
    slots_ = std::move(slots);
    std::array<double, D> mn, mx;
    mn.fill(std::numeric_limits<double>::infinity());
    mx.fill(-std::numeric_limits<double>::infinity());
    for (const Slot& p : slots_)
      for (int i = 0; i < D; ++i) mn[i] = std::min(mn[i], p.x[i]), mx[i] = std::max(mx[i], p.x[i]);
    // The origin: on an axis whose points all lie within 2^-8 of their
    // midpoint m (relative to |m|), m rounded; else 0. Then every x on that
    // axis is within a factor 2 of m and of the same sign, so x - m is exact
    // (Sterbenz's lemma). Without it, consecutive doubles far from zero
    // (half-integers near 2^52, binade-doubles) scale to enclosures as wide
    // as their spacing and nothing is pruned.
    for (int i = 0; i < D; ++i) {
      origin_[i] = 0;
      if (slots_.empty()) continue;
      const double m = mn[i] / 2 + mx[i] / 2;
      if (mx[i] - mn[i] <= std::fabs(m) * 0x1p-8) origin_[i] = m;  // mixed signs: spread >= 2 |m|
    }
    double big = 0;
    for (const Slot& p : slots_)
      for (int i = 0; i < D; ++i) big = std::max(big, std::fabs(p.x[i] - origin_[i]));
    int e = 0;
    if (big > 0) std::frexp(big, &e);
    // big * scale_ in [0.5, 1), or as close as a representable power of two
    // allows (subnormal inputs: 2^1074 overflows; 2^1000 brings them to 2^-74).
    scale_ = std::ldexp(1.0, std::clamp(-e, -1000, 1000));
    // Huge pages for the large arrays (algorithms/huge_pages.hpp).
    assign_huge(leaf_of_, id_count, kNoNode);
    nodes_.clear();
    reserve_huge(nodes_, 2 * (slots_.size() / kLeaf + 1));
    frame_of_.clear();
    reserve_huge(frame_of_, nodes_.capacity());
    frames_.clear();
    if (!slots_.empty()) build_node(0, static_cast<std::uint32_t>(slots_.size()), kNoParent);
    share_rows();
    exact_enclosures_ = true;
    for (const Slot& p : slots_)
      for (int i = 0; i < D; ++i) {
        const Iv v = scaled_iv(p.x[i], i);
        exact_enclosures_ &= v.lo == v.hi;
      }
  }

  // Whether every point's enclosure is a point (scaled_iv exact): then a
  // box's ends are coordinates of its own points, and a split of a node's
  // points by (coordinate, id) leaves the two boxes apart or touching.
  bool exact_enclosures() const { return exact_enclosures_; }

  // An enclosure of (x - origin) * scale for a coordinate x on `axis` of a
  // point given to build(): the difference is exact (see build), the product
  // exact unless it underflows.
  Iv scaled_iv(double x, int axis) const {
    const double d = x - origin_[axis];
    const double v = d * scale_;
    if (std::fabs(v) >= 0x1p-1000 || d == 0.0) return Iv::exact(v);
    return {Iv::down(v), Iv::up(v)};
  }

  // scaled_iv's point where exact_enclosures() holds, for a point given to
  // build(): there every enclosure is the one double (x - origin) * scale.
  double scaled_exact(double x, int axis) const { return (x - origin_[axis]) * scale_; }

  // The translation and the scale of scaled_iv (for tests).
  double origin(int axis) const { return origin_[axis]; }
  double scale() const { return scale_; }

  static constexpr std::uint32_t root() { return 0; }
  const Node& node(std::uint32_t k) const { return nodes_[k]; }
  static bool is_leaf(const Node& n) { return n.right == kNoNode; }
  // The axis an inner node splits: its box's widest (the first of equals).
  static int split_axis(const Node& n) {
    int axis = 0;
    for (int i = 1; i < D; ++i)
      if (n.hi[i] - n.lo[i] > n.hi[axis] - n.lo[axis]) axis = i;
    return axis;
  }
  std::uint32_t left(std::uint32_t k) const { return k + 1; }
  std::uint32_t sibling(std::uint32_t k) const {
    const std::uint32_t up = parent(k);
    return nodes_[up].right == k ? up + 1 : nodes_[up].right;
  }
  // The leaf that holds point `id` (an id given to build()).
  std::uint32_t leaf_of(std::uint32_t id) const { return leaf_of_[id]; }
  // The oriented box of node k, if its points are flat and oblique
  // (algorithms/node_frame.hpp), else null.
  const NodeFrame<D>* frame(std::uint32_t k) const {
    return nodes_[k].parent & kFramed ? &frames_[frame_of_[k]] : nullptr;
  }
  bool framed(std::uint32_t k) const { return (nodes_[k].parent & kFramed) != 0; }
  std::uint32_t parent(std::uint32_t k) const { return nodes_[k].parent & ~kFramed; }
  std::size_t frame_count() const { return frames_.size(); }
  std::uint32_t id(std::uint32_t slot) const { return slots_[slot].id; }
  const Point<D>& coords(std::uint32_t slot) const { return slots_[slot].x; }
  std::size_t node_count() const { return nodes_.size(); }
  std::size_t bytes() const {
    return nodes_.capacity() * sizeof(Node) + frame_of_.capacity() * 4 + frames_.capacity() * sizeof(NodeFrame<D>) +
           slots_.capacity() * sizeof(Slot) + leaf_of_.capacity() * 4;
  }

 private:
  // The box of the points of slots [b, e): their enclosures' extremes.
  // Where every coordinate on an axis scales to 2^-1000 or more in magnitude,
  // each enclosure there is one double, (x - origin) * scale rounded, which
  // is monotone in x: the box's ends are then the extreme coordinates'. Else
  // (the range reaches below 2^-1000: zero, underflow) each point's own.
  void set_box(Node& n, std::uint32_t b, std::uint32_t e) const {
    std::array<double, D> mn = slots_[b].x, mx = slots_[b].x;
    for (std::uint32_t s = b + 1; s < e; ++s)
      for (int i = 0; i < D; ++i) mn[i] = std::min(mn[i], slots_[s].x[i]), mx[i] = std::max(mx[i], slots_[s].x[i]);
    for (int i = 0; i < D; ++i) {
      const Iv lo = scaled_iv(mn[i], i), hi = scaled_iv(mx[i], i);
      if (lo.lo >= 0x1p-1000 || hi.hi <= -0x1p-1000) {
        n.lo[i] = lo.lo;
        n.hi[i] = hi.hi;
        continue;
      }
      for (std::uint32_t s = b; s < e; ++s) {
        const Iv v = scaled_iv(slots_[s].x[i], i);
        n.lo[i] = s == b ? v.lo : std::min(n.lo[i], v.lo);
        n.hi[i] = s == b ? v.hi : std::max(n.hi[i], v.hi);
      }
    }
  }

  // How many of c > kLeaf points go to the left child: the node's share of
  // the ceil(c / kLeaf) leaves its subtree has, half of them (rounded down) to
  // the left.  Every leaf then holds about n / leaves points: kLeaf - 1 or
  // kLeaf once n >= 20 (tests/test_kd_tree.cpp: every n up to 600, and
  // some larger).  Median splits gave n / 2^depth, anywhere in (kLeaf / 2,
  // kLeaf]: 4.9 points a leaf at n = 10^4 and 7.6 at 10^6, which made the
  // points a search examines grow with n (papers/triangulation_costs.md,
  // session 46).
  static std::uint32_t split_count(std::uint32_t c) {
    const std::uint64_t leaves = (std::uint64_t{c} + kLeaf - 1) / kLeaf;
    return static_cast<std::uint32_t>(std::uint64_t{c} * (leaves / 2) / leaves);
  }

  std::uint32_t build_node(std::uint32_t b, std::uint32_t e, std::uint32_t parent) {
    const auto k = static_cast<std::uint32_t>(nodes_.size());
    Node n{};
    n.begin = b;
    n.end = e;
    n.right = kNoNode;
    n.parent = parent;
    set_box(n, b, e);
    nodes_.push_back(n);
    frame_of_.push_back(kNoNode);
    if (e - b <= kLeaf) {
      for (std::uint32_t s = b; s < e; ++s) leaf_of_[slots_[s].id] = k;  // final: no later split moves them
      fit_frame(k);
      return k;
    }
    const int axis = split_axis(n);
    const std::uint32_t m = b + split_count(e - b);
    // A total order (coordinate, then id): the tree is the same on every run.
    std::nth_element(slots_.begin() + b, slots_.begin() + m, slots_.begin() + e,
                     [axis](const Slot& x, const Slot& y) {
                       const double u = x.x[axis], w = y.x[axis];
                       return u < w || (u == w && x.id < y.id);
                     });
    build_node(b, m, k);
    const std::uint32_t r = build_node(m, e, k);
    nodes_[k].right = r;
    // Bottom up: a node is tried only if a child is flat (uniform sets: the
    // leaves alone; a line or a plane: every node along it).
    if (frame_of_[k + 1] != kNoNode || frame_of_[r] != kNoNode) fit_frame(k);
    return k;
  }

  void gather(std::uint32_t k) {  // node k's scaled points into scratch_
    const Node& n = nodes_[k];
    scratch_.clear();
    for (std::uint32_t s = n.begin; s < n.end; ++s) {
      std::array<Iv, D> x;
      for (int i = 0; i < D; ++i) x[i] = scaled_iv(slots_[s].x[i], i);
      scratch_.push_back(x);
    }
  }

  void fit_frame(std::uint32_t k) {
    const Node& n = nodes_[k];
    gather(k);
    if (auto fr = NodeFrame<D>::fit(scratch_, n.lo, n.hi)) {
      frame_of_[k] = static_cast<std::uint32_t>(frames_.size());
      frames_.push_back(*fr);
      nodes_[k].parent |= kFramed;
    }
  }

  // Top down: a framed node under a framed parent takes the parent's rows
  // where they fit it about as well as its own (thinnest extent at most
  // twice its own), so a line or a plane of points has one set of rows
  // (rows_id) and a search projects a point once for all its nodes
  // (Tanemura's frame tests were half of its time on 2D collinear input,
  // most of it in the projections). Not where the parent's rows are tilted
  // by a point off the line (still flat by fit's rule): the child's box in
  // them was thick, and 2D collinear n = 5000 cost twice the instructions.
  void share_rows() {
    for (std::uint32_t k = 0; k < nodes_.size(); ++k) {
      if (!(nodes_[k].parent & kFramed)) continue;
      NodeFrame<D>& fr = frames_[frame_of_[k]];
      fr.rows_id = frame_of_[k];
      if (k == root() || !(nodes_[parent(k)].parent & kFramed)) continue;
      const NodeFrame<D>& up = frames_[frame_of_[parent(k)]];
      gather(k);
      if (auto made = NodeFrame<D>::make(scratch_, up.u); made && made->thinnest() <= 2 * fr.thinnest()) {
        made->rows_id = up.rows_id;
        fr = *made;
      }
    }
  }

  std::array<double, D> origin_{};
  double scale_ = 1;
  bool exact_enclosures_ = true;
  std::vector<Node> nodes_;  // preorder: a node's left child follows it
  std::vector<std::uint32_t> frame_of_;  // per node: its index in frames_, or kNoNode
  std::vector<NodeFrame<D>> frames_;
  std::vector<std::array<Iv, D>> scratch_;  // build: a node's scaled points
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> leaf_of_;
};

}  // namespace dlab
