// George's corrected-cavity point insertion, 2D and 3D
// (P. L. George, "Improvements on Delaunay-based three-dimensional automatic
// mesh generator", Finite Elements in Analysis and Design 25 (1997) 297-317,
// sections 2.2-2.4).  A variant of Bowyer–Watson (algorithms/bowyer_watson.hpp)
// whose cavity step is replaced by section 2.3's steps (1)-(7):
//
//   (1) base: the element(s) containing P (the walk of locate.hpp, then every
//       element whose closure holds P, reached across facets on which P lies:
//       two elements for P on a facet, the shell for P on an edge);
//   (2) approximate cavity: grown by adjacency from the base with the FLOATING
//       circumsphere test |P - c|^2 < r^2 on each element's centre and radius
//       in doubles (section 2.4, which keeps them in tables; here they are
//       recomputed per test, with the same answers: algorithms/floating_sphere.hpp);
//   (3) connectivity: elements not connected to the base through the cavity
//       are removed;
//   (4) volumes: for each boundary face F_j the simplex K_j = (F_j, P) has its
//       volume's sign computed EXACTLY (the kernel's orientation; `integer` is
//       the paper's choice).  Det > 0: fine; Det < 0: remove the cavity element
//       with face F_j; Det = 0: add the element behind F_j;
//   (5) if anything changed, back to (3);
//   (6) nv (distinct vertices of the F_j) == ns (distinct vertices of the
//       cavity), i.e. no vertex enclosed; otherwise remove a cavity element,
//       not in the base, that has an enclosed vertex, and back to (3);
//   (7) re-star: join P to every F_j (algorithms/cavity.hpp, shared with
//       Bowyer–Watson).
// The result is always a valid triangulation (every orientation is exact), not
// necessarily Delaunay: counters report the corrections, and the registry
// (variants/george_*.cpp) counts the locally non-Delaunay facets exactly.
//
// Where the paper is ambiguous, and what is done here:
//  - Connectivity (3).  The paper checks "each element in this set has at least
//    one neighbor in the set", which does not make a set connected (two
//    separate pairs pass).  Here: reachability from the base through cavity
//    elements (implies the paper's condition).
//  - Order of changes (4).  The paper loops j = 1..p over one snapshot.  Here the
//    faces are visited in order and each change is applied at once; a face
//    whose cavity element was already removed, or whose outer element was
//    already added, is skipped (it is no longer a boundary face).
//  - Termination.  The paper does not bound the loop (3)-(6): an element added
//    for a zero volume might be removed again and re-added forever.  Here an
//    element removed during one insertion is never added again during it
//    (a zero volume against such an element removes the cavity element
//    instead), so each element changes state at most twice and the loop ends.
//  - The base is never removed: P lies in its closure, so every face of the
//    base alone sees P with positive volume; the base is a valid cavity and the
//    corrections can always fall back to it.  A rule that would remove a base
//    element is reported as an internal failure (impossible with an exact
//    orientation kernel).
//  - Step 6's "K is any possible simplex": the most recently added cavity
//    element (the farthest from the base in the search order) holding the first
//    enclosed vertex found.
//  - Zero volume (4) against a ghost (a hull facet F: P coplanar with the hull
//    facet, outside it, since otherwise the ghost is in the base): the element
//    behind F is the ghost of a hull facet; adding it would put P on the hull
//    in the plane of F and fold the new hull facets over F, so the cavity
//    element with face F is removed instead (counter zero_volume_not_addable).
//  - The hull.  The paper has no hull: its enclosing box T0 contains every
//    point.  By default here, a ghost vertex closes the mesh (mesh.hpp), and a
//    ghost element's "circumsphere" is the open half-space beyond its hull
//    facet, so its floating sphere test is replaced by the exact orientation
//    test (P strictly beyond the hull facet); the coplanar in-circle refinement
//    of the exact hull rule (oriented.hpp) is used only with exact_sphere.  For
//    P outside the hull, the base is every ghost whose hull facet P sees
//    strictly (beneath-beyond; these are connected).  A boundary face of a
//    ghost element that contains the ghost vertex gives a new ghost; its
//    "volume" is positive iff the hull facet of the ghost behind it is strictly
//    hidden from P, or P is in that facet's plane (line) strictly across the
//    ridge from it; otherwise the face is negative.  With exact_sphere the
//    cavity is exactly Bowyer–Watson's (the same conflict tests), and the result
//    is the Delaunay triangulation (CGAL's with the sos policy).
//  - enclosing_box: the paper's box (george_box.hpp), removed at the end with
//    every element that has a box corner; what is then missing from the convex
//    hull is reported by the registry.
#pragma once
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/cavity_histogram.hpp"
#include "algorithms/floating_sphere.hpp"
#include "algorithms/george_box.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/merge_record.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/triangulation_result.hpp"

