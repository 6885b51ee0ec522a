// See point_writer.hpp.
#include "cli/point_writer.hpp"

#include <string>

#include "cli/numbers.hpp"

namespace dlab::io {
namespace {

template <int D>
void write_any(std::ostream& out, std::span<const Point<D>> pts, FloatFormat f) {
  std::string buf;
  for (const auto& p : pts) {
    for (int i = 0; i < D; ++i) {
      buf += f == FloatFormat::hex ? format_hex(p[i]) : format_decimal(p[i]);
      buf += i + 1 == D ? '\n' : ' ';
    }
    if (buf.size() > (1 << 16)) {
      out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
      buf.clear();
    }
  }
  out.write(buf.data(), static_cast<std::streamsize>(buf.size()));
}

}  // namespace

void write_points(std::ostream& out, std::span<const Point2> pts, FloatFormat f) {
  write_any<2>(out, pts, f);
}
void write_points(std::ostream& out, std::span<const Point3> pts, FloatFormat f) {
  write_any<3>(out, pts, f);
}
void write_points(std::ostream& out, const PointSet& ps, FloatFormat f) {
  if (ps.dimension == 2) write_points(out, std::span<const Point2>(ps.p2), f);
  else write_points(out, std::span<const Point3>(ps.p3), f);
}

}  // namespace dlab::io
