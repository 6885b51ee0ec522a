// See shrink_ddmin.hpp (Zeller and Hildebrandt 2002, section 3).
#include "fuzz/shrink_ddmin.hpp"

#include <algorithm>

namespace dlab::fuzz {
namespace {

// Part i of n of c: contiguous, sizes differing by at most one.
std::vector<std::size_t> part(const std::vector<std::size_t>& c, std::size_t n, std::size_t i) {
  return {c.begin() + static_cast<std::ptrdiff_t>(i * c.size() / n),
          c.begin() + static_cast<std::ptrdiff_t>((i + 1) * c.size() / n)};
}

std::vector<std::size_t> complement(const std::vector<std::size_t>& c, std::size_t n, std::size_t i) {
  std::vector<std::size_t> out(c.begin(), c.begin() + static_cast<std::ptrdiff_t>(i * c.size() / n));
  out.insert(out.end(), c.begin() + static_cast<std::ptrdiff_t>((i + 1) * c.size() / n), c.end());
  return out;
}

}  // namespace

std::vector<std::size_t> ddmin(std::size_t count, const SubsetTest& fails) {
  std::vector<std::size_t> c(count);
  for (std::size_t i = 0; i < count; ++i) c[i] = i;
  std::size_t n = 2;
  while (c.size() >= 2) {
    n = std::min(n, c.size());
    bool reduced = false;
    for (std::size_t i = 0; i < n && !reduced; ++i) {
      std::vector<std::size_t> d = part(c, n, i);
      if (fails(d)) {
        c = std::move(d);
        n = 2;
        reduced = true;
      }
    }
    for (std::size_t i = 0; i < n && !reduced && n > 2; ++i) {
      std::vector<std::size_t> d = complement(c, n, i);
      if (fails(d)) {
        c = std::move(d);
        n = std::max<std::size_t>(n - 1, 2);
        reduced = true;
      }
    }
    if (reduced) continue;
    if (n >= c.size()) break;  // 1-minimal
    n = std::min(2 * n, c.size());
  }
  return c;
}

}  // namespace dlab::fuzz
