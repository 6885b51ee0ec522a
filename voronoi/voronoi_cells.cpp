// See voronoi_cells.hpp.
#include "voronoi/voronoi_cells.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "voronoi/circumcentre.hpp"
#include "voronoi/convex_clip.hpp"

namespace dlab::voronoi {
namespace {

template <int D>
Point<D> centre_of(const std::vector<Point<D>>& pts, const std::uint32_t* v) {
  if constexpr (D == 2)
    return circumcentre(pts[v[0]], pts[v[1]], pts[v[2]]);
  else
    return circumcentre(pts[v[0]], pts[v[1]], pts[v[2]], pts[v[3]]);
}

template <int D>
class Builder {
 public:
  static constexpr std::size_t K = D + 1;

  Builder(const std::vector<Point<D>>& pts, const std::vector<std::uint32_t>& simplices,
          const Point<D>& lo, const Point<D>& hi)
      : pts_(pts), simplices_(simplices), lo_(lo), hi_(hi), incident_(pts.size()) {
    double l2 = 0;
    for (int k = 0; k < D; ++k) l2 += (hi[k] - lo[k]) * (hi[k] - lo[k]);
    scale_ = std::sqrt(l2);
    const std::size_t m = simplices.size() / K;
    std::map<Point<D>, std::uint32_t> first;  // equal centres share the first one's vertex
    canon_.resize(m);
    for (std::uint32_t t = 0; t < m; ++t) {
      out_.vertices.push_back(centre_of<D>(pts, &simplices[t * K]));
      canon_[t] = first.emplace(out_.vertices.back(), t).first->second;
      for (std::size_t j = 0; j < K; ++j) incident_[simplices[t * K + j]].push_back(t);
    }
    out_.centres = m;
  }

  Diagram<D> build() {
    if (simplices_.empty()) {
      // Lower-dimensional: every distinct site against all the others.
      std::map<Point<D>, std::uint32_t> first;
      std::vector<std::uint32_t> sites;
      for (std::uint32_t i = 0; i < pts_.size(); ++i)
        if (first.emplace(pts_[i], i).second) sites.push_back(i);
      for (std::uint32_t s : sites) {
        std::vector<std::uint32_t> others;
        for (std::uint32_t q : sites)
          if (q != s) others.push_back(q);
        add_cut_box_cell(s, others);
      }
      return std::move(out_);
    }
    for (std::uint32_t s = 0; s < pts_.size(); ++s) {
      if (incident_[s].empty()) continue;  // a duplicate: no cell
      std::vector<std::uint32_t> neighbours;
      for (std::uint32_t t : incident_[s])
        for (std::size_t j = 0; j < K; ++j)
          if (simplices_[t * K + j] != s) neighbours.push_back(simplices_[t * K + j]);
      std::sort(neighbours.begin(), neighbours.end());
      neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
      if (!add_dual_cell(s, neighbours)) add_cut_box_cell(s, neighbours);
    }
    return std::move(out_);
  }

 private:
  // The vertex of a cell in out_.vertices: a centre's own, or a new one.
  std::uint32_t global(const Vertex<D>& v) {
    if (v.id >= 0) return canon_[static_cast<std::size_t>(v.id)];
    out_.vertices.push_back(v.p);
    return static_cast<std::uint32_t>(out_.vertices.size() - 1);
  }

  bool outside_box(const Point<D>& p) const {
    for (int k = 0; k < D; ++k)
      if (p[k] < lo_[k] || p[k] > hi_[k]) return true;
    return false;
  }

  Vertex<D> centre_vertex(std::uint32_t t) const {
    const std::uint32_t c = canon_[t];
    return {out_.vertices[c], static_cast<std::int64_t>(c)};
  }

  // The cycle of the simplices around an interior ridge (2D: the site; 3D: the
  // edge s-t), from edges a -> b of the link; nullopt if it does not close
  // (the ridge is on the hull).
  static std::optional<std::vector<std::uint32_t>> cycle(
      const std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>>& next) {
    if (next.empty()) return std::nullopt;
    std::vector<std::uint32_t> order;
    std::uint32_t a = next.begin()->first;
    for (std::size_t step = 0; step < next.size(); ++step) {  // bounded: one lap
      const auto it = next.find(a);
      if (it == next.end()) return std::nullopt;
      order.push_back(it->second.second);
      a = it->second.first;
    }
    if (a != next.begin()->first) return std::nullopt;
    return order;
  }

  // The position of vertex v in simplex t.
  std::size_t slot(std::uint32_t t, std::uint32_t v) const {
    for (std::size_t j = 0; j < K; ++j)
      if (simplices_[t * K + j] == v) return j;
    return K;
  }

  bool add_dual_cell(std::uint32_t s, const std::vector<std::uint32_t>& neighbours);

  void add_cut_box_cell(std::uint32_t s, const std::vector<std::uint32_t>& neighbours);

