// Point sets at the edges of the double format (issue 17): lattices that cross
// a binade edge 2^e, where the spacing of doubles doubles, from the smallest
// subnormal to 2^1023, on both signs; half-integers around 2^51..2^53, where
// integer certificates such as "(|x| + 2^52) - 2^52 == |x|" live; and the
// largest finite and smallest subnormal doubles. Exact by construction, and
// every claim below is checked independently in tests/test_generators.cpp.
//
// Spacing facts used (IEEE 754 binary64): the doubles in [2^k, 2^(k+1)) are
// the multiples of ulp = 2^(k-52) for k >= -1022; below 2^-1022 (subnormals)
// they are the multiples of 2^-1074. So the multiples of 2^s with s >=
// max(e - 52, -1074) and magnitude below 2^(e+1) are all doubles: each is
// j 2^s with |j| < 2^(e+1-s) <= 2^53.
//
// Axis values are listed in increasing order; index floor(m/2) is the edge
// (or the centre), so an axis of m >= 2 values has the edge and values on both
// of its sides. Lattices are the first n points, x fastest, of the smallest
// m^D grid holding n points (as gen::lattice).
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "predicates/point.hpp"

namespace dlab::gen {

// Edges worth hitting often: the smallest subnormals, the subnormal/normal
// boundary 2^-1022, around 1, the small-integer certificates' 2^50..2^54
// (predicates/small_integer.hpp), the top of the range. Seeded generators draw
// half their edges from here, half uniformly from -1074..1023.
const std::vector<int>& notable_edges();

// signs[j] = +1 or -1: axis j sits at signs[j] 2^exp.
template <int D>
using AxisSigns = std::array<int, D>;

// Axis j: signs[j] 2^exp + (i - floor(m/2)) 2^step, i in [0, m). Requires
// -1074 <= exp <= 1023 and max(exp - 52, -1074) <= step <= exp (so every value
// is a multiple of 2^step below 2^53 2^step: a double, computed exactly); step
// = max(exp - 52, -1074) is the finest (consecutive doubles above the edge, and
// every other double below it when exp >= -1021, where the small side is normal). May overflow for exp near 1023
// and a coarse step (generate() then refuses the set). Throws
// std::invalid_argument for parameters out of range.
template <int D>
std::vector<Point<D>> binade_lattice(std::size_t n, int exp, int step, const AxisSigns<D>& signs);

// Axis j: the m consecutive doubles around signs[j] 2^exp (floor(m/2) below
// it, the edge, the rest above): for exp >= -1021 spacing 2^(exp-53) on the
// small side and 2^(exp-52) on the large side -- Kettner's grid at an edge;
// for exp <= -1022 spacing 2^-1074 on both sides.
// -1074 <= exp <= 1023; a low edge's window may cross zero (the doubles there
// are consecutive too: ..., -2^-1074, 0, 2^-1074, ...).
template <int D>
std::vector<Point<D>> binade_doubles(std::size_t n, int exp, const AxisSigns<D>& signs);

// The issue-17 class: n distinct points chosen (seeded) from a grid m^D with
// m^D >= 2n whose axis j holds the m consecutive doubles that are multiples of
// 1/2 around centres[j] (index floor(m/2) is the centre): centres are 0 or
// +-2^51, +-2^52, +-2^53. Around 2^51 they are half-integers, around 2^52
// half-integers below and integers above, around 2^53 integers below and even
// integers above; around 0 the values j/2.
template <int D>
std::vector<Point<D>> half_integers(std::size_t n, std::uint64_t seed, const std::array<double, D>& centres);

// n distinct points chosen (seeded) from a grid (4k+1)^D >= 2n whose every axis
// holds the k largest finite doubles of each sign (DBL_MAX and its k-1
// predecessors), the k smallest subnormals of each sign (j 2^-1074, j = 1..k)
// and 0.
template <int D>
std::vector<Point<D>> extreme_doubles(std::size_t n, std::uint64_t seed);

}  // namespace dlab::gen
