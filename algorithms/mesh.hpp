// A geometry-free simplicial mesh for D = 2 (triangles) and D = 3 (tetrahedra).
//
// Layout (design.md section 7, items 1 and 4; the compact array form used by the
// fastest sequential codes, e.g. Marot, Pellerin, Remacle, "One machine, one
// minute, three billion tetrahedra", IJNME 2019):
//  - simplex s owns a block of uint32 in one flat, 64-byte aligned array (3D:
//    4 vertices + 4 neighbours = 32 bytes; 2D: 3 + 3 padded to 32 bytes):
//      vertex(s, i)     its i-th vertex id (an index the caller gives meaning to);
//      neighbour(s, i)  the simplex across the facet opposite vertex i, encoded as
//                       4t + j where j is that same facet's index in t, so
//                       the way back costs nothing: neighbour(t, j) == 4s + i
//                       (4 in 2D too: shifts and masks instead of a division
//                       by 3 at every step of a walk or a search).
//  - kGhost is the single ghost ("infinite") vertex.  Every hull facet F has a
//    ghost simplex F + ghost on its outer side, so the mesh is a closed
//    pseudo-manifold (a triangulated sphere S^D) and the finite simplices cover
//    exactly the convex hull.  Invariant: the ghost vertex is always in slot D.
//  - Orientation convention: a finite simplex (v0..vD) is positively oriented,
//    det[v1-v0; ...; vD-v0] > 0.  A ghost simplex (v0..v{D-1}, ghost) is
//    oriented so that putting any point q strictly outside the hull beyond its
//    finite facet in slot D gives a positive simplex.  Replacing the vertex in
//    slot i of a positive simplex by a point on the same side of facet i keeps it
//    positive, which is why ghosts stay in slot D through cavity re-starring.
//  - Deleted slots are kept on a free list and reused last-in-first-out (they
//    are still in cache).  vertex(s, 0) == kDead marks a deleted slot.
//  - mark(s): one uint32 per simplex for algorithms' stamps (cavity membership,
//    visited flags): bump a counter instead of clearing sets. 2D keeps it in
//    the block's first padding word (no array of its own, and the same cache
//    line as the simplex), 3D in an array beside the blocks, unless the owner
//    keeps its stamps elsewhere (without_marks: no array at all; the serial
//    3D Bowyer–Watson's TopBitMarks, algorithms/simplex_guard.hpp).
// The mesh never sees a coordinate: algorithms ask predicates on vertex ids.
#pragma once
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "algorithms/huge_pages.hpp"

namespace dlab {

inline constexpr std::uint32_t kGhost = 0xFFFFFFFFu;  // the vertex at infinity
inline constexpr std::uint32_t kDead = 0xFFFFFFFEu;   // vertex(s,0) of a deleted slot
inline constexpr std::uint32_t kNoNeighbour = 0xFFFFFFFFu;

// Thrown when a mesh would need more slots than its 32-bit neighbour codes
// (4t + j) can name: a triangulation too large for dlab, not a failed run.
struct MeshTooLarge : std::length_error {
  using std::length_error::length_error;
};

// Where the mark words of a mesh are: mark(s) is base[s * stride].
struct MarkWords {
  std::uint32_t* base = nullptr;
  std::size_t stride = 1;
  std::uint32_t& operator[](std::uint32_t s) const { return base[s * stride]; }
};

// Allocator for the simplex array: 64-byte aligned, so that a 32-byte simplex
// block never straddles two cache lines (large mallocs are only 16-aligned);
// an array of a huge page or more is aligned to one and advised as huge pages
// before it is touched (algorithms/huge_pages.hpp).
template <class T>
struct CacheAligned {
  using value_type = T;
  CacheAligned() = default;
  template <class U>
  CacheAligned(const CacheAligned<U>&) {}
  static std::align_val_t alignment(std::size_t bytes) { return std::align_val_t(bytes >= kHugePage ? kHugePage : 64); }
  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    T* p = static_cast<T*>(::operator new(bytes, alignment(bytes)));
    if (bytes >= kHugePage) advise_huge_pages(p, bytes);
    return p;
  }
  void deallocate(T* p, std::size_t n) { ::operator delete(p, alignment(n * sizeof(T))); }
  // resize(n) without a value leaves the new elements unwritten (default-
  // initialised), so that Mesh::add_reserve can have them written on several
  // threads: the first touch of a new page, the kernel's zeroing of it, is
  // paid by whichever thread writes it.  Every other growth gives a value.
  template <class U>
  void construct(U* p) noexcept {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... A>
  void construct(U* p, A&&... a) {
    ::new (static_cast<void*>(p)) U(std::forward<A>(a)...);
  }
  template <class U>
  bool operator==(const CacheAligned<U>&) const { return true; }
};

template <int D>
class Mesh {
  static_assert(D == 2 || D == 3, "2D and 3D only");

