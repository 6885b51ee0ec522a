// Runs a function over the ranges of [0, n) on `threads` oneTBB threads, for
// the passes around the triangulation (insertion order, output order) that
// split into independent ranges.
#pragma once
#include <algorithm>
#include <cstddef>

#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

namespace dlab {

// f(first, last) over [0, n) cut into ranges of about `grain`, on `threads`
// oneTBB threads when > 1; threads <= 1: f(0, n) on the calling thread.
template <class F>
void for_ranges(std::size_t n, unsigned threads, F&& f, std::size_t grain = 1 << 14) {
  if (threads <= 1) return f(std::size_t{0}, n);
  tbb::global_control allowed(tbb::global_control::max_allowed_parallelism, threads);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                    [&](const tbb::blocked_range<std::size_t>& r) { f(r.begin(), r.end()); });
}

// [0, n) cut into fixed chunks of `chunk` (the last one shorter):
// f(c, first, last) for each chunk c, on `threads` threads.  The chunks do not
// depend on the thread count, so passes that give each chunk places of its
// own give the same result for every count.
template <class F>
void for_chunks(std::size_t n, std::size_t chunk, unsigned threads, F&& f) {
  for_ranges((n + chunk - 1) / chunk, threads, [&](std::size_t first, std::size_t last) {
    for (std::size_t c = first; c < last; ++c) f(c, c * chunk, std::min(n, (c + 1) * chunk));
  }, 1);
}

}  // namespace dlab
