// Child processes and private temporary directories for the external
// baselines (studies/baselines.hpp): run a program with its standard streams
// redirected to files, kill it (its whole process group) at a wall-clock limit.
#pragma once
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace dlab::baselines {

// A directory of its own under $TMPDIR (or /tmp), removed with its contents
// when the object goes.
class TempDir {
 public:
  TempDir();  // throws std::runtime_error when it cannot be created
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

struct ProcessResult {
  bool started = false;    // false: exec failed (message in `error`)
  bool timed_out = false;  // killed at the limit
  int exit_status = -1;    // when it exited normally
  int signal = 0;          // when a signal ended it (SIGKILL after a timeout)
  std::string error;
};

// Runs argv[0] (a path, or a name searched in PATH) with argv in `cwd`,
// standard input from `stdin_file` (or /dev/null), output and error to the
// given files. Kills the child's process group after `timeout_seconds`.
ProcessResult run_process(const std::vector<std::string>& argv, const std::filesystem::path& cwd,
                          const std::optional<std::filesystem::path>& stdin_file,
                          const std::filesystem::path& stdout_file,
                          const std::filesystem::path& stderr_file, double timeout_seconds);

// "killed by SIGSEGV", "exit status 3", "timed out after 60 s", "could not start: ...".
std::string describe(const ProcessResult& r, double timeout_seconds);

// The executable `name` resolves to: itself if it contains a '/', else the
// first executable file of that name in PATH; nullopt if none.
std::optional<std::filesystem::path> find_executable(const std::string& name);

// The whole content of a file ("" if it cannot be read).
std::string read_text(const std::filesystem::path& file);

}  // namespace dlab::baselines
