// See scheduler.hpp.
#include "fuzz/scheduler.hpp"

#include <poll.h>

#include <algorithm>
#include <deque>
#include <map>
#include <memory>
#include <tuple>
#include <vector>

#include "fuzz/case_runner.hpp"
#include "fuzz/fuzz_outcome.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {
namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  std::unique_ptr<Child> child;
  Clock::time_point started;
};

struct Pending {
  std::string lines;
  std::uint64_t got = 0, failures = 0, exact_failures = 0;
};

// The record of a case x pair whose child died running it alone.
std::string death_record(const Work& w, std::uint64_t flat, const Death& d, double seconds) {
  const std::uint64_t P = w.pairs.size();
  const PreparedCase c = w.prepared(flat / P);
  PairRecord r = record_header(c, w.pairs[flat % P]);
  r.outcome = d.outcome;
  r.kind = d.kind;
  r.detail = d.detail;
  r.seconds = w.timing ? seconds : 0.0;
  return to_json_line(r);
}

}  // namespace

void run_schedule(const Work& w, const Schedule& s, const std::function<void(const CaseDone&)>& on_case,
                  const std::function<void()>& tick) {
  const std::uint64_t P = w.pairs.size();
  std::deque<std::pair<Span, bool>> retry;  // spans left by dead children; bool: alone
  std::vector<Running> running;
  std::map<std::uint64_t, Pending> pending;
  std::uint64_t next_case = s.start, write_case = s.start, batch = 4;
  auto last_tick = Clock::now();

  const auto deliver = [&](std::uint64_t flat, const std::string& outcome, bool exact, const std::string& json) {
    Pending& p = pending[flat / P];
    p.lines += json;
    p.lines += '\n';
    ++p.got;
    if (is_failure(outcome)) {
      ++p.failures;
      if (exact) ++p.exact_failures;
    }
    for (auto it = pending.find(write_case); it != pending.end() && it->second.got == P;
         it = pending.find(write_case)) {
      on_case(CaseDone{write_case, std::move(it->second.lines), it->second.failures, it->second.exact_failures});
      pending.erase(it);
      ++write_case;
    }
  };

  for (;;) {
    const auto now = Clock::now();
    while (running.size() < std::max(1u, s.jobs)) {
      Span span;
      bool alone = false;
      if (!retry.empty()) {
        std::tie(span, alone) = retry.front();
        retry.pop_front();
      } else if (next_case < s.end && (!s.deadline || now < *s.deadline)) {
        const std::uint64_t e = s.single ? next_case + 1 : std::min(s.end, next_case + batch);
        span = {next_case * P, e * P};
        alone = s.single && P == 1;
        next_case = e;
      } else {
        break;
      }
      running.push_back({std::make_unique<Child>(w, span, alone), Clock::now()});
    }
    if (running.empty()) break;

    std::vector<pollfd> fds;
    for (const auto& r : running) fds.push_back({r.child->fd(), POLLIN, 0});
    poll(fds.data(), fds.size(), 250);
    std::vector<ChildLine> lines;
    for (std::size_t i = running.size(); i-- > 0;) {
      Running& r = running[i];
      if (fds[i].revents == 0) {
        if (std::chrono::duration<double>(Clock::now() - r.child->last_progress()).count() > s.wall_seconds)
          r.child->kill_for_wall_time();
        continue;
      }
      lines.clear();
      const bool open = r.child->read(lines);
      for (const auto& l : lines) deliver(l.flat, l.outcome, l.exact, l.json);
      if (open) continue;
      const auto death = r.child->reap(w.limits);
      const double seconds = std::chrono::duration<double>(Clock::now() - r.started).count();
      const Span span = r.child->span();
      if (!death || r.child->next() >= span.end) {  // finished (a late exit status changes nothing)
        if (!r.child->alone()) {  // about a quarter of a second per batch
          const double cases = static_cast<double>(span.end - span.begin) / static_cast<double>(P);
          const double rate = cases / std::max(seconds, 1e-3);
          batch = static_cast<std::uint64_t>(std::clamp(rate * 0.25, 1.0, 1024.0));
        }
      } else {
        const std::uint64_t culprit = r.child->next();
        if (r.child->alone()) {
          deliver(culprit, death->outcome, w.pairs[culprit % P].exact(), death_record(w, culprit, *death, seconds));
        } else {  // name the culprit alone, then the rest of the batch
          if (culprit + 1 < span.end) retry.push_front({Span{culprit + 1, span.end}, false});
          retry.push_front({Span{culprit, culprit + 1}, true});
        }
      }
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(i));
    }
    if (Clock::now() - last_tick > std::chrono::milliseconds(250)) {
      tick();
      last_tick = Clock::now();
    }
  }
  tick();
}

}  // namespace dlab::fuzz
