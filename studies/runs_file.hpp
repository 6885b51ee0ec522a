// Reading DIR/runs.csv back: to resume a study (which runs are done) and to
// merge shards. The header must be this build's (studies/columns.hpp); every
// complete line must be a row of that many fields with a unique run id. A
// last line without its newline -- cut by a kill -- is not a row: `bytes`
// stops before it, and a resumed study truncates the file there.
#pragma once
#include <cstdint>
#include <map>
#include <string>

namespace dlab::study {

struct RunsFile {
  std::map<std::uint64_t, std::string> rows;  // run id -> the line, without newline
  std::uint64_t bytes = 0;                     // the header and the complete rows
  bool partial_line = false;                   // a cut last line was left out
};

// Throws ConfigError "FILE:LINE: problem".
RunsFile read_runs(const std::string& path);

// The field of a row in column `name` (a leading column); throws std::out_of_range.
std::string field(const std::string& row, const std::string& name);

}  // namespace dlab::study
