// A study's configuration (studies/README.md "Config"): parsed from JSON with
// nlohmann-json, every key checked for name, type and range. Anything wrong is
// a ConfigError whose message names the file and the key as a JSON pointer
// ("study.json: /inputs/1/n: ..."), or the line and column of a JSON syntax
// error ("study.json:3:17: ..."); the command reports it with exit status 2.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fuzz/generators.hpp"

namespace dlab::study {

struct ConfigError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One element of "inputs": a generator (n-major, then seed) or a point file.
struct InputSpec {
  std::string pointer;             // "/inputs/3", for messages
  std::string label;               // the `input` column: "label", else the generator name or the file's name
  std::string generator;           // empty for a file input
  gen::GenOptions options;         // generator inputs: everything but n and seed
  std::string file;                // file inputs: the path as given (relative to the working directory)
  std::vector<std::uint64_t> ns;   // generator inputs; file inputs: {point count} once checked
  std::vector<std::uint64_t> seeds;  // generator and order seed (file inputs: the order seed only)
  int dimension = 0;               // known after check_inputs()
};

struct StudyConfig {
  std::string path;          // as given, for messages ("<default>" for the built-in one)
  nlohmann::ordered_json json;  // the document, in its own key order (meta.json stores it)
  std::string name;
  std::vector<std::string> algorithms;  // pair names: "bowyer-watson", "george+exact-sphere", ...
  std::vector<std::string> kernels;
  std::vector<std::string> orders{"brio"};
  std::vector<std::string> policies{"default"};
  std::vector<std::string> locations{"walk"};
  std::vector<InputSpec> inputs;
  std::uint32_t repeats = 1;
  std::vector<std::string> baselines;
  std::uint64_t epeck_max_n = 10000;
  double timeout_seconds = 60;
  std::uint64_t memory_limit_mib = 4096;
};

// Parses `text` (the content of `path`). Throws ConfigError.
StudyConfig parse_config(const std::string& text, const std::string& path);
// Reads and parses a file. Throws ConfigError (also for an unreadable file).
StudyConfig read_config(const std::string& path);

// The "baselines" names this build knows (studies/baselines.hpp).
std::vector<std::string> known_baselines();

// Byte offset (0-based) -> "LINE:COLUMN" (1-based), for JSON syntax errors.
std::string line_column(const std::string& text, std::size_t offset);

}  // namespace dlab::study
