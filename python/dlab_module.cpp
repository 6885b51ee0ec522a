// The Python module `dlab` (python/README.md): triangulate, check, predicate
// and generate on NumPy arrays. Every answer comes from the code behind the
// `dlab` command -- dlab::run() (variants/run.hpp), the outcome classes
// (variants/outcome.hpp), the --stats record (cli/stats_json.hpp), the exact
// validator (algorithms/validate.hpp), the kernels by name (cli/kernels.hpp),
// the generators (fuzz/generators.hpp) -- and bad input raises ValueError with
// the command line's message, prefixed by where it is ("points[3, 1]: ..."
// where the command line says "FILE:LINE: ...").
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "algorithms/validate.hpp"
#include "cli/kernels.hpp"
#include "cli/numbers.hpp"
#include "cli/outcome_report.hpp"
#include "cli/run_choices.hpp"
#include "cli/stats_json.hpp"
#include "fuzz/generators.hpp"
#include "variants/outcome.hpp"
#include "variants/run.hpp"

namespace py = pybind11;

namespace {

using dlab::PointSet;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

std::string shape_text(const py::array& a) {
  std::string s = "(";
  for (py::ssize_t i = 0; i < a.ndim(); ++i) s += (i ? ", " : "") + std::to_string(a.shape(i));
  return s + (a.ndim() == 1 ? ",)" : ")");
}

// The command line's reason for a non-finite coordinate (cli/numbers.hpp), as
// the reader gives it for the token "nan", "inf" or "-inf".
void require_finite(double x, const std::string& where) {
  if (std::isnan(x)) throw py::value_error(where + ": " + dlab::io::describe(dlab::io::ParseStatus::nan, "nan"));
  if (std::isinf(x))
    throw py::value_error(where + ": " + dlab::io::describe(dlab::io::ParseStatus::infinity, x > 0 ? "inf" : "-inf"));
}

// An (n, dims) array of finite doubles; `name` names it in messages.
DoubleArray coordinates(const py::handle& obj, const std::string& name, std::initializer_list<int> dims) {
  DoubleArray a = DoubleArray::ensure(obj);
  if (!a) throw py::value_error(name + " must be an array of float64");
  std::string want;
  bool ok = false;
  for (int d : dims) {
    want += (want.empty() ? "" : " or ") + std::string("(n, ") + std::to_string(d) + ")";
    ok = ok || (a.ndim() == 2 && a.shape(1) == d);
  }
  if (!ok) throw py::value_error(name + " must be an " + want + " array, not of shape " + shape_text(a));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i)
    for (py::ssize_t j = 0; j < r.shape(1); ++j)
      require_finite(r(i, j), name + "[" + std::to_string(i) + ", " + std::to_string(j) + "]");
  return a;
}

PointSet point_set(const py::handle& obj) {
  const DoubleArray a = coordinates(obj, "points", {2, 3});
  const auto r = a.unchecked<2>();
  PointSet ps;
  ps.dimension = static_cast<int>(r.shape(1));
  for (py::ssize_t i = 0; i < r.shape(0); ++i) {
    if (ps.dimension == 2) ps.p2.push_back({r(i, 0), r(i, 1)});
    else ps.p3.push_back({r(i, 0), r(i, 1), r(i, 2)});
  }
  return ps;
}

py::array_t<double> to_array(const PointSet& ps) {
  const auto n = static_cast<py::ssize_t>(ps.size());
  py::array_t<double> out({n, static_cast<py::ssize_t>(ps.dimension)});
  auto w = out.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i)
    for (int j = 0; j < ps.dimension; ++j)
      w(i, j) = ps.dimension == 2 ? ps.p2[static_cast<std::size_t>(i)][j] : ps.p3[static_cast<std::size_t>(i)][j];
  return out;
}

py::array_t<std::int32_t> simplex_array(const std::vector<std::uint32_t>& s, int dimension) {
  const py::ssize_t k = dimension + 1;
  py::array_t<std::int32_t> out({static_cast<py::ssize_t>(s.size()) / k, k});
  std::int32_t* w = out.mutable_data();
  for (std::size_t i = 0; i < s.size(); ++i) w[i] = static_cast<std::int32_t>(s[i]);
  return out;
}

