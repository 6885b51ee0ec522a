// Text <-> double and integer conversions shared by every reader and writer of
// the `dlab` command. Deterministic and locale-independent: std::from_chars /
// std::to_chars (C++17 [charconv]: correctly rounded, exact round trip).
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace dlab::io {

enum class ParseStatus { ok, nan, infinity, out_of_range, underflow, malformed };

struct ParsedDouble {
  ParseStatus status = ParseStatus::malformed;
  double value = 0;
};

// One token, as C's strtod would read the whole of it: optional sign, then a
// decimal float ("1.5e-3", ".5", "7.") or a C99 hexadecimal float ("0x1.8p-3",
// "0X1P4", "0x.8"), correctly rounded to nearest, ties to even. Rejected alike,
// since neither gives the number written: a value that rounds to infinity
// (|x| >= 2^1024 - 2^970) is out_of_range, and a nonzero literal that rounds to
// zero (|x| <= 2^-1075, e.g. "1e-400", "0x1p-1075") is underflow. A subnormal
// result is ok, and so is a zero literal ("0", "-0", "0e999": a signed zero).
// "nan"/"inf"/"infinity" are recognised and reported as such.
ParsedDouble parse_double(std::string_view token);

// The normalised hexadecimal float that format_hex and C's "%a" write for a
// normal double, "[+-]0x1.hhh...p[+-]E" (at most 13 fraction digits, at most 4
// exponent digits, -1022 <= E <= 1023), read from the front of [p, end) with no
// rounding: the end of the number, its value in v. nullptr for anything else,
// which parse_double reads. The readers' fast path: no token is cut first.
const char* read_normalised_hex(const char* p, const char* end, double& v);

// Human-readable reason for a non-ok status, e.g. "NaN coordinate 'nan'".
std::string describe(ParseStatus status, std::string_view token);

// Non-negative decimal integer without sign; nullopt if malformed or > max.
std::optional<std::uint64_t> parse_u64(std::string_view token,
                                       std::uint64_t max = UINT64_MAX);

// C99 "%a"-style hexadecimal float, e.g. "0x1.8p-3", "-0x0p+0",
// "0x0.0000000000001p-1022"; exact, and parse_double reads it back bit for bit.
std::string format_hex(double x);

// Shortest decimal that reads back to exactly x (std::to_chars); e.g. "0.1", "1e-300".
std::string format_decimal(double x);

}  // namespace dlab::io
