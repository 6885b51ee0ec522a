// See binade_edges.hpp for the spacing facts and the exactness arguments.
#include "fuzz/binade_edges.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "fuzz/generators.hpp"

namespace dlab::gen {
namespace {

// Smallest m >= 1 with m^D >= target.
template <int D>
std::size_t side_for(std::size_t target) {
  std::size_t m = 1;
  while (D == 2 ? m * m < target : m * m * m < target) ++m;
  return m;
}

// The grid point with flat index idx (x fastest) of the axes' values.
template <int D>
Point<D> grid_point(const std::array<std::vector<double>, D>& axes, std::size_t idx) {
  Point<D> p;
  const std::size_t m = axes[0].size();
  for (int j = 0; j < D; ++j) {
    p[j] = axes[j][idx % m];
    idx /= m;
  }
  return p;
}

// The first n grid points, x fastest.
template <int D>
std::vector<Point<D>> first_points(const std::array<std::vector<double>, D>& axes, std::size_t n) {
  std::vector<Point<D>> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) pts.push_back(grid_point<D>(axes, i));
  return pts;
}

// n distinct grid points of a grid with m^D >= 2n, chosen with the seed.
template <int D>
std::vector<Point<D>> chosen_points(const std::array<std::vector<double>, D>& axes, std::size_t n,
                                    std::uint64_t seed) {
  std::size_t total = 1;
  for (int j = 0; j < D; ++j) total *= axes[j].size();
  SplitMix64 rng(seed);
  std::vector<Point<D>> pts;
  pts.reserve(n);
  for (std::size_t idx : choose(total, n, rng)) pts.push_back(grid_point<D>(axes, idx));
  return pts;
}

// m consecutive doubles in increasing order, index floor(m/2) = centre, each
// the next double after the previous one that satisfies keep (0, never -0).
template <class Keep>
std::vector<double> consecutive(double centre, std::size_t m, Keep keep) {
  const double inf = std::numeric_limits<double>::infinity();
  const auto next = [&](double x, double dir) {
    for (int guard = 0; guard < 64; ++guard) {
      x = std::nextafter(x, dir);
      if (x == 0) x = 0;  // -0 -> +0
      if (keep(x)) return x;
    }
    throw std::logic_error("binade_edges: no kept double within 64 steps");
  };
  std::vector<double> v(m);
  const std::size_t h = m / 2;
  if (m == 0) return v;
  v[h] = centre;
  for (std::size_t i = h; i > 0; --i) v[i - 1] = next(v[i], -inf);
  for (std::size_t i = h + 1; i < m; ++i) v[i] = next(v[i - 1], inf);
  return v;
}

void check_exp(int exp, const char* what) {
  if (exp < -1074 || exp > 1023)
    throw std::invalid_argument(std::string(what) + ": --exp must be in -1074..1023");
}

}  // namespace

const std::vector<int>& notable_edges() {
  static const std::vector<int> e{-1074, -1073, -1023, -1022, -1021, -1, 0, 1, 50, 51, 52, 53, 54, 1022, 1023};
  return e;
}

template <int D>
std::vector<Point<D>> binade_lattice(std::size_t n, int exp, int step, const AxisSigns<D>& signs) {
  check_exp(exp, "binade-lattice");
  const int finest = std::max(exp - 52, -1074);
  if (step < finest || step > exp)
    throw std::invalid_argument("binade-lattice: --step-exp must be in " + std::to_string(finest) + ".." +
                                std::to_string(exp) + " for --exp " + std::to_string(exp) +
                                " (finer steps are not doubles above the edge)");
  const std::size_t m = side_for<D>(n);
  std::array<std::vector<double>, D> axes;
  for (int j = 0; j < D; ++j) {
    const double edge = signs[j] * std::ldexp(1.0, exp);
    const auto half = static_cast<std::int64_t>(m / 2);
    for (std::int64_t i = 0; i < static_cast<std::int64_t>(m); ++i)  // exact: see the header
      axes[j].push_back(edge + std::ldexp(static_cast<double>(i - half), step));
  }
  return first_points<D>(axes, n);
}

template <int D>
std::vector<Point<D>> binade_doubles(std::size_t n, int exp, const AxisSigns<D>& signs) {
  check_exp(exp, "binade-doubles");
  const std::size_t m = side_for<D>(n);
  std::array<std::vector<double>, D> axes;
  for (int j = 0; j < D; ++j)
    axes[j] = consecutive(signs[j] * std::ldexp(1.0, exp), m, [](double) { return true; });
  return first_points<D>(axes, n);
}

template <int D>
std::vector<Point<D>> half_integers(std::size_t n, std::uint64_t seed, const std::array<double, D>& centres) {
  const std::size_t m = std::max<std::size_t>(2, side_for<D>(2 * n));
  std::array<std::vector<double>, D> axes;
  for (int j = 0; j < D; ++j) {
    const double c = centres[j], a = std::fabs(c);
    if (c != 0 && a != 0x1p51 && a != 0x1p52 && a != 0x1p53)
      throw std::invalid_argument("half-integers: centres are 0, +-2^51, +-2^52 or +-2^53");
    if (c == 0) {
      for (std::size_t i = 0; i < m; ++i)  // (i - floor(m/2)) / 2: small, exact
        axes[j].push_back((static_cast<double>(i) - static_cast<double>(m / 2)) * 0.5);
    } else {
      // 2x is exact here (|x| < 2^55), so this tests "x is a multiple of 1/2".
      axes[j] = consecutive(c, m, [](double x) { return std::floor(2 * x) == 2 * x; });
    }
  }
  return chosen_points<D>(axes, n, seed);
}

template <int D>
std::vector<Point<D>> extreme_doubles(std::size_t n, std::uint64_t seed) {
  std::size_t k = 1;
  while (side_for<D>(2 * n) > 4 * k + 1) ++k;
  const double max = std::numeric_limits<double>::max(), tiny = std::numeric_limits<double>::denorm_min();
  std::vector<double> axis;
  std::vector<double> largest{max};  // max and its predecessors, decreasing
  for (std::size_t i = 1; i < k; ++i) largest.push_back(std::nextafter(largest.back(), 0.0));
  for (double x : largest) axis.push_back(-x);
  for (std::size_t j = k; j >= 1; --j) axis.push_back(-static_cast<double>(j) * tiny);  // exact: j 2^-1074
  axis.push_back(0);
  for (std::size_t j = 1; j <= k; ++j) axis.push_back(static_cast<double>(j) * tiny);
  for (std::size_t i = k; i >= 1; --i) axis.push_back(largest[i - 1]);
  std::array<std::vector<double>, D> axes;
  axes.fill(axis);
  return chosen_points<D>(axes, n, seed);
}

#define DLAB_BINADE_INSTANTIATE(D)                                                                         \
  template std::vector<Point<D>> binade_lattice<D>(std::size_t, int, int, const AxisSigns<D>&);           \
  template std::vector<Point<D>> binade_doubles<D>(std::size_t, int, const AxisSigns<D>&);                \
  template std::vector<Point<D>> half_integers<D>(std::size_t, std::uint64_t, const std::array<double, D>&); \
  template std::vector<Point<D>> extreme_doubles<D>(std::size_t, std::uint64_t);
DLAB_BINADE_INSTANTIATE(2)
DLAB_BINADE_INSTANTIATE(3)
#undef DLAB_BINADE_INSTANTIATE

}  // namespace dlab::gen
