// See config.hpp.
#include "studies/config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <sstream>

#include "fuzz/campaign_spec.hpp"
#include "variants/run.hpp"

namespace dlab::study {
namespace {

using Json = nlohmann::ordered_json;

// Largest n of one generated input (as `dlab gen --n`).
constexpr std::uint64_t kMaxN = std::uint64_t{1} << 28;

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// A JSON pointer's reference token (RFC 6901: ~ -> ~0, / -> ~1).
std::string token(const std::string& key) {
  std::string t;
  for (char c : key) t += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return t;
}

// Errors name the file and the pointer of the value at fault.
class Reader {
 public:
  explicit Reader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& pointer, const std::string& what) const {
    throw ConfigError(path_ + ": " + (pointer.empty() ? "(top level)" : pointer) + ": " + what);
  }

  // Every key of the object at `pointer` must be one of `known`.
  void only_keys(const Json& obj, const std::string& pointer, const std::vector<std::string>& known) const {
    if (!obj.is_object()) fail(pointer, "must be a JSON object");
    for (const auto& [key, value] : obj.items())
      if (std::find(known.begin(), known.end(), key) == known.end())
        fail(pointer + "/" + token(key), "unknown key '" + key + "' (known here: " + join(known) + ")");
  }

  std::string string(const Json& v, const std::string& pointer) const {
    if (!v.is_string()) fail(pointer, "must be a string, not " + type_of(v));
    return v.get<std::string>();
  }

  std::uint64_t u64(const Json& v, const std::string& pointer, std::uint64_t lo, std::uint64_t hi) const {
    if (!v.is_number_integer() || (v.is_number_integer() && !v.is_number_unsigned() && v.get<std::int64_t>() < 0) ||
        v.get<std::uint64_t>() < lo || v.get<std::uint64_t>() > hi)
      fail(pointer, "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " + text(v));
    return v.get<std::uint64_t>();
  }

  std::int64_t i64(const Json& v, const std::string& pointer, std::int64_t lo, std::int64_t hi) const {
    if (!v.is_number_integer() || (v.is_number_unsigned() && v.get<std::uint64_t>() > std::uint64_t(hi)) ||
        v.get<std::int64_t>() < lo || v.get<std::int64_t>() > hi)
      fail(pointer, "must be an integer in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not " + text(v));
    return v.get<std::int64_t>();
  }

  double real(const Json& v, const std::string& pointer) const {
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(pointer, "must be a finite number, not " + text(v));
    return v.get<double>();
  }

  // A non-empty array of distinct strings, each accepted by `check` (which
  // returns an error text, or "" when the name is fine).
  std::vector<std::string> names(const Json& v, const std::string& pointer,
                                 const std::function<std::string(const std::string&)>& check,
                                 bool may_be_empty = false) const {
    if (!v.is_array()) fail(pointer, "must be an array of strings, not " + type_of(v));
    if (v.empty() && !may_be_empty) fail(pointer, "must not be empty");
    std::vector<std::string> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string p = pointer + "/" + std::to_string(i);
      std::string s = string(v[i], p);
      if (const std::string why = check(s); !why.empty()) fail(p, why);
      if (std::find(out.begin(), out.end(), s) != out.end()) fail(p, "'" + s + "' is listed twice");
      out.push_back(std::move(s));
    }
    return out;
  }

  // An integer, or a non-empty array of distinct integers, in lo..hi.
  std::vector<std::uint64_t> integers(const Json& v, const std::string& pointer, std::uint64_t lo,
                                      std::uint64_t hi) const {
    if (!v.is_array()) return {u64(v, pointer, lo, hi)};
    if (v.empty()) fail(pointer, "must not be empty");
    std::vector<std::uint64_t> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string p = pointer + "/" + std::to_string(i);
      const std::uint64_t x = u64(v[i], p, lo, hi);
      if (std::find(out.begin(), out.end(), x) != out.end()) fail(p, std::to_string(x) + " is listed twice");
      out.push_back(x);
    }
    return out;
  }

  static std::string type_of(const Json& v) {
    if (v.is_number()) return "a number";
    if (v.is_string()) return "a string";
    if (v.is_boolean()) return "a boolean";
    if (v.is_null()) return "null";
    if (v.is_array()) return "an array";
    return "an object";
  }
  static std::string text(const Json& v) {
    std::string s = v.dump();
    return s.size() > 40 ? s.substr(0, 40) + "..." : s;
  }

 private:
  std::string path_;
};

std::string one_of(const std::string& what, const std::string& s, const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), s) != known.end()) return "";
  return "unknown " + what + " '" + s + "' (known: " + join(known) + ")";
}

