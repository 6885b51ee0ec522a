// The mesh a failing pair makes of a failure's points, for its picture
// (DIR/failures/*.svg in 2D, *.vtu in 3D: cli/mesh_picture.hpp). The pair runs
// in a forked child under the campaign's limits (fuzz/child_limits.hpp), as
// every case x pair does, so a pair that crashes or spins on these points
// costs a missing picture, never the campaign.
#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "fuzz/campaign_spec.hpp"
#include "fuzz/isolation.hpp"
#include "variants/run.hpp"

namespace dlab::fuzz {

struct FailureMesh {
  PointSet points;  // the points triangulated (the integer kernel's snapped ones)
  std::vector<std::uint32_t> simplices;
};

// Nothing when the run fails (an exception, a reported failure), dies, or
// outlives 10 x the CPU limit + 10 s of wall time. Throws std::runtime_error
// if it cannot fork.
std::optional<FailureMesh> failure_mesh(const PointSet& points, const Pair& pair, std::uint64_t order_seed,
                                        const Limits& limits);

}  // namespace dlab::fuzz
