// Case x pairs run in child processes (fork), so that a crash, a hang or a
// runaway allocation of an inexact pair never takes the campaign down.
//
// The work of a shard is a sequence of case x pairs numbered flat:
// f = j * P + p for the j-th case of the shard and pair p of P. A child runs a
// span [begin, end) of it under the limits of fuzz/child_limits.hpp and
// writes one line per case x pair to a pipe as soon as it has it:
//   "F OUTCOME EXACT\tJSON\n"   (F the flat index, EXACT 0 or 1, JSON the record)
// so the parent knows the first case x pair it did not get when the child
// dies. The child's exit says why: a signal (crash; SIGXCPU: timeout), exit
// status kOutOfMemoryExit (out-of-memory), kGenerationExit after a line
// "E F MESSAGE" (the generator refused the case: a campaign error).
#pragma once
#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/case_runner.hpp"
#include "fuzz/selftest.hpp"

namespace dlab::fuzz {

inline constexpr int kGenerationExit = 87;

struct Limits {
  double cpu_seconds = 10;                         // per case x pair
  std::uint64_t memory_bytes = std::uint64_t{4} << 30;  // per child, beyond its start
};

// What every child needs to know.
struct Work {
  CampaignSpec spec;
  std::vector<PreparedCase> cases;  // the corpus's cases (fuzz/corpus_run.hpp); empty for a campaign
  std::vector<Pair> pairs;
  std::vector<Misbehaviour> selftest;
  Limits limits;
  bool timing = true;

  // The j-th case: cases[j] when the work lists its cases, else the
  // campaign's case spec.case_index(j), generated.
  PreparedCase prepared(std::uint64_t j) const;
};

struct Span {
  std::uint64_t begin = 0, end = 0;  // flat case x pair indices
};

// One line the child wrote.
struct ChildLine {
  std::uint64_t flat = 0;
  std::string outcome;
  bool exact = false;
  std::string json;
};

// How a child ended, when it did not finish its span.
struct Death {
  std::string outcome;  // crash | timeout | out-of-memory
  std::string kind;     // crash: the signal's name ("SIGSEGV") or "exit N"; timeout: "cpu" or "wall"
  std::string detail;
};

class Child {
 public:
  // Forks; the child runs `span` and exits. Throws std::runtime_error if fork fails.
  Child(const Work& work, Span span, bool alone);
  Child(Child&&) noexcept;
  Child& operator=(Child&&) noexcept;
  Child(const Child&) = delete;
  ~Child();

  int fd() const { return fd_; }
  const Span& span() const { return span_; }
  bool alone() const { return alone_; }
  // The first case x pair of the span not yet received.
  std::uint64_t next() const { return next_; }

  // Reads what is available; appends complete lines to `out`. Returns false at
  // end of file. Throws std::runtime_error for a generator failure ("E" line)
  // or a malformed line.
  bool read(std::vector<ChildLine>& out);
  // Kills the child (SIGKILL) for making no progress within the wall limit.
  void kill_for_wall_time();
  std::chrono::steady_clock::time_point last_progress() const { return last_progress_; }
  // Waits for the child after end of file; nothing if it finished its span cleanly.
  std::optional<Death> reap(const Limits& limits);

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  Span span_;
  bool alone_ = false;
  std::uint64_t next_ = 0;
  std::string buffer_;
  bool wall_killed_ = false;
  std::chrono::steady_clock::time_point last_progress_;
};

}  // namespace dlab::fuzz
