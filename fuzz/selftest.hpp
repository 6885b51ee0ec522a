// Deliberate misbehaviour, for the tests of isolation only: with
//   DLAB_FUZZ_SELFTEST=ACTION@CASE:[ALGO/]KERNEL[,ACTION@CASE:[ALGO/]KERNEL...]
// in the environment, the child process that runs case CASE with a pair of
// kernel KERNEL (and algorithm ALGO, a Pair::algo_name(), if given) does
// ACTION instead of running it:
//   crash     std::abort() (SIGABRT)
//   hang      spins until its CPU-time limit stops it
//   allocate  allocates 64 MiB blocks (touched) until its memory limit stops it
//   unperturbed  runs the pair with the strict policy: an exact kernel then
//             returns *a* Delaunay triangulation, on cocircular input not the
//             perturbed one -- `differs`, a simulated bug that only the
//             reference comparison (fuzz/reference.hpp) can see
// Guard: nothing else reads this variable; a campaign started with it says so
// on stderr and stores it in DIR/campaign.json (so it cannot be resumed or
// merged with a campaign without it), and `allocate` is refused where the
// memory limit is not enforced (sanitizer builds), so it can never exhaust the
// machine.
#pragma once
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "fuzz/campaign_spec.hpp"

namespace dlab::fuzz {

struct Misbehaviour {
  std::string action;  // crash | hang | allocate | unperturbed
  std::uint64_t case_index = 0;
  std::string algo;  // empty: every algorithm
  std::string kernel;
};

inline constexpr const char* kSelftestVariable = "DLAB_FUZZ_SELFTEST";

// Throws UsageError for a malformed spec.
std::vector<Misbehaviour> parse_selftest(std::string_view spec);

// Does the action of `m` if one matches (case, pair); returns otherwise.
void maybe_misbehave(const std::vector<Misbehaviour>& m, std::uint64_t case_index, const Pair& pair);

// True if an `unperturbed` action matches (case, pair); the child then runs
// unperturbed(pair) instead of the pair.
bool runs_unperturbed(const std::vector<Misbehaviour>& m, std::uint64_t case_index, const Pair& pair);
Pair unperturbed(const Pair& p);

}  // namespace dlab::fuzz
