// See run_child.hpp.
#include "studies/run_child.hpp"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

#include "algorithms/validate.hpp"
#include "fuzz/child_io.hpp"
#include "fuzz/child_limits.hpp"
#include "studies/inputs.hpp"
#include "variants/outcome.hpp"
#if DLAB_STUDY_BASELINES
#include "studies/baselines.hpp"
#endif

namespace dlab::study {
namespace {

using fuzz::signal_name;
using fuzz::write_all;

constexpr int kInputErrorExit = 87;

void send(int fd, const nlohmann::json& j) { write_all(fd, j.dump() + "\n"); }

// Resets the peak resident size of this process (VmHWM) to the current one.
void reset_peak_rss() {
  if (std::FILE* f = std::fopen("/proc/self/clear_refs", "w")) {
    std::fputs("5", f);
    std::fclose(f);
  }
}

// VmHWM of /proc/self/status in bytes (0 if it cannot be read).
std::uint64_t peak_rss() {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stoull(line.substr(6)) * 1024;
  return 0;
}

nlohmann::json counters_json(const Counters& c) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& [name, v] : c) a.push_back({name, v});
  return a;
}

// Takes the points, as `dlab triangulate` does (the run's memory is then
// that command's): they come back in res.points, or stay in `pts` after an
// exception.
nlohmann::json run_dlab(PointSet&& pts, const RunSpec& s, double timeout) {
  const RunOptions opt = s.options();
  const std::size_t input_points = pts.size();
  const int dimension = pts.dimension;
  reset_peak_rss();
  fuzz::limit_cpu_for_next(timeout);
  RunResult res;
  try {
    res = dlab::run(std::move(pts), opt);
  } catch (const UsageError& e) {
    throw std::invalid_argument(e.what());  // a configuration the registry refuses
  } catch (const std::exception& e) {       // as dlab triangulate: an algorithm that throws has failed
    res = RunResult{};
    res.outcome = RunResult::Outcome::failed;
    res.message = std::string("exception: ") + e.what();
  }
  const std::uint64_t rss = peak_rss();
  res.dimension = dimension;
  if (res.points.size() != input_points) res.points = std::move(pts);  // after an exception
  fuzz::limit_cpu_for_next(timeout);
  const Outcome o = classify(res.points, res, s.exact_pair(), Validate::always);
  const bool built = res.outcome != RunResult::Outcome::lower_dimensional;
  nlohmann::json m;
  m["distinct_points"] = res.distinct_points;
  m["simplices"] = built ? res.simplices.size() / static_cast<std::size_t>(dimension + 1) : 0;
  m["outcome"] = std::string(outcome_name(o.kind));
  m["message"] = o.detail;
  m["wall"] = res.seconds;
  m["cpu"] = res.cpu_seconds;
  m["rss"] = rss;
  m["pred"] = counters_json(res.predicates);
  m["ctr"] = counters_json(res.counters);
  return m;
}

nlohmann::json run_external(const PointSet& pts, const RunSpec& s, double timeout) {
#if DLAB_STUDY_BASELINES
  // No RLIMIT_CPU here: CGAL's timer (baselines_cgal.cpp) reads
  // CLOCK_PROCESS_CPUTIME_ID, which an armed process CPU limit makes
  // tick-granular (variants/driver.hpp); external tools have the baselines'
  // own wall-clock limit, CGAL the parent's (10 x timeout + 10 s).
  reset_peak_rss();
  BaselineRun b = run_baseline(s.tool, pts, BaselineOptions{timeout});
  if (b.skipped) return {{"skipped", b.message}};
  std::uint64_t rss = 0;
  if (s.tool.rfind("cgal-", 0) == 0) {
    rss = peak_rss();
  } else {
    rusage u{};
    if (getrusage(RUSAGE_CHILDREN, &u) == 0) rss = static_cast<std::uint64_t>(u.ru_maxrss) * 1024;
  }
  fuzz::limit_cpu_for_next(timeout);
  ValidationReport rep;
  rep.distinct_points = 0;
  classify_baseline(pts, b, &rep);
  nlohmann::json m;
  if (rep.points != 0) m["distinct_points"] = rep.distinct_points;
  m["simplices"] = b.simplices.size() / static_cast<std::size_t>(pts.dimension + 1);
  m["outcome"] = b.outcome;
  m["message"] = b.message;
  m["wall"] = b.wall_seconds;
  m["cpu"] = b.cpu_seconds;
  m["rss"] = rss;
  return m;
#else
  (void)pts;
  (void)s;
  (void)timeout;
  return {{"skipped", "the external baselines are not part of this build"}};
#endif
}

[[noreturn]] void child_main(const StudyConfig& c, const RunSpec& s, int fd) {
  fuzz::enter_child_limits(c.memory_limit_mib << 20);
  try {
    PointSet pts = load_input(c.inputs.at(s.input), s.n, s.seed, c.path);
    send(fd, {{"input_points", pts.size()}});
    // Test hook (tests/test_study.sh): the run with this id dies of SIGSEGV,
    // as an inexact kernel's run may, to check that it becomes outcome crash.
    if (const char* crash = std::getenv("DLAB_STUDY_CRASH_RUN"); crash && std::to_string(s.id) == crash)
      std::raise(SIGSEGV);
    send(fd, s.is_baseline() ? run_external(pts, s, c.timeout_seconds)
                             : run_dlab(std::move(pts), s, c.timeout_seconds));
  } catch (const std::bad_alloc&) {
    _exit(fuzz::kOutOfMemoryExit);
  } catch (const std::exception& e) {  // ConfigError, std::invalid_argument
    send(fd, {{"error", e.what()}});
    _exit(kInputErrorExit);
  }
  _exit(0);
}


