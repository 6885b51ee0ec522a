// See progress.hpp.
#include "studies/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "fuzz/progress.hpp"

namespace dlab::study {

using fuzz::clock_text;

Progress::Progress(std::uint64_t total, std::uint64_t already_done)
    : enabled_(isatty(STDERR_FILENO) == 1), total_(total), before_(already_done),
      start_(std::chrono::steady_clock::now()), last_(start_) {}

void Progress::update(std::uint64_t done_now, std::uint64_t not_ok) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const bool last = before_ + done_now >= total_;
  if (drawn_ && !last && now - last_ < std::chrono::milliseconds(200)) return;  // at most 5 redraws a second
  last_ = now;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const std::uint64_t left_runs = total_ - std::min(total_, before_ + done_now);
  const std::string left =
      done_now > 0 ? clock_text(elapsed / static_cast<double>(done_now) * static_cast<double>(left_runs)) : "?";
  std::fprintf(stderr, "\r\033[Kdlab study: %llu/%llu runs, %llu not ok, %s elapsed, %s left",
               static_cast<unsigned long long>(before_ + done_now), static_cast<unsigned long long>(total_),
               static_cast<unsigned long long>(not_ok), clock_text(elapsed).c_str(), left.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (drawn_) std::fputs("\n", stderr);
  drawn_ = false;
}

}  // namespace dlab::study
