// A small command-line parser for the subcommands: positional arguments,
// options with a value ("--seed 7" or "--seed=7", "-o FILE") and flags.
// Everything it rejects is a dlab::UsageError (exit status 2).
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "variants/run.hpp"

namespace dlab::cli {

struct Args {
  std::vector<std::string> positional;
  std::map<std::string, std::string> values;  // option -> value
  std::set<std::string> flags;

  std::optional<std::string> get(const std::string& opt) const;
  bool has(const std::string& flag) const { return flags.count(flag) != 0; }
  // Typed accessors: UsageError "--seed: 'x' is not a ..." on a bad value.
  std::uint64_t u64(const std::string& opt, std::uint64_t fallback, std::uint64_t max = UINT64_MAX) const;
  std::int64_t i64(const std::string& opt, std::int64_t fallback, std::int64_t lo, std::int64_t hi) const;
  double real(const std::string& opt, double fallback) const;  // finite
};

// argv[first..argc) of one subcommand. A lone "-" and numbers such as "-1.5"
// are positional.
Args parse_args(int argc, char** argv, int first, const std::set<std::string>& with_value,
                const std::set<std::string>& flag_names);

}  // namespace dlab::cli
