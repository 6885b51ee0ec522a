// Bowyer–Watson incremental Delaunay triangulation in 2D and 3D
// (A. Bowyer, "Computing Dirichlet tessellations", Comput. J. 24 (1981);
//  D. F. Watson, "Computing the n-dimensional Delaunay tessellation with
//  application to Voronoi polytopes", Comput. J. 24 (1981); Baker, Handbook of
//  Grid Generation ch. 16.2.2; survey section 2.2).
//
// For each point p, in the order given:
//   1. locate: visibility walk from a simplex created for the previous point
//      (algorithms/locate.hpp), or, with LocationScheme::scan, live simplices
//      tested in storage order until one contains p (no location structure:
//      O(N^2) in all, Baker ch. 16.2.2; counter scan_tests); a point equal
//      to a vertex of the simplex found is a duplicate and is merged into that
//      vertex;
//   2. cavity: the simplices in conflict with p (algorithms/cavity_search.hpp,
//      in 2D with an exact kernel depth first, its boundary in cycle order;
//      with the `sos` policy K is perturbed<...>, which never answers zero,
//      giving the unique perturbed Delaunay triangulation, CGAL's);
//   3. re-star: connect p to every boundary facet (algorithms/cavity.hpp).
//
// The simplex containing p is always in the cavity (p inside the closed
// simplex and not a vertex is strictly inside its circumsphere), and with an
// exact kernel the walk always ends.  With an inexact kernel (K::exact false)
// every step is checked: a walk beyond its step bound, a new finite simplex
// that the kernel itself does not see positively oriented (cavity not
// star-shaped), a cavity boundary that is not a closed manifold, or a vertex
// swallowed by a cavity end the run with Outcome::failed and a message; every
// loop is bounded (stamps visit each simplex at most once per insertion).
#pragma once
#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "algorithms/cavity.hpp"
#include "algorithms/cavity_histogram.hpp"
#include "algorithms/cavity_search.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/merge_record.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"
#include "algorithms/simplex_guard.hpp"
#include "algorithms/triangulation_result.hpp"

namespace dlab {

template <class K, int D>
class BowyerWatson {
  static_assert(KernelFor<K, D>);
  static constexpr int V = D + 1;

 public:
  explicit BowyerWatson(const K& k = K{}) : k_(k) {}

  // The kernel sees only the points given to run(); variants/driver.hpp may then
  // fit a static filter (tests/test_static_filter.cpp checks the promise).
  static constexpr bool kernel_sees_given_points_only = true;

  // Triangulates pts in the order given.  pts must outlive the call. The
  // simplices are taken out of the mesh (Mesh::take_finite_simplices), which
  // is empty afterwards.
  TriangulationResult run(std::span<const Point<D>> pts);

  const Mesh<D>& mesh() const { return mesh_; }
  const K& kernel() const { return k_; }
  // Point location: the walk from the last insertion (default) or a scan of
  // every live simplex (algorithms/locate.hpp); variants/driver.hpp sets it.
  void set_location(LocationScheme s) { location_ = s; }

 private:
  bool insert(std::uint32_t i);  // false: failure (message_ set)
  bool new_simplex_positive(const BoundaryRecord<D>& r) const;
  void fail(std::string msg) { message_ = std::move(msg); }

