// SIMPLICES files (design.md section 5): one simplex per line, d+1 zero-based
// indices into the INPUT points, separated by blanks; '#' comments and blank
// lines are allowed when reading.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace dlab::io {

// Writes simplices.size()/(dimension+1) lines.
void write_simplices(std::ostream& out, const std::vector<std::uint32_t>& simplices, int dimension);

// Reads "FILE" ("-" = stdin); every line must hold exactly dimension+1 indices,
// each < point_count. Errors are InputError("FILE:LINE: problem").
std::vector<std::uint32_t> read_simplices(const std::string& path, int dimension,
                                          std::size_t point_count);
std::vector<std::uint32_t> parse_simplices(std::string_view text, const std::string& name,
                                           int dimension, std::size_t point_count);

}  // namespace dlab::io
