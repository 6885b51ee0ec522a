# External baselines of `dlab study` (studies/baselines.hpp), included by
# studies/CMakeLists.txt: CGAL in process (baselines_cgal.cpp is the only
# translation unit here that includes CGAL), TetGen, Qhull and scipy as child
# processes.
find_package(CGAL QUIET)
add_library(dlab_baselines STATIC
  ${CMAKE_CURRENT_LIST_DIR}/baselines.cpp
  ${CMAKE_CURRENT_LIST_DIR}/baselines_process.cpp
  ${CMAKE_CURRENT_LIST_DIR}/baselines_cgal.cpp
  ${CMAKE_CURRENT_LIST_DIR}/baselines_tetgen.cpp
  ${CMAKE_CURRENT_LIST_DIR}/baselines_qhull.cpp
  ${CMAKE_CURRENT_LIST_DIR}/baselines_scipy.cpp
)
target_include_directories(dlab_baselines PUBLIC ${PROJECT_SOURCE_DIR})
target_link_libraries(dlab_baselines PUBLIC dlab_core dlab_validate)
target_compile_definitions(dlab_baselines PRIVATE
  DLAB_SCIPY_SCRIPT="${CMAKE_CURRENT_LIST_DIR}/baselines/scipy_delaunay.py")
if(CGAL_FOUND)
  target_link_libraries(dlab_baselines PRIVATE CGAL::CGAL)
  target_compile_definitions(dlab_baselines PRIVATE DLAB_HAVE_CGAL=1)
else()
  message(STATUS "CGAL not found: the cgal-epick and cgal-epeck baselines are unavailable")
endif()
