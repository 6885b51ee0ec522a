// The 2D depth-first cavity search (algorithms/cavity_search.hpp,
// search_cavity_ccw): the same cavity and boundary as the breadth-first
// search, with the boundary records in counterclockwise order around the
// cavity, so that each record's edge ends where the next one's begins (what
// Restar<2>::link_chain relies on to link the new triangles without a table).
// Checked on cavities of new points in a Delaunay mesh (Lawson's, kept by
// keep_mesh()), inside the hull and outside it (ghost triangles).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <span>
#include <tuple>
#include <vector>

#include "algorithms/cavity_search.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/locate.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

using K = perturbed<AdaptiveKernel>;

std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int>> sorted_records(
    const std::vector<BoundaryRecord<2>>& records) {
  std::vector<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t, std::uint32_t, int>> r;
  for (const auto& b : records) r.emplace_back(b.v[0], b.v[1], b.v[2], b.outside, b.slot);
  std::sort(r.begin(), r.end());
  return r;
}

}  // namespace

TEST_CASE("cavity search 2D: depth first gives the breadth-first cavity, its boundary in cycle order",
          "[cavity_search]") {
  const std::size_t n = 3000;
  std::vector<Point<2>> pts = gen::uniform<2>(n, 11);
  Lawson<K, 2> dt;
  dt.keep_mesh();
  REQUIRE(dt.run(std::span<const Point<2>>(pts)).outcome == RunResult::Outcome::ok);
  Mesh<2> m = dt.mesh();
  const K k;
  // New points: inside the unit square and around it (outside the hull).
  const std::vector<Point<2>> extra = gen::uniform<2>(400, 12);
  pts.push_back({0, 0});
  const std::uint32_t i = static_cast<std::uint32_t>(n);
  std::uint32_t stamp = 0x40000000u;
  std::vector<std::uint32_t> cavity_bfs, cavity_dfs;
  std::vector<BoundaryRecord<2>> records_bfs, records_dfs;
  std::vector<std::uint32_t> stack;
  WalkRng rng;
  std::uint32_t start = 0;
  while (!m.alive(start)) ++start;
  std::size_t outside = 0, largest = 0;
  for (std::size_t q = 0; q < extra.size(); ++q) {
    pts[i] = {extra[q][0] * 1.4 - 0.2, extra[q][1] * 1.4 - 0.2};
    const Located loc = visibility_walk<K, 2>(k, m, pts.data(), start, pts[i], 1u << 20, rng);
    REQUIRE((loc.end == Located::End::inside || loc.end == Located::End::outside));
    outside += loc.end == Located::End::outside;
    stamp += 4;
    NoGuard guard;
    REQUIRE(search_cavity<K, 2>(k, m, pts.data(), i, loc.simplex, stamp, stamp + 1, cavity_bfs, records_bfs,
                                guard));
    stamp += 4;
    REQUIRE(search_cavity_ccw<K>(k, m, pts.data(), i, loc.simplex, stamp, stamp + 1, cavity_dfs, records_dfs, stack,
                                 guard));
    largest = std::max(largest, cavity_dfs.size());
    // The same simplices and the same boundary facets.
    std::sort(cavity_bfs.begin(), cavity_bfs.end());
    std::vector<std::uint32_t> sorted_dfs = cavity_dfs;
    std::sort(sorted_dfs.begin(), sorted_dfs.end());
    REQUIRE(sorted_dfs == cavity_bfs);
    REQUIRE(sorted_records(records_dfs) == sorted_records(records_bfs));
    // Record r is the new triangle (p, u_r, w_r) in p's slot order; the next
    // record starts where it ends, around the whole cycle, and no vertex
    // starts two edges.
    const std::size_t kb = records_dfs.size();
    REQUIRE(kb == cavity_dfs.size() + 2);
    std::vector<std::uint32_t> starts;
    for (std::size_t r = 0; r < kb; ++r) {
      const BoundaryRecord<2>& a = records_dfs[r];
      const BoundaryRecord<2>& b = records_dfs[(r + 1) % kb];
      REQUIRE(a.v[a.slot] == i);
      REQUIRE(a.v[(a.slot + 2) % 3] == b.v[(b.slot + 1) % 3]);
      starts.push_back(a.v[(a.slot + 1) % 3]);
    }
    std::sort(starts.begin(), starts.end());
    REQUIRE(std::adjacent_find(starts.begin(), starts.end()) == starts.end());
  }
  // Both kinds of cavity were met, and some large ones.
  CHECK(outside > 20);
  CHECK(outside < extra.size() - 20);
  CHECK(largest >= 6);
}

