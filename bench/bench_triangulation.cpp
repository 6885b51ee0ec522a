// dlab against CGAL on the same points in the same run (issue 3).
// For each point set: CGAL Delaunay_triangulation_2/3 (Epick, range insertion
// with CGAL's spatial sort) and dlab::run() for each requested kernel; prints
// seconds, the ratio dlab/CGAL, and peak memory per point; also the CPU time
// over the same span as the seconds, and its ratio (steadier than wall time on
// a shared, loaded machine). The span: for CGAL, copying the points and the
// construction; for dlab, RunResult::seconds (the insertion order, the run and
// the output's indices, not a check after it such as George's validation).
// Each measurement runs in a forked child so its peak resident size is its own.
//
// usage: dlab_bench_triangulation [--dim 2|3] [--n N] [--set uniform|grid]
//                                 [--kernels adaptive,mp,...] [--algo A] [--repeat R]
//                                 [--order brio|hilbert|random|input] [--cgal 0|1] [--stats 0|1]
// --cgal 0 skips CGAL (for profiling dlab alone, e.g. under callgrind); --stats 1
// prints dlab's algorithm and predicate counters (calls per predicate and stage).
// Exit status: 2 for a bad option (checked before any timing, the names by a
// run on the first 8 points), 1 if a timed dlab run failed, else 0.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "variants/run.hpp"
#include "bench/bench_points.hpp"

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Measure {
  double seconds = 0;
  double cpu = 0;         // CPU seconds over the span of `seconds` (less sensitive to a loaded machine)
  double bytes = 0;       // resident growth during the run (peak - before)
  double simplices = 0;
  bool ok = true;
};

long resident_kib(const char* key) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(key, 0) == 0) return std::strtol(line.c_str() + std::strlen(key), nullptr, 10);
  return 0;
}

