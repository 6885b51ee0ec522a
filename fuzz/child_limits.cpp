// See child_limits.hpp.
#include "fuzz/child_limits.hpp"

#include <gmp.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace dlab::fuzz {
namespace {

[[noreturn]] void out_of_memory() { _exit(kOutOfMemoryExit); }

void* gmp_alloc(std::size_t n) {
  void* p = std::malloc(n);
  if (p == nullptr) out_of_memory();
  return p;
}
void* gmp_realloc(void* old, std::size_t, std::size_t n) {
  void* p = std::realloc(old, n);
  if (p == nullptr) out_of_memory();
  return p;
}
void gmp_free(void* p, std::size_t) { std::free(p); }

// The current address-space size (first field of /proc/self/statm, in pages).
std::uint64_t address_space_bytes() {
  std::FILE* f = std::fopen("/proc/self/statm", "r");
  unsigned long long pages = 0;
  if (f != nullptr) {
    if (std::fscanf(f, "%llu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

}  // namespace

bool memory_limit_enforced() {
#if defined(__SANITIZE_ADDRESS__)
  return false;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  return false;
#else
  return true;
#endif
#else
  return true;
#endif
}

void enter_child_limits(std::uint64_t memory_bytes) {
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  std::set_new_handler(&out_of_memory);
  mp_set_memory_functions(&gmp_alloc, &gmp_realloc, &gmp_free);
  if (memory_limit_enforced()) {
    const rlim_t as = address_space_bytes() + memory_bytes;
    rlimit r{};
    getrlimit(RLIMIT_AS, &r);
    if (r.rlim_max == RLIM_INFINITY || as < r.rlim_max) r.rlim_cur = as;
    setrlimit(RLIMIT_AS, &r);
  }
}

void limit_cpu_for_next(double seconds) {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  const double used = static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                      1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  rlimit r{};
  getrlimit(RLIMIT_CPU, &r);
  const rlim_t soft = static_cast<rlim_t>(std::ceil(used + seconds));
  if (r.rlim_max == RLIM_INFINITY || soft < r.rlim_max) r.rlim_cur = soft;
  setrlimit(RLIMIT_CPU, &r);
}

}  // namespace dlab::fuzz