 public:
  static constexpr int V = D + 1;  // vertices (and facets) per simplex
  using Simplex = std::array<std::uint32_t, V>;

  static constexpr std::uint32_t simplex_of(std::uint32_t enc) { return enc >> 2; }
  static constexpr int facet_of(std::uint32_t enc) { return static_cast<int>(enc & 3u); }
  static constexpr std::uint32_t encode(std::uint32_t s, int f) { return s * 4 + static_cast<std::uint32_t>(f); }
  // The most slots a mesh holds: encode(s, f) must fit 32 bits and differ from
  // kNoNeighbour, so s < 2^30 - 1 (about 1.6e8 points in 3D, 5e8 in 2D).
  static constexpr std::uint32_t kMaxSlots = (1u << 30) - 1;

  void clear() {
    d_.clear();
    mark_.clear();
    nfree_ = 0;
    live_ = 0;
  }
  void reserve(std::size_t simplices) {
    d_.reserve(simplices * S);  // S words per simplex (2D: padded to 8)
    if constexpr (!kMarkInBlock)
      if (has_marks_) mark_.reserve(simplices);
  }
  // From now on mark(), set_mark() and marks() must not be called: 3D keeps
  // no mark array (its owner keeps stamps of its own: TopBitMarks).
  void without_marks() {
    has_marks_ = false;
    decltype(mark_)().swap(mark_);
  }
  // A lower limit than kMaxSlots: an owner's (TopBitMarks'), or a test's.
  void limit_slots(std::uint32_t n) { max_slots_ = std::min(n, kMaxSlots); }
  std::uint32_t max_slots() const { return max_slots_; }

  // Slots the reserve holds without a reallocation.
  std::size_t capacity() const { return d_.capacity() / S; }
  // Number of slots (live or free); simplex ids are < slots().
  std::uint32_t slots() const { return static_cast<std::uint32_t>(d_.size() / S); }
  std::uint32_t live() const { return live_; }

  std::uint32_t vertex(std::uint32_t s, int i) const { return d_[std::size_t(s) * S + i]; }
  std::uint32_t& vertex(std::uint32_t s, int i) { return d_[std::size_t(s) * S + i]; }
  const std::uint32_t* vertices(std::uint32_t s) const { return d_.data() + std::size_t(s) * S; }
  std::uint32_t* vertices(std::uint32_t s) { return d_.data() + std::size_t(s) * S; }
  Simplex simplex(std::uint32_t s) const {
    Simplex r;
    std::copy_n(vertices(s), V, r.begin());
    return r;
  }

  std::uint32_t neighbour(std::uint32_t s, int i) const { return d_[std::size_t(s) * S + V + i]; }
  std::uint32_t neighbour_enc(std::uint32_t enc) const { return d_[nb_index(enc)]; }
  // Make facet a of one simplex and facet b of another mutual neighbours.
  void link(std::uint32_t a, std::uint32_t b) {
    d_[nb_index(a)] = b;
    d_[nb_index(b)] = a;
  }
  void set_neighbour(std::uint32_t enc, std::uint32_t other) { d_[nb_index(enc)] = other; }

  bool alive(std::uint32_t s) const { return d_[std::size_t(s) * S] != kDead; }
  // Ghost simplices carry the ghost vertex in slot D (invariant above).
  bool is_ghost(std::uint32_t s) const { return d_[std::size_t(s) * S + D] == kGhost; }