// `dlab gen` options by name, without the dashes (cli/cmd_gen.cpp).
void read_gen_options(const Reader& r, const Json& o, const std::string& pointer, gen::GenOptions& g) {
  r.only_keys(o, pointer,
              {"off", "ulps", "base", "clusters", "sigma", "copies", "side", "exp", "set", "lo", "hi", "step-exp",
               "sign", "spacing"});
  for (const auto& [key, v] : o.items()) {
    const std::string p = pointer + "/" + token(key);
    if (key == "off") g.off = r.u64(v, p, 0, kMaxN);
    if (key == "ulps") g.ulps = r.i64(v, p, 0, 1 << 20);
    if (key == "base") g.base = r.string(v, p);
    if (key == "clusters") g.clusters = r.u64(v, p, 1, 1u << 24);
    if (key == "sigma") g.sigma = r.real(v, p);
    if (key == "copies") g.copies = r.u64(v, p, 1, kMaxN);
    if (key == "side") g.side = r.u64(v, p, 1, 4096);
    if (key == "exp") {
      g.exp = static_cast<int>(r.i64(v, p, -1074, 1023));
      g.exp_set = true;
    }
    if (key == "step-exp") {
      g.step_exp = static_cast<int>(r.i64(v, p, -1074, 1023));
      g.step_exp_set = true;
    }
    if (key == "set") g.set = r.string(v, p);
    if (key == "lo") g.lo = r.real(v, p);
    if (key == "hi") g.hi = r.real(v, p);
    if (key == "sign") g.sign = r.string(v, p);
    if (key == "spacing") g.spacing = r.real(v, p);
  }
}

InputSpec read_input(const Reader& r, const Json& in, const std::string& pointer) {
  InputSpec s;
  s.pointer = pointer;
  if (!in.is_object()) r.fail(pointer, "must be a JSON object with \"generator\" or \"file\"");
  const bool is_gen = in.contains("generator"), is_file = in.contains("file");
  if (is_gen == is_file) r.fail(pointer, "needs exactly one of \"generator\" and \"file\"");
  if (is_gen) {
    r.only_keys(in, pointer, {"generator", "dimension", "n", "seeds", "options", "label"});
    s.generator = r.string(in["generator"], pointer + "/generator");
    if (const std::string why = one_of("generator", s.generator, gen::generator_names()); !why.empty())
      r.fail(pointer + "/generator", why);
    s.options.name = s.generator;
    if (in.contains("dimension")) {
      s.options.dim = static_cast<int>(r.i64(in["dimension"], pointer + "/dimension", 2, 3));
      if (!gen::generator_has_dimension(s.generator, s.options.dim))
        r.fail(pointer + "/dimension", s.generator + " has no dimension " + std::to_string(s.options.dim));
    }
    if (!in.contains("n")) r.fail(pointer, "missing \"n\" (an integer or an array of integers)");
    s.ns = r.integers(in["n"], pointer + "/n", 1, kMaxN);
    if (in.contains("options")) read_gen_options(r, in["options"], pointer + "/options", s.options);
    s.label = s.generator;
  } else {
    r.only_keys(in, pointer, {"file", "seeds", "label"});
    s.file = r.string(in["file"], pointer + "/file");
    if (s.file.empty()) r.fail(pointer + "/file", "must not be empty");
    s.label = std::filesystem::path(s.file).filename().string();
  }
  s.seeds = in.contains("seeds") ? r.integers(in["seeds"], pointer + "/seeds", 0, UINT64_MAX)
                                 : std::vector<std::uint64_t>{0};
  if (in.contains("label")) {
    s.label = r.string(in["label"], pointer + "/label");
    if (s.label.empty()) r.fail(pointer + "/label", "must not be empty");
  }
  return s;
}

// Duplicate keys are an error (nlohmann-json would keep the last silently).
Json parse_rejecting_duplicates(const std::string& text, const std::string& path) {
  std::vector<std::set<std::string>> keys;
  const Json::parser_callback_t cb = [&](int, Json::parse_event_t ev, Json& value) {
    if (ev == Json::parse_event_t::object_start) keys.emplace_back();
    if (ev == Json::parse_event_t::object_end && !keys.empty()) keys.pop_back();
    if (ev == Json::parse_event_t::key && !keys.empty() && !keys.back().insert(value.get<std::string>()).second)
      throw ConfigError(path + ": key '" + value.get<std::string>() + "' appears twice in one object");
    return true;
  };
  try {
    return Json::parse(text, cb);
  } catch (const Json::parse_error& e) {
    // e.byte: 1-based index of the byte at which parsing stopped.
    // what(): "[json.exception.parse_error.101] parse error at line L, column C: WHY"; keep WHY.
    std::string why = e.what();
    if (const auto at = why.find("parse error"); at != std::string::npos)
      if (const auto colon = why.find(": ", at); colon != std::string::npos) why = why.substr(colon + 2);
    throw ConfigError(path + ":" + line_column(text, e.byte == 0 ? 0 : e.byte - 1) + ": JSON syntax error: " + why);
  }
}

}  // namespace

