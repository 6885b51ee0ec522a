// The parallel Bowyer–Watson (algorithms/parallel_bowyer_watson.hpp): for any
// number of threads its simplices, in canonical order, are those of the serial
// Bowyer–Watson (itself checked against CGAL by the oracle tests), and the
// exact validator finds them valid and Delaunay.  The inputs are chosen so
// that the workers meet: random sets, integer lattices (every cell
// cocircular / cospherical: the perturbation decides), duplicates.
//
// Header-only on purpose (no dlab_core): .ci/run compiles this file alone
// under ThreadSanitizer (executable dlab_parallel_tests, -DDLAB_TSAN=ON), and
// a race between the workers (two slabs writing one word) is a report there.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <numeric>
#include <random>
#include <rapidcheck.h>
#include <rapidcheck/catch.h>
#include <utility>
#include <vector>

#include "algorithms/bowyer_watson.hpp"
#include "algorithms/canonical_simplices.hpp"
#include "algorithms/kd_boxes.hpp"
#include "algorithms/parallel_bowyer_watson.hpp"
#include "algorithms/simplex_guard.hpp"
#include "algorithms/validate.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/counted.hpp"
#include "predicates/mp_kernel.hpp"
#include "predicates/perturbed.hpp"
#include "variants/insertion_order.hpp"

using namespace dlab;

namespace {

std::uint64_t counter(const TriangulationResult& r, const std::string& name) {
  for (const auto& [n, v] : r.counters)
    if (n == name) return v;
  FAIL("no counter " << name);
  return 0;
}

// Points in BRIO order (as the driver inserts them).
template <int D>
std::vector<Point<D>> in_brio_order(const std::vector<Point<D>>& pts, std::uint64_t seed) {
  const auto order = insertion_order(std::span<const Point<D>>(pts), InsertionOrder::brio, seed);
  std::vector<Point<D>> seq(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) seq[i] = pts[order[i]];
  return seq;
}

// Duplicates are merged into the copy inserted first, which the schedule
// decides: every vertex is mapped to the first index of its position (as the
// driver maps to the first input occurrence).
template <int D>
std::vector<std::uint32_t> first_occurrence(const std::vector<Point<D>>& seq, std::vector<std::uint32_t> flat) {
  std::vector<std::uint32_t> first(seq.size()), by_point(seq.size());
  for (std::uint32_t i = 0; i < seq.size(); ++i) by_point[i] = i;
  std::stable_sort(by_point.begin(), by_point.end(), [&](auto a, auto b) { return seq[a] < seq[b]; });
  for (std::size_t j = 0; j < by_point.size(); ++j)
    first[by_point[j]] = j > 0 && seq[by_point[j]] == seq[by_point[j - 1]] ? first[by_point[j - 1]] : by_point[j];
  for (std::uint32_t& v : flat) v = first[v];
  return flat;
}

struct Totals {
  std::uint64_t rounds = 0, deferrals = 0;
};

// Serial against parallel on T = 1, 2, 3, 4, 8 threads, with kernel K.
template <class K, int D>
void check_all_thread_counts(const std::vector<Point<D>>& pts, std::uint64_t seed, Totals& totals) {
  const std::vector<Point<D>> seq = in_brio_order<D>(pts, seed);
  BowyerWatson<K, D> serial;
  const TriangulationResult s = serial.run(std::span<const Point<D>>(seq));
  REQUIRE(s.outcome == RunOutcome::ok);
  const auto expected = canonical_simplices<D>(first_occurrence<D>(seq, s.simplices));
  for (unsigned t : {1u, 2u, 3u, 4u, 8u}) {
    ParallelBowyerWatson<K, D> par;
    par.set_threads(t);
    par.set_vertices_per_box(256);  // T boxes on these small sets, not two
    par.keep_mesh();
    const TriangulationResult p = par.run(std::span<const Point<D>>(seq));
    INFO("threads " << t << ", " << seq.size() << " points in " << D << "D");
    REQUIRE(p.outcome == RunOutcome::ok);
    REQUIRE(par.mesh().check_structure().empty());
    const std::vector<std::uint32_t> mapped = first_occurrence<D>(seq, p.simplices);
    const bool same = canonical_simplices<D>(mapped) == expected;  // (not printed: thousands of simplices)
    CHECK(same);
    const ValidationReport v = validate(std::span<const Point<D>>(seq), std::span<const std::uint32_t>(mapped));
    CHECK(v.delaunay());
    totals.rounds += counter(p, "parallel_rounds");
    if (counter(p, "parallel_rounds") > 0) {  // boxes inserting at once (a small 3D box may own nothing)
      CHECK(counter(p, "parallel_boxes_max") >= 2);
      CHECK(counter(p, "parallel_boxes_max") <= t);
    }
    totals.deferrals += counter(p, "deferred_insertions");
  }
}

template <int D>
std::vector<Point<D>> uniform(std::mt19937_64& rng, std::size_t n) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point<D>> p(n);
  for (auto& q : p)
    for (double& c : q) c = u(rng);
  return p;
}

