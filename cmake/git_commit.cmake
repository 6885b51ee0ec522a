# Writes OUT, the header with the source tree's git commit and whether tracked
# files differ from it. cli/CMakeLists.txt runs this script at every build, so
# `dlab --version` and a study's meta.json name the commit the binary was built
# from; OUT is replaced only when its text changes (nothing recompiles else).
# Usage: cmake -DSOURCE_DIR=... -DGIT_EXECUTABLE=... -DOUT=... -P git_commit.cmake
set(commit unknown)
set(dirty false)
if(GIT_EXECUTABLE)
  execute_process(COMMAND ${GIT_EXECUTABLE} rev-parse --short=12 HEAD
                  WORKING_DIRECTORY ${SOURCE_DIR} RESULT_VARIABLE rc
                  OUTPUT_VARIABLE out OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(rc EQUAL 0)
    set(commit ${out})
    execute_process(COMMAND ${GIT_EXECUTABLE} status --porcelain --untracked-files=no
                    WORKING_DIRECTORY ${SOURCE_DIR} OUTPUT_VARIABLE status ERROR_QUIET)
    if(NOT status STREQUAL "")
      set(dirty true)
    endif()
  endif()
endif()
file(WRITE ${OUT}.new
"// Generated at build time by cmake/git_commit.cmake: do not edit.
#pragma once

namespace dlab::cli::build_info {

inline constexpr const char* kCommit = \"${commit}\";  // \"unknown\" outside a git checkout
inline constexpr bool kCommitDirty = ${dirty};       // tracked files differed from it

}  // namespace dlab::cli::build_info
")
execute_process(COMMAND ${CMAKE_COMMAND} -E copy_if_different ${OUT}.new ${OUT})
file(REMOVE ${OUT}.new)
