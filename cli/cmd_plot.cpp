// `dlab plot STUDY_DIR [--out DIR]` (issue 13): runs studies/plot/dlab_plot.py,
// which reads STUDY_DIR/runs.csv and draws the figures with matplotlib. This file
// only finds the interpreter and the script and passes the exit status through.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"

#if !defined(DLAB_SOURCE_DIR) || !defined(DLAB_PLOT_FROM_BINDIR)
#error "DLAB_SOURCE_DIR and DLAB_PLOT_FROM_BINDIR (where the script is installed) must be defined"
#endif

namespace dlab::cli {
namespace {

const char* const kPlotDescription =
    "Draws the figures of a study (dlab study's STUDY_DIR/runs.csv, studies/README.md), each as\n"
    "SVG and PNG in DIR (default STUDY_DIR/plots), with matplotlib:\n"
    "  time_per_point    triangulation time per input point against n, log-log\n"
    "  predicate_calls   predicate calls per point against n\n"
    "  stage_shares      share of each predicate's calls answered by each stage, per generator\n"
    "  flips_per_point   flips of each type per point against n\n"
    "  cavity_sizes      mean and largest cavity (simplices) against n\n"
    "  outcomes          heatmap: algorithm x kernel (and baselines) x generator, runs not ok\n"
    "One panel per generator x dimension, one line per algorithm x kernel and per baseline\n"
    "tool; per-point figures use the ok runs (median over seeds and repeats). A figure whose\n"
    "columns are absent or empty is skipped with a notice. DIR/figures.json holds every\n"
    "plotted value. Reruns give identical files.\n"
    "Needs python3 with matplotlib and numpy (Debian: python3-matplotlib); /usr/bin/python3 is\n"
    "used when it exists. The script: $DLAB_PLOT_SCRIPT if set, else the copy installed beside\n"
    "this dlab (PREFIX/share/dlab/plot), else the source tree's studies/plot/dlab_plot.py.\n";
const char* const kPlotExamples =
    "  dlab study --default --out s1 && dlab plot s1\n"
    "  dlab plot s1 --out figures\n";

bool is_file(const std::string& path, bool executable) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
         (!executable || ::access(path.c_str(), X_OK) == 0);
}

// $DLAB_PLOT_SCRIPT; else the copy `cmake --install` puts beside this
// executable (PREFIX/bin/dlab -> PREFIX/share/dlab/plot/dlab_plot.py); else
// the source tree's.
std::string plot_script() {
  if (const char* env = std::getenv("DLAB_PLOT_SCRIPT"); env && *env) return env;
  std::string exe(4096, '\0');
  const ssize_t n = ::readlink("/proc/self/exe", exe.data(), exe.size() - 1);
  if (n > 0) {
    exe.resize(static_cast<std::size_t>(n));
    const std::string installed =
        (std::filesystem::path(exe).parent_path() / DLAB_PLOT_FROM_BINDIR).lexically_normal().string();
    if (is_file(installed, false)) return installed;
  }
  return std::string(DLAB_SOURCE_DIR) + "/studies/plot/dlab_plot.py";
}

}  // namespace

int cmd_plot(int argc, char** argv) {
  std::string study, out;
  CommandLine cl("plot", "usage: dlab plot STUDY_DIR [--out DIR]\n",
                 kPlotDescription + ("This dlab's script: " + plot_script() + "\n"), kPlotExamples,
                 "Exit status: the script's: 0 drawn, 2 bad usage or an unreadable runs.csv.\n");
  cl.app().add_option("STUDY_DIR", study, "a directory written by dlab study (its runs.csv)")->required();
  cl.app().add_option("--out", out, "where the figures go (default STUDY_DIR/plots)")->type_name("DIR");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  const std::string script = plot_script();
  if (!is_file(script, false)) {
    std::cerr << "dlab plot: " << script << ": no such file (set DLAB_PLOT_SCRIPT to "
              << "studies/plot/dlab_plot.py of the source tree)\n";
    return 2;
  }
  const std::string python = is_file("/usr/bin/python3", true) ? "/usr/bin/python3" : "python3";
  std::vector<std::string> args = {python, script, "--", study};
  if (!out.empty()) args.insert(args.end() - 2, {"--out", out});
  std::vector<char*> cargs;
  for (auto& s : args) cargs.push_back(s.data());
  cargs.push_back(nullptr);

  std::cout << std::flush;
  const pid_t pid = ::fork();
  if (pid < 0) {
    std::cerr << "dlab plot: fork: " << std::strerror(errno) << "\n";
    return 2;
  }
  if (pid == 0) {
    ::execvp(cargs[0], cargs.data());
    std::cerr << "dlab plot: cannot run " << python << ": " << std::strerror(errno)
              << " (dlab plot needs python3 with matplotlib: apt-get install python3-matplotlib)\n";
    ::_exit(2);
  }
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      std::cerr << "dlab plot: waitpid: " << std::strerror(errno) << "\n";
      return 2;
    }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  std::cerr << "dlab plot: " << python << " died of signal " << WTERMSIG(status) << "\n";
  return 1;
}

}  // namespace dlab::cli
