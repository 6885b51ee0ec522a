// The exact validator (see validate.hpp for what is checked and why it suffices).
// Facets, simplices, ridges and points are matched through open-addressing hash
// tables of 32-bit ids whose keys are recomputed from the index arrays, so the
// whole check is O(n + m) expected time. Memory beside the input's simplices:
// 4 bytes per facet incidence (the links) and the facet table's 8 bytes per
// expected facet, 1.25 times over; the simplices are copied only when they
// name a duplicated point.
#include "algorithms/validate.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>
#include <utility>

#include "algorithms/huge_pages.hpp"
#include "predicates/filtered.hpp"
#include "predicates/float_filter.hpp"
#include "predicates/mp_kernel.hpp"

namespace dlab {
namespace {

// Exact: a semi-static floating filter that answers only when its error bound
// proves the sign, then GMP (predicates/filtered.hpp, float_filter.hpp).
using ExactKernel = filtered<FloatFilter, MpKernel>;
static_assert(ExactKernel::exact);

constexpr std::uint32_t kNone = 0xffffffffu;
constexpr std::uint32_t kExtra = kNone - 1;  // a facet link that is neither a mate nor the boundary

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Open addressing with linear probing over 32-bit ids; the key of an id is
// recomputed by the caller's equality test, which only runs when the stored
// 32-bit hash tag matches. The tag alone places an entry (its fraction of the
// capacity, Lemire's multiply-shift), so the table grows without recomputing
// keys: it doubles before it is 4/5 full, and a probe always reaches an empty
// slot.
class IdTable {
 public:
  explicit IdTable(std::size_t expected_entries) {
    assign_huge(slots_, expected_entries + expected_entries / 4 + 16, kEmpty);  // algorithms/huge_pages.hpp
  }
  // The stored id whose key equals the new one, or kNone after storing `id`.
  template <class Eq>
  std::uint32_t find_or_insert(std::uint64_t hash, std::uint32_t id, Eq&& equal) {
    const std::uint64_t tag = mix(hash) >> 32;
    for (std::size_t i = home(tag);; i = next(i)) {
      const std::uint64_t s = slots_[i];
      if (s == kEmpty) {
        slots_[i] = tag << 32 | id;
        if (++entries_ * 5 >= slots_.size() * 4) grow();
        return kNone;
      }
      if ((s >> 32) == tag && equal(static_cast<std::uint32_t>(s))) return static_cast<std::uint32_t>(s);
    }
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // id kNone never stored
  std::size_t home(std::uint64_t tag) const {
    return static_cast<std::size_t>((static_cast<unsigned __int128>(tag) * slots_.size()) >> 32);
  }
  std::size_t next(std::size_t i) const { return i + 1 < slots_.size() ? i + 1 : 0; }  // linear probing
  void grow() {
    std::vector<std::uint64_t> old = huge_vector(2 * slots_.size(), kEmpty);
    old.swap(slots_);
    for (const std::uint64_t s : old) {
      if (s == kEmpty) continue;
      std::size_t i = home(s >> 32);
      while (slots_[i] != kEmpty) i = next(i);
      slots_[i] = s;
    }
  }
  std::vector<std::uint64_t> slots_;
  std::size_t entries_ = 0;
};

template <std::size_t N>
std::uint64_t hash_ids(const std::array<std::uint32_t, N>& a) {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL;
  for (std::uint32_t v : a) h = mix(h ^ v) + 0x632be59bd9b4e019ULL;
  return h;
}

void flag(CheckResult& c, std::int64_t simplex, int facet = -1, std::int64_t point = -1) {
  if (c.count++ == 0) {
    c.simplex = simplex;
    c.facet = facet;
    c.point = point;
  }
}

// Lexicographic comparison of points: -1, 0, 1 (exact: comparisons only).
template <int D>
int lex_compare(const Point<D>& a, const Point<D>& b) {
  for (int j = 0; j < D; ++j) {
    if (a[j] < b[j]) return -1;
    if (a[j] > b[j]) return 1;
  }
  return 0;
}

// Orientation in the output convention: sign det[v1-v0; ...; vd-v0].
// 2D it is orient2d; in 3D it is the opposite of Shewchuk's orient3d.
Sign orientation(const ExactKernel& k, const Point2& a, const Point2& b, const Point2& c) {
  return k.orient2d(a, b, c);
}
Sign orientation(const ExactKernel& k, const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  return -k.orient3d(a, b, c, d);
}

template <int D>
Sign orientation(const ExactKernel& k, const std::array<const Point<D>*, D + 1>& v) {
  // A repeated point makes two rows of det[v1-v0; ...; vd-v0] equal (or one
  // zero): the sign is 0 exactly, without arithmetic. The cover-degree probe
  // asks this often, and the floating filter cannot certify a zero.
  for (int a = 1; a <= D; ++a)
    for (int b = 0; b < a; ++b)
      if (*v[a] == *v[b]) return Sign::zero;
  if constexpr (D == 2)
    return orientation(k, *v[0], *v[1], *v[2]);
  else
    return orientation(k, *v[0], *v[1], *v[2], *v[3]);
}

// Where q lies for the circumcircle / circumsphere of the positively oriented
// simplex v: positive strictly inside, zero on it, negative outside.
template <int D>
Sign sphere_side(const ExactKernel& k, const std::array<const Point<D>*, D + 1>& v, const Point<D>& q) {
  if constexpr (D == 2) {
    return k.incircle(*v[0], *v[1], *v[2], q);
  } else {
    // orient3d(v1,v0,v2,v3) = -orient3d(v0,v1,v2,v3) > 0, so insphere > 0 means inside.
    return k.insphere(*v[1], *v[0], *v[2], *v[3], q);
  }
}

// Canonical (first-occurrence) index of every point; -0.0 and +0.0 are equal.
template <int D>
std::vector<std::uint32_t> first_occurrences(std::span<const Point<D>> pts, std::size_t& distinct) {
  const auto bits = [&](std::uint32_t i) {
    std::array<std::uint64_t, D> b{};
    for (int j = 0; j < D; ++j) {
      const double x = pts[i][j] == 0 ? 0.0 : pts[i][j];
      std::memcpy(&b[j], &x, sizeof x);
    }
    return b;
  };
  std::vector<std::uint32_t> first(pts.size());
  IdTable table(pts.size());
  distinct = 0;
  for (std::uint32_t i = 0; i < pts.size(); ++i) {
    const auto key = bits(i);
    std::uint64_t h = 0;
    for (auto b : key) h = mix(h ^ b);
    const std::uint32_t found = table.find_or_insert(h, i, [&](std::uint32_t s) {
      for (int j = 0; j < D; ++j)
        if (!(pts[s][j] == pts[i][j])) return false;
      return true;
    });
    first[i] = found == kNone ? i : found;
    if (found == kNone) ++distinct;
  }
  return first;
}

// Does the point set span dimension D? Exact; O(n).
template <int D>
bool full_dimensional(const ExactKernel& k, std::span<const Point<D>> p) {
  const std::size_t n = p.size();
  std::size_t i1 = 1;
  while (i1 < n && p[i1] == p[0]) ++i1;
  if (i1 >= n) return false;
  if constexpr (D == 2) {
    for (std::size_t i = i1 + 1; i < n; ++i)
      if (k.orient2d(p[0], p[i1], p[i]) != Sign::zero) return true;
    return false;
  } else {
    // A third point off the line p0 p1: some coordinate projection is non-degenerate.
    const auto off_line = [&](const Point3& q) {
      for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3;
        const Point2 u{p[0][a], p[0][b]}, v{p[i1][a], p[i1][b]}, w{q[a], q[b]};
        if (k.orient2d(u, v, w) != Sign::zero) return true;
      }
      return false;
    };
    std::size_t i2 = i1 + 1;
    while (i2 < n && !off_line(p[i2])) ++i2;
    if (i2 >= n) return false;
    for (std::size_t i = i2 + 1; i < n; ++i)
      if (k.orient3d(p[0], p[i1], p[i2], p[i]) != Sign::zero) return true;
    return false;
  }
}

// The facet of simplex `s` opposite local vertex i, sorted, with the parity of
// its induced orientation: (-1)^i times the parity of the sorting permutation.
template <int D>
std::array<std::uint32_t, D> sorted_facet(const std::uint32_t* s, int i, int& parity) {
  std::array<std::uint32_t, D> f{};
  int k = 0;
  for (int j = 0; j <= D; ++j)
    if (j != i) f[k++] = s[j];
  parity = i & 1;
  for (int a = 1; a < D; ++a)
    for (int b = a; b > 0 && f[b - 1] > f[b]; --b) {
      std::swap(f[b - 1], f[b]);
      parity ^= 1;
    }
  return f;
}

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) {
    for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<std::uint32_t>(i);
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    parent[std::max(a, b)] = std::min(a, b);
    return true;
  }
};

