// Runs a shard's cases in child processes (fuzz/isolation.hpp), J at a time,
// in batches of consecutive cases, and hands back each case's lines in case
// order. A batch whose child dies is continued: the case x pair it did not
// finish is re-run alone in a fresh child (its outcome there is the record:
// crash, timeout or out-of-memory if it dies again), then the rest of the
// batch in another child. Batches grow or shrink so that one takes about a
// quarter of a second; the records do not depend on the batching.
#pragma once
#include <chrono>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "fuzz/isolation.hpp"

namespace dlab::fuzz {

struct CaseDone {
  std::uint64_t position = 0;   // the case's position in the shard (case index: spec.case_index)
  std::string lines;            // its records, one JSON line per pair, in pair order, each ending '\n'
  std::uint64_t failures = 0;   // pairs whose outcome is a failure
  std::uint64_t exact_failures = 0;  // of those, exact pairs
};

struct Schedule {
  unsigned jobs = 1;
  std::uint64_t start = 0;  // first case position to run
  std::uint64_t end = 0;    // one past the last (UINT64_MAX: until the deadline)
  std::optional<std::chrono::steady_clock::time_point> deadline;  // no new batch after it
  double wall_seconds = 0;  // a child that writes nothing for this long is killed (timeout)
  // Spans of one case x pair (P = 1, batch 1) whose death is their record at
  // once, without the re-run alone (dlab shrink: a hang then costs one limit, not two).
  bool single = false;
};

// Calls on_case for each finished case, in position order, and tick about
// four times a second. Throws std::runtime_error when a child reports that
// the generator refused a case or breaks the line protocol.
void run_schedule(const Work& work, const Schedule& s, const std::function<void(const CaseDone&)>& on_case,
                  const std::function<void()>& tick);

}  // namespace dlab::fuzz
