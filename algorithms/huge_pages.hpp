// Transparent huge pages (Linux) for the simplex slots (algorithms/mesh.hpp),
// which the walk and the cavity searches touch all over: with 4 KiB pages
// nearly every step to a slot not touched lately misses the TLB, and each
// page is a fault of its own; a 2 MiB page covers 512 of them
// (papers/triangulation_costs.md, session 23). The run's other large arrays
// (the points, the insertion order, the result) are written once each, but
// each of their 4 KiB pages is a fault too, and on a virtual machine a fault
// costs microseconds: there they were a fifth of a 2D run (session 27).
// Advice only: the kernel uses huge pages where THP is enabled ("madvise" or
// "always") and it has them free; nothing else changes, the results least of
// all. Elsewhere: nothing.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dlab {

inline constexpr std::size_t kHugePage = std::size_t{1} << 21;

// The whole 2 MiB pages inside [p, p + bytes), as addresses [first, last)
// (first == last: none).
inline std::pair<std::uintptr_t, std::uintptr_t> huge_page_range(std::uintptr_t p, std::size_t bytes) {
  const std::uintptr_t first = (p + kHugePage - 1) / kHugePage * kHugePage;
  const std::uintptr_t last = (p + bytes) / kHugePage * kHugePage;
  return last > first ? std::pair{first, last} : std::pair{first, first};
}

// MADV_HUGEPAGE on those pages: the ones faulted in from now on are huge.
inline void advise_huge_pages(const void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto [first, last] = huge_page_range(reinterpret_cast<std::uintptr_t>(p), bytes);
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p, (void)bytes;
#endif
}

// v's elements moved into new room for n of them (n >= v.size()), whose
// whole huge pages are advised before anything touches them.
template <class T, class A>
void move_to_huge_room(std::vector<T, A>& v, std::size_t n) {
  std::vector<T, A> room(v.get_allocator());
  room.reserve(n);
  if (n * sizeof(T) >= kHugePage) advise_huge_pages(room.data(), n * sizeof(T));
  room.insert(room.end(), std::make_move_iterator(v.begin()), std::make_move_iterator(v.end()));
  v.swap(room);
}

// As v.reserve(n), in huge pages.
template <class T, class A>
void reserve_huge(std::vector<T, A>& v, std::size_t n) {
  if (n > v.capacity()) move_to_huge_room(v, n);
}

// As v.shrink_to_fit(), in huge pages.
template <class T, class A>
void shrink_huge(std::vector<T, A>& v) {
  if (v.size() < v.capacity()) move_to_huge_room(v, v.size());
}

// As v.assign(n, value), in huge pages.
template <class T, class A>
void assign_huge(std::vector<T, A>& v, std::size_t n, const T& value) {
  if (n > v.capacity()) {
    v.clear();
    move_to_huge_room(v, n);
  }
  v.assign(n, value);
}

// v resized to n (new elements value-initialized) in huge pages.
template <class T, class A>
void resize_huge(std::vector<T, A>& v, std::size_t n) {
  reserve_huge(v, n);
  v.resize(n);
}

// A new vector of n copies of value, in huge pages.
template <class T>
std::vector<T> huge_vector(std::size_t n, const T& value = T{}) {
  std::vector<T> v;
  assign_huge(v, n, value);
  return v;
}

// Room for n elements of a trivial type, not written (no value-initialising
// pass: each page is faulted in by its first real write, on whichever thread
// makes it), in huge pages from its start.
struct FreeMemory {
  void operator()(void* p) const { std::free(p); }
};
template <class T>
using HugeBuffer = std::unique_ptr<T[], FreeMemory>;
template <class T>
HugeBuffer<T> huge_buffer(std::size_t n) {
  static_assert(std::is_trivially_default_constructible_v<T> && std::is_trivially_destructible_v<T>);
  const std::size_t bytes = std::max<std::size_t>(n * sizeof(T), 1);
  void* p = bytes >= kHugePage ? std::aligned_alloc(kHugePage, (bytes + kHugePage - 1) / kHugePage * kHugePage)
                               : std::malloc(bytes);
  if (p == nullptr) throw std::bad_alloc();
  if (bytes >= kHugePage) advise_huge_pages(p, bytes);
  return HugeBuffer<T>(static_cast<T*>(p));
}

}  // namespace dlab
