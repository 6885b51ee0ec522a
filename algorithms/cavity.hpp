// Re-starring a cavity from a new vertex: the step shared by Bowyer–Watson
// (Bowyer 1981, Watson 1981; Baker, Handbook of Grid Generation ch. 16.2.2)
// and George's corrected cavity (George 1997, section 2.3 step 7).
//
// Input: the cavity (simplex ids, in any order) and its boundary, collected
// while the cavity was searched, as records
//   { the new simplex's vertices: the cavity simplex's vertices with p in the
//     slot of the boundary facet's opposite vertex; that slot; the outside
//     facet (encoded t*(D+1)+j) across the boundary }.
// The new simplex keeps the cavity simplex's orientation because p sits on the
// same side of the boundary facet as the vertex it replaces (star-shapedness).
//
// Every other facet of a new simplex contains p and D-1 boundary vertices; such
// a facet is shared by exactly two new simplices (the cavity boundary is a
// closed (D-1)-manifold: a cycle in 2D, a triangulated sphere in 3D).  In 2D
// the records of an exact kernel's search come in cycle order
// (search_cavity_ccw), and each new triangle's successor is the next record;
// otherwise (cavities of up to 32 triangles) each new triangle finds its
// successor through a 64-entry table of the boundary edges' start vertices.
// Larger 2D cavities, and every 3D one, pair their new facets through a small
// open-addressing table keyed by those D-1 vertex ids (design.md section 7
// item 3 uses a 32x32 table on local ids; a hash on global ids does the same
// job with no local numbering), marked by a stamp so it is never cleared.  A
// key used too often, or left unpaired, means the cavity boundary was not a
// manifold: reported, never trusted (inexact kernels can produce such
// cavities).
//
// New simplices reuse the cavity's slots first; extra cavity slots go back to
// the free list.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "algorithms/mesh.hpp"

namespace dlab {

// In a counterclockwise triangle, edge f (opposite vertex f) joins vertex
// kAfter[f] to vertex kBefore[f]; the next edge counterclockwise is kAfter[f].
inline constexpr int kAfter[3] = {1, 2, 0}, kBefore[3] = {2, 0, 1};

template <int D>
struct BoundaryRecord {
  std::array<std::uint32_t, D + 1> v;  // vertices of the new simplex (p included)
  std::uint32_t outside;               // encoded facet of the simplex outside the cavity
  int slot;                            // where p sits in v (= the facet index towards `outside`)
};

// The record of facet f of cavity simplex s, whose outside is `outside`, for
// new vertex i.
template <int D>
BoundaryRecord<D> boundary_record(const Mesh<D>& m, std::uint32_t s, int f, std::uint32_t i,
                                  std::uint32_t outside) {
  BoundaryRecord<D> r;
  const std::uint32_t* w = m.vertices(s);
  for (int j = 0; j <= D; ++j) r.v[j] = w[j];
  r.v[f] = i;
  r.outside = outside;
  r.slot = f;
  return r;
}

template <int D>
class Restar {
  static constexpr int V = D + 1;
  static constexpr std::uint32_t kPaired = 0xFFFFFFFFu;

