// See generators.hpp for the sources and the exactness arguments.
#include "fuzz/generators.hpp"

#include "fuzz/binade_edges.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace dlab::gen {

// ---- random numbers ------------------------------------------------------

std::uint64_t SplitMix64::next() {
  std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SplitMix64::uniform01() { return static_cast<double>(next() >> 11) * 0x1p-53; }

double SplitMix64::uniform(double lo, double hi) { return lo + (hi - lo) * uniform01(); }

std::uint64_t SplitMix64::below(std::uint64_t n) {
  // Rejection: accept x < the largest multiple of n (Lemire's bound is not needed here).
  const std::uint64_t limit = UINT64_MAX - UINT64_MAX % n;
  for (int guard = 0; guard < 1000; ++guard) {
    const std::uint64_t x = next();
    if (x < limit) return x % n;
  }
  return next() % n;  // probability < 2^-1000 of getting here
}

std::int64_t SplitMix64::between(std::int64_t lo, std::int64_t hi) {
  const std::uint64_t span = static_cast<std::uint64_t>(hi) - static_cast<std::uint64_t>(lo) + 1;
  if (span == 0) return static_cast<std::int64_t>(next());  // the full 64-bit range
  return static_cast<std::int64_t>(static_cast<std::uint64_t>(lo) + below(span));
}

double SplitMix64::gaussian() {
  double s = 0;
  for (int i = 0; i < 12; ++i) s += uniform01();
  return s - 6;
}

// ---- ulps ----------------------------------------------------------------

double move_ulps(double x, std::int64_t k) {
  if (k > (1 << 20) || k < -(1 << 20)) throw std::invalid_argument("move_ulps: |k| > 2^20");
  const double dir = k >= 0 ? std::numeric_limits<double>::infinity()
                            : -std::numeric_limits<double>::infinity();
  for (std::int64_t i = 0; i < (k >= 0 ? k : -k); ++i) x = std::nextafter(x, dir);
  return x;
}

namespace {
// Monotone map of finite doubles to integers (-0 and +0 both map to 0).
std::int64_t ordinal(double x) {
  const auto bits = std::bit_cast<std::int64_t>(x);
  return bits >= 0 ? bits : -(bits & INT64_MAX);
}
}  // namespace

std::int64_t ulp_distance(double a, double b) { return ordinal(b) - ordinal(a); }

std::vector<std::size_t> choose(std::size_t total, std::size_t n, SplitMix64& rng) {
  std::vector<std::size_t> idx(total);
  for (std::size_t i = 0; i < total; ++i) idx[i] = i;
  for (std::size_t i = 0; i < n; ++i) std::swap(idx[i], idx[i + rng.below(total - i)]);
  idx.resize(n);
  std::sort(idx.begin(), idx.end());
  return idx;
}

// ---- helpers -------------------------------------------------------------

namespace {

template <int D>
Point<D> from_ints(const std::array<std::int64_t, D>& v) {
  Point<D> p;
  for (int i = 0; i < D; ++i) p[i] = static_cast<double>(v[i]);  // |v| < 2^53: exact
  return p;
}

std::int64_t isqrt(std::int64_t m) {  // floor(sqrt(m)) for 0 <= m < 2^62
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(m)));
  while (r * r > m) --r;
  while ((r + 1) * (r + 1) <= m) ++r;
  return r;
}

struct Gauss {
  std::int64_t re, im;
};
Gauss mul(Gauss a, Gauss b) { return {a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }

}  // namespace

template <int D>
void scale_to_unit(std::vector<Point<D>>& pts) {
  double m = 0;
  for (const auto& p : pts)
    for (double c : p) m = std::max(m, std::fabs(c));
  if (m == 0 || !std::isfinite(m)) return;
  int e = 0;
  std::frexp(m, &e);  // m = f 2^e, f in [0.5, 1): exact
  const double s = std::ldexp(1.0, -e);
  for (auto& p : pts)
    for (double& c : p) c *= s;  // power of two: exact unless it underflows (not for integers)
}

// ---- generators ----------------------------------------------------------

