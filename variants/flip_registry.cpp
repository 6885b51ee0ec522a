// Kernel name -> the translation unit that flips with it (variants/flip.hpp).
#include <string>

#include "variants/flip.hpp"

namespace dlab {

RunResult run_flip_adaptive(const PointSet&, std::span<const std::uint32_t>);
RunResult run_flip_integer(const PointSet&, std::span<const std::uint32_t>);
RunResult run_flip_mp(const PointSet&, std::span<const std::uint32_t>);
RunResult run_flip_float(const PointSet&, std::span<const std::uint32_t>);
RunResult run_flip_epsilon(const PointSet&, std::span<const std::uint32_t>);

RunResult run_flip(const PointSet& points, std::span<const std::uint32_t> simplices, const RunOptions& o) {
  if (points.dimension != 2 && points.dimension != 3)
    throw UsageError("dimension must be 2 or 3, not " + std::to_string(points.dimension));
  if (o.kernel == "adaptive") return run_flip_adaptive(points, simplices);
  if (o.kernel == "integer") return run_flip_integer(points, simplices);
  if (o.kernel == "mp") return run_flip_mp(points, simplices);
  if (o.kernel == "float") return run_flip_float(points, simplices);
  if (o.kernel == "epsilon") return run_flip_epsilon(points, simplices);
  throw UsageError("unknown kernel '" + o.kernel + "' (expected adaptive, integer, mp, float or epsilon)");
}

}  // namespace dlab