template <int D>
class Validator {
  static constexpr int V = D + 1;  // vertices per simplex

 public:
  Validator(std::span<const Point<D>> pts, std::span<const std::uint32_t> simplices,
            std::vector<Offence>* offences = nullptr)
      : p_(pts), in_(simplices), offences_(offences) {}

  ValidationReport run() {
    r_.dimension = D;
    r_.points = p_.size();
    if (in_.size() % V != 0) {  // a truncated simplex: report, nothing else is meaningful
      flag(Check::index_range, static_cast<std::int64_t>(in_.size() / V));
      r_.skipped = true;
      return r_;
    }
    m_ = in_.size() / V;
    r_.simplices = m_;
    if (p_.size() >= kNone || in_.size() / V >= kNone / V) {
      flag(Check::index_range, 0);  // more than 32-bit ids can address
      r_.skipped = true;
      return r_;
    }
    first_ = first_occurrences<D>(p_, r_.distinct_points);
    r_.lower_dimensional = !full_dimensional<D>(k_, p_);
    if (!canonical_indices()) {
      r_.skipped = true;
      return r_;
    }
    orientations();
    duplicate_simplices();
    link_facets();
    if constexpr (D == 2)
      boundary_2d();
    else
      boundary_3d();
    connectivity();
    cover_degree();
    missing_vertices();
    delaunay();
    return r_;
  }

