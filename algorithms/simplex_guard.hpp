// Guards: who may read and write a simplex.  The walk (algorithms/locate.hpp)
// and the Bowyer–Watson cavity search (algorithms/cavity_search.hpp) ask
// guard.acquire(s) before they read simplex s and stop when it refuses.
//
//  - NoGuard: one thread owns the whole mesh; never refuses (compiles away).
//  - LockGuard: the parallel Bowyer–Watson's (algorithms/parallel_bowyer_watson.hpp)
//    per-simplex locks, one byte per slot holding 0 (free) or the owner's id
//    (1..255).  A worker takes each simplex it reads or writes with one
//    compare-and-swap (acquire) and lets all of them go when its insertion ends
//    or is abandoned (release): every read and write of a simplex's words
//    happens under its lock, so the mesh arrays themselves need no atomics.
//    A simplex held by another worker is a refusal, never a wait, so there is
//    no deadlock; the worker drops its locks and retries the point later
//    (the optimistic scheme of Marot, Pellerin, Remacle, "One machine, one
//    minute, three billion tetrahedra", IJNME 2019, section 4).
#pragma once
#include <atomic>
#include <cstdint>
#include <vector>

namespace dlab {

struct NoGuard {
  static constexpr bool acquire(std::uint32_t) { return true; }
  static constexpr void release_all() {}
};

class LockGuard {
 public:
  LockGuard(std::uint8_t* locks, std::uint8_t owner) : locks_(locks), owner_(owner) {}

  // True when s is held by this guard now (taken now or earlier).  Inlined:
  // a worker asks for every simplex it reads.
  [[gnu::always_inline]] bool acquire(std::uint32_t s) {
    std::atomic_ref<std::uint8_t> lock(locks_[s]);
    const std::uint8_t holder = lock.load(std::memory_order_relaxed);
    if (holder == owner_) return true;  // only this owner ever writes its own id
    std::uint8_t expected = 0;
    if (holder != 0 ||
        !lock.compare_exchange_strong(expected, owner_, std::memory_order_acquire, std::memory_order_relaxed))
      return false;
    if (held_count_ == held_.size()) held_.resize(2 * held_.size() + 64);  // rare: amortised
    held_[held_count_++] = s;
    return true;
  }

  // Lets every held simplex go; the writes made under the locks become
  // visible to the next owner (release).
  void release_all() {
    for (std::size_t i = 0; i < held_count_; ++i)
      std::atomic_ref<std::uint8_t>(locks_[held_[i]]).store(0, std::memory_order_release);
    held_count_ = 0;
  }

  // The lock array moves when the mesh grows (between parallel rounds).
  void rebind(std::uint8_t* locks) { locks_ = locks; }

 private:
  std::uint8_t* locks_;
  std::uint8_t owner_;
  std::vector<std::uint32_t> held_;  // the first held_count_ entries
  std::size_t held_count_ = 0;
};

}  // namespace dlab
