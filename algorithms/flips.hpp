// Flip primitives on the ghost-closed mesh (algorithms/mesh.hpp), 2D and 3D,
// and the local Delaunay test they serve (Lawson 1977; Joe, "Construction of
// three-dimensional Delaunay triangulations using local transformations",
// CAGD 8 (1991); survey section 2.1; Baker, Handbook of Grid Generation
// ch. 16.2.4).  Written here from the geometry.
//
// Every change swaps a small set of old simplices for new ones, each new
// simplex written as an old one with one vertex substituted.  That keeps
// orientation for free: a new simplex shares a facet f with the old one it
// came from, f is on the boundary of the region both cover, so both lie on
// the same side of f and the substitution keeps the sign (the same argument
// as cavity re-starring, algorithms/cavity.hpp).  Ghost simplices follow the
// same rule (mesh.hpp: "replacing the vertex in slot i by a point on the same
// side of facet i keeps it positive"), then an even permutation puts the
// ghost back in slot D.  Neighbours are relinked by matching facet vertex
// sets in a small hash table (`replace`); the frequent 3D flips (2-3, 3-2,
// 4-4) wire theirs directly from the same substitution rule.
//
// The flips.  s is a simplex holding p, F its facet opposite p, t the simplex
// across F and d its apex; in 3D F = xyz and nw[k] = s with x_k replaced by d
// (finite_facet).  Drawings: a 3D flip is drawn looking along one line, which
// then shows as a point o.
//
//   2D 2-2: triangles s = pwu, t = duw.
//         u                 u
//        /|\               / \      edge uw becomes pd;
//       / | \             /   \     new: s[u->d] = pwd,
//      p  |  d    -->    p-----d         s[w->d] = pdu
//       \ | /             \   /
//        \|/               \ /
//         w                 w
//
//   3D 2-3: s = p+xyz, t = d+xyz; the segment pd crosses F inside.  Seen
//   along pd (p in front of F, d behind it; o = pd):
//         x                     x
//        / \                   /|\      edge pd added:
//       /   \                 / | \     pd+yz = s[x->d],
//      /  o  \      -->      /  o  \    pd+zx = s[y->d],
//     /       \             / ,' '. \   pd+xy = s[z->d]
//    y---------z           y'-------'z
//
//   3D 3-2: pd meets the plane of F beyond edge yz (s[x->d] < 0), and yz has
//   exactly three tetrahedra: s = p+xyz, t = d+xyz, r = pd+yz.  Seen along yz
//   (y in front, z behind; o = yz), the 2-3 picture reversed:
//         x                     x
//        /|\                   / \      edge yz removed,
//       / | \                 /   \     triangle xpd added:
//      /  o  \      -->      /     \    xpd+y = s[z->d],
//     / ,' '. \             /       \   xpd+z = s[y->d]
//    p'-------'d           p---------d
//
//   3D 4-4: p, d, y, z coplanar and pd crosses edge yz (s[x->d] = 0); yz has
//   exactly four tetrahedra: s = p+xyz, t = d+xyz, r1 = d+eyz, r2 = p+eyz,
//   x and e on either side of the plane.  Seen from x (e behind the plane):
//         y                     y
//        /|\                   / \      diagonal yz of the
//       / | \                 /   \     square pydz becomes pd:
//      p  |  d      -->      p-----d    pd+xy, pd+xz (from s),
//       \ | /                 \   /     pd+ey, pd+ez (from r2)
//        \|/                   \ /
//         z                     z
//
// Which flip (Joe's rule): all three nw[k] positive -> 2-3; one negative ->
// 3-2 about the edge opposite that x_k if it has degree 3; one zero -> 4-4
// about it if it has degree 4; anything else: not flippable now (another
// facet's flip removes it later: Joe 1991, Edelsbrunner-Shah 1996).  When F
// holds the ghost (F = ab+ghost: hull triangles abp and abd meet at hull edge
// ab) only the coplanar case flips: the hull edge flip (hull_edge_flip, with
// its drawing), of which the 4-4 about ab is the smallest instance.  Every
// candidate is checked: each new finite simplex must be positively oriented.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "algorithms/mesh.hpp"
#include "algorithms/oriented.hpp"

