// Bytes -> a small point set, for the coverage-guided fuzz targets
// (fuzz/fuzz_triangulate_2d.cpp, fuzz/fuzz_triangulate_3d.cpp). Random bytes
// read as raw doubles almost never give a degenerate set; this decoder reads
// them as a little program whose instructions build the configurations that
// break predicates and algorithms: small integer lattices, exact repeats,
// exactly cocircular / cospherical points, collinear and coplanar points,
// k-ulp moves, extreme exponents, sign flips and binade-edge values.
//
// Format. Byte 0: the insertion order (bits 0-1: input, random, brio, hilbert)
// and the order's seed (bits 2-7). Then instructions, each one opcode byte
// (low nibble: which instruction, high nibble `a`: its small argument) and
// the bytes it reads; a read past the end yields 0 and ends the program.
// State: the points so far, a scale exponent e (start 0) and an origin o
// (start 0). "int8" is a byte read as a two's-complement integer.
//
//   0 lattice       D int8 v                      o + v 2^e
//   1 lattice line  D int8 base, D int8 dir       a+2 points o + (base + t dir) 2^e, t = 0..a+1
//   2 cocircular    byte r, a+1 bytes k           o + c_k 2^e, c_k the k-th (mod count) integer
//                                                 point of the circle / sphere of radius R[r]
//   3 repeat        byte i                        point i (mod count) again
//   4 ulp move      byte i, int8 k                point i, the axes in mask a (0: all) moved by
//                                                 k mod 33 - 16 ulps (k successive nextafter)
//   5 sign flip     byte i                        point i, the axes in mask a (0: all) negated
//   6 scale         a < 8: byte j                 e = notable_edges()[j mod 15] + a - 4
//                   a >= 8: 2 bytes u (LE)        e = -1074 + u mod 2098
//   7 origin        a mod 4 = 0: -                o = 0
//                             1: byte i           o = point i
//                             2: D bytes b        o_j = binade-edge value of b (as in 9)
//                             3: D x 8 bytes      o_j = that bit pattern (if finite; else unchanged)
//   8 raw point     D x 8 bytes                   the bit patterns as doubles
//   9 binade point  D bytes b                     +-2^E moved by m ulps: sign bit 7, E =
//                                                 notable_edges()[b mod 16 mod 15], m = (b >> 4 & 7) - 4
//  10 affine        bytes i, j (, k in 3D), int8 t (, int8 s)
//                                                 p_i + t/4 (p_j - p_i) (+ s/4 (p_k - p_i)), in
//                                                 doubles: exactly collinear / coplanar when no
//                                                 operation rounds, nearly otherwise
//  11 power scale   byte i, int8 k                point i times 2^k (ldexp)
//  12 permute       byte i                        point i with its axes permuted (a mod D!)
//  13 whole circle  byte r, byte k                a+3 consecutive points c_k, c_k+1, ... of R[r]
//  14 nibble grid   ceil(D/2) bytes               o + (nibbles, 0..15) 2^e: a dense 16^D grid
//  15 translate     byte i                        o = o + point i (rounded)
//
// A point with a non-finite coordinate (overflow) is dropped: dlab refuses
// non-finite input (variants/registry.cpp), and every finite double is valid
// input, subnormals included. At most kMaxPoints points and kMaxInstructions
// instructions: every input decodes in a bounded number of steps.
//
// Exactness: o + c 2^e is computed in doubles. With o = 0 (or any multiple of
// 2^e with |o / 2^e + c| < 2^53) and no overflow, every step is exact (scaling
// by a power of two, adding integers times 2^e below 2^53 2^e, including the
// subnormal range since e >= -1074), so cocircular instructions give exactly
// cocircular points (tests/test_byte_decoder.cpp checks with the mp kernel).
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "predicates/point.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

inline constexpr std::size_t kMaxPoints = 64;
inline constexpr std::size_t kMaxInstructions = 512;

struct DecodedInput {
  PointSet points;
  std::string order = "input";  // input | random | brio | hilbert
  std::uint64_t seed = 0;
};

// dim is 2 or 3 (std::invalid_argument otherwise). Deterministic.
DecodedInput decode_points(std::span<const std::uint8_t> bytes, int dim);

// The integer points (x, y) with x^2 + y^2 = R^2 (dim 2) or (x, y, z) with
// x^2 + y^2 + z^2 = R^2 (dim 3), for the r-th radius of the decoder's table
// (r mod the table's size), in a fixed order. Exposed for the tests.
const std::vector<Point3>& circle_points(int dim, std::size_t r);
std::size_t circle_radius_count(int dim);
std::int64_t circle_radius(int dim, std::size_t r);

}  // namespace dlab::fuzz