 private:
  // Counts the offence in the report; lists it too when the caller asked for all.
  void flag(Check c, std::int64_t simplex, int facet = -1, std::int64_t point = -1) {
    dlab::flag(r_[c], simplex, facet, point);
    if (offences_ != nullptr) offences_->push_back({c, simplex, facet, point});
  }

  const std::uint32_t* simplex(std::size_t s) const { return &v_[s * V]; }
  std::array<const Point<D>*, V> coords(std::size_t s) const {
    std::array<const Point<D>*, V> c{};
    for (int j = 0; j < V; ++j) c[j] = &p_[v_[s * V + j]];
    return c;
  }

  // Indices in range; copies of duplicated points replaced by the first one
  // (in a copy of the simplices, made only then).
  bool canonical_indices() {
    bool in_range = true;
    for (std::size_t i = 0; i < in_.size(); ++i) {
      const std::uint32_t x = in_[i];
      if (x >= p_.size()) {
        flag(Check::index_range, static_cast<std::int64_t>(i / V), -1, x);
        in_range = false;
        continue;
      }
      if (first_[x] == x) continue;
      flag(Check::duplicate_reference, static_cast<std::int64_t>(i / V), -1, x);
      if (canonical_copy_.empty()) {
        reserve_huge(canonical_copy_, in_.size());
        canonical_copy_.assign(in_.begin(), in_.end());
      }
      canonical_copy_[i] = first_[x];
    }
    v_ = canonical_copy_.empty() ? in_ : std::span<const std::uint32_t>(canonical_copy_);
    return in_range;
  }

  void orientations() {
    assign_huge(ok_, m_, std::uint8_t{0});
    for (std::size_t s = 0; s < m_; ++s) {
      if (orientation<D>(k_, coords(s)) == Sign::positive)
        ok_[s] = 1;
      else
        flag(Check::orientation, static_cast<std::int64_t>(s));
    }
  }