Counters counters_from(const nlohmann::json& a) {
  Counters c;
  for (const auto& e : a) c.emplace_back(e.at(0).get<std::string>(), e.at(1).get<std::uint64_t>());
  return c;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", s);
  return buf;
}

}  // namespace

RunChild::RunChild(const StudyConfig& config, const RunSpec& spec) : id_(spec.id) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(nullptr);  // nothing buffered is written twice
  const pid_t pid = fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    // Only the write end stays open (as fd 3): a child holding a sibling's
    // read end would keep it from seeing end of file.
    if (fds[1] != 3 && dup2(fds[1], 3) < 0) _exit(1);
    if (close_range(4, ~0U, 0) != 0)
      for (int fd = 4; fd < 65536; ++fd) ::close(fd);
    child_main(config, spec, 3);
  }
  ::close(fds[1]);
  pid_ = pid;
  fd_ = fds[0];
  started_ = std::chrono::steady_clock::now();
}

RunChild::RunChild(RunChild&& o) noexcept { *this = std::move(o); }

RunChild& RunChild::operator=(RunChild&& o) noexcept {
  std::swap(pid_, o.pid_);
  std::swap(fd_, o.fd_);
  id_ = o.id_;
  buffer_ = std::move(o.buffer_);
  wall_killed_ = o.wall_killed_;
  started_ = o.started_;
  return *this;
}

RunChild::~RunChild() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    int status = 0;
    while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (fd_ >= 0) ::close(fd_);
}

bool RunChild::read() {
  char buf[1 << 16];
  ssize_t got;
  do {
    got = ::read(fd_, buf, sizeof buf);
  } while (got < 0 && errno == EINTR);
  if (got <= 0) return false;
  buffer_.append(buf, static_cast<std::size_t>(got));
  return true;
}

void RunChild::kill_for_wall_time() {
  if (pid_ > 0 && !wall_killed_) {
    ::kill(pid_, SIGKILL);
    wall_killed_ = true;
  }
}

RunChild::Result RunChild::finish(double timeout_seconds, std::uint64_t memory_limit_mib) {
  int status = 0;
  while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  // Complete lines only: a line cut by the child's death is not read.
  std::vector<nlohmann::json> lines;
  for (std::size_t start = 0, nl; (nl = buffer_.find('\n', start)) != std::string::npos; start = nl + 1)
    lines.push_back(nlohmann::json::parse(buffer_.substr(start, nl - start), nullptr, false));
  Result r;
  RunMeasure m;
  for (const auto& j : lines) {
    if (j.is_discarded()) throw std::runtime_error("run " + std::to_string(id_) + ": malformed line from its child");
    if (j.contains("error")) {
      r.error = j["error"].get<std::string>();
      return r;
    }
    if (j.contains("skipped")) {
      r.skipped = j["skipped"].get<std::string>();
      return r;
    }
    if (j.contains("input_points")) m.input_points = j["input_points"].get<std::uint64_t>();
    if (j.contains("outcome")) {
      if (j.contains("distinct_points")) m.distinct_points = j["distinct_points"].get<std::uint64_t>();
      m.simplices = j["simplices"].get<std::uint64_t>();
      m.outcome = j["outcome"].get<std::string>();
      m.message = j["message"].get<std::string>();
      m.wall_seconds = j["wall"].get<double>();
      m.cpu_seconds = j["cpu"].get<double>();
      m.peak_rss_bytes = j["rss"].get<std::uint64_t>();
      if (j.contains("pred")) m.predicates = counters_from(j["pred"]);
      if (j.contains("ctr")) m.counters = counters_from(j["ctr"]);
    }
  }
  if (WIFSIGNALED(status) && !wall_killed_)
    for (int sig : {SIGINT, SIGTERM, SIGHUP})
      if (WTERMSIG(status) == sig) {
        r.interrupted = signal_name(sig) ? signal_name(sig) : "SIGHUP";
        return r;
      }
  const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0 && !m.outcome.empty();
  if (!clean) {
    m.outcome = "crash";
    if (wall_killed_) {
      m.outcome = "timeout";
      m.message = "no result within the wall-clock limit; killed";
    } else if (WIFSIGNALED(status) && WTERMSIG(status) == SIGXCPU) {
      m.outcome = "timeout";
      m.message = "CPU-time limit of " + seconds_text(timeout_seconds) + " s reached";
    } else if (WIFSIGNALED(status)) {
      const char* name = signal_name(WTERMSIG(status));
      m.message = std::string("killed by ") + (name ? name : "signal " + std::to_string(WTERMSIG(status)));
    } else if (WIFEXITED(status) && WEXITSTATUS(status) == fuzz::kOutOfMemoryExit) {
      m.outcome = "out-of-memory";
      m.message = "an allocation failed under the memory limit of " + std::to_string(memory_limit_mib) + " MiB";
    } else {
      m.message = "the run's process ended with exit status " +
                  std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + " without a result";
    }
    m.distinct_points.reset();
    m.simplices.reset();
    m.wall_seconds.reset();
    m.cpu_seconds.reset();
    m.peak_rss_bytes.reset();
    m.predicates.clear();
    m.counters.clear();
  }
  r.measure = std::move(m);
  return r;
}

}  // namespace dlab::study