// dlab triangulate: run, classify as the command does, and the --stats JSON
// (cli/stats_json.cpp) read back by Python's json module, so the dict has the
// command's keys, order and values.
py::tuple triangulate(const py::handle& points, const std::string& algo, const std::string& kernel,
                      const std::optional<std::string>& policy, const std::string& order,
                      std::uint64_t seed, const std::string& location, bool validate, unsigned threads,
                      bool canonical) {
  const PointSet ps = point_set(points);
  dlab::RunOptions opt;
  opt.algorithm = algo;
  opt.kernel = kernel;
  opt.policy = policy.value_or(dlab::kernel_is_exact(kernel) ? "sos" : "strict");
  opt.order = order;
  opt.location = location;
  opt.seed = seed;
  opt.threads = threads;
  opt.canonical = canonical;
  // The command line's check of the names before run() (cli/run_choices.hpp; the
  // tests compare the messages with the command's).
  try {
    dlab::cli::check_run_choices(opt);
  } catch (const dlab::UsageError& e) {
    throw py::value_error(e.what());
  }
  dlab::RunResult res;
  std::string usage_error;
  std::uint64_t peak_rss = 0;
  dlab::Outcome outcome;
  {
    py::gil_scoped_release unlocked;
    try {
      res = dlab::run(ps, opt);
    } catch (const dlab::UsageError& e) {
      usage_error = e.what();
    } catch (const std::exception& e) {  // as the command: an algorithm that throws has failed
      res = dlab::RunResult{};
      res.outcome = dlab::RunResult::Outcome::failed;
      res.message = std::string("exception: ") + e.what();
    }
    if (usage_error.empty()) {
      peak_rss = dlab::io::peak_rss_bytes();
      if (res.points.size() != ps.size()) res.points = ps;
      res.dimension = ps.dimension;
      outcome = dlab::classify(ps, res, dlab::pair_is_exact(opt),
                               validate ? dlab::Validate::always : dlab::Validate::unless_exact);
    }
  }
  if (!usage_error.empty()) throw py::value_error(usage_error);
  std::ostringstream json;
  dlab::io::write_stats_json(json, dlab::cli::stats_record(opt, ps.size(), res, outcome, peak_rss));
  py::object stats = py::module_::import("json").attr("loads")(json.str());
  return py::make_tuple(simplex_array(res.simplices, res.dimension), stats);
}

// dlab check: the exact validator's report as a dict.
py::dict check(const py::handle& points, const py::handle& simplices, const std::string& orientation) {
  if (orientation != "positive" && orientation != "any")
    throw py::value_error("--orientation must be positive or any, not '" + orientation + "'");
  const PointSet ps = point_set(points);
  auto s = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(simplices);
  const py::ssize_t k = ps.dimension + 1;
  if (!s || (!(s.ndim() == 2 && s.shape(1) == k) && !(s.ndim() == 1 && s.shape(0) == 0)))
    throw py::value_error("simplices must be an (m, " + std::to_string(k) + ") integer array" +
                          (s ? ", not of shape " + shape_text(s) : std::string()));
  std::vector<std::uint32_t> flat;
  for (py::ssize_t i = 0; i < s.size(); ++i) {
    const std::int64_t v = s.data()[i];
    if (v < 0 || v > UINT32_MAX)
      throw py::value_error("simplices[" + std::to_string(i / k) + ", " + std::to_string(i % k) +
                            "]: index " + std::to_string(v) + " out of range");
    flat.push_back(static_cast<std::uint32_t>(v));
  }
  std::size_t reoriented = 0;
  dlab::ValidationReport rep;
  {
    py::gil_scoped_release unlocked;
    if (orientation == "any") reoriented = dlab::orient_positively(ps, flat);
    rep = dlab::validate(ps, flat);
  }
  py::list problems;
  for (int c = 0; c < dlab::kCheckCount; ++c) {
    const dlab::CheckResult& r = rep.checks[static_cast<std::size_t>(c)];
    if (r.count == 0) continue;
    py::dict p;
    p["check"] = std::string(dlab::check_name(static_cast<dlab::Check>(c)));
    p["count"] = r.count;
    p["simplex"] = r.simplex;
    p["facet"] = r.facet;
    p["point"] = r.point;
    problems.append(p);
  }
  py::dict d;
  d["valid"] = rep.valid();
  d["delaunay"] = rep.delaunay();
  d["problems"] = problems;
  std::string summary = rep.summary();
  while (!summary.empty() && summary.back() == '\n') summary.pop_back();
  d["summary"] = summary;  // the lines `dlab check` prints
  d["dimension"] = rep.dimension;
  d["points"] = rep.points;
  d["distinct_points"] = rep.distinct_points;
  d["simplices"] = rep.simplices;
  d["interior_facets"] = rep.interior_facets;
  d["boundary_facets"] = rep.boundary_facets;
  d["cospherical_facets"] = rep.cospherical_facets;
  d["lower_dimensional"] = rep.lower_dimensional;
  d["reoriented"] = reoriented;
  return d;
}

