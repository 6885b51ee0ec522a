// The runs of a study, numbered from 0 in the order of studies/README.md
// ("Matrix order and run ids"): input (a generator input n-major, then seed)
// x repeat x algorithm x kernel x order x policy x location, then the
// baselines of that input x repeat. The id is the row's `run` column.
//
// Choices that keep every run distinct (README): the policy `default`
// resolves to sos for an exact kernel and strict for an inexact one, and a
// policy that resolves to one already listed for that kernel is not run
// twice; an algorithm whose point location cannot be chosen (location_is_selectable)
// runs once per order x policy with location "-", whatever `locations` lists;
// cgal-epeck runs only on inputs with n <= epeck_max_n.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "studies/config.hpp"
#include "variants/run.hpp"

namespace dlab::study {

struct RunSpec {
  std::uint64_t id = 0;
  std::size_t input = 0;     // index into config.inputs
  std::uint64_t n = 0;       // generator inputs: the n asked for; file inputs: the point count
  std::uint64_t seed = 0;
  std::uint32_t repeat = 0;  // 0-based
  std::string tool = "dlab";  // "dlab" or a baseline name
  std::string algorithm;     // pair name ("george+exact-sphere"); baselines: the tool name
  std::string kernel = "-", order = "-", policy = "-", location = "-";

  bool is_baseline() const { return tool != "dlab"; }
  // What dlab::run() gets (dlab runs only).
  RunOptions options() const;
  // The pair promises a valid Delaunay result (variants/outcome.hpp).
  bool exact_pair() const;
};

// bowyer-watson and lawson (RunOptions::location); the others have one
// location scheme of their own (george walks, tanemura does not locate).
bool location_is_selectable(const std::string& algorithm);

// Every run of the study, in id order (the config's inputs must be checked:
// check_inputs gives file inputs their n).
std::vector<RunSpec> expand_matrix(const StudyConfig& config);

// "k/n" -> shard k of n (1 <= k <= n); throws ConfigError.
struct Shard {
  std::uint64_t k = 1, n = 1;
  bool has(std::uint64_t id) const { return id % n == k - 1; }
};
Shard parse_shard(const std::string& text);

}  // namespace dlab::study