  void add_cell(std::uint32_t s, bool clipped, const Polygon& poly) {
    if (poly.size() < 3) return;
    Cell c{s, clipped, {{}}};
    for (const auto& v : poly) c.faces[0].push_back(global(v));
    out_.cells.push_back(std::move(c));
  }
  void add_cell(std::uint32_t s, bool clipped, const Polyhedron& poly) {
    if (poly.empty()) return;
    std::vector<std::uint32_t> ids;
    for (const auto& v : poly.vertices) ids.push_back(global(v));
    Cell c{s, clipped, {}};
    for (const auto& f : poly.faces) {
      c.faces.emplace_back();
      for (std::uint32_t v : f) c.faces.back().push_back(ids[v]);
    }
    out_.cells.push_back(std::move(c));
  }

  const std::vector<Point<D>>& pts_;
  const std::vector<std::uint32_t>& simplices_;
  Point<D> lo_, hi_;
  double scale_ = 1;
  std::vector<std::vector<std::uint32_t>> incident_;
  std::vector<std::uint32_t> canon_;
  Diagram<D> out_;
};

template <>
bool Builder<2>::add_dual_cell(std::uint32_t s, const std::vector<std::uint32_t>&) {
  // Triangle (s, a, b) counterclockwise: the link edge a -> b.
  std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> next;
  for (std::uint32_t t : incident_[s]) {
    const std::size_t i = slot(t, s);
    next[simplices_[t * 3 + (i + 1) % 3]] = {simplices_[t * 3 + (i + 2) % 3], t};
  }
  const auto order = cycle(next);
  if (!order) return false;
  Polygon poly;
  bool outside = false;
  for (std::uint32_t t : *order) {
    poly.push_back(centre_vertex(t));
    outside = outside || outside_box(poly.back().p);
  }
  poly = merge_equal(poly);
  if (outside) poly = cut_to_box(poly, lo_, hi_);
  add_cell(s, outside, poly);
  return true;
}

template <>
bool Builder<3>::add_dual_cell(std::uint32_t s, const std::vector<std::uint32_t>& neighbours) {
  Polyhedron poly;
  std::map<std::uint32_t, std::uint32_t> local;  // canonical centre -> poly vertex
  bool outside = false;
  for (std::uint32_t q : neighbours) {
    // Tetrahedron (s, q, a, b) positively oriented: the link edge a -> b,
    // counterclockwise about q - s.
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> next;
    for (std::uint32_t t : incident_[s]) {
      const std::size_t j = slot(t, q);
      if (j == K) continue;
      std::size_t p[4] = {slot(t, s), j, 0, 0}, n = 2;
      for (std::size_t k = 0; k < 4; ++k)
        if (k != p[0] && k != p[1]) p[n++] = k;
      int inversions = 0;
      for (int x = 0; x < 4; ++x)
        for (int y = x + 1; y < 4; ++y) inversions += p[x] > p[y];
      if (inversions % 2) std::swap(p[2], p[3]);
      next[simplices_[t * 4 + p[2]]] = {simplices_[t * 4 + p[3]], t};
    }
    const auto order = cycle(next);
    if (!order) return false;
    std::vector<std::uint32_t> face;
    for (std::uint32_t t : *order) {
      const Vertex<3> v = centre_vertex(t);
      auto [it, fresh] = local.emplace(static_cast<std::uint32_t>(v.id),
                                       static_cast<std::uint32_t>(poly.vertices.size()));
      if (fresh) {
        poly.vertices.push_back(v);
        outside = outside || outside_box(v.p);
      }
      face.push_back(it->second);
    }
    poly.faces.push_back(std::move(face));
  }
  poly = merge_equal(poly);
  if (outside) poly = cut_to_box(poly, lo_, hi_);
  add_cell(s, outside, poly);
  return true;
}

template <int D>
void Builder<D>::add_cut_box_cell(std::uint32_t s, const std::vector<std::uint32_t>& neighbours) {
  auto cell = [&] {
    if constexpr (D == 2)
      return box_polygon(lo_, hi_);
    else
      return box_polyhedron(lo_, hi_);
  }();
  for (std::uint32_t q : neighbours) {
    Point<D> n, m;
    for (int k = 0; k < D; ++k) {
      n[k] = pts_[q][k] - pts_[s][k];
      m[k] = pts_[s][k] + n[k] / 2;
    }
    cell = cut(cell, n, m, scale_);
    if (cell.empty()) break;
  }
  add_cell(s, true, cell);
}

}  // namespace

Diagram<2> voronoi_cells(const std::vector<Point2>& points, const std::vector<std::uint32_t>& simplices,
                         const Point2& lo, const Point2& hi) {
  return Builder<2>(points, simplices, lo, hi).build();
}

Diagram<3> voronoi_cells(const std::vector<Point3>& points, const std::vector<std::uint32_t>& simplices,
                         const Point3& lo, const Point3& hi) {
  return Builder<3>(points, simplices, lo, hi).build();
}

}  // namespace dlab::voronoi