 public:
  // Replaces the cavity by the star of p.  Returns the id of a new simplex
  // (a finite one if there is any), or sets `error` (and leaves the mesh
  // possibly inconsistent) when the boundary is not a closed manifold.
  // `verify` re-checks that every new adjacency is mutual (for inexact
  // kernels, whose cavities can be anything).
  //
  // M is Mesh<D> or a view of it with the same members that takes new slots
  // from elsewhere (the parallel Bowyer–Watson's WorkerSlots).
  template <class M>
  std::uint32_t star(M& m, const std::vector<std::uint32_t>& cavity,
                     const std::vector<BoundaryRecord<D>>& records, std::string& error,
                     bool verify = false) {
    // A cavity without boundary is the whole triangulation, ghosts included:
    // no exact conflict test admits it (p is never in conflict with a ghost
    // whose finite facet it lies strictly inside), inexact ones can.
    if (records.empty()) {
      error = "the cavity has no boundary (it swallowed the whole triangulation)";
      return kNoNeighbour;
    }
    // New simplices: cavity slots first, then fresh ones; link across the boundary.
    ids_.resize(records.size());
    std::uint32_t first = kNoNeighbour;
    bool first_finite = false;
    auto place = [&](std::size_t r, std::uint32_t s) {
      const BoundaryRecord<D>& rec = records[r];
      ids_[r] = s;
      if (!first_finite && (first == kNoNeighbour || rec.v[D] != kGhost)) {  // the mesh is not read
        first = s;
        first_finite = rec.v[D] != kGhost;
      }
      m.link(Mesh<D>::encode(s, rec.slot), rec.outside);
    };
    // Two loops, so that the inline create() stays out of the reusing one.
    const std::size_t reused = std::min(records.size(), cavity.size());
    for (std::size_t r = 0; r < reused; ++r) {
      m.assign(cavity[r], records[r].v.data());
      place(r, cavity[r]);
    }
    for (std::size_t r = reused; r < records.size(); ++r) place(r, m.create(records[r].v.data()));
    bool ok;
    if constexpr (D == 2)
      ok = (!verify && link_chain(m, records)) ||
           (records.size() <= 32 ? link_cycle(m, records, error) : link_facets(m, records, error));
    else
      ok = link_facets(m, records, error);
    if (!ok) return kNoNeighbour;
    if (verify) {  // inexact kernels: every new link must be mutual
      for (std::size_t r = 0; r < records.size(); ++r)
        for (int f = 0; f < V; ++f) {
          const std::uint32_t enc = Mesh<D>::encode(ids_[r], f);
          const std::uint32_t n = m.neighbour_enc(enc);
          if (Mesh<D>::simplex_of(n) >= m.slots() || m.neighbour_enc(n) != enc) {
            error = "cavity boundary is not a manifold (adjacency not mutual)";
            return kNoNeighbour;
          }
        }
    }
    for (std::size_t r = records.size(); r < cavity.size(); ++r) m.destroy(cavity[r]);
    return first;
  }

  std::size_t bytes_reserved() const { return table_.capacity() * sizeof(Entry); }

  // The simplices created by the last successful star(), one per boundary
  // record, in record order.
  const std::vector<std::uint32_t>& created() const { return ids_; }

 private:
  // 2D, records in counterclockwise order around the cavity (as
  // search_cavity_ccw gives them): new triangle r is (p, u_r, w_r), and its
  // edge (w_r, p) is shared with triangle r+1 (mod k) when u_{r+1} = w_r.
  // With an exact kernel every boundary vertex starts exactly one boundary
  // edge, so a chain that closes is the cycle; false at the first link
  // missing (records in another order), and link_cycle then sets every link.
  template <class M>
  bool link_chain(M& m, const std::vector<BoundaryRecord<D>>& records) {
    const std::size_t k = records.size();
    for (std::size_t r = 0; r < k; ++r) {
      const std::size_t next = r + 1 == k ? 0 : r + 1;
      const int slot = records[r].slot, next_slot = records[next].slot;
      if (records[r].v[kBefore[slot]] != records[next].v[kAfter[next_slot]]) return false;
      m.link(Mesh<D>::encode(ids_[r], kAfter[slot]), Mesh<D>::encode(ids_[next], kBefore[next_slot]));
    }
    return true;
  }