  void duplicate_simplices() {
    assign_huge(dup_, m_, std::uint8_t{0});
    IdTable table(m_);
    const auto key = [&](std::size_t s) {
      std::array<std::uint32_t, V> a{};
      std::copy(simplex(s), simplex(s) + V, a.begin());
      std::sort(a.begin(), a.end());
      return a;
    };
    for (std::uint32_t s = 0; s < m_; ++s) {
      const auto ks = key(s);
      const std::uint32_t found =
          table.find_or_insert(hash_ids(ks), s, [&](std::uint32_t t) { return key(t) == ks; });
      if (found != kNone) {
        dup_[s] = 1;
        flag(Check::duplicate_simplex, s);
      }
    }
  }

  // nb_[s*V+i]: the facet incidence on the other side of facet i of s; kNone
  // on the boundary; kExtra for a third simplex on a facet or a facet with a
  // repeated vertex.
  void link_facets() {
    assign_huge(nb_, m_ * V, kNone);
    IdTable table(m_ * V / 2 + m_ / 16 + 16);  // V/2 facets per simplex, and the boundary's
    for (std::uint32_t s = 0; s < m_; ++s) {
      if (dup_[s]) continue;
      for (int i = 0; i < V; ++i) {
        int parity = 0;
        const auto f = sorted_facet<D>(simplex(s), i, parity);
        const std::uint32_t inc = s * V + i;
        const std::uint32_t other = table.find_or_insert(hash_ids(f), inc, [&](std::uint32_t e) {
          int q = 0;
          return sorted_facet<D>(simplex(e / V), static_cast<int>(e % V), q) == f;
        });
        if (other == kNone) continue;
        if (nb_[other] != kNone || other / V == s) {  // third simplex, or a repeated vertex
          nb_[inc] = kExtra;
          flag(Check::non_manifold_facet, s, i);
          continue;
        }
        nb_[other] = inc;
        nb_[inc] = other;
        int q = 0;
        sorted_facet<D>(simplex(other / V), static_cast<int>(other % V), q);
        if (q == parity) flag(Check::facet_same_side, s, i);
      }
    }
    for (std::size_t inc = 0; inc < m_ * V; ++inc) {
      if (dup_[inc / V] || nb_[inc] == kExtra) continue;
      if (nb_[inc] == kNone)
        ++r_.boundary_facets;
      else if (nb_[inc] > inc)
        ++r_.interior_facets;
    }
  }

  bool is_boundary(std::size_t inc) const { return !dup_[inc / V] && nb_[inc] == kNone; }

  // 2D: boundary edges, oriented with the triangle on their left, must form one
  // cycle that turns left (or goes straight on) at every vertex and turns once.
  void boundary_2d() {
    const std::size_t n = p_.size();
    std::vector<std::uint32_t> next(n, kNone), prev(n, kNone), edge_of(n, kNone);
    std::vector<std::uint8_t> outs(n, 0), ins(n, 0);
    for (std::size_t inc = 0; inc < m_ * V; ++inc) {
      if (!is_boundary(inc)) continue;
      const std::uint32_t* t = simplex(inc / V);
      const int i = static_cast<int>(inc % V);
      const std::uint32_t a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      if (outs[a]++ == 0) next[a] = b, edge_of[a] = static_cast<std::uint32_t>(inc);
      if (ins[b]++ == 0) prev[b] = a;
      if (outs[a] == 2 || ins[b] == 2)
        flag(Check::boundary_manifold, static_cast<std::int64_t>(inc / V), i);
    }
    std::uint64_t minima = 0;
    std::int64_t first_min = -1;
    for (std::uint32_t v = 0; v < n; ++v) {
      if (outs[v] == 0 && ins[v] == 0) continue;
      const std::int64_t s = edge_of[v] == kNone ? -1 : edge_of[v] / V;
      if (outs[v] != ins[v]) {
        flag(Check::boundary_manifold, s, -1, v);
        continue;
      }
      if (outs[v] != 1) continue;  // already reported
      const Point2 &u = p_[prev[v]], &x = p_[v], &w = p_[next[v]];
      if (lex_compare<2>(u, x) > 0 && lex_compare<2>(w, x) > 0) {
        if (minima++ == 0) first_min = s;
      }
      const Sign turn = k_.orient2d(u, x, w);
      const bool straight_on = turn == Sign::zero && lex_compare<2>(u, x) == lex_compare<2>(x, w);
      if (turn == Sign::negative || (turn == Sign::zero && !straight_on))
        flag(Check::boundary_convex, s, static_cast<int>(edge_of[v] % V), v);
      // Only ok_ simplices give a meaningful turn; a bad one is reported already.
    }
    if (r_.boundary_facets > 0 && r_[Check::boundary_manifold].count == 0 && minima != 1)
      flag(Check::boundary_convex, first_min);
  }

