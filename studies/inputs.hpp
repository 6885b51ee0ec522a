// The point sets of a study's inputs: generated (fuzz/generators.hpp) or read
// from a file with the reader of `dlab triangulate` (cli/point_reader.hpp).
#pragma once
#include <cstdint>

#include "studies/config.hpp"
#include "variants/run.hpp"

namespace dlab::study {

// The points of `input` at size n and seed (a file input ignores both).
// Throws ConfigError naming the input's pointer when the generator refuses
// its options or the file cannot be read.
PointSet load_input(const InputSpec& input, std::uint64_t n, std::uint64_t seed, const std::string& config_path);

// Reads every file input once and generates every generator input at its
// smallest and largest n and first seed, so that a bad file, option or size is an error
// before the first run: sets each input's dimension, and a file input's ns to
// {its point count}. Throws ConfigError.
void check_inputs(StudyConfig& config);

}  // namespace dlab::study
