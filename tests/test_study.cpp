// `dlab study` (studies/): the fixed column lists cover every counter any
// algorithm x kernel x policy x location emits in 2D and 3D; the location
// column's rule matches the registry; config errors name the key as a JSON
// pointer (syntax errors: line and column); the run order of
// studies/README.md; CSV quoting round-trips.
#include <algorithm>
#include <set>
#include <string>

#include <catch2/catch.hpp>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/generators.hpp"
#include "studies/columns.hpp"
#include "studies/config.hpp"
#include "studies/matrix.hpp"
#include "variants/run.hpp"

using namespace dlab;
using namespace dlab::study;

namespace {

// Every algorithm name a config accepts.
std::vector<std::string> all_algorithms() {
  std::vector<std::string> a = algorithm_names();
  for (const char* g : {"george+exact-sphere", "george+enclosing-box", "george+exact-sphere+enclosing-box"})
    a.emplace_back(g);
  return a;
}

std::vector<PointSet> inputs_of_dimension(int dim) {
  std::vector<PointSet> out;
  for (const char* name : {"uniform", "near-degenerate", "lattice"}) {
    gen::GenOptions o;
    o.name = name;
    o.dim = dim;
    o.n = dim == 2 ? 40 : 30;
    o.seed = 5;
    out.push_back(gen::generate(o));
  }
  return out;
}

std::string config_error(const std::string& text) {
  try {
    StudyConfig c = parse_config(text, "t.json");
    return "";
  } catch (const ConfigError& e) {
    return e.what();
  }
}

}  // namespace

TEST_CASE("every counter emitted by any algorithm x kernel x policy has a column", "[study]") {
  const auto& pred = predicate_counter_names();
  const auto& ctr = algorithm_counter_names();
  std::set<std::string> missing, seen_pred, seen_ctr;
  const std::vector<std::string> locations = {"walk", "scan"};
  for (int dim : {2, 3})
    for (const PointSet& ps : inputs_of_dimension(dim))
      for (const auto& algo : all_algorithms())
        for (const auto& kernel : kernel_names())
          for (const char* policy : {"sos", "strict"})
            for (const auto& location : locations)
            for (unsigned threads : {0u, 2u}) {  // 2: the parallel bowyer-watson
              const fuzz::Pair pair = fuzz::make_pair(algo, kernel);
              if (location != "walk" && !location_is_selectable(pair.algorithm)) continue;
              if (threads > 0 && (algo != "bowyer-watson" || !kernel_is_exact(kernel) || location != "walk" ||
                                  std::string(policy) != "sos"))
                continue;
              RunOptions o = pair.options(1);
              o.policy = policy;
              o.location = location;
              o.threads = threads;
              RunResult r;
              try {
                r = run(ps, o);
              } catch (const std::exception&) {
                continue;  // an inexact run that throws reports no counters
              }
              for (const auto& [name, v] : r.predicates) {
                seen_pred.insert(name);
                if (std::find(pred.begin(), pred.end(), name) == pred.end()) missing.insert("pred." + name);
              }
              for (const auto& [name, v] : r.counters) {
                seen_ctr.insert(name);
                if (std::find(ctr.begin(), ctr.end(), name) == ctr.end()) missing.insert("ctr." + name + " (" + algo + ")");
              }
            }
  INFO("counters without a column in studies/columns.cpp");
  CHECK(std::vector<std::string>(missing.begin(), missing.end()) == std::vector<std::string>{});
  // The lists hold nothing that no run emits (a renamed counter leaves no dead column).
  std::vector<std::string> dead;
  for (const auto& n : ctr)
    if (!seen_ctr.count(n)) dead.push_back("ctr." + n);
  for (const auto& n : pred)
    if (!seen_pred.count(n)) dead.push_back("pred." + n);
  CHECK(dead == std::vector<std::string>{});
}

TEST_CASE("location is selectable exactly where the registry takes scan", "[study]") {
  const PointSet ps = inputs_of_dimension(2)[0];
  for (const auto& algo : all_algorithms()) {
    RunOptions o = fuzz::make_pair(algo, "adaptive").options(1);
    o.location = "scan";
    bool refused = false;
    try {
      run(ps, o);
    } catch (const UsageError&) {
      refused = true;
    }
    INFO(algo);
    CHECK(refused == !location_is_selectable(o.algorithm));
  }
}

TEST_CASE("the header is the contract's, columns are unique", "[study]") {
  const std::string h = csv_header();
  CHECK(h.rfind("run,input,generator,dimension,n,seed,repeat,tool,algorithm,kernel,order,policy,location,"
                "input_points,distinct_points,simplices,outcome,message,wall_seconds,cpu_seconds,peak_rss_bytes,"
                "pred.orient2d,",
                0) == 0);
  const auto cells = csv_split(h);
  CHECK(cells.size() == column_count());
  CHECK(std::set<std::string>(cells.begin(), cells.end()).size() == cells.size());
}

TEST_CASE("CSV fields round-trip", "[study]") {
  const std::vector<std::string> fields = {"", "plain", "a,b", "say \"x\"", "line\nbreak", "\"", ",", "x\"\"y"};
  std::string line = csv_field(fields[0]);
  for (std::size_t i = 1; i < fields.size(); ++i) line += "," + csv_field(fields[i]);
  CHECK(csv_split(line) == fields);
  CHECK_THROWS(csv_split("\"open"));
  CHECK_THROWS(csv_split("\"a\"b"));
}