namespace dlab {

struct GeorgeOptions {
  bool exact_sphere = false;   // exact (kernel) circumsphere test instead of the floating one
  bool enclosing_box = false;  // the paper's enclosing box instead of the ghost vertex
};

template <class K, int D>
class George {
  static_assert(KernelFor<K, D>);
  static constexpr int V = D + 1;

 public:
  explicit George(const K& k = K{}, GeorgeOptions o = {}) : k_(k), opt_(o) {}

  // The kernel sees only the points given to run() (and, for George's box, its
  // corners: added_points); variants/driver.hpp may then fit a static filter
  // (tests/test_static_filter.cpp checks the promise).
  static constexpr bool kernel_sees_given_points_only = true;

  // The simplices are taken out of the mesh (Mesh::take_finite_simplices),
  // which is empty afterwards.
  TriangulationResult run(std::span<const Point<D>> pts);

  const Mesh<D>& mesh() const { return mesh_; }
  const K& kernel() const { return k_; }

 private:
  enum class Face { positive, negative, zero };
  bool insert(std::uint32_t i);
  bool correct(std::uint32_t i, std::size_t nbase);
  bool approx_conflict(std::uint32_t t, const Point<D>& p);
  bool other_conflict(std::uint32_t t, const Point<D>& p) const;
  Face face_volume(const BoundaryRecord<D>& r, const Point<D>& p) const;
  bool first_round_positive(std::uint32_t i);
  // base_ and in_ are consecutive stamps: one unsigned comparison.
  bool member(std::uint32_t t) const { return mesh_.mark(t) - base_ < 2; }
  void exclude(std::uint32_t t) { mesh_.set_mark(t, excl_); }
  void fail(std::string msg) { message_ = std::move(msg); }

  K k_;
  GeorgeOptions opt_;
  Mesh<D> mesh_;
  Restar<D> restar_;
  std::vector<Point<D>> box_pts_;  // input + box corners (enclosing_box)
  const Point<D>* pts_ = nullptr;
  std::size_t npts_ = 0;            // points including box corners
  MergeRecord<D> merged_;  // which vertex each point became
  std::vector<std::uint32_t> cavity_, queue_;
  std::vector<std::uint32_t> faces_;  // step 2's boundary faces, encoded (s, f), in step 3's order
  std::vector<BoundaryRecord<D>> records_;
  std::vector<std::uint32_t> vmark_;    // per vertex (ghost last): step 6 stamps
  std::uint32_t vstamp_ = 0;
  std::uint32_t last_ = 0;
  std::uint32_t stamp_ = 0, base_ = 0, in_ = 0, out_ = 0, excl_ = 0, reached_ = 0;
  WalkRng rng_;
  std::string message_;
  // counters
  std::uint64_t walk_steps_ = 0, approx_total_ = 0, cavity_total_ = 0, cavity_max_ = 0, created_ = 0,
                duplicates_ = 0, float_tests_ = 0, removed_visibility_ = 0, added_zero_ = 0,
                zero_not_addable_ = 0, removed_connectivity_ = 0, removed_enclosed_ = 0,
                corrected_insertions_ = 0, rounds_ = 0, base_total_ = 0, box_removed_ = 0;
  CavityHistogram cavity_sizes_;
};

template <class K, int D>
bool George<K, D>::approx_conflict(std::uint32_t t, const Point<D>& p) {
  const std::uint32_t* w = mesh_.vertices(t);
  if (w[D] != kGhost && !opt_.exact_sphere) [[likely]] {
    ++float_tests_;
    std::array<const Point<D>*, V> v;
    for (int j = 0; j < V; ++j) v[j] = &pts_[w[j]];
    return inside_floating_sphere<D>(v, p);
  }
  return other_conflict(t, p);
}

// Ghosts, and the exact sphere test.
template <class K, int D>
bool George<K, D>::other_conflict(std::uint32_t t, const Point<D>& p) const {
  const std::uint32_t* w = mesh_.vertices(t);
  if (w[D] == kGhost) {
    if (!opt_.exact_sphere) return orient_with<K, D>(k_, mesh_, pts_, t, D, p) == Sign::positive;
    if constexpr (D == 2) {
      return ghost_conflict(k_, pts_[w[0]], pts_[w[1]], p);
    } else {
      const std::uint32_t enc = mesh_.neighbour(t, 3);
      const std::uint32_t d = mesh_.vertex(Mesh<3>::simplex_of(enc), Mesh<3>::facet_of(enc));
      return ghost_conflict(k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], pts_[d], p);
    }
  }
  if constexpr (D == 2)
    return inside_pos(k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], p) == Sign::positive;
  else
    return inside_pos(k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], pts_[w[3]], p) == Sign::positive;
}

