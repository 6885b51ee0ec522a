// Named counters of a run (predicate calls, algorithm steps), in a fixed order
// so that --stats output is byte-identical.
#pragma once
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace dlab {

using Counters = std::vector<std::pair<std::string, std::uint64_t>>;

}  // namespace dlab
