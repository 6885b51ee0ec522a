# Runs one Gappa script (ctest label "gappa"; registered by CMakeLists.txt here).
#   -DGAPPA=<gappa or empty> -DSCRIPT=<file.g> -DMODE=prove
#       gappa must prove every goal of the script (exit status 0) and accept every
#       rewriting hint as an identity (no "not trivially equal" warning).
#   -DGAPPA=... -DSCRIPT=... -DMODE=tighten -DCONSTANT=<name> -DWORK=<dir>
#       the same script with the constant <name> (a line `name = 0x...p<e>;  # dlab-constant
#       ...`) divided by 2 -- by 4 where the line ends in `tighten=4` -- must NOT be proved:
#       gappa must exit nonzero and say that a goal was not satisfied (not a syntax error).
if(NOT GAPPA OR NOT EXISTS "${GAPPA}")
  message("gappa is not installed: skipped (apt-get install gappa)")
  return()
endif()

if(MODE STREQUAL "prove")
  execute_process(COMMAND ${GAPPA} ${SCRIPT} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${err}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "gappa did not prove ${SCRIPT} (exit ${rc})")
  endif()
  # A rewriting hint `a -> b` whose sides differ only draws a warning, and gappa still
  # exits 0 using it: such a proof proves nothing.
  if(err MATCHES "not trivially equal")
    message(FATAL_ERROR "${SCRIPT}: a hint's two sides are not equal (see the warning above)")
  endif()
  return()
endif()

if(NOT MODE STREQUAL "tighten")
  message(FATAL_ERROR "MODE must be prove or tighten")
endif()
file(READ ${SCRIPT} text)
string(REPLACE ";" "<semicolon>" text "${text}")  # a ';' would split CMake lists
set(line_re "\n${CONSTANT} = (0x[0-9a-fA-F.]+p)([-+]?[0-9]+)<semicolon>([^\n]*# dlab-constant[^\n]*)")
string(REGEX MATCHALL "${line_re}" lines "${text}")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "${SCRIPT}: expected one `${CONSTANT} = 0x...;  # dlab-constant` line, found ${count}")
endif()
string(REGEX MATCH "${line_re}" line "${text}")
set(mantissa ${CMAKE_MATCH_1})
set(exponent ${CMAKE_MATCH_2})
set(comment "${CMAKE_MATCH_3}")
set(shift 1)
if(comment MATCHES "tighten=4")
  set(shift 2)
endif()
math(EXPR tightened "${exponent} - ${shift}")
string(REPLACE "${line}" "\n${CONSTANT} = ${mantissa}${tightened}<semicolon>${comment}" text "${text}")
string(REPLACE "<semicolon>" ";" text "${text}")
get_filename_component(name ${SCRIPT} NAME_WE)
set(copy ${WORK}/${name}.${CONSTANT}.g)
file(WRITE ${copy} "${text}")
execute_process(COMMAND ${GAPPA} ${copy} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${CONSTANT}: ${mantissa}${exponent} -> ${mantissa}${tightened}\n${err}")
if(rc EQUAL 0)
  message(FATAL_ERROR "gappa still proves ${name} with ${CONSTANT} divided by 2^${shift}: the bound is not tight")
endif()
if(NOT err MATCHES "some properties were not satisfied")
  message(FATAL_ERROR "gappa failed on ${copy} for another reason than an unproved goal")
endif()