template <int D>
std::vector<Point<D>> uniform(std::size_t n, std::uint64_t seed, double lo, double hi) {
  SplitMix64 rng(seed);
  std::vector<Point<D>> pts(n);
  for (auto& p : pts)
    for (double& c : p) c = rng.uniform(lo, hi);
  return pts;
}

template <int D>
std::vector<Point<D>> gaussian(std::size_t n, std::uint64_t seed, double sigma) {
  SplitMix64 rng(seed);
  std::vector<Point<D>> pts(n);
  for (auto& p : pts)
    for (double& c : p) c = sigma * rng.gaussian();
  return pts;
}

template <int D>
std::vector<Point<D>> clustered(std::size_t n, std::uint64_t seed, std::size_t clusters, double sigma) {
  if (clusters == 0) throw std::invalid_argument("clustered: --clusters must be at least 1");
  SplitMix64 rng(seed);
  std::vector<Point<D>> centres(clusters);
  for (auto& c : centres)
    for (double& x : c) x = rng.uniform01();
  std::vector<Point<D>> pts(n);
  for (auto& p : pts) {
    const auto& c = centres[rng.below(clusters)];
    for (int i = 0; i < D; ++i) p[i] = c[i] + sigma * rng.gaussian();
  }
  return pts;
}

template <int D>
std::vector<Point<D>> lattice(std::size_t n) {
  std::size_t m = 1;
  while (D == 2 ? m * m < n : m * m * m < n) ++m;
  std::vector<Point<D>> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::array<std::int64_t, D> v;
    std::size_t r = i;
    for (int k = 0; k < D; ++k) {
      v[k] = static_cast<std::int64_t>(r % m);
      r /= m;
    }
    pts.push_back(from_ints<D>(v));
  }
  return pts;
}

template <int D>
std::vector<Point<D>> rotated_lattice(std::size_t n) {
  auto pts = lattice<D>(n);
  for (auto& p : pts) {
    if constexpr (D == 2) {
      const double x = p[0], y = p[1];  // 5 x rotation by atan2(4,3): integers stay exact
      p = {3 * x - 4 * y, 4 * x + 3 * y};
    } else {
      const double x = p[0], y = p[1], z = p[2];
      p = {3 * x - 2 * y + 6 * z, 6 * x + 3 * y - 2 * z, -2 * x + 6 * y + 3 * z};
    }
  }
  return pts;
}

