// The mesh's storage (algorithms/mesh.hpp): the mark words (2D keeps them in
// each block's padding, 3D in an array) and take_finite_simplices, which hands
// the slot array's pages back while it writes the result. Both are checked on
// meshes of a real triangulation (Lawson's, kept: keep_mesh()) large
// enough to span several release chunks (a 2 MiB huge page of slots each).
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "algorithms/bowyer_watson.hpp"
#include "algorithms/huge_pages.hpp"
#include "algorithms/lawson.hpp"
#include "algorithms/parallel_bowyer_watson.hpp"
#include "algorithms/simplex_guard.hpp"
#include "fuzz/generators.hpp"
#include "predicates/adaptive_kernel.hpp"
#include "predicates/perturbed.hpp"

using namespace dlab;

namespace {

template <int D>
Mesh<D> triangulated_mesh(std::size_t n) {
  const std::vector<Point<D>> pts = gen::uniform<D>(n, 7);
  Lawson<perturbed<AdaptiveKernel>, D> dt;
  dt.keep_mesh();
  REQUIRE(dt.run(std::span<const Point<D>>(pts)).outcome == RunResult::Outcome::ok);
  return dt.mesh();
}

// Every slot's words, read through the public accessors.
template <int D>
std::vector<std::uint32_t> all_words(const Mesh<D>& m) {
  std::vector<std::uint32_t> w;
  for (std::uint32_t s = 0; s < m.slots(); ++s) {
    for (int i = 0; i <= D; ++i) w.push_back(m.vertex(s, i));
    if (!m.alive(s)) continue;
    for (int i = 0; i <= D; ++i) w.push_back(m.neighbour(s, i));
  }
  return w;
}

template <int D>
void check_take(std::size_t n) {
  Mesh<D> m = triangulated_mesh<D>(n);
  REQUIRE(m.slots() > 4 * (kHugePage / 32));  // 32 bytes per slot
  Mesh<D> copy = m;
  std::vector<std::uint32_t> expected, without_vertex_0;
  m.for_each_finite([&](std::uint32_t s) {
    bool has_0 = false;
    for (int i = 0; i <= D; ++i) {
      expected.push_back(m.vertex(s, i));
      has_0 = has_0 || m.vertex(s, i) == 0;
    }
    if (!has_0)
      for (int i = 0; i <= D; ++i) without_vertex_0.push_back(m.vertex(s, i));
  });
  const std::vector<std::uint32_t> taken = m.take_finite_simplices();
  // A page released before it was read reads as zeros.  (Not decomposed:
  // Catch would print both vectors.)
  CHECK((taken == expected));
  CHECK(m.slots() == 0);
  CHECK(m.live() == 0);
  // With a filter (George's box corners are left out so).
  CHECK((copy.take_finite_simplices([](const std::uint32_t* v) { return std::find(v, v + D + 1, 0u) == v + D + 1; }) ==
         without_vertex_0));
}

template <int D>
void check_marks(std::size_t n) {
  Mesh<D> m = triangulated_mesh<D>(n);
  const std::vector<std::uint32_t> before = all_words(m);
  for (std::uint32_t s = 0; s < m.slots(); ++s) m.set_mark(s, 0xA5000000u ^ s);
  // A mark word that overlapped a vertex or a neighbour would change them.
  CHECK((all_words(m) == before));
  CHECK(m.check_structure().empty());
  bool all_read_back = true;
  for (std::uint32_t s = 0; s < m.slots(); ++s) all_read_back = all_read_back && m.mark(s) == (0xA5000000u ^ s);
  CHECK(all_read_back);
  // PartitionGuard<2>'s view of the same words (algorithms/simplex_guard.hpp).
  const MarkWords words = m.marks();
  CHECK(words[m.slots() - 1] == (0xA5000000u ^ (m.slots() - 1)));
  // Slots added at the end (create's path too, once the free list is empty)
  // start with mark 0, below every stamp.
  const std::uint32_t first = m.add_reserve(3);
  for (std::uint32_t s = first; s < first + 3; ++s) CHECK(m.mark(s) == 0);
}

// add_reserve's words are the same whichever ranges write them: the parallel
// Bowyer–Watson's workers write them in pieces, in any order (the vector grows
// without writing them: CacheAligned::construct).
template <int D>
void check_reserve_in_pieces() {
  Mesh<D> whole, pieces;
  auto backwards_in_pieces = [](std::uint32_t first, std::uint32_t last, auto&& write) {
    for (std::uint32_t hi = last; hi > first;) {
      const std::uint32_t lo = hi - std::min<std::uint32_t>(777, hi - first);
      write(lo, hi);
      hi = lo;
    }
  };
  for (std::size_t n : {100000u, 60000u}) {  // the second grows past the first's capacity
    const std::uint32_t a = whole.add_reserve(n), b = pieces.add_reserve(n, backwards_in_pieces);
    CHECK(a == b);
  }
  REQUIRE(whole.slots() == pieces.slots());
  bool dead = true, unset = true, unmarked = true;
  for (std::uint32_t s = 0; s < pieces.slots(); ++s) {
    dead = dead && !pieces.alive(s);
    unmarked = unmarked && pieces.mark(s) == 0;
    for (int f = 0; f <= D; ++f) unset = unset && pieces.neighbour(s, f) == kNoNeighbour;
  }
  CHECK(dead);
  CHECK(unset);
  CHECK(unmarked);
  CHECK((all_words(pieces) == all_words(whole)));
}

}  // namespace