// Integer lattice points with repeats: co-circular / co-spherical everywhere.
template <int D>
std::vector<Point<D>> lattice_with_duplicates(std::mt19937_64& rng, std::size_t n, int side) {
  std::uniform_int_distribution<int> u(0, side - 1);
  std::vector<Point<D>> p(n);
  for (auto& q : p)
    for (double& c : q) c = u(rng);
  return p;
}

using Adaptive = counted<perturbed<AdaptiveKernel>>;
using Mp = counted<perturbed<MpKernel>>;

}  // namespace

// Would catch: a lost or doubled insertion, an adjacency written without its
// lock (a torn cavity), a deferred point never retried, duplicates merged
// differently, any dependence of the result on the thread count.
TEST_CASE("parallel bowyer-watson: same triangulation as the serial one for every thread count",
          "[parallel_bowyer_watson]") {
  Totals totals;
  std::mt19937_64 rng(20261124);
  for (int rep = 0; rep < 2; ++rep) {
    check_all_thread_counts<Adaptive, 2>(uniform<2>(rng, 6000), rep, totals);
    check_all_thread_counts<Adaptive, 3>(uniform<3>(rng, 4000), rep, totals);
    check_all_thread_counts<Adaptive, 2>(lattice_with_duplicates<2>(rng, 5000, 60), rep, totals);
    check_all_thread_counts<Adaptive, 3>(lattice_with_duplicates<3>(rng, 4000, 14), rep, totals);
  }
  check_all_thread_counts<Mp, 3>(lattice_with_duplicates<3>(rng, 2500, 10), 7, totals);
  // The parallel path ran, and workers met (points were put back and retried):
  // otherwise this test would prove nothing about the locking.
  CHECK(totals.rounds > 0);
  CHECK(totals.deferrals > 0);
}

TEST_CASE("parallel bowyer-watson: random small sets, 2 and 5 threads", "[parallel_bowyer_watson]") {
  rc::prop("equals the serial triangulation", [](std::uint64_t seed, bool three_d, bool lattice) {
    std::mt19937_64 rng(seed);
    const std::size_t n = 1500 + seed % 1500;  // at least one parallel round for T = 2
    Totals totals;
    if (three_d)
      check_all_thread_counts<Adaptive, 3>(lattice ? lattice_with_duplicates<3>(rng, n, 9) : uniform<3>(rng, n),
                                           seed, totals);
    else
      check_all_thread_counts<Adaptive, 2>(lattice ? lattice_with_duplicates<2>(rng, n, 30) : uniform<2>(rng, n),
                                           seed, totals);
    RC_ASSERT(totals.rounds > 0);
  });
}

