// See point_reader.hpp. Triangle's .node format: J.R. Shewchuk, "Triangle"
// documentation (node files); TetGen's is the same with dimension 3.
#include "cli/point_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>
#include <vector>

#include "algorithms/huge_pages.hpp"
#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

[[noreturn]] void fail(const std::string& name, std::size_t line, const std::string& what) {
  throw InputError(name + ":" + std::to_string(line) + ": " + what);
}

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == ',' || c == '\v' || c == '\f';
}

// Splits the input (text in memory, or a stream read in chunks so that a
// large file is never held whole in memory) into lines without '\n', drops
// comments, and returns the tokens of each line with its 1-based number. The
// tokens stay valid until the next call. A line longer than kMaxLineBytes is
// refused as soon as the limit is passed, so the reader's memory beyond the
// points stays below about 10 x kMaxLineBytes (the line's buffer, and a 16-byte
// token per 2 bytes of it) + one 64 KiB chunk, whatever the input.
class LineSplitter {
 public:
  LineSplitter(std::string_view text, const std::string& name) : text_(text), name_(name) {}
  LineSplitter(std::istream& in, const std::string& name) : in_(&in), name_(name) {}
  // Next line that has at least one token; false at the end of the input.
  bool next(std::vector<std::string_view>& tokens, std::size_t& line_no) {
    std::string_view line;
    while (next_line(line)) {
      if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
      tokens.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && is_separator(line[i])) ++i;
        std::size_t j = i;
        while (j < line.size() && !is_separator(line[j])) ++j;
        if (j > i) tokens.push_back(line.substr(i, j - i));
        i = j;
      }
      if (!tokens.empty()) {
        line_no = line_;
        return true;
      }
    }
    return false;
  }
  std::size_t lines_seen() const { return line_ == 0 ? 1 : line_; }

 private:
  [[noreturn]] void too_long() const {
    fail(name_, line_, "line longer than " + std::to_string(kMaxLineBytes) +
                           " bytes (a point needs a few dozen): not a point set?");
  }
  // The next line, counted in line_; false at the end of the input.
  bool next_line(std::string_view& line) {
    if (in_) return next_stream_line(line);
    if (done_) return false;
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) {
      end = text_.size();
      done_ = true;
      if (end == pos_) return false;  // nothing after the last newline
    }
    ++line_;
    if (end - pos_ > kMaxLineBytes) too_long();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return true;
  }
  // As std::getline, but a line is a view into the chunk when it lies within
  // one, and is copied (at most kMaxLineBytes) only when it spans chunks.
  bool next_stream_line(std::string_view& line) {
    line_buffer_.clear();
    bool any = false;  // a byte of this line was read
    for (;;) {
      if (pos_ == chunk_end_) {
        if (chunk_.empty()) chunk_.resize(kChunkBytes);
        in_->read(chunk_.data(), static_cast<std::streamsize>(chunk_.size()));
        chunk_end_ = static_cast<std::size_t>(in_->gcount());
        pos_ = 0;
        if (chunk_end_ == 0) {  // end of input (or a read error, checked by the caller)
          if (!any) return false;
          ++line_;
          line = line_buffer_;
          return true;
        }
      }
      any = true;
      const char* begin = chunk_.data() + pos_;
      const auto* nl = static_cast<const char*>(std::memchr(begin, '\n', chunk_end_ - pos_));
      const std::size_t len = nl ? static_cast<std::size_t>(nl - begin) : chunk_end_ - pos_;
      if (line_buffer_.size() + len > kMaxLineBytes) {
        ++line_;
        too_long();
      }
      if (nl && line_buffer_.empty()) {
        line = std::string_view(begin, len);
      } else {
        line_buffer_.append(begin, len);
        line = line_buffer_;
      }
      pos_ += len;
      if (nl) {
        ++pos_;
        ++line_;
        return true;
      }
    }
  }

  static constexpr std::size_t kChunkBytes = std::size_t{1} << 16;
  std::string_view text_;
  std::istream* in_ = nullptr;
  const std::string& name_;
  std::vector<char> chunk_;
  std::size_t chunk_end_ = 0;
  std::string line_buffer_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  bool done_ = false;
};

