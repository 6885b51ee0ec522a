// See selftest.hpp.
#include "fuzz/selftest.hpp"

#include <cstdlib>
#include <cstring>
#include <new>

#include "fuzz/child_limits.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

std::vector<Misbehaviour> parse_selftest(std::string_view spec) {
  std::vector<Misbehaviour> out;
  while (!spec.empty()) {
    const auto comma = spec.find(',');
    const std::string_view item = spec.substr(0, comma);
    spec = comma == std::string_view::npos ? std::string_view{} : spec.substr(comma + 1);
    const auto at = item.find('@');
    const auto colon = item.find(':');
    const auto bad = [&] {
      return UsageError(std::string(kSelftestVariable) + ": '" + std::string(item) +
                        "' is not ACTION@CASE:[ALGO/]KERNEL (ACTION crash, hang, allocate or unperturbed)");
    };
    if (at == std::string_view::npos || colon == std::string_view::npos || colon < at) throw bad();
    Misbehaviour m;
    m.action = std::string(item.substr(0, at));
    const std::string_view digits = item.substr(at + 1, colon - at - 1);
    if (digits.empty() || digits.size() > 18) throw bad();
    for (char c : digits) {
      if (c < '0' || c > '9') throw bad();
      m.case_index = m.case_index * 10 + static_cast<std::uint64_t>(c - '0');
    }
    m.kernel = std::string(item.substr(colon + 1));
    if (const auto slash = m.kernel.find('/'); slash != std::string::npos) {
      m.algo = m.kernel.substr(0, slash);
      m.kernel.erase(0, slash + 1);
      if (m.algo.empty()) throw bad();
    }
    if (m.action != "crash" && m.action != "hang" && m.action != "allocate" && m.action != "unperturbed")
      throw bad();
    if (m.action == "allocate" && !memory_limit_enforced())
      throw UsageError(std::string(kSelftestVariable) +
                       ": allocate needs the memory limit, which this (sanitizer) build does not enforce");
    out.push_back(m);
  }
  return out;
}

namespace {

bool matches(const Misbehaviour& m, std::uint64_t case_index, const Pair& p) {
  return m.case_index == case_index && m.kernel == p.kernel && (m.algo.empty() || m.algo == p.algo_name());
}

}  // namespace

void maybe_misbehave(const std::vector<Misbehaviour>& ms, std::uint64_t case_index, const Pair& pair) {
  for (const auto& m : ms) {
    if (!matches(m, case_index, pair)) continue;
    if (m.action == "crash") std::abort();
    if (m.action == "hang") {
      volatile std::uint64_t x = 0;
      for (;;) x = x + 1;  // stopped by RLIMIT_CPU (SIGXCPU)
    }
    if (m.action == "allocate") {
      for (;;) {  // stopped by RLIMIT_AS: operator new's handler ends the child
        char* p = new char[std::size_t{64} << 20];
        std::memset(p, 1, std::size_t{64} << 20);
      }
    }
  }
}

bool runs_unperturbed(const std::vector<Misbehaviour>& ms, std::uint64_t case_index, const Pair& pair) {
  for (const auto& m : ms)
    if (m.action == "unperturbed" && matches(m, case_index, pair)) return true;
  return false;
}

Pair unperturbed(const Pair& p) {
  Pair q = p;
  q.unperturbed = true;
  return q;
}

}  // namespace dlab::fuzz