// The sign of the new simplex r: a boundary face of the cavity joined to p,
// which sits in slot r.slot; r.outside is the encoded facet across the face.
// See the header for ghost faces.
template <class K, int D>
typename George<K, D>::Face George<K, D>::face_volume(const BoundaryRecord<D>& r, const Point<D>& p) const {
  auto as_face = [](Sign o) { return o == Sign::positive ? Face::positive : o == Sign::negative ? Face::negative : Face::zero; };
  if (r.v[D] != kGhost) {  // a finite new simplex: its vertices are r.v (p is pts_[r.v[r.slot]])
    if constexpr (D == 2)
      return as_face(orient_pos(k_, pts_[r.v[0]], pts_[r.v[1]], pts_[r.v[2]]));
    else
      return as_face(orient_pos(k_, pts_[r.v[0]], pts_[r.v[1]], pts_[r.v[2]], pts_[r.v[3]]));
  }
  // A new ghost (p, ridge, ghost): u is the ghost behind the face.
  const int f = r.slot;
  const std::uint32_t u = Mesh<D>::simplex_of(r.outside);
  const Sign o = orient_with<K, D>(k_, mesh_, pts_, u, D, p);
  if (o == Sign::positive) return Face::negative;  // u's hull facet seen: the new hull would be reflex
  if (o == Sign::negative) return Face::positive;
  // p in the plane (line) of u's hull facet: valid iff strictly across the ridge from it.
  const int fu = Mesh<D>::facet_of(r.outside);  // u's vertex not on the ridge (u's slot D holds the ghost)
  const Point<D>& y = pts_[mesh_.vertex(u, fu)];
  if constexpr (D == 2) {
    const Point2& b = pts_[r.v[1 - f]];  // the ridge is one vertex
    return strictly_between(p, b, y) ? Face::positive : Face::negative;
  } else {
    std::uint32_t e[2];
    int n = 0;
    for (int i = 0; i < D; ++i)
      if (i != f) e[n++] = r.v[i];
    const std::uint32_t w = mesh_.neighbour(u, D);
    const Point3& z = pts_[mesh_.vertex(Mesh<3>::simplex_of(w), Mesh<3>::facet_of(w))];
    const Sign sp = k_.orient3d(pts_[e[0]], pts_[e[1]], z, p);
    const Sign sy = k_.orient3d(pts_[e[0]], pts_[e[1]], z, y);
    return sp != Sign::zero && sp == -sy ? Face::positive : Face::negative;
  }
}

// Step 4 on step 2's boundary faces before anything changed: true, with
// records_ the new simplices, iff every face is positive.
template <class K, int D>
bool George<K, D>::first_round_positive(std::uint32_t i) {
  const Point<D>& p = pts_[i];
  records_.clear();
  for (std::uint32_t e : faces_) {
    const std::uint32_t s = Mesh<D>::simplex_of(e);
    const int f = Mesh<D>::facet_of(e);
    const BoundaryRecord<D> r = boundary_record<D>(mesh_, s, f, i, mesh_.neighbour(s, f));
    if (face_volume(r, p) != Face::positive) return false;
    records_.push_back(r);
  }
  return true;
}

