// See campaign_spec.hpp.
#include "fuzz/campaign_spec.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "fuzz/generators.hpp"
#include "variants/outcome.hpp"

namespace dlab::fuzz {
namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// A decimal integer that fits in 0..max, or nothing.
bool parse_count(const std::string& s, std::uint64_t max, std::uint64_t& out) {
  if (s.empty() || s.size() > 19) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (v > max) return false;
  out = v;
  return true;
}

// The generators of `names` in dimension `dim`, one of the aliases cocircular / cospherical.
std::vector<std::string> of_dimension(const std::vector<std::string>& names, int dim) {
  std::vector<std::string> out;
  for (const auto& g : names) {
    if ((dim == 2 && g == "cospherical") || (dim == 3 && g == "cocircular")) continue;
    if (gen::generator_has_dimension(g, dim)) out.push_back(g);
  }
  return out;
}

}  // namespace

std::string Pair::algo_name() const {
  std::string s = algorithm;
  if (exact_sphere) s += "+exact-sphere";
  if (enclosing_box) s += "+enclosing-box";
  return s;
}

RunOptions Pair::options(std::uint64_t order_seed) const {
  RunOptions o;
  o.algorithm = algorithm;
  o.kernel = kernel;
  o.policy = !policy.empty() ? policy : kernel_is_exact(kernel) && !unperturbed ? "sos" : "strict";
  o.order = order;
  o.seed = order_seed;
  o.exact_sphere = exact_sphere;
  o.enclosing_box = enclosing_box;
  return o;
}

bool Pair::exact() const { return pair_is_exact(options(0)); }

Pair make_pair(const std::string& algo_name, const std::string& kernel) {
  Pair p;
  std::string rest = algo_name;
  for (auto [suffix, flag] : {std::pair{"+exact-sphere", &p.exact_sphere}, {"+enclosing-box", &p.enclosing_box}})
    if (auto at = rest.find(suffix); at != std::string::npos) {
      *flag = true;
      rest.erase(at, std::string(suffix).size());
    }
  p.algorithm = rest;
  p.kernel = kernel;
  if (!contains(algorithm_names(), p.algorithm) || ((p.exact_sphere || p.enclosing_box) && rest != "george"))
    throw UsageError("--algo: unknown algorithm '" + algo_name + "' (known: " + join(algorithm_names()) +
                     ", george+exact-sphere, george+enclosing-box)");
  if (!contains(kernel_names(), kernel))
    throw UsageError("--kernel: unknown kernel '" + kernel + "' (known: " + join(kernel_names()) + ")");
  return p;
}

std::vector<Pair> CampaignSpec::pairs() const {
  std::vector<Pair> out;
  for (const auto& a : algorithms)
    for (const auto& k : kernels) out.push_back(make_pair(a, k));
  return out;
}

std::uint64_t CampaignSpec::cases_in_shard(std::uint64_t total) const {
  return total / shards + (total % shards >= shard ? 1 : 0);
}

std::vector<std::string> parse_list(const std::string& option, const std::string& value) {
  std::vector<std::string> out(1);
  for (char c : value)
    if (c == ',')
      out.emplace_back();
    else
      out.back() += c;
  for (const auto& x : out)
    if (x.empty()) throw UsageError(option + ": empty name in '" + value + "'");
  for (std::size_t i = 0; i < out.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (out[i] == out[j]) throw UsageError(option + ": '" + out[i] + "' is listed twice");
  return out;
}

void parse_n_range(const std::string& value, std::uint64_t& lo, std::uint64_t& hi) {
  constexpr std::uint64_t kMax = std::uint64_t{1} << 24;
  const auto dots = value.find("..");
  const std::string a = value.substr(0, dots);
  const std::string b = dots == std::string::npos ? a : value.substr(dots + 2);
  if (!parse_count(a, kMax, lo) || !parse_count(b, kMax, hi) || lo < 1)
    throw UsageError("--n: '" + value + "' is not N or LO..HI with integers in 1.." + std::to_string(kMax));
  if (lo > hi) throw UsageError("--n: empty range '" + value + "' (LO must be at most HI)");
}

void parse_shard(const std::string& value, std::uint64_t& k, std::uint64_t& n) {
  const auto slash = value.find('/');
  if (slash == std::string::npos || !parse_count(value.substr(0, slash), UINT32_MAX, k) ||
      !parse_count(value.substr(slash + 1), UINT32_MAX, n))
    throw UsageError("--shard: '" + value + "' is not k/n");
  if (n < 1 || k < 1 || k > n)
    throw UsageError("--shard: '" + value + "' must have 1 <= k <= n (shards are numbered from 1)");
}

double parse_duration(const std::string& option, const std::string& value) {
  double unit = 1;
  std::string digits = value;
  if (!digits.empty() && (digits.back() == 's' || digits.back() == 'm' || digits.back() == 'h')) {
    unit = digits.back() == 'h' ? 3600 : digits.back() == 'm' ? 60 : 1;
    digits.pop_back();
  }
  std::uint64_t v = 0;
  if (!parse_count(digits, std::uint64_t{1} << 32, v) || v == 0)
    throw UsageError(option + ": '" + value + "' is not a positive duration such as 90, 90s, 15m or 2h");
  return static_cast<double>(v) * unit;
}

std::vector<std::string> default_mix(int dim) { return of_dimension(gen::generator_names(), dim); }

void check_and_expand(CampaignSpec& spec) {
  if (spec.dim != 2 && spec.dim != 3) throw UsageError("--dim must be 2 or 3");
  if (spec.algorithms.empty() || spec.kernels.empty() || spec.generators.empty())
    throw UsageError("--algo, --kernel and --gen each need at least one name");
  spec.pairs();  // throws for an unknown name
  std::vector<std::string> gens;
  for (const auto& g : spec.generators) {
    if (g == "mix" || g == "degenerate") {
      for (const auto& m : g == "mix" ? default_mix(spec.dim) : of_dimension(gen::degenerate_generator_names(), spec.dim))
        if (!contains(gens, m)) gens.push_back(m);
      continue;
    }
    if (!contains(gen::generator_names(), g))
      throw UsageError("--gen: unknown generator '" + g + "' (known: mix, degenerate, " + join(gen::generator_names()) +
                       ")");
    if (!gen::generator_has_dimension(g, spec.dim))
      throw UsageError("--gen: generator '" + g + "' does not exist in " + std::to_string(spec.dim) + "D");
    if (!contains(gens, g)) gens.push_back(g);
  }
  spec.generators = gens;
}

}  // namespace dlab::fuzz
