// See mesh_formats.hpp: the vertex lists of .xyz, OFF (Geomview's OFF
// documentation) and ASCII PLY (G. Turk, "The PLY polygon file format")
// files as a point set. Only the vertices are read; faces and other elements
// are skipped unchecked. Every problem is InputError "FILE:LINE: problem".
#include <algorithm>
#include <string>
#include <vector>

#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"
#include "cli/point_reader.hpp"

namespace dlab::io {
namespace {

// Lines of the text with their 1-based numbers, split into blank-separated
// tokens; '#' starts a comment when `comments` (not in PLY, whose header has
// its own "comment" lines).
class Lines {
 public:
  Lines(std::string_view text, const std::string& name, bool comments)
      : text_(text), name_(name), comments_(comments) {}
  // The next line with a token; false at the end.
  bool next(std::vector<std::string_view>& tok) {
    while (pos_ < text_.size()) {
      std::size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view l = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      if (l.size() > kMaxLineBytes) fail("line longer than " + std::to_string(kMaxLineBytes) + " bytes");
      if (comments_)
        if (auto h = l.find('#'); h != std::string_view::npos) l = l.substr(0, h);
      tok.clear();
      for (std::size_t i = 0; i < l.size();) {
        while (i < l.size() && is_blank(l[i])) ++i;
        std::size_t j = i;
        while (j < l.size() && !is_blank(l[j])) ++j;
        if (j > i) tok.push_back(l.substr(i, j - i));
        i = j;
      }
      if (!tok.empty()) return true;
    }
    return false;
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(name_ + ":" + std::to_string(line_ == 0 ? 1 : line_) + ": " + what);
  }
  double coordinate(std::string_view tok) const {
    const ParsedDouble p = parse_double(tok);
    if (p.status != ParseStatus::ok) fail(describe(p.status, tok));
    return p.value;
  }
  std::uint64_t count(std::string_view tok, const char* what) const {
    auto v = parse_u64(tok, std::uint64_t{1} << 30);
    if (!v) fail(std::string("bad ") + what + " '" + shown(tok) + "': expected an integer in 0..2^30");
    return *v;
  }
  static std::string shown(std::string_view tok) {
    std::string s;
    for (char c : tok.substr(0, 40)) s += (c >= 0x20 && c < 0x7f) ? c : '?';
    return s;
  }

