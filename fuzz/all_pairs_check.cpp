// See all_pairs_check.hpp.
#include "fuzz/all_pairs_check.hpp"

#include <exception>
#include <new>
#include <utility>
#include <vector>

#include "fuzz/reference.hpp"
#include "variants/outcome.hpp"

namespace dlab::fuzz {
namespace {

RunOptions options(const char* algo, const char* kernel, const char* policy, const std::string& order,
                   std::uint64_t seed, bool exact_sphere = false, bool enclosing_box = false) {
  RunOptions o;
  o.algorithm = algo;
  o.kernel = kernel;
  o.policy = policy;
  o.order = order;
  o.seed = seed;
  o.exact_sphere = exact_sphere;
  o.enclosing_box = enclosing_box;
  return o;
}

std::string pair_text(const RunOptions& o) {
  return describe_pair(o) + ", --policy " + o.policy + " --order " + o.order + " --seed " + std::to_string(o.seed);
}

bool same_points(const PointSet& a, const PointSet& b) {
  return a.dimension == b.dimension && (a.dimension == 2 ? a.p2 == b.p2 : a.p3 == b.p3);
}

bool promise_kept(const Outcome& o) {
  return o.kind == OutcomeClass::ok || o.kind == OutcomeClass::lower_dimensional;
}

// The perturbed reference of some points, judged once by the exact validator.
struct JudgedReference {
  PointSet points;
  RunResult result;
  Outcome verdict;
};

class Checker {
 public:
  Checker(const PointSet& pts, const std::string& order, std::uint64_t seed)
      : pts_(pts), order_(order), seed_(seed) {}

  std::optional<PairFailure> run() {
    static constexpr const char* kAlgos[] = {"bowyer-watson", "lawson", "tanemura", "george"};
    for (const char* algo : kAlgos) {
      const bool george = std::string_view(algo) == "george";
      for (const char* kernel : {"adaptive", "integer", "mp"})
        if (auto f = exact_sos(options(algo, kernel, "sos", order_, seed_, george))) return f;
      if (auto f = exact_strict(options(algo, "adaptive", "strict", order_, seed_, george))) return f;
      for (const char* kernel : {"float", "epsilon"}) no_crash(options(algo, kernel, "strict", order_, seed_));
    }
    no_crash(options("george", "adaptive", "sos", order_, seed_));
    no_crash(options("george", "adaptive", "sos", order_, seed_, false, true));
    return std::nullopt;
  }

 private:
  const PointSet& pts_;
  std::string order_;
  std::uint64_t seed_;
  std::vector<JudgedReference> refs_;  // of the input, and of the integer kernel's snapped points

  const JudgedReference& reference_of(const PointSet& p) {
    for (const auto& r : refs_)
      if (same_points(r.points, p)) return r;
    JudgedReference r{p, run_reference(p), {}};
    r.verdict = classify(p, r.result, true);
    refs_.push_back(std::move(r));
    return refs_.back();
  }

  std::optional<PairFailure> exact_sos(const RunOptions& o) {
    RunResult res;
    try {
      res = dlab::run(pts_, o);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      return PairFailure{pair_text(o), std::string("threw: ") + e.what()};
    }
    const PointSet& used = res.points.size() == pts_.size() ? res.points : pts_;
    const JudgedReference& ref = reference_of(used);
    if (!promise_kept(ref.verdict))
      return PairFailure{"reference (Bowyer-Watson, sos, filtered mp)",
                         outcome_line("reference", ref.verdict, "reference")};
    Outcome o0;
    o0.kind = ref.result.outcome == RunResult::Outcome::lower_dimensional ? OutcomeClass::lower_dimensional
                                                                           : OutcomeClass::ok;
    const Outcome cmp = compare_with_reference(o0, res, ref.result);
    if (cmp.kind == OutcomeClass::differs || res.outcome != ref.result.outcome) {
      // Say more: what the validator thinks of it.
      const Outcome own = classify(pts_, res, true);
      const std::string line = promise_kept(own) ? outcome_line("run", cmp, describe_pair(o))
                                                 : outcome_line("run", own, describe_pair(o));
      return PairFailure{pair_text(o), line};
    }
    return std::nullopt;
  }

  std::optional<PairFailure> exact_strict(const RunOptions& o) {
    try {
      const RunResult res = dlab::run(pts_, o);
      const Outcome own = classify(pts_, res, true);
      if (!promise_kept(own)) return PairFailure{pair_text(o), outcome_line("run", own, describe_pair(o))};
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      return PairFailure{pair_text(o), std::string("threw: ") + e.what()};
    }
    return std::nullopt;
  }

  void no_crash(const RunOptions& o) {
    try {
      const RunResult res = dlab::run(pts_, o);
      (void)classify(pts_, res, false);
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      // an outcome like any other for these pairs
    }
  }
};

}  // namespace

std::optional<PairFailure> check_all_pairs(const PointSet& points, const std::string& order, std::uint64_t seed) {
  return Checker(points, order, seed).run();
}

}  // namespace dlab::fuzz
