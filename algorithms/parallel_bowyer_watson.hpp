// Parallel Bowyer–Watson in 2D and 3D (`dlab triangulate --threads T`).
//
// The insertion is algorithms/bowyer_watson.hpp's (walk, cavity search,
// re-star: the same functions), run by T workers at once on oneTBB
// (tbb::task_arena, tbb::parallel_for) with the spatial partitions of Marot,
// Pellerin, Remacle, "One machine, one minute, three billion tetrahedra",
// IJNME 2019, section 4, re-derived:
//  - the points (in the driver's insertion order: BRIO rounds, each sorted along
//    a Hilbert curve) are inserted in batches that double in size; each round
//    of a batch cuts space into B <= T boxes with about equal shares of the
//    round's points (kd-tree cuts at the quantiles of a sample: B = c_1 c_2 ...
//    pieces along the axes, the most along the widest; B = 2 is two slabs; B
//    grows with the mesh, as small boxes defer most of their points), and B
//    tasks insert the points of their box, each in the order given;
//  - a task may read and write only simplices whose vertices all lie in its
//    box (algorithms/simplex_guard.hpp's PartitionGuard, which also says why
//    two tasks then never write one word): no locks, no atomic
//    read-modify-write; an insertion whose walk or cavity leaves the box is
//    refused before anything is written, and the point waits for the next
//    round, whose cuts start from the next axis; when few points remain (or D
//    rounds make no progress) one worker inserts them alone;
//  - each task starts walking from a simplex of its box, found between rounds
//    by a walk of the calling thread to one of the task's points, and then
//    from the simplex of its last insertion, also after a walk or a cavity
//    the box refused.  (Starting where a refused walk stopped, at the box's
//    side, left later walks stuck there, one refused facet away from all the
//    task's later points: 10^6 uniform 2D points, BRIO seed 1, deferred
//    77 000 of one box's 238 000 points in a row; papers/triangulation_costs.md,
//    session 46);
//  - the first points are inserted by one worker alone, until the mesh is large
//    enough for T boxes;
//  - each worker takes new slots from its own free list and from blocks of a
//    reserve that the mesh grows between rounds, never during one.
//
// Why the output does not depend on T or on the schedule: with an exact kernel
// and the sos policy the Delaunay triangulation of the perturbed points is
// unique (Edelsbrunner & Mücke 1990), so every insertion order that completes
// builds the same simplices; the driver writes them in canonical order
// (algorithms/canonical_simplices.hpp), and merges each group of duplicate
// points into its first input index whichever copy was inserted.  Only exact
// kernels are allowed (variants/registry.cpp): with inexact predicates the
// result would depend on the order, hence on the schedule.  Counters that
// measure the work (walk steps, deferrals, cavity sizes) do depend on it.
//
// Every loop is bounded: a round either inserts a point or falls back to one
// worker, which inserts every point (with the serial algorithm's bounds and
// failure messages).
#pragma once
#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <deque>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include "algorithms/cavity.hpp"
#include "algorithms/cavity_histogram.hpp"
#include "algorithms/cavity_search.hpp"
#include "algorithms/huge_pages.hpp"
#include "algorithms/initial_simplex.hpp"
#include "algorithms/kd_boxes.hpp"
#include "algorithms/locate.hpp"
#include "algorithms/mesh.hpp"
#include "algorithms/simplex_guard.hpp"
#include "algorithms/triangulation_result.hpp"

namespace dlab {

// New slots for one worker: its own free list (slots its cavities gave up)
// and blocks claimed from the mesh's reserve; no other task reads them (a dead
// slot is nobody's neighbour).  Presents the members of Mesh<D> that
// Restar::star uses.
template <int D>
class WorkerSlots {
 public:
  // 1024 slots (32 KiB): with blocks of 64 (2 KiB), the two workers' blocks
  // alternated in memory, and the tasks of 10^6 uniform 2D points took 0.189
  // s on two threads against 0.166 (256), 0.161 (1024) and 0.160 (4096 and
  // 8192): medians of 8, in one process (papers/triangulation_costs.md,
  // session 46).  A worker keeps at most one block part used.
  static constexpr std::uint32_t kBlock = 1024;

  explicit WorkerSlots(Mesh<D>& m) : m_(m) {}