namespace {

// All 4 * 3^k lattice points of x^2 + y^2 = R^2, R = p_1 ... p_k (primes = 1 mod 4):
// z = u * prod pi_j^e_j conj(pi_j)^(2-e_j), e_j in {0,1,2}, u a unit. Distinct by
// unique factorisation in Z[i]. R <= 1.03e15 < 2^53 for k <= 10.
std::vector<Point2> circle_points(std::size_t n, std::uint64_t seed) {
  static constexpr Gauss primes[] = {{2, 1}, {3, 2}, {4, 1}, {5, 2}, {6, 1},
                                     {5, 4}, {7, 2}, {6, 5}, {8, 3}, {8, 5}};
  std::size_t k = 0, total = 4;
  while (total < n) {
    if (k == std::size(primes))
      throw std::invalid_argument("cocircular: at most 236196 points in 2D");
    ++k;
    total *= 3;
  }
  std::vector<Gauss> zs{{1, 0}};
  for (std::size_t j = 0; j < k; ++j) {
    const Gauss p = primes[j], q{p.re, -p.im};
    const Gauss choices[3] = {mul(p, p), mul(p, q), mul(q, q)};
    std::vector<Gauss> next;
    next.reserve(zs.size() * 3);
    for (const Gauss& z : zs)
      for (const Gauss& c : choices) next.push_back(mul(z, c));
    zs.swap(next);
  }
  std::vector<Point2> all;
  all.reserve(total);
  for (const Gauss& z : zs) {
    all.push_back(from_ints<2>({z.re, z.im}));
    all.push_back(from_ints<2>({-z.im, z.re}));
    all.push_back(from_ints<2>({-z.re, -z.im}));
    all.push_back(from_ints<2>({z.im, -z.re}));
  }
  SplitMix64 rng(seed);
  std::vector<Point2> pts;
  for (std::size_t i : choose(all.size(), n, rng)) pts.push_back(all[i]);
  return pts;
}

// Lattice points of x^2 + y^2 + z^2 = R^2 for the smallest odd R >= n/6 that has
// n of them (for odd R there are at least 6R: Gauss/Hurwitz; checked anyway).
std::vector<Point3> sphere_points(std::size_t n, std::uint64_t seed) {
  if (n > 50000) throw std::invalid_argument("cospherical: at most 50000 points in 3D");
  std::int64_t R = static_cast<std::int64_t>(n / 6) | 1;
  std::vector<Point3> all;
  for (int attempt = 0; attempt < 1000; ++attempt, R += 2) {
    all.clear();
    const std::int64_t R2 = R * R;
    for (std::int64_t x = -R; x <= R; ++x)
      for (std::int64_t y = -R; y <= R; ++y) {
        const std::int64_t m = R2 - x * x - y * y;
        if (m < 0) continue;
        const std::int64_t z = isqrt(m);
        if (z * z != m) continue;
        all.push_back(from_ints<3>({x, y, z}));
        if (z != 0) all.push_back(from_ints<3>({x, y, -z}));
      }
    if (all.size() >= n) break;
  }
  if (all.size() < n) throw std::logic_error("cospherical: no radius found");
  SplitMix64 rng(seed);
  std::vector<Point3> pts;
  for (std::size_t i : choose(all.size(), n, rng)) pts.push_back(all[i]);
  return pts;
}

// n distinct integers from [0, 4n), ascending.
std::vector<std::int64_t> distinct_params(std::size_t n, SplitMix64& rng) {
  std::vector<std::int64_t> t;
  for (std::size_t i : choose(4 * n + 4, n, rng)) t.push_back(static_cast<std::int64_t>(i));
  return t;
}

}  // namespace

template <int D>
std::vector<Point<D>> cospherical(std::size_t n, std::uint64_t seed) {
  std::vector<Point<D>> pts;
  if constexpr (D == 2) pts = circle_points(n, seed);
  else pts = sphere_points(n, seed);
  scale_to_unit<D>(pts);
  return pts;
}

template <int D>
std::vector<Point<D>> collinear(std::size_t n, std::size_t off, std::uint64_t seed) {
  off = std::min(off, n);
  SplitMix64 rng(seed);
  // Direction v and normals w (w . v = 0); base point a. Parameters t < 4n <= 2^26,
  // so every coordinate stays far below 2^53 and is exact.
  if (n > (std::size_t{1} << 24)) throw std::invalid_argument("collinear: at most 2^24 points");
  std::array<std::int64_t, D> a, v;
  std::array<std::array<std::int64_t, D>, D - 1> w;
  if constexpr (D == 2) {
    a = {-1000, 333};
    v = {3, 7};
    w = {{{-7, 3}}};
  } else {
    a = {-1000, 333, 77};
    v = {3, 7, 11};
    w = {{{0, 11, -7}, {-170, 21, 33}}};  // v x e_x and v x (v x e_x)
  }
  const auto t = distinct_params(n, rng);
  std::vector<Point<D>> pts;
  for (std::size_t i = 0; i < n; ++i) {
    std::array<std::int64_t, D> p;
    for (int k = 0; k < D; ++k) p[k] = a[k] + t[i] * v[k];
    if (i >= n - off) {  // the last `off` points leave the line
      std::int64_t s[D - 1];
      bool nonzero = false;
      while (!nonzero) {
        for (int j = 0; j < D - 1; ++j) {
          s[j] = rng.between(-3, 3);
          nonzero = nonzero || s[j] != 0;
        }
      }
      for (int j = 0; j < D - 1; ++j)
        for (int k = 0; k < D; ++k) p[k] += s[j] * w[j][k];
    }
    pts.push_back(from_ints<D>(p));
  }
  // Shuffle so that the off-line points are not all at the end.
  for (std::size_t i = n; i > 1; --i) std::swap(pts[i - 1], pts[rng.below(i)]);
  scale_to_unit<D>(pts);
  return pts;
}

