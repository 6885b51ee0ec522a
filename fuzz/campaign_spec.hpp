// What defines a fuzzing campaign (`dlab fuzz`, issue 12): the algorithm x
// kernel pairs, the generators, the dimension, the range of n, the seed and the
// shard. Two runs with the same spec run the same cases and write the same
// records; DIR/campaign.json stores it so that a resumed or merged campaign can
// check that it continues the same one.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "variants/run.hpp"

namespace dlab::fuzz {

// One algorithm x kernel pair. George's variants are algorithm names of their
// own here: "george+exact-sphere", "george+enclosing-box" (`dlab triangulate
// --algo george --exact-sphere`, ...).
struct Pair {
  std::string algorithm;  // as in RunOptions (bowyer-watson, lawson, tanemura, george)
  std::string kernel;
  bool exact_sphere = false;
  bool enclosing_box = false;
  bool unperturbed = false;  // test only (fuzz/selftest.hpp): the strict policy even for an exact kernel
  // `dlab shrink --policy / --order` (a campaign keeps the defaults): empty
  // policy: dlab triangulate's default for the kernel.
  std::string policy;
  std::string order = "brio";

  std::string algo_name() const;  // "bowyer-watson", "george+exact-sphere", ...
  // dlab triangulate's defaults: sos for exact kernels, strict for the others; brio order.
  RunOptions options(std::uint64_t order_seed) const;
  // The pair promises a valid Delaunay triangulation identical to the
  // perturbed reference (variants/outcome.hpp's pair_is_exact).
  bool exact() const;
};

// "george+exact-sphere" -> algorithm george, exact_sphere; throws UsageError
// for an unknown algorithm or kernel.
Pair make_pair(const std::string& algo_name, const std::string& kernel);

struct CampaignSpec {
  std::vector<std::string> algorithms;  // algo names as given (see Pair)
  std::vector<std::string> kernels;
  std::vector<std::string> generators;  // dlab gen names
  int dim = 2;
  std::uint64_t n_lo = 20, n_hi = 20;
  std::uint64_t seed = 0;
  std::uint64_t shard = 1, shards = 1;  // this is shard `shard` of `shards` (1-based)
  std::string selftest;                 // DLAB_FUZZ_SELFTEST (test only; fuzz/selftest.hpp)

  // Algorithm-major: for each algorithm, each kernel.
  std::vector<Pair> pairs() const;
  // Case i belongs to shard 1 + i mod shards; the j-th case (from 0) of this shard.
  std::uint64_t case_index(std::uint64_t j) const { return j * shards + (shard - 1); }
  // How many of the cases 0..total-1 belong to this shard.
  std::uint64_t cases_in_shard(std::uint64_t total) const;
};

// Parsers for the command line; each throws UsageError naming the option.
std::vector<std::string> parse_list(const std::string& option, const std::string& value);
// "N" or "LO..HI" with 1 <= LO <= HI <= 2^24.
void parse_n_range(const std::string& value, std::uint64_t& lo, std::uint64_t& hi);
// "k/n" with 1 <= k <= n.
void parse_shard(const std::string& value, std::uint64_t& k, std::uint64_t& n);
// "90", "90s", "15m", "2h" -> seconds (> 0).
double parse_duration(const std::string& option, const std::string& value);
// Checks every name of the spec: algorithms, kernels, generators (each must
// exist in spec.dim; "mix" expands to every generator of the dimension,
// "degenerate" to gen::degenerate_generator_names() of the dimension).
void check_and_expand(CampaignSpec& spec);
// The generators of the default mix in dimension `dim`.
std::vector<std::string> default_mix(int dim);

}  // namespace dlab::fuzz