  // Takes n slots for the coming re-star.  False: the reserve ran out (the
  // point waits for the mesh to grow).
  bool prepare(std::size_t n, std::atomic<std::uint32_t>& reserve_next, std::uint32_t reserve_end) {
    while (ready_.size() < n) {
      std::uint32_t s;
      if (!free_.empty()) {
        s = free_.back();
        free_.pop_back();
      } else {
        if (block_next_ == block_end_) {
          const std::uint32_t b = reserve_next.fetch_add(kBlock, std::memory_order_relaxed);
          if (b >= reserve_end) {
            give_back();
            return false;
          }
          block_next_ = b;
          block_end_ = std::min(b + kBlock, reserve_end);
        }
        s = block_next_++;
      }
      ready_.push_back(s);
    }
    return true;
  }
  // After an abandoned insertion: the slots prepared and not used go back.
  void give_back() {
    for (std::uint32_t s : ready_) free_.push_back(s);
    ready_.clear();
  }
  std::int64_t live_delta() const { return live_delta_; }

  // ---- what Restar::star uses ----
  std::uint32_t create(const std::uint32_t* verts) {
    const std::uint32_t s = ready_.back();
    ready_.pop_back();
    m_.assign(s, verts);
    ++live_delta_;
    return s;
  }
  void destroy(std::uint32_t s) {
    m_.vertex(s, 0) = kDead;
    free_.push_back(s);
    --live_delta_;
  }
  void assign(std::uint32_t s, const std::uint32_t* verts) { m_.assign(s, verts); }
  void link(std::uint32_t a, std::uint32_t b) { m_.link(a, b); }
  void set_neighbour(std::uint32_t enc, std::uint32_t other) { m_.set_neighbour(enc, other); }
  std::uint32_t neighbour_enc(std::uint32_t enc) const { return m_.neighbour_enc(enc); }
  bool is_ghost(std::uint32_t s) const { return m_.is_ghost(s); }
  std::uint32_t slots() const { return m_.slots(); }

 private:
  Mesh<D>& m_;
  std::vector<std::uint32_t> free_, ready_;
  std::uint32_t block_next_ = 0, block_end_ = 0;
  std::int64_t live_delta_ = 0;
};

// A copy of the kernel for one thread: counted<> kernels count into counters
// of their own (predicates/counted.hpp), summed back by add_thread_counts.
template <class K>
K thread_kernel(const K& k) {
  if constexpr (requires { k.with_own_counters(); })
    return k.with_own_counters();
  else
    return k;
}
template <class K>
void add_thread_counts(const K& into, const K& from) {
  if constexpr (requires { into.add_counts(from); }) into.add_counts(from);
}

template <class K, int D>
class ParallelBowyerWatson {
  static_assert(KernelFor<K, D>);
  static_assert(K::exact, "the parallel result is schedule-independent only with exact predicates");
  static constexpr int V = D + 1;

 public:
  static constexpr unsigned kMaxThreads = 255;  // the command line's limit (variants/registry.cpp)
  static_assert(kMaxThreads <= 256, "a box's label is a byte");

  explicit ParallelBowyerWatson(const K& k = K{}) : k_(k) {}

  // The kernel sees only the points given to run() (variants/driver.hpp).
  static constexpr bool kernel_sees_given_points_only = true;

  void set_threads(unsigned t) { threads_ = std::clamp(t, 1u, kMaxThreads); }
  // Each box of a round gets at least this many of the mesh's vertices (see
  // insert_batch); tests lower it to run many boxes on small inputs.
  void set_vertices_per_box(std::size_t v) { vertices_per_box_ = std::max<std::size_t>(v, 1); }

  // Triangulates pts (in the order given, T workers at once).  pts must
  // outlive the call.
  TriangulationResult run(std::span<const Point<D>> pts);

  // The mesh stays in mesh() after run() (tests); otherwise its memory goes to
  // the result.
  void keep_mesh() { keep_mesh_ = true; }
  const Mesh<D>& mesh() const { return mesh_; }
  const K& kernel() const { return k_; }

 private:
  enum class Status : unsigned char { inserted, deferred, failed };

