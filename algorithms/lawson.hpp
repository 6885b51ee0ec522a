// Incremental Delaunay triangulation by flips, 2D and 3D
// (C. L. Lawson, "Software for C1 surface interpolation", 1977 -- survey
// section 2.1; Baker, Handbook of Grid Generation ch. 16.2.4; B. Joe,
// "Construction of three-dimensional Delaunay triangulations using local
// transformations", CAGD 8 (1991); Edelsbrunner & Shah, "Incremental
// topological flipping works for regular triangulations", Algorithmica 15
// (1996), which covers the perturbed, i.e. regular, setting used here).
//
// For each point p, in the order given:
//   1. locate by the visibility walk (algorithms/locate.hpp; or by a scan of
//      every live simplex, LocationScheme::scan), then split the
//      simplex found by the number of facets p lies on (orientation is never
//      perturbed, so these cases remain under `sos`):
//        2D: 1->3 (inside, or in a ghost triangle: outside the hull),
//            2->4 (on an edge, a hull edge included), duplicate (on a vertex);
//        3D: 1->4, 2->6 (on a facet), n->2n (on an edge: every tetrahedron of
//            the edge's ring, ghosts included: a hull facet or edge splits
//            like any other), duplicate; outside the hull, Joe's exterior
//            rule: p joined to every hull facet it sees strictly (the ghosts
//            on them become finite tetrahedra, new ghosts on the horizon),
//            so the hull stays convex and every later flip is a finite one
//            or the coplanar hull edge flip (flips.hpp);
//   2. flip: a queue of the simplices holding p; the facet opposite p is
//      tested with the Bowyer-Watson conflict rule (flips.hpp), so the fixed
//      point is the same (perturbed) Delaunay triangulation; a facet that
//      fails and cannot be flipped yet (3D) is kept aside and retried when the
//      stack is empty (Edelsbrunner-Shah: another flip removes it).
// Invariant of step 2: every tetrahedron without p is one of the Delaunay
// triangulation before p, and every flip removes only tetrahedra in conflict
// with p (the Bowyer-Watson cavity), so the flips end at Bowyer-Watson's
// result.  No cavity fallback: the exterior step is Joe's rule (ghosts on
// strictly visible hull facets re-starred from p: orientation tests only, no
// in-sphere), then flips; a point on a hull facet or edge is a 2->6 / n->2n
// split, then flips.  (Tests compare with Bowyer-Watson and CGAL on
// lattices, coplanar and cospherical sets, random small grids.)
// Every loop is bounded: the walk by its step bound, the flips by
// 64 n log2 n (inexact kernels) or n^2 (exact ones, where the flips provably
// end), the retry rounds by the flip bound.  An exceeded bound, a flip that
// finds an inconsistent mesh or a stuck insertion ends the run with
// Outcome::failed.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/flips.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/simplex_guard.hpp"
#include "algorithms/triangulation_result.hpp"

namespace dlab {

// Flip budget of a run of n insertions (or of flipping n vertices).
inline std::uint64_t flip_bound(std::size_t n, bool exact) {
  const double nn = static_cast<double>(n) + 2;
  const double inexact = 64.0 * nn * std::log2(nn) + 4096;
  return static_cast<std::uint64_t>(exact ? std::max(inexact, nn * nn) : inexact);
}

template <class K, int D>
class Lawson {
  static_assert(KernelFor<K, D>);
  static constexpr int V = D + 1;
  using Simplex = typename Mesh<D>::Simplex;

 public:
  explicit Lawson(const K& k = K{}) : k_(k), flipper_(k_, mesh_) {}

  // The kernel sees only the points given to run(); variants/driver.hpp may then
  // fit a static filter (tests/test_static_filter.cpp checks the promise).
  static constexpr bool kernel_sees_given_points_only = true;
  Lawson(const Lawson&) = delete;
  Lawson& operator=(const Lawson&) = delete;

  TriangulationResult run(std::span<const Point<D>> pts);

  const Mesh<D>& mesh() const { return mesh_; }
  const K& kernel() const { return k_; }
  // Point location: the walk from the last insertion (default) or a scan of
  // every live simplex (algorithms/locate.hpp); variants/driver.hpp sets it.
  void set_location(LocationScheme s) { location_ = s; }
  // mesh() stays whole after run() (tests and the fuzzer read it); otherwise
  // run() hands the mesh's memory over to the result, and the 3D mesh keeps
  // no mark array.
  void keep_mesh() { keep_mesh_ = true; }