TEST_CASE("config errors name the file and the key", "[study]") {
  const std::string ok_inputs = R"("inputs": [{"generator": "uniform", "n": 10}])";
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], )" + ok_inputs + "}") == "");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "colour": 1, )" + ok_inputs + "}") ==
        "t.json: /colour: unknown key 'colour' (known here: name, algorithms, kernels, orders, policies, "
        "locations, inputs, repeats, baselines, epeck_max_n, timeout_seconds, memory_limit_mib)");
  CHECK(config_error(R"({"algorithms": "lawson", "kernels": ["mp"], )" + ok_inputs + "}") ==
        "t.json: /algorithms: must be an array of strings, not a string");
  CHECK(config_error(R"({"algorithms": ["lawson", "delaunay"], "kernels": ["mp"], )" + ok_inputs + "}")
            .rfind("t.json: /algorithms/1: unknown algorithm 'delaunay'", 0) == 0);
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp", "double"], )" + ok_inputs + "}")
            .rfind("t.json: /kernels/1: unknown kernel 'double'", 0) == 0);
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"]})") == "t.json: (top level): missing \"inputs\"");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "inputs": [{"generator": "uniform", "n": 10},
        {"generator": "uniform", "n": [10, 0]}]})") == "t.json: /inputs/1/n/1: must be an integer in 1..268435456, not 0");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "inputs": [{"generator": "uniform", "n": 2.5}]})") ==
        "t.json: /inputs/0/n: must be an integer in 1..268435456, not 2.5");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "inputs": [{"generator": "sphere", "n": 5}]})")
            .rfind("t.json: /inputs/0/generator: unknown generator 'sphere'", 0) == 0);
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "inputs": [{"generator": "uniform", "n": 5,
        "options": {"sigma": "big"}}]})") == "t.json: /inputs/0/options/sigma: must be a finite number, not \"big\"");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp", "mp"], )" + ok_inputs + "}") ==
        "t.json: /kernels/1: 'mp' is listed twice");
  CHECK(config_error(R"({"algorithms": ["lawson"], "kernels": ["mp"], "kernels": ["mp"], )" + ok_inputs + "}") ==
        "t.json: key 'kernels' appears twice in one object");
  // Syntax: line and column of the byte where parsing stopped.
  CHECK(config_error("{\n  \"algorithms\": [\"lawson\",]\n}").rfind("t.json:2:27: JSON syntax error: ", 0) == 0);
  CHECK(line_column("ab\ncd\n\xc3\xa9x", 8) == "3:2");
}

TEST_CASE("runs are numbered in the README's order", "[study]") {
  StudyConfig c = parse_config(R"({"algorithms": ["bowyer-watson", "tanemura"], "kernels": ["mp", "float"],
      "policies": ["default", "sos"], "locations": ["walk", "scan"], "repeats": 2,
      "baselines": ["qhull", "cgal-epeck"], "epeck_max_n": 10,
      "inputs": [{"generator": "uniform", "n": [10, 20], "seeds": [7, 8]}]})",
                               "t.json");
  c.inputs[0].dimension = 2;
  const auto runs = expand_matrix(c);
  // Per input x repeat: bowyer-watson: mp {sos} x {walk, scan} + float {strict, sos} x {walk, scan} = 6;
  // tanemura (no location choice): mp 1 + float 2 = 3; qhull 1; cgal-epeck only at n = 10.
  const std::size_t per10 = 6 + 3 + 2, per20 = 6 + 3 + 1;
  REQUIRE(runs.size() == 2 * 2 * per10 + 2 * 2 * per20);
  for (std::size_t i = 0; i < runs.size(); ++i) CHECK(runs[i].id == i);
  auto desc = [](const RunSpec& r) {
    return std::to_string(r.n) + " " + std::to_string(r.seed) + " " + std::to_string(r.repeat) + " " + r.tool + " " +
           r.algorithm + " " + r.kernel + " " + r.policy + " " + r.location;
  };
  CHECK(desc(runs[0]) == "10 7 0 dlab bowyer-watson mp sos walk");
  CHECK(desc(runs[1]) == "10 7 0 dlab bowyer-watson mp sos scan");
  CHECK(desc(runs[2]) == "10 7 0 dlab bowyer-watson float strict walk");
  CHECK(desc(runs[4]) == "10 7 0 dlab bowyer-watson float sos walk");
  CHECK(desc(runs[6]) == "10 7 0 dlab tanemura mp sos -");
  CHECK(desc(runs[8]) == "10 7 0 dlab tanemura float sos -");
  CHECK(desc(runs[9]) == "10 7 0 qhull qhull - - -");
  CHECK(desc(runs[10]) == "10 7 0 cgal-epeck cgal-epeck - - -");
  CHECK(desc(runs[11]) == "10 7 1 dlab bowyer-watson mp sos walk");
  CHECK(desc(runs[2 * per10]) == "10 8 0 dlab bowyer-watson mp sos walk");
  CHECK(desc(runs[4 * per10]) == "20 7 0 dlab bowyer-watson mp sos walk");
  CHECK(desc(runs.back()) == "20 8 1 qhull qhull - - -");
  CHECK(parse_shard("2/3").has(4));
  CHECK_FALSE(parse_shard("2/3").has(5));
  CHECK_THROWS_AS(parse_shard("0/3"), ConfigError);
  CHECK_THROWS_AS(parse_shard("4/3"), ConfigError);
}