std::vector<Point3> coplanar(std::size_t n, std::size_t off, std::uint64_t seed) {
  off = std::min(off, n);
  if (n > (std::size_t{1} << 24)) throw std::invalid_argument("coplanar: at most 2^24 points");
  SplitMix64 rng(seed);
  const std::array<std::int64_t, 3> a{-1000, 333, 77}, u{2, -1, 3}, w{1, 4, -2},
      normal{-10, 7, 9};  // u x w
  // Distinct (s, t) pairs from a side x side grid of parameters.
  std::size_t side = 2;
  while (side * side < 4 * n) ++side;
  std::vector<Point3> pts;
  for (std::size_t idx : choose(side * side, n, rng)) {
    const auto s = static_cast<std::int64_t>(idx % side), t = static_cast<std::int64_t>(idx / side);
    std::array<std::int64_t, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = a[k] + s * u[k] + t * w[k];
    pts.push_back(from_ints<3>(p));
  }
  for (std::size_t i = n; i > 1; --i) std::swap(pts[i - 1], pts[rng.below(i)]);
  for (std::size_t i = 0; i < off; ++i) {
    std::int64_t k = rng.between(-3, 2);
    if (k >= 0) ++k;  // never 0
    for (int c = 0; c < 3; ++c) pts[i][c] += static_cast<double>(k * normal[c]);  // small integers: exact
  }
  for (std::size_t i = n; i > 1; --i) std::swap(pts[i - 1], pts[rng.below(i)]);
  scale_to_unit<3>(pts);
  return pts;
}

template <int D>
std::vector<Point<D>> perturb_ulps(std::vector<Point<D>> pts, std::int64_t k, std::uint64_t seed) {
  if (k < 0 || k > (1 << 20)) throw std::invalid_argument("--ulps must be in 0..1048576");
  SplitMix64 rng(seed ^ 0x5eedf00dULL);
  for (auto& p : pts)
    for (double& c : p) c = move_ulps(c, rng.between(-k, k));
  return pts;
}

template <int D>
std::vector<Point<D>> near_duplicates(std::size_t n, std::uint64_t seed, std::size_t copies, std::int64_t k) {
  if (copies == 0) throw std::invalid_argument("near-duplicates: --copies must be at least 1");
  if (k < 0 || k > (1 << 20)) throw std::invalid_argument("--ulps must be in 0..1048576");
  const std::size_t m = std::max<std::size_t>(1, n / copies);
  const auto base = uniform<D>(m, seed);
  SplitMix64 rng(seed ^ 0xd0bb1e5ULL);
  std::vector<Point<D>> pts(n);
  for (auto& p : pts) {
    p = base[rng.below(m)];
    for (double& c : p) c = move_ulps(c, rng.between(-k, k));
  }
  return pts;
}

template <int D>
std::vector<Point<D>> huge(std::size_t n, std::uint64_t seed, int exp) {
  if (exp > 1023 || exp < -1022) throw std::invalid_argument("huge: --exp must be in -1022..1023");
  auto pts = uniform<D>(n, seed, -1, 1);
  const double s = std::ldexp(1.0, exp);
  for (auto& p : pts)
    for (double& c : p) c *= s;  // |c| < 1, so no overflow; exact power-of-two scaling
  return pts;
}

template <int D>
std::vector<Point<D>> tiny(std::size_t n, std::uint64_t seed, int exp) {
  if (exp < -1074 || exp > 1000) throw std::invalid_argument("tiny: --exp must be in -1074..1000");
  SplitMix64 rng(seed);
  std::vector<Point<D>> pts(n);
  for (auto& p : pts)
    for (double& c : p)  // 21-bit integer times 2^exp: exact (>= 2^-1074 granularity)
      c = std::ldexp(static_cast<double>(rng.between(-(1 << 20), 1 << 20)), exp);
  return pts;
}

