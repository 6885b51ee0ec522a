// Seeded point-set generators (design.md section 6): the same arguments give
// the same points, bit for bit, on every machine. Only IEEE-754 operations that
// are correctly rounded (+ - * / and exact scalings by powers of two) touch
// the values, and the random stream is our own splitmix64 (Steele, Lea, Flood,
// "Fast splittable pseudorandom number generators", OOPSLA 2014), so neither
// libm nor the standard library's distributions are involved.
//
// Exactly degenerate sets have integer coordinates, optionally scaled by a
// power of two (exact): cocircular / cospherical points are lattice points of
// a circle x^2+y^2 = R^2 (products of Gaussian primes) or a sphere
// x^2+y^2+z^2 = R^2 (enumerated); rotated lattices use rational rotations
// (3-4-5 in 2D; the quaternion (2,1,1,1) in 3D, i.e. the integer matrix
// [[3,-2,6],[6,3,-2],[-2,6,3]] = 7 x a rotation).
//
// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness
// problems in geometric computations", CGTA 40 (2008): the 256x256 grid
// p = (0.5 + x 2^-53, 0.5 + y 2^-53) with q = (12,12), r = (24,24), and the
// published failure sets of the incremental convex hull (A1, A2, B1, B2).
#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "predicates/point.hpp"
#include "variants/run.hpp"

namespace dlab::gen {

// splitmix64: 64-bit state, one output per step.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next();
  double uniform01();                                 // k * 2^-53, k uniform in [0, 2^53)
  double uniform(double lo, double hi);               // lo + (hi - lo) * uniform01()
  std::uint64_t below(std::uint64_t n);               // uniform in [0, n), n > 0, unbiased
  std::int64_t between(std::int64_t lo, std::int64_t hi);  // uniform in [lo, hi]
  double gaussian();  // Irwin-Hall: sum of 12 uniforms minus 6 (mean 0, variance 1)

 private:
  std::uint64_t state_;
};

// n distinct indices of [0, total) (n <= total), ascending, chosen with a
// seeded partial Fisher-Yates shuffle.
std::vector<std::size_t> choose(std::size_t total, std::size_t n, SplitMix64& rng);

// x moved by k units in the last place (k < 0: downwards), as k successive
// std::nextafter steps (|k| <= 2^20); x must be finite.
double move_ulps(double x, std::int64_t k);
// Signed number of representable doubles from a to b (b - a in ulps).
std::int64_t ulp_distance(double a, double b);

