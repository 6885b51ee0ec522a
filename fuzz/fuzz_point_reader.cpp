// libFuzzer target: the INPUT reader (plain and .node formats) must turn every
// byte sequence into points or an InputError, never a crash or a hang.
// A first byte below 8 selects the format (odd: .node) and is not part of the
// text; any other input is plain text as it is, so that point files such as
// tests/corpus/*.pts are seeds as they stand.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cli/point_reader.hpp"
#include "cli/simplex_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const bool format_byte = size > 0 && data[0] < 8;
  const bool node = format_byte && (data[0] & 1);
  try {
    const dlab::PointSet ps = dlab::io::parse_points(text.substr(format_byte ? 1 : 0), "fuzz", node);
    if (ps.dimension != 2 && ps.dimension != 3) __builtin_trap();
    if (ps.size() == 0) __builtin_trap();
    for (const auto& p : ps.p2)
      for (double c : p)
        if (!(c - c == 0)) __builtin_trap();  // NaN and infinity must be rejected
    for (const auto& p : ps.p3)
      for (double c : p)
        if (!(c - c == 0)) __builtin_trap();
    (void)dlab::io::parse_simplices(text, "fuzz", ps.dimension, ps.size());
  } catch (const dlab::io::InputError&) {
  }
  return 0;
}
