// See shrink_coords.hpp.
#include "fuzz/shrink_coords.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "fuzz/shrink_numbers.hpp"

namespace dlab::fuzz {
namespace {

double coord(const PointSet& s, std::size_t i, int k) { return s.dimension == 2 ? s.p2[i][k] : s.p3[i][k]; }
void set_coord(PointSet& s, std::size_t i, int k, double v) {
  if (s.dimension == 2)
    s.p2[i][k] = v;
  else
    s.p3[i][k] = v;
}

// Every coordinate replaced by f(x); nothing if f gives nothing for one.
template <class F>
std::optional<PointSet> map_coords(const PointSet& s, F f, int only_axis = -1) {
  PointSet out = s;
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int k = 0; k < s.dimension; ++k) {
      if (only_axis >= 0 && k != only_axis) continue;
      const std::optional<double> v = f(coord(s, i, k));
      if (!v) return std::nullopt;
      set_coord(out, i, k, *v);
    }
  return out;
}

// The value of x's last 1 bit (x != 0): 2^(e - significant bits) for x = m 2^e.
double last_bit(double x) {
  int e = 0;
  std::frexp(x, &e);
  return std::ldexp(1.0, e - significant_bits(x));
}

// nearbyint(c / unit) * unit for a power of two `unit`; nothing if not finite.
std::optional<double> round_to_multiple(double c, double unit) {
  const double t = std::nearbyint(c / unit) * unit;
  return std::isfinite(t) ? std::optional(t) : std::nullopt;
}

// The offsets of translate_toward_origin for axis k, in the order tried.
std::vector<double> offsets(const PointSet& s, int k) {
  double lo = coord(s, 0, k), hi = lo, grid = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double x = coord(s, i, k);
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    if (x != 0) grid = grid == 0 ? last_bit(x) : std::min(grid, last_bit(x));
  }
  std::vector<double> t = {lo};
  const double range = hi - lo;
  if (range > 0 && std::isfinite(range)) {
    const double centre = lo + range / 2;
    if (auto a = round_to_multiple(centre, std::ldexp(1.0, std::ilogb(range)))) t.push_back(*a);
    if (auto g = round_to_multiple(centre, grid)) t.push_back(*g);
  }
  std::vector<double> out;
  for (double x : t)
    if (x != 0 && std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
  return out;
}

// Bisects b in [1, hi) for the fewest significant bits that still fail, with
// round(b) the candidate at b; returns whether it kept one.
template <class Round>
bool bisect_bits(Simplifier& s, int hi, Round round) {
  bool kept = false;
  int lo = 1;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    std::optional<PointSet> c = round(mid);
    const bool unchanged = c && c->p2 == s.points().p2 && c->p3 == s.points().p3;
    if (unchanged || (c && s.offer(std::move(*c)))) {
      kept = kept || !unchanged;
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  return kept;
}

}  // namespace

ShrinkSize size_of(const PointSet& s) {
  ShrinkSize z;
  z.points = s.size();
  for (std::size_t i = 0; i < s.size(); ++i)
    for (int k = 0; k < s.dimension; ++k) {
      z.bits += static_cast<std::uint64_t>(significant_bits(coord(s, i, k)));
      z.exponents += static_cast<std::uint64_t>(exponent_distance(coord(s, i, k)));
    }
  return z;
}

Simplifier::Simplifier(PointSet failing, PointTest fails) : fails_(std::move(fails)) { keep(std::move(failing)); }

void Simplifier::keep(PointSet failing) {
  points_ = std::move(failing);
  size_ = size_of(points_);
}

bool Simplifier::offer(PointSet candidate) {
  if (!(size_of(candidate) < size_) || !fails_(candidate)) return false;
  keep(std::move(candidate));
  return true;
}

bool translate_toward_origin(Simplifier& s) {
  bool kept = false;
  for (int k = 0; k < s.points().dimension && s.points().size() > 0; ++k)
    for (double t : offsets(s.points(), k)) {
      std::optional<PointSet> c = map_coords(s.points(), [t](double x) { return exact_difference(x, t); }, k);
      if (c && s.offer(std::move(*c))) {
        kept = true;
        break;
      }
    }
  return kept;
}

bool snap_whole_set(Simplifier& s) {
  bool kept = false;
  if (auto c = map_coords(s.points(), [](double x) { return std::optional(std::nearbyint(x)); }))
    kept = s.offer(std::move(*c));
  int most = 0;
  for (std::size_t i = 0; i < s.points().size(); ++i)
    for (int k = 0; k < s.points().dimension; ++k) most = std::max(most, significant_bits(coord(s.points(), i, k)));
  const auto round_all = [&s](int b) {
    // A coordinate that cannot be rounded (it would overflow) keeps its bits.
    return map_coords(s.points(), [b](double x) { return std::optional(round_to_bits(x, b).value_or(x)); });
  };
  return bisect_bits(s, most, round_all) || kept;
}

bool simplify_each_coordinate(Simplifier& s) {
  bool kept = false;
  for (std::size_t i = 0; i < s.points().size(); ++i)
    for (int k = 0; k < s.points().dimension; ++k) {
      const double x = coord(s.points(), i, k);
      const auto with = [&s, i, k](double v) {
        PointSet c = s.points();
        set_coord(c, i, k, v);
        return c;
      };
      if (x != 0 && s.offer(with(0))) {
        kept = true;
        continue;
      }
      const double r = std::nearbyint(x);
      if (r != x && r != 0 && s.offer(with(r))) {
        kept = true;
        continue;
      }
      const auto round_one = [&](int b) -> std::optional<PointSet> {
        const std::optional<double> v = round_to_bits(coord(s.points(), i, k), b);
        return v ? std::optional(with(*v)) : std::nullopt;
      };
      kept = bisect_bits(s, significant_bits(x), round_one) || kept;
    }
  return kept;
}

}  // namespace dlab::fuzz