  K k_;
  Mesh<D> mesh_;
  Restar<D> restar_;
  const Point<D>* pts_ = nullptr;
  MergeRecord<D> merged_;
  std::vector<std::uint32_t> cavity_;
  std::vector<BoundaryRecord<D>> records_;
  std::vector<std::uint32_t> ccw_edges_;  // search_cavity_ccw's stack
  std::uint32_t last_ = 0;   // where the next walk starts
  std::uint32_t stamp_ = 0;  // 2D cavity stamp: stamp_ = in, stamp_ + 1 = out
  // Where the stamps live: 3D in the top bits of neighbour words (the mesh
  // has no mark array: 27 bytes per point less; at most 2^29 slots), 2D
  // in the mesh's blocks (free).
  std::conditional_t<D == 3, TopBitMarks, NoGuard> stamps_;
  WalkRng rng_;
  LocationScheme location_ = LocationScheme::walk;
  std::string message_;
  // counters
  std::uint64_t walk_steps_ = 0, scan_tests_ = 0, cavity_total_ = 0, cavity_max_ = 0, created_ = 0,
                duplicates_ = 0, boundary_max_ = 0;
  CavityHistogram cavity_sizes_;
};

template <class K, int D>
bool BowyerWatson<K, D>::new_simplex_positive(const BoundaryRecord<D>& r) const {
  if (r.v[D] == kGhost) return true;
  if constexpr (D == 2)
    return orient_pos(k_, pts_[r.v[0]], pts_[r.v[1]], pts_[r.v[2]]) == Sign::positive;
  else
    return orient_pos(k_, pts_[r.v[0]], pts_[r.v[1]], pts_[r.v[2]], pts_[r.v[3]]) == Sign::positive;
}

template <class K, int D>
bool BowyerWatson<K, D>::insert(std::uint32_t i) {
  const Point<D>& p = pts_[i];
  // An exact walk on a Delaunay triangulation never revisits a simplex, so
  // the number of slots bounds it; the slack covers nothing but bugs.
  const std::uint64_t bound = 4ull * mesh_.slots() + 1000;
  const Located loc = locate<K, D>(location_, k_, mesh_, pts_, last_, p, bound, rng_);
  walk_steps_ += loc.steps;
  scan_tests_ += loc.tests;
  if (loc.end == Located::End::not_found) {
    fail("the scan found no simplex containing " + std::string("insertion #") + std::to_string(i) +
         (K::exact ? " (a bug: the kernel is exact)" : " (inconsistent orientations)"));
    return false;
  }
  if (loc.end == Located::End::step_bound) {
    fail("point location exceeded its bound of " + std::to_string(bound) + " steps at insertion #" +
         std::to_string(i) + (K::exact ? " (a bug: the kernel is exact)" : " (inconsistent orientations)"));
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

  // Cavity search (algorithms/cavity_search.hpp).
  if constexpr (D == 2) {
    if (stamp_ >= 0xFFFFFFF0u) {
      for (std::uint32_t s = 0; s < mesh_.slots(); ++s) mesh_.set_mark(s, 0);
      stamp_ = 0;
    }
    stamp_ += 2;
  }
  if constexpr (D == 2 && K::exact)  // records in cycle order: Restar links them without a table
    search_cavity_ccw<K>(k_, mesh_, pts_, i, loc.simplex, stamp_, stamp_ + 1, cavity_, records_, ccw_edges_, stamps_);
  else if constexpr (D == 2)
    search_cavity<K, D>(k_, mesh_, pts_, i, loc.simplex, stamp_, stamp_ + 1, cavity_, records_, stamps_);
  else {  // what the search marked: the cavity (in) and its outside neighbours (out)
    constexpr std::uint32_t in = TopBitMarks::kIn, out = TopBitMarks::kOut;
    search_cavity<K, D>(k_, mesh_, pts_, i, loc.simplex, in, out, cavity_, records_, stamps_);
    for (std::uint32_t s : cavity_) stamps_.unmark(mesh_, s, in);
    for (const BoundaryRecord<D>& r : records_) stamps_.unmark(mesh_, Mesh<D>::simplex_of(r.outside), out);
  }
  cavity_total_ += cavity_.size();
  cavity_max_ = std::max<std::uint64_t>(cavity_max_, cavity_.size());
  cavity_sizes_.add(cavity_.size());
  boundary_max_ = std::max<std::uint64_t>(boundary_max_, records_.size());
  created_ += records_.size();

  if constexpr (!K::exact) {
    for (const BoundaryRecord<D>& r : records_)
      if (!new_simplex_positive(r)) {
        fail("cavity of insertion #" + std::to_string(i) +
             " is not star-shaped: a new simplex is not positively oriented");
        return false;
      }
  }
  std::string err;
  const std::uint32_t first = restar_.star(mesh_, cavity_, records_, err, !K::exact);
  if (!err.empty()) {
    fail("insertion #" + std::to_string(i) + ": " + err);
    return false;
  }
  last_ = first;
  return true;
}

template <class K, int D>
TriangulationResult BowyerWatson<K, D>::run(std::span<const Point<D>> pts) {
  TriangulationResult res;
  pts_ = pts.data();
  const std::size_t n = pts.size();
  if constexpr (D == 3) {
    mesh_.without_marks();
    mesh_.limit_slots(TopBitMarks::kMaxSlots);
  }
  const std::optional<IncrementalStart<D>> start = start_incremental_mesh<D>(k_, pts, mesh_, res);
  if (!start) return res;
  last_ = start->simplex;
  merged_.start(n, start->ids);

  for (std::uint32_t i = 0; i < n; ++i) {
    if (merged_.is_initial(i)) continue;  // already a vertex
    if (!insert(i)) {
      res.outcome = RunOutcome::failed;
      res.message = message_;
      merged_.stop_before(i);
      break;
    }
  }

  if constexpr (!K::exact) res.merged_into = merged_.merged_into();  // read by the check below
  if (res.outcome == RunOutcome::ok) {
    if constexpr (!K::exact) {
      // A cavity that swallowed a vertex leaves it out of every simplex.
      std::vector<bool> present(n, false);
      mesh_.for_each_finite([&](std::uint32_t s) {
        for (int j = 0; j < V; ++j) present[mesh_.vertex(s, j)] = true;
      });
      for (std::uint32_t i = 0; i < n; ++i)
        if (res.merged_into[i] == i && !present[i]) {
          res.outcome = RunOutcome::failed;
          res.message = "the vertex of insertion #" + std::to_string(i) + " was lost (enclosed in a cavity)";
          break;
        }
    }
  }
  res.counters = {
      {"walk_steps", walk_steps_},
      {"scan_tests", scan_tests_},
      {"cavity_simplices", cavity_total_},
      {"max_cavity_simplices", cavity_max_},
      {"max_cavity_boundary", boundary_max_},
      {"simplices_created", created_},
      {"duplicates", duplicates_},
      {"mesh_slots", mesh_.slots()},
      {"mesh_bytes_reserved", mesh_.bytes_reserved() + restar_.bytes_reserved()},
  };
  cavity_sizes_.append_to(res.counters);
  // Last, as it hands the mesh's memory over to the result (mesh() is then empty).
  if (res.outcome == RunOutcome::ok) res.simplices = mesh_.take_finite_simplices();
  if constexpr (K::exact) res.merged_into = merged_.merged_into();  // the mesh is gone: not part of the peak
  return res;
}

}  // namespace dlab