double coordinate(std::string_view tok, const std::string& name, std::size_t line) {
  const ParsedDouble p = parse_double(tok);
  if (p.status != ParseStatus::ok) fail(name, line, describe(p.status, tok));
  return p.value;
}

// Grows as push_back does (doubling), in huge pages (algorithms/huge_pages.hpp).
template <class T>
void push_point(std::vector<T>& v, const T& p) {
  if (v.size() == v.capacity()) reserve_huge(v, std::max<std::size_t>(64, 2 * v.capacity()));
  v.push_back(p);
}

void add_point(PointSet& ps, const double* c) {
  if (ps.dimension == 2) push_point(ps.p2, {c[0], c[1]});
  else push_point(ps.p3, {c[0], c[1], c[2]});
}

PointSet parse_plain(LineSplitter& lines, const std::string& name) {
  PointSet ps;
  std::vector<std::string_view> tok;
  std::size_t line = 0;
  bool first = true;
  std::size_t first_line = 0;
  while (lines.next(tok, line)) {
    if (first) {
      if (tok.size() != 2 && tok.size() != 3)
        fail(name, line, "expected 2 or 3 coordinates per point, found " + std::to_string(tok.size()));
      ps.dimension = static_cast<int>(tok.size());
      first = false;
      first_line = line;
    } else if (tok.size() != static_cast<std::size_t>(ps.dimension)) {
      fail(name, line, "wrong number of coordinates: expected " + std::to_string(ps.dimension) +
                           " (as on line " + std::to_string(first_line) + "), found " +
                           std::to_string(tok.size()));
    }
    double c[3];
    for (std::size_t i = 0; i < tok.size(); ++i) c[i] = coordinate(tok[i], name, line);
    add_point(ps, c);
  }
  if (first) fail(name, lines.lines_seen(), "empty input: no points");
  return ps;
}

std::uint64_t header_field(std::string_view tok, const std::string& name, std::size_t line,
                           const char* what, std::uint64_t max) {
  auto v = parse_u64(tok, max);
  if (!v)
    fail(name, line, std::string("bad .node header: ") + what + " must be an integer in 0.." +
                         std::to_string(max) + ", found '" + std::string(tok.substr(0, 40)) + "'");
  return *v;
}

PointSet parse_node(LineSplitter& lines, const std::string& name) {
  std::vector<std::string_view> tok;
  std::size_t line = 0;
  if (!lines.next(tok, line)) fail(name, lines.lines_seen(), "empty input: no .node header");
  if (tok.size() != 4)
    fail(name, line,
         "bad .node header: expected '<#points> <dimension> <#attributes> <#boundary markers>', "
         "found " + std::to_string(tok.size()) + " fields");
  const std::uint64_t count = header_field(tok[0], name, line, "#points", 1u << 30);
  const std::uint64_t dim = header_field(tok[1], name, line, "dimension", 1000);
  const std::uint64_t attrs = header_field(tok[2], name, line, "#attributes", 1000);
  const std::uint64_t markers = header_field(tok[3], name, line, "#boundary markers", 1);
  if (dim != 2 && dim != 3)
    fail(name, line, "dimension must be 2 or 3, found " + std::to_string(dim));
  if (count == 0) fail(name, line, "empty input: the .node header declares 0 points");
  const std::size_t header_line = line;
  PointSet ps;
  ps.dimension = static_cast<int>(dim);
  const std::size_t fields = 1 + dim + attrs + markers;
  std::uint64_t first_index = 0;
  std::uint64_t n = 0;
  while (lines.next(tok, line)) {
    if (n == count)
      fail(name, line, ".node count mismatch: the header (line " + std::to_string(header_line) +
                           ") declares " + std::to_string(count) + " points, found more");
    if (tok.size() != fields)
      fail(name, line, "wrong number of fields: expected " + std::to_string(fields) +
                           " (index, " + std::to_string(dim) + " coordinates, " +
                           std::to_string(attrs) + " attributes, " + std::to_string(markers) +
                           " markers), found " + std::to_string(tok.size()));
    auto index = parse_u64(tok[0], UINT64_MAX / 2);
    if (!index) fail(name, line, "bad point index '" + std::string(tok[0].substr(0, 40)) + "'");
    if (n == 0) {
      if (*index > 1)
        fail(name, line, "the first point index must be 0 or 1, found " + std::to_string(*index));
      first_index = *index;
    } else if (*index != first_index + n) {
      fail(name, line, "point index " + std::to_string(*index) + " out of sequence: expected " +
                           std::to_string(first_index + n));
    }
    double c[3];
    for (std::size_t i = 0; i < dim; ++i) c[i] = coordinate(tok[1 + i], name, line);
    for (std::size_t i = 0; i < attrs; ++i) {
      const ParsedDouble a = parse_double(tok[1 + dim + i]);
      if (a.status == ParseStatus::malformed)
        fail(name, line, "attribute: " + describe(a.status, tok[1 + dim + i]));
    }
    if (markers && !parse_u64(tok.back()) &&
        !(tok.back().size() > 1 && tok.back()[0] == '-' && parse_u64(tok.back().substr(1))))
      fail(name, line, "bad boundary marker '" + std::string(tok.back().substr(0, 40)) + "'");
    add_point(ps, c);
    ++n;
  }
  if (n != count)
    fail(name, lines.lines_seen(),
         ".node count mismatch: the header (line " + std::to_string(header_line) + ") declares " +
             std::to_string(count) + " points, found " + std::to_string(n));
  return ps;
}

}  // namespace

