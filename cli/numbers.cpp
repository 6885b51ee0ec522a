// See numbers.hpp. std::from_chars does not take a leading '+' nor a "0x"
// prefix (its hex format is the bare digits), so both are handled here.
#include "cli/numbers.hpp"

#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <system_error>

namespace dlab::io {
namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// True if every digit before the exponent ('e' decimal, 'p' hex) is 0, i.e.
// the literal (already read whole by from_chars) denotes zero.
bool mantissa_is_zero(std::string_view body, bool hex) {
  for (char c : body) {
    if (hex ? (c == 'p' || c == 'P') : (c == 'e' || c == 'E')) break;
    if (c != '0' && c != '.') return false;
  }
  return true;
}

// Each byte's hexadecimal digit value, -1 for a byte that is none: a table,
// since random digits would make a branch per case mispredict.
constexpr auto kHexValue = [] {
  std::array<signed char, 256> t{};
  t.fill(-1);
  for (int c = '0'; c <= '9'; ++c) t[c] = static_cast<signed char>(c - '0');
  for (int c = 'a'; c <= 'f'; ++c) t[c] = static_cast<signed char>(c - 'a' + 10);
  for (int c = 'A'; c <= 'F'; ++c) t[c] = static_cast<signed char>(c - 'A' + 10);
  return t;
}();
int hex_value(char c) { return kHexValue[static_cast<unsigned char>(c)]; }
bool is_hex_digit(char c) { return hex_value(c) >= 0; }

}  // namespace

// 1.hhh...pE with at most 13 fraction digits (a double's 52 fraction bits) and
// -1022 <= E <= 1023 is the normal double 1.hhh... * 2^E exactly: its bits are
// assembled, nothing rounds.
const char* read_normalised_hex(const char* p, const char* end, double& v) {
  const bool negative = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  if (end - p < 5 || p[0] != '0' || (p[1] != 'x' && p[1] != 'X') || p[2] != '1') return nullptr;
  p += 3;
  std::uint64_t fraction = 0;
  int digits = 0;
  if (*p == '.')
    for (++p; p < end && digits < 13; ++p, ++digits) {
      const int h = hex_value(*p);
      if (h < 0) break;
      fraction = fraction << 4 | static_cast<std::uint64_t>(h);
    }
  if (p == end || (*p != 'p' && *p != 'P')) return nullptr;
  ++p;
  const bool negative_exponent = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  int e = 0, exponent_digits = 0;
  for (; p < end && is_digit(*p) && exponent_digits <= 4; ++p, ++exponent_digits) e = 10 * e + (*p - '0');
  if (exponent_digits == 0 || exponent_digits > 4) return nullptr;
  if (negative_exponent) e = -e;
  if (e < -1022 || e > 1023) return nullptr;
  const double x = std::bit_cast<double>(static_cast<std::uint64_t>(e + 1023) << 52 | fraction << (4 * (13 - digits)));
  v = negative ? -x : x;
  return p;
}

ParsedDouble parse_double(std::string_view tok) {
  ParsedDouble out;
  const char* const end = tok.data() + tok.size();
  if (read_normalised_hex(tok.data(), end, out.value) == end) {  // what dlab writes: no rounding
    out.status = ParseStatus::ok;
    return out;
  }
  bool negative = false;
  std::string_view body = tok;
  if (!body.empty() && (body.front() == '+' || body.front() == '-')) {
    negative = body.front() == '-';
    body.remove_prefix(1);
  }
  bool hex = body.size() >= 2 && body[0] == '0' && (body[1] == 'x' || body[1] == 'X');
  if (hex) body.remove_prefix(2);
  if (body.empty()) return out;
  // The first character must start a number (from_chars would also read
  // "inf"/"nan", handled below only for the decimal form).
  const char c0 = body.front();
  if (hex ? !(is_hex_digit(c0) || c0 == '.') : !(is_digit(c0) || c0 == '.')) {
    if (!hex) {
      double v = 0;
      auto r = std::from_chars(body.data(), body.data() + body.size(), v);
      if (r.ec == std::errc() && r.ptr == body.data() + body.size()) {
        if (std::isnan(v)) out.status = ParseStatus::nan;
        else if (std::isinf(v)) out.status = ParseStatus::infinity;
      }
    }
    return out;
  }
  double v = 0;
  auto r = std::from_chars(body.data(), body.data() + body.size(), v,
                           hex ? std::chars_format::hex : std::chars_format::general);
  if (r.ptr != body.data() + body.size()) return out;  // trailing garbage or nothing read
  if (r.ec == std::errc::result_out_of_range) {
    // libstdc++ reports both overflow and underflow to zero this way and leaves
    // v unset (a subnormal result comes back normally). strtod, in the C locale
    // (this program never calls setlocale), tells them apart: infinity after an
    // overflow, the correctly rounded value (a zero) after an underflow.
    const std::string copy = (hex ? "0x" : "") + std::string(body);
    v = std::strtod(copy.c_str(), nullptr);
    if (std::isinf(v)) {
      out.status = ParseStatus::out_of_range;
      return out;
    }
  } else if (r.ec != std::errc()) {
    return out;
  }
  // Whatever reported it, a zero from a literal with a nonzero digit is an underflow.
  if (v == 0 && !mantissa_is_zero(body, hex)) {
    out.status = ParseStatus::underflow;
    return out;
  }
  out.status = ParseStatus::ok;
  out.value = negative ? -v : v;
  return out;
}

std::string describe(ParseStatus status, std::string_view token) {
  // Quoted, at most 40 characters, control and non-ASCII bytes as \xNN.
  std::string t = "'";
  for (char c : token.substr(0, 40)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      t += c;
    } else {
      static const char* hexd = "0123456789abcdef";
      t += "\\x";
      t += hexd[u >> 4];
      t += hexd[u & 15];
    }
  }
  t += token.size() > 40 ? "...'" : "'";
  std::string r;
  switch (status) {
    case ParseStatus::ok: r = "ok"; break;
    case ParseStatus::nan: r = "NaN coordinate "; r += t; break;
    case ParseStatus::infinity: r = "infinite coordinate "; r += t; break;
    case ParseStatus::out_of_range: r = "coordinate "; r += t; r += " overflows to infinity"; break;
    case ParseStatus::underflow:
      r = "coordinate "; r += t; r += " is not zero but rounds to zero (|x| <= 2^-1075)"; break;
    case ParseStatus::malformed: r = "unparsable number "; r += t; break;
  }
  return r;
}

std::optional<std::uint64_t> parse_u64(std::string_view tok, std::uint64_t max) {
  if (tok.empty() || !is_digit(tok.front())) return std::nullopt;
  std::uint64_t v = 0;
  auto r = std::from_chars(tok.data(), tok.data() + tok.size(), v, 10);
  if (r.ec != std::errc() || r.ptr != tok.data() + tok.size() || v > max) return std::nullopt;
  return v;
}

std::string format_hex(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::hex);
  std::string s(buf, r.ptr);
  if (!std::isfinite(x)) return s;  // never produced by our writers
  const std::size_t at = (s.front() == '-') ? 1 : 0;
  s.insert(at, "0x");
  return s;
}

std::string format_decimal(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace dlab::io
