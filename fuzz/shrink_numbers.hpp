// The floating-point steps of `dlab shrink`'s coordinate passes
// (fuzz/shrink_coords.hpp) and of its measure of a point set's size. Each
// step returns a double that is exactly what it says, or nothing.
#pragma once
#include <optional>

namespace dlab::fuzz {

// How many bits of x's significand lie between its leading and its last 1 bit,
// both included: 0 for 0, 1 for a power of two, 53 at most (1 + 2^-52, the
// largest double); a subnormal counts only the bits it has (the smallest: 1).
int significant_bits(double x);

// |e| for x = m 2^e with 1/2 <= |m| < 1 (frexp); 0 for 0.
int exponent_distance(double x);

// x rounded to the nearest double with at most `bits` (>= 1) significant
// bits, ties to even: with x = m 2^e as above, nearbyint(m 2^bits) 2^(e-bits).
// Every step is exact but the last, which is exact too unless the result is
// 2^1024 (x within half a unit of the bits-th place of 2^1024): then nothing.
// A subnormal x is already a multiple of 2^-1074, so the result is too.
std::optional<double> round_to_bits(double x, int bits);

// x - t if that difference is a double exactly (the tail of two_diff,
// predicates/expansion.hpp, is 0, and it is finite); nothing otherwise.
std::optional<double> exact_difference(double x, double t);

}  // namespace dlab::fuzz