// One predicate per row of the argument arrays, as `dlab predicate` computes it
// (cli/cmd_predicate.cpp): the integer kernel's grid is fitted to each row's points.
template <int D, int N>
py::array_t<std::int8_t> predicate_rows(const std::string& name, const std::string& kernel,
                                        const std::vector<DoubleArray>& arrays) {
  const py::ssize_t rows = arrays[0].shape(0);
  for (int i = 1; i < N; ++i)
    if (arrays[static_cast<std::size_t>(i)].shape(0) != rows)
      throw py::value_error(name + ": every array needs the same number of rows (argument 1 has " +
                            std::to_string(rows) + ", argument " + std::to_string(i + 1) + " has " +
                            std::to_string(arrays[static_cast<std::size_t>(i)].shape(0)) + ")");
  std::vector<const double*> data;
  for (const auto& a : arrays) data.push_back(a.data());
  py::array_t<std::int8_t> out(rows);
  std::int8_t* w = out.mutable_data();
  std::string error;
  {
    py::gil_scoped_release unlocked;
    try {
      std::array<dlab::Point<D>, N> pts;
      for (py::ssize_t r = 0; r < rows; ++r) {
        for (int i = 0; i < N; ++i)
          for (int j = 0; j < D; ++j) pts[static_cast<std::size_t>(i)][j] = data[static_cast<std::size_t>(i)][r * D + j];
        w[r] = static_cast<std::int8_t>(dlab::cli::with_kernel<D>(
            kernel, std::span<const dlab::Point<D>>(pts), [&](const auto& k) {
              if constexpr (D == 2)
                return dlab::to_int(N == 3 ? k.orient2d(pts[0], pts[1], pts[2])
                                           : k.incircle(pts[0], pts[1], pts[2], pts[N - 1]));
              else
                return dlab::to_int(N == 4 ? k.orient3d(pts[0], pts[1], pts[2], pts[3])
                                           : k.insphere(pts[0], pts[1], pts[2], pts[3], pts[N - 1]));
            }));
      }
    } catch (const dlab::UsageError& e) {
      error = e.what();
    }
  }
  if (!error.empty()) throw py::value_error(error);
  return out;
}

py::array_t<std::int8_t> predicate(const std::string& name, const std::string& kernel, const py::args& args) {
  int dim = 0, npts = 0;
  if (name == "orient2d") dim = 2, npts = 3;
  else if (name == "incircle") dim = 2, npts = 4;
  else if (name == "orient3d") dim = 3, npts = 4;
  else if (name == "insphere") dim = 3, npts = 5;
  else
    throw py::value_error("unknown predicate '" + name + "' (known: orient2d, incircle, orient3d, insphere)");
  if (static_cast<int>(args.size()) != npts)
    throw py::value_error(name + " takes " + std::to_string(npts) + " arrays of points, found " +
                          std::to_string(args.size()));
  if (!dlab::cli::kernel_available(kernel))
    throw py::value_error("unknown kernel '" + kernel + "' (known: adaptive, integer, mp, float, epsilon)");
  std::vector<DoubleArray> arrays;
  for (int i = 0; i < npts; ++i)
    arrays.push_back(coordinates(args[static_cast<std::size_t>(i)], "argument " + std::to_string(i + 1), {dim}));
  if (name == "orient2d") return predicate_rows<2, 3>(name, kernel, arrays);
  if (name == "incircle") return predicate_rows<2, 4>(name, kernel, arrays);
  if (name == "orient3d") return predicate_rows<3, 4>(name, kernel, arrays);
  return predicate_rows<3, 5>(name, kernel, arrays);
}

