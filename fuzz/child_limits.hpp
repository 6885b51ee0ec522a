// The limits a campaign's child process runs under (fuzz/isolation.hpp):
//   - no core files (RLIMIT_CORE 0);
//   - memory: RLIMIT_AS = the address space it starts with + the limit; a
//     failed allocation (operator new, GMP's allocator) ends the child at once
//     with exit status kOutOfMemoryExit, which the parent reads as out-of-memory;
//   - CPU time: before each case x pair, the soft RLIMIT_CPU is set to the CPU
//     time used so far + the limit (rounded up to whole seconds, as the kernel
//     counts), so the pair that spins gets SIGXCPU.
// Sanitizer builds reserve terabytes of shadow address space, so there the
// memory limit is not set (memory_limit_enforced() is false).
#pragma once
#include <cstdint>

namespace dlab::fuzz {

inline constexpr int kOutOfMemoryExit = 86;

bool memory_limit_enforced();

// Called once in the child, right after fork.
void enter_child_limits(std::uint64_t memory_bytes);

// Soft RLIMIT_CPU for the next case x pair.
void limit_cpu_for_next(double seconds);

}  // namespace dlab::fuzz
