// See convex_clip.hpp.
#include "voronoi/convex_clip.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace dlab::voronoi {
namespace {

template <class P>
double dot(const P& a, const P& b) {
  double s = 0;
  for (std::size_t i = 0; i < a.size(); ++i) s += a[i] * b[i];
  return s;
}

template <class P>
P minus(const P& a, const P& b) {
  P r;
  for (std::size_t i = 0; i < a.size(); ++i) r[i] = a[i] - b[i];
  return r;
}

// Signed distances (times |n|) and their classes -1 / 0 / +1 (within tol: 0).
template <class V, class P>
std::vector<int> classify(const std::vector<V>& vs, const P& n, const P& m, double scale,
                          std::vector<double>& d) {
  const double tol = 1e-12 * std::sqrt(dot(n, n)) * scale;
  std::vector<int> s(vs.size());
  d.resize(vs.size());
  for (std::size_t i = 0; i < vs.size(); ++i) {
    d[i] = dot(n, minus(vs[i].p, m));
    s[i] = d[i] > tol ? 1 : (d[i] < -tol ? -1 : 0);
  }
  return s;
}

// The point where edge (i, j) crosses the plane, computed from the smaller
// index so that both faces of the edge get the same bits.
template <class V>
auto crossing(const std::vector<V>& vs, const std::vector<double>& d, std::size_t i, std::size_t j) {
  if (j < i) std::swap(i, j);
  const double t = d[i] / (d[i] - d[j]);
  auto r = vs[i].p;
  for (std::size_t k = 0; k < r.size(); ++k) r[k] = vs[i].p[k] + (vs[j].p[k] - vs[i].p[k]) * t;
  return r;
}

template <class P>
double diagonal(const P& lo, const P& hi) {
  const P e = minus(hi, lo);
  return std::sqrt(dot(e, e));
}

}  // namespace

Polygon box_polygon(const Point2& lo, const Point2& hi) {
  return {{{lo[0], lo[1]}}, {{hi[0], lo[1]}}, {{hi[0], hi[1]}}, {{lo[0], hi[1]}}};
}

Polyhedron box_polyhedron(const Point3& lo, const Point3& hi) {
  Polyhedron b;
  for (int v = 0; v < 8; ++v)  // bit 0: x, bit 1: y, bit 2: z
    b.vertices.push_back({{(v & 1) ? hi[0] : lo[0], (v & 2) ? hi[1] : lo[1], (v & 4) ? hi[2] : lo[2]}});
  b.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  return b;
}

Polygon merge_equal(const Polygon& poly) {
  Polygon out;
  for (const auto& v : poly)
    if (out.empty() || out.back().p != v.p) out.push_back(v);
  while (out.size() > 1 && out.back().p == out.front().p) out.pop_back();
  if (out.size() < 3) out.clear();
  return out;
}

Polyhedron merge_equal(const Polyhedron& poly) {
  std::map<Point3, std::uint32_t> first;  // position -> first vertex there
  std::vector<std::uint32_t> canon(poly.vertices.size());
  for (std::uint32_t i = 0; i < poly.vertices.size(); ++i)
    canon[i] = first.emplace(poly.vertices[i].p, i).first->second;
  Polyhedron out;
  std::vector<std::int64_t> renum(poly.vertices.size(), -1);
  for (const auto& f : poly.faces) {
    std::vector<std::uint32_t> g;
    for (std::uint32_t v : f)
      if (g.empty() || g.back() != canon[v]) g.push_back(canon[v]);
    while (g.size() > 1 && g.back() == g.front()) g.pop_back();
    if (g.size() < 3) continue;
    for (auto& v : g) {
      if (renum[v] < 0) {
        renum[v] = static_cast<std::int64_t>(out.vertices.size());
        out.vertices.push_back(poly.vertices[v]);
      }
      v = static_cast<std::uint32_t>(renum[v]);
    }
    out.faces.push_back(std::move(g));
  }
  return out;
}

