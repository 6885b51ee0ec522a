// One run of a study in a child process of its own (fork), so that a crash,
// a runaway loop or a runaway allocation of an inexact kernel is an outcome
// of that run and not the end of the study. The child runs under the fuzzer's
// limits (fuzz/child_limits.hpp: no core files, an address-space limit, a
// CPU-time limit per step) and the parent kills it after a wall-clock limit.
//
// In the child, in this order:
//   1. the input: generated, or read from its file (not measured);
//   2. one line {"input_points": N} to the parent;
//   3. VmHWM reset ("5" written to /proc/self/clear_refs; proc(5)), the CPU
//      limit set, the run: dlab::run() (or run_baseline());
//   4. VmHWM read from /proc/self/status: the peak resident size of the
//      process during the run -- the process's own baseline (the dlab image
//      and the input points, resident when the mark was reset) included, the
//      validator's memory excluded. George's runs validate inside dlab::run()
//      (variants/george_run.hpp), so their peak includes that validation. An
//      external baseline reports the peak of its own process
//      (getrusage(RUSAGE_CHILDREN) ru_maxrss); CGAL runs in the child itself;
//   5. a fresh CPU limit, then the exact validator (variants/outcome.hpp's
//      classify(), Validate::always: every result is judged; baselines:
//      classify_baseline(), orientation any);
//   6. one line with the measure (JSON), then _exit(0).
// Wall and CPU seconds are RunResult::seconds and ::cpu_seconds: measured
// inside dlab::run() around the triangulation alone (variants/driver.hpp).
#pragma once
#include <sys/types.h>

#include <chrono>
#include <optional>
#include <string>

#include "studies/columns.hpp"
#include "studies/config.hpp"
#include "studies/matrix.hpp"

namespace dlab::study {

class RunChild {
 public:
  // Forks; the child runs `spec` and exits. Throws std::runtime_error if fork fails.
  RunChild(const StudyConfig& config, const RunSpec& spec);
  RunChild(RunChild&&) noexcept;
  RunChild& operator=(RunChild&&) noexcept;
  RunChild(const RunChild&) = delete;
  ~RunChild();

  int fd() const { return fd_; }
  std::uint64_t id() const { return id_; }
  std::chrono::steady_clock::time_point started() const { return started_; }

  // Reads what is available; false at end of file.
  bool read();
  // SIGKILL for running past the wall-clock limit.
  void kill_for_wall_time();

  struct Result {
    std::optional<RunMeasure> measure;  // none: the run was skipped (baseline unavailable)
    std::string skipped;                // why
    std::string error;                  // the input could not be made: a configuration error
    std::string interrupted;            // killed by SIGINT, SIGTERM or SIGHUP (not ours): no row
  };
  // After end of file: waits for the child and says what the run gave.
  Result finish(double timeout_seconds, std::uint64_t memory_limit_mib);

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::uint64_t id_ = 0;
  std::string buffer_;
  bool wall_killed_ = false;
  std::chrono::steady_clock::time_point started_;
};

}  // namespace dlab::study
