// The SVG writer of `dlab draw` (see svg_mesh.hpp).
#include "cli/svg_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace dlab::cli {
namespace {

constexpr double kSize = 800;     // the longer side of the drawing area, px
constexpr double kMargin = 24;    // around the drawing area, px
constexpr double kLegendRow = 18;  // px per legend line

std::string num(long double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", static_cast<double>(x));
  return buf;
}

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '&') r += "&amp;";
    else if (c == '<') r += "&lt;";
    else if (c == '>') r += "&gt;";
    else if (c == '"') r += "&quot;";
    else r += c;
  }
  return r;
}

// Bounding box -> picture: one scale, y flipped. long double keeps the
// differences of coordinates near +-DBL_MAX finite.
struct Viewport {
  long double x0 = 0, y1 = 0, scale = 1, width = 0, height = 0;
  explicit Viewport(std::span<const Point2> p) {
    if (p.empty()) return;
    long double x1 = p[0][0], y0 = p[0][1];
    x0 = x1, y1 = y0;
    for (const Point2& q : p) {
      x0 = std::min<long double>(x0, q[0]), x1 = std::max<long double>(x1, q[0]);
      y0 = std::min<long double>(y0, q[1]), y1 = std::max<long double>(y1, q[1]);
    }
    const long double span = std::max(x1 - x0, y1 - y0);
    scale = span > 0 ? kSize / span : 1;
    width = (x1 - x0) * scale;
    height = (y1 - y0) * scale;
  }
  long double x(const Point2& q) const { return kMargin + (q[0] - x0) * scale; }
  long double y(const Point2& q) const { return kMargin + (y1 - q[1]) * scale; }
  std::string xy(const Point2& q) const { return num(x(q)) + "," + num(y(q)); }
};

}  // namespace