// 3D, the serial Bowyer–Watson's TopBitMarks (algorithms/simplex_guard.hpp):
// marks in the top bits of neighbour words give the cavity and the boundary
// records of stamps in the mesh's mark array, the records' neighbour codes
// carry no mark bit, and unmarking what the search marked restores every word.
TEST_CASE("cavity search 3D: marks in the neighbour words' top bits give the stamps' cavity", "[cavity_search]") {
  const std::size_t n = 2000;
  std::vector<Point<3>> pts = gen::uniform<3>(n, 21);
  Lawson<K, 3> dt;
  dt.keep_mesh();
  REQUIRE(dt.run(std::span<const Point<3>>(pts)).outcome == RunResult::Outcome::ok);
  Mesh<3> m = dt.mesh();
  auto words = [](const Mesh<3>& mesh) {
    std::vector<std::uint32_t> w;
    for (std::uint32_t s = 0; s < mesh.slots(); ++s)
      if (mesh.alive(s))
        for (int j = 0; j < 4; ++j) w.insert(w.end(), {mesh.vertex(s, j), mesh.neighbour(s, j)});
    return w;
  };
  const std::vector<std::uint32_t> before = words(m);
  const K k;
  const std::vector<Point<3>> extra = gen::uniform<3>(300, 22);
  pts.push_back({0, 0, 0});
  const std::uint32_t i = static_cast<std::uint32_t>(n);
  std::uint32_t stamp = 0x40000000u;
  std::vector<std::uint32_t> cavity_stamped, cavity_bits;
  std::vector<BoundaryRecord<3>> records_stamped, records_bits;
  WalkRng rng;
  std::uint32_t start = 0;
  while (!m.alive(start)) ++start;
  std::size_t outside = 0, marked_out = 0;
  for (const Point<3>& q : extra) {
    pts[i] = {q[0] * 1.4 - 0.2, q[1] * 1.4 - 0.2, q[2] * 1.4 - 0.2};
    const Located loc = visibility_walk<K, 3>(k, m, pts.data(), start, pts[i], 1u << 20, rng);
    REQUIRE((loc.end == Located::End::inside || loc.end == Located::End::outside));
    outside += loc.end == Located::End::outside;
    stamp += 4;
    NoGuard stamps;
    REQUIRE(search_cavity<K, 3>(k, m, pts.data(), i, loc.simplex, stamp, stamp + 1, cavity_stamped,
                                records_stamped, stamps));
    TopBitMarks bits;
    REQUIRE(search_cavity<K, 3>(k, m, pts.data(), i, loc.simplex, TopBitMarks::kIn, TopBitMarks::kOut,
                                cavity_bits, records_bits, bits));
    REQUIRE(cavity_bits == cavity_stamped);
    REQUIRE(records_bits.size() == records_stamped.size());
    for (std::size_t r = 0; r < records_bits.size(); ++r) {
      REQUIRE(records_bits[r].v == records_stamped[r].v);
      REQUIRE(records_bits[r].outside == records_stamped[r].outside);
      REQUIRE(records_bits[r].slot == records_stamped[r].slot);
    }
    for (std::uint32_t s : cavity_bits) REQUIRE(TopBitMarks::mark(m, s) == TopBitMarks::kIn);
    for (const BoundaryRecord<3>& r : records_bits) {
      REQUIRE(TopBitMarks::mark(m, Mesh<3>::simplex_of(r.outside)) == TopBitMarks::kOut);
      ++marked_out;
    }
    for (std::uint32_t s : cavity_bits) TopBitMarks::unmark(m, s, TopBitMarks::kIn);
    for (const BoundaryRecord<3>& r : records_bits) TopBitMarks::unmark(m, Mesh<3>::simplex_of(r.outside), TopBitMarks::kOut);
    REQUIRE(words(m) == before);
  }
  CHECK(outside > 10);
  CHECK(outside < extra.size() - 10);
  CHECK(marked_out > 10 * extra.size());
}
