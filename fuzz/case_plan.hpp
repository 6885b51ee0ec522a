// Case i of a campaign, derived from the campaign seed and i alone, so that any
// case can be re-run by itself, byte for byte (`dlab fuzz ... --case i`, or the
// `dlab gen ... | dlab triangulate ...` command that replay_command prints).
//
// The case seed is the (i+1)-th output of splitmix64 seeded with the campaign
// seed S (Steele, Lea, Flood, OOPSLA 2014), computed directly:
//   case_seed(S, i) = mix(S + (i + 1) * 0x9e3779b97f4a7c15)   (mod 2^64)
// with mix splitmix64's output function. A splitmix64 stream seeded with the
// case seed then draws, in this order: the generator (uniform among the
// campaign's), n (uniform in LO..HI), the generator's --seed, the insertion
// order's --seed, and the generator's own options (plan_case below).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/generators.hpp"

namespace dlab::fuzz {

std::uint64_t case_seed(std::uint64_t campaign_seed, std::uint64_t i);

struct CasePlan {
  std::uint64_t index = 0;
  std::uint64_t seed = 0;        // case_seed(campaign seed, index)
  gen::GenOptions gen;           // name, dim, n, seed and the drawn options
  std::uint64_t order_seed = 0;  // RunOptions::seed (brio order)
};

CasePlan plan_case(const CampaignSpec& spec, std::uint64_t i);

// The `dlab gen` options beyond NAME --dim --n --seed that the case uses
// ("--base lattice --ulps 3"); empty when none.
std::string gen_extra_args(const gen::GenOptions& g);
// "dlab gen NAME --dim D --n N --seed G [extra]".
std::string gen_command(const gen::GenOptions& g);
// gen_command | dlab triangulate - --algo ... --kernel ... --seed O --validate
std::string replay_command(const CasePlan& c, const Pair& p);
// The options of dlab triangulate that run the pair as the campaign (or
// dlab shrink) does: " --algo A [--exact-sphere] [--enclosing-box] --kernel K
// [--policy P] [--order O] --seed S --validate" (S: order_seed).
std::string triangulate_options(const Pair& p, std::uint64_t order_seed);

}  // namespace dlab::fuzz
