// The driver shared by every algorithm x kernel instantiation: snap (integer
// kernel), choose the degeneracy policy, compute the insertion order, reorder
// the points physically (id = insertion position; design.md section 7 item 7),
// run the algorithm, and map its ids back to input indices, duplicates to their
// first occurrence.
//
// An algorithm is a class template Algo<K, D> constructible from a K, with
//   TriangulationResult run(std::span<const Point<D>> points_in_order);
//   const K& kernel() const;   (the driver reads the predicate counters there)
// (algorithms/triangulation_result.hpp). An algorithm that inserts points of
// its own (George's enclosing box) also has
//   static std::optional<std::vector<Point<D>>> added_points(std::span<const Point<D>> input);
// and a snapping kernel's grid is then fitted to those points too. An algorithm
// that passes its kernel no other points than these (and the input) says
//   static constexpr bool kernel_sees_given_points_only = true;
// and a kernel with a static filter (StaticFilterKernel) is then fitted to them;
// without the promise, it stays unfitted.
//
// Policy: `sos` wraps the kernel in perturbed<K> (predicates/perturbed.hpp),
// `strict` uses K alone.  For the inexact kernels (float, epsilon) `sos` also
// applies perturbed<K>: the perturbation then only acts where K answers an
// exact zero, which keeps the two policies meaningful and comparable; no
// guarantee is claimed either way.
#pragma once
#include <algorithm>
#include <chrono>
#include <concepts>
#include <cmath>
#include <ctime>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "algorithms/huge_pages.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/triangulation_result.hpp"
#include "predicates/counted.hpp"
#include "predicates/kernel.hpp"
#include "predicates/perturbed.hpp"
#include "variants/canonical_order.hpp"
#include "variants/insertion_order.hpp"
#include "variants/packed_indices.hpp"
#include "variants/run.hpp"


namespace dlab {

// An algorithm whose point location can be chosen (algorithms/locate.hpp).
template <class A>
concept HasLocationScheme = requires(A& a) { a.set_location(LocationScheme::walk); };

// An algorithm that runs on several threads (algorithms/parallel_bowyer_watson.hpp).
template <class A>
concept HasThreads = requires(A& a) { a.set_threads(1u); };

// RunOptions::location by name.
inline LocationScheme location_scheme(std::string_view name) {
  if (name == "walk") return LocationScheme::walk;
  if (name == "scan") return LocationScheme::scan;
  throw UsageError("unknown location scheme '" + std::string(name) + "' (expected walk or scan)");
}

namespace driver_detail {

// CPU time of the calling thread, which runs the whole triangulation, in
// seconds. Not CLOCK_PROCESS_CPUTIME_ID: once a process-wide CPU timer is
// armed (RLIMIT_CPU, as in the children of `dlab study` and `dlab fuzz`), Linux
// answers that clock from its tick-updated group accounting, and runs below a
// few milliseconds then read 0 (seen here: 0 for 0.7 ms runs).
inline double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

template <int D>
std::size_t count_distinct(std::vector<Point<D>> pts) {
  std::sort(pts.begin(), pts.end());
  return static_cast<std::size_t>(std::unique(pts.begin(), pts.end()) - pts.begin());
}

// Keeps a point vector in insertion order while it lives (apply_order), and
// puts it back as it was when it goes (or at restore()), also when the run
// throws (in place if memory is short then). The vector holds one copy of the
// points during the run; the second, while it is reordered, comes before the
// mesh exists. The order itself is kept packed (PackedIndices: 20 bits per
// point at 10^6 instead of 32), since it lives through the mesh's peak.
template <int D>
class InInsertionOrder {
 public:
  InInsertionOrder(std::vector<Point<D>>& pts, const std::vector<std::uint32_t>& order, unsigned threads)
      : pts_(pts), order_(order, pts.size()), threads_(threads) {  // packed first: a bad_alloc leaves pts as they were
    apply_order(pts_, order, false, done_, false, threads_);
  }
  ~InInsertionOrder() { restore(); }
  InInsertionOrder(const InInsertionOrder&) = delete;
  InInsertionOrder& operator=(const InInsertionOrder&) = delete;

