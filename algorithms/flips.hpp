// Flip primitives on the ghost-closed mesh (algorithms/mesh.hpp), 2D and 3D,
// and the local Delaunay test they serve (Lawson 1977; Joe, "Construction of
// three-dimensional Delaunay triangulations using local transformations",
// CAGD 8 (1991); survey section 2.1; Baker, Handbook of Grid Generation
// ch. 16.2.4).  Written here from the geometry.
//
// One mechanism does every change: `replace` swaps a small set of old
// simplices for new ones, each new simplex written as an old one with one
// vertex substituted.  That keeps orientation for free: a new simplex shares
// a facet f with the old one it came from, f is on the boundary of the region
// both cover, so both lie on the same side of f and the substitution keeps the
// sign (the same argument as cavity re-starring, algorithms/cavity.hpp).  Ghost
// simplices follow the same rule (mesh.hpp: "replacing the vertex in slot i by
// a point on the same side of facet i keeps it positive"), then an even
// permutation puts the ghost back in slot D.  Neighbours are relinked by
// matching facet vertex sets (brute force over at most a few dozen facets).
//
// The flips, p the apex of simplex s opposite the facet F, d the apex across F:
//
//   2D edge flip (2-2)            3D 2-3: segment pd crosses F=abc inside
//        u                              new edge pd; 3 tets pd+ab, pd+bc, pd+ca
//       /|\            u
//      / | \          / \               3D 3-2: pd crosses the plane of abc beyond
//     p  |  d  -->   p---d              edge ab, and ab has exactly 3 tets
//      \ | /          \ /               (abcp, abcd, abpd): edge ab -> triangle cpd
//       \|/            w                     a
//        w                                  /|\      tets around ab:  ->  cpd+a, cpd+b
//   new: s[u->d], s[w->d]              p---|---d   abcp abcd abpd
//                                           \|/
//   3D 4-4: p, d, a, b coplanar, pd         b
//   crosses edge ab, ab has 4 tets
//   (ring c, d, e, p): swap diagonal ab of the square apbd for pd:
//          c                                   c
//          |                                   |
//     p----a----d     ab-ring abcp abcd   p----+----d    pd+ca pd+cb
//      \  /  \  /     abde abep       ->   \  / \  /      pd+ea pd+eb
//       b(behind)                          (diagonal pd)
//          |                                   |
//          e                                   e
//
// Which flip (Joe's rule): with F = xyz and new simplices s[x->d] (positive
// iff pd passes on x's side of edge yz), all three positive -> 2-3; one
// negative -> 3-2 about that edge if it has degree 3; one zero -> 4-4 about
// that edge if it has degree 4; anything else: not flippable now.  When F
// holds the ghost (F = abg, a hull edge ab between hull triangles abp, abd),
// the finite new tetrahedron abpd decides: positive -> 2-3 (a tetrahedron
// fills the concave hull edge), or 3-2 when a or b has only the hull
// neighbours a/b, p, d (edge pd already exists); zero (coplanar hull
// triangles, in-circle by the hull rule) -> 4-4 about ab.  Every candidate is
// checked: each new finite simplex must be positively oriented.
#pragma once
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

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

  static int slot_of(const Mesh<D>& m, std::uint32_t s, std::uint32_t v) {
    for (int i = 0; i < V; ++i)
      if (m.vertex(s, i) == v) return i;
    return -1;
  }

  // Replaces the old simplices (distinct, live) by the new ones: destroys the
  // old, creates the new (reusing slots), links every facet.  Returns false
  // when a facet of a new simplex matches nothing (inconsistent input: a bug,
  // or an inexact kernel); the mesh is then inconsistent.
  bool replace(Mesh<D>& m, const std::uint32_t* old, int n_old, const Simplex* news, int n_new,
               std::vector<std::uint32_t>& out) {
    ext_.clear();
    for (int a = 0; a < n_old; ++a)
      for (int f = 0; f < V; ++f) {
        const std::uint32_t enc = m.neighbour(old[a], f);
        const std::uint32_t t = Mesh<D>::simplex_of(enc);
        if (is_old(old, n_old, t)) continue;
        ext_.push_back({key(m.vertices(old[a]), f), enc});
      }
    for (int a = 0; a < n_old; ++a) m.destroy(old[a]);
    out.clear();
    for (int a = 0; a < n_new; ++a) out.push_back(m.create(news[a]));
    nk_.clear();
    for (int a = 0; a < n_new; ++a)
      for (int f = 0; f < V; ++f) nk_.push_back({key(news[a].data(), f), Mesh<D>::encode(out[a], f)});
    for (std::size_t i = 0; i < nk_.size(); ++i) {
      if (nk_[i].enc == kNoNeighbour) continue;  // already paired
      bool found = false;
      for (Facet& e : ext_)
        if (e.enc != kNoNeighbour && same(e.k, nk_[i].k)) {
          m.link(nk_[i].enc, e.enc);
          e.enc = kNoNeighbour;
          found = true;
          break;
        }
      if (!found)
        for (std::size_t j = i + 1; j < nk_.size(); ++j)
          if (nk_[j].enc != kNoNeighbour && same(nk_[j].k, nk_[i].k)) {
            m.link(nk_[i].enc, nk_[j].enc);
            nk_[j].enc = kNoNeighbour;
            found = true;
            break;
          }
      if (!found) return false;
      nk_[i].enc = kNoNeighbour;
    }
    for (const Facet& e : ext_)
      if (e.enc != kNoNeighbour) return false;
    return true;
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
    Key k;
    std::uint32_t enc;
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
  std::vector<Facet> ext_, nk_;
};

