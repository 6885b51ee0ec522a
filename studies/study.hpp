// `dlab study` and `dlab study merge` (studies/README.md): the entry point of
// studies/. run_study() runs the shard's runs of a configuration in child
// processes (studies/run_child.hpp), `jobs` at a time, and appends one row per
// run to DIR/runs.csv in run-id order; DIR/meta.json records the config and
// the machine. A directory that already holds the same study (same config,
// same shard) is resumed: its complete rows are kept, a cut last line is
// dropped, and only the missing runs are run.
//
// Exit status: 0; 1 when a pair that promises a Delaunay triangulation (an
// exact kernel; variants/outcome.hpp's pair_is_exact) has a row whose outcome
// is neither ok nor lower-dimensional (design.md 5.1). Errors of the config,
// the directory or the shard are ConfigError (exit 2).
#pragma once
#include <ostream>
#include <string>
#include <vector>

#include "studies/config.hpp"
#include "studies/matrix.hpp"
#include "studies/meta.hpp"

namespace dlab::study {

struct StudyOptions {
  StudyConfig config;  // parsed (check_inputs is run_study's business)
  std::string dir;
  Shard shard;
  unsigned jobs = 1;
  BuildInfo build;
};

// `out` gets the summary, `err` notices and the progress line's neighbours.
int run_study(StudyOptions options, std::ostream& out, std::ostream& err);

// Shard directories (all n shards of one study, each complete) -> `out_dir`
// with the rows of all of them in run-id order: the unsharded runs.csv apart
// from the measured columns. Throws ConfigError.
int merge_studies(const std::vector<std::string>& dirs, const std::string& out_dir, const BuildInfo& build,
                  std::ostream& out, std::ostream& err);

}  // namespace dlab::study