 private:
  bool insert(std::uint32_t i);
  bool restore(std::uint32_t i);
  bool connect_exterior(std::uint32_t i, std::uint32_t start);  // 3D, p outside the hull
  void split14(std::uint32_t s, std::uint32_t i);
  bool split(const std::uint32_t* old, int n_old, const std::uint32_t* carrier, int n_carrier, std::uint32_t i,
             std::uint64_t& counter);
  void fail(std::string msg) { message_ = std::move(msg); }

  K k_;
  Mesh<D> mesh_;
  Flipper<K, D> flipper_;
  FlipMesh<D> fm_;
  const Point<D>* pts_ = nullptr;
  std::vector<std::uint32_t> merged_, stack_, aside_, ring_, created_;
  std::vector<Simplex> news_;
  Restar<D> restar_;
  std::vector<std::uint32_t> cavity_;
  std::vector<BoundaryRecord<D>> records_;
  std::uint64_t ins_ext_ = 0, ext_facets_ = 0, ins_on_hull_ = 0;
  std::uint32_t last_ = 0;
  std::uint64_t flip_budget_ = 0;
  WalkRng rng_;
  LocationScheme location_ = LocationScheme::walk;
  bool keep_mesh_ = false;
  std::string message_;
  std::uint64_t walk_steps_ = 0, scan_tests_ = 0, duplicates_ = 0, ins_1_ = 0, ins_2_ = 0, ins_n_ = 0,
                retries_ = 0;
};

// Replaces `old` by the star of p: in every old simplex, p substituted for
// each vertex of p's carrier (the simplex p is inside, the facet or edge p
// lies on; for a point outside the hull, the ghost simplex whose hull facet
// it sees, ghost vertex included).
template <class K, int D>
bool Lawson<K, D>::split(const std::uint32_t* old, int n_old, const std::uint32_t* carrier, int n_carrier,
                         std::uint32_t i, std::uint64_t& counter) {
  news_.clear();
  for (int a = 0; a < n_old; ++a)
    for (int j = 0; j < V; ++j) {
      const std::uint32_t w = mesh_.vertex(old[a], j);
      if (std::find(carrier, carrier + n_carrier, w) == carrier + n_carrier) continue;
      news_.push_back(FlipMesh<D>::substitute(mesh_, old[a], j, i));
      if constexpr (!K::exact) {
        const Simplex& v = news_.back();
        if (v[D] != kGhost) {
          Sign o;
          if constexpr (D == 2)
            o = orient_pos(k_, pts_[v[0]], pts_[v[1]], pts_[v[2]]);
          else
            o = orient_pos(k_, pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[v[3]]);
          if (o != Sign::positive) {
            fail("point " + std::to_string(i) + ": a simplex of its star is not positively oriented");
            return false;
          }
        }
      }
    }
  if (!fm_.replace(mesh_, old, n_old, news_.data(), static_cast<int>(news_.size()), created_)) {
    fail("point " + std::to_string(i) + ": the split left a facet unmatched");
    return false;
  }
  ++counter;
  return true;
}

// 3D 1->4 with its neighbours wired directly: new tetrahedron k is s with
// vertex k replaced by p (s's slots, positive since p is inside s); its facet
// opposite p is s's facet k, and its facet opposite vertex j is shared with
// tetrahedron j's facet opposite vertex k.
template <class K, int D>
void Lawson<K, D>::split14(std::uint32_t s, std::uint32_t i) {
  static_assert(D == 3);
  const Simplex v = mesh_.simplex(s);
  std::uint32_t out[4];
  for (int k = 0; k < 4; ++k) out[k] = mesh_.neighbour(s, k);
  mesh_.destroy(s);
  created_.resize(4);
  for (int k = 0; k < 4; ++k) {
    Simplex w = v;
    w[k] = i;
    created_[k] = mesh_.create(w);
  }
  for (int k = 0; k < 4; ++k) {
    mesh_.link(Mesh<D>::encode(created_[k], k), out[k]);
    for (int j = k + 1; j < 4; ++j)
      mesh_.link(Mesh<D>::encode(created_[k], j), Mesh<D>::encode(created_[j], k));
  }
  ++ins_1_;
}

template <class K, int D>
bool Lawson<K, D>::insert(std::uint32_t i) {
  const Point<D>& p = pts_[i];
  const std::uint64_t bound = 4ull * mesh_.slots() + 1000;
  const bool from_ghost = mesh_.is_ghost(last_);
  const Located loc = locate<K, D>(location_, k_, mesh_, pts_, last_, p, bound, rng_);
  walk_steps_ += loc.steps;
  scan_tests_ += loc.tests;
  if (loc.end == Located::End::not_found) {
    fail("the scan found no simplex containing " + std::string("point ") + std::to_string(i) +
         (K::exact ? " (a bug: the kernel is exact)" : " (inconsistent orientations)"));
    return false;
  }
  if (loc.end == Located::End::step_bound) {
    fail("point location exceeded its bound of " + std::to_string(bound) + " steps at point " +
         std::to_string(i) + (K::exact ? " (a bug: the kernel is exact)" : " (inconsistent orientations)"));
    return false;
  }
  const std::uint32_t s = loc.simplex;
  if constexpr (D == 3) {
    if (loc.end == Located::End::outside) {  // Joe's exterior rule, then flips
      if (!connect_exterior(i, s)) return false;
      merged_[i] = i;
      return restore(i);
    }
  }
  if (loc.end == Located::End::outside) {
    // 2D: p strictly beyond the hull edge of ghost s: 1 -> 3 split of the
    // ghost, then 2-2 flips (a ghost triangle's flip is checked by the finite
    // triangle it creates, which fixes the new edge in the plane).
    const Simplex all = mesh_.simplex(s);
    if (!split(&s, 1, all.data(), V, i, ins_1_)) return false;
  } else {
    // With exact signs the walk's count is the number of facets p lies on:
    // each facet it crossed into s has p strictly beyond, save the one a walk
    // from a ghost enters by, which it tested only for "strictly beyond".
    const bool none_zero = K::exact && loc.zeros == 0 && !(location_ == LocationScheme::walk && from_ghost);
    int zeros[V], nz = 0;
    if (!none_zero)
      for (int j = 0; j < V; ++j)
        if (orient_with<K, D>(k_, mesh_, pts_, s, j, p) == Sign::zero) zeros[nz++] = j;
    if (nz >= D) {  // on a vertex: a duplicate
      for (int j = 0; j < V; ++j) {
        const std::uint32_t w = mesh_.vertex(s, j);
        if (pts_[w] == p) {
          merged_[i] = w;
          ++duplicates_;
          last_ = s;
          return true;
        }
      }
      fail("point " + std::to_string(i) + " lies on " + std::to_string(nz) +
           " facet hyperplanes of a simplex but on none of its vertices (inconsistent orientations)");
      return false;
    }
    if (nz == 0) {
      if constexpr (D == 3) {
        split14(s, i);
      } else {
        const Simplex all = mesh_.simplex(s);
        if (!split(&s, 1, all.data(), V, i, ins_1_)) return false;
      }
    } else if (nz == 1) {  // on a facet: the simplex and its neighbour across it
      const std::uint32_t old[2] = {s, Mesh<D>::simplex_of(mesh_.neighbour(s, zeros[0]))};
      std::uint32_t facet[D];
      int nf = 0;
      for (int j = 0; j < V; ++j)
        if (j != zeros[0]) facet[nf++] = mesh_.vertex(s, j);
      if (mesh_.is_ghost(old[1])) ++ins_on_hull_;
      if (!split(old, 2, facet, D, i, ins_2_)) return false;
    } else {  // 3D, on an edge: the edge's ring
      std::uint32_t e[2];
      int ne = 0;
      for (int j = 0; j < V; ++j)
        if (j != zeros[0] && j != zeros[1]) e[ne++] = mesh_.vertex(s, j);
      if (!FlipMesh<D>::edge_ring(mesh_, s, e[0], e[1], ring_, mesh_.slots())) {
        fail("point " + std::to_string(i) + ": the ring of the edge it lies on is corrupt");
        return false;
      }
      const std::vector<std::uint32_t> ring = ring_;
      if (std::any_of(ring.begin(), ring.end(), [&](std::uint32_t r) { return mesh_.is_ghost(r); })) ++ins_on_hull_;
      if (!split(ring.data(), static_cast<int>(ring.size()), e, 2, i, ins_n_)) return false;
    }
  }
  merged_[i] = i;
  last_ = created_.front();
  return restore(i);
}

// Joe 1991's exterior rule on the ghost-closed mesh: p is joined to every
// hull facet it sees strictly (the ghost on that facet becomes the finite
// tetrahedron facet + p), and each horizon edge e gets the ghost e + p.  The
// strictly visible ghosts form a connected set (the facets of a convex
// polytope seen from an outside point), searched from the ghost the walk
// ended in; the change is the re-starring of that set (cavity.hpp), so every
// new tetrahedron keeps its ghost's orientation.  Facets coplanar with p are
// not visible: their hull faces are repaired by the coplanar hull flips
// (flips.hpp), like every other facet, by the flips that follow.
template <class K, int D>
bool Lawson<K, D>::connect_exterior(std::uint32_t i, std::uint32_t start) {
  static_assert(D == 3);
  // The marks are TopBitMarks' (the mesh keeps no mark array): in = the
  // visible ghosts, out = their neighbours found not visible; every neighbour
  // word is read through code(), and the bits go before the re-star.
  constexpr std::uint32_t in = TopBitMarks::kIn, out = TopBitMarks::kOut;
  const Point<D>& p = pts_[i];
  cavity_.clear();
  records_.clear();
  TopBitMarks::set_mark(mesh_, start, in);
  cavity_.push_back(start);
  for (std::size_t c = 0; c < cavity_.size(); ++c) {  // each ghost enters once: bounded
    const std::uint32_t s = cavity_[c];
    for (int f = 0; f < V; ++f) {
      const std::uint32_t enc = TopBitMarks::code(mesh_.neighbour(s, f));
      const std::uint32_t t = Mesh<D>::simplex_of(enc);
      const std::uint32_t m = TopBitMarks::mark(mesh_, t);
      if (m == in) continue;
      if (m != out) {
        if (f != D && mesh_.is_ghost(t) && orient_with<K, D>(k_, mesh_, pts_, t, D, p) == Sign::positive) {
          TopBitMarks::set_mark(mesh_, t, in);
          cavity_.push_back(t);
          continue;
        }
        TopBitMarks::set_mark(mesh_, t, out);
      }
      records_.push_back(boundary_record<D>(mesh_, s, f, i, enc));
    }
  }
  for (std::uint32_t s : cavity_) TopBitMarks::unmark(mesh_, s, in);
  for (const BoundaryRecord<D>& r : records_) TopBitMarks::unmark(mesh_, Mesh<D>::simplex_of(r.outside), out);
  std::string err;
  const std::uint32_t first = restar_.star(mesh_, cavity_, records_, err, !K::exact);
  if (!err.empty()) {
    fail("point " + std::to_string(i) + ": joining it to the hull facets it sees: " + err);
    return false;
  }
  created_.assign(restar_.created().begin(), restar_.created().end());
  ++ins_ext_;
  ext_facets_ += cavity_.size();
  last_ = first;
  return true;
}

template <class K, int D>
bool Lawson<K, D>::restore(std::uint32_t i) {
  using R = typename Flipper<K, D>::Result;
  stack_.assign(created_.begin(), created_.end());
  aside_.clear();
  // Each round drains the queue (facets that cannot be flipped yet go aside),
  // then re-tests the facets put aside; a round flips at least once or ends.
  for (std::uint64_t round = 0;; ++round) {
    bool flipped_any = false;
    // First in, first out (breadth first, in creation order): fewer facets are
    // found unflippable than in last-in-first-out order (4.4 against 6.5 per
    // point on uniform 3D points), with the same flips.
    for (std::size_t head = 0; head < stack_.size(); ++head) {
      const std::uint32_t s = stack_[head];
      if (!mesh_.alive(s)) continue;
      const int f = FlipMesh<D>::slot_of(mesh_, s, i);
      if (f < 0) continue;  // the slot was reused by a simplex away from p
      const R r = flipper_.try_flip(s, f);
      if (r == R::delaunay) continue;
      if (r == R::unflippable) {
        aside_.push_back(s);
        continue;
      }
      if (r == R::broken) {
        fail("point " + std::to_string(i) + ": a flip found an inconsistent mesh");
        return false;
      }
      flipped_any = true;
      if (flipper_.counts.total() > flip_budget_) {
        fail("flip count exceeded its bound of " + std::to_string(flip_budget_) + " at point " +
             std::to_string(i) + (K::exact ? " (a bug: the kernel is exact)" : " (inconsistent predicates)"));
        return false;
      }
      for (std::uint32_t c : flipper_.created()) stack_.push_back(c);
      last_ = flipper_.created().front();
    }
    stack_.clear();
    if (aside_.empty()) return true;
    if (round > 0 && !flipped_any) {
      fail("point " + std::to_string(i) + ": flips are stuck (" + std::to_string(aside_.size()) +
           " non-Delaunay facets, none flippable)" + (K::exact ? " (unexpected with an exact kernel)" : ""));
      return false;
    }
    ++retries_;
    stack_.swap(aside_);
    aside_.clear();
  }
}

template <class K, int D>
TriangulationResult Lawson<K, D>::run(std::span<const Point<D>> pts) {
  TriangulationResult res;
  pts_ = pts.data();
  flipper_.set_points(pts_);
  const std::size_t n = pts.size();
  merged_.assign(n, kNotProcessed);
  mesh_.clear();
  if constexpr (D == 3) {  // connect_exterior's marks are TopBitMarks'
    if (!keep_mesh_) mesh_.without_marks();
    mesh_.limit_slots(TopBitMarks::kMaxSlots);
  }
  flip_budget_ = flip_bound(n, K::exact);

  const InitialSimplex<D> init = initial_simplex_or_outcome<D>(k_, pts, res);
  if (!init.found) return res;
  mesh_.reserve(D == 2 ? 2 * n + 16 : (27 * n) / 4 + 64);
  last_ = build_initial_mesh<D>(mesh_, init.ids);
  for (std::uint32_t id : init.ids) merged_[id] = id;

  for (std::uint32_t i = 0; i < n; ++i) {
    if (merged_[i] != kNotProcessed) continue;
    if (!insert(i)) {
      res.outcome = RunOutcome::failed;
      res.message = message_;
      break;
    }
    if (!mesh_.alive(last_)) last_ = created_.empty() ? 0 : created_.front();
  }

  if (res.outcome == RunOutcome::ok) {
    if constexpr (!K::exact) {
      std::vector<bool> present(n, false);
      mesh_.for_each_finite([&](std::uint32_t s) {
        for (int j = 0; j < V; ++j) present[mesh_.vertex(s, j)] = true;
      });
      for (std::uint32_t i = 0; i < n; ++i)
        if (merged_[i] == i && !present[i]) {
          res.outcome = RunOutcome::failed;
          res.message = "vertex " + std::to_string(i) + " was lost";
          break;
        }
    }
  }
  const FlipCounts& c = flipper_.counts;
  if constexpr (D == 2) {
    res.counters = {{"walk_steps", walk_steps_}, {"scan_tests", scan_tests_}, {"insert_1_3", ins_1_},
                    {"insert_2_4", ins_2_},      {"flips_2_2", c.f22},         {"duplicates", duplicates_}};
  } else {
    // insert_1_4 / 2_6 / n_2n: splits (a point on a hull facet or edge is
    // also counted in insert_on_hull); insert_exterior: points outside the
    // hull (Joe's rule), exterior_facets: hull facets they were joined to;
    // hull_edge_removals: coplanar hull edge flips with more than two finite
    // tetrahedra below, each counted in flips_2_3 / flips_4_4 as the 2-3
    // flips and the 4-4 flip it is made of.
    res.counters = {{"walk_steps", walk_steps_},
                    {"scan_tests", scan_tests_},
                    {"insert_1_4", ins_1_},
                    {"insert_2_6", ins_2_},
                    {"insert_n_2n", ins_n_},
                    {"insert_exterior", ins_ext_},
                    {"exterior_facets", ext_facets_},
                    {"insert_on_hull", ins_on_hull_},
                    {"flips_2_3", c.f23},
                    {"flips_3_2", c.f32},
                    {"flips_4_4", c.f44},
                    {"hull_edge_removals", c.hull_removals},
                    {"duplicates", duplicates_}};
  }
  res.counters.push_back({"flips_total", c.total()});
  res.counters.push_back({"unflippable_tests", c.unflippable});
  res.counters.push_back({"retry_rounds", retries_});
  res.counters.push_back({"mesh_slots", mesh_.slots()});
  res.counters.push_back({"mesh_bytes_reserved", mesh_.bytes_reserved()});
  // Last, as it hands the mesh's memory over to the result (mesh() is then
  // empty), unless the mesh is kept.
  if (res.outcome == RunOutcome::ok)
    res.simplices = keep_mesh_ ? Mesh<D>(mesh_).take_finite_simplices() : mesh_.take_finite_simplices();
  res.merged_into = std::move(merged_);  // after the mesh is gone: not part of the peak
  return res;
}

}  // namespace dlab