  std::uint32_t mark(std::uint32_t s) const {
    if constexpr (kMarkInBlock)
      return d_[std::size_t(s) * S + kMarkWord];
    else
      return mark_[s];
  }
  void set_mark(std::uint32_t s, std::uint32_t m) { marks()[s] = m; }
  // The mark words themselves (algorithms/simplex_guard.hpp's PartitionGuard<2>
  // reads and writes them atomically); valid until the mesh grows.
  MarkWords marks() {
    if constexpr (kMarkInBlock)
      return {d_.data() + kMarkWord, S};
    else
      return {mark_.data(), 1};
  }

  // A new simplex with the given vertices and unset neighbours; reuses the most
  // recently freed slot first.
  std::uint32_t create(const std::uint32_t* verts) {
    const std::uint32_t s = nfree_ != 0 ? free_[--nfree_] : new_slot();
    assign(s, verts);
    ++live_;
    return s;
  }
  std::uint32_t create(const Simplex& verts) { return create(verts.data()); }

  void destroy(std::uint32_t s) {
    d_[std::size_t(s) * S] = kDead;
    if (nfree_ == free_.size()) [[unlikely]] grow_free();
    free_[nfree_++] = s;  // (no push_back: g++ left it out of line in the flips, 23 instructions a call)
    --live_;
  }

  // n more slots, deleted and on no free list: a reserve that a caller hands
  // out itself (the parallel Bowyer–Watson's workers; they count what they
  // create and destroy there and report it with adjust_live).  Returns the
  // first.  Their words are written by for_ranges(first, last, write), which
  // must call write(a, b) on disjoint ranges that cover [first, last), on as
  // many threads as it likes (the workers: so that the new pages are first
  // touched in parallel, not between two rounds by one thread).
  template <class ForRanges>
  std::uint32_t add_reserve(std::size_t n, ForRanges&& for_ranges) {
    const std::uint32_t first = slots();
    if (n > max_slots_ - first) [[unlikely]]
      too_large(max_slots_);
    d_.resize(d_.size() + n * S);  // unwritten: CacheAligned::construct
    const bool marks = !kMarkInBlock && has_marks_;
    if (marks) mark_.resize(mark_.size() + n);
    for_ranges(first, slots(), [&](std::uint32_t a, std::uint32_t b) {
      std::fill(d_.begin() + std::size_t(a) * S, d_.begin() + std::size_t(b) * S, kNoNeighbour);
      for (std::uint32_t s = a; s < b; ++s) {
        d_[std::size_t(s) * S] = kDead;
        if constexpr (kMarkInBlock) d_[std::size_t(s) * S + kMarkWord] = 0;
      }
      if (marks) std::fill(mark_.begin() + a, mark_.begin() + b, 0u);
    });
    return first;
  }
  std::uint32_t add_reserve(std::size_t n) {
    return add_reserve(n, [](std::uint32_t a, std::uint32_t b, auto&& write) { write(a, b); });
  }
  void adjust_live(std::int64_t delta) { live_ = static_cast<std::uint32_t>(std::int64_t(live_) + delta); }

  // Overwrite the vertices of a live slot (re-using a cavity slot in place).
  // 2D a loop, 3D one 16-byte copy: the fewest instructions measured (std::copy_n
  // became a call to memmove in 2D, the loop added an overlap test in 3D).
  void assign(std::uint32_t s, const std::uint32_t* verts) {
    std::uint32_t* w = vertices(s);
    if constexpr (D == 2) {
      for (int i = 0; i < V; ++i) w[i] = verts[i];
    } else {
      std::memcpy(w, verts, V * sizeof(std::uint32_t));
    }
  }

  // Bytes held by the mesh's arrays (capacity, not size): the memory cost.
  std::size_t bytes_reserved() const {
    return (d_.capacity() + mark_.capacity() + free_.capacity()) *
           sizeof(std::uint32_t);
  }