// Runs `job` in a child process; the child reports seconds, memory growth and
// simplex count through a pipe.
template <class Job>
Measure in_child(Job job) {
  std::fflush(stdout);  // else the child would print the parent's buffered lines again
  int fd[2];
  if (pipe(fd) != 0) std::abort();
  const pid_t pid = fork();
  if (pid == 0) {
    close(fd[0]);
    const long before = resident_kib("VmRSS:");
    Measure m = job();
    m.bytes = double(resident_kib("VmHWM:") - before) * 1024.0;
    if (write(fd[1], &m, sizeof m) != sizeof m) _exit(3);
    _exit(0);
  }
  close(fd[1]);
  Measure m;
  const bool got = read(fd[0], &m, sizeof m) == sizeof m;
  close(fd[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (!got) m.ok = false;
  return m;
}

template <class Clock = std::chrono::steady_clock>
double since(typename Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// CPU seconds of the calling thread (as variants/driver.hpp times dlab::run).
double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

Measure cgal_run(const dlab::PointSet& ps) {
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = thread_cpu_seconds();
  Measure m;
  if (ps.dimension == 2) {
    std::vector<Epick::Point_2> pts;
    pts.reserve(ps.p2.size());
    for (const auto& p : ps.p2) pts.emplace_back(p[0], p[1]);
    CGAL::Delaunay_triangulation_2<Epick> dt(pts.begin(), pts.end());
    m.seconds = since(t0);
    m.cpu = thread_cpu_seconds() - cpu0;
    m.simplices = double(dt.number_of_faces());
  } else {
    std::vector<Epick::Point_3> pts;
    pts.reserve(ps.p3.size());
    for (const auto& p : ps.p3) pts.emplace_back(p[0], p[1], p[2]);
    CGAL::Delaunay_triangulation_3<Epick> dt(pts.begin(), pts.end());
    m.seconds = since(t0);
    m.cpu = thread_cpu_seconds() - cpu0;
    m.simplices = double(dt.number_of_finite_cells());
  }
  return m;
}

Measure dlab_run(const dlab::PointSet& ps, const dlab::RunOptions& opt, bool stats) {
  Measure m;
  const dlab::RunResult r = dlab::run(ps, opt);
  if (stats) {
    for (const auto& [key, value] : r.counters)
      std::printf("  %-34s %14llu\n", key.c_str(), (unsigned long long)value);
    for (const auto& [key, value] : r.predicates)
      if (value != 0) std::printf("  %-34s %14llu\n", key.c_str(), (unsigned long long)value);
    std::fflush(stdout);
  }
  m.seconds = r.seconds;
  m.cpu = r.cpu_seconds;
  m.simplices = double(r.simplices.size() / std::size_t(ps.dimension + 1));
  m.ok = r.outcome == dlab::RunResult::Outcome::ok;
  return m;
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int dim = 2;
  std::size_t n = 100000;
  std::string set = "uniform", algo = "bowyer-watson", kernels = "adaptive";
  int repeat = 1;
  std::string order = "brio";
  bool with_cgal = true, stats = false;
  // A whole number in [lo, hi], or 0 after an error message (exit 2).
  auto whole_number = [](const std::string& key, const std::string& value, unsigned long long lo,
                  unsigned long long hi) -> unsigned long long {
    char* end = nullptr;
    const unsigned long long v = std::strtoull(value.c_str(), &end, 10);
    if (value.empty() || value[0] == '-' || *end != '\0' || v < lo || v > hi) {
      std::fprintf(stderr, "%s needs a whole number from %llu to %llu, not '%s'\n", key.c_str(), lo, hi,
                   value.c_str());
      return 0;
    }
    return v;
  };
  if (argc % 2 == 0) {
    std::fprintf(stderr, "option %s has no value\n", argv[argc - 1]);
    return 2;
  }
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--dim") {
      if ((dim = static_cast<int>(whole_number(key, value, 2, 3))) == 0) return 2;
    } else if (key == "--n") {
      if ((n = whole_number(key, value, 1, 1ull << 32)) == 0) return 2;
    } else if (key == "--repeat") {
      if ((repeat = static_cast<int>(whole_number(key, value, 1, 1000))) == 0) return 2;
    } else if (key == "--set") {
      set = value;
    } else if (key == "--algo") {
      algo = value;
    } else if (key == "--kernels") {
      kernels = value;
    } else if (key == "--order") {
      order = value;
    } else if (key == "--cgal") {
      with_cgal = value != "0";
    } else if (key == "--stats") {
      stats = value != "0";
    } else {
      std::fprintf(stderr, "unknown option %s\n", key.c_str());
      return 2;
    }
  }
  auto options = [&](const std::string& kernel) {
    dlab::RunOptions opt;
    opt.algorithm = algo;
    opt.kernel = kernel;
    opt.order = order;
    return opt;
  };
  dlab::PointSet ps;
  try {  // a bad set, algorithm, kernel or order: a message and exit 2, before any timing
    ps = dlab::bench::make_points(set, dim, n);
    dlab::PointSet few{ps.dimension, {}, {}};
    if (dim == 2)
      few.p2.assign(ps.p2.begin(), ps.p2.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(n, 8)));
    else
      few.p3.assign(ps.p3.begin(), ps.p3.begin() + static_cast<std::ptrdiff_t>(std::min<std::size_t>(n, 8)));
    for (const std::string& kernel : split_commas(kernels)) dlab::run(few, options(kernel));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  std::printf("# %dD %s, %zu points, %s; best of %d\n", dim, set.c_str(), ps.size(), algo.c_str(),
              repeat);
  std::printf("%-22s %10s %10s %12s %12s %10s %10s\n", "run", "seconds", "ratio", "bytes/point",
              "simplices", "cpu_s", "cpu_ratio");

  auto best = [&](auto job) {
    Measure b;
    for (int r = 0; r < repeat; ++r) {
      Measure m = in_child(job);
      if (r == 0 || m.seconds < b.seconds) b = m;
    }
    return b;
  };
  Measure cgal;
  cgal.seconds = 1;
  if (with_cgal) cgal = best([&] { return cgal_run(ps); });
  if (with_cgal)
    std::printf("%-22s %10.3f %10.2f %12.0f %12.0f %10.3f %10.2f\n", "cgal-epick", cgal.seconds, 1.0,
                cgal.bytes / double(ps.size()), cgal.simplices, cgal.cpu, 1.0);
  else
    cgal.cpu = 1;
  bool failed = false;
  for (const std::string& kernel : split_commas(kernels)) {
    const dlab::RunOptions opt = options(kernel);
    const Measure m = best([&] { return dlab_run(ps, opt, stats); });
    std::printf("%-22s %10.3f %10.2f %12.0f %12.0f %10.3f %10.2f%s\n", ("dlab-" + kernel).c_str(),
                m.seconds, m.seconds / cgal.seconds, m.bytes / double(ps.size()), m.simplices, m.cpu,
                m.cpu / cgal.cpu, m.ok ? "" : "  (failed)");
    failed |= !m.ok;
  }
  return failed ? 1 : 0;
}
