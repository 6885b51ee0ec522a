// See shrink_numbers.hpp.
#include "fuzz/shrink_numbers.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "predicates/expansion.hpp"

namespace dlab::fuzz {

int significant_bits(double x) {
  if (x == 0) return 0;
  int e = 0;
  const double m = std::frexp(std::fabs(x), &e);  // in [1/2, 1), at most 53 bits
  const auto integer = static_cast<std::uint64_t>(std::ldexp(m, 53));  // exact, in [2^52, 2^53)
  return 53 - std::countr_zero(integer);
}

int exponent_distance(double x) {
  if (x == 0) return 0;
  int e = 0;
  std::frexp(x, &e);
  return std::abs(e);
}

std::optional<double> round_to_bits(double x, int bits) {
  if (x == 0 || bits >= 53) return x;
  int e = 0;
  const double m = std::frexp(x, &e);
  const double r = std::nearbyint(std::ldexp(m, bits));  // |r| <= 2^bits
  const double y = std::ldexp(r, e - bits);
  if (!std::isfinite(y) || std::ldexp(y, bits - e) != r) return std::nullopt;
  return y;
}

std::optional<double> exact_difference(double x, double t) {
  const double d = x - t;
  if (!std::isfinite(d) || xp::two_diff_tail(x, t, d) != 0) return std::nullopt;
  return d;
}

}  // namespace dlab::fuzz
