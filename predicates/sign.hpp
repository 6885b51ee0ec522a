// Sign of a predicate: the one result type every kernel answers with.
#pragma once

namespace dlab {

enum class Sign : signed char { negative = -1, zero = 0, positive = 1 };

constexpr Sign operator-(Sign s) { return static_cast<Sign>(-static_cast<int>(s)); }
constexpr Sign operator*(Sign a, Sign b) {
  return static_cast<Sign>(static_cast<int>(a) * static_cast<int>(b));
}
constexpr int to_int(Sign s) { return static_cast<int>(s); }

// Sign of a double; NaN maps to zero (only inexact kernels can produce NaN).
constexpr Sign sign_of(double x) {
  return x > 0 ? Sign::positive : (x < 0 ? Sign::negative : Sign::zero);
}

}  // namespace dlab
