// See simplex_io.hpp.
#include "cli/simplex_io.hpp"

#include <array>

#include "cli/numbers.hpp"
#include "cli/point_reader.hpp"

namespace dlab::io {

namespace {

// "00" "01" ... "99": two decimal digits per lookup.
constexpr auto kDigitPairs = [] {
  std::array<char, 200> t{};
  for (int i = 0; i < 100; ++i) {
    t[2 * i] = static_cast<char>('0' + i / 10);
    t[2 * i + 1] = static_cast<char>('0' + i % 10);
  }
  return t;
}();

int decimal_length(std::uint32_t v) {
  int n = 1;
  for (std::uint32_t bound = 10; n < 10 && v >= bound; bound *= 10) ++n;
  return n;
}

// v in decimal at p (at most 10 characters); returns the end.
char* write_decimal(char* p, std::uint32_t v) {
  const int n = decimal_length(v);
  char* q = p + n;
  while (v >= 100) {
    const std::uint32_t pair = (v % 100) * 2;
    v /= 100;
    *--q = kDigitPairs[pair + 1];
    *--q = kDigitPairs[pair];
  }
  if (v >= 10) {
    *--q = kDigitPairs[2 * v + 1];
    *--q = kDigitPairs[2 * v];
  } else {
    *--q = static_cast<char>('0' + v);
  }
  return p + n;
}

}  // namespace

void write_simplices(std::ostream& out, const std::vector<std::uint32_t>& s, int dimension) {
  const std::size_t k = static_cast<std::size_t>(dimension) + 1;
  constexpr std::size_t kBuffer = 1 << 16;
  const std::size_t line_max = k * 11;  // 10 digits and a separator per index
  std::vector<char> buf(kBuffer);
  char* p = buf.data();
  for (std::size_t i = 0; i + k <= s.size(); i += k) {
    if (static_cast<std::size_t>(buf.data() + kBuffer - p) < line_max) {
      out.write(buf.data(), p - buf.data());
      p = buf.data();
    }
    for (std::size_t j = 0; j < k; ++j) {
      p = write_decimal(p, s[i + j]);
      *p++ = j + 1 == k ? '\n' : ' ';
    }
  }
  out.write(buf.data(), p - buf.data());
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