  // 3D: boundary triangles with their induced (outward) orientation must form a
  // closed, consistently oriented, connected surface of Euler characteristic 2,
  // convex at every ridge.
  void boundary_3d() {
    std::vector<std::uint32_t> faces;  // boundary facet incidences
    for (std::size_t inc = 0; inc < m_ * V; ++inc)
      if (is_boundary(inc)) faces.push_back(static_cast<std::uint32_t>(inc));
    if (faces.empty()) return;
    // Directed triangle of a boundary incidence, oriented as induced by its tet.
    const auto tri = [&](std::uint32_t inc) {
      const std::uint32_t* t = simplex(inc / V);
      const int i = static_cast<int>(inc % V);
      std::array<std::uint32_t, 3> f{};
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i) f[k++] = t[j];
      if (i & 1) std::swap(f[0], f[1]);
      return f;
    };
    // Ridge id = 3 * (index in faces) + edge; edge e goes f[e] -> f[(e+1)%3].
    const auto ridge = [&](std::uint32_t id) {
      const auto f = tri(faces[id / 3]);
      const int e = static_cast<int>(id % 3);
      return std::array<std::uint32_t, 2>{f[e], f[(e + 1) % 3]};
    };
    const auto key = [](std::array<std::uint32_t, 2> r) {
      if (r[0] > r[1]) std::swap(r[0], r[1]);
      return r;
    };
    std::vector<std::uint32_t> mate(faces.size() * 3, kNone);
    IdTable table(faces.size() * 3);
    UnionFind components(faces.size());
    std::size_t components_left = faces.size();
    std::vector<std::uint8_t> on_boundary(p_.size(), 0);
    std::size_t boundary_vertices = 0;
    for (std::uint32_t id = 0; id < faces.size() * 3; ++id) {
      const auto r = ridge(id);
      if (!on_boundary[r[0]]) on_boundary[r[0]] = 1, ++boundary_vertices;
      const auto kr = key(r);
      const std::uint32_t other =
          table.find_or_insert(hash_ids(kr), id, [&](std::uint32_t e) { return key(ridge(e)) == kr; });
      if (other == kNone) continue;
      const std::uint32_t s = faces[id / 3] / V;
      if (mate[other] != kNone || ridge(other) != std::array<std::uint32_t, 2>{r[1], r[0]}) {
        flag(Check::boundary_manifold, s, static_cast<int>(faces[id / 3] % V));
        continue;
      }
      mate[other] = id;
      mate[id] = other;
      if (components.unite(id / 3, other / 3)) --components_left;
      // Convexity: the far vertex of the other face is not strictly outside this one.
      const std::uint32_t t = faces[other / 3] / V;
      if (!ok_[s] || !ok_[t]) continue;
      const auto f = tri(faces[id / 3]);
      const auto g = tri(faces[other / 3]);
      const std::uint32_t far = g[(other % 3 + 2) % 3];
      const std::uint32_t apex = simplex(s)[faces[id / 3] % V];
      const Sign side = k_.orient3d(p_[f[0]], p_[f[1]], p_[f[2]], p_[far]);
      const Sign inner = k_.orient3d(p_[f[0]], p_[f[1]], p_[f[2]], p_[apex]);
      if (side != Sign::zero && side != inner)
        flag(Check::boundary_convex, s, static_cast<int>(faces[id / 3] % V), far);
    }
    for (std::uint32_t id = 0; id < faces.size() * 3; ++id)
      if (mate[id] == kNone)
        flag(Check::boundary_manifold, faces[id / 3] / V, static_cast<int>(faces[id / 3] % V));
    if (r_[Check::boundary_manifold].count != 0) return;
    // Closed surface: E = 3F/2. Euler characteristic V - E + F must be 2, connected.
    const std::int64_t euler = static_cast<std::int64_t>(boundary_vertices) -
                               static_cast<std::int64_t>(faces.size() * 3 / 2) +
                               static_cast<std::int64_t>(faces.size());
    if (euler != 2 || components_left != 1)
      flag(Check::boundary_manifold, faces[0] / V, static_cast<int>(faces[0] % V));
  }

  void connectivity() {
    std::vector<std::uint8_t> seen(m_, 0);
    std::vector<std::uint32_t> stack;
    std::size_t components = 0;
    for (std::uint32_t s0 = 0; s0 < m_; ++s0) {
      if (seen[s0] || dup_[s0]) continue;
      if (++components == 2) flag(Check::disconnected, s0);
      seen[s0] = 1;
      stack.push_back(s0);
      while (!stack.empty()) {
        const std::uint32_t s = stack.back();
        stack.pop_back();
        for (int i = 0; i < V; ++i) {
          const std::uint32_t o = nb_[s * V + i];
          if (o < kExtra && !seen[o / V]) seen[o / V] = 1, stack.push_back(o / V);
        }
      }
    }
  }

  // The number of simplices containing p = v0 + e(w1-v0) + e^2(w2-v0) + ...
  // (e -> 0+), a point inside the first valid simplex s0 = (v0, w1, ..., wd).
  // For simplex t and its vertex j, the orientation of t with vertex j replaced
  // by p is affine in p, so its sign is the first non-zero among the signs with
  // v0, w1, ..., wd in that place; p is inside t iff all d+1 are positive.
  // Never all zero: that would make s0 flat.
  void cover_degree() {
    std::size_t s0 = 0;
    while (s0 < m_ && (!ok_[s0] || dup_[s0])) ++s0;
    if (s0 == m_) return;
    const auto probe = coords(s0);
    const Point<D>& v0 = *probe[0];
    std::uint64_t degree = 0;
    std::int64_t other = -1;
    for (std::size_t t = 0; t < m_; ++t) {
      if (!ok_[t] || dup_[t]) continue;
      auto c = coords(t);
      bool in_box = true;  // p is near v0: t must contain v0 (exact comparisons)
      for (int j = 0; j < D && in_box; ++j) {
        double lo = (*c[0])[j], hi = lo;
        for (int a = 1; a < V; ++a) lo = std::min(lo, (*c[a])[j]), hi = std::max(hi, (*c[a])[j]);
        in_box = lo <= v0[j] && v0[j] <= hi;
      }
      if (!in_box) continue;
      bool inside = true;
      for (int j = 0; j < V && inside; ++j) {
        const Point<D>* keep = c[j];
        Sign s = Sign::zero;
        for (int q = 0; q < V && s == Sign::zero; ++q) {
          c[j] = probe[q];
          s = orientation<D>(k_, c);
        }
        c[j] = keep;
        inside = s == Sign::positive;
      }
      if (inside && ++degree >= 2 && other < 0) other = static_cast<std::int64_t>(t);
    }
    if (degree != 1) flag(Check::cover_degree, other >= 0 ? other : static_cast<std::int64_t>(s0));
  }

  void missing_vertices() {
    if (r_.lower_dimensional) return;  // zero simplices expected; orientation catches others
    std::vector<std::uint8_t> used(p_.size(), 0);
    for (std::uint32_t x : v_) used[x] = 1;
    for (std::uint32_t i = 0; i < p_.size(); ++i)
      if (first_[i] == i && !used[i]) flag(Check::missing_vertex, -1, -1, i);
  }

  void delaunay() {
    for (std::size_t inc = 0; inc < m_ * V; ++inc) {
      const std::uint32_t o = nb_[inc];
      if (o >= kExtra || o < inc) continue;
      const std::size_t s = inc / V, t = o / V;
      if (!ok_[s] || !ok_[t]) continue;
      const Point<D>& far = p_[simplex(t)[o % V]];
      const Sign side = sphere_side<D>(k_, coords(s), far);
      if (side == Sign::positive)
        flag(Check::not_delaunay, static_cast<std::int64_t>(s), static_cast<int>(inc % V));
      else if (side == Sign::zero)
        ++r_.cospherical_facets;
    }
  }

  ExactKernel k_{};
  std::span<const Point<D>> p_;
  std::span<const std::uint32_t> in_;
  std::size_t m_ = 0;
  ValidationReport r_;
  std::vector<Offence>* offences_ = nullptr;
  std::vector<std::uint32_t> first_, canonical_copy_, nb_;
  std::span<const std::uint32_t> v_;  // the simplices, canonical: in_ or canonical_copy_
  std::vector<std::uint8_t> ok_, dup_;
};

}  // namespace

