// See progress.hpp.
#include "fuzz/progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <string>

namespace dlab::fuzz {

std::string clock_text(double seconds) {
  const long s = seconds < 0 ? 0 : static_cast<long>(seconds + 0.5);
  char buf[32];
  if (s >= 3600)
    std::snprintf(buf, sizeof buf, "%ld:%02ld:%02ld", s / 3600, s / 60 % 60, s % 60);
  else
    std::snprintf(buf, sizeof buf, "%ld:%02ld", s / 60, s % 60);
  return buf;
}

Progress::Progress(std::optional<std::uint64_t> total, std::optional<std::chrono::steady_clock::time_point> deadline)
    : enabled_(isatty(STDERR_FILENO) == 1), total_(total), deadline_(deadline),
      start_(std::chrono::steady_clock::now()) {}

void Progress::update(std::uint64_t done, std::uint64_t failures) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  std::string left = "?";
  if (deadline_)
    left = clock_text(std::chrono::duration<double>(*deadline_ - now).count());
  else if (total_ && rate > 0)
    left = clock_text(static_cast<double>(*total_ - std::min(done, *total_)) / rate);
  const std::string of = total_ ? std::string("/").append(std::to_string(*total_)) : std::string();
  std::fprintf(stderr, "\r\033[Kdlab fuzz: %llu%s cases, %.0f cases/s, %llu failures, %s left",
               static_cast<unsigned long long>(done), of.c_str(), rate,
               static_cast<unsigned long long>(failures), left.c_str());
  std::fflush(stderr);
  drawn_ = true;
}

void Progress::finish() {
  if (drawn_) std::fputs("\n", stderr);
  drawn_ = false;
}

}  // namespace dlab::fuzz
