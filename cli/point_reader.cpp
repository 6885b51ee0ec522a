// See point_reader.hpp. Triangle's .node format: J.R. Shewchuk, "Triangle"
// documentation (node files); TetGen's is the same with dimension 3.
#include "cli/point_reader.hpp"

#include <algorithm>
#include <array>
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

// Each byte's class for the tokenizer: one table lookup a byte instead of six
// compares (the tokenizer, with its separate search for '#', took as many
// perf samples as the number parser reading 10^6 2D points: session 44).
enum class ByteClass : unsigned char { token, separator, comment };
constexpr auto kByteClass = [] {
  std::array<ByteClass, 256> t{};
  t.fill(ByteClass::token);
  for (unsigned char c : {' ', '\t', '\r', ',', '\v', '\f'}) t[c] = ByteClass::separator;
  t['#'] = ByteClass::comment;
  return t;
}();
ByteClass byte_class(char c) { return kByteClass[static_cast<unsigned char>(c)]; }

// Splits the input (text in memory, or a stream read in chunks so that a
// large file is never held whole in memory) into lines without '\n', drops
// comments, and returns the tokens of each line with its 1-based number. The
// tokens stay valid until the next call. A line longer than kMaxLineBytes is
// refused as soon as the limit is passed, so the reader's memory beyond the
// points stays below about 10 x kMaxLineBytes (the line's buffer, and a 16-byte
// token per 2 bytes of it) + one 64 KiB chunk, whatever the input.
class LineSplitter {
 public:
  LineSplitter(std::string_view text, const std::string& name) : text_(text), name_(name), total_(text.size()) {}
  // total: the stream's size in bytes, 0 if unknown.
  LineSplitter(std::istream& in, const std::string& name, std::size_t total)
      : in_(&in), name_(name), total_(total) {}
  // Next line that has at least one token; false at the end of the input.
  bool next(std::vector<std::string_view>& tokens, std::size_t& line_no) {
    std::string_view line;
    while (next_line(line)) {
      split(line, tokens);
      if (!tokens.empty()) {
        line_no = line_;
        return true;
      }
    }
    return false;
  }
  // The line's tokens, up to a '#' (which ends it), in one pass.
  static void split(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    const char* p = line.data();
    const char* const end = p + line.size();
    for (;;) {
      while (p < end && byte_class(*p) == ByteClass::separator) ++p;
      if (p == end || *p == '#') return;
      const char* q = p;
      while (q < end && byte_class(*q) == ByteClass::token) ++q;
      tokens.emplace_back(p, static_cast<std::size_t>(q - p));
      p = q;
    }
  }
  // The next line as it is (its number is line_number()); false at the end of the input.
  bool next_line(std::string_view& line) { return in_ ? next_stream_line(line) : next_text_line(line); }
  std::size_t line_number() const { return line_; }
  std::size_t lines_seen() const { return line_ == 0 ? 1 : line_; }
  // The input's size in bytes (0: unknown), and the bytes of the lines returned so far.
  std::size_t total_bytes() const { return total_; }
  std::size_t bytes_done() const { return chunks_done_ + pos_; }

 private:
  [[noreturn]] void too_long() const {
    fail(name_, line_, "line longer than " + std::to_string(kMaxLineBytes) +
                           " bytes (a point needs a few dozen): not a point set?");
  }
  // The next line of the text in memory, counted in line_; false at its end.
  bool next_text_line(std::string_view& line) {
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
        chunks_done_ += chunk_end_;
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
  std::size_t chunk_end_ = 0, chunks_done_ = 0, total_ = 0;
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

// After the first kSample points, room for the whole input at their bytes per
// point and a sixteenth more, at most one point per 2 x dimension bytes (the
// shortest line, "0 0"): the vector then grows once instead of doubling about
// twenty times, each a copy into fresh pages (with the one-pass hex lines,
// reading 10^6 2D points went from 0.10-0.15 s to 0.06-0.09 s: session 44).
// Room never written costs no memory.
constexpr std::size_t kSample = 1024;
void reserve_for_input(PointSet& ps, const LineSplitter& lines) {
  const std::size_t total = lines.total_bytes(), done = lines.bytes_done();
  if (total == 0 || done == 0 || done >= total) return;
  const double per_point = static_cast<double>(done) / static_cast<double>(ps.size());
  const double guess = static_cast<double>(total) / per_point * (17.0 / 16.0) + 64;
  const std::size_t most = total / (2 * static_cast<std::size_t>(ps.dimension)) + 1;
  const std::size_t n = guess < static_cast<double>(most) ? static_cast<std::size_t>(guess) : most;
  if (ps.dimension == 2) reserve_huge(ps.p2, n);
  else reserve_huge(ps.p3, n);
}

void add_point(PointSet& ps, const double* c, const LineSplitter& lines) {
  if (ps.dimension == 2) push_point(ps.p2, {c[0], c[1]});
  else push_point(ps.p3, {c[0], c[1], c[2]});
  if (ps.size() == kSample) reserve_for_input(ps, lines);
}

// A line of `dimension` normalised hexadecimal floats (what dlab writes) and
// separators, then the end or a comment, read in one pass into c; false for
// any other line, which the general path then reads (and judges).
bool read_hex_line(std::string_view line, int dimension, double* c) {
  const char* p = line.data();
  const char* const end = p + line.size();
  for (int a = 0; a < dimension; ++a) {
    while (p < end && byte_class(*p) == ByteClass::separator) ++p;
    p = read_normalised_hex(p, end, c[a]);
    if (p == nullptr || (p < end && byte_class(*p) == ByteClass::token)) return false;
  }
  while (p < end && byte_class(*p) == ByteClass::separator) ++p;
  return p == end || *p == '#';
}

PointSet parse_plain(LineSplitter& lines, const std::string& name) {
  PointSet ps;
  std::vector<std::string_view> tok;
  std::string_view text;
  bool first = true;
  std::size_t first_line = 0;
  while (lines.next_line(text)) {
    double c[3];
    if (!first && read_hex_line(text, ps.dimension, c)) {
      add_point(ps, c, lines);
      continue;
    }
    LineSplitter::split(text, tok);
    if (tok.empty()) continue;
    const std::size_t line = lines.line_number();
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
    for (std::size_t i = 0; i < tok.size(); ++i) c[i] = coordinate(tok[i], name, line);
    add_point(ps, c, lines);
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
    add_point(ps, c, lines);
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

namespace {

// The bytes from the stream's position to its end, 0 when it cannot seek (a pipe).
std::size_t bytes_left(std::istream& in) {
  const std::istream::pos_type here = in.tellg();
  if (here == std::istream::pos_type(-1)) return 0;
  in.seekg(0, std::ios::end);
  const std::istream::pos_type end = in.tellg();
  in.seekg(here);
  if (!in || end == std::istream::pos_type(-1) || end <= here) {
    in.clear();
    in.seekg(here);
    return 0;
  }
  return static_cast<std::size_t>(end - here);
}

// A vector that grew by doubling gives its slack back before the run; the
// reserve_for_input's sixteenth stays (never written: no memory).
template <class T>
void shrink_slack(std::vector<T>& v) {
  if (v.capacity() - v.size() > v.size() / 8 + 64) shrink_huge(v);
}

}  // namespace

PointSet read_points(std::istream& in, const std::string& name, bool node_format) {
  LineSplitter lines(in, name, bytes_left(in));
  PointSet ps = node_format ? parse_node(lines, name) : parse_plain(lines, name);
  if (in.bad()) throw InputError(name + ": cannot read: input error");
  shrink_slack(ps.p2);
  shrink_slack(ps.p3);
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