template <class K, int D>
bool George<K, D>::correct(std::uint32_t i, std::size_t nbase) {
  const Point<D>& p = pts_[i];
  bool corrected = false;
  const std::uint64_t bound = 2ull * mesh_.slots() + 16;
  for (std::uint64_t round = 0;; ++round) {
    if (round > bound) {
      fail("point " + std::to_string(i) + ": cavity correction exceeded its bound of " + std::to_string(bound) +
           " rounds (a bug)");
      return false;
    }
    ++rounds_;
    // (3) connectivity from the base (cavity_'s first nbase elements).  Step 2
    // grew the cavity by adjacency from the base, so it is connected in the
    // first round; after a removal, the members reached from the base are
    // marked reached_ during the search, those left at in_ are excluded, and
    // the reached ones are in_ again.
    if (round > 0) {
      queue_.assign(cavity_.begin(), cavity_.begin() + static_cast<std::ptrdiff_t>(nbase));
      for (std::size_t q = 0; q < queue_.size(); ++q)
        for (int f = 0; f < V; ++f) {
          const std::uint32_t t = Mesh<D>::simplex_of(mesh_.neighbour(queue_[q], f));
          if (mesh_.mark(t) == in_) {
            mesh_.set_mark(t, reached_);
            queue_.push_back(t);
          }
        }
      const bool unreached = queue_.size() != cavity_.size();
      if (unreached)
        for (std::uint32_t t : cavity_)
          if (mesh_.mark(t) == in_) {
            exclude(t);
            ++removed_connectivity_;
          }
      for (std::size_t q = nbase; q < queue_.size(); ++q) mesh_.set_mark(queue_[q], in_);
      if (unreached) {
        cavity_.erase(std::remove_if(cavity_.begin() + static_cast<std::ptrdiff_t>(nbase), cavity_.end(),
                                     [&](std::uint32_t t) { return !member(t); }),
                      cavity_.end());
        corrected = true;
      }
    }
    // (3) boundary faces, (4) their volumes.  In the first round, step 2's
    // faces are these, in this order; if they are all positive nothing
    // changes, and otherwise the scan below starts over from the same state.
    if (round > 0 || !first_round_positive(i)) {
      bool changed = false;
      records_.clear();
      for (std::size_t c = 0, ncav = cavity_.size(); c < ncav; ++c) {
        const std::uint32_t s = cavity_[c];
        for (int f = 0; f < V; ++f) {
          if (!member(s)) break;  // removed while visiting its faces
          const std::uint32_t enc = mesh_.neighbour(s, f);
          const std::uint32_t t = Mesh<D>::simplex_of(enc);
          if (member(t)) continue;
          const BoundaryRecord<D> r = boundary_record<D>(mesh_, s, f, i, enc);
          const Face vol = face_volume(r, p);
          if (vol == Face::positive) {
            records_.push_back(r);
            continue;
          }
          changed = true;
          if (vol == Face::zero && !mesh_.is_ghost(t) && mesh_.mark(t) != excl_) {
            mesh_.set_mark(t, in_);  // the element behind the face
            cavity_.push_back(t);
            ++added_zero_;
            continue;
          }
          if (vol == Face::zero) ++zero_not_addable_;
          if (mesh_.mark(s) == base_) {
            fail("point " + std::to_string(i) + ": the correction would remove a base element (" +
                 (K::exact ? "a bug: the kernel is exact)" : "inconsistent orientations)"));
            return false;
          }
          exclude(s);
          ++removed_visibility_;
        }
      }
      if (changed) {
        cavity_.erase(std::remove_if(cavity_.begin() + static_cast<std::ptrdiff_t>(nbase), cavity_.end(),
                                     [&](std::uint32_t t) { return !member(t); }),
                      cavity_.end());
        corrected = true;
        continue;  // (5)
      }
    }
    // (6) nv == ns: no cavity vertex off the boundary faces.
    if (vmark_.size() < npts_ + 1) vmark_.resize(npts_ + 1, 0);
    if (vstamp_ >= 0xFFFFFFF0u) {
      std::fill(vmark_.begin(), vmark_.end(), 0u);
      vstamp_ = 0;
    }
    vstamp_ += 2;
    const std::uint32_t on_boundary = vstamp_;
    auto vid = [&](std::uint32_t v) { return v == kGhost ? npts_ : std::size_t(v); };
    for (const BoundaryRecord<D>& r : records_)
      for (int j = 0; j < V; ++j)
        if (j != r.slot) vmark_[vid(r.v[j])] = on_boundary;
    std::uint32_t enclosed = kNoNeighbour;
    for (std::uint32_t s : cavity_) {
      for (int j = 0; j < V && enclosed == kNoNeighbour; ++j)
        if (vmark_[vid(mesh_.vertex(s, j))] != on_boundary) enclosed = mesh_.vertex(s, j);
      if (enclosed != kNoNeighbour) break;
    }
    if (enclosed == kNoNeighbour) break;  // (7)
    bool removed = false;
    for (std::size_t c = cavity_.size(); c-- > nbase && !removed;) {
      const std::uint32_t s = cavity_[c];
      for (int j = 0; j < V; ++j)
        if (mesh_.vertex(s, j) == enclosed) {
          exclude(s);
          cavity_.erase(cavity_.begin() + static_cast<std::ptrdiff_t>(c));
          removed = true;
          break;
        }
    }
    if (!removed) {
      fail("point " + std::to_string(i) + ": an enclosed vertex belongs to base elements only (" +
           (K::exact ? "a bug: the kernel is exact)" : "inconsistent orientations)"));
      return false;
    }
    ++removed_enclosed_;
    corrected = true;
  }
  if (corrected) ++corrected_insertions_;
  return true;
}