template <int D>
std::vector<Point<D>> pdb_like(std::size_t n, std::uint64_t seed, double spacing) {
  if (!(spacing > 0) || spacing > 100) throw std::invalid_argument("pdb-like: --spacing must be in (0, 100]");
  std::size_t m = 1;
  const auto cells_of = [](std::size_t side) { return D == 2 ? side * side : side * side * side; };
  while (cells_of(m) < n) ++m;
  const std::size_t cells = cells_of(m);
  if (static_cast<double>(m) * spacing + 50 >= 9999)
    throw std::invalid_argument("pdb-like: the set does not fit PDB's 8.3f field (fewer points or a smaller --spacing)");
  SplitMix64 rng(seed);
  std::array<double, D> origin;
  for (double& o : origin) o = rng.uniform(-50, 50);
  std::vector<Point<D>> pts;
  pts.reserve(n);
  char buf[64];
  for (std::size_t cell : choose(cells, n, rng)) {
    Point<D> p;
    for (int j = 0; j < D; ++j) {
      const double index = static_cast<double>(cell % m);
      cell /= m;
      const double x = origin[j] + (index + 0.5 + rng.uniform(-0.25, 0.25)) * spacing;
      std::snprintf(buf, sizeof buf, "%8.3f", x);  // PDB ATOM record, columns 31-54
      p[j] = std::strtod(buf, nullptr);
    }
    pts.push_back(p);
  }
  return pts;
}

std::vector<Point2> kettner_grid(std::size_t side) {
  if (side == 0 || side > 4096) throw std::invalid_argument("kettner-grid: --side must be in 1..4096");
  std::vector<Point2> pts;
  pts.reserve(side * side + 2);
  const double u = 0x1p-53;  // the spacing of doubles in [0.5, 1)
  for (std::size_t y = 0; y < side; ++y)
    for (std::size_t x = 0; x < side; ++x)
      pts.push_back({0.5 + static_cast<double>(x) * u, 0.5 + static_cast<double>(y) * u});
  pts.push_back({12, 12});
  pts.push_back({24, 24});
  return pts;
}

std::vector<Point2> kettner_hull(const std::string& set) {
  // Kettner et al. 2008, section 4 (failures of the incremental hull, in insertion order).
  if (set == "A1")
    return {{7.3000000000000194, 7.3000000000000167}, {24.000000000000068, 24.000000000000071},
            {24.00000000000005, 24.000000000000053},  {0.50000000000001621, 0.50000000000001243},
            {8, 4}, {4, 9}, {15, 27}, {26, 25}, {19, 11}};
  if (set == "A2")
    return {{27.643564356435643, -21.881188118811881}, {83.366336633663366, 15.544554455445542},
            {4.0, 4.0}, {73.415841584158414, 8.8613861386138595}};
  if (set == "B1")
    return {{200.0, 49.200000000000003}, {100.0, 49.600000000000001},
            {-233.33333333333334, 50.93333333333333}, {166.66666666666669, 49.333333333333336}};
  if (set == "B2")
    return {{0.50000000000001243, 0.50000000000000189}, {0.50000000000001243, 0.50000000000000333},
            {24.00000000000005, 24.000000000000053}, {24.000000000000068, 24.000000000000071},
            {17.300000000000001, 17.300000000000001}};
  throw std::invalid_argument("kettner-hull: --set must be A1, A2, B1 or B2, not '" + set + "'");
}

// ---- by name -------------------------------------------------------------

std::vector<std::string> generator_names() {
  return {"uniform",   "gaussian",       "clustered",       "lattice", "rotated-lattice",
          "cocircular", "cospherical",   "collinear",       "coplanar", "near-degenerate",
          "near-duplicates", "huge",     "tiny",            "kettner-grid", "kettner-hull",
          "binade-lattice", "binade-doubles", "half-integers", "extreme-doubles", "pdb-like"};
}

std::vector<std::string> degenerate_generator_names() {
  std::vector<std::string> out;
  for (const auto& g : generator_names())
    if (g != "uniform" && g != "gaussian" && g != "clustered" && g != "huge" && g != "tiny" && g != "pdb-like")
      out.push_back(g);
  return out;
}

