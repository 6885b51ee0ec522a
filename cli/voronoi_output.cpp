// See voronoi_output.hpp.
#include "cli/voronoi_output.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"

namespace dlab::cli {
namespace {

std::string fixed(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

template <class T>
void array(std::string& s, const char* type, const char* name, const std::vector<T>& values) {
  s += std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\" format=\"ascii\">\n";
  for (const T& v : values) s += std::to_string(v) + '\n';
  s += "        </DataArray>\n";
}

}  // namespace

std::string voronoi_svg(const voronoi::Diagram<2>& d, const std::vector<Point2>& sites,
                        const Point2& lo, const Point2& hi) {
  const double frame = 800, margin = 10;
  const double scale = frame / std::max(hi[0] - lo[0], hi[1] - lo[1]);
  const double w = (hi[0] - lo[0]) * scale + 2 * margin, h = (hi[1] - lo[1]) * scale + 2 * margin;
  const auto X = [&](double x) { return fixed(margin + (x - lo[0]) * scale); };
  const auto Y = [&](double y) { return fixed(margin + (hi[1] - y) * scale); };
  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                  fixed(w) + "\" height=\"" + fixed(h) + "\" viewBox=\"0 0 " + fixed(w) + " " + fixed(h) +
                  "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  s += "<g stroke=\"#1f4e79\" stroke-width=\"1\" stroke-linejoin=\"round\">\n";
  for (const voronoi::Cell& c : d.cells) {
    s += std::string("<polygon fill=\"") + (c.clipped ? "#e8eef6" : "none") + "\" points=\"";
    for (std::size_t i = 0; i < c.faces[0].size(); ++i) {
      const Point2& p = d.vertices[c.faces[0][i]];
      s += (i ? " " : "") + X(p[0]) + "," + Y(p[1]);
    }
    s += "\"><title>site " + std::to_string(c.site) + (c.clipped ? " (clipped)" : "") + "</title></polygon>\n";
  }
  s += "</g>\n<rect x=\"" + X(lo[0]) + "\" y=\"" + Y(hi[1]) + "\" width=\"" + fixed((hi[0] - lo[0]) * scale) +
       "\" height=\"" + fixed((hi[1] - lo[1]) * scale) + "\" fill=\"none\" stroke=\"black\" stroke-width=\"1.5\"/>\n";
  s += "<g fill=\"#c0392b\">\n";
  std::set<std::uint32_t> drawn;
  for (const voronoi::Cell& c : d.cells)
    if (drawn.insert(c.site).second)
      s += "<circle cx=\"" + X(sites[c.site][0]) + "\" cy=\"" + Y(sites[c.site][1]) + "\" r=\"2.5\"/>\n";
  s += "</g>\n</svg>\n";
  return s;
}

template <int D>
std::string voronoi_vtu(const voronoi::Diagram<D>& d) {
  const std::size_t n = d.vertices.size(), cells = d.cells.size();
  std::string s = io::vtu_piece_header(n, cells) + "      <PointData>\n";
  std::vector<std::int64_t> simplex(n, -1);
  for (std::size_t i = 0; i < d.centres; ++i) simplex[i] = static_cast<std::int64_t>(i);
  array(s, "Int64", "simplex", simplex);
  s += "      </PointData>\n      <CellData>\n";
  std::vector<std::uint32_t> site;
  std::vector<int> clipped;
  for (const voronoi::Cell& c : d.cells) {
    site.push_back(c.site);
    clipped.push_back(c.clipped ? 1 : 0);
  }
  array(s, "UInt32", "site", site);
  array(s, "UInt8", "clipped", clipped);
  s += "      </CellData>\n      <Points>\n"
       "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Point<D>& p : d.vertices) {
    for (int k = 0; k < 3; ++k) {
      s += io::format_decimal(k < D ? p[k] : 0.0);
      s += k == 2 ? '\n' : ' ';
    }
  }
  s += "        </DataArray>\n      </Points>\n      <Cells>\n";
  // connectivity: 2D the polygon; 3D the polyhedron's points, each once, in
  // order of first appearance in its faces.
  std::vector<std::int64_t> connectivity, offsets, faces, faceoffsets;
  for (const voronoi::Cell& c : d.cells) {
    if (D == 2) {
      connectivity.insert(connectivity.end(), c.faces[0].begin(), c.faces[0].end());
    } else {
      std::set<std::uint32_t> seen;
      for (const auto& f : c.faces)
        for (std::uint32_t v : f)
          if (seen.insert(v).second) connectivity.push_back(v);
      faces.push_back(static_cast<std::int64_t>(c.faces.size()));
      for (const auto& f : c.faces) {
        faces.push_back(static_cast<std::int64_t>(f.size()));
        faces.insert(faces.end(), f.begin(), f.end());
      }
      faceoffsets.push_back(static_cast<std::int64_t>(faces.size()));
    }
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  array(s, "Int64", "connectivity", connectivity);
  array(s, "Int64", "offsets", offsets);
  array(s, "UInt8", "types", std::vector<int>(cells, D == 2 ? 7 : 42));
  if (D == 3) {
    array(s, "Int64", "faces", faces);
    array(s, "Int64", "faceoffsets", faceoffsets);
  }
  s += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  return s;
}

template std::string voronoi_vtu<2>(const voronoi::Diagram<2>&);
template std::string voronoi_vtu<3>(const voronoi::Diagram<3>&);

}  // namespace dlab::cli