  // Finite live simplices, in slot order.
  template <class F>
  void for_each_finite(F&& f) const {
    for (std::uint32_t s = 0; s < slots(); ++s)
      if (alive(s) && !is_ghost(s)) f(s);
  }
  std::size_t count_finite() const {
    std::size_t n = 0;
    for_each_finite([&](std::uint32_t) { ++n; });
    return n;
  }

  // The finite live simplices' vertices, V per simplex in slot order (as
  // for_each_finite), of those for which keep(vertices) holds; the mesh is
  // cleared. The result is written while the slot array is read, and the slot
  // array's pages already read go back to the system (Linux: madvise
  // MADV_DONTNEED), so the peak memory is about the mesh's own instead of
  // mesh plus result (3D: 36 + 16 bytes per simplex).
  struct KeepAll {
    bool operator()(const std::uint32_t*) const { return true; }
  };
  template <class Keep = KeepAll>
  std::vector<std::uint32_t> take_finite_simplices(Keep keep = {});

  // Links the facets of the given simplices that carry the same vertex set
  // (brute force: meant for the handful of simplices of an initial
  // configuration or a test).  Returns false if a facet is shared by more than
  // two of them.
  bool link_by_facets(const std::vector<std::uint32_t>& ids) {
    auto facet_key = [&](std::uint32_t s, int f) {
      std::array<std::uint32_t, D> k;
      int n = 0;
      for (int i = 0; i < V; ++i)
        if (i != f) k[n++] = vertex(s, i);
      std::sort(k.begin(), k.end());
      return k;
    };
    for (std::size_t a = 0; a < ids.size(); ++a)
      for (int fa = 0; fa < V; ++fa) {
        const auto ka = facet_key(ids[a], fa);
        int found = 0;
        for (std::size_t b = 0; b < ids.size(); ++b)
          for (int fb = 0; fb < V; ++fb)
            if (b != a && facet_key(ids[b], fb) == ka) {
              d_[nb_index(encode(ids[a], fa))] = encode(ids[b], fb);
              ++found;
            }
        if (found > 1) return false;
      }
    return true;
  }

  // Structural self-check (no geometry): every live simplex's neighbours are
  // live, point back, and share the facet's vertex set; ghosts keep the ghost in
  // slot D only.  Returns an empty string when consistent.
  std::string check_structure() const;