Polygon cut(const Polygon& poly, const Point2& n, const Point2& m, double scale) {
  std::vector<double> d;
  const std::vector<int> s = classify(poly, n, m, scale, d);
  if (std::none_of(s.begin(), s.end(), [](int x) { return x > 0; })) return poly;
  Polygon out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const std::size_t j = (i + 1) % poly.size();
    if (s[i] <= 0) out.push_back(poly[i]);
    if (s[i] * s[j] < 0) out.push_back({crossing(poly, d, i, j), kNewVertex});
  }
  return merge_equal(out);
}

Polyhedron cut(const Polyhedron& poly, const Point3& n, const Point3& m, double scale) {
  std::vector<double> d;
  const std::vector<int> s = classify(poly.vertices, n, m, scale, d);
  if (std::none_of(s.begin(), s.end(), [](int x) { return x > 0; })) return poly;
  if (std::none_of(s.begin(), s.end(), [](int x) { return x < 0; })) return {};
  Polyhedron out;
  out.vertices = poly.vertices;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> on_edge;
  std::vector<std::uint32_t> cap;
  for (std::uint32_t i = 0; i < s.size(); ++i)
    if (s[i] == 0) cap.push_back(i);  // those not in a kept face go with merge_equal
  for (const auto& f : poly.faces) {
    std::vector<std::uint32_t> g;
    for (std::size_t k = 0; k < f.size(); ++k) {
      const std::uint32_t i = f[k], j = f[(k + 1) % f.size()];
      if (s[i] <= 0) g.push_back(i);
      if (s[i] * s[j] < 0) {
        const auto key = std::minmax(i, j);
        auto [it, fresh] = on_edge.emplace(key, static_cast<std::uint32_t>(out.vertices.size()));
        if (fresh) {
          out.vertices.push_back({crossing(poly.vertices, d, i, j), kNewVertex});
          cap.push_back(it->second);
        }
        g.push_back(it->second);
      }
    }
    if (g.size() >= 3) out.faces.push_back(std::move(g));
  }
  if (cap.size() >= 3) {
    // Angular order around the centroid, counterclockwise about n.
    Point3 c{0, 0, 0};
    for (auto v : cap)
      for (int k = 0; k < 3; ++k) c[k] += out.vertices[v].p[k] / static_cast<double>(cap.size());
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(n[k]) < std::fabs(n[axis])) axis = k;
    Point3 a{0, 0, 0};
    a[axis] = 1;
    const auto cross = [](const Point3& p, const Point3& q) {
      return Point3{p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
    };
    const Point3 e1 = cross(n, a), e2 = cross(n, e1);  // e1 x e2 points along n
    std::vector<std::pair<double, std::uint32_t>> by_angle;
    for (auto v : cap) {
      const Point3 r = minus(out.vertices[v].p, c);
      by_angle.push_back({std::atan2(dot(r, e2), dot(r, e1)), v});
    }
    std::sort(by_angle.begin(), by_angle.end());
    std::vector<std::uint32_t> face;
    for (const auto& [angle, v] : by_angle) face.push_back(v);
    out.faces.push_back(std::move(face));
  }
  out = merge_equal(out);
  if (out.empty()) return {};
  return out;
}

Polygon cut_to_box(Polygon poly, const Point2& lo, const Point2& hi) {
  const double L = diagonal(lo, hi);
  for (int k = 0; k < 2 && !poly.empty(); ++k) {
    Point2 n{0, 0};
    n[k] = -1;
    poly = cut(poly, n, lo, L);
    n[k] = 1;
    if (!poly.empty()) poly = cut(poly, n, hi, L);
  }
  return poly;
}

Polyhedron cut_to_box(Polyhedron poly, const Point3& lo, const Point3& hi) {
  const double L = diagonal(lo, hi);
  for (int k = 0; k < 3 && !poly.empty(); ++k) {
    Point3 n{0, 0, 0};
    n[k] = -1;
    poly = cut(poly, n, lo, L);
    n[k] = 1;
    if (!poly.empty()) poly = cut(poly, n, hi, L);
  }
  return poly;
}

}  // namespace dlab::voronoi
