// Guards: who may read and write a simplex, and where its stamp lives.  The
// walk (algorithms/locate.hpp) and the Bowyer–Watson cavity search
// (algorithms/cavity_search.hpp) ask guard.acquire(s) before they read simplex
// s and stop when it refuses; the search reads and writes stamps through
// guard.mark / guard.set_mark.
//
//  - NoGuard: one thread owns the whole mesh; never refuses (compiles away);
//    stamps are Mesh::mark.
//  - TopBitMarks: one thread owns the whole 3D mesh, as with NoGuard, and a
//    search's two marks are the top bits of the simplex's own neighbour words
//    0 ("in") and 1 ("out"), which neighbour codes leave free below its slot
//    limit (kMaxSlots = 2^29: every code 4t + j < 2^31).  The search reads
//    neighbour words through code(), which clears that bit, and the owner
//    clears the bit of every simplex the search marked (unmark: the cavity
//    and the simplices across its boundary) before anything else reads the
//    mesh.  The serial 3D Bowyer–Watson's: no mark array at all (session 19's
//    byte per slot cost 6.75 bytes per point; a 4-byte stamp 27), and a mark
//    is read from the cache line the simplex's vertices are on.
//  - LockGuard: the parallel Bowyer–Watson's (algorithms/parallel_bowyer_watson.hpp)
//    per-simplex locks, kept in the mesh's mark word itself: its top 8 bits
//    hold 0 (free) or the owner's id (1..255), its low 24 bits the stamp, so
//    that taking a simplex touches no cache line the serial search would not
//    (a separate lock array cost a third line per simplex visited).  A worker
//    takes each simplex it reads or writes with one compare-and-swap (acquire)
//    and lets all of them go when its insertion ends or is abandoned
//    (release): every read and write of a simplex's vertices and neighbours
//    happens under its lock, so those arrays need no atomics; the mark words,
//    which other workers test, are only accessed atomically.  A simplex held
//    by another worker is a refusal, never a wait, so there is no deadlock; the
//    worker drops its locks and retries the point later (the optimistic scheme
//    of Marot, Pellerin, Remacle, "One machine, one minute, three billion
//    tetrahedra", IJNME 2019, section 4).  Stamps must stay below 2^24
//    (kStampLimit): the parallel algorithm clears the marks before that.
#pragma once
#include <atomic>
#include <cstdint>
#include <vector>

#include "algorithms/mesh.hpp"

namespace dlab {

struct NoGuard {
  static constexpr bool acquire(std::uint32_t) { return true; }
  static constexpr void prefetch(std::uint32_t) {}
  static constexpr void release_all() {}
  // The neighbour code in a neighbour word (TopBitMarks keeps a bit there).
  static constexpr std::uint32_t code(std::uint32_t word) { return word; }
  template <class M>
  static std::uint32_t mark(const M& m, std::uint32_t s) {
    return m.mark(s);
  }
  template <class M>
  static void set_mark(M& m, std::uint32_t s, std::uint32_t stamp) {
    m.set_mark(s, stamp);
  }
};

class TopBitMarks {
 public:
  static constexpr std::uint32_t kMaxSlots = 1u << 29;
  static constexpr std::uint32_t kBit = 1u << 31;
  static_assert(Mesh<3>::encode(kMaxSlots - 1, 3) < kBit, "codes below the slot limit leave the top bit free");

  static constexpr bool acquire(std::uint32_t) { return true; }
  static constexpr void prefetch(std::uint32_t) {}
  static constexpr void release_all() {}
  static constexpr std::uint32_t code(std::uint32_t word) { return word & ~kBit; }

  // The stamps: kIn is the top bit of neighbour word 0, kOut of word 1; a
  // simplex has at most one of them, so 0, kIn or kOut.
  static constexpr std::uint32_t kIn = 1, kOut = 2;
  static std::uint32_t mark(const Mesh<3>& m, std::uint32_t s) {
    if (m.neighbour(s, 0) & kBit) return kIn;
    return m.neighbour(s, 1) & kBit ? kOut : 0;
  }
  // On an unmarked simplex; stamp kIn or kOut.
  static void set_mark(Mesh<3>& m, std::uint32_t s, std::uint32_t stamp) {
    const std::uint32_t word = Mesh<3>::encode(s, static_cast<int>(stamp) - 1);
    m.set_neighbour(word, m.neighbour_enc(word) | kBit);
  }
  // Unmarked again (stamp: the one set), its neighbour codes as they were.
  static void unmark(Mesh<3>& m, std::uint32_t s, std::uint32_t stamp) {
    const std::uint32_t word = Mesh<3>::encode(s, static_cast<int>(stamp) - 1);
    m.set_neighbour(word, code(m.neighbour_enc(word)));
  }
};

class LockGuard {
 public:
  static constexpr int kOwnerShift = 24;
  static constexpr std::uint32_t kStampLimit = (1u << kOwnerShift) - 1;

  static constexpr std::uint32_t code(std::uint32_t word) { return word; }

  LockGuard(MarkWords marks, std::uint8_t owner) : words_(marks), owner_(std::uint32_t(owner) << kOwnerShift) {}

  // True when s is held by this guard now (taken now or earlier).  Inlined:
  // a worker asks for every simplex it reads.
  [[gnu::always_inline]] bool acquire(std::uint32_t s) {
    std::atomic_ref<std::uint32_t> word(words_[s]);
    std::uint32_t v = word.load(std::memory_order_relaxed);
    const std::uint32_t holder = v & ~kStampLimit;
    if (holder == owner_) return true;  // only this owner ever writes its own id
    if (holder != 0 ||
        !word.compare_exchange_strong(v, v | owner_, std::memory_order_acquire, std::memory_order_relaxed))
      return false;
    if (held_count_ == held_.size()) held_.resize(2 * held_.size() + 64);  // rare: amortised
    held_[held_count_++] = s;
    return true;
  }

  // A hint only (no read): the search asks for a simplex's lock word before it
  // takes it, as for its block.  always_inline: g++ 12 deletes calls to a
  // function that only prefetches (papers/triangulation_costs.md, session 38).
  [[gnu::always_inline]] void prefetch(std::uint32_t s) const { __builtin_prefetch(&words_[s]); }

  // The stamp of a held simplex.
  template <class M>
  std::uint32_t mark(const M&, std::uint32_t s) const {
    return std::atomic_ref<std::uint32_t>(words_[s]).load(std::memory_order_relaxed) & kStampLimit;
  }
  template <class M>
  void set_mark(M&, std::uint32_t s, std::uint32_t stamp) {
    std::atomic_ref<std::uint32_t>(words_[s]).store(owner_ | stamp, std::memory_order_relaxed);
  }

  // Lets every held simplex go, keeping its stamp; the writes made under the
  // locks become visible to the next owner (release).
  void release_all() {
    for (std::size_t i = 0; i < held_count_; ++i) {
      std::atomic_ref<std::uint32_t> word(words_[held_[i]]);
      word.store(word.load(std::memory_order_relaxed) & kStampLimit, std::memory_order_release);
    }
    held_count_ = 0;
  }

  // The mark words move when the mesh grows (between parallel rounds).
  void rebind(MarkWords marks) { words_ = marks; }

 private:
  MarkWords words_;
  std::uint32_t owner_;              // owner id << kOwnerShift
  std::vector<std::uint32_t> held_;  // the first held_count_ entries
  std::size_t held_count_ = 0;
};

}  // namespace dlab