 private:
  // Simplex s: d_[s*S .. s*S+D] its vertices, d_[s*S+V .. s*S+V+D] its
  // neighbours; one block per simplex so that reading a simplex's vertices
  // (a predicate) brings its neighbours into cache too (32 bytes in 3D).
  // 2D pads the 6 words to 8 so that no block straddles a cache line.
  static constexpr int S = D == 2 ? 8 : 2 * V;
  static constexpr bool kMarkInBlock = S > 2 * V;
  static constexpr int kMarkWord = 2 * V;  // its word in the block, when kMarkInBlock
  // n new slots: unset neighbours, mark 0.  Throws MeshTooLarge instead of
  // letting the neighbour codes wrap.
  void grow(std::size_t n) {
    const std::uint32_t first = slots();
    if (n > max_slots_ - first) [[unlikely]]
      too_large(max_slots_);
    d_.resize(d_.size() + n * S, kNoNeighbour);
    if constexpr (kMarkInBlock)
      for (std::uint32_t s = first; s < slots(); ++s) d_[std::size_t(s) * S + kMarkWord] = 0;
    else if (has_marks_)
      mark_.resize(mark_.size() + n, 0);
  }
  // Out of line: create() then inlines (the flips create 5.6 slots per point, 0.7 of them new).
  [[gnu::noinline]] std::uint32_t new_slot() {
    const std::uint32_t s = slots();
    grow(1);
    return s;
  }
  [[gnu::cold, gnu::noinline]] void grow_free() { free_.resize(std::max<std::size_t>(64, 2 * free_.size())); }
  [[noreturn, gnu::cold, gnu::noinline]] static void too_large(std::uint32_t limit) {
    throw MeshTooLarge("the triangulation needs more than " + std::to_string(limit) +
                       " simplex slots, the most this algorithm's 32-bit neighbour codes can name");
  }
  static std::size_t nb_index(std::uint32_t enc) { return std::size_t(enc >> 2) * S + V + (enc & 3u); }
  std::vector<std::uint32_t, CacheAligned<std::uint32_t>> d_;
  std::vector<std::uint32_t, CacheAligned<std::uint32_t>> mark_;  // 3D's marks (2D: in the blocks)
  bool has_marks_ = true;            // 3D: false after without_marks()
  std::uint32_t max_slots_ = kMaxSlots;
  std::vector<std::uint32_t> free_;  // the free slots: free_[0, nfree_)
  std::uint32_t nfree_ = 0;
  std::uint32_t live_ = 0;
};

template <int D>
template <class Keep>
std::vector<std::uint32_t> Mesh<D>::take_finite_simplices(Keep keep) {
  std::vector<std::uint32_t> out;
  out.reserve(count_finite() * V);
  // The result in huge pages but for its first one: a huge page is resident
  // from its first write, and the first one, written before any of d_ is
  // released, would add 2 MiB to the peak (later ones come after releases).
  if (out.capacity() * sizeof(std::uint32_t) > kHugePage)
    advise_huge_pages(out.data() + kHugePage / sizeof(std::uint32_t),
                      out.capacity() * sizeof(std::uint32_t) - kHugePage);
  decltype(mark_)().swap(mark_);
  std::vector<std::uint32_t>().swap(free_);
  nfree_ = 0;
#if defined(__linux__)
  // Whole huge pages of d_ strictly below `end` that are not yet released.
  // Only whole ones: releasing part of a huge page splits it, and with 4 KiB
  // releases the 3D Bowyer-Watson of 10^6 points ran 12 % longer on a VM
  // (papers/triangulation_costs.md, session 26).
  std::uintptr_t released = huge_page_range(reinterpret_cast<std::uintptr_t>(d_.data()), 0).first;
  auto release_below = [&](const std::uint32_t* end) {
    const std::uintptr_t to = reinterpret_cast<std::uintptr_t>(end) / kHugePage * kHugePage;
    if (to <= released) return;
    madvise(reinterpret_cast<void*>(released), to - released, MADV_DONTNEED);
    released = to;
  };
#endif
  // Slots between two looks for a huge page read whole (128 KiB): the
  // result written before a release (half the slots read, at most a huge page
  // and a look's worth) is all that the peak gains.
  constexpr std::uint32_t kChunk = 1u << 12;
  for (std::uint32_t s = 0; s < slots(); ++s) {
    if (alive(s) && !is_ghost(s) && keep(vertices(s))) out.insert(out.end(), vertices(s), vertices(s) + V);
#if defined(__linux__)
    if ((s + 1) % kChunk == 0) release_below(vertices(s + 1));
#endif
  }
  decltype(d_)().swap(d_);
  live_ = 0;
  return out;
}

template <int D>
std::string Mesh<D>::check_structure() const {
  for (std::uint32_t s = 0; s < slots(); ++s) {
    if (!alive(s)) continue;
    for (int i = 0; i < D; ++i)
      if (vertex(s, i) == kGhost) return "ghost vertex outside slot D in simplex " + std::to_string(s);
    for (int i = 0; i < V; ++i) {
      const std::uint32_t n = neighbour(s, i);
      if (n == kNoNeighbour || simplex_of(n) >= slots() || !alive(simplex_of(n)))
        return "simplex " + std::to_string(s) + " facet " + std::to_string(i) + ": no live neighbour";
      if (neighbour_enc(n) != encode(s, i))
        return "simplex " + std::to_string(s) + " facet " + std::to_string(i) + ": neighbour does not point back";
      std::array<std::uint32_t, D> a, b;
      int na = 0, nbn = 0;
      for (int j = 0; j < V; ++j) {
        if (j != i) a[na++] = vertex(s, j);
        if (j != facet_of(n)) b[nbn++] = vertex(simplex_of(n), j);
      }
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      if (a != b) return "simplex " + std::to_string(s) + " facet " + std::to_string(i) + ": vertex sets differ";
    }
  }
  return {};
}

}  // namespace dlab
