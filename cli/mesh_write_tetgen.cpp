// See mesh_formats.hpp: Triangle (2D) and TetGen (3D) .node/.ele/.neigh/.face.
// File layouts from J.R. Shewchuk's Triangle documentation and H. Si's TetGen
// user manual (section 5.2): a header line of counts, then one numbered
// record per line. Everything is numbered from 0, the .node file included.
#include <algorithm>
#include <array>
#include <string>

#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

// Outward facets of a positively oriented tetrahedron (det[v1-v0; v2-v0;
// v3-v0] > 0, simplex_io.hpp): the facet opposite vertex i, as vertex slots.
constexpr int kOutwardFacet3[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

template <std::size_t D>
void append_node_records(std::string& s, const std::vector<std::array<double, D>>& pts) {
  for (std::size_t i = 0; i < pts.size(); ++i) {
    s += std::to_string(i);
    for (std::size_t k = 0; k < D; ++k) {
      s += ' ';
      s += format_decimal(pts[i][k]);
    }
    s += '\n';
  }
}

}  // namespace

std::vector<std::int64_t> simplex_neighbours(const std::vector<std::uint32_t>& simplices,
                                             int dimension) {
  const std::size_t k = static_cast<std::size_t>(dimension) + 1;
  const std::size_t count = simplices.size() / k;
  // (sorted facet vertices, simplex * k + opposite slot), sorted: equal facets meet.
  struct Facet {
    std::array<std::uint32_t, 3> v;
    std::size_t where;
  };
  std::vector<Facet> facets;
  facets.reserve(count * k);
  for (std::size_t s = 0; s < count; ++s) {
    for (std::size_t i = 0; i < k; ++i) {
      Facet f{{UINT32_MAX, UINT32_MAX, UINT32_MAX}, s * k + i};
      std::size_t m = 0;
      for (std::size_t j = 0; j < k; ++j)
        if (j != i) f.v[m++] = simplices[s * k + j];
      std::sort(f.v.begin(), f.v.end());  // the UINT32_MAX padding (2D) stays last
      facets.push_back(f);
    }
  }
  std::sort(facets.begin(), facets.end(), [](const Facet& a, const Facet& b) {
    return a.v != b.v ? a.v < b.v : a.where < b.where;
  });
  std::vector<std::int64_t> nb(count * k, -1);
  // A facet shared by exactly two simplices links them; one shared by more
  // (not a triangulation) is left at -1 for all of them.
  for (std::size_t a = 0; a < facets.size();) {
    std::size_t b = a;
    while (b < facets.size() && facets[b].v == facets[a].v) ++b;
    if (b - a == 2) {
      nb[facets[a].where] = static_cast<std::int64_t>(facets[a + 1].where / k);
      nb[facets[a + 1].where] = static_cast<std::int64_t>(facets[a].where / k);
    }
    a = b;
  }
  return nb;
}

std::vector<std::string> write_node_files(const std::string& base, const PointSet& points,
                                          const std::vector<std::uint32_t>* simplices) {
  const int d = points.dimension;
  const std::size_t k = static_cast<std::size_t>(d) + 1;
  // .node: <#points> <dimension> <#attributes> <#boundary markers>
  std::string node = std::to_string(points.size()) + " " + std::to_string(d) + " 0 0\n";
  if (d == 2) append_node_records(node, points.p2);
  else append_node_records(node, points.p3);
  write_text_file(base + ".node", node);
  std::vector<std::string> written{base + ".node"};
  if (!simplices) return written;

  const std::size_t count = simplices->size() / k;
  // .ele: <#simplices> <nodes per simplex> <#attributes>
  std::string ele = std::to_string(count) + " " + std::to_string(k) + " 0\n";
  for (std::size_t s = 0; s < count; ++s) {
    ele += std::to_string(s);
    for (std::size_t j = 0; j < k; ++j) ele += ' ' + std::to_string((*simplices)[s * k + j]);
    ele += '\n';
  }
  write_text_file(base + ".ele", ele);
  written.push_back(base + ".ele");

  const std::vector<std::int64_t> nb = simplex_neighbours(*simplices, d);
  if (d == 2) {
    // .neigh: <#triangles> 3, then "t n0 n1 n2", n_i across the edge opposite vertex i.
    std::string neigh = std::to_string(count) + " 3\n";
    for (std::size_t s = 0; s < count; ++s) {
      neigh += std::to_string(s);
      for (std::size_t j = 0; j < 3; ++j) neigh += ' ' + std::to_string(nb[s * 3 + j]);
      neigh += '\n';
    }
    write_text_file(base + ".neigh", neigh);
    written.push_back(base + ".neigh");
  } else {
    // .face: <#faces> <#boundary markers>, then "f a b c": the hull facets, outward.
    std::string body;
    std::size_t faces = 0;
    for (std::size_t s = 0; s < count; ++s)
      for (std::size_t i = 0; i < 4; ++i) {
        if (nb[s * 4 + i] != -1) continue;
        body += std::to_string(faces++);
        for (int j : kOutwardFacet3[i]) body += ' ' + std::to_string((*simplices)[s * 4 + j]);
        body += '\n';
      }
    write_text_file(base + ".face", std::to_string(faces) + " 0\n" + body);
    written.push_back(base + ".face");
  }
  return written;
}

}  // namespace dlab::io
