// `dlab --version` (also `dlab version`): the project version (CMake's
// project(VERSION)), the git commit the build was configured from, and the
// compiler. The commit is recorded when CMake configures, not at each build.
#include <iostream>

#include "cli/cli_app.hpp"
#include "cli/commands.hpp"
#include "dlab_version.hpp"

namespace dlab::cli {

int cmd_version(int argc, char** argv) {
  CommandLine cl("--version", "usage: dlab --version\n       dlab version\n",
                 "Prints the project version, the git commit the build was configured from (with\n"
                 "uncommitted changes, if any: recorded when CMake configures, not at each build) and\n"
                 "the compiler, C++ standard and build type.\n",
                 "  dlab --version\n"
                 "  dlab version | head -1\n",
                 "Exit status: 0, 2 bad usage.\n");
  if (auto rc = cl.parse(argc, argv, 2)) return *rc;
  std::cout << "dlab " << build_info::kVersion << " (delaunay-lab)\n"
            << "commit " << build_info::kCommit
            << (build_info::kCommitDirty ? " with uncommitted changes" : "") << " (at build time)\n"
            << "compiler " << build_info::kCompiler << ", C++" << __cplusplus / 100 % 100 << ", "
            << build_info::kBuildType << " build\n";
  return 0;
}

}  // namespace dlab::cli
