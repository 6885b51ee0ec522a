// See byte_decoder.hpp.
#include "fuzz/byte_decoder.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <stdexcept>

#include "fuzz/binade_edges.hpp"
#include "fuzz/generators.hpp"

namespace dlab::fuzz {
namespace {

// Radii with many lattice points: 5, 25, 65, 325, 1105 are products of primes
// 1 mod 4 (sums of two squares in several ways); 3D radii are odd, with
// several representations as sums of three squares.
constexpr std::array<std::int64_t, 6> kRadii2{1, 5, 25, 65, 325, 1105};
constexpr std::array<std::int64_t, 6> kRadii3{1, 3, 9, 11, 21, 27};

std::int64_t isqrt_exact(std::int64_t v) {  // r with r*r == v, or -1
  if (v < 0) return -1;
  auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(v)));
  while (r * r > v) --r;
  while ((r + 1) * (r + 1) <= v) ++r;
  return r * r == v ? r : -1;
}

std::vector<Point3> enumerate_circle(int dim, std::int64_t R) {
  std::vector<Point3> out;
  const std::int64_t R2 = R * R;
  if (dim == 2) {
    for (std::int64_t x = -R; x <= R; ++x) {
      const std::int64_t y = isqrt_exact(R2 - x * x);
      if (y < 0) continue;
      out.push_back({double(x), double(y), 0});
      if (y != 0) out.push_back({double(x), double(-y), 0});
    }
  } else {
    for (std::int64_t x = -R; x <= R; ++x)
      for (std::int64_t y = -R; y <= R; ++y) {
        const std::int64_t z = isqrt_exact(R2 - x * x - y * y);
        if (z < 0) continue;
        out.push_back({double(x), double(y), double(z)});
        if (z != 0) out.push_back({double(x), double(y), double(-z)});
      }
  }
  return out;
}

// Reads bytes; past the end it yields 0 and remembers that it ran out.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::uint8_t> b) : b_(b) {}
  std::uint8_t byte() {
    if (pos_ < b_.size()) return b_[pos_++];
    out_ = true;
    return 0;
  }
  int int8() { return static_cast<std::int8_t>(byte()); }
  std::uint64_t u64() {
    std::uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= std::uint64_t{byte()} << (8 * i);
    return v;
  }
  bool done() const { return out_ || pos_ >= b_.size(); }
  bool out() const { return out_; }

 private:
  std::span<const std::uint8_t> b_;
  std::size_t pos_ = 0;
  bool out_ = false;
};

// +-2^E moved by m ulps (instruction 9's byte).
double binade_value(std::uint8_t b) {
  const auto& edges = gen::notable_edges();
  const int E = edges[(b & 15u) % edges.size()];
  const int m = static_cast<int>((b >> 4) & 7u) - 4;
  const double v = gen::move_ulps(std::ldexp(1.0, E), m);
  return (b & 128u) ? -v : v;
}

template <int D>
class Decoder {
 public:
  explicit Decoder(std::span<const std::uint8_t> bytes) : in_(bytes) {}

  std::vector<Point<D>> run() {
    for (std::size_t step = 0; step < kMaxInstructions && !in_.done() && pts_.size() < kMaxPoints; ++step) {
      const std::uint8_t op = in_.byte();
      instruction(op & 15u, op >> 4);
    }
    return std::move(pts_);
  }

 private:
  ByteReader in_;
  std::vector<Point<D>> pts_;
  int e_ = 0;
  Point<D> o_{};

  // Adds p unless a read ran past the end, it has a non-finite coordinate, or the set is full.
  void add(const Point<D>& p) {
    if (in_.out() || pts_.size() >= kMaxPoints) return;
    for (double c : p)
      if (!std::isfinite(c)) return;
    pts_.push_back(p);
  }
  // o + v 2^e, coordinate by coordinate.
  Point<D> grid(const std::array<double, D>& v) const {
    Point<D> p;
    for (int j = 0; j < D; ++j) p[j] = o_[j] + std::ldexp(v[j], e_);
    return p;
  }
  // Point i (mod count); false when there is none.
  bool earlier(std::uint8_t i, Point<D>& p) const {
    if (pts_.empty()) return false;
    p = pts_[i % pts_.size()];
    return true;
  }
  static constexpr unsigned all_axes = (1u << D) - 1;