namespace {

// The promise the parallel rounds rest on (algorithms/simplex_guard.hpp,
// PartitionGuard): with space cut into boxes, every point is in one box, no
// simplex is owned by two boxes, two simplices owned by different boxes are
// never neighbours, and a simplex next to simplices of two boxes (which both
// tasks may read and stamp) is a 2D ghost owned by neither, reached through
// two different facets (so the two tasks write different neighbour words).
template <int D>
void check_boxes_never_share(const std::vector<Point<D>>& pts, int a, unsigned across, int b, unsigned down) {
  ParallelBowyerWatson<Adaptive, D> par;
  par.set_threads(1);
  par.keep_mesh();
  REQUIRE(par.run(std::span<const Point<D>>(pts)).outcome == RunOutcome::ok);
  const Mesh<D>& m = par.mesh();
  // The rounds' boxes: `across` slabs along axis a, each cut into `down` along b.
  std::array<int, D> axes{a, b};
  if constexpr (D == 3) axes[2] = 3 - a - b;
  std::vector<std::uint32_t> all(pts.size());
  std::iota(all.begin(), all.end(), 0u);
  const KdBoxes<D> cut = cut_at_quantiles<D>(pts.data(), all, axes, across * down);
  REQUIRE(cut.size() == across * down);
  // Each point in exactly one half-open box (checked here on the bounds), the
  // one box_of finds and whose share holds it.
  bool one_box_each = true;
  std::vector<std::uint8_t> label(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    unsigned n = 0;
    std::size_t in = 0;
    for (std::size_t t = 0; t < cut.size(); ++t) {
      bool inside = true;
      for (int x = 0; x < D; ++x) inside = inside && cut.lo[t][x] <= pts[i][x] && pts[i][x] < cut.hi[t][x];
      if (inside) ++n, in = t;
    }
    one_box_each = one_box_each && n == 1 && cut.box_of(pts[i]) == in;
    label[i] = static_cast<std::uint8_t>(cut.box_of(pts[i]));
  }
  CHECK(one_box_each);
  bool shares_agree = true;
  std::size_t shared = 0;
  for (std::size_t t = 0; t < cut.size(); ++t) {
    shared += cut.shares[t].size();
    for (std::uint32_t i : cut.shares[t]) shares_agree = shares_agree && label[i] == t;
  }
  CHECK(shares_agree);
  CHECK(shared == pts.size());
  std::vector<PartitionGuard<D>> boxes(cut.size());
  for (std::size_t t = 0; t < cut.size(); ++t) {
    boxes[t].bind(m, label.data());
    boxes[t].set_box(static_cast<std::uint8_t>(t));
  }
  const std::size_t T = boxes.size();
  INFO(T << " boxes, axes " << a << " and " << b << ", " << pts.size() << " points in " << D << "D");
  constexpr int kNobody = -1;
  std::vector<int> owner(m.slots(), kNobody);
  std::vector<unsigned> owned(T, 0);
  bool one_owner = true;
  for (std::uint32_t s = 0; s < m.slots(); ++s) {
    if (!m.alive(s)) continue;
    for (std::size_t t = 0; t < T; ++t)
      if (boxes[t].acquire(s)) {
        one_owner = one_owner && owner[s] == kNobody;
        owner[s] = static_cast<int>(t);
        ++owned[t];
      }
  }
  CHECK(one_owner);
  // Else the test proves nothing (a box one lattice layer thick owns no tetrahedron).
  CHECK(std::count_if(owned.begin(), owned.end(), [](unsigned n) { return n > 0; }) >= 2);
  // reached[s]: the (box, facet of s) of each owned neighbour of s.
  std::vector<std::vector<std::pair<int, int>>> reached(m.slots());
  bool owned_neighbours_share_box = true;
  for (std::uint32_t s = 0; s < m.slots(); ++s) {
    if (!m.alive(s) || owner[s] == kNobody) continue;
    for (int f = 0; f <= D; ++f) {
      const std::uint32_t enc = m.neighbour(s, f);
      const std::uint32_t n = Mesh<D>::simplex_of(enc);
      if (owner[n] != kNobody) owned_neighbours_share_box = owned_neighbours_share_box && owner[n] == owner[s];
      reached[n].push_back({owner[s], Mesh<D>::facet_of(enc)});
    }
  }
  CHECK(owned_neighbours_share_box);
  bool shared_only_as_2d_ghosts = true;
  for (std::uint32_t s = 0; s < m.slots(); ++s)
    for (const auto& [t, f] : reached[s])
      for (const auto& [u, g] : reached[s])
        if (t != u && !(D == 2 && owner[s] == kNobody && m.is_ghost(s) && f != g)) shared_only_as_2d_ghosts = false;
  CHECK(shared_only_as_2d_ghosts);
}

}  // namespace

// Would catch: a point on a cut labelled with the wrong box (box_of or the
// shares disagreeing with the half-open bounds), an ownership test that skips
// a vertex, or a 3D simplex two boxes can both reach.
TEST_CASE("parallel bowyer-watson: boxes never share a simplex they write", "[parallel_bowyer_watson]") {
  std::mt19937_64 rng(20261207);
  for (auto [across, down] : {std::pair{2u, 1u}, std::pair{7u, 1u}, std::pair{2u, 2u}, std::pair{3u, 2u}})
    for (int a = 0; a < 2; ++a) {
      const int b = 1 - a;
      check_boxes_never_share<2>(uniform<2>(rng, 3000), a, across, b, down);
      check_boxes_never_share<2>(lattice_with_duplicates<2>(rng, 2000, 25), a, across, b, down);
      check_boxes_never_share<3>(uniform<3>(rng, 2000), a, across, 2, down);
      check_boxes_never_share<3>(lattice_with_duplicates<3>(rng, 2000, 9), 2, across, a, down);
    }
}

// Would catch: a task whose walk a box refused starting its next walk where
// that walk stopped, at the box's side: one refused facet there can separate
// it from all the task's later points, which then all wait for the next round
// (10^6 uniform 2D points, BRIO seed 1: 77 000 of one box's 238 000 points in
// a row, 111 000 deferrals in the whole run against 19 000).  Not in the
// ThreadSanitizer stage (tag): its 8*10^5 insertions would take minutes there.
TEST_CASE("parallel bowyer-watson: a refused walk does not strand the task's later points",
          "[parallel_bowyer_watson_deferrals]") {
  std::mt19937_64 rng(20261208);
  const std::vector<Point<2>> pts = uniform<2>(rng, 200000);
  std::uint64_t deferrals = 0;
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    ParallelBowyerWatson<Adaptive, 2> par;
    par.set_threads(2);
    const std::vector<Point<2>> seq = in_brio_order<2>(pts, seed);
    const TriangulationResult p = par.run(std::span<const Point<2>>(seq));
    REQUIRE(p.outcome == RunOutcome::ok);
    INFO("BRIO seed " << seed << ": " << counter(p, "deferred_insertions") << " deferred");
    deferrals += counter(p, "deferred_insertions");
  }
  CHECK(deferrals <= 4 * 200000 / 20);  // 5 % of the points
}
