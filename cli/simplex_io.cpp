// See simplex_io.hpp.
#include "cli/simplex_io.hpp"

#include <charconv>

#include "cli/numbers.hpp"
#include "cli/point_reader.hpp"

namespace dlab::io {

void write_simplices(std::ostream& out, const std::vector<std::uint32_t>& s, int dimension) {
  const std::size_t k = static_cast<std::size_t>(dimension) + 1;
  std::string buf;
  buf.reserve(1 << 16);
  char num[16];
  for (std::size_t i = 0; i + k <= s.size(); i += k) {
    for (std::size_t j = 0; j < k; ++j) {
      auto r = std::to_chars(num, num + sizeof num, s[i + j]);
      buf.append(num, r.ptr);
      buf.push_back(j + 1 == k ? '\n' : ' ');
    }
    if (buf.size() > (1 << 16) - 64) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

std::vector<std::uint32_t> parse_simplices(std::string_view text, const std::string& name,
                                           int dimension, std::size_t point_count) {
  const std::size_t k = static_cast<std::size_t>(dimension) + 1;
  std::vector<std::uint32_t> out;
  std::size_t pos = 0, line = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view l = text.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    if (auto h = l.find('#'); h != std::string_view::npos) l = l.substr(0, h);
    std::size_t found = 0, i = 0;
    const auto where = [&] { return name + ":" + std::to_string(line) + ": "; };
    while (i < l.size()) {
      while (i < l.size() && (l[i] == ' ' || l[i] == '\t' || l[i] == '\r' || l[i] == ',')) ++i;
      std::size_t j = i;
      while (j < l.size() && !(l[j] == ' ' || l[j] == '\t' || l[j] == '\r' || l[j] == ',')) ++j;
      if (j == i) break;
      const std::string_view tok = l.substr(i, j - i);
      i = j;
      ++found;
      if (found > k) continue;  // counted, reported below
      auto v = parse_u64(tok);
      if (!v) {
        std::string shown;
        for (char c : tok.substr(0, 40)) shown += (c >= 0x20 && c < 0x7f) ? c : '?';
        throw InputError(where() + "bad vertex index '" + shown + "'");
      }
      if (*v >= point_count)
        throw InputError(where() + "vertex index " + std::to_string(*v) + " out of range (" +
                         std::to_string(point_count) + " points)");
      out.push_back(static_cast<std::uint32_t>(*v));
    }
    if (found != 0 && found != k)
      throw InputError(where() + "expected " + std::to_string(k) + " vertex indices per simplex, found " +
                       std::to_string(found));
  }
  return out;
}

std::vector<std::uint32_t> read_simplices(const std::string& path, int dimension,
                                          std::size_t point_count) {
  return parse_simplices(read_file(path), display_name(path), dimension, point_count);
}

}  // namespace dlab::io
