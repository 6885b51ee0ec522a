// See runs_file.hpp.
#include "studies/runs_file.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "studies/columns.hpp"
#include "studies/config.hpp"

namespace dlab::study {

RunsFile read_runs(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path + ": cannot read");
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  RunsFile f;
  const std::string header = csv_header();
  const std::size_t columns = column_count();
  std::size_t start = 0, line = 0;
  for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1) {
    ++line;
    const std::string l = text.substr(start, nl - start);
    const std::string where = path + ":" + std::to_string(line) + ": ";
    if (line == 1) {
      if (l != header)
        throw ConfigError(where + "not the header of this dlab's runs.csv (a study of another version?)");
    } else {
      std::vector<std::string> cells;
      try {
        cells = csv_split(l);
      } catch (const std::invalid_argument& e) {
        throw ConfigError(where + "malformed row: " + e.what());
      }
      if (cells.size() != columns)
        throw ConfigError(where + "a row of " + std::to_string(cells.size()) + " fields, not " +
                          std::to_string(columns));
      const std::string& id = cells[0];
      if (id.empty() || id.size() > 19 || id.find_first_not_of("0123456789") != std::string::npos)
        throw ConfigError(where + "run id '" + id + "' is not a number");
      if (!f.rows.emplace(std::stoull(id), l).second) throw ConfigError(where + "run " + id + " appears twice");
    }
    f.bytes = nl + 1;
  }
  f.partial_line = f.bytes < text.size();
  return f;
}

std::string field(const std::string& row, const std::string& name) {
  const auto& cols = leading_columns();
  const auto it = std::find(cols.begin(), cols.end(), name);
  if (it == cols.end()) throw std::out_of_range("no leading column " + name);
  return csv_split(row).at(static_cast<std::size_t>(it - cols.begin()));
}

}  // namespace dlab::study
