// Insertion orders; see insertion_order.hpp for the sources.
#include "variants/insertion_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include "algorithms/huge_pages.hpp"
#include "variants/for_ranges.hpp"
#include "variants/run.hpp"

namespace dlab {

InsertionOrder parse_insertion_order(std::string_view name) {
  if (name == "input") return InsertionOrder::input;
  if (name == "random") return InsertionOrder::random;
  if (name == "brio") return InsertionOrder::brio;
  if (name == "hilbert") return InsertionOrder::hilbert;
  throw UsageError("unknown insertion order '" + std::string(name) +
                   "' (expected input, random, brio or hilbert)");
}

// n dimensions: Skilling 2004: convert axes to the "transposed" Hilbert index in place
// (undo the excess rotations/reflections from the top bit down, then Gray
// encode), and read the index off bit-plane by bit-plane.
// 2D: a 4-state machine, one table look-up per two levels.  The state is the
// transform (identity, transpose, anti-transpose, half-turn) that maps the
// current sub-square onto the canonical one; these four form the Klein group,
// encoded so that composition is XOR.  In the canonical square the quadrants
// (x,y) = (0,0), (0,1), (1,1), (1,0) get digits 0, 1, 2, 3, and the sub-squares
// (0,0) and (1,0) are entered transposed and anti-transposed (the recursion of
// Hilbert's construction).
namespace {
constexpr std::array<std::uint8_t, 16> kHilbert2 = [] {
  std::array<std::uint8_t, 16> t{};
  for (int m = 0; m < 4; ++m)
    for (int bx = 0; bx < 2; ++bx)
      for (int by = 0; by < 2; ++by) {
        int rx = bx, ry = by;
        if (((m >> 1) ^ m) & 1) {  // transpose or anti-transpose: swap
          const int tmp = rx;
          rx = ry;
          ry = tmp;
        }
        if (m & 2) rx ^= 1, ry ^= 1;  // anti-transpose or half-turn: reflect
        const int digit = (rx << 1) | (rx ^ ry);
        const int sub = (rx == 0 && ry == 0) ? 1 : (rx == 1 && ry == 0) ? 2 : 0;
        t[(m << 2) | (bx << 1) | by] = static_cast<std::uint8_t>(((m ^ sub) << 2) | digit);
      }
  return t;
}();
}  // namespace

// 3D: Skilling's transform read as a state machine.
// At each level Skilling's loop reads the level's bits t (the raw bits r under
// the transform the levels above left on the lower bits), then reflects x[0]'s
// lower bits (t_i set) or exchanges them with x[i]'s (t_i clear), i = 0, 1, 2:
// the transform is a signed permutation of the axes (48 of them), updated per
// level from t alone. The Gray code g of t and the parity P of x[2]'s Gray bits
// on the levels above (Skilling's final XOR) give the level's digit, g ^ (P P P).
// State: (permutation, reflections, P); the table is derived from those rules.
namespace {
struct AxisTransform {  // lower bit j = r[perm[j]] ^ flip[j]
  int perm[3];
  int flip[3];
};
constexpr std::array<std::array<int, 3>, 6> kPerms3 = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
constexpr int state3(const AxisTransform& a, int parity) {
  int p = 0;
  while (!(kPerms3[p][0] == a.perm[0] && kPerms3[p][1] == a.perm[1])) ++p;
  return ((p * 8 + (a.flip[0] << 2 | a.flip[1] << 1 | a.flip[2])) << 1) | parity;
}
// (state << 3 | r) -> (next state << 3 | digit), r = (x0, x1, x2) bits of the level.
constexpr std::array<std::uint16_t, 96 * 8> kHilbert3 = [] {
  std::array<std::uint16_t, 96 * 8> t{};
  for (int p = 0; p < 6; ++p)
    for (int fl = 0; fl < 8; ++fl)
      for (int parity = 0; parity < 2; ++parity)
        for (int r = 0; r < 8; ++r) {
          AxisTransform a{{kPerms3[p][0], kPerms3[p][1], kPerms3[p][2]}, {fl >> 2 & 1, fl >> 1 & 1, fl & 1}};
          const int raw[3] = {r >> 2 & 1, r >> 1 & 1, r & 1};
          int bit[3];
          for (int j = 0; j < 3; ++j) bit[j] = raw[a.perm[j]] ^ a.flip[j];
          for (int i = 0; i < 3; ++i) {
            if (bit[i]) {
              a.flip[0] ^= 1;
            } else {
              const int tp = a.perm[0], tf = a.flip[0];
              a.perm[0] = a.perm[i], a.flip[0] = a.flip[i];
              a.perm[i] = tp, a.flip[i] = tf;
            }
          }
          const int g0 = bit[0], g1 = bit[1] ^ g0, g2 = bit[2] ^ g1;
          const int digit = ((g0 << 2) | (g1 << 1) | g2) ^ (parity ? 7 : 0);
          t[(((p * 8 + fl) << 1 | parity) << 3) | r] = static_cast<std::uint16_t>((state3(a, parity ^ g2) << 3) | digit);
        }
  return t;
}();
static_assert(state3({{0, 1, 2}, {0, 0, 0}}, 0) == 0);  // the machine starts in state 0
// Both machines' tables map (state << N | the level's bits, axis 0's highest) to
// (next state << N | the level's N digits). Two levels a look-up: the table
// applied twice, (state << 2N | two bits of each axis) -> (state << 2N | 2N digits).
template <int N, int States, class One>
constexpr std::array<std::uint16_t, (States << 2 * N)> two_levels(const One& one) {
  constexpr int mask = (1 << N) - 1;
  std::array<std::uint16_t, (States << 2 * N)> t{};
  for (int m = 0; m < States; ++m)
    for (int in = 0; in < (1 << 2 * N); ++in) {
      int hi = 0, lo = 0;
      for (int i = 0; i < N; ++i) {
        const int two = in >> (2 * (N - 1 - i)) & 3;
        hi = hi << 1 | two >> 1;
        lo = lo << 1 | (two & 1);
      }
      const int e1 = one[(m << N) | hi], e2 = one[(e1 & ~mask) | lo];
      t[(m << 2 * N) | in] = static_cast<std::uint16_t>((e2 >> N) << 2 * N | (e1 & mask) << N | (e2 & mask));
    }
  return t;
}
constexpr auto kHilbert2x2 = two_levels<2, 4>(kHilbert2);
constexpr auto kHilbert3x2 = two_levels<3, 96>(kHilbert3);

// The key of x on `bits` levels through the tables: an odd level first, then two at a time.
template <int N, class One, class Two>
[[gnu::always_inline]] inline std::uint64_t key_by_tables(const std::uint32_t* x, int bits, const One& one,
                                                          const Two& two) {
  auto level_bits = [&](int b, unsigned width) {
    unsigned r = 0;
    for (int i = 0; i < N; ++i) r = r << width | ((x[i] >> b) & ((1u << width) - 1));
    return r;
  };
  std::uint64_t key = 0;
  unsigned m = 0;
  int b = bits;
  if (b & 1) {
    --b;
    const unsigned e = one[level_bits(b, 1)];
    key = e & ((1u << N) - 1);
    m = e >> N;
  }
  while (b > 0) {
    b -= 2;
    const unsigned e = two[(m << 2 * N) | level_bits(b, 2)];
    key = (key << 2 * N) | (e & ((1u << 2 * N) - 1));
    m = e >> 2 * N;
  }
  return key;
}
}  // namespace

std::uint64_t hilbert_key_skilling(std::uint32_t* x, int n, int bits) {
  const std::uint32_t top = std::uint32_t(1) << (bits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t low = q - 1;
    for (int i = 0; i < n; ++i) {
      // Branch-free form of: if (x[i] & q) reflect (x[0] ^= low); else
      // exchange the low bits of x[0] and x[i].  (The branch is a coin flip on
      // real data: mispredictions dominated the cost.)
      const std::uint32_t set = 0u - ((x[i] & q) != 0);
      const std::uint32_t t = (x[0] ^ x[i]) & low & ~set;
      x[0] ^= (low & set) ^ t;
      x[i] ^= t;
    }
  }
  for (int i = 1; i < n; ++i) x[i] ^= x[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1) t ^= (q - 1) & (0u - ((x[n - 1] & q) != 0));
  for (int i = 0; i < n; ++i) x[i] ^= t;
  std::uint64_t key = 0;
  for (int b = bits - 1; b >= 0; --b)
    for (int i = 0; i < n; ++i) key = (key << 1) | ((x[i] >> b) & 1u);
  return key;
}

std::uint64_t hilbert_key(std::uint32_t* x, int n, int bits) {
  if (n == 2) return key_by_tables<2>(x, bits, kHilbert2, kHilbert2x2);
  if (n == 3) return key_by_tables<3>(x, bits, kHilbert3, kHilbert3x2);
  return hilbert_key_skilling(x, n, bits);
}

namespace {

struct SplitMix64 {
  std::uint64_t s;
  std::uint64_t next() {
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
};

void shuffle(std::vector<std::uint32_t>& v, std::uint64_t seed) {
  SplitMix64 g{seed};
  for (std::size_t i = v.size(); i > 1; --i) {
    const std::size_t j = static_cast<std::size_t>(g.next() % i);
    std::swap(v[i - 1], v[j]);
  }
}

// Hilbert keys over the bounding cube of the points (one scale for every axis,
// so the curve keeps distances; halves avoid overflow of max - min).
template <int D>
HugeBuffer<std::uint64_t> hilbert_keys(std::span<const Point<D>> pts, unsigned threads) {
  // Cells per axis: about 16 per point along each axis (2^(log2(n)/D + 4)),
  // at most 2^24 (2D) / 2^18 (3D).  The key's cost is linear in the bits.
  constexpr int max_bits = D == 2 ? 24 : 18;
  int bits = 4;
  while (bits < max_bits && (std::uint64_t(1) << (D * (bits - 4))) < pts.size()) ++bits;
  HugeBuffer<std::uint64_t> keys = huge_buffer<std::uint64_t>(pts.size());
  if (pts.empty()) return keys;
  Point<D> lo = pts[0], hi = pts[0];
  for (const auto& p : pts)
    for (int a = 0; a < D; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  double extent = 0;
  for (int a = 0; a < D; ++a) extent = std::max(extent, hi[a] * 0.5 - lo[a] * 0.5);
  const double cells = double((std::uint64_t(1) << bits) - 1);
  // cells / extent overflows to infinity when the extent is below
  // 2^(bits - 1024), e.g. on subnormal input: every point then fell in a corner
  // cell (an order no better than random). Such extents divide first instead.
  const bool usable = extent > 0 && std::isfinite(extent);
  const double scale = usable ? cells / extent : 0;
  auto key_range = [&](std::size_t first, std::size_t last) {
    for (std::size_t i = first; i < last; ++i) {
      std::uint32_t x[D];
      for (int a = 0; a < D; ++a) {
        const double offset = pts[i][a] * 0.5 - lo[a] * 0.5;
        double t = std::isfinite(scale) ? offset * scale : offset / extent * cells;
        if (!(t >= 0)) t = 0;  // NaN-safe
        if (t > cells) t = cells;
        x[a] = static_cast<std::uint32_t>(t);
      }
      keys[i] = hilbert_key(x, D, bits);
    }
  };
  for_ranges(pts.size(), threads, key_range, 4096);
  return keys;
}

struct KeyedIndex {
  std::uint64_t key;
  std::uint32_t index;
};

// Stable LSD radix sort of idx[first, last) by keys[idx], 11-bit digits,
// skipping digits on which all keys agree; a and b: room for last - first
// entries.  Each pass counts its digits in fixed chunks of the entries, then
// each chunk moves its entries to places of its own (after the earlier
// chunks' entries of the same digit): on `threads` oneTBB threads, with the
// same result for every thread count.
void sort_by_key(std::vector<std::uint32_t>& idx, std::size_t first, std::size_t last, const std::uint64_t* keys,
                 KeyedIndex* a, KeyedIndex* b, unsigned threads) {
  const std::size_t n = last - first;
  if (n < 2) return;
  if (n < 256) {
    std::stable_sort(idx.begin() + first, idx.begin() + last,
                     [&](std::uint32_t x, std::uint32_t y) { return keys[x] < keys[y]; });
    return;
  }
  constexpr int digit = 11;  // 2048 buckets: a chunk's counters and write heads stay in L1
  constexpr std::size_t buckets = std::size_t{1} << digit;
  const std::size_t chunk = std::max<std::size_t>(std::size_t{1} << 15, (n + 63) / 64);
  const std::size_t chunks = (n + chunk - 1) / chunk;
  auto for_chunks = [&](auto&& f) { dlab::for_chunks(n, chunk, threads, f); };
  std::vector<std::uint64_t> chunk_or(chunks, 0), chunk_and(chunks, ~std::uint64_t(0));
  for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) {
      const std::uint32_t j = idx[first + i];
      a[i] = {keys[j], j};
      chunk_or[c] |= a[i].key;
      chunk_and[c] &= a[i].key;
    }
  });
  std::uint64_t all_or = 0, all_and = ~std::uint64_t(0);
  for (std::size_t c = 0; c < chunks; ++c) all_or |= chunk_or[c], all_and &= chunk_and[c];
  const std::uint64_t varying = all_or ^ all_and;
  constexpr std::uint64_t dmask = buckets - 1;
  std::vector<std::size_t> at(chunks * buckets);  // at[c * buckets + d]: chunk c's next place for digit d
  for (int shift = 0; shift < 64; shift += digit) {
    if (((varying >> shift) & dmask) == 0) continue;
    std::fill(at.begin(), at.end(), 0);
    for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
      std::size_t* count = &at[c * buckets];
      for (std::size_t i = lo; i < hi; ++i) ++count[(a[i].key >> shift) & dmask];
    });
    std::size_t sum = 0;
    for (std::size_t d = 0; d < buckets; ++d)
      for (std::size_t c = 0; c < chunks; ++c) sum += std::exchange(at[c * buckets + d], sum);
    for_chunks([&](std::size_t c, std::size_t lo, std::size_t hi) {
      std::size_t* next = &at[c * buckets];
      for (std::size_t i = lo; i < hi; ++i) b[next[(a[i].key >> shift) & dmask]++] = a[i];
    });
    std::swap(a, b);
  }
  for_chunks([&](std::size_t, std::size_t lo, std::size_t hi) {
    for (std::size_t i = lo; i < hi; ++i) idx[first + i] = a[i].index;
  });
}

}  // namespace

