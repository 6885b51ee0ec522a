// See mesh_formats.hpp: OFF (Geomview's documentation): "OFF", then
// "<#vertices> <#faces> <#edges>", one "x y z" per vertex, one "3 a b c" per
// triangle. 2D points get z = 0; triangles keep SIMPLICES' counterclockwise order.
#include <string>

#include "cli/mesh_formats.hpp"
#include "cli/numbers.hpp"

namespace dlab::io {

std::string off_text(const PointSet& points, const std::vector<std::uint32_t>* simplices) {
  const std::size_t n = points.size();
  const std::size_t faces = simplices ? simplices->size() / 3 : 0;
  std::string s = "OFF\n" + std::to_string(n) + " " + std::to_string(faces) + " 0\n";
  for (std::size_t i = 0; i < n; ++i) {
    for (int c = 0; c < 3; ++c) {
      const double x = points.dimension == 2 ? (c < 2 ? points.p2[i][c] : 0.0) : points.p3[i][c];
      s += format_decimal(x);
      s += c == 2 ? '\n' : ' ';
    }
  }
  for (std::size_t f = 0; f < faces; ++f)
    s += "3 " + std::to_string((*simplices)[3 * f]) + ' ' + std::to_string((*simplices)[3 * f + 1]) +
         ' ' + std::to_string((*simplices)[3 * f + 2]) + '\n';
  return s;
}

}  // namespace dlab::io
