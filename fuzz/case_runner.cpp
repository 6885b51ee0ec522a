// See case_runner.hpp.
#include "fuzz/case_runner.hpp"

#include <chrono>
#include <exception>
#include <memory>

#include "algorithms/validate.hpp"

#include "fuzz/fuzz_outcome.hpp"

namespace dlab::fuzz {
namespace {

// True when the run triangulated other points than the input (the integer kernel snaps).
bool moved(const PointSet& input, const PointSet& used) {
  if (used.size() != input.size()) return false;
  return input.dimension == 2 ? used.p2 != input.p2 : used.p3 != input.p3;
}

}  // namespace

PreparedCase prepare_case(const CampaignSpec& spec, std::uint64_t i) {
  PreparedCase c;
  c.plan = plan_case(spec, i);
  c.points = gen::generate(c.plan.gen);
  return c;
}

PairRecord record_header(const PreparedCase& c, const Pair& p) {
  PairRecord r;
  r.case_index = c.plan.index;
  r.seed = c.plan.seed;
  r.gen = c.plan.gen.name;
  r.gen_args = gen_extra_args(c.plan.gen);
  r.n = c.points.size();
  r.dim = c.points.dimension;
  r.algo = p.algo_name();
  r.kernel = p.kernel;
  r.exact = p.exact();
  return r;
}

PairRecord CaseRunner::run(const Pair& p, bool timing) {
  PairRecord rec = record_header(*case_, p);
  const PointSet& pts = case_->points;
  const auto t0 = std::chrono::steady_clock::now();
  RunResult res;
  try {
    res = dlab::run(pts, p.options(case_->plan.order_seed));
  } catch (const std::bad_alloc&) {
    throw;  // out-of-memory: the child's limit (fuzz/isolation.hpp) classifies it
  } catch (const std::exception& e) {  // as dlab triangulate: an algorithm that throws has failed
    res = RunResult{};
    res.outcome = RunResult::Outcome::failed;
    res.message = std::string("exception: ") + e.what();
  }
  res.dimension = pts.dimension;
  if (res.points.size() != pts.size()) res.points = pts;
  // The exact validator's report, kept: it says whether the reference is needed.
  if (!res.validation && res.outcome != RunResult::Outcome::failed) {
    try {
      res.validation = std::make_shared<const ValidationReport>(validate(res.points, res.simplices));
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception&) {
      // classify() validates again and reports the exception as `invalid`
    }
  }
  Outcome o = classify(pts, res, rec.exact, Validate::always);
  // A valid Delaunay result without a cospherical interior facet is the unique
  // Delaunay triangulation (algorithms/validate.hpp, cospherical_facets), so it
  // is the perturbed one: the reference is computed only when that count is
  // not 0 -- on degenerate input.
  if (rec.exact && o.kind == OutcomeClass::ok && res.validation && res.validation->cospherical_facets > 0) {
    try {
      if (moved(pts, res.points)) {  // integer: the reference of the snapped points
        Reference snapped(res.points);
        o = compare_with_reference(std::move(o), res, snapped.result());
      } else {
        o = compare_with_reference(std::move(o), res, reference_.result());
      }
    } catch (const std::bad_alloc&) {
      throw;
    } catch (const std::exception& e) {
      o.kind = OutcomeClass::differs;
      o.detail = std::string("the reference failed: ") + e.what();
    }
  }
  const auto t1 = std::chrono::steady_clock::now();
  rec.outcome = std::string(outcome_name(o.kind));
  rec.kind = o.kind == OutcomeClass::differs && o.detail.rfind("the reference", 0) == 0 ? "reference"
                                                                                        : detail_kind(o);
  rec.detail = o.detail;
  rec.counters = std::move(res.counters);
  rec.predicates = std::move(res.predicates);
  rec.seconds = timing ? std::chrono::duration<double>(t1 - t0).count() : 0.0;
  return rec;
}

}  // namespace dlab::fuzz