  // 2D, small cavities: the boundary is one cycle.  New triangle r is
  // (p, u_r, w_r) counterclockwise, with u_r, w_r the vertices after p's slot;
  // its edge (w_r, p) (opposite u_r) is shared with the triangle whose u is w_r.
  template <class M>
  bool link_cycle(M& m, const std::vector<BoundaryRecord<D>>& records, std::string& error) {
    // A 64-entry open-addressing table u -> record, marked by a stamp (k <= 32
    // keys: load <= 1/2).
    if (++cycle_stamp_ == 0) {
      for (auto& e : cycle_) e.stamp = 0;
      cycle_stamp_ = 1;
    }
    const std::size_t k = records.size();
    auto hash = [](std::uint32_t v) { return static_cast<unsigned>((v * 0x9E3779B1u) >> 26); };
    for (std::size_t r = 0; r < k; ++r) {
      const std::uint32_t u = records[r].v[kAfter[records[r].slot]];
      unsigned h = hash(u);
      while (cycle_[h].stamp == cycle_stamp_) {
        if (cycle_[h].vertex == u) {
          error = "cavity boundary is not a simple cycle (a vertex starts two boundary edges)";
          return false;
        }
        h = (h + 1) & 63;
      }
      cycle_[h] = {u, static_cast<std::uint32_t>(r), cycle_stamp_};
    }
    for (std::size_t r = 0; r < k; ++r) {
      const int slot = records[r].slot;
      const std::uint32_t w = records[r].v[kBefore[slot]];
      unsigned h = hash(w);
      while (cycle_[h].stamp == cycle_stamp_ && cycle_[h].vertex != w) h = (h + 1) & 63;
      if (cycle_[h].stamp != cycle_stamp_) {
        error = "cavity boundary is not closed (a boundary edge without a successor)";
        return false;
      }
      const std::uint32_t next = cycle_[h].value;
      m.link(Mesh<D>::encode(ids_[r], kAfter[slot]),
             Mesh<D>::encode(ids_[next], kBefore[records[next].slot]));
    }
    return true;
  }


  // kEdge[slot][f]: the slots of (a, b) in the oriented facet opposite f,
  // rotated to start at p = slot `slot` (see link_facets).  The facet
  // opposite slot f, its slots in increasing order, is oriented with vertex f
  // on its positive side when f is even (moving slot f to the front of a
  // positive simplex takes f transpositions); reversed when f is odd.
  static constexpr std::array<std::array<std::array<int, 2>, 4>, 4> kEdge = [] {
    std::array<std::array<std::array<int, 2>, 4>, 4> t{};
    for (int slot = 0; slot < 4; ++slot)
      for (int f = 0; f < 4; ++f) {
        if (f == slot) continue;
        int x[3];
        int n = 0;
        for (int i = 0; i < 4; ++i)
          if (i != f) x[n++] = i;
        if (f & 1) {
          const int tmp = x[1];
          x[1] = x[2];
          x[2] = tmp;
        }
        const int ip = x[0] == slot ? 0 : (x[1] == slot ? 1 : 2);
        t[slot][f] = {x[(ip + 1) % 3], x[(ip + 2) % 3]};
      }
    return t;
  }();

