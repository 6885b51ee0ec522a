// See inputs.hpp.
#include "studies/inputs.hpp"

#include <algorithm>
#include <stdexcept>

#include "cli/point_reader.hpp"

namespace dlab::study {

PointSet load_input(const InputSpec& input, std::uint64_t n, std::uint64_t seed, const std::string& config_path) {
  if (!input.file.empty()) {
    try {
      return io::read_points(input.file);
    } catch (const io::InputError& e) {
      throw ConfigError(config_path + ": " + input.pointer + "/file: " + e.what());
    }
  }
  gen::GenOptions o = input.options;
  o.n = n;
  o.seed = seed;
  try {
    return gen::generate(o);
  } catch (const std::invalid_argument& e) {
    throw ConfigError(config_path + ": " + input.pointer + ": the generator refuses n = " + std::to_string(n) +
                      ", seed " + std::to_string(seed) + ": " + e.what());
  }
}

void check_inputs(StudyConfig& config) {
  for (InputSpec& in : config.inputs) {
    if (!in.file.empty()) {
      const PointSet ps = load_input(in, 0, 0, config.path);
      in.dimension = ps.dimension;
      in.ns = {ps.size()};
      continue;
    }
    // The extremes of n: a generator that refuses a size usually refuses the large one.
    const auto [lo, hi] = std::minmax_element(in.ns.begin(), in.ns.end());
    in.dimension = load_input(in, *lo, in.seeds.front(), config.path).dimension;
    if (*hi != *lo) load_input(in, *hi, in.seeds.front(), config.path);
  }
}

}  // namespace dlab::study