template <class K, int D>
bool George<K, D>::insert(std::uint32_t i) {
  const Point<D>& p = pts_[i];
  const std::uint64_t bound = 4ull * mesh_.slots() + 1000;
  const Located loc = visibility_walk<K, D>(k_, mesh_, pts_, last_, p, bound, rng_);
  walk_steps_ += loc.steps;
  if (loc.end == Located::End::step_bound) {
    fail("point location exceeded its bound of " + std::to_string(bound) + " steps at point " +
         std::to_string(i));
    return false;
  }
  if (loc.end == Located::End::inside && loc.zeros > 0) {
    for (int j = 0; j < V; ++j) {
      const std::uint32_t w = mesh_.vertex(loc.simplex, j);
      if (w != kGhost && pts_[w] == p) {
        merged_.merge(i, w);
        ++duplicates_;
        last_ = loc.simplex;
        return true;
      }
    }
  }
  if (stamp_ >= 0xFFFFFFF0u) {
    for (std::uint32_t s = 0; s < mesh_.slots(); ++s) mesh_.set_mark(s, 0);
    stamp_ = 0;
  }
  stamp_ += 5;
  base_ = stamp_;
  in_ = stamp_ + 1;  // consecutive: member()
  out_ = stamp_ + 2;
  excl_ = stamp_ + 3;
  reached_ = stamp_ + 4;  // step 3's search only

  // (1) the base.  The walk has taken the orientation of every facet of the
  // simplex it ends in: with no zero among them, that simplex alone holds p.
  cavity_.clear();
  mesh_.set_mark(loc.simplex, base_);
  cavity_.push_back(loc.simplex);
  const bool alone = loc.end == Located::End::inside && loc.zeros == 0;
  for (std::size_t c = 0; c < cavity_.size() && !alone; ++c) {
    const std::uint32_t s = cavity_[c];
    const bool ghost = mesh_.is_ghost(s);
    if (loc.end == Located::End::inside && ghost) continue;
    for (int f = 0; f < V; ++f) {
      const std::uint32_t t = Mesh<D>::simplex_of(mesh_.neighbour(s, f));
      if (mesh_.mark(t) == base_) continue;
      bool in_base;
      if (loc.end == Located::End::inside)  // p on facet f of s: the element behind holds p too
        in_base = orient_with<K, D>(k_, mesh_, pts_, s, f, p) == Sign::zero;
      else  // p outside: ghosts whose hull facet p sees strictly
        in_base = f != D && orient_with<K, D>(k_, mesh_, pts_, t, D, p) == Sign::positive;
      if (in_base) {
        mesh_.set_mark(t, base_);
        cavity_.push_back(t);
      }
    }
  }
  const std::size_t nbase = cavity_.size();
  base_total_ += nbase;

  // (2) the approximate cavity, and its boundary faces.
  faces_.clear();
  for (std::size_t c = 0; c < cavity_.size(); ++c) {
    const std::uint32_t s = cavity_[c];
    for (int f = 0; f < V; ++f) {
      const std::uint32_t t = Mesh<D>::simplex_of(mesh_.neighbour(s, f));
      const std::uint32_t m = mesh_.mark(t);
      if (m == base_ || m == in_) continue;
      if (m != out_) {
        if (approx_conflict(t, p)) {
          mesh_.set_mark(t, in_);
          cavity_.push_back(t);
          continue;
        }
        mesh_.set_mark(t, out_);
      }
      faces_.push_back(Mesh<D>::encode(s, f));
    }
  }
  approx_total_ += cavity_.size();

  // (3)-(6) the correction.
  if (!correct(i, nbase)) return false;
  cavity_total_ += cavity_.size();
  cavity_max_ = std::max<std::uint64_t>(cavity_max_, cavity_.size());
  cavity_sizes_.add(cavity_.size());
  created_ += records_.size();

  // (7) re-star.
  std::string err;
  const std::uint32_t first = restar_.star(mesh_, cavity_, records_, err, !K::exact);
  if (!err.empty()) {
    fail("point " + std::to_string(i) + ": " + err);
    return false;
  }
  last_ = first;
  return true;
}