  struct Worker {
    Worker(const K& kernel, Mesh<D>& m) : k(thread_kernel(kernel)), slots(m) {}
    K k;
    PartitionGuard<D> guard;  // the box of the task this worker runs
    WorkerSlots<D> slots;
    Restar<D> restar;
    std::vector<std::uint32_t> cavity, edges;  // edges: search_cavity_ccw's stack (2D)
    std::vector<BoundaryRecord<D>> records;
    std::uint32_t last = 0;   // where the next walk starts: the last insertion's simplex (see the header)
    std::uint32_t stamp = 0;  // this worker's stamps: stamp (in), stamp + 1 (out)
    WalkRng rng;
    std::string message;
    std::uint64_t walk_steps = 0, cavity_total = 0, cavity_max = 0, created = 0, duplicates = 0,
                  boundary_max = 0, deferrals = 0;
    CavityHistogram cavity_sizes;
    // A worker thread may leave the arena between two chunks of a round and
    // another take its slot, and with it this worker.  oneTBB orders the two
    // threads inside libtbb, where a race detector (ThreadSanitizer) does not
    // see; an acquire at the start of each chunk and a release at its end
    // show it that order.
    std::atomic<std::uint32_t> handoff{0};
  };

  // Guard: the worker's PartitionGuard in a parallel round; NoGuard (3D:
  // TopBitMarks) when one worker runs alone (nobody to exclude).
  template <class Guard>
  Status insert(Worker& w, Guard& guard, std::uint32_t i, bool alone);
  template <class Guard>
  Status abandon(Worker& w, Guard& guard) {
    w.slots.give_back();
    guard.release_all();
    return Status::deferred;
  }
  template <class Guard>
  bool start_simplex(Worker& w, Guard& guard, std::uint32_t& start, bool alone);
  // One task of a parallel round: the box, the simplex its walks start from
  // (kNoStart: none found, every point waits) and its points.
  static constexpr std::uint32_t kNoStart = 0xFFFFFFFFu;
  struct Cell {
    std::uint32_t start = kNoStart;
    std::vector<std::uint32_t> points, deferred;
  };
  void label_vertices(const KdBoxes<D>& boxes);
  std::uint32_t live_simplex();
  void find_start(Cell& cell, std::uint8_t box);
  void insert_alone(const std::vector<std::uint32_t>& points);
  // `points` after `before` points: a batch of rounds.
  void insert_batch(std::vector<std::uint32_t> points, std::size_t before);
  void ensure_reserve(std::size_t slots);
  // A guard's view of the mesh (again whenever the mesh grows).
  void bind(PartitionGuard<D>& guard) {
    guard.bind(mesh_, box_of_vertex_.data());
    if constexpr (D == 2) guard.bind_marks(mesh_.marks());
  }
  void reset_stamps_if_needed(std::uint64_t insertions);
  // f(r) on the workers' threads for the subranges r of `range`, between two
  // steps of the calling thread.  oneTBB orders the two inside libtbb, where a
  // race detector (ThreadSanitizer) does not see; the atomics around the
  // round show it that order.
  template <class Range, class Partitioner, class F>
  void on_workers(const Range& range, const Partitioner& partitioner, F&& f) {
    round_started_.fetch_add(1, std::memory_order_release);
    arena_.execute([&] {
      tbb::parallel_for(
          range,
          [&](const Range& r) {
            (void)round_started_.load(std::memory_order_acquire);
            f(r);
            workers_done_.fetch_add(1, std::memory_order_release);
          },
          partitioner);
    });
    (void)workers_done_.load(std::memory_order_acquire);
  }