namespace dlab {

enum class FlipKind : unsigned char { none, f22, f23, f32, f44 };

template <int D>
class FlipMesh {
  static constexpr int V = D + 1;
  using Simplex = typename Mesh<D>::Simplex;
  using Key = std::array<std::uint32_t, D>;

 public:
  // old simplex s with the vertex in slot j replaced by z, ghost moved to slot D
  // by an even permutation.
  static Simplex substitute(const Mesh<D>& m, std::uint32_t s, int j, std::uint32_t z) {
    Simplex v = m.simplex(s);
    v[j] = z;
    normalise(v);
    return v;
  }
  static void normalise(Simplex& v) {
    for (int k = 0; k < D; ++k)
      if (v[k] == kGhost) {
        std::swap(v[k], v[D]);
        std::swap(v[0], v[1]);  // second transposition: the permutation stays even
        break;
      }
  }

  // The first slot of s holding v, or -1. 3D with SSE2: the four vertex words
  // compared at once, the lowest match taken (the same answer; Lawson on uniform
  // 3D 10^5 points ran 1.5 % fewer instructions than with the loop).
  static int slot_of(const Mesh<D>& m, std::uint32_t s, std::uint32_t v) {
#if defined(__SSE2__)
    if constexpr (D == 3) {
      const __m128i w = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m.vertices(s)));
      const int hits = _mm_movemask_ps(_mm_castsi128_ps(_mm_cmpeq_epi32(w, _mm_set1_epi32(static_cast<int>(v)))));
      return hits != 0 ? __builtin_ctz(static_cast<unsigned>(hits)) : -1;
    }
#endif
    for (int i = 0; i < V; ++i)
      if (m.vertex(s, i) == v) return i;
    return -1;
  }

  // Replaces the old simplices (distinct, live) by the new ones: destroys the
  // old, creates the new (reusing slots), links every facet.  Returns false
  // when a facet of a new simplex matches nothing (inconsistent input: a bug,
  // or an inexact kernel); the mesh is then inconsistent.
  // Facets are paired through a small open-addressing table keyed by their
  // sorted vertex ids (stamped, never cleared): linear in the facet count.
  bool replace(Mesh<D>& m, const std::uint32_t* old, int n_old, const Simplex* news, int n_new,
               std::vector<std::uint32_t>& out) {
    const std::size_t facets = static_cast<std::size_t>(n_old + n_new) * V;
    if (table_.size() < 2 * facets) {
      std::size_t size = 64;
      while (size < 2 * facets) size *= 2;
      table_.assign(size, Facet{});
      stamp_ = 0;
    }
    if (++stamp_ == 0) {
      for (Facet& e : table_) e.stamp = 0;
      stamp_ = 1;
    }
    const std::size_t mask = table_.size() - 1;
    std::size_t pending = 0;
    // Pairs facet `enc` with the facet of the same key seen before, or keeps it.
    auto meet = [&](const Key& k, std::uint32_t enc) {
      std::size_t h = hash(k) & mask;
      for (;; h = (h + 1) & mask) {
        Facet& e = table_[h];
        if (e.stamp != stamp_) {
          e = Facet{k, enc, stamp_};
          ++pending;
          return true;
        }
        if (!same(e.k, k)) continue;
        if (e.enc == kNoNeighbour) return false;  // a third facet with these vertices
        m.link(e.enc, enc);
        e.enc = kNoNeighbour;
        --pending;
        return true;
      }
    };
    for (int a = 0; a < n_old; ++a)
      for (int f = 0; f < V; ++f) {
        const std::uint32_t enc = m.neighbour(old[a], f);
        if (is_old(old, n_old, Mesh<D>::simplex_of(enc))) continue;
        if (!meet(key(m.vertices(old[a]), f), enc)) return false;
      }
    for (int a = 0; a < n_old; ++a) m.destroy(old[a]);
    out.resize(static_cast<std::size_t>(n_new));
    for (int a = 0; a < n_new; ++a) out[a] = m.create(news[a]);
    for (int a = 0; a < n_new; ++a)
      for (int f = 0; f < V; ++f)
        if (!meet(key(news[a].data(), f), Mesh<D>::encode(out[a], f))) return false;
    return pending == 0;
  }

  // The simplices around edge (u, v) in 3D, in rotation order starting at s
  // (which must hold u and v).  False if the ring exceeds `max` (corrupt mesh).
  static bool edge_ring(const Mesh<D>& m, std::uint32_t s, std::uint32_t u, std::uint32_t v,
                        std::vector<std::uint32_t>& ring, std::size_t max = 4096) {
    ring.clear();
    int x = -1;
    std::uint32_t y = kDead;
    for (int i = 0; i < V; ++i) {
      const std::uint32_t w = m.vertex(s, i);
      if (w == u || w == v) continue;
      if (x < 0)
        x = i;
      else
        y = w;
    }
    std::uint32_t cur = s;
    for (;;) {
      ring.push_back(cur);
      if (ring.size() > max) return false;
      const std::uint32_t enc = m.neighbour(cur, x);
      const std::uint32_t next = Mesh<D>::simplex_of(enc);
      const std::uint32_t z = m.vertex(next, Mesh<D>::facet_of(enc));
      if (next == s) return true;
      x = slot_of(m, next, y);
      if (x < 0) return false;
      y = z;
      cur = next;
    }
  }

 private:
  struct Facet {
    Key k{};
    std::uint32_t enc = 0;
    std::uint32_t stamp = 0;
  };
  // The facet's vertex ids in increasing order (a sorting network).
  static Key key(const std::uint32_t* w, int f) {
    Key k;
    int n = 0;
    for (int i = 0; i < V; ++i)
      if (i != f) k[n++] = w[i];
    auto order = [&](int a, int b) {
      if (k[b] < k[a]) std::swap(k[a], k[b]);
    };
    order(0, 1);
    if constexpr (D == 3) {
      order(1, 2);
      order(0, 1);
    }
    return k;
  }
  static std::size_t hash(const Key& k) {
    std::uint64_t h = k[0];
    for (int i = 1; i < D; ++i) h = h * 0x9E3779B97F4A7C15ull + k[i];
    return static_cast<std::size_t>((h * 0xD6E8FEB86659FD93ull) >> 32);
  }
  static bool same(const Key& a, const Key& b) {
    for (int i = 0; i < D; ++i)
      if (a[i] != b[i]) return false;
    return true;
  }
  static bool is_old(const std::uint32_t* old, int n_old, std::uint32_t t) {
    for (int a = 0; a < n_old; ++a)
      if (old[a] == t) return true;
    return false;
  }
  std::vector<Facet> table_;
  std::uint32_t stamp_ = 0;
};