  void restore() {
    if (restored_) return;
    restored_ = true;
    apply_order(pts_, order_, true, done_, false, threads_);
  }
  // Position i holds the input index of the point inserted i-th.
  const PackedIndices& order() const { return order_; }

 private:
  std::vector<Point<D>>& pts_;
  PackedIndices order_;
  std::vector<bool> done_;
  unsigned threads_;
  bool restored_ = false;
};

// The heap's free pages go back to the system before a run, whose peak is
// the memory reported (peak_rss_bytes): glibc keeps freed blocks below its
// dynamic mmap threshold (up to 32 MiB) in the heap, so the parser's and the
// insertion order's buffers would otherwise stay resident through the run
// (6 bytes per point of 10^6 in 3D, session 19).  Small runs skip it: a
// fuzzing campaign makes millions of them, and their memory is not the point.
inline void release_free_heap(std::size_t points) {
#if defined(__GLIBC__)
  if (points >= (1u << 16)) malloc_trim(0);
#endif
}

// Runs the algorithm on pts, which are put in insertion order for the run
// (design.md section 7 item 7: ids are insertion positions) and restored
// after it: no second copy of the points during the run.
template <template <class, int> class Algo, class K, int D>
void run_kernel(const K& k, std::vector<Point<D>>& pts, const RunOptions& o, RunResult& r) {
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  InInsertionOrder<D> in_order(
      pts, insertion_order(std::span<const Point<D>>(pts), parse_insertion_order(o.order), o.seed, o.threads),
      o.threads);
  const PackedIndices& order = in_order.order();
  const auto t1 = std::chrono::steady_clock::now();

  Algo<K, D> algo(k);
  if constexpr (HasLocationScheme<Algo<K, D>>) algo.set_location(location_scheme(o.location));
  if constexpr (HasThreads<Algo<K, D>>) algo.set_threads(o.threads);
  release_free_heap(pts.size());
  TriangulationResult t = algo.run(std::span<const Point<D>>(pts));
  const auto t2 = std::chrono::steady_clock::now();
  in_order.restore();

  r.outcome = t.outcome;
  r.message = std::move(t.message);
  r.counters = std::move(t.counters);
  if (t.outcome != RunResult::Outcome::lower_dimensional) {
    // First occurrence: the smallest input index among the points merged into a vertex.
    std::vector<std::uint32_t> rep = huge_vector(pts.size(), kNotProcessed);
    std::size_t distinct = 0, processed = 0;
    for (std::size_t i = 0; i < t.merged_into.size(); ++i) {
      const std::uint32_t v = t.merged_into[i];
      if (v == kNotProcessed || v >= rep.size()) continue;
      ++processed;
      if (v == i) ++distinct;
      rep[v] = std::min(rep[v], order[i]);
    }
    r.inserted_points = processed;
    // After a failure only the processed points were seen: count the input's.
    r.distinct_points = t.outcome == RunResult::Outcome::ok ? distinct : count_distinct<D>(pts);
    r.simplices = std::move(t.simplices);
    map_indices(r.simplices, rep, o.threads);
    if (o.canonical || o.threads > 0) sort_canonically(r.simplices, D, o.threads);
  }
  const auto t3 = std::chrono::steady_clock::now();
  auto span = [](auto from, auto to) { return std::chrono::duration<double>(to - from).count(); };
  r.seconds = span(t0, t3);
  r.phase_seconds = {span(t0, t1), span(t1, t2), span(t2, t3)};
  r.cpu_seconds = thread_cpu_seconds() - cpu0;
  if (t.outcome == RunResult::Outcome::lower_dimensional) r.distinct_points = count_distinct<D>(pts);

  r.predicates = algo.kernel().counters();
}

template <class A, int D>
concept AddsPoints = requires(std::span<const Point<D>> p) {
  { A::added_points(p) } -> std::same_as<std::optional<std::vector<Point<D>>>>;
};

template <class A>
concept SeesGivenPointsOnly = requires { requires A::kernel_sees_given_points_only; };

// The input and the points the algorithm adds (George's box corners).
template <template <class, int> class Algo, class K, int D>
std::vector<Point<D>> with_added_points(const std::vector<Point<D>>& pts) {
  std::vector<Point<D>> all = pts;
  if constexpr (AddsPoints<Algo<K, D>, D>)
    if (!pts.empty())
      if (auto added = Algo<K, D>::added_points(std::span<const Point<D>>(pts)))
        all.insert(all.end(), added->begin(), added->end());
  return all;
}

// Triangulates `input` (the caller's, reordered during the run and restored
// after it), which ends in r.points; a snapping kernel triangulates a snapped
// copy instead, which is r.points, and leaves `input` as it was. After an
// exception `input` is as it was.
template <template <class, int> class Algo, class K, int D>
RunResult run_dimension(std::vector<Point<D>>& input, const RunOptions& o, bool sos) {
  RunResult r;
  r.dimension = D;
  r.points.dimension = D;
  std::vector<Point<D>>& snapped = points_of<D>(r.points);
  K base{};
  if constexpr (SnappingKernel<K, D>) {
    snapped = input;
    // The grid is fitted to the input and the added points together, so that
    // those are on it too (the input itself is snapped below).
    if constexpr (AddsPoints<Algo<K, D>, D>) {
      std::vector<Point<D>> fit = with_added_points<Algo, K, D>(snapped);
      base.snap_all(fit);
    }
    const auto st = base.snap_all(snapped);
    r.snapping = {{"points_moved", st.moved}, {"points_merged", st.merged}};
    r.max_snap_displacement = st.max_displacement;
  }
  std::vector<Point<D>>& pts = SnappingKernel<K, D> ? snapped : input;
  if constexpr (StaticFilterKernel<K, D> && SeesGivenPointsOnly<Algo<K, D>>) {
    if constexpr (AddsPoints<Algo<K, D>, D>)
      base.fit_static_filter(std::span<const Point<D>>(with_added_points<Algo, K, D>(pts)));
    else  // no copy of the points
      base.fit_static_filter(std::span<const Point<D>>(pts));
  }
  // Predicate calls are always counted (design.md section 5, --stats).
  if (sos)
    run_kernel<Algo, counted<perturbed<K>>, D>(counted<perturbed<K>>(perturbed<K>(base)), pts, o, r);
  else
    run_kernel<Algo, counted<K>, D>(counted<K>(base), pts, o, r);
  if constexpr (!SnappingKernel<K, D>) snapped = std::move(input);
  return r;
}

}  // namespace driver_detail

// Entry point of one algorithm x kernel translation unit. The points are
// taken (they end in the result's points, in their order); after an exception
// they are left in `ps` as they were.
template <template <class, int> class Algo, class K>
RunResult run_algorithm(PointSet&& ps, const RunOptions& o) {
  bool sos;
  if (o.policy == "sos")
    sos = true;
  else if (o.policy == "strict")
    sos = false;
  else
    throw UsageError("unknown policy '" + o.policy + "' (expected sos or strict)");
  parse_insertion_order(o.order);  // throws on an unknown name
  if (location_scheme(o.location) != LocationScheme::walk && !HasLocationScheme<Algo<counted<K>, 2>>)
    throw UsageError("--location " + o.location + " is available with bowyer-watson and lawson only");
  if (ps.dimension == 2) return driver_detail::run_dimension<Algo, K, 2>(ps.p2, o, sos);
  if (ps.dimension == 3) return driver_detail::run_dimension<Algo, K, 3>(ps.p3, o, sos);
  throw UsageError("dimension must be 2 or 3, not " + std::to_string(ps.dimension));
}

// The same on a copy of the points.
template <template <class, int> class Algo, class K>
RunResult run_algorithm(const PointSet& ps, const RunOptions& o) {
  PointSet copy = ps;
  return run_algorithm<Algo, K>(std::move(copy), o);
}

}  // namespace dlab
