// The huge-page helpers (algorithms/huge_pages.hpp): reserve_huge,
// resize_huge, assign_huge, huge_vector and shrink_huge do what reserve,
// resize, assign, a sized constructor and shrink_to_fit do, and advise the new
// room's whole huge pages; the result of Mesh::take_finite_simplices is
// advised but for its first huge page (which would otherwise add 2 MiB to the
// run's peak). Whether the advice was given is read from the VmFlags of
// /proc/self/smaps ("hg": MADV_HUGEPAGE), which Linux shows whether or not
// huge pages are free; elsewhere, or where the kernel has no transparent huge
// pages, only the contents are checked.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "algorithms/huge_pages.hpp"
#include "algorithms/mesh.hpp"

using namespace dlab;

namespace {

// Whether the mapping holding address p was advised MADV_HUGEPAGE; nullopt
// when this system cannot say.
std::optional<bool> advised_huge(const void* p) {
#if defined(__linux__)
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled")) return std::nullopt;
  std::ifstream smaps("/proc/self/smaps");
  if (!smaps) return std::nullopt;
  const auto a = reinterpret_cast<std::uintptr_t>(p);
  bool inside = false;
  std::string line;
  while (std::getline(smaps, line)) {
    unsigned long lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
      inside = lo <= a && a < hi;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0) return line.find(" hg") != std::string::npos;
  }
  return std::nullopt;
#else
  (void)p;
  return std::nullopt;
#endif
}

// Rooms above glibc's largest mmap threshold (32 MiB), so that each is a
// mapping of its own, never advised before (a heap block could be).
constexpr std::size_t kBytes = 40 * kHugePage / 2;
constexpr std::size_t kWords = kBytes / sizeof(std::uint32_t);

std::vector<std::uint32_t> counting(std::size_t n) {
  std::vector<std::uint32_t> v(n);
  std::iota(v.begin(), v.end(), 7u);
  return v;
}

// The middle of v's room, a whole huge page away from both of its ends.
const void* middle_of_room(const std::vector<std::uint32_t>& v) { return v.data() + v.capacity() / 2; }

}  // namespace

TEST_CASE("huge pages: reserve_huge keeps the elements and advises the new room", "[huge_pages]") {
  std::vector<std::uint32_t> v = counting(1000);
  reserve_huge(v, kWords);
  CHECK(v.capacity() >= kWords);
  CHECK((v == counting(1000)));
  if (const auto hg = advised_huge(middle_of_room(v))) CHECK(*hg);
  // Only whole huge pages inside the room: not the one holding its start
  // (unless the room starts on a huge page's boundary).
  if (reinterpret_cast<std::uintptr_t>(v.data()) % kHugePage != 0)
    if (const auto hg = advised_huge(v.data())) CHECK_FALSE(*hg);
  // Less than the capacity: nothing moves.
  const std::uint32_t* at = v.data();
  reserve_huge(v, 10);
  CHECK(v.data() == at);
}

TEST_CASE("huge pages: resize_huge value-initializes the new elements", "[huge_pages]") {
  std::vector<std::uint32_t> v = counting(5);
  resize_huge(v, kWords);
  REQUIRE(v.size() == kWords);
  CHECK(v[4] == 11);
  CHECK(v[5] == 0);
  CHECK(v.back() == 0);
  if (const auto hg = advised_huge(middle_of_room(v))) CHECK(*hg);
}

TEST_CASE("huge pages: assign_huge fills the new room with the value", "[huge_pages]") {
  std::vector<std::uint32_t> v = counting(5);
  assign_huge(v, kWords, 9u);
  REQUIRE(v.size() == kWords);
  CHECK(v.front() == 9);
  CHECK(v.back() == 9);
  if (const auto hg = advised_huge(middle_of_room(v))) CHECK(*hg);
  // Within the capacity: in place.
  const std::uint32_t* at = v.data();
  assign_huge(v, 3, 4u);
  CHECK((v == std::vector<std::uint32_t>{4, 4, 4}));
  CHECK(v.data() == at);
}

TEST_CASE("huge pages: huge_vector holds n copies of the value", "[huge_pages]") {
  const std::vector<std::uint32_t> v = huge_vector(kWords, 5u);
  REQUIRE(v.size() == kWords);
  CHECK(v.front() == 5);
  CHECK(v.back() == 5);
  CHECK(huge_vector<std::uint32_t>(3) == std::vector<std::uint32_t>{0, 0, 0});
  if (const auto hg = advised_huge(middle_of_room(v))) CHECK(*hg);
}

TEST_CASE("huge pages: shrink_huge gives the slack back and keeps the elements", "[huge_pages]") {
  std::vector<std::uint32_t> v = counting(kWords);
  v.reserve(2 * kWords);
  shrink_huge(v);
  CHECK(v.capacity() == kWords);
  CHECK((v == counting(kWords)));
  if (const auto hg = advised_huge(middle_of_room(v))) CHECK(*hg);
}

TEST_CASE("huge pages: the taken result is advised but for its first huge page", "[huge_pages]") {
  // A mesh of isolated simplices is enough: take_finite_simplices copies
  // every live finite slot's vertices.
  Mesh<3> m;
  const std::size_t n = kWords / 4;
  m.reserve(n);
  for (std::uint32_t s = 0; s < n; ++s) m.create({4 * s, 4 * s + 1, 4 * s + 2, 4 * s + 3});
  const std::vector<std::uint32_t> out = m.take_finite_simplices();
  REQUIRE(out.size() == 4 * n);
  CHECK(out[4 * n - 1] == 4 * n - 1);
  // The first whole huge page of the result is left to 4 KiB pages.
  const std::uintptr_t first_whole = huge_page_range(reinterpret_cast<std::uintptr_t>(out.data()), 0).first;
  if (const auto hg = advised_huge(reinterpret_cast<const void*>(first_whole))) CHECK_FALSE(*hg);
  if (const auto hg = advised_huge(middle_of_room(out))) CHECK(*hg);
}
