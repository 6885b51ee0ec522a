// See isolation.hpp.
#include "fuzz/isolation.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <stdexcept>
#include <utility>

#include "fuzz/case_runner.hpp"
#include "fuzz/child_io.hpp"
#include "fuzz/child_limits.hpp"
#include "fuzz/record.hpp"

namespace dlab::fuzz {
namespace {

// The child: runs the span, one line per case x pair, then exits without
// running the parent's destructors or flushing its buffers.
[[noreturn]] void child_main(const Work& w, Span span, int fd) {
  enter_child_limits(w.limits.memory_bytes);
  const std::uint64_t P = w.pairs.size();
  std::optional<PreparedCase> c;
  std::optional<CaseRunner> runner;
  std::optional<std::uint64_t> loaded;  // j of c
  std::string line;
  for (std::uint64_t f = span.begin; f < span.end; ++f) {
    const std::uint64_t j = f / P;
    const Pair& pair = w.pairs[f % P];
    if (loaded != j) {
      runner.reset();
      try {
        c = w.prepared(j);
      } catch (const std::exception& e) {
        write_all(fd, "E " + std::to_string(f) + " " + e.what() + "\n");
        _exit(kGenerationExit);
      }
      loaded = j;
      runner.emplace(*c);
    }
    limit_cpu_for_next(w.limits.cpu_seconds);
    maybe_misbehave(w.selftest, c->plan.index, pair);
    const PairRecord r = runs_unperturbed(w.selftest, c->plan.index, pair)
                             ? runner->run(unperturbed(pair), w.timing)
                             : runner->run(pair, w.timing);
    line = std::to_string(f) + ' ' + r.outcome + ' ' + (r.exact ? '1' : '0') + '\t' + to_json_line(r) + '\n';
    write_all(fd, line);
  }
  _exit(0);
}


std::string format_seconds(double s) {
  std::string t = std::to_string(s);
  while (t.size() > 1 && t.back() == '0') t.pop_back();
  if (!t.empty() && t.back() == '.') t.pop_back();
  return t;
}

}  // namespace

PreparedCase Work::prepared(std::uint64_t j) const {
  return cases.empty() ? prepare_case(spec, spec.case_index(j)) : cases.at(j);
}

Child::Child(const Work& work, Span span, bool alone) : span_(span), alone_(alone), next_(span.begin) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Keep only the write end, as fd 3: a child holding the read end of a
    // sibling's pipe would keep that sibling from ever getting EOF / SIGPIPE
    // after the parent dies, and two such children could block each other.
    int out = fds[1];
    if (out != 3) {
      if (dup2(out, 3) < 0) _exit(1);
      out = 3;
    }
    if (close_range(4, ~0U, 0) != 0)
      for (int fd = 4; fd < 65536; ++fd) ::close(fd);
    child_main(work, span, out);
  }
  ::close(fds[1]);
  pid_ = pid;
  fd_ = fds[0];
  last_progress_ = std::chrono::steady_clock::now();
}

Child::Child(Child&& o) noexcept { *this = std::move(o); }

Child& Child::operator=(Child&& o) noexcept {
  std::swap(pid_, o.pid_);
  std::swap(fd_, o.fd_);
  span_ = o.span_;
  alone_ = o.alone_;
  next_ = o.next_;
  buffer_ = std::move(o.buffer_);
  wall_killed_ = o.wall_killed_;
  last_progress_ = o.last_progress_;
  return *this;
}

Child::~Child() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (fd_ >= 0) ::close(fd_);
}

bool Child::read(std::vector<ChildLine>& out) {
  char buf[1 << 16];
  ssize_t got;
  do {
    got = ::read(fd_, buf, sizeof buf);
  } while (got < 0 && errno == EINTR);
  if (got <= 0) return false;
  buffer_.append(buf, static_cast<std::size_t>(got));
  std::size_t start = 0;
  for (std::size_t nl; (nl = buffer_.find('\n', start)) != std::string::npos; start = nl + 1) {
    const std::string_view l(buffer_.data() + start, nl - start);
    if (l.rfind("E ", 0) == 0) throw std::runtime_error("the generator refused: " + std::string(l.substr(2)));
    const auto sp1 = l.find(' '), sp2 = l.find(' ', sp1 + 1), tab = l.find('\t');
    if (sp1 == l.npos || sp2 == l.npos || tab == l.npos || tab != sp2 + 2)
      throw std::runtime_error("malformed line from a child: " + std::string(l.substr(0, 80)));
    ChildLine c;
    c.flat = std::stoull(std::string(l.substr(0, sp1)));
    c.outcome = std::string(l.substr(sp1 + 1, sp2 - sp1 - 1));
    c.exact = l[sp2 + 1] == '1';
    c.json = std::string(l.substr(tab + 1));
    if (c.flat != next_) throw std::runtime_error("a child skipped a case x pair");
    ++next_;
    out.push_back(std::move(c));
    last_progress_ = std::chrono::steady_clock::now();
  }
  buffer_.erase(0, start);
  return true;
}

void Child::kill_for_wall_time() {
  if (pid_ > 0 && !wall_killed_) {
    ::kill(pid_, SIGKILL);
    wall_killed_ = true;
  }
}

std::optional<Death> Child::reap(const Limits& limits) {
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && next_ == span_.end) return std::nullopt;
  Death d;
  if (wall_killed_) {
    d = {"timeout", "wall", "no progress within the wall-clock limit; killed"};
  } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
    d = {"timeout", "cpu", "CPU-time limit of " + format_seconds(limits.cpu_seconds) + " s reached"};
  } else if (WIFSIGNALED(status)) {
    const char* name = signal_name(WTERMSIG(status));
    const std::string sig = name ? name : "signal " + std::to_string(WTERMSIG(status));
    d = {"crash", sig, "killed by " + sig};
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == kOutOfMemoryExit) {
    d = {"out-of-memory", "",
         "an allocation failed under the memory limit of " + std::to_string(limits.memory_bytes >> 20) + " MiB"};
  } else {
    const std::string code = "exit " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    d = {"crash", code, "the child ended with " + code + " before finishing"};
  }
  return d;
}

}  // namespace dlab::fuzz