bool generator_has_dimension(const std::string& name, int dim) {
  if (dim == 2) return name != "coplanar";
  return dim == 3 && name.rfind("kettner", 0) != 0;
}

namespace {

// The seeded parameters of the binade-edge generators (fuzz/binade_edges.hpp),
// drawn from their own stream so that they do not shift the points' choice.
template <int D>
AxisSigns<D> axis_signs(const GenOptions& o, SplitMix64& rng) {
  if (o.sign != "positive" && o.sign != "negative" && o.sign != "mixed")
    throw std::invalid_argument(o.name + ": --sign must be positive, negative or mixed, not '" + o.sign + "'");
  AxisSigns<D> s;
  for (int& v : s) v = o.sign == "positive" ? 1 : o.sign == "negative" ? -1 : (rng.below(2) ? 1 : -1);
  return s;
}

template <int D>
std::vector<Point<D>> binade_by_name(const GenOptions& o) {
  SplitMix64 rng(o.seed ^ 0xb1ade0edULL);
  if (o.name == "binade-lattice" || o.name == "binade-doubles") {
    const auto& notable = notable_edges();
    const int exp = o.exp_set            ? o.exp
                    : rng.below(2) != 0 ? notable[rng.below(notable.size())]
                                        : static_cast<int>(rng.between(-1074, 1023));
    const auto signs = axis_signs<D>(o, rng);
    if (o.name == "binade-doubles") return binade_doubles<D>(o.n, exp, signs);
    const int finest = std::max(exp - 52, -1074);
    const int step = o.step_exp_set ? o.step_exp : std::min(exp, finest + static_cast<int>(rng.below(3)));
    return binade_lattice<D>(o.n, exp, step, signs);
  }
  if (o.name == "half-integers") {
    if (o.exp_set && (o.exp < 51 || o.exp > 53))
      throw std::invalid_argument("half-integers: --exp must be 51, 52 or 53");
    const auto signs = axis_signs<D>(o, rng);
    std::array<double, D> centres;
    for (int j = 0; j < D; ++j) {
      // Axis 0 always at an edge; the others at an edge (2 in 3) or at 0.
      const bool at_edge = j == 0 || rng.below(3) != 0;
      const int exp = o.exp_set ? o.exp : 51 + static_cast<int>(rng.below(3));
      centres[j] = at_edge ? signs[j] * std::ldexp(1.0, exp) : 0.0;
    }
    return half_integers<D>(o.n, o.seed, centres);
  }
  return extreme_doubles<D>(o.n, o.seed);
}

template <int D>
std::vector<Point<D>> by_name(const GenOptions& o, const std::string& name) {
  if (name == "uniform") return uniform<D>(o.n, o.seed, o.lo, o.hi);
  if (name == "gaussian") return gaussian<D>(o.n, o.seed, o.sigma < 0 ? 1.0 : o.sigma);
  if (name == "clustered") return clustered<D>(o.n, o.seed, o.clusters, o.sigma < 0 ? 0.01 : o.sigma);
  if (name == "lattice") return lattice<D>(o.n);
  if (name == "rotated-lattice") return rotated_lattice<D>(o.n);
  if (name == "cocircular" || name == "cospherical") return cospherical<D>(o.n, o.seed);
  if (name == "collinear") return collinear<D>(o.n, o.off, o.seed);
  if (name == "coplanar") {
    if constexpr (D == 3) return coplanar(o.n, o.off, o.seed);
    throw std::invalid_argument("coplanar exists in 3D only (use collinear in 2D)");
  }
  if (name == "near-degenerate") {
    std::string base = o.base.empty() ? (D == 2 ? "cocircular" : "cospherical") : o.base;
    if (base == "near-degenerate" || base == "near-duplicates" || base == "uniform" ||
        base == "gaussian" || base == "clustered" || base == "huge" || base == "tiny")
      throw std::invalid_argument("near-degenerate: --base must be an exact degenerate set "
                                  "(cocircular, cospherical, collinear, coplanar, lattice, "
                                  "rotated-lattice, kettner-grid, kettner-hull, binade-lattice, "
                                  "binade-doubles, half-integers, extreme-doubles)");
    return perturb_ulps<D>(by_name<D>(o, base), o.ulps, o.seed);
  }
  if (name == "pdb-like") return pdb_like<D>(o.n, o.seed, o.spacing);
  if (name == "near-duplicates") return near_duplicates<D>(o.n, o.seed, o.copies, o.ulps);
  if (name == "huge") return huge<D>(o.n, o.seed, o.exp_set ? o.exp : 1000);
  if (name == "tiny") return tiny<D>(o.n, o.seed, o.exp_set ? o.exp : -1074);
  if (name == "kettner-grid" || name == "kettner-hull") {
    if constexpr (D == 2) return name == "kettner-grid" ? kettner_grid(o.side) : kettner_hull(o.set);
    throw std::invalid_argument(name + " exists in 2D only");
  }
  if (name == "binade-lattice" || name == "binade-doubles" || name == "half-integers" ||
      name == "extreme-doubles") {
    GenOptions b = o;
    b.name = name;
    return binade_by_name<D>(b);
  }
  std::string all;
  for (const auto& g : generator_names()) all += (all.empty() ? "" : ", ") + g;
  throw std::invalid_argument("unknown generator '" + name + "' (known: " + all + ")");
}

}  // namespace