void write_svg_mesh(std::ostream& out, std::span<const Point2> points,
                    std::span<const std::uint32_t> simplices, const MeshMarks& marks,
                    const SvgMeshOptions& options) {
  const Viewport vp(points);
  const std::size_t m = simplices.size() / 3;
  const auto count = [](const std::vector<std::uint8_t>& v) {
    return static_cast<std::size_t>(std::count(v.begin(), v.end(), std::uint8_t{1}));
  };
  struct Entry {
    std::string swatch, text;
  };
  const std::vector<Entry> legend = {
      {"<rect class=\"swatch\" width=\"14\" height=\"10\" fill=\"#e8eef8\" stroke=\"#4a6fa5\"/>",
       "triangle (" + std::to_string(m) + ")"},
      {"<line class=\"swatch\" x1=\"0\" y1=\"5\" x2=\"14\" y2=\"5\" stroke=\"#d62728\" stroke-width=\"3\"/>",
       "non-Delaunay edge (" + std::to_string(marks.non_delaunay_edges.size()) + ")"},
      {"<rect class=\"swatch\" width=\"14\" height=\"10\" fill=\"#9467bd\" fill-opacity=\"0.7\"/>",
       "inverted or flat triangle (" + std::to_string(count(marks.inverted)) + ")"},
      {"<rect class=\"swatch\" width=\"14\" height=\"10\" fill=\"#ff7f0e\" fill-opacity=\"0.5\"/>",
       "overlapping triangle / edge (" + std::to_string(count(marks.overlapping)) + " / " +
           std::to_string(marks.overlap_edges.size()) + ")"},
      {"<circle class=\"swatch\" cx=\"7\" cy=\"5\" r=\"5\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>",
       "missing point (" + std::to_string(count(marks.missing)) + ")"},
  };
  const std::size_t rows = legend.size() + marks.other.size();
  const long double w = vp.width + 2 * kMargin;
  const long double h = vp.height + 2 * kMargin + static_cast<double>(rows) * kLegendRow + 8;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(std::max<long double>(w, 360))
      << "\" height=\"" << num(h) << "\" viewBox=\"0 0 " << num(std::max<long double>(w, 360)) << " "
      << num(h) << "\" font-family=\"sans-serif\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  out << "<g id=\"triangles\" stroke=\"#4a6fa5\" stroke-width=\"0.8\" stroke-linejoin=\"round\">\n";
  for (std::size_t s = 0; s < m; ++s) {
    const bool inv = s < marks.inverted.size() && marks.inverted[s];
    const bool ovl = s < marks.overlapping.size() && marks.overlapping[s];
    const char* cls = inv ? "tri inverted" : ovl ? "tri overlap" : "tri";
    // An inverted triangle may be flat (zero area): its thick outline shows it.
    const char* fill = inv ? "fill=\"#9467bd\" fill-opacity=\"0.7\" stroke=\"#9467bd\" stroke-width=\"3\""
                     : ovl ? "fill=\"#ff7f0e\" fill-opacity=\"0.5\""
                           : "fill=\"#e8eef8\"";
    out << "<polygon class=\"" << cls << "\" data-simplex=\"" << s << "\" " << fill << " points=\"";
    for (int j = 0; j < 3; ++j) out << (j ? " " : "") << vp.xy(points[simplices[3 * s + j]]);
    out << "\"/>\n";
  }
  out << "</g>\n";

  if (options.circles) {
    // Drawing only: the centre is computed in long double and drawn where it
    // is finite and not absurdly far; the verdicts do not depend on it.
    out << "<g id=\"circumcircles\" fill=\"none\" stroke=\"#888888\" stroke-width=\"0.5\">\n";
    for (std::size_t s = 0; s < m; ++s) {
      if (s < marks.inverted.size() && marks.inverted[s]) continue;
      const Point2 &a = points[simplices[3 * s]], &b = points[simplices[3 * s + 1]],
                   &c = points[simplices[3 * s + 2]];
      const long double bx = (long double)b[0] - a[0], by = (long double)b[1] - a[1];
      const long double cx = (long double)c[0] - a[0], cy = (long double)c[1] - a[1];
      const long double d = 2 * (bx * cy - by * cx);
      const long double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
      const long double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
      const long double r = std::sqrt(ux * ux + uy * uy) * vp.scale;
      if (!std::isfinite(static_cast<double>(r)) || r > 100 * kSize) continue;
      out << "<circle data-circle=\"" << s << "\" cx=\"" << num(kMargin + (a[0] - vp.x0 + ux) * vp.scale)
          << "\" cy=\"" << num(kMargin + (vp.y1 - a[1] - uy) * vp.scale) << "\" r=\"" << num(r) << "\"/>\n";
    }
    out << "</g>\n";
  }

  const auto edges = [&](const char* cls, const char* style,
                         const std::vector<std::array<std::uint32_t, 2>>& list) {
    for (const auto& e : list)
      out << "<line class=\"edge-bad " << cls << "\" data-edge=\"" << e[0] << " " << e[1] << "\" x1=\""
          << num(vp.x(points[e[0]])) << "\" y1=\"" << num(vp.y(points[e[0]])) << "\" x2=\""
          << num(vp.x(points[e[1]])) << "\" y2=\"" << num(vp.y(points[e[1]])) << "\" " << style << "/>\n";
  };
  out << "<g id=\"faults\" stroke-linecap=\"round\">\n";
  edges("overlap", "stroke=\"#ff7f0e\" stroke-width=\"3\" stroke-dasharray=\"6 4\"", marks.overlap_edges);
  edges("non-delaunay", "stroke=\"#d62728\" stroke-width=\"3\"", marks.non_delaunay_edges);
  out << "</g>\n";

  out << "<g id=\"points\" fill=\"#222222\">\n";
  for (std::size_t i = 0; i < points.size(); ++i)
    out << "<circle cx=\"" << num(vp.x(points[i])) << "\" cy=\"" << num(vp.y(points[i])) << "\" r=\"2\"/>\n";
  for (std::size_t i = 0; i < points.size() && i < marks.missing.size(); ++i)
    if (marks.missing[i])
      out << "<circle class=\"missing\" data-point=\"" << i << "\" cx=\"" << num(vp.x(points[i])) << "\" cy=\""
          << num(vp.y(points[i])) << "\" r=\"7\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>\n";
  out << "</g>\n";

  if (options.labels) {
    out << "<g id=\"labels\" font-size=\"11\" fill=\"#000000\">\n";
    for (std::size_t i = 0; i < points.size(); ++i)
      out << "<text x=\"" << num(vp.x(points[i]) + 4) << "\" y=\"" << num(vp.y(points[i]) - 4) << "\">" << i
          << "</text>\n";
    out << "</g>\n";
  }

  out << "<g id=\"legend\" font-size=\"12\">\n";
  long double y = vp.height + 2 * kMargin;
  for (const Entry& e : legend) {
    out << "<g transform=\"translate(" << num(kMargin) << "," << num(y) << ")\">" << e.swatch
        << "<text x=\"20\" y=\"10\">" << xml_escape(e.text) << "</text></g>\n";
    y += kLegendRow;
  }
  for (const std::string& line : marks.other) {
    out << "<text x=\"" << num(kMargin) << "\" y=\"" << num(y + 10) << "\">" << xml_escape(line) << "</text>\n";
    y += kLegendRow;
  }
  out << "</g>\n</svg>\n";
}

}  // namespace dlab::cli