std::string_view check_name(Check c) {
  switch (c) {
    case Check::index_range:
      return "index_range";
    case Check::duplicate_reference:
      return "duplicate_reference";
    case Check::orientation:
      return "orientation";
    case Check::duplicate_simplex:
      return "duplicate_simplex";
    case Check::non_manifold_facet:
      return "non_manifold_facet";
    case Check::facet_same_side:
      return "facet_same_side";
    case Check::boundary_manifold:
      return "boundary_manifold";
    case Check::boundary_convex:
      return "boundary_convex";
    case Check::cover_degree:
      return "cover_degree";
    case Check::disconnected:
      return "disconnected";
    case Check::missing_vertex:
      return "missing_vertex";
    case Check::not_delaunay:
      return "not_delaunay";
    case Check::count_:
      break;
  }
  return "?";
}

bool ValidationReport::valid() const {
  for (int c = 0; c < kCheckCount; ++c)
    if (c != static_cast<int>(Check::not_delaunay) && checks[c].count != 0) return false;
  return true;
}

std::string ValidationReport::summary() const {
  std::ostringstream out;
  for (int c = 0; c < kCheckCount; ++c) {
    const CheckResult& r = checks[c];
    if (r.count == 0) continue;
    out << check_name(static_cast<Check>(c)) << ": " << r.count << " (first:";
    if (r.simplex >= 0) out << " simplex " << r.simplex;
    if (r.facet >= 0) out << " facet " << r.facet;
    if (r.point >= 0) out << " point " << r.point;
    out << ")\n";
  }
  if (skipped) out << "geometric checks skipped\n";
  if (out.str().empty())
    out << (lower_dimensional ? "valid (lower-dimensional input, no simplex)\n" : "valid Delaunay\n");
  return out.str();
}

