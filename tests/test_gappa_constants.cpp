// The constants the Gappa proofs in predicates/gappa/ are about are the adaptive
// kernel's own: every script marks each constant it proves with a line
//   name = 0x...p<e>;  # dlab-constant adaptive::<constant>
// and this test reads those lines and checks that the kernel's constant is at least the
// proved one (every script's claim stays true when its constant grows: each bound only
// grows with it). It also checks that every constant listed below is proved by some
// script, so that deleting a script or a marker fails here. The proofs themselves run
// under the ctest label "gappa" (predicates/gappa/CMakeLists.txt).
#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <string>

#include "predicates/adaptive_kernel.hpp"

namespace {

namespace fs = std::filesystem;

fs::path gappa_dir() {
  return fs::path(__FILE__).parent_path().parent_path() / "predicates" / "gappa";
}

// Every constant a script must prove, by the name its marker uses.
const std::map<std::string, double>& kernel_constants() {
  using namespace dlab::adaptive;
  static const std::map<std::string, double> m = {
      {"adaptive::o3_ss8", o3_ss8},       {"adaptive::is_lift128", is_lift128},
      {"adaptive::ic_lift_filter", ic_lift_filter},
      {"adaptive::o2_fast", o2_fast},     {"adaptive::o2_fast_abs", o2_fast_abs},
      {"adaptive::o2A", o2A},             {"adaptive::o3A", o3A},
      {"adaptive::icA", icA},             {"adaptive::isA", isA},
      {"adaptive::o2B", o2B},             {"adaptive::o3B", o3B},
      {"adaptive::icB", icB},             {"adaptive::isB", isB},
      {"adaptive::o2C", o2C},             {"adaptive::o3C", o3C},
      {"adaptive::icC", icC},             {"adaptive::isC", isC},
      {"adaptive::result_err", result_err},
  };
  return m;
}

}  // namespace

TEST_CASE("every Gappa script proves a kernel constant no larger than the kernel's") {
  const std::regex marker(R"(^(\w+) = (0x[0-9a-fA-F.]+p[-+]?[0-9]+);\s+# dlab-constant (\S+).*$)");
  std::map<std::string, int> proved;
  int scripts = 0;
  REQUIRE(fs::is_directory(gappa_dir()));
  for (const auto& entry : fs::directory_iterator(gappa_dir())) {
    if (entry.path().extension() != ".g") continue;
    ++scripts;
    std::ifstream in(entry.path());
    std::string line;
    int markers = 0;
    while (std::getline(in, line)) {
      std::smatch m;
      if (!std::regex_match(line, m, marker)) continue;
      ++markers;
      INFO(entry.path().filename().string() << ": " << line);
      const auto it = kernel_constants().find(m[3]);
      REQUIRE(it != kernel_constants().end());
      char* end = nullptr;
      const std::string hex = m[2];
      const double in_script = std::strtod(hex.c_str(), &end);  // hex: exact
      REQUIRE(end == hex.c_str() + hex.size());
      CHECK(in_script > 0);
      CHECK(it->second >= in_script);
      ++proved[it->first];
    }
    INFO(entry.path().filename().string());
    CHECK(markers >= 1);
  }
  CHECK(scripts >= 17);
  for (const auto& [name, value] : kernel_constants()) {
    INFO(name);
    CHECK(proved[name] >= 1);
  }
}
