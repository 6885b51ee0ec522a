// Reading INPUT point sets (design.md section 5):
//  * plain text: one point per line, 2 or 3 coordinates separated by blanks
//    and/or commas, decimal or C99 hexadecimal floats, '#' starts a comment,
//    blank lines ignored; the dimension is the number of coordinates on the
//    first data line and every data line must agree;
//  * Triangle / TetGen .node files (chosen by the file name's extension):
//    header "<#points> <dimension> <#attributes> <#boundary markers>", then
//    "index x y [z] [attributes...] [marker]" with indices numbered
//    consecutively from 0 or from 1;
//  * the vertex lists of .xyz, .off and ASCII .ply files (mesh_formats.hpp).
// Every problem is an InputError whose message is "FILE:LINE: problem" (or
// "FILE: problem" when no line applies, e.g. a file that cannot be opened).
#pragma once
#include <cstddef>
#include <istream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "variants/run.hpp"

namespace dlab::io {

// Bad input: the command reports what() and exits with status 2.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The longest line the readers accept (a comment included): a point needs a
// few dozen bytes, so a longer line is refused, as "FILE:LINE: line longer than
// ...", before more of it is read; the reader's memory stays bounded.
inline constexpr std::size_t kMaxLineBytes = std::size_t{1} << 20;

// "-" reads standard input (always the plain text format).
PointSet read_points(const std::string& path);

// The INPUT formats by name, as --input-format takes them: text, node, and the
// vertex lists xyz, off, ply (mesh_formats.hpp).
inline constexpr const char* kInputFormats[] = {"text", "node", "xyz", "off", "ply"};
// The format of a path by its extension: node, xyz, off, ply, else text.
std::string input_format_of(std::string_view path);
// Reads `path` ("-": standard input) in `format` (one of kInputFormats), or by
// its extension when `format` is empty; an unknown name is an InputError
// naming the choices.
PointSet read_points(const std::string& path, std::string_view format);

// Reads a stream in chunks (never whole); `name` is used in messages only.
PointSet read_points(std::istream& in, const std::string& name, bool node_format);

// Parses text already in memory; `name` is used in messages only.
// Never crashes on any byte sequence: every failure is an InputError.
PointSet parse_points(std::string_view text, const std::string& name, bool node_format);

// True if the path ends in ".node" (any case).
bool is_node_file(std::string_view path);

// Reads a whole file ("-": standard input); InputError "FILE: cannot read: reason".
std::string read_file(const std::string& path);

// The name used in messages for a path ("-" is "<stdin>").
std::string display_name(const std::string& path);

}  // namespace dlab::io
