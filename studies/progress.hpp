// The live line of a study on standard error, only when that is a terminal:
// runs done of the shard's total, runs whose outcome is not ok, time left at
// this session's rate.
#pragma once
#include <chrono>
#include <cstdint>

namespace dlab::study {

class Progress {
 public:
  Progress(std::uint64_t total, std::uint64_t already_done);
  void update(std::uint64_t done_now, std::uint64_t not_ok);
  void finish();  // ends the line, if one was drawn

 private:
  bool enabled_;
  bool drawn_ = false;
  std::uint64_t total_, before_;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace dlab::study
