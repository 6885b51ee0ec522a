#include "studies/baselines_process.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace dlab::baselines {

TempDir::TempDir() {
  const char* base = std::getenv("TMPDIR");
  std::string templ = std::string(base && *base ? base : "/tmp") + "/dlab-baseline-XXXXXX";
  if (!mkdtemp(templ.data()))
    throw std::runtime_error("cannot create a temporary directory " + templ + ": " + std::strerror(errno));
  path_ = templ;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::optional<std::filesystem::path> find_executable(const std::string& name) {
  if (name.empty()) return std::nullopt;
  const auto executable = [](const std::filesystem::path& p) {
    struct stat st{};
    return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
  };
  if (name.find('/') != std::string::npos) {
    if (executable(name)) return std::filesystem::path(name);
    return std::nullopt;
  }
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    const auto candidate = std::filesystem::path(dir.empty() ? "." : dir) / name;
    if (executable(candidate)) return candidate;
  }
  return std::nullopt;
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

namespace {

// posix_spawn file actions that fail cleanly: the child exits 127 if a file
// cannot be opened (reported as "exit status 127").
struct Actions {
  posix_spawn_file_actions_t a{};
  Actions() { posix_spawn_file_actions_init(&a); }
  ~Actions() { posix_spawn_file_actions_destroy(&a); }
};
struct Attributes {
  posix_spawnattr_t a{};
  Attributes() { posix_spawnattr_init(&a); }
  ~Attributes() { posix_spawnattr_destroy(&a); }
};

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                          const std::optional<std::filesystem::path>& stdin_file,
                          const std::filesystem::path& stdout_file,
                          const std::filesystem::path& stderr_file, double timeout_seconds) {
  ProcessResult r;
  const auto program = find_executable(argv.at(0));
  if (!program) {
    r.error = argv[0] + ": not found";
    return r;
  }
  // Absolute paths: the child changes directory before it opens them.
  const auto abs = [](const std::filesystem::path& p) { return std::filesystem::absolute(p).string(); };
  const std::string in = stdin_file ? abs(*stdin_file) : std::string("/dev/null");
  const std::string out = abs(stdout_file), err = abs(stderr_file), exe = abs(*program);
  Actions actions;
  posix_spawn_file_actions_addchdir_np(&actions.a, cwd.c_str());
  posix_spawn_file_actions_addopen(&actions.a, 0, in.c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions.a, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions.a, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  Attributes attributes;
  // Its own process group, so that a timeout kills whatever it started too;
  // default signal handling, whatever the caller ignores.
  sigset_t all;
  sigfillset(&all);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setpgroup(&attributes.a, 0);
  posix_spawnattr_setsigdefault(&attributes.a, &all);
  posix_spawnattr_setsigmask(&attributes.a, &none);
  posix_spawnattr_setflags(&attributes.a,
                           POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t pid = 0;
  if (const int e = posix_spawn(&pid, exe.c_str(), &actions.a, &attributes.a, args.data(), environ)) {
    r.error = exe + ": " + std::strerror(e);
    return r;
  }
  r.started = true;
  // Poll: at most 10 ms late, and no signal handler shared with the caller.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_seconds);
  auto pause = std::chrono::microseconds(200);
  for (;;) {
    // WNOWAIT: the exited child stays a zombie, so its pid -- the group's id --
    // cannot be reused before the group is killed below.
    siginfo_t info{};
    const int w = waitid(P_PID, static_cast<id_t>(pid), &info, WEXITED | WNOHANG | WNOWAIT);
    if (w == 0 && info.si_pid == pid) break;
    if (w < 0 && errno != EINTR) {
      r.error = std::string("waitid: ") + std::strerror(errno);
      break;
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      r.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::microseconds(10000));
  }
  // The child (on a timeout) and anything it left running in its group.
  ::kill(-pid, SIGKILL);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) r.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

std::string describe(const ProcessResult& r, double timeout_seconds) {
  std::ostringstream s;
  if (!r.started)
    s << "could not start: " << r.error;
  else if (r.timed_out)
    s << "timed out after " << timeout_seconds << " s";
  else if (r.signal)
    s << "killed by " << (sigabbrev_np(r.signal) ? std::string("SIG") + sigabbrev_np(r.signal)
                                                 : "signal " + std::to_string(r.signal));
  else if (!r.error.empty())
    s << r.error;
  else
    s << "exit status " << r.exit_status;
  return s.str();
}

}  // namespace dlab::baselines