bool is_node_file(std::string_view path) {
  if (path.size() < 5) return false;
  std::string ext(path.substr(path.size() - 5));
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext == ".node";
}

std::string display_name(const std::string& path) { return path == "-" ? "<stdin>" : path; }

std::string read_file(const std::string& path) {
  if (path == "-") {
    std::ostringstream ss;
    ss << std::cin.rdbuf();
    if (std::cin.bad()) throw InputError("<stdin>: cannot read standard input");
    return ss.str();
  }
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read: is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read: " + std::strerror(errno));
  std::string s{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path + ": cannot read: " + std::strerror(errno));
  return s;
}

PointSet parse_points(std::string_view text, const std::string& name, bool node_format) {
  LineSplitter lines(text, name);
  return node_format ? parse_node(lines, name) : parse_plain(lines, name);
}

PointSet read_points(std::istream& in, const std::string& name, bool node_format) {
  LineSplitter lines(in, name);
  PointSet ps = node_format ? parse_node(lines, name) : parse_plain(lines, name);
  if (in.bad()) throw InputError(name + ": cannot read: input error");
  // The vectors grew by doubling: give the slack back before triangulating.
  shrink_huge(ps.p2);
  shrink_huge(ps.p3);
  return ps;
}

PointSet read_points(const std::string& path) { return read_points(path, ""); }

std::string input_format_of(std::string_view path) {
  if (is_node_file(path)) return "node";
  if (is_vertex_list_file(path)) {  // .xyz .off .ply, any case
    std::string ext(path.substr(path.size() - 3));
    for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    return ext;
  }
  return "text";
}

PointSet read_points(const std::string& path, std::string_view format) {
  const std::string f = format.empty() ? input_format_of(path) : std::string(format);
  if (std::find(std::begin(kInputFormats), std::end(kInputFormats), f) == std::end(kInputFormats)) {
    std::string choices;
    for (const char* c : kInputFormats) choices += std::string(choices.empty() ? "" : ", ") + c;
    throw InputError("unknown input format '" + f + "' (choices: " + choices + ")");
  }
  if (f == "xyz" || f == "off" || f == "ply")
    return parse_vertex_list(read_file(path), display_name(path), "." + f);
  if (path == "-") return read_points(std::cin, display_name(path), f == "node");
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": cannot read: is a directory");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path + ": cannot read: " + std::strerror(errno));
  return read_points(file, path, f == "node");
}

}  // namespace dlab::io
