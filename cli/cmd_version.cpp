// `dlab --version` (also `dlab version`): the project version (CMake's
// project(VERSION)), the git commit the build was configured from, and the
// compiler. The commit is recorded when CMake configures, not at each build.
#include <iostream>

#include "cli/commands.hpp"
#include "dlab_version.hpp"

namespace dlab::cli {

int cmd_version(int argc, char**) {
  if (argc > 2) {
    std::cerr << "dlab --version: takes no arguments\n";
    return 2;
  }
  std::cout << "dlab " << build_info::kVersion << " (delaunay-lab)\n"
            << "commit " << build_info::kCommit
            << (build_info::kCommitDirty ? " with uncommitted changes" : "") << " (at configure time)\n"
            << "compiler " << build_info::kCompiler << ", C++" << __cplusplus / 100 % 100 << ", "
            << build_info::kBuildType << " build\n";
  return 0;
}

}  // namespace dlab::cli