  K k_;
  Mesh<D> mesh_;
  const Point<D>* pts_ = nullptr;
  // Each point's box in the current round (labels 0 .. B - 1 < kMaxThreads),
  // for the points below label_end_: the mesh's vertices and the batch's points.
  std::vector<std::uint8_t> box_of_vertex_;
  std::uint32_t label_end_ = 0;
  unsigned threads_ = 1;
  // 3D boxes of 2^18 vertices defer up to about 0.45 a point, 2D boxes of 2^17
  // about 0.25 (session 43's curves at 10^6 points).
  std::size_t vertices_per_box_ = D == 3 ? 1u << 18 : 1u << 17;
  bool keep_mesh_ = false;
  std::deque<Worker> workers_;  // never moved
  tbb::task_arena arena_;
  std::atomic<std::uint32_t> reserve_next_{0};
  std::uint32_t reserve_end_ = 0;
  std::vector<std::uint32_t> merged_;
  std::atomic<bool> failed_{false};
  // Explicit happens-before edges around each parallel round, so that a
  // race detector that does not see inside oneTBB (ThreadSanitizer) sees them.
  std::atomic<std::uint32_t> round_started_{0}, workers_done_{0};
  std::uint64_t rounds_ = 0, boxes_max_ = 0, alone_insertions_ = 0;
  WalkRng rng_;  // find_start's walks
};

// The simplex to start the walk from: the worker's last one, which in a
// parallel round is one of its box's (set by find_start, then by its own
// insertions: no other task deletes it).  Alone: it or, when it was deleted,
// the next live slot.  False (a parallel round only): it is not the box's.
template <class K, int D>
template <class Guard>
bool ParallelBowyerWatson<K, D>::start_simplex(Worker& w, Guard& guard, std::uint32_t& start, bool alone) {
  if (!alone) {
    start = w.last;
    return w.last != kNoStart && guard.acquire(w.last);
  }
  const std::uint32_t slots = mesh_.slots();
  std::uint32_t s = w.last < slots ? w.last : 0;
  for (std::uint32_t t = 0; t < slots && !mesh_.alive(s); ++t) s = s + 1 < slots ? s + 1 : 0;
  start = s;
  return true;
}

// Flattened: g++ 12 left the search, the conflict test and the in-sphere
// filter out of line here (inline in the serial insert); with them inline the
// two-thread run of 10^5 uniform 3D points executes 2 723 M -> 2 508 M
// instructions (callgrind, whole process; serial 2 050 M).
template <class K, int D>
template <class Guard>
[[gnu::flatten]] typename ParallelBowyerWatson<K, D>::Status ParallelBowyerWatson<K, D>::insert(Worker& w, Guard& guard,
                                                                               std::uint32_t i, bool alone) {
  const Point<D>& p = pts_[i];
  std::uint32_t start = 0;
  if (!start_simplex(w, guard, start, alone)) return abandon(w, guard);
  // As in the serial algorithm: an exact walk never revisits a simplex.
  const std::uint64_t bound = 4ull * mesh_.slots() + 1000;
  const Located loc = visibility_walk<K, D>(w.k, mesh_, pts_, start, p, bound, w.rng, guard);
  w.walk_steps += loc.steps;
  if (loc.end == Located::End::blocked) return abandon(w, guard);  // w.last stays: see the header
  if (loc.end == Located::End::step_bound) {
    // Other workers may have changed the mesh under a long walk: only a walk
    // alone proves a bug.
    if (!alone) return abandon(w, guard);
    w.message = "point location exceeded its bound of " + std::to_string(bound) + " steps at insertion #" +
                std::to_string(i) + " (a bug: the kernel is exact)";
    return Status::failed;
  }
  if (loc.end == Located::End::inside && loc.zeros > 0) {
    for (int j = 0; j < V; ++j) {
      const std::uint32_t v = mesh_.vertex(loc.simplex, j);
      if (v != kGhost && pts_[v] == p) {
        merged_[i] = v;
        ++w.duplicates;
        w.last = loc.simplex;
        guard.release_all();
        return Status::inserted;
      }
    }
  }
  bool searched;
  if constexpr (D == 2) {  // records in cycle order: Restar links them without a table
    const std::uint32_t step = 2 * threads_;
    if (std::uint64_t{w.stamp} + step + 1 > PartitionGuard<2>::kStampLimit) return abandon(w, guard);  // reset between rounds
    w.stamp += step;
    searched = search_cavity_ccw<K>(w.k, mesh_, pts_, i, loc.simplex, w.stamp, w.stamp + 1, w.cavity, w.records,
                                    w.edges, guard);
  } else {  // the stamps are bits in the neighbour words: cleared before anything else reads them
    constexpr std::uint32_t in = PartitionGuard<3>::kIn, out = PartitionGuard<3>::kOut;
    searched = search_cavity<K, D>(w.k, mesh_, pts_, i, loc.simplex, in, out, w.cavity, w.records, guard);
    for (std::uint32_t s : w.cavity) guard.unmark(mesh_, s, in);
    for (const BoundaryRecord<D>& r : w.records) guard.unmark(mesh_, Mesh<D>::simplex_of(r.outside), out);
  }
  if (!searched) return abandon(w, guard);
  const std::size_t extra = w.records.size() > w.cavity.size() ? w.records.size() - w.cavity.size() : 0;
  if (!w.slots.prepare(extra, reserve_next_, reserve_end_)) return abandon(w, guard);

  w.cavity_total += w.cavity.size();
  w.cavity_max = std::max<std::uint64_t>(w.cavity_max, w.cavity.size());
  w.cavity_sizes.add(w.cavity.size());
  w.boundary_max = std::max<std::uint64_t>(w.boundary_max, w.records.size());
  w.created += w.records.size();
  std::string err;
  const std::uint32_t first = w.restar.star(w.slots, w.cavity, w.records, err);
  if (!err.empty()) {
    w.message = "insertion #" + std::to_string(i) + ": " + err + " (a bug: the kernel is exact)";
    return Status::failed;
  }
  merged_[i] = i;
  w.last = first;
  guard.release_all();
  return Status::inserted;
}

// The mesh holds at least `slots` unclaimed reserve slots (between rounds
// only).  The reserve is always the mesh's last slots, so it grows in place:
// blocks the workers claimed stay theirs.
template <class K, int D>
void ParallelBowyerWatson<K, D>::ensure_reserve(std::size_t slots) {
  const std::uint32_t next = std::min(reserve_next_.load(std::memory_order_relaxed), reserve_end_);
  if (reserve_end_ - next >= slots) return;
  // The new slots are written by the workers when there are several (the
  // first touch of a page is the kernel zeroing it: 6.5 % of the cycles of 10^6
  // points in 3D on two threads when one thread wrote them between rounds).
  // Small reserves too, so that the tests' runs take this path.
  auto write = [&](std::uint32_t first, std::uint32_t last, auto&& write_range) {
    if (threads_ == 1 || last - first < (1u << 12)) return write_range(first, last);
    on_workers(tbb::blocked_range<std::uint32_t>(first, last, 1u << 12), tbb::auto_partitioner(),
               [&](const tbb::blocked_range<std::uint32_t>& r) { write_range(r.begin(), r.end()); });
  };
  mesh_.add_reserve(std::max<std::size_t>(slots, mesh_.slots() / 8), write);
  reserve_next_.store(next, std::memory_order_relaxed);
  reserve_end_ = mesh_.slots();
  for (Worker& w : workers_) bind(w.guard);
}

// Stamps stay below PartitionGuard::kStampLimit: clear every mark, between
// rounds, when `insertions` more (2T stamps each, all by one worker at worst)
// might not fit.
template <class K, int D>
void ParallelBowyerWatson<K, D>::reset_stamps_if_needed(std::uint64_t insertions) {
  if constexpr (D == 3) return;  // TopBitMarks: no stamps
  const std::uint64_t need = 2ull * threads_ * (insertions + 64);
  bool reset = false;
  for (const Worker& w : workers_) reset = reset || w.stamp + need > PartitionGuard<2>::kStampLimit;
  if (!reset) return;
  for (std::uint32_t s = 0; s < mesh_.slots(); ++s) mesh_.set_mark(s, 0);
  for (std::size_t t = 0; t < workers_.size(); ++t) workers_[t].stamp = static_cast<std::uint32_t>(2 * t);
}

// Worker 0 alone, on the calling thread: every point is inserted (the reserve
// grows when a cavity needs it) or the run fails.
template <class K, int D>
void ParallelBowyerWatson<K, D>::insert_alone(const std::vector<std::uint32_t>& points) {
  Worker& w = workers_[0];
  std::conditional_t<D == 3, TopBitMarks, NoGuard> alone;  // the stamps where the tasks keep them
  for (std::uint32_t i : points) {
    for (std::size_t room = 256;; room *= 4) {
      ensure_reserve(room);
      reset_stamps_if_needed(1);
      const Status st = insert(w, alone, i, true);
      if (st == Status::failed) {
        failed_.store(true, std::memory_order_relaxed);
        return;
      }
      if (st == Status::inserted) break;
      // Deferred alone: only the reserve (or the stamps) ran out.  A cavity
      // needs at most one new slot per boundary facet.
      if (room > 4ull * mesh_.slots() + 4096) {
        w.message = "insertion #" + std::to_string(i) + " could not be completed (a bug)";
        failed_.store(true, std::memory_order_relaxed);
        return;
      }
    }
    ++alone_insertions_;
  }
}

// Between rounds: each point below label_end_ labelled with its box (a
// vertex's label is what PartitionGuard compares).
template <class K, int D>
void ParallelBowyerWatson<K, D>::label_vertices(const KdBoxes<D>& boxes) {
  auto label = [&](std::uint32_t first, std::uint32_t last) {
    for (std::uint32_t i = first; i < last; ++i) box_of_vertex_[i] = static_cast<std::uint8_t>(boxes.box_of(pts_[i]));
  };
  if (label_end_ < (1u << 14)) return label(0, label_end_);
  on_workers(tbb::blocked_range<std::uint32_t>(0, label_end_, 1u << 14), tbb::auto_partitioner(),
             [&](const tbb::blocked_range<std::uint32_t>& r) { label(r.begin(), r.end()); });
}

// A live simplex (between rounds): a worker's last one, or the first live slot
// (the mesh always has one).
template <class K, int D>
std::uint32_t ParallelBowyerWatson<K, D>::live_simplex() {
  for (const Worker& w : workers_)
    if (w.last < mesh_.slots() && mesh_.alive(w.last)) return w.last;
  std::uint32_t s = 0;
  while (s + 1 < mesh_.slots() && !mesh_.alive(s)) ++s;
  return s;
}

// Between rounds, on the calling thread: the simplex holding one of a few of
// the box's points, if all its vertices are in the box (so no other task
// deletes it), else kNoStart.  The middle point first: a box's first points in
// Hilbert order are where the curve enters it, on its boundary.
template <class K, int D>
void ParallelBowyerWatson<K, D>::find_start(Cell& cell, std::uint8_t box) {
  PartitionGuard<D> guard;
  bind(guard);
  guard.set_box(box);
  const std::uint64_t bound = 4ull * mesh_.slots() + 1000;
  cell.start = kNoStart;
  std::uint32_t from = live_simplex();
  const std::size_t m = cell.points.size();
  for (std::size_t tries = 0, j = m / 2; tries < std::min<std::size_t>(8, m); ++tries, j = (j + m / 8 + 1) % m) {
    const Located loc = visibility_walk<K, D>(k_, mesh_, pts_, from, pts_[cell.points[j]], bound, rng_);
    if (loc.end == Located::End::step_bound) return;  // the alone insertions will report it
    if (guard.acquire(loc.simplex)) {
      cell.start = loc.simplex;
      return;
    }
    from = loc.simplex;
  }
}

// One batch: rounds of up to T tasks, one box each, then the remainder alone.
// A point is deferred when its walk or cavity meets a box's side, within a
// few point spacings of it, so small boxes defer most of their points (3D, 10^6
// uniform points, T boxes of the whole mesh: 0.09 deferrals a point at T = 2,
// 0.45 at T = 4, 3.3 at T = 16; papers/triangulation_costs.md, session 43):
// each box gets at least vertices_per_box_ of the mesh's vertices, two boxes
// at least, and the threads beyond that wait.
template <class K, int D>
void ParallelBowyerWatson<K, D>::insert_batch(std::vector<std::uint32_t> points, std::size_t before) {
  const std::size_t T = threads_;
  const std::size_t boxes = std::min(T, std::max<std::size_t>(2, before / vertices_per_box_));
  // The axes, widest extent of the batch first: round r cuts first along
  // axes[r % D], then the next ones.
  std::array<int, D> axes;
  {
    std::array<double, D> lo, hi;
    lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    for (std::uint32_t i : points)
      for (int a = 0; a < D; ++a) lo[a] = std::min(lo[a], pts_[i][a]), hi[a] = std::max(hi[a], pts_[i][a]);
    for (int a = 0; a < D; ++a) axes[a] = a;
    std::stable_sort(axes.begin(), axes.end(), [&](int a, int b) { return hi[a] - lo[a] > hi[b] - lo[b]; });
  }
  for (std::size_t round = 0; !points.empty() && !failed_.load(std::memory_order_relaxed); ++round) {
    if (T == 1 || points.size() < 64 * T) {
      insert_alone(points);
      return;
    }
    // About 6.75 new tetrahedra per point in 3D, 2 triangles in 2D (the
    // serial algorithm's reservation); a worker that runs out defers its
    // points to the next round.
    ensure_reserve(points.size() * (D == 3 ? 7 : 2) + T * 2 * WorkerSlots<D>::kBlock);
    reset_stamps_if_needed(points.size());
    std::array<int, D> order;
    for (int a = 0; a < D; ++a) order[a] = axes[(round + a) % D];
    // The cuts at the quantiles of every stride-th point (about 2^14 of them,
    // along the Hilbert curve: an even sample), and each point's share read
    // off its label.  Cutting all the points on the calling thread took 40 ms
    // of 270 (10^6 uniform 2D points, two threads); this cut, the labels and
    // the shares take 4, 6 and 9 ms (papers/triangulation_costs.md, session 45).
    const std::size_t stride = std::max<std::size_t>(1, points.size() >> 14);
    std::vector<std::uint32_t> sample;
    for (std::size_t j = 0; j < points.size(); j += stride) sample.push_back(points[j]);
    const KdBoxes<D> cut = cut_at_quantiles<D>(pts_, std::move(sample), order, boxes);
    label_vertices(cut);
    std::vector<Cell> cells(cut.size());
    {
      std::vector<std::size_t> size(cells.size(), 0);
      for (std::uint32_t i : points) ++size[box_of_vertex_[i]];
      for (std::size_t t = 0; t < cells.size(); ++t) cells[t].points.reserve(size[t]);
    }
    for (std::uint32_t i : points) cells[box_of_vertex_[i]].points.push_back(i);
    for (std::size_t t = 0; t < cells.size(); ++t) find_start(cells[t], static_cast<std::uint8_t>(t));
    // One task a box, on whichever thread is free; each thread inserts with
    // the worker of its arena slot.
    on_workers(tbb::blocked_range<std::size_t>(0, cells.size(), 1), tbb::simple_partitioner(),
               [&](const tbb::blocked_range<std::size_t>& range) {
                 Worker& w = workers_[static_cast<std::size_t>(tbb::this_task_arena::current_thread_index())];
                 w.handoff.fetch_add(1, std::memory_order_acquire);
                 for (std::size_t t = range.begin(); t < range.end(); ++t) {
                   Cell& cell = cells[t];
                   w.guard.set_box(static_cast<std::uint8_t>(t));
                   w.last = cell.start;
                   for (std::size_t j = 0; j < cell.points.size(); ++j) {
                     const std::uint32_t i = cell.points[j];
                     if (failed_.load(std::memory_order_relaxed)) {
                       cell.deferred.insert(cell.deferred.end(), cell.points.begin() + j, cell.points.end());
                       break;
                     }
                     const Status st = insert(w, w.guard, i, false);
                     if (st == Status::deferred) {
                       cell.deferred.push_back(i);
                       ++w.deferrals;
                     } else if (st == Status::failed) {
                       failed_.store(true, std::memory_order_relaxed);
                     }
                   }
                 }
                 w.handoff.fetch_add(1, std::memory_order_release);
               });
    ++rounds_;
    // The boxes that inserted a point: T of them at best (fewer when a task's
    // points all waited, or its box owned none of the mesh).
    const auto busy = std::count_if(cells.begin(), cells.end(),
                                    [](const Cell& c) { return c.deferred.size() < c.points.size(); });
    boxes_max_ = std::max<std::uint64_t>(boxes_max_, static_cast<std::uint64_t>(busy));
    std::vector<std::uint32_t> rest;
    for (const Cell& cell : cells) rest.insert(rest.end(), cell.deferred.begin(), cell.deferred.end());
    if (rest.size() == points.size() && round + 1 >= D) {  // no progress along any axis: one worker does the rest
      insert_alone(rest);
      return;
    }
    points.swap(rest);
  }
}

template <class K, int D>
TriangulationResult ParallelBowyerWatson<K, D>::run(std::span<const Point<D>> pts) {
  TriangulationResult res;
  pts_ = pts.data();
  const std::size_t n = pts.size();
  if constexpr (D == 3) {  // PartitionGuard<3> keeps its stamps in the neighbour words
    mesh_.without_marks();
    mesh_.limit_slots(TopBitMarks::kMaxSlots);
  }
  const std::optional<IncrementalStart<D>> first = start_incremental_mesh<D>(k_, pts, mesh_, res);
  if (!first) return res;
  merged_.assign(n, kNotProcessed);
  for (std::uint32_t id : first->ids) merged_[id] = id;
  box_of_vertex_ = huge_vector<std::uint8_t>(n);
  label_end_ = *std::max_element(first->ids.begin(), first->ids.end()) + 1;
  // Room for 7.5 tetrahedra (2.25 triangles) a point, more than
  // start_incremental_mesh's 7 (2): the batches' reserve of 7 (2) a point and
  // a slack went past it at the last batch, which copied the whole mesh
  // (session 28).  The reserve now grows in place, and room never written
  // costs no memory.
  mesh_.reserve(n * (D == 3 ? 30 : 9) / 4 + 4096);
  reserve_next_.store(mesh_.slots(), std::memory_order_relaxed);
  reserve_end_ = mesh_.slots();

  workers_.clear();
  // T threads even on fewer cores (oneTBB would otherwise cap them at the
  // core count): the result must not depend on it, and tests check that.
  tbb::global_control threads_allowed(tbb::global_control::max_allowed_parallelism, threads_);
  if (threads_ > 1 && !arena_.is_active()) arena_.initialize(static_cast<int>(threads_));
  for (unsigned t = 0; t < threads_; ++t) {
    workers_.emplace_back(k_, mesh_);
    bind(workers_.back().guard);
    workers_.back().last = first->simplex;
    workers_.back().stamp = 2 * t;
  }

  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i)
    if (merged_[i] == kNotProcessed) order.push_back(i);
  // Alone until the mesh has room for T regions, then batches that double.
  std::size_t pos = std::min(order.size(), std::size_t{256} * threads_);
  insert_alone(std::vector<std::uint32_t>(order.begin(), order.begin() + pos));
  while (pos < order.size() && !failed_.load(std::memory_order_relaxed)) {
    const std::size_t end = std::min(order.size(), 2 * pos);
    label_end_ = std::max(label_end_, order[end - 1] + 1);  // the batch's points in order
    insert_batch(std::vector<std::uint32_t>(order.begin() + pos, order.begin() + end), pos);
    pos = end;
  }