// dlab gen: GenOptions (fuzz/generators.hpp) from keyword arguments.
py::array_t<double> generate(const std::string& name, std::size_t n, int dim, std::uint64_t seed,
                             const py::kwargs& options) {
  dlab::gen::GenOptions o;
  o.name = name;
  o.n = n;
  o.dim = dim;
  o.seed = seed;
  for (const auto& [key_obj, value] : options) {
    const std::string key = py::cast<std::string>(key_obj);
    if (key == "off") o.off = py::cast<std::size_t>(value);
    else if (key == "ulps") o.ulps = py::cast<std::int64_t>(value);
    else if (key == "base") o.base = py::cast<std::string>(value);
    else if (key == "clusters") o.clusters = py::cast<std::size_t>(value);
    else if (key == "sigma") o.sigma = py::cast<double>(value);
    else if (key == "copies") o.copies = py::cast<std::size_t>(value);
    else if (key == "side") o.side = py::cast<std::size_t>(value);
    else if (key == "exp") o.exp = py::cast<int>(value), o.exp_set = true;
    else if (key == "set") o.set = py::cast<std::string>(value);
    else if (key == "lo") o.lo = py::cast<double>(value);
    else if (key == "hi") o.hi = py::cast<double>(value);
    else if (key == "spacing") o.spacing = py::cast<double>(value);
    else if (key == "step_exp") o.step_exp = py::cast<int>(value), o.step_exp_set = true;
    else if (key == "sign") o.sign = py::cast<std::string>(value);
    else
      throw py::value_error("unknown generator option '" + key +
                            "' (known: off, ulps, base, clusters, sigma, copies, side, exp, set, lo, hi, "
                            "spacing, step_exp, sign)");
  }
  PointSet ps;
  try {
    ps = dlab::gen::generate(o);
  } catch (const std::invalid_argument& e) {
    throw py::value_error(e.what());
  }
  return to_array(ps);
}

}  // namespace

PYBIND11_MODULE(dlab, m) {
  m.doc() = "delaunay-lab: exact 2D/3D Delaunay triangulation (python/README.md)";
  m.def("triangulate", &triangulate, py::arg("points"), py::arg("algo") = "bowyer-watson",
        py::arg("kernel") = "adaptive", py::arg("policy") = py::none(), py::arg("order") = "brio",
        py::arg("seed") = 0, py::arg("location") = "walk", py::arg("validate") = false,
        py::arg("threads") = 0, py::arg("canonical") = false,
        "(simplices int32 (m, d+1), stats dict with the keys of `dlab triangulate --stats`)");
  m.def("check", &check, py::arg("points"), py::arg("simplices"), py::arg("orientation") = "positive",
        "The exact validator's verdict (`dlab check`); orientation='any' accepts either orientation.");
  m.def("predicate", &predicate, py::arg("name"), py::arg("kernel"),
        "predicate(name, kernel, *arrays): signs (int8) of one predicate per row of (k, d) arrays.");
  m.def("generate", &generate, py::arg("name"), py::arg("n") = 1000, py::arg("dim") = 0, py::arg("seed") = 0,
        "generate(name, n, dim=0, seed=0, **options): the points of `dlab gen` as an (n, d) array.");
  m.def("generator_names", &dlab::gen::generator_names);
  m.def("algorithm_names", &dlab::algorithm_names);
  m.def("kernel_names", &dlab::cli::all_kernel_names);
}
