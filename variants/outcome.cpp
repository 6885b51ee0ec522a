// See outcome.hpp.
#include "variants/outcome.hpp"

#include <exception>
#include <string>

namespace dlab {
namespace {

struct CheckText {
  std::string_view group;         // the fuzzer's name for what failed
  std::string_view one, many;     // what is counted, singular and plural ("" : not counted)
  std::string_view what;          // after it
};

CheckText check_text(Check c) {
  switch (c) {
    case Check::index_range: return {"indices", "simplex", "simplices", "with an index out of range"};
    case Check::duplicate_reference:
      return {"indices", "index", "indices", "naming a later copy of a duplicated point"};
    case Check::orientation: return {"orientation", "simplex", "simplices", "not positively oriented"};
    case Check::duplicate_simplex: return {"overlap", "simplex", "simplices", "listed twice"};
    case Check::non_manifold_facet: return {"adjacency", "facet", "facets", "in more than two simplices"};
    case Check::facet_same_side: return {"overlap", "facet", "facets", "with both simplices on one side"};
    case Check::boundary_manifold:
      return {"hull-coverage", "defect", "defects", "of the boundary (not one closed manifold)"};
    case Check::boundary_convex:
      return {"hull-coverage", "reflex boundary ridge", "reflex boundary ridges", "(the union is not convex)"};
    case Check::cover_degree: return {"overlap", "", "", "a point is covered other than once"};
    case Check::disconnected: return {"adjacency", "", "", "the simplices form more than one component"};
    case Check::missing_vertex: return {"missing-point", "distinct point", "distinct points", "in no simplex"};
    case Check::not_delaunay: return {"not-delaunay", "facet", "facets", "not locally Delaunay"};
    case Check::count_: break;
  }
  return {"invalid", "", "", "?"};
}

// "3 facets with both simplices on one side", "1 simplex listed twice".
std::string counted_text(const CheckText& t, std::uint64_t n) {
  if (t.one.empty()) return std::string(t.what);
  return std::to_string(n) + " " + std::string(n == 1 ? t.one : t.many) + " " + std::string(t.what);
}

std::string first_offender(const CheckResult& r) {
  std::string s;
  if (r.simplex >= 0) s += " simplex " + std::to_string(r.simplex);
  if (r.facet >= 0) s += " facet " + std::to_string(r.facet);
  if (r.point >= 0) s += " point " + std::to_string(r.point);
  return s.empty() ? "" : " (first:" + s + ")";
}

// The algorithm's message on one line.
std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace

std::string_view outcome_name(OutcomeClass c) {
  switch (c) {
    case OutcomeClass::ok: return "ok";
    case OutcomeClass::lower_dimensional: return "lower-dimensional";
    case OutcomeClass::not_delaunay: return "not-delaunay";
    case OutcomeClass::invalid: return "invalid";
    case OutcomeClass::reported: return "reported";
    case OutcomeClass::differs: return "differs";
  }
  return "reported";
}

int exit_status(OutcomeClass c) {
  return c == OutcomeClass::ok || c == OutcomeClass::lower_dimensional ? 0 : 1;
}

bool pair_is_exact(const RunOptions& o) {
  return kernel_is_exact(o.kernel) && !(o.algorithm == "george" && (!o.exact_sphere || o.enclosing_box));
}

Outcome classify_report(const ValidationReport& rep, bool exact_pair) {
  Outcome out;
  out.exact_pair = exact_pair;
  out.validated = true;
  if (!rep.valid()) {
    out.kind = OutcomeClass::invalid;
    std::string also;
    for (int c = 0; c < kCheckCount; ++c) {
      const Check check = static_cast<Check>(c);
      if (check == Check::not_delaunay || rep[check].count == 0) continue;
      const CheckText t = check_text(check);
      if (out.first_check == Check::count_) {
        out.first_check = check;
        out.check = t.group;
        out.count = rep[check].count;
        out.detail = std::string(t.group) + ": " + counted_text(t, out.count) + first_offender(rep[check]);
      } else {
        also += (also.empty() ? "; also: " : ", ") + std::string(check_name(check));
      }
    }
    if (rep.skipped) also += (also.empty() ? "; " : ", ") + std::string("geometric checks skipped");
    out.detail += also;
  } else if (!rep.delaunay()) {
    out.kind = OutcomeClass::not_delaunay;
    out.count = rep.non_delaunay_facets();
    out.detail = counted_text(check_text(Check::not_delaunay), out.count) + first_offender(rep[Check::not_delaunay]);
  } else if (rep.lower_dimensional) {
    out.kind = OutcomeClass::lower_dimensional;
    out.detail = "fewer than " + std::to_string(rep.dimension + 1) +
                 " affinely independent points, no simplices";
  }
  return out;
}

Outcome classify(const PointSet& input, const RunResult& r, bool exact_pair, Validate when) {
  if (r.outcome == RunResult::Outcome::failed) {
    Outcome out;
    out.kind = OutcomeClass::reported;
    out.exact_pair = exact_pair;
    out.detail = one_line(r.message.empty() ? "the algorithm failed without saying why" : r.message);
    return out;
  }
  Outcome out;
  if (r.validation) {
    out = classify_report(*r.validation, exact_pair);
  } else if (when == Validate::always || !exact_pair) {
    const PointSet& pts = r.points.size() == input.size() ? r.points : input;
    try {
      out = classify_report(validate(pts, r.simplices), exact_pair);
    } catch (const std::exception& e) {
      out.kind = OutcomeClass::invalid;
      out.exact_pair = exact_pair;
      out.check = "validator";
      out.detail = std::string("validator: ") + e.what();
      return out;
    }
  } else {  // an exact pair's own verdict
    out.exact_pair = exact_pair;
    if (r.outcome == RunResult::Outcome::lower_dimensional) out.kind = OutcomeClass::lower_dimensional;
  }
  // The algorithm's own words: why the input is lower-dimensional, or what it
  // noticed about a result it returned (e.g. flips stuck).
  if (!r.message.empty()) {
    if (out.kind == OutcomeClass::lower_dimensional)
      out.detail = one_line(r.message);
    else if (out.kind != OutcomeClass::ok)
      out.detail += "; " + one_line(r.message);
  }
  return out;
}

std::string describe_pair(const RunOptions& o) {
  std::string s = o.algorithm;
  if (o.exact_sphere) s += " --exact-sphere";
  if (o.enclosing_box) s += " --enclosing-box";
  return s + ", " + o.kernel + " kernel";
}

std::string outcome_line(std::string_view command, const Outcome& o, std::string_view pair) {
  std::string s = "dlab " + std::string(command) + ": " + std::string(outcome_name(o.kind)) + ": " + o.detail +
                  " (" + std::string(pair) + ")";
  if (o.bug()) s += "; a bug: the pair is exact";
  return s;
}

}  // namespace dlab