  // Records not in cycle order (2D), and every 3D cavity: each internal facet
  // of a new simplex is keyed by its boundary vertices and paired with the
  // facet of the same key in one pass over an open-addressing table (at least
  // twice as many entries as the D facets a record registers, a power of
  // two), marked by a stamp so that it is never cleared.  2D: the facet (p, u) is keyed by u, the same from both sides.
  // 3D: the facet (p, a, b) is keyed by (a, b) in the order that puts the
  // tetrahedron's own remaining vertex on the positive side of the oriented
  // facet; the tetrahedron across it sees the facet reversed, (b, a) (HXT's
  // directed keys, Marot et al. 2019, re-derived; HXT pairs them in a 32x32
  // table on local vertex ids, which costs a vertex -> id lookup per vertex:
  // probing on the global ids costs less, papers/triangulation_costs.md,
  // session 31).  Both orders of an edge hash alike (on the smaller key).
  // A facet whose partner waits is linked to it (both ways) and the entry is
  // marked paired; otherwise it waits under its own key.  So every key must
  // be used once each way: a facet that finds its partner already paired or
  // its own key taken (a facet of more than two new simplices), or one left
  // waiting at the end (no partner), is an error, also for inexact kernels,
  // whose links are then mutual whatever their cavity was.
  template <class M>
  bool link_facets(M& m, const std::vector<BoundaryRecord<D>>& records, std::string& error) {
    const std::size_t facets = records.size() * D;  // facet registrations
    if (table_.size() < 2 * facets) {
      std::size_t size = 64;
      while (size < 2 * facets) size *= 2;
      table_.assign(size, Entry{});
      stamp_ = 0;
      shift_ = 64;
      for (std::size_t t = size; t > 1; t >>= 1) --shift_;
    }
    if (++stamp_ == 0) {  // wrapped: clear once every 2^32 uses
      for (auto& e : table_) e.stamp = 0;
      stamp_ = 1;
    }
    const std::size_t mask = table_.size() - 1;
    // Locals: the mesh's and the table's uint32 stores may alias the members,
    // which g++ then reloads after each.
    Entry* const table = table_.data();
    const std::uint32_t stamp = stamp_;
    const int shift = shift_;
    std::uint32_t waiting = 0;
    // Registers facet `enc` of a new simplex under (own, partner) and links
    // it to its partner if that waits; false: a facet of more than two new
    // simplices. Always inline: g++ 12 left it out of line (5.2 % more).
    auto register_facet = [&](std::uint32_t enc, std::uint64_t own,
                              std::uint64_t partner) __attribute__((always_inline)) {
      std::size_t h = static_cast<std::size_t>((std::min(own, partner) * 0x9E3779B97F4A7C15ull) >> shift);
      Entry* found = nullptr;  // the partner's entry
      bool own_taken = false;
      for (; table[h].stamp == stamp; h = (h + 1) & mask) {
        if (table[h].key == partner) {
          found = &table[h];
          break;
        }
        own_taken |= table[h].key == own;
      }
      if (found && found->value != kPaired) {
        m.link(enc, found->value);
        found->value = kPaired;
        --waiting;
        return true;
      }
      if (found || own_taken) return false;
      table[h] = {own, enc, stamp};
      ++waiting;
      return true;
    };
    for (std::size_t r = 0; r < records.size(); ++r) {
      const BoundaryRecord<D>& rec = records[r];
      const int slot = rec.slot;
      bool ok = true;
      if constexpr (D == 2) {
        for (int f = 0; f < V; ++f)
          if (f != slot) {
            const std::uint32_t u = rec.v[3 - f - slot];
            ok &= register_facet(Mesh<D>::encode(ids_[r], f), u, u);
          }
      } else {
        // The three facets through p, each with its slots from kEdge as
        // constants (a switch on p's slot). Against a loop over the four
        // facets that skipped p's: Bowyer-Watson on uniform 3D 10^5 points
        // ran 4.4 % fewer instructions; a loop over the three, 2.2 % more.
        const auto facets = [&]<int P>(std::integral_constant<int, P>) {
          const auto one = [&]<int F>(std::integral_constant<int, F>) {
            const std::uint32_t a = rec.v[kEdge[P][F][0]], b = rec.v[kEdge[P][F][1]];
            return register_facet(Mesh<D>::encode(ids_[r], F), (std::uint64_t(a) << 32) | b,
                                  (std::uint64_t(b) << 32) | a);
          };
          bool all = true;
          if constexpr (P != 0) all &= one(std::integral_constant<int, 0>{});
          if constexpr (P != 1) all &= one(std::integral_constant<int, 1>{});
          if constexpr (P != 2) all &= one(std::integral_constant<int, 2>{});
          if constexpr (P != 3) all &= one(std::integral_constant<int, 3>{});
          return all;
        };
        switch (slot) {
          case 0: ok = facets(std::integral_constant<int, 0>{}); break;
          case 1: ok = facets(std::integral_constant<int, 1>{}); break;
          case 2: ok = facets(std::integral_constant<int, 2>{}); break;
          default: ok = facets(std::integral_constant<int, 3>{}); break;
        }
      }
      if (!ok) {
        error = "cavity boundary is not a manifold (a facet shared by more than two new simplices)";
        return false;
      }
    }
    if (waiting != 0) {
      error = "cavity boundary is not closed (a new facet without a partner)";
      return false;
    }
    return true;
  }

  struct Entry {
    std::uint64_t key = 0;
    std::uint32_t value = 0;
    std::uint32_t stamp = 0;
  };
  std::vector<Entry> table_;
  std::vector<std::uint32_t> ids_;
  struct VertexEntry {
    std::uint32_t vertex = 0, value = 0, stamp = 0;
  };
  std::array<VertexEntry, 64> cycle_{};   // vertex -> record (link_cycle)
  std::uint32_t cycle_stamp_ = 0;
  std::uint32_t stamp_ = 0;
  int shift_ = 64;  // 64 - log2(table_.size())
};

}  // namespace dlab