struct FlipCounts {
  std::uint64_t f22 = 0, f23 = 0, f32 = 0, f44 = 0, unflippable = 0;
  std::uint64_t hull_removals = 0;  // coplanar hull edge removals of ring > 4 (counted in f23, f44 too)
  std::uint64_t total() const { return f22 + f23 + f32 + f44; }
};

// The local Delaunay test of a facet and the flip that repairs it.
template <class K, int D>
class Flipper {
  static constexpr int V = D + 1;
  using Simplex = typename Mesh<D>::Simplex;

 public:
  enum class Result : unsigned char { delaunay, flipped, unflippable, broken };

  Flipper(const K& k, Mesh<D>& m) : k_(&k), m_(&m) {}
  Flipper(const Flipper&) = delete;  // created_ may point into direct_
  Flipper& operator=(const Flipper&) = delete;
  void set_points(const Point<D>* pts) { pts_ = pts; }

  // Whether simplex s conflicts with vertex q: the Bowyer-Watson rule exactly
  // (bowyer_watson.hpp: in-circle/in-sphere for finite simplices, the CGAL
  // hull rules of oriented.hpp for ghosts), so the fixed point of the flips
  // is the triangulation Bowyer-Watson and CGAL build.  The ghost vertex
  // conflicts with nothing.
  bool conflict(std::uint32_t s, std::uint32_t q) const {
    if (q == kGhost) return false;
    const std::uint32_t* w = m_->vertices(s);
    const Point<D>& p = pts_[q];
    if constexpr (D == 2) {
      if (w[2] == kGhost) return ghost_conflict(*k_, pts_[w[0]], pts_[w[1]], p);
      return inside_pos(*k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], p) == Sign::positive;
    } else {
      if (w[3] == kGhost) {
        const std::uint32_t enc = m_->neighbour(s, 3);
        const std::uint32_t d = m_->vertex(Mesh<3>::simplex_of(enc), Mesh<3>::facet_of(enc));
        return ghost_conflict(*k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], pts_[d], p);
      }
      return inside_pos(*k_, pts_[w[0]], pts_[w[1]], pts_[w[2]], pts_[w[3]], p) == Sign::positive;
    }
  }

  // Facet f of s (opposite vertex p = vertex(s, f)): locally Delaunay, or
  // flipped (new simplices in created()), or not flippable now.
  Result try_flip(std::uint32_t s, int f) {
    const std::uint32_t enc = m_->neighbour(s, f);
    const std::uint32_t t = Mesh<D>::simplex_of(enc);
    const std::uint32_t d = m_->vertex(t, Mesh<D>::facet_of(enc));
    if (!conflict(s, d)) return Result::delaunay;
    if constexpr (D == 2) {
      Simplex nw[2] = {FlipMesh<2>::substitute(*m_, s, (f + 1) % 3, d),
                       FlipMesh<2>::substitute(*m_, s, (f + 2) % 3, d)};
      if (!(orient(nw[0]) == Sign::positive && orient(nw[1]) == Sign::positive)) return not_now();
      const std::uint32_t old[2] = {s, t};
      if (!fm_.replace(*m_, old, 2, nw, 2, replaced_)) return Result::broken;
      created_ = replaced_;
      ++counts.f22;
      return Result::flipped;
    } else {
      if (f == 3 && m_->is_ghost(s)) return not_now();  // p is the ghost: a broken hull
      s_apex_ = m_->vertex(s, f);
      int xs[3], n = 0;
      for (int i = 0; i < 4; ++i)
        if (i != f) xs[n++] = i;
      if (!m_->is_ghost(s)) return finite_facet(s, t, f, d, xs);
      return ghost_facet(s, t, f, d, xs);
    }
  }

  std::span<const std::uint32_t> created() const { return created_; }
  FlipCounts counts;

 private:
  Result not_now() {
    ++counts.unflippable;
    return Result::unflippable;
  }
  // Orientation of a new simplex; ghosts count as positive (see header).
  Sign orient(const Simplex& v) const {
    if (v[D] == kGhost) return Sign::positive;
    if constexpr (D == 2)
      return orient_pos(*k_, pts_[v[0]], pts_[v[1]], pts_[v[2]]);
    else
      return orient_pos(*k_, pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[v[3]]);
  }

  Result finite_facet(std::uint32_t s, std::uint32_t t, int f, std::uint32_t d, const int* xs) {
    Simplex nw[4];
    Sign o[3];
    int neg = 0, zero = 0, which = -1;
    // s and d are finite (conflict() is false for the ghost vertex), so is every
    // nw[k]: no ghost to move, no ghost to skip.
    // Unrolled: Lawson on uniform 3D 10^5 points ran 3.1 % fewer instructions.
#pragma GCC unroll 3
    for (int k = 0; k < 3; ++k) {
      nw[k] = m_->simplex(s);
      nw[k][xs[k]] = d;
      o[k] = orient_pos(*k_, pts_[nw[k][0]], pts_[nw[k][1]], pts_[nw[k][2]], pts_[nw[k][3]]);
      if (o[k] == Sign::negative) ++neg, which = k;
      if (o[k] == Sign::zero) ++zero, which = k;
      if (neg + zero > 1) return not_now();  // no flip whatever the third sign
    }
    if (neg == 0 && zero == 0) return flip23(s, t, f, xs, nw);
    if (neg + zero != 1) return not_now();
    // The edge opposite x_which in F.
    const int ky = (which + 1) % 3, kz = (which + 2) % 3;
    const std::uint32_t y = m_->vertex(s, xs[ky]), z = m_->vertex(s, xs[kz]);
    if (neg == 1) {  // 3-2 if the edge has degree 3: s and t share the tetrahedron pd+yz
      const std::uint32_t x = m_->vertex(s, xs[which]);
      const std::uint32_t es = m_->neighbour(s, xs[which]);
      const int tx = FlipMesh<3>::slot_of(*m_, t, x);
      if (tx < 0) return Result::broken;
      const std::uint32_t r = Mesh<3>::simplex_of(es);
      if (r != Mesh<3>::simplex_of(m_->neighbour(t, tx)) || m_->vertex(r, Mesh<3>::facet_of(es)) != d)
        return not_now();
      return flip32(s, t, r, f, xs, which, nw);
    }
    // 4-4 if the edge has degree 4.
    if (!FlipMesh<3>::edge_ring(*m_, s, y, z, ring_, 4) || ring_.size() != 4) return not_now();
    return four_four(s, t, d, f, xs, which, nw);
  }

  // 2-3 with its neighbours wired directly (drawing in the header).  nw[k] =
  // s[x_k -> d] keeps s's slots: its facet opposite d (slot xs[k]) is s's
  // facet opposite x_k, its facet opposite p (slot f) is t's facet opposite
  // x_k, and its facet opposite x_j is {p, d, x_l}, shared with nw[j]'s
  // facet opposite x_k.
  Result flip23(std::uint32_t s, std::uint32_t t, int f, const int* xs, const Simplex* nw) {
    std::uint32_t out_s[3], out_t[3];
    for (int k = 0; k < 3; ++k) {
      out_s[k] = m_->neighbour(s, xs[k]);
      const int ts = FlipMesh<3>::slot_of(*m_, t, m_->vertex(s, xs[k]));
      if (ts < 0) return Result::broken;
      out_t[k] = m_->neighbour(t, ts);
    }
    m_->destroy(s);
    m_->destroy(t);
    std::uint32_t* c = direct_.data();
    created_ = {c, 3};
    for (int k = 0; k < 3; ++k) c[k] = m_->create(nw[k]);
    for (int k = 0; k < 3; ++k) {
      m_->link(Mesh<3>::encode(c[k], xs[k]), out_s[k]);
      m_->link(Mesh<3>::encode(c[k], f), out_t[k]);
      for (int j = k + 1; j < 3; ++j) m_->link(Mesh<3>::encode(c[k], xs[j]), Mesh<3>::encode(c[j], xs[k]));
    }
    ++counts.f23;
    return Result::flipped;
  }

  // 3-2 with its neighbours wired directly: s = p+xyz, t = d+xyz, r = pd+yz
  // (x = x_kx); the new a = s[y->d] and b = s[z->d] keep s's slots.  a's
  // facet opposite d is s's facet opposite y, opposite p is t's facet
  // opposite y, opposite x is r's facet opposite y; the same for b with z;
  // a and b share {p, x, d} (a's facet opposite z, b's opposite y).
  Result flip32(std::uint32_t s, std::uint32_t t, std::uint32_t r, int f, const int* xs, int kx, const Simplex* nw) {
    const int ky = (kx + 1) % 3, kz = (kx + 2) % 3;
    std::uint32_t out[2][3];
    const int ks[2] = {ky, kz};
    for (int i = 0; i < 2; ++i) {
      const std::uint32_t v = m_->vertex(s, xs[ks[i]]);
      const int ts = FlipMesh<3>::slot_of(*m_, t, v), rs = FlipMesh<3>::slot_of(*m_, r, v);
      if (ts < 0 || rs < 0) return Result::broken;
      out[i][0] = m_->neighbour(s, xs[ks[i]]);
      out[i][1] = m_->neighbour(t, ts);
      out[i][2] = m_->neighbour(r, rs);
    }
    m_->destroy(s);
    m_->destroy(t);
    m_->destroy(r);
    std::uint32_t* c = direct_.data();
    created_ = {c, 2};
    for (int i = 0; i < 2; ++i) c[i] = m_->create(nw[ks[i]]);
    for (int i = 0; i < 2; ++i) {
      m_->link(Mesh<3>::encode(c[i], xs[ks[i]]), out[i][0]);
      m_->link(Mesh<3>::encode(c[i], f), out[i][1]);
      m_->link(Mesh<3>::encode(c[i], xs[kx]), out[i][2]);
    }
    m_->link(Mesh<3>::encode(c[0], xs[kz]), Mesh<3>::encode(c[1], xs[ky]));
    ++counts.f32;
    return Result::flipped;
  }

  // 4-4 with its neighbours wired directly (drawing in the header): ring of
  // yz = s = p+xyz, t = d+xyz, r1 = d+eyz, r2 = p+eyz.  New A = s[y->d], B =
  // s[z->d] (s's slots; positive: finite_facet checked them), C = r2[y->d],
  // E = r2[z->d] (r2's slots).  A's facet opposite d is s's facet opposite y,
  // opposite p is t's facet opposite y; likewise B with z, and C, E with r2,
  // r1.  Inside: A-B share {p,x,d}, C-E {p,e,d}, A-C {p,d,z}, B-E {p,d,y}.
  Result four_four(std::uint32_t s, std::uint32_t t, std::uint32_t d, int f, const int* xs, int kx,
                   const Simplex* nw) {
    const std::uint32_t p = s_apex_;
    const int ky = (kx + 1) % 3, kz = (kx + 2) % 3;
    const std::uint32_t y = m_->vertex(s, xs[ky]), z = m_->vertex(s, xs[kz]);
    std::uint32_t r1 = kDead, r2 = kDead;  // r2 holds p, r1 holds d
    for (std::uint32_t r : ring_) {
      if (r == s || r == t) continue;
      if (FlipMesh<3>::slot_of(*m_, r, p) >= 0)
        r2 = r;
      else
        r1 = r;
    }
    if (r1 == kDead || r2 == kDead || FlipMesh<3>::slot_of(*m_, r1, d) < 0) return not_now();
    const int fp2 = FlipMesh<3>::slot_of(*m_, r2, p), fy2 = FlipMesh<3>::slot_of(*m_, r2, y),
              fz2 = FlipMesh<3>::slot_of(*m_, r2, z);
    const int fe2 = 6 - fp2 - fy2 - fz2;
    const Simplex c2[2] = {FlipMesh<3>::substitute(*m_, r2, fy2, d), FlipMesh<3>::substitute(*m_, r2, fz2, d)};
    if (orient(c2[0]) != Sign::positive || orient(c2[1]) != Sign::positive) return not_now();
    const int ty = FlipMesh<3>::slot_of(*m_, t, y), tz = FlipMesh<3>::slot_of(*m_, t, z);
    const int r1y = FlipMesh<3>::slot_of(*m_, r1, y), r1z = FlipMesh<3>::slot_of(*m_, r1, z);
    if (ty < 0 || tz < 0 || r1y < 0 || r1z < 0) return Result::broken;
    const std::uint32_t out[8] = {m_->neighbour(s, xs[ky]), m_->neighbour(t, ty), m_->neighbour(s, xs[kz]),
                                  m_->neighbour(t, tz),     m_->neighbour(r2, fy2), m_->neighbour(r1, r1y),
                                  m_->neighbour(r2, fz2),   m_->neighbour(r1, r1z)};
    for (const std::uint32_t o : {s, t, r1, r2}) m_->destroy(o);
    std::uint32_t* c = direct_.data();
    created_ = {c, 4};
    c[0] = m_->create(nw[ky]);  // A
    c[1] = m_->create(nw[kz]);  // B
    c[2] = m_->create(c2[0]);   // C
    c[3] = m_->create(c2[1]);   // E
    using M = Mesh<3>;
    m_->link(M::encode(c[0], xs[ky]), out[0]);
    m_->link(M::encode(c[0], f), out[1]);
    m_->link(M::encode(c[1], xs[kz]), out[2]);
    m_->link(M::encode(c[1], f), out[3]);
    m_->link(M::encode(c[2], fy2), out[4]);
    m_->link(M::encode(c[2], fp2), out[5]);
    m_->link(M::encode(c[3], fz2), out[6]);
    m_->link(M::encode(c[3], fp2), out[7]);
    m_->link(M::encode(c[0], xs[kz]), M::encode(c[1], xs[ky]));  // {p, x, d}
    m_->link(M::encode(c[2], fz2), M::encode(c[3], fy2));        // {p, e, d}
    m_->link(M::encode(c[0], xs[kx]), M::encode(c[2], fe2));     // {p, d, z}
    m_->link(M::encode(c[1], xs[kx]), M::encode(c[3], fe2));     // {p, d, y}
    ++counts.f44;
    return Result::flipped;
  }

  // F = (a, b, ghost): hull triangles abp (s) and abd (t) meet at hull edge
  // ab.  The hull rule (oriented.hpp) puts them in conflict when d is beyond
  // the plane abp (a reflex hull edge) or coplanar with it and inside circle
  // abp.  Lawson joins a point outside the hull to every hull facet it sees
  // before any flip (lawson.hpp, Joe's exterior rule), so the hull is convex
  // throughout and only the coplanar case is left: the hull edge flip.
  // Reflex hull edges are not flipped (no ghost 2-3 / 3-2): a ghost has no
  // volume, so a positive tetrahedron abpd does not show that the new edge pd
  // is not in the mesh already; such a flip can make two hull triangles with
  // one vertex set, after which nothing flips (the "stuck" of session 1).
  Result ghost_facet(std::uint32_t s, std::uint32_t t, int f, std::uint32_t d, const int* xs) {
    (void)f;
    (void)t;
    int fa = -1, fb = -1;
    for (int k = 0; k < 3; ++k)
      if (xs[k] != 3) (fa < 0 ? fa : fb) = xs[k];
    const std::uint32_t a = m_->vertex(s, fa), b = m_->vertex(s, fb);
    const Simplex fin = FlipMesh<3>::substitute(*m_, s, 3, d);  // abpd
    const Sign o = orient(fin);
    if (o == Sign::zero) return hull_edge_flip(s, a, b);
    return not_now();
  }

  // Coplanar hull edge flip.  s = (a, b, p, ghost) and t = (a, b, d, ghost)
  // are hull triangles in one plane H, and d is inside the circle abp (the
  // hull rule, oriented.hpp): in the hull's 2D triangulation of H the edge ab
  // must become pd, so edge ab leaves the 3D mesh with every tetrahedron
  // around it.  Its ring is (ghost, d, w1, ..., wm, p), m >= 1 finite
  // apexes below H; every ring tetrahedron T without p becomes T[a->p] and
  // T[b->p] (the ring re-coned from p; the two with p just go):
  //
  //   hull plane H, from outside:        ring of ab, seen along ab (o = ab):
  //        a              a                         ghost
  //       /|\            / \                    /     |     \       above H
  //      p | d   -->    p---d                  p------o------d      in H
  //       \|/            \ /                    \    / \    /
  //        b              b                      wm ...... w1       below H
  //   after: the ring polygon (ghost, d, w1, ..., wm, p) fanned from p, each
  //   triangle coned to a and to b: (p, ghost, d), (p, d, w1), ...,
  //   (p, w(m-1), wm); with a: T[b->p], with b: T[a->p].
  //
  // m = 1 is the 4-4 flip (ring ghost, d, w1, p); m > 1 equals m-1 2-3
  // flips (each joining p to the next wi, peeling the ring from p's side)
  // then that 4-4, and is counted so.  Done only if every new finite
  // tetrahedron is positive; those checks also orient the new hull
  // triangles: (p,b,d,w1) = T[a->p] for T = (a,b,d,w1) is positive iff p is
  // on a's side of the plane bdw1, i.e. (a, b, d, p all in H) of line bd in
  // H, which is what makes the new ghost (p,b,d) a proper hull triangle.
  Result hull_edge_flip(std::uint32_t s, std::uint32_t a, std::uint32_t b) {
    const std::uint32_t p = s_apex_;
    if (!FlipMesh<3>::edge_ring(*m_, s, a, b, ring_, 64) || ring_.size() < 4) return not_now();
    int with_p = 0;
    news_.clear();
    for (std::uint32_t r : ring_) {
      if (FlipMesh<3>::slot_of(*m_, r, p) >= 0) {
        ++with_p;
        continue;
      }
      for (const std::uint32_t x : {a, b}) {
        news_.push_back(FlipMesh<3>::substitute(*m_, r, FlipMesh<3>::slot_of(*m_, r, x), p));
        if (orient(news_.back()) != Sign::positive) return not_now();
      }
    }
    if (with_p != 2) return not_now();
    if (!fm_.replace(*m_, ring_.data(), static_cast<int>(ring_.size()), news_.data(),
                     static_cast<int>(news_.size()), replaced_))
      return Result::broken;
    created_ = replaced_;
    const std::uint64_t m = ring_.size() - 3;
    counts.f23 += m - 1;
    ++counts.f44;
    if (m > 1) ++counts.hull_removals;
    return Result::flipped;
  }

  const K* k_;
  Mesh<D>* m_;
  const Point<D>* pts_ = nullptr;
  FlipMesh<D> fm_;
  // The simplices the last flip made: direct_ (2-3, 3-2, 4-4) or replaced_ (by
  // FlipMesh::replace), seen through created_.
  std::array<std::uint32_t, 4> direct_{};
  std::vector<std::uint32_t> replaced_, ring_;
  std::span<const std::uint32_t> created_;
  std::vector<Simplex> news_;
  std::uint32_t s_apex_ = 0;
};

}  // namespace dlab
