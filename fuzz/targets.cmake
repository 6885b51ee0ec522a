# Coverage-guided fuzz targets (fuzz/README.md), included from fuzz/CMakeLists.txt.
#   fuzz_point_reader     the INPUT reader: bytes -> points or a clear error
#   fuzz_triangulate_2d   bytes -> degenerate-prone 2D point set -> every pair
#   fuzz_triangulate_3d   the same in 3D
# With -DDLAB_FUZZ=ON (clang or afl-clang-fast++; the top-level CMakeLists.txt
# instruments every library) they link the fuzzing engine (DLAB_FUZZ_ENGINE);
# otherwise, when the tests are built, they link fuzz/replay_main.cpp and ctest
# replays their seeds (label fuzz-seeds).
add_library(dlab_fuzz_targets STATIC byte_decoder.cpp all_pairs_check.cpp triangulate_target.cpp)
target_link_libraries(dlab_fuzz_targets PUBLIC dlab_generators dlab_fuzz_campaign dlab_core dlab_validate)

set(dlab_fuzz_targets fuzz_point_reader fuzz_triangulate_2d fuzz_triangulate_3d)
# Seed directories of each target: fuzz/seeds/<target without fuzz_>, and the
# regression corpus for the reader.
set(dlab_fuzz_seeds_fuzz_point_reader ${CMAKE_CURRENT_SOURCE_DIR}/seeds/point_reader
    ${PROJECT_SOURCE_DIR}/tests/corpus)
set(dlab_fuzz_seeds_fuzz_triangulate_2d ${CMAKE_CURRENT_SOURCE_DIR}/seeds/triangulate_2d)
set(dlab_fuzz_seeds_fuzz_triangulate_3d ${CMAKE_CURRENT_SOURCE_DIR}/seeds/triangulate_3d)

if(DLAB_FUZZ OR DLAB_BUILD_TESTS)
  foreach(t IN LISTS dlab_fuzz_targets)
    add_executable(${t} ${t}.cpp)
    if(DLAB_FUZZ)
      separate_arguments(dlab_fuzz_engine UNIX_COMMAND "${DLAB_FUZZ_ENGINE}")
      target_link_options(${t} PRIVATE ${dlab_fuzz_engine})
    else()
      target_sources(${t} PRIVATE replay_main.cpp)
    endif()
  endforeach()
  target_link_libraries(fuzz_point_reader PRIVATE dlab_io)
  target_link_libraries(fuzz_triangulate_2d PRIVATE dlab_fuzz_targets)
  target_link_libraries(fuzz_triangulate_3d PRIVATE dlab_fuzz_targets)
endif()

if(DLAB_FUZZ)
  # ctest -L libfuzzer: each target for DLAB_FUZZ_SMOKE_SECONDS on its seeds
  # (fuzz/smoke_target.sh; fuzz/smoke.sh builds and runs these).
  set(DLAB_FUZZ_SMOKE_SECONDS 20 CACHE STRING "Seconds each libFuzzer target runs under ctest -L libfuzzer")
  foreach(t IN LISTS dlab_fuzz_targets)
    add_test(NAME libfuzzer.${t}
             COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/smoke_target.sh $<TARGET_FILE:${t}>
                     ${CMAKE_CURRENT_BINARY_DIR}/smoke_${t} ${DLAB_FUZZ_SMOKE_SECONDS} ${dlab_fuzz_seeds_${t}})
    set_tests_properties(libfuzzer.${t} PROPERTIES LABELS libfuzzer TIMEOUT 600)
  endforeach()
elseif(DLAB_BUILD_TESTS)
  # The seeds, replayed once: every exact pair gives the reference on them.
  foreach(t IN LISTS dlab_fuzz_targets)
    add_test(NAME fuzz_seeds.${t} COMMAND ${t} ${dlab_fuzz_seeds_${t}})
    set_tests_properties(fuzz_seeds.${t} PROPERTIES LABELS fuzz-seeds TIMEOUT 300)
  endforeach()
endif()
