// The live progress line of a campaign, on standard error and only when that
// is a terminal: cases done, cases per second, failures, time left (the
// budget's, or the remaining cases at the current rate).
#pragma once
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

namespace dlab::fuzz {

// "m:ss", or "h:mm:ss" from an hour on (negative: 0:00).
std::string clock_text(double seconds);

class Progress {
 public:
  // total: cases to run in this session (none with a budget); deadline: the budget's end.
  Progress(std::optional<std::uint64_t> total, std::optional<std::chrono::steady_clock::time_point> deadline);
  void update(std::uint64_t cases_done, std::uint64_t failures);
  // Ends the line (if one was drawn).
  void finish();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::optional<std::uint64_t> total_;
  std::optional<std::chrono::steady_clock::time_point> deadline_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace dlab::fuzz