PointSet generate(const GenOptions& o) {
  PointSet ps;
  ps.dimension = o.dim != 0 ? o.dim : (o.name == "cospherical" || o.name == "coplanar" ? 3 : 2);
  if (ps.dimension != 2 && ps.dimension != 3) throw std::invalid_argument("--dim must be 2 or 3");
  if (o.n > (std::size_t{1} << 28)) throw std::invalid_argument("--n must be at most 2^28");
  if (ps.dimension == 2) ps.p2 = by_name<2>(o, o.name);
  else ps.p3 = by_name<3>(o, o.name);
  // Options such as --sigma 1e308 or --lo -1e308 --hi 1e308 can overflow.
  const auto finite = [](const auto& pts) {
    for (const auto& p : pts)
      for (double c : p)
        if (!std::isfinite(c)) return false;
    return true;
  };
  if (!finite(ps.p2) || !finite(ps.p3))
    throw std::invalid_argument(o.name + ": these options overflow to non-finite coordinates");
  return ps;
}

#define DLAB_GEN_INSTANTIATE(D)                                                                 \
  template std::vector<Point<D>> uniform<D>(std::size_t, std::uint64_t, double, double);        \
  template std::vector<Point<D>> gaussian<D>(std::size_t, std::uint64_t, double);               \
  template std::vector<Point<D>> clustered<D>(std::size_t, std::uint64_t, std::size_t, double); \
  template std::vector<Point<D>> lattice<D>(std::size_t);                                       \
  template std::vector<Point<D>> rotated_lattice<D>(std::size_t);                               \
  template std::vector<Point<D>> cospherical<D>(std::size_t, std::uint64_t);                    \
  template std::vector<Point<D>> collinear<D>(std::size_t, std::size_t, std::uint64_t);         \
  template std::vector<Point<D>> perturb_ulps<D>(std::vector<Point<D>>, std::int64_t, std::uint64_t); \
  template std::vector<Point<D>> near_duplicates<D>(std::size_t, std::uint64_t, std::size_t, std::int64_t); \
  template std::vector<Point<D>> huge<D>(std::size_t, std::uint64_t, int);                      \
  template std::vector<Point<D>> tiny<D>(std::size_t, std::uint64_t, int);                      \
  template std::vector<Point<D>> pdb_like<D>(std::size_t, std::uint64_t, double);               \
  template void scale_to_unit<D>(std::vector<Point<D>>&);
DLAB_GEN_INSTANTIATE(2)
DLAB_GEN_INSTANTIATE(3)
#undef DLAB_GEN_INSTANTIATE

}  // namespace dlab::gen
