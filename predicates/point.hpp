// Points are plain arrays of doubles; the dimension D is 2 or 3.
#pragma once
#include <array>

namespace dlab {

template <int D>
using Point = std::array<double, D>;
using Point2 = Point<2>;
using Point3 = Point<3>;

}  // namespace dlab