struct FlipCounts {
  std::uint64_t f22 = 0, f23 = 0, f32 = 0, f44 = 0, unflippable = 0;
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
      if (!fm_.replace(*m_, old, 2, nw, 2, created_)) return Result::broken;
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

  const std::vector<std::uint32_t>& created() const { return created_; }
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
    (void)f;
    Simplex nw[4];
    Sign o[3];
    int neg = 0, zero = 0, which = -1;
    for (int k = 0; k < 3; ++k) {
      nw[k] = FlipMesh<3>::substitute(*m_, s, xs[k], d);
      o[k] = orient(nw[k]);
      if (o[k] == Sign::negative) ++neg, which = k;
      if (o[k] == Sign::zero) ++zero, which = k;
    }
    if (neg == 0 && zero == 0) {  // 2-3
      const std::uint32_t old[2] = {s, t};
      if (!fm_.replace(*m_, old, 2, nw, 3, created_)) return Result::broken;
      ++counts.f23;
      return Result::flipped;
    }
    if (neg + zero != 1) return not_now();
    // The edge opposite x_which in F.
    const int ky = (which + 1) % 3, kz = (which + 2) % 3;
    const std::uint32_t y = m_->vertex(s, xs[ky]), z = m_->vertex(s, xs[kz]);
    if (!FlipMesh<3>::edge_ring(*m_, s, y, z, ring_, 64)) return not_now();
    if (neg == 1) {  // 3-2 if the edge has degree 3
      if (ring_.size() != 3) return not_now();
      const std::uint32_t r = ring_[1] == t ? ring_[2] : ring_[1];
      const std::uint32_t old[3] = {s, t, r};
      const Simplex news[2] = {nw[ky], nw[kz]};
      if (!fm_.replace(*m_, old, 3, news, 2, created_)) return Result::broken;
      ++counts.f32;
      return Result::flipped;
    }
    // 4-4 if the edge has degree 4.
    if (ring_.size() != 4) return not_now();
    return four_four(s, t, d, y, z, nw[ky], nw[kz]);
  }

  Result four_four(std::uint32_t s, std::uint32_t t, std::uint32_t d, std::uint32_t y, std::uint32_t z,
                   const Simplex& a, const Simplex& b) {
    const std::uint32_t p = s_apex_;
    std::uint32_t r1 = kDead, r2 = kDead;  // r2 holds p, r1 holds d
    for (std::uint32_t r : ring_) {
      if (r == s || r == t) continue;
      if (FlipMesh<3>::slot_of(*m_, r, p) >= 0)
        r2 = r;
      else
        r1 = r;
    }
    if (r1 == kDead || r2 == kDead || FlipMesh<3>::slot_of(*m_, r1, d) < 0) return not_now();
    const Simplex nw[4] = {a, b, FlipMesh<3>::substitute(*m_, r2, FlipMesh<3>::slot_of(*m_, r2, y), d),
                           FlipMesh<3>::substitute(*m_, r2, FlipMesh<3>::slot_of(*m_, r2, z), d)};
    for (const Simplex& v : nw)
      if (orient(v) != Sign::positive) return not_now();
    const std::uint32_t old[4] = {s, t, r1, r2};
    if (!fm_.replace(*m_, old, 4, nw, 4, created_)) return Result::broken;
    ++counts.f44;
    return Result::flipped;
  }

  // F = (a, b, ghost): hull triangles abp (s) and abd (t) meet at hull edge ab.
  Result ghost_facet(std::uint32_t s, std::uint32_t t, int f, std::uint32_t d, const int* xs) {
    (void)f;
    int fa = -1, fb = -1;
    for (int k = 0; k < 3; ++k)
      if (xs[k] != 3) (fa < 0 ? fa : fb) = xs[k];
    const std::uint32_t a = m_->vertex(s, fa), b = m_->vertex(s, fb);
    const Simplex fin = FlipMesh<3>::substitute(*m_, s, 3, d);  // abpd
    const Sign o = orient(fin);
    if (o == Sign::positive) {
      for (const int fx : {fa, fb}) {  // 3-2 about (x, ghost) when x has hull degree 3
        if (!FlipMesh<3>::edge_ring(*m_, s, m_->vertex(s, fx), kGhost, ring_, 64)) return not_now();
        if (ring_.size() == 3) {
          const std::uint32_t r = ring_[1] == t ? ring_[2] : ring_[1];
          const std::uint32_t old[3] = {s, t, r};
          const Simplex news[2] = {FlipMesh<3>::substitute(*m_, s, fx, d), fin};
          if (!fm_.replace(*m_, old, 3, news, 2, created_)) return Result::broken;
          ++counts.f32;
          return Result::flipped;
        }
      }
      const Simplex nw[3] = {FlipMesh<3>::substitute(*m_, s, fa, d), FlipMesh<3>::substitute(*m_, s, fb, d),
                             fin};
      const std::uint32_t old[2] = {s, t};
      if (!fm_.replace(*m_, old, 2, nw, 3, created_)) return Result::broken;
      ++counts.f23;
      return Result::flipped;
    }
    if (o == Sign::zero) {
      if (!FlipMesh<3>::edge_ring(*m_, s, a, b, ring_, 64) || ring_.size() != 4) return not_now();
      return four_four(s, t, d, a, b, FlipMesh<3>::substitute(*m_, s, fa, d),
                       FlipMesh<3>::substitute(*m_, s, fb, d));
    }
    return not_now();
  }

  const K* k_;
  Mesh<D>* m_;
  const Point<D>* pts_ = nullptr;
  FlipMesh<D> fm_;
  std::vector<std::uint32_t> created_, ring_;
  std::uint32_t s_apex_ = 0;
};

}  // namespace dlab
