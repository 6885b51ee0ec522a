// See args.hpp.
#include "cli/args.hpp"

#include "cli/numbers.hpp"

namespace dlab::cli {

std::optional<std::string> Args::get(const std::string& opt) const {
  auto it = values.find(opt);
  if (it == values.end()) return std::nullopt;
  return it->second;
}

std::uint64_t Args::u64(const std::string& opt, std::uint64_t fallback, std::uint64_t max) const {
  auto v = get(opt);
  if (!v) return fallback;
  auto r = io::parse_u64(*v, max);
  if (!r)
    throw UsageError(opt + ": '" + *v + "' is not an integer in 0.." + std::to_string(max));
  return *r;
}

std::int64_t Args::i64(const std::string& opt, std::int64_t fallback, std::int64_t lo,
                       std::int64_t hi) const {
  auto v = get(opt);
  if (!v) return fallback;
  std::string_view s = *v;
  const bool neg = !s.empty() && s.front() == '-';
  if (neg) s.remove_prefix(1);
  auto r = io::parse_u64(s, std::uint64_t{1} << 62);
  const std::int64_t x = r ? (neg ? -static_cast<std::int64_t>(*r) : static_cast<std::int64_t>(*r)) : 0;
  if (!r || x < lo || x > hi)
    throw UsageError(opt + ": '" + *v + "' is not an integer in " + std::to_string(lo) + ".." +
                     std::to_string(hi));
  return x;
}

double Args::real(const std::string& opt, double fallback) const {
  auto v = get(opt);
  if (!v) return fallback;
  auto p = io::parse_double(*v);
  if (p.status != io::ParseStatus::ok) throw UsageError(opt + ": " + io::describe(p.status, *v));
  return p.value;
}

namespace {
bool looks_like_option(const std::string& a) {
  if (a.size() < 2 || a[0] != '-') return false;
  const char c = a[1];
  return !(c == '.' || (c >= '0' && c <= '9'));
}
}  // namespace

Args parse_args(int argc, char** argv, int first, const std::set<std::string>& with_value,
                const std::set<std::string>& flag_names) {
  Args a;
  bool only_positional = false;
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    if (only_positional || !looks_like_option(arg)) {
      a.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      only_positional = true;
      continue;
    }
    std::optional<std::string> inline_value;
    if (auto eq = arg.find('='); arg.rfind("--", 0) == 0 && eq != std::string::npos) {
      inline_value = arg.substr(eq + 1);
      arg = arg.substr(0, eq);
    }
    if (with_value.count(arg)) {
      if (inline_value) {
        a.values[arg] = *inline_value;
      } else {
        if (i + 1 >= argc) throw UsageError("option " + arg + " needs a value");
        a.values[arg] = argv[++i];
      }
    } else if (flag_names.count(arg)) {
      if (inline_value) throw UsageError("option " + arg + " takes no value");
      a.flags.insert(arg);
    } else {
      throw UsageError("unknown option '" + arg + "'");
    }
  }
  return a;
}

}  // namespace dlab::cli
