// See case_plan.hpp.
#include "fuzz/case_plan.hpp"

#include <cmath>

namespace dlab::fuzz {
namespace {

// Exact degenerate sets that near-degenerate may perturb, per dimension.
const std::vector<std::string>& near_degenerate_bases(int dim) {
  static const std::vector<std::string> b2 = {"cocircular", "collinear", "lattice", "rotated-lattice",
                                              "kettner-grid"};
  static const std::vector<std::string> b3 = {"cospherical", "collinear", "coplanar", "lattice",
                                              "rotated-lattice"};
  return dim == 2 ? b2 : b3;
}

// Kettner's grid has side^2 + 2 points: the largest side with at most n points (>= 1).
std::size_t kettner_side(std::uint64_t n) {
  std::size_t s = 1;
  while ((s + 1) * (s + 1) + 2 <= n && s < 4096) ++s;
  return s;
}

// The generator's own options, drawn from `r` (the order is part of the contract).
void draw_options(gen::GenOptions& g, gen::SplitMix64& r) {
  const std::string& name = g.name;
  if (name == "clustered") {
    g.clusters = 1 + r.below(8);
  } else if (name == "collinear" || name == "coplanar") {
    g.off = r.below(4);
  } else if (name == "near-degenerate") {
    const auto& bases = near_degenerate_bases(g.dim);
    g.base = bases[r.below(bases.size())];
    g.ulps = 1 + static_cast<std::int64_t>(r.below(4));
    g.off = r.below(4);
    g.side = kettner_side(g.n);
  } else if (name == "near-duplicates") {
    g.copies = 2 + r.below(4);
    g.ulps = static_cast<std::int64_t>(r.below(4));
  } else if (name == "huge") {
    g.exp = 900 + static_cast<int>(r.below(124));
    g.exp_set = true;
  } else if (name == "tiny") {
    g.exp = -1074 + static_cast<int>(r.below(75));
    g.exp_set = true;
  } else if (name == "kettner-grid") {
    g.side = kettner_side(g.n);
  } else if (name == "kettner-hull") {
    static const char* const sets[] = {"A1", "A2", "B1", "B2"};
    g.set = sets[r.below(4)];
  }
  // Other generators (and ones added later) run with dlab gen's defaults.
}

}  // namespace

std::uint64_t case_seed(std::uint64_t campaign_seed, std::uint64_t i) {
  // The (i+1)-th output of gen::SplitMix64(campaign_seed), without the i steps.
  return gen::SplitMix64(campaign_seed + i * 0x9e3779b97f4a7c15ULL).next();
}

CasePlan plan_case(const CampaignSpec& spec, std::uint64_t i) {
  CasePlan c;
  c.index = i;
  c.seed = case_seed(spec.seed, i);
  gen::SplitMix64 r(c.seed);
  c.gen.name = spec.generators[r.below(spec.generators.size())];
  c.gen.dim = spec.dim;
  c.gen.n = spec.n_lo + r.below(spec.n_hi - spec.n_lo + 1);
  c.gen.seed = r.next();
  c.order_seed = r.next();
  draw_options(c.gen, r);
  return c;
}

std::string gen_extra_args(const gen::GenOptions& g) {
  std::string s;
  const auto add = [&](const std::string& opt, const std::string& v) { s += (s.empty() ? "" : " ") + opt + " " + v; };
  const std::string& name = g.name;
  if (name == "clustered") add("--clusters", std::to_string(g.clusters));
  if (name == "collinear" || name == "coplanar" ||
      (name == "near-degenerate" && (g.base == "collinear" || g.base == "coplanar")))
    add("--off", std::to_string(g.off));
  if (name == "near-degenerate") add("--base", g.base);
  if (name == "near-degenerate" || name == "near-duplicates") add("--ulps", std::to_string(g.ulps));
  if (name == "near-duplicates") add("--copies", std::to_string(g.copies));
  if ((name == "huge" || name == "tiny") && g.exp_set) add("--exp", std::to_string(g.exp));
  if (name == "kettner-grid" || (name == "near-degenerate" && g.base == "kettner-grid"))
    add("--side", std::to_string(g.side));
  if (name == "kettner-hull") add("--set", g.set);
  return s;
}

std::string gen_command(const gen::GenOptions& g) {
  std::string s = "dlab gen " + g.name + " --dim " + std::to_string(g.dim) + " --n " + std::to_string(g.n) +
                  " --seed " + std::to_string(g.seed);
  const std::string extra = gen_extra_args(g);
  return extra.empty() ? s : s + " " + extra;
}

std::string replay_command(const CasePlan& c, const Pair& p) {
  return gen_command(c.gen) + " | dlab triangulate -" + triangulate_options(p, c.order_seed);
}

std::string triangulate_options(const Pair& p, std::uint64_t order_seed) {
  std::string s = " --algo " + p.algorithm;
  if (p.exact_sphere) s += " --exact-sphere";
  if (p.enclosing_box) s += " --enclosing-box";
  s += " --kernel " + p.kernel;
  if (!p.policy.empty()) s += " --policy " + p.policy;
  if (p.order != "brio") s += " --order " + p.order;
  return s + " --seed " + std::to_string(order_seed) + " --validate";
}

}  // namespace dlab::fuzz
