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
//  - PartitionGuard: the parallel Bowyer–Watson's
//    (algorithms/parallel_bowyer_watson.hpp). Space is cut into boxes, one a
//    task; a vertex belongs to the box its point lies in (the vertex at
//    infinity to every box; algorithms/kd_boxes.hpp's boxes tile space, so
//    each finite vertex to one), and a task may read or write only a simplex
//    whose vertices are all in its box (acquire; HXT's rule, Marot, Pellerin,
//    Remacle, "One machine, one minute, three billion tetrahedra", IJNME
//    2019, section 4). A refusal ends the insertion before anything is
//    written, and the point is retried in a later round, cut another way.
//    Taking a simplex is a few loads and compares: no atomic
//    read-modify-write, no lock word, nothing to release (with the
//    per-simplex compare-and-swap locks used here before, the two-thread run
//    took 1.6 times the serial run's CPU time: papers/triangulation_costs.md,
//    session 43).
//    Why two tasks never touch one simplex: a task writes its own simplices
//    (its cavity, new slots) and the neighbour words of the simplices across
//    its cavity's boundary, and reads its own simplices and their neighbours.
//    Two simplices that share a facet share its finite vertices, d of them,
//    or d - 1 >= 1 with the vertex at infinity; a vertex lies in one box
//    only, so a simplex one task owns is nobody else's, nor a neighbour of
//    anybody else's. The one simplex that two tasks may both reach is, in 2D,
//    a ghost (a, b, infinity) with a and b in two boxes, across the facets
//    {a, infinity} and {b, infinity}: it is owned by neither (never written
//    but for those two different neighbour words) and its mark word, which
//    both may stamp, is only accessed atomically. In 3D the stamps are
//    TopBitMarks' bits.
#pragma once
#include <atomic>
#include <cstdint>

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

// Which simplices a task of the parallel Bowyer–Watson may read and write
// (PartitionGuard, in the header comment).  Each vertex carries the label of
// the box its point lies in, written between rounds; a task's box is a label.
// (Comparing the vertices' coordinates with the box's bounds at each acquire
// was 14 % of the instructions of a two-thread run: session 44.)
template <int D>
class BoxOwnership {
 public:
  // The mesh and the vertices' labels (again when the mesh grows: between rounds).
  void bind(const Mesh<D>& mesh, const std::uint8_t* box_of_vertex) {
    mesh_ = &mesh;
    box_of_vertex_ = box_of_vertex;
  }
  void set_box(std::uint8_t box) { box_ = box; }
  bool owns_vertex(std::uint32_t v) const { return v == kGhost || box_of_vertex_[v] == box_; }

  // True when every vertex of s is in the box.  Inlined: a task asks for
  // every simplex it enters.
  [[gnu::always_inline]] bool acquire(std::uint32_t s) const {
    const std::uint32_t* w = mesh_->vertices(s);
    bool own = true;
#pragma GCC unroll 4
    for (int j = 0; j <= D; ++j) own &= owns_vertex(w[j]);
    return own;
  }
  static constexpr void prefetch(std::uint32_t) {}  // nothing beside the block
  static constexpr void release_all() {}             // nothing taken

 private:
  const Mesh<D>* mesh_ = nullptr;
  const std::uint8_t* box_of_vertex_ = nullptr;
  std::uint8_t box_ = 0;
};

template <int D>
class PartitionGuard;

// 2D: stamps in the block's mark word, accessed atomically (the ghost that two
// tasks may both stamp).
template <>
class PartitionGuard<2> : public BoxOwnership<2> {
 public:
  static constexpr std::uint32_t kStampLimit = 0xFFFFFFFFu;  // the whole word
  static constexpr std::uint32_t code(std::uint32_t word) { return word; }
  void bind_marks(MarkWords marks) { words_ = marks; }
  std::uint32_t mark(const Mesh<2>&, std::uint32_t s) const {
    return std::atomic_ref<std::uint32_t>(words_[s]).load(std::memory_order_relaxed);
  }
  void set_mark(Mesh<2>&, std::uint32_t s, std::uint32_t stamp) {
    std::atomic_ref<std::uint32_t>(words_[s]).store(stamp, std::memory_order_relaxed);
  }

 private:
  MarkWords words_;
};

// 3D: TopBitMarks' two bits in the simplex's own neighbour words, which only
// the task that stamps them reads (no simplex is two tasks' in 3D); the task
// clears them after each search, as the serial algorithm does.
template <>
class PartitionGuard<3> : public BoxOwnership<3> {
 public:
  static constexpr std::uint32_t kIn = TopBitMarks::kIn, kOut = TopBitMarks::kOut;
  static constexpr std::uint32_t code(std::uint32_t word) { return TopBitMarks::code(word); }
  static std::uint32_t mark(const Mesh<3>& m, std::uint32_t s) { return TopBitMarks::mark(m, s); }
  static void set_mark(Mesh<3>& m, std::uint32_t s, std::uint32_t stamp) { TopBitMarks::set_mark(m, s, stamp); }
  static void unmark(Mesh<3>& m, std::uint32_t s, std::uint32_t stamp) { TopBitMarks::unmark(m, s, stamp); }
};

}  // namespace dlab