template <class K, int D>
TriangulationResult George<K, D>::run(std::span<const Point<D>> pts) {
  TriangulationResult res;
  const std::size_t n = pts.size();
  mesh_.clear();
  const InitialSimplex<D> init = initial_simplex_or_outcome<D>(k_, pts, res);
  if (!init.found) return res;
  mesh_.reserve(D == 2 ? 2 * n + 16 : (27 * n) / 4 + 64);
  if (opt_.enclosing_box) {
    auto corners = enclosing_box_corners<D>(pts);
    if (!corners || !snap_box_corners<K, D>(k_, pts, *corners)) {
      res.outcome = RunOutcome::failed;
      res.message = corners ? "the enclosing box's corners are not strictly outside the points on the kernel's grid"
                            : "the enclosing box does not fit in finite doubles";
      return res;
    }
    merged_.start(n);
    box_pts_.assign(pts.begin(), pts.end());
    box_pts_.insert(box_pts_.end(), corners->begin(), corners->end());
    pts_ = box_pts_.data();
    npts_ = box_pts_.size();
    const auto fin = build_box_mesh<K, D>(k_, mesh_, pts_, static_cast<std::uint32_t>(n));
    last_ = fin[0];
  } else {
    pts_ = pts.data();
    npts_ = n;
    last_ = build_initial_mesh<D>(mesh_, init.ids);
    merged_.start(n, init.ids);
  }

  for (std::uint32_t i = 0; i < n; ++i) {
    if (merged_.is_initial(i)) continue;  // already a vertex
    if (!insert(i)) {
      res.outcome = RunOutcome::failed;
      res.message = message_;
      merged_.stop_before(i);
      break;
    }
  }
  res.counters = {
      {"walk_steps", walk_steps_},
      {"base_simplices", base_total_},
      {"approx_cavity_simplices", approx_total_},
      {"cavity_simplices", cavity_total_},
      {"max_cavity_simplices", cavity_max_},
      {"simplices_created", created_},
      {"duplicates", duplicates_},
      {"float_sphere_tests", float_tests_},
      {"corrected_insertions", corrected_insertions_},
      {"correction_rounds", rounds_},
      {"removed_for_visibility", removed_visibility_},
      {"added_for_zero_volume", added_zero_},
      {"zero_volume_not_addable", zero_not_addable_},
      {"removed_for_connectivity", removed_connectivity_},
      {"removed_for_enclosed_vertex", removed_enclosed_},
      {"mesh_slots", mesh_.slots()},
      {"mesh_bytes_reserved", mesh_.bytes_reserved() + restar_.bytes_reserved()},
  };
  cavity_sizes_.append_to(res.counters);
  // Last, as it hands the mesh's memory over to the result (mesh() is then
  // empty); the simplices of the enclosing box's corners are left out.
  if (res.outcome == RunOutcome::ok)
    res.simplices = mesh_.take_finite_simplices([&](const std::uint32_t* v) {
      const bool keep = std::all_of(v, v + V, [&](std::uint32_t id) { return id < n; });
      box_removed_ += keep ? 0 : 1;
      return keep;
    });
  if (opt_.enclosing_box) res.counters.push_back({"box_simplices_removed", box_removed_});
  res.merged_into = merged_.merged_into();  // the mesh is gone: not part of the peak
  return res;
}

}  // namespace dlab