TEST_CASE("mesh: add_reserve writes the same words whatever the ranges", "[mesh]") {
  check_reserve_in_pieces<2>();
  check_reserve_in_pieces<3>();
}

TEST_CASE("mesh: take_finite_simplices equals for_each_finite and empties the mesh", "[mesh]") {
  check_take<2>(150000);
  check_take<3>(60000);
}

TEST_CASE("mesh: marks are per slot, start at 0 and touch no other word", "[mesh]") {
  check_marks<2>(70000);
  check_marks<3>(30000);
}

TEST_CASE("mesh: without marks, 3D holds its blocks only", "[mesh]") {
  Mesh<3> m;
  m.without_marks();
  m.reserve(1000);
  CHECK(m.bytes_reserved() == 32u * 1000);
  CHECK(m.capacity() == 1000);
  // Slots added past the reserve add no mark words either.
  m.add_reserve(1500);
  Mesh<3> with_marks;
  with_marks.reserve(1000);
  with_marks.add_reserve(1500);
  CHECK(m.bytes_reserved() * 36 == with_marks.bytes_reserved() * 32);
}

// The 32-bit neighbour codes 4t + j name slots below 2^30 - 1 only (the last
// code, of slot 2^30 - 1, would be kNoNeighbour; slot 2^30 would wrap to 0).
TEST_CASE("mesh: kMaxSlots is the most slots the neighbour codes name", "[mesh]") {
  using M = Mesh<3>;
  const std::uint32_t last = M::kMaxSlots - 1;
  for (int f = 0; f < 4; ++f) {
    CHECK(M::encode(last, f) != kNoNeighbour);
    CHECK(M::simplex_of(M::encode(last, f)) == last);
    CHECK(M::facet_of(M::encode(last, f)) == f);
  }
  CHECK(M::encode(M::kMaxSlots, 3) == kNoNeighbour);  // one slot more is one too many
  CHECK(Mesh<2>::kMaxSlots == M::kMaxSlots);
}

TEST_CASE("mesh: growing past the slot limit throws instead of wrapping", "[mesh]") {
  Mesh<3> m;
  m.limit_slots(6);
  const std::array<std::uint32_t, 4> v{0, 1, 2, 3};
  for (int i = 0; i < 6; ++i) m.create(v);
  CHECK_THROWS_AS(m.create(v), MeshTooLarge);
  CHECK(m.slots() == 6);
  CHECK(m.live() == 6);
  m.destroy(2);
  CHECK(m.create(v) == 2);  // a freed slot is reused, not a new one
  CHECK_THROWS_AS(m.add_reserve(1), MeshTooLarge);
  Mesh<2> t;
  t.limit_slots(4);
  CHECK(t.add_reserve(4) == 0);
  CHECK_THROWS_AS(t.add_reserve(1), MeshTooLarge);
  CHECK(t.slots() == 4);
}