void sort_indices_by_key(std::vector<std::uint32_t>& idx, std::size_t first, std::size_t last,
                         std::span<const std::uint64_t> keys, unsigned threads) {
  const auto a = huge_buffer<KeyedIndex>(last - first), b = huge_buffer<KeyedIndex>(last - first);
  sort_by_key(idx, first, last, keys.data(), a.get(), b.get(), threads);
}

namespace {

template <int D>
std::vector<std::uint32_t> order_impl(std::span<const Point<D>> pts, InsertionOrder order,
                                      std::uint64_t seed, unsigned threads) {
  std::vector<std::uint32_t> idx = huge_vector<std::uint32_t>(pts.size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint32_t>(i);
  switch (order) {
    case InsertionOrder::input:
      break;
    case InsertionOrder::random:
      shuffle(idx, seed);
      break;
    case InsertionOrder::hilbert: {
      const auto keys = hilbert_keys<D>(pts, threads);
      const auto a = huge_buffer<KeyedIndex>(idx.size()), b = huge_buffer<KeyedIndex>(idx.size());
      sort_by_key(idx, 0, idx.size(), keys.get(), a.get(), b.get(), threads);
      break;
    }
    case InsertionOrder::brio: {
      shuffle(idx, seed);
      const auto keys = hilbert_keys<D>(pts, threads);
      // Rounds [0, b_k), [b_k, b_{k-1}), ..., [b_1, n) with b_{j+1} = b_j / 8;
      // the last is the largest.
      std::size_t end = idx.size();
      const std::size_t largest = end - (end >= 64 ? end / 8 : 0);
      const auto a = huge_buffer<KeyedIndex>(largest), b = huge_buffer<KeyedIndex>(largest);
      while (end > 0) {
        const std::size_t begin = end >= 64 ? end / 8 : 0;
        sort_by_key(idx, begin, end, keys.get(), a.get(), b.get(), threads);
        end = begin;
      }
      break;
    }
  }
  return idx;
}

}  // namespace

std::vector<std::uint32_t> insertion_order(std::span<const Point2> pts, InsertionOrder order,
                                           std::uint64_t seed, unsigned threads) {
  return order_impl<2>(pts, order, seed, threads);
}
std::vector<std::uint32_t> insertion_order(std::span<const Point3> pts, InsertionOrder order,
                                           std::uint64_t seed, unsigned threads) {
  return order_impl<3>(pts, order, seed, threads);
}

}  // namespace dlab
