// Writing point sets: one point per line, coordinates separated by one blank,
// as hexadecimal floats (exact, the default for --points-out and `dlab gen`)
// or as shortest round-trip decimals (also exact). Both are read back bit for
// bit by the INPUT reader.
#pragma once
#include <ostream>
#include <span>

#include "predicates/point.hpp"
#include "variants/run.hpp"

namespace dlab::io {

enum class FloatFormat { hex, decimal };

void write_points(std::ostream& out, std::span<const Point2> pts, FloatFormat f = FloatFormat::hex);
void write_points(std::ostream& out, std::span<const Point3> pts, FloatFormat f = FloatFormat::hex);
void write_points(std::ostream& out, const PointSet& ps, FloatFormat f = FloatFormat::hex);

}  // namespace dlab::io
