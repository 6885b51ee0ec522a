// See record.hpp.
#include "fuzz/record.hpp"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "cli/numbers.hpp"
#include "cli/stats_json.hpp"

namespace dlab::fuzz {
namespace {

using Json = nlohmann::ordered_json;

Counters counters_from(const Json& o, const char* key) {
  if (!o.is_object()) throw std::runtime_error(std::string("'") + key + "' is not an object");
  Counters c;
  for (const auto& [k, v] : o.items()) {
    if (!v.is_number_unsigned()) throw std::runtime_error(std::string("'") + key + "." + k + "' is not a count");
    c.emplace_back(k, v.get<std::uint64_t>());
  }
  return c;
}

template <class T>
T field(const Json& j, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) throw std::runtime_error(std::string("missing key '") + key + "'");
  try {
    return it->template get<T>();
  } catch (const Json::exception&) {
    throw std::runtime_error(std::string("key '") + key + "' has the wrong type");
  }
}

}  // namespace

// Written by hand (keys fixed, values escaped by the --stats writer): five
// times fewer instructions than building an nlohmann object, which mattered at
// thousands of records per second; parse_json_line reads it back with nlohmann
// (tests/test_fuzz_campaign.cpp checks the round trip).
std::string to_json_line(const PairRecord& r) {
  std::string s;
  s.reserve(512);
  const auto key = [&](const char* k) {
    s += s.empty() ? "{\"" : ",\"";
    s += k;
    s += "\":";
  };
  const auto counters = [&](const Counters& c) {
    s += '{';
    bool first = true;
    for (const auto& [k, v] : c) {
      if (v == 0) continue;
      if (!first) s += ',';
      first = false;
      s += io::json_string(k);
      s += ':';
      s += std::to_string(v);
    }
    s += '}';
  };
  key("case"), s += std::to_string(r.case_index);
  key("seed"), s += std::to_string(r.seed);
  key("gen"), s += io::json_string(r.gen);
  key("gen_args"), s += io::json_string(r.gen_args);
  key("n"), s += std::to_string(r.n);
  key("dim"), s += std::to_string(r.dim);
  key("algo"), s += io::json_string(r.algo);
  key("kernel"), s += io::json_string(r.kernel);
  key("exact"), s += r.exact ? "true" : "false";
  key("outcome"), s += io::json_string(r.outcome);
  key("kind"), s += io::json_string(r.kind);
  key("detail"), s += io::json_string(r.detail);
  key("counters"), counters(r.counters);
  key("predicates"), counters(r.predicates);
  key("seconds"), s += std::isfinite(r.seconds) && r.seconds >= 0 ? io::format_decimal(r.seconds) : "0";
  s += '}';
  return s;
}

PairRecord parse_json_line(std::string_view line) {
  Json j;
  try {
    j = Json::parse(line);
  } catch (const Json::parse_error& e) {
    throw std::runtime_error("not a JSON object (" + std::string(e.what()) + ")");
  }
  if (!j.is_object()) throw std::runtime_error("not a JSON object");
  PairRecord r;
  if (!j.contains("case") || !j["case"].is_number_unsigned()) throw std::runtime_error("no case index");
  r.case_index = field<std::uint64_t>(j, "case");
  r.seed = field<std::uint64_t>(j, "seed");
  r.gen = field<std::string>(j, "gen");
  r.gen_args = field<std::string>(j, "gen_args");
  r.n = field<std::uint64_t>(j, "n");
  r.dim = field<int>(j, "dim");
  r.algo = field<std::string>(j, "algo");
  r.kernel = field<std::string>(j, "kernel");
  r.exact = field<bool>(j, "exact");
  r.outcome = field<std::string>(j, "outcome");
  r.kind = field<std::string>(j, "kind");
  r.detail = field<std::string>(j, "detail");
  r.counters = counters_from(j["counters"], "counters");
  r.predicates = counters_from(j["predicates"], "predicates");
  r.seconds = field<double>(j, "seconds");
  return r;
}

}  // namespace dlab::fuzz