template <int D> std::vector<Point<D>> uniform(std::size_t n, std::uint64_t seed, double lo = 0, double hi = 1);
template <int D> std::vector<Point<D>> gaussian(std::size_t n, std::uint64_t seed, double sigma = 1);
template <int D> std::vector<Point<D>> clustered(std::size_t n, std::uint64_t seed, std::size_t clusters = 10, double sigma = 0.01);
// The first n points, x fastest, of the smallest m^D integer grid holding n points.
template <int D> std::vector<Point<D>> lattice(std::size_t n);
// lattice(n) rotated by the exact rational rotations above (integer coordinates).
template <int D> std::vector<Point<D>> rotated_lattice(std::size_t n);
// n distinct points on one circle (D=2) or sphere (D=3) centred at the origin,
// integer coordinates scaled by 2^-e into [-1, 1]; a seeded choice among all
// lattice points of the smallest suitable radius. Throws std::invalid_argument
// above 236196 (D=2) or 50000 (D=3) points.
template <int D> std::vector<Point<D>> cospherical(std::size_t n, std::uint64_t seed);
// n points: n - off on one line with a non-axis direction, off exactly off it.
template <int D> std::vector<Point<D>> collinear(std::size_t n, std::size_t off, std::uint64_t seed);
// 3D: n - off points on one plane (normal (-10,7,9)), off exactly off it.
std::vector<Point3> coplanar(std::size_t n, std::size_t off, std::uint64_t seed);
// Every coordinate moved by a seeded uniform number of ulps in [-k, k].
template <int D> std::vector<Point<D>> perturb_ulps(std::vector<Point<D>> pts, std::int64_t k, std::uint64_t seed);
// n points that are copies of about n/copies uniform points, each copy moved by
// up to k ulps per coordinate (k = 0: exact duplicates).
template <int D> std::vector<Point<D>> near_duplicates(std::size_t n, std::uint64_t seed, std::size_t copies = 4, std::int64_t k = 2);
// Uniform in [-1,1]^D times 2^exp (exact scaling; exp <= 1023).
template <int D> std::vector<Point<D>> huge(std::size_t n, std::uint64_t seed, int exp = 1000);
// Random integers in [-2^20, 2^20] times 2^exp (default 2^-1074: all subnormal).
template <int D> std::vector<Point<D>> tiny(std::size_t n, std::uint64_t seed, int exp = -1074);
// Well-spaced points written as a PDB file writes atom coordinates (Liu &
// Snoeyink, "A comparison of five implementations of 3D Delaunay
// tessellation", MSRI Publications 52, 2005: atoms are evenly spread with a
// minimum separation, and PDB's 8.3f field keeps three decimals): one point
// per chosen cell of a grid of `spacing`, jittered by at most spacing/4 per
// axis (so any two points are at least spacing/2 apart), the whole set moved
// by a seeded offset in [-50, 50)^D, then each coordinate printed with "%8.3f"
// and read back. The doubles are the nearest to multiples of 0.001: decimal
// degeneracies become near-degeneracies of a few ulps.
template <int D> std::vector<Point<D>> pdb_like(std::size_t n, std::uint64_t seed, double spacing = 1.9);
// Kettner's grid: p(x,y) for x, y in [0, side), x fastest, then q = (12,12), r = (24,24).
std::vector<Point2> kettner_grid(std::size_t side = 256);
// The published incremental-hull failure sets: "A1", "A2", "B1", "B2".
std::vector<Point2> kettner_hull(const std::string& set);

// Multiplies every coordinate by the power of two that brings the largest
// magnitude into [0.5, 1] (exact for integer inputs below 2^53).
template <int D> void scale_to_unit(std::vector<Point<D>>& pts);

// ---- by name, for `dlab gen`, the demo and the fuzzer -------------------
struct GenOptions {
  std::string name;          // see generator_names()
  std::size_t n = 1000;
  int dim = 0;               // 0: the generator's default (3 for cospherical/coplanar, else 2)
  std::uint64_t seed = 0;
  std::size_t off = 3;       // collinear / coplanar: points off the line or plane
  std::int64_t ulps = 1;     // near-degenerate, near-duplicates: largest move in ulps
  std::string base;          // near-degenerate: the exact set to perturb
  std::size_t clusters = 10; // clustered
  double sigma = -1;         // gaussian (default 1), clustered (default 0.01)
  std::size_t copies = 4;    // near-duplicates
  std::size_t side = 256;    // kettner-grid
  int exp = 0;               // huge (default 1000), tiny (default -1074); 0 = default
  bool exp_set = false;
  std::string set = "A1";    // kettner-hull
  double lo = 0, hi = 1;     // uniform box
  double spacing = 1.9;      // pdb-like: grid spacing (angstroms)
  // binade-lattice, binade-doubles, half-integers (fuzz/binade_edges.hpp): the
  // edge exponent is `exp` when exp_set (else seeded); the lattice step 2^step_exp
  // when step_exp_set (else seeded among the three finest); the axes' signs.
  int step_exp = 0;
  bool step_exp_set = false;
  std::string sign = "mixed";  // positive | negative | mixed (seeded per axis)
};

// Throws std::invalid_argument with a readable message for an unknown name,
// a dimension the generator does not have, or an out-of-range option.
PointSet generate(const GenOptions& o);
// Every generator, in `dlab gen --help` order.
std::vector<std::string> generator_names();
// The fuzzer's degenerate mix (issue 12 draws from it): the generators whose
// sets are exactly degenerate, within a few ulps of it, or at the edges of the
// double format -- all but uniform, gaussian, clustered, huge and tiny.
std::vector<std::string> degenerate_generator_names();
// Whether `name` generates points of dimension dim (2 or 3).
bool generator_has_dimension(const std::string& name, int dim);

}  // namespace dlab::gen
