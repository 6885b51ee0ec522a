// See fuzz_outcome.hpp.
#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {

std::string message_kind(std::string_view message) {
  std::string s;
  bool in_digits = false;
  for (char c : message) {
    const bool digit = c >= '0' && c <= '9';
    if (digit && !in_digits) s += '#';
    if (!digit) s += c;
    in_digits = digit;
    if (s.size() >= 80) break;
  }
  return s;
}

std::string detail_kind(const Outcome& o) {
  if (o.kind == OutcomeClass::invalid) return std::string(o.check);
  if (o.kind == OutcomeClass::reported) return message_kind(o.detail);
  return "";
}

}  // namespace dlab::fuzz