 private:
  static bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
  std::string_view text_;
  const std::string& name_;
  bool comments_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// 3D coordinates -> the point set: 2D when every z is 0 (or there is no z).
PointSet to_point_set(const std::vector<Point3>& pts, bool has_z) {
  PointSet ps;
  const bool flat = !has_z || std::all_of(pts.begin(), pts.end(), [](const Point3& p) { return p[2] == 0; });
  ps.dimension = flat ? 2 : 3;
  if (flat)
    for (const Point3& p : pts) ps.p2.push_back({p[0], p[1]});
  else
    ps.p3 = pts;
  return ps;
}

PointSet parse_xyz(Lines& lines) {
  std::vector<Point3> pts;
  std::vector<std::string_view> tok;
  while (lines.next(tok)) {
    if (tok.size() != 3) lines.fail("expected 3 coordinates (x y z), found " + std::to_string(tok.size()));
    pts.push_back({lines.coordinate(tok[0]), lines.coordinate(tok[1]), lines.coordinate(tok[2])});
  }
  if (pts.empty()) lines.fail("empty input: no points");
  return to_point_set(pts, true);
}

PointSet parse_off(Lines& lines) {
  std::vector<std::string_view> tok;
  if (!lines.next(tok)) lines.fail("empty input: no OFF header");
  if (tok[0] != "OFF")
    lines.fail("expected the keyword 'OFF' (plain OFF: no colours, normals or 4D), found '" +
               Lines::shown(tok[0]) + "'");
  if (tok.size() > 1) tok.erase(tok.begin());  // "OFF n f e" on one line
  else if (!lines.next(tok)) lines.fail("missing the counts line '<#vertices> <#faces> <#edges>'");
  if (tok.size() != 3 && tok.size() != 2)
    lines.fail("expected the counts '<#vertices> <#faces> <#edges>', found " + std::to_string(tok.size()) +
               " fields");
  const std::uint64_t n = lines.count(tok[0], "#vertices");
  lines.count(tok[1], "#faces");
  if (n == 0) lines.fail("empty input: the OFF header declares 0 vertices");
  std::vector<Point3> pts;
  while (pts.size() < n) {
    if (!lines.next(tok))
      lines.fail("the OFF header declares " + std::to_string(n) + " vertices, found " +
                 std::to_string(pts.size()));
    if (tok.size() != 3) lines.fail("expected a vertex 'x y z', found " + std::to_string(tok.size()) + " fields");
    pts.push_back({lines.coordinate(tok[0]), lines.coordinate(tok[1]), lines.coordinate(tok[2])});
  }
  return to_point_set(pts, true);
}

struct PlyProperty {
  bool list = false;
  std::string name;
};
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

PointSet parse_ply(Lines& lines) {
  std::vector<std::string_view> tok;
  if (!lines.next(tok) || tok.size() != 1 || tok[0] != "ply") lines.fail("expected 'ply' on the first line");
  std::vector<PlyElement> elements;
  bool format_seen = false;
  for (;;) {
    if (!lines.next(tok)) lines.fail("the PLY header has no 'end_header'");
    if (tok[0] == "end_header") break;
    if (tok[0] == "comment" || tok[0] == "obj_info") continue;
    if (tok[0] == "format") {
      if (tok.size() != 3) lines.fail("expected 'format ascii 1.0'");
      if (tok[1] == "binary_little_endian" || tok[1] == "binary_big_endian")
        lines.fail("binary PLY is not supported: write it as ASCII PLY (format ascii 1.0)");
      if (tok[1] != "ascii") lines.fail("unknown PLY format '" + Lines::shown(tok[1]) + "'");
      format_seen = true;
    } else if (tok[0] == "element") {
      if (tok.size() != 3) lines.fail("expected 'element NAME COUNT'");
      elements.push_back({std::string(tok[1]), lines.count(tok[2], "element count"), {}});
    } else if (tok[0] == "property") {
      if (elements.empty()) lines.fail("'property' before any 'element'");
      const bool list = tok.size() >= 2 && tok[1] == "list";
      if (tok.size() != (list ? 5u : 3u))
        lines.fail(list ? "expected 'property list COUNT_TYPE ITEM_TYPE NAME'" : "expected 'property TYPE NAME'");
      elements.back().properties.push_back({list, std::string(tok.back())});
    } else {
      lines.fail("unknown PLY header line '" + Lines::shown(tok[0]) + "'");
    }
  }
  if (!format_seen) lines.fail("the PLY header has no 'format' line");
  for (const PlyElement& e : elements) {
    int slot[3] = {-1, -1, -1};  // x, y, z: property positions
    for (std::size_t p = 0; p < e.properties.size(); ++p)
      for (int c = 0; c < 3; ++c)
        if (!e.properties[p].list && e.properties[p].name == std::string(1, static_cast<char>('x' + c)))
          slot[c] = static_cast<int>(p);
    const bool vertex = e.name == "vertex";
    if (vertex && (slot[0] < 0 || slot[1] < 0))
      lines.fail("the PLY vertex element has no x and y properties");
    if (vertex && e.count == 0) lines.fail("empty input: the PLY vertex element has 0 vertices");
    std::vector<Point3> pts;
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (!lines.next(tok))
        lines.fail("the PLY header declares " + std::to_string(e.count) + " " + e.name + " elements, found " +
                   std::to_string(i));
      if (!vertex) continue;  // one line per element in ASCII PLY: skipped
      Point3 p{0, 0, 0};
      std::size_t t = 0;
      for (std::size_t q = 0; q < e.properties.size(); ++q) {
        if (t >= tok.size()) lines.fail("too few values for the PLY vertex properties");
        if (e.properties[q].list) {
          t += 1 + lines.count(tok[t], "list length");
          continue;
        }
        for (int c = 0; c < 3; ++c)
          if (slot[c] == static_cast<int>(q)) p[c] = lines.coordinate(tok[t]);
        ++t;
      }
      if (t != tok.size())
        lines.fail("expected " + std::to_string(t) + " values for the PLY vertex properties, found " +
                   std::to_string(tok.size()));
      pts.push_back(p);
    }
    if (vertex) return to_point_set(pts, slot[2] >= 0);
  }
  lines.fail("the PLY header declares no 'vertex' element");
}

}  // namespace

PointSet parse_vertex_list(std::string_view text, const std::string& name, std::string_view ext) {
  Lines lines(text, name, ext != ".ply");
  if (ext == ".xyz") return parse_xyz(lines);
  if (ext == ".off") return parse_off(lines);
  return parse_ply(lines);
}

}  // namespace dlab::io