// The serial 3D Bowyer–Watson and 3D Lawson keep their marks in the neighbour
// codes' top bit (TopBitMarks), so their meshes must stop below 2^29 slots;
// 2D's go on to the codes' own limit.
TEST_CASE("mesh: the 3D Bowyer-Watson's (serial, parallel) and Lawson's meshes stop where their marks need", "[mesh]") {
  BowyerWatson<perturbed<AdaptiveKernel>, 3> bw3;
  const std::vector<Point<3>> p3 = gen::uniform<3>(50, 3);
  REQUIRE(bw3.run(std::span<const Point<3>>(p3)).outcome == RunResult::Outcome::ok);
  CHECK(bw3.mesh().max_slots() == TopBitMarks::kMaxSlots);
  ParallelBowyerWatson<perturbed<AdaptiveKernel>, 3> pbw3;  // PartitionGuard<3>: TopBitMarks' bits
  pbw3.set_threads(2);
  pbw3.keep_mesh();
  REQUIRE(pbw3.run(std::span<const Point<3>>(p3)).outcome == RunResult::Outcome::ok);
  CHECK(pbw3.mesh().max_slots() == TopBitMarks::kMaxSlots);
  CHECK(Mesh<3>::encode(TopBitMarks::kMaxSlots - 1, 3) < TopBitMarks::kBit);
  CHECK(Mesh<3>::encode(TopBitMarks::kMaxSlots, 0) >= TopBitMarks::kBit);  // one slot more would collide
  BowyerWatson<perturbed<AdaptiveKernel>, 2> bw2;
  const std::vector<Point<2>> p2 = gen::uniform<2>(50, 3);
  REQUIRE(bw2.run(std::span<const Point<2>>(p2)).outcome == RunResult::Outcome::ok);
  CHECK(bw2.mesh().max_slots() == Mesh<2>::kMaxSlots);
  CHECK(triangulated_mesh<3>(50).max_slots() == TopBitMarks::kMaxSlots);
  CHECK(triangulated_mesh<2>(50).max_slots() == Mesh<2>::kMaxSlots);
}

TEST_CASE("mesh: the slot array's allocator, huge-page aligned from a huge page on", "[mesh]") {
  // huge_page_range: the whole 2 MiB pages inside a range.
  constexpr std::uintptr_t H = kHugePage;
  CHECK(huge_page_range(0, H) == std::pair<std::uintptr_t, std::uintptr_t>{0, H});
  CHECK(huge_page_range(H, H - 1).first == huge_page_range(H, H - 1).second);  // less than a page
  CHECK(huge_page_range(1, H).first == huge_page_range(1, H).second);          // straddles two
  CHECK(huge_page_range(1, 2 * H) == std::pair<std::uintptr_t, std::uintptr_t>{H, 2 * H});
  CHECK(huge_page_range(H - 1, 3 * H + 1) == std::pair<std::uintptr_t, std::uintptr_t>{H, 4 * H});
  CHECK(huge_page_range(H - 1, 3 * H) == std::pair<std::uintptr_t, std::uintptr_t>{H, 3 * H});
  // Allocations of a huge page or more start on one (whole pages for the advice),
  // smaller ones on a cache line; either way the memory is usable.
  CacheAligned<std::uint32_t> a;
  for (const std::size_t n : {std::size_t{100}, kHugePage / 4 - 1, kHugePage / 4, kHugePage})
    for (int round = 0; round < 3; ++round) {
      std::uint32_t* p = a.allocate(n);
      const auto address = reinterpret_cast<std::uintptr_t>(p);
      CHECK(address % (n * sizeof(std::uint32_t) >= kHugePage ? kHugePage : 64) == 0);
      p[0] = 1, p[n - 1] = 2;
      CHECK(p[0] + p[n - 1] == 3);
      a.deallocate(p, n);
    }
}