ValidationReport validate(std::span<const Point2> points, std::span<const std::uint32_t> simplices) {
  return Validator<2>(points, simplices).run();
}
ValidationReport validate(std::span<const Point3> points, std::span<const std::uint32_t> simplices) {
  return Validator<3>(points, simplices).run();
}
ValidationReport validate(const PointSet& points, std::span<const std::uint32_t> simplices) {
  if (points.dimension == 3) return validate(std::span<const Point3>(points.p3), simplices);
  return validate(std::span<const Point2>(points.p2), simplices);
}
ValidationReport validate(const PointSet& points, std::span<const std::uint32_t> simplices,
                          std::vector<Offence>& offences) {
  offences.clear();
  if (points.dimension == 3)
    return Validator<3>(std::span<const Point3>(points.p3), simplices, &offences).run();
  return Validator<2>(std::span<const Point2>(points.p2), simplices, &offences).run();
}

namespace {
template <int D>
std::size_t orient_all(std::span<const Point<D>> pts, std::span<std::uint32_t> simplices) {
  const ExactKernel k;
  constexpr std::size_t n = D + 1;
  std::size_t swapped = 0;
  for (std::size_t s = 0; s + n <= simplices.size(); s += n) {
    std::array<const Point<D>*, n> v{};
    bool in_range = true;
    for (std::size_t j = 0; j < n; ++j) {
      if (simplices[s + j] >= pts.size()) in_range = false;
      else v[j] = &pts[simplices[s + j]];
    }
    if (in_range && orientation<D>(k, v) == Sign::negative) {
      std::swap(simplices[s], simplices[s + 1]);
      ++swapped;
    }
  }
  return swapped;
}
}  // namespace

std::size_t orient_positively(const PointSet& points, std::span<std::uint32_t> simplices) {
  if (points.dimension == 3) return orient_all<3>(std::span<const Point3>(points.p3), simplices);
  return orient_all<2>(std::span<const Point2>(points.p2), simplices);
}

}  // namespace dlab