  std::int64_t live = 0;
  for (Worker& w : workers_) {
    live += w.slots.live_delta();
    add_thread_counts(k_, w.k);
  }
  mesh_.adjust_live(live);
  if (failed_.load(std::memory_order_relaxed)) {
    res.outcome = RunOutcome::failed;
    for (const Worker& w : workers_)
      if (res.message.empty()) res.message = w.message;
  }

  std::uint64_t walk = 0, total = 0, cmax = 0, bmax = 0, created = 0, dups = 0, deferrals = 0;
  CavityHistogram sizes;
  for (const Worker& w : workers_) {
    walk += w.walk_steps;
    total += w.cavity_total;
    cmax = std::max(cmax, w.cavity_max);
    bmax = std::max(bmax, w.boundary_max);
    created += w.created;
    dups += w.duplicates;
    deferrals += w.deferrals;
    sizes.add(w.cavity_sizes);
  }
  std::size_t restar_bytes = 0;
  for (const Worker& w : workers_) restar_bytes += w.restar.bytes_reserved();
  res.counters = {
      {"walk_steps", walk},
      {"cavity_simplices", total},
      {"max_cavity_simplices", cmax},
      {"max_cavity_boundary", bmax},
      {"simplices_created", created},
      {"duplicates", dups},
      {"mesh_slots", mesh_.slots()},
      {"mesh_bytes_reserved", mesh_.bytes_reserved() + restar_bytes},
      {"threads", threads_},
      {"parallel_rounds", rounds_},
      {"parallel_boxes_max", boxes_max_},
      {"deferred_insertions", deferrals},
      {"insertions_alone", alone_insertions_},
  };
  sizes.append_to(res.counters);
  // Last, as it hands the mesh's memory over to the result (Mesh::take_finite_simplices:
  // mesh() is then empty unless keep_mesh() was called).
  if (res.outcome == RunOutcome::ok)
    res.simplices = keep_mesh_ ? Mesh<D>(mesh_).take_finite_simplices() : mesh_.take_finite_simplices();
  res.merged_into = std::move(merged_);
  return res;
}

}  // namespace dlab
