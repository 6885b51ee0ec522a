// Kernel by name, for the commands that call predicates directly (`dlab
// predicate`, the demo); an unknown name is a UsageError.
#pragma once
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "predicates/adaptive_kernel.hpp"
#include "predicates/epsilon_kernel.hpp"
#include "predicates/float_kernel.hpp"
#include "predicates/integer_kernel.hpp"
#include "predicates/mp_kernel.hpp"
#include "variants/run.hpp"

namespace dlab::cli {

// The kernel names of design.md section 5, in the order the demo prints them.
inline std::vector<std::string> all_kernel_names() {
  return {"float", "epsilon", "adaptive", "integer", "mp"};
}

inline bool kernel_available(std::string_view name) {
  for (const auto& k : all_kernel_names())
    if (name == k) return true;
  return false;
}

using dlab::kernel_is_exact;  // variants/run.hpp

// Calls f(kernel) with the kernel named `name`. The integer kernel's grid is
// fitted to `pts` (the points of the call), so it answers for those points
// snapped to that grid.
template <int D, class F>
decltype(auto) with_kernel(std::string_view name, std::span<const Point<D>> pts, F&& f) {
  if (name == "float") return f(FloatKernel{});
  if (name == "mp") return f(MpKernel{});
  if (name == "epsilon") return f(EpsilonKernel{});
  if (name == "integer") return f(IntegerKernel::fit<D>(pts));
  if (name == "adaptive") return f(AdaptiveKernel{});
  throw UsageError("unknown kernel '" + std::string(name) +
                   "' (known: adaptive, integer, mp, float, epsilon)");
}

}  // namespace dlab::cli