  void instruction(unsigned op, unsigned a) {
    Point<D> p, q, r;
    std::array<double, D> v;
    switch (op) {
      case 0:  // lattice
        for (auto& c : v) c = in_.int8();
        add(grid(v));
        break;
      case 1: {  // lattice line
        std::array<double, D> base, dir;
        for (auto& c : base) c = in_.int8();
        for (auto& c : dir) c = in_.int8();
        for (unsigned t = 0; t < a + 2; ++t) {
          for (int j = 0; j < D; ++j) v[j] = base[j] + t * dir[j];
          add(grid(v));
        }
        break;
      }
      case 2: {  // cocircular / cospherical points
        const auto& c = circle_points(D, in_.byte());
        for (unsigned t = 0; t < a + 1; ++t) {
          const Point3& k = c[in_.byte() % c.size()];
          for (int j = 0; j < D; ++j) v[j] = k[j];
          add(grid(v));
        }
        break;
      }
      case 3:  // repeat
        if (earlier(in_.byte(), p)) add(p);
        break;
      case 4: {  // ulp move
        const bool ok = earlier(in_.byte(), p);
        const int k = ((in_.int8() % 33) + 33) % 33 - 16;
        const unsigned mask = (a & all_axes) ? (a & all_axes) : all_axes;
        if (!ok) break;
        for (int j = 0; j < D; ++j)
          if (mask & (1u << j)) p[j] = gen::move_ulps(p[j], k);
        add(p);
        break;
      }
      case 5: {  // sign flip
        const unsigned mask = (a & all_axes) ? (a & all_axes) : all_axes;
        if (!earlier(in_.byte(), p)) break;
        for (int j = 0; j < D; ++j)
          if (mask & (1u << j)) p[j] = -p[j];
        add(p);
        break;
      }
      case 6:  // scale
        if (a < 8) {
          const auto& edges = gen::notable_edges();
          e_ = edges[in_.byte() % edges.size()] + static_cast<int>(a) - 4;
        } else {
          const unsigned u = in_.byte() | (unsigned{in_.byte()} << 8);
          e_ = -1074 + static_cast<int>(u % 2098);
        }
        e_ = std::clamp(e_, -1074, 1023);
        break;
      case 7:  // origin
        switch (a % 4) {
          case 0: o_ = Point<D>{}; break;
          case 1: earlier(in_.byte(), o_); break;
          case 2: for (auto& c : o_) c = binade_value(in_.byte()); break;
          default: {
            Point<D> b;
            for (auto& c : b) c = std::bit_cast<double>(in_.u64());
            if (std::all_of(b.begin(), b.end(), [](double c) { return std::isfinite(c); })) o_ = b;
          }
        }
        break;
      case 8:  // raw point
        for (auto& c : p) c = std::bit_cast<double>(in_.u64());
        add(p);
        break;
      case 9:  // binade point
        for (auto& c : p) c = binade_value(in_.byte());
        add(p);
        break;
      case 10: {  // affine combination of earlier points
        const std::uint8_t i = in_.byte(), j = in_.byte(), k = D == 3 ? in_.byte() : 0;
        const double t = in_.int8() / 4.0, s = D == 3 ? in_.int8() / 4.0 : 0.0;
        if (!earlier(i, p) || !earlier(j, q) || !earlier(k, r)) break;
        Point<D> x;
        for (int c = 0; c < D; ++c) x[c] = p[c] + t * (q[c] - p[c]) + (D == 3 ? s * (r[c] - p[c]) : 0.0);
        add(x);
        break;
      }
      case 11: {  // power-of-two scale
        const bool ok = earlier(in_.byte(), p);
        const int k = in_.int8();
        if (!ok) break;
        for (auto& c : p) c = std::ldexp(c, k);
        add(p);
        break;
      }
      case 12: {  // permute axes
        if (!earlier(in_.byte(), p)) break;
        std::array<int, D> perm;
        for (int j = 0; j < D; ++j) perm[j] = j;
        for (unsigned t = 0; t < a % (D == 2 ? 2 : 6); ++t) std::next_permutation(perm.begin(), perm.end());
        for (int j = 0; j < D; ++j) q[j] = p[perm[j]];
        add(q);
        break;
      }
      case 13: {  // consecutive points of one circle / sphere
        const auto& c = circle_points(D, in_.byte());
        const std::size_t k0 = in_.byte();
        for (std::size_t t = 0; t < a + 3; ++t) {
          const Point3& k = c[(k0 + t) % c.size()];
          for (int j = 0; j < D; ++j) v[j] = k[j];
          add(grid(v));
        }
        break;
      }
      case 14: {  // dense 16^D grid
        for (int j = 0; j < D; j += 2) {
          const std::uint8_t b = in_.byte();
          v[j] = b & 15u;
          if (j + 1 < D) v[j + 1] = b >> 4;
        }
        add(grid(v));
        break;
      }
      default: {  // 15: translate the origin
        if (!earlier(in_.byte(), p)) break;
        Point<D> t;
        for (int j = 0; j < D; ++j) t[j] = o_[j] + p[j];
        if (std::all_of(t.begin(), t.end(), [](double c) { return std::isfinite(c); })) o_ = t;
      }
    }
  }
};

}  // namespace

std::size_t circle_radius_count(int dim) { return dim == 2 ? kRadii2.size() : kRadii3.size(); }

std::int64_t circle_radius(int dim, std::size_t r) {
  return dim == 2 ? kRadii2[r % kRadii2.size()] : kRadii3[r % kRadii3.size()];
}

const std::vector<Point3>& circle_points(int dim, std::size_t r) {
  static const auto tables = [] {
    std::array<std::vector<std::vector<Point3>>, 2> t;
    for (std::int64_t R : kRadii2) t[0].push_back(enumerate_circle(2, R));
    for (std::int64_t R : kRadii3) t[1].push_back(enumerate_circle(3, R));
    return t;
  }();
  const auto& t = tables[dim == 2 ? 0 : 1];
  return t[r % t.size()];
}

DecodedInput decode_points(std::span<const std::uint8_t> bytes, int dim) {
  if (dim != 2 && dim != 3) throw std::invalid_argument("decode_points: dimension must be 2 or 3");
  static constexpr const char* kOrders[] = {"input", "random", "brio", "hilbert"};
  DecodedInput d;
  d.points.dimension = dim;
  if (bytes.empty()) return d;
  d.order = kOrders[bytes[0] & 3u];
  d.seed = bytes[0] >> 2;
  if (dim == 2)
    d.points.p2 = Decoder<2>(bytes.subspan(1)).run();
  else
    d.points.p3 = Decoder<3>(bytes.subspan(1)).run();
  return d;
}

}  // namespace dlab::fuzz
