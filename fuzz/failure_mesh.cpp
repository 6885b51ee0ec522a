// See failure_mesh.hpp. The child sends its mesh down a pipe as raw values of
// this machine (the parent is the same binary): the point count and the
// coordinates, then the simplex index count and the indices.
#include "fuzz/failure_mesh.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <stdexcept>
#include <string>

#include "fuzz/child_io.hpp"
#include "fuzz/child_limits.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {
namespace {

template <class T>
void append(std::string& out, const T* data, std::uint64_t count) {
  out.append(reinterpret_cast<const char*>(&count), sizeof count);
  out.append(reinterpret_cast<const char*>(data), count * sizeof(T));
}

[[noreturn]] void run_in_child(int fd, const PointSet& points, const Pair& pair, std::uint64_t order_seed,
                               const Limits& limits) {
  enter_child_limits(limits.memory_bytes);
  limit_cpu_for_next(limits.cpu_seconds);
  RunResult r;
  try {
    r = dlab::run(points, pair.options(order_seed));
  } catch (...) {
    _exit(3);
  }
  if (r.outcome == RunResult::Outcome::failed) _exit(3);
  const PointSet& p = r.points.size() == points.size() ? r.points : points;
  std::string out;
  if (p.dimension == 2)
    append(out, p.p2.data()->data(), 2 * p.p2.size());
  else
    append(out, p.p3.data()->data(), 3 * p.p3.size());
  append(out, r.simplices.data(), r.simplices.size());
  write_all(fd, out);
  _exit(0);
}

// Reads one "count, values" block at `at`; false if the bytes run short.
template <class T>
bool take(const std::string& in, std::size_t& at, std::vector<T>& values) {
  std::uint64_t count = 0;
  if (in.size() - at < sizeof count) return false;
  std::memcpy(&count, in.data() + at, sizeof count);
  at += sizeof count;
  if (count > (in.size() - at) / sizeof(T)) return false;
  values.resize(count);
  std::memcpy(values.data(), in.data() + at, count * sizeof(T));
  at += count * sizeof(T);
  return true;
}

}  // namespace

std::optional<FailureMesh> failure_mesh(const PointSet& points, const Pair& pair, std::uint64_t order_seed,
                                        const Limits& limits) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]), close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    close(fds[0]);
    run_in_child(fds[1], points, pair, order_seed, limits);
  }
  close(fds[1]);
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(10 * limits.cpu_seconds + 10);
  std::string in;
  bool killed = false;
  for (;;) {
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, 250) > 0) {
      char buf[1 << 16];
      const ssize_t got = read(fds[0], buf, sizeof buf);
      if (got > 0) {
        in.append(buf, static_cast<std::size_t>(got));
        continue;
      }
      if (got == 0 || errno != EINTR) break;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      killed = true;
      break;
    }
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (killed || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return std::nullopt;
  FailureMesh mesh;
  mesh.points.dimension = points.dimension;
  std::vector<double> coords;
  std::size_t at = 0;
  if (!take(in, at, coords) || !take(in, at, mesh.simplices) || at != in.size()) return std::nullopt;
  const std::size_t d = static_cast<std::size_t>(points.dimension);
  if (coords.size() != d * points.size()) return std::nullopt;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (d == 2)
      mesh.points.p2.push_back({coords[2 * i], coords[2 * i + 1]});
    else
      mesh.points.p3.push_back({coords[3 * i], coords[3 * i + 1], coords[3 * i + 2]});
  }
  return mesh;
}

}  // namespace dlab::fuzz