std::string line_column(const std::string& text, std::size_t offset) {
  offset = std::min(offset, text.size());
  std::size_t line = 1, col = 1;
  for (std::size_t i = 0; i < offset; ++i) {
    if (text[i] == '\n') {
      ++line;
      col = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {  // UTF-8: count characters
      ++col;
    }
  }
  return std::to_string(line) + ":" + std::to_string(col);
}

std::vector<std::string> known_baselines() { return {"cgal-epick", "cgal-epeck", "tetgen", "qhull", "scipy"}; }

StudyConfig parse_config(const std::string& text, const std::string& path) {
  const Reader r(path);
  StudyConfig c;
  c.path = path;
  c.json = parse_rejecting_duplicates(text, path);
  const Json& j = c.json;
  r.only_keys(j, "",
              {"name", "algorithms", "kernels", "orders", "policies", "locations", "inputs", "repeats", "baselines",
               "epeck_max_n", "timeout_seconds", "memory_limit_mib"});
  c.name = j.contains("name") ? r.string(j["name"], "/name") : std::filesystem::path(path).stem().string();
  for (const char* required : {"algorithms", "kernels", "inputs"})
    if (!j.contains(required)) r.fail("", std::string("missing \"") + required + "\"");

  c.algorithms = r.names(j["algorithms"], "/algorithms", [](const std::string& a) -> std::string {
    try {
      fuzz::make_pair(a, "mp");
      return "";
    } catch (const UsageError&) {
      return "unknown algorithm '" + a + "' (known: " + join(algorithm_names()) +
             ", george+exact-sphere, george+enclosing-box, george+exact-sphere+enclosing-box)";
    }
  });
  c.kernels = r.names(j["kernels"], "/kernels", [](const std::string& k) { return one_of("kernel", k, kernel_names()); });
  if (j.contains("orders"))
    c.orders = r.names(j["orders"], "/orders",
                       [](const std::string& o) { return one_of("order", o, {"input", "random", "brio", "hilbert"}); });
  if (j.contains("policies"))
    c.policies = r.names(j["policies"], "/policies",
                         [](const std::string& p) { return one_of("policy", p, {"default", "sos", "strict"}); });
  if (j.contains("locations"))
    c.locations = r.names(j["locations"], "/locations",
                          [](const std::string& l) { return one_of("location", l, {"walk", "scan"}); });

  const Json& inputs = j["inputs"];
  if (!inputs.is_array()) r.fail("/inputs", "must be an array of inputs, not " + Reader::type_of(inputs));
  if (inputs.empty()) r.fail("/inputs", "must not be empty");
  for (std::size_t i = 0; i < inputs.size(); ++i)
    c.inputs.push_back(read_input(r, inputs[i], "/inputs/" + std::to_string(i)));

  if (j.contains("repeats")) c.repeats = static_cast<std::uint32_t>(r.u64(j["repeats"], "/repeats", 1, 1000));
  if (j.contains("baselines"))
    c.baselines = r.names(
        j["baselines"], "/baselines", [](const std::string& b) { return one_of("baseline", b, known_baselines()); },
        true);
  if (j.contains("epeck_max_n")) c.epeck_max_n = r.u64(j["epeck_max_n"], "/epeck_max_n", 0, kMaxN);
  if (j.contains("timeout_seconds")) {
    c.timeout_seconds = r.real(j["timeout_seconds"], "/timeout_seconds");
    if (!(c.timeout_seconds > 0 && c.timeout_seconds <= 86400))
      r.fail("/timeout_seconds", "must be a number of seconds in (0, 86400]");
  }
  if (j.contains("memory_limit_mib"))
    c.memory_limit_mib = r.u64(j["memory_limit_mib"], "/memory_limit_mib", 16, std::uint64_t{1} << 24);
  return c;
}

StudyConfig read_config(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot read the study configuration");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ConfigError(path + ": error reading the study configuration");
  return parse_config(text.str(), path);
}

}  // namespace dlab::study
