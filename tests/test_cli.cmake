# Exit codes and messages of the `dlab` command (design.md section 5), run by
# ctest as:  cmake -DDLAB=<path to dlab> -DWORK=<scratch dir> -P test_cli.cmake
# Each case runs dlab, then checks the exit status (0, 1, 2; a crash shows up
# as a non-numeric status and fails every case) and a regex on stderr/stdout.
cmake_minimum_required(VERSION 3.25)
if(NOT DLAB OR NOT WORK)
  message(FATAL_ERROR "usage: cmake -DDLAB=... -DWORK=... -P test_cli.cmake")
endif()
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(failures 0)

# Contents of a file the run should have written ("<missing FILE>" if not).
function(read_output var path)
  if(EXISTS "${path}")
    file(READ "${path}" content)
  else()
    set(content "<missing ${path}>")
  endif()
  set(${var} "${content}" PARENT_SCOPE)
endfunction()

# dlab_case(NAME RC <expected status> [ERR <regex>] [OUT <regex>] [IN <stdin file>] ARGS ...)
function(dlab_case name)
  cmake_parse_arguments(C "" "RC;ERR;OUT;IN" "ARGS" ${ARGN})
  set(extra)
  if(C_IN)
    set(extra INPUT_FILE "${C_IN}")
  endif()
  execute_process(COMMAND "${DLAB}" ${C_ARGS} WORKING_DIRECTORY "${WORK}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err ${extra}
                  TIMEOUT 120)
  set(ok TRUE)
  if(NOT "${rc}" STREQUAL "${C_RC}")
    set(ok FALSE)
  endif()
  if(DEFINED C_ERR AND NOT err MATCHES "${C_ERR}")
    set(ok FALSE)
  endif()
  if(DEFINED C_OUT AND NOT out MATCHES "${C_OUT}")
    set(ok FALSE)
  endif()
  if(ok)
    message(STATUS "ok   ${name}")
  else()
    message(STATUS "FAIL ${name}: dlab ${C_ARGS}\n  status ${rc} (want ${C_RC})\n  stdout: ${out}\n  stderr: ${err}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  endif()
  set(last_out "${out}" PARENT_SCOPE)
endfunction()

# ---- inputs -----------------------------------------------------------------
file(WRITE "${WORK}/square.txt" "# unit square and its centre\n0 0\n1 0\n1 1\n0 1\n0.5 0.5\n")
file(WRITE "${WORK}/hex.txt" "0x0p+0, 0x0p+0\n0x1p+0, 0\n0x1p+0 0x1p+0\n0 0x1.0p0\n0x1p-1 0x1p-1\n")
file(WRITE "${WORK}/nan.txt" "0 0\n1 nan\n")
file(WRITE "${WORK}/inf.txt" "0 0\n1 0\n\n-inf 1\n")
file(WRITE "${WORK}/count.txt" "0 0\n1 0\n1 1 1\n")
file(WRITE "${WORK}/junk.txt" "0 0\n1 0x\n")
file(WRITE "${WORK}/empty.txt" "# nothing here\n")
file(WRITE "${WORK}/dim4.txt" "1 2 3 4\n")
file(WRITE "${WORK}/collinear.txt" "0 0\n1 1\n2 2\n3 3\n")
file(WRITE "${WORK}/dups.txt" "0 0\n1 0\n0 1\n1 0\n")
file(WRITE "${WORK}/square.node" "5 2 0 1\n1 0 0 1\n2 1 0 1\n3 1 1 1\n4 0 1 1\n5 0.5 0.5 0\n")
file(WRITE "${WORK}/short.node" "3 2 0 0\n0 0 0\n1 1 0\n")
file(WRITE "${WORK}/cube.txt" "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 0 1\n1 0 1\n0 1 1\n1 1 1\n0.5 0.5 0.5\n")
# A kite whose Delaunay triangulation uses the short diagonal 2-3 ...
file(WRITE "${WORK}/kite.txt" "0 0\n4 0\n2 1\n2 -1\n")
file(WRITE "${WORK}/kite_delaunay.txt" "0 3 2\n3 1 2\n")
# ... and a valid but non-Delaunay triangulation of it (long diagonal 0-1),
file(WRITE "${WORK}/kite_bad.txt" "0 1 2\n0 3 1\n")
# ... an invalid one (clockwise), and one with a bad index.
file(WRITE "${WORK}/kite_cw.txt" "0 2 3\n3 2 1\n")
file(WRITE "${WORK}/kite_range.txt" "0 3 2\n3 1 9\n")
file(WRITE "${WORK}/kite_short.txt" "0 3\n")

# ---- bad input and usage: exit 2, message names file:line and the problem ----
dlab_case(no_command RC 2 ERR "usage:")
dlab_case(unknown_command RC 2 ERR "unknown command 'frobnicate'" ARGS frobnicate)
dlab_case(nan RC 2 ERR "nan.txt:2: NaN coordinate 'nan'" ARGS triangulate nan.txt)
dlab_case(infinity RC 2 ERR "inf.txt:4: infinite coordinate '-inf'" ARGS triangulate inf.txt)
dlab_case(coordinate_count RC 2 ERR "count.txt:3: wrong number of coordinates: expected 2" ARGS triangulate count.txt)
dlab_case(unparsable RC 2 ERR "junk.txt:2: unparsable number '0x'" ARGS triangulate junk.txt)
dlab_case(empty RC 2 ERR "empty.txt:1: empty input" ARGS triangulate empty.txt)
dlab_case(dimension4 RC 2 ERR "dim4.txt:1: expected 2 or 3 coordinates per point, found 4" ARGS triangulate dim4.txt)
dlab_case(unreadable RC 2 ERR "missing.txt: cannot read" ARGS triangulate missing.txt)
dlab_case(directory RC 2 ERR "${WORK}: cannot read: is a directory" ARGS triangulate "${WORK}")
dlab_case(node_count RC 2 ERR "short.node:3: .node count mismatch" ARGS triangulate short.node)
dlab_case(unknown_option RC 2 ERR "unknown option '--frob'" ARGS triangulate square.txt --frob)
dlab_case(missing_value RC 2 ERR "option -o needs a value" ARGS triangulate square.txt -o)
dlab_case(bad_seed RC 2 ERR "--seed: 'x1' is not an integer" ARGS triangulate square.txt --seed x1)
dlab_case(bad_policy RC 2 ERR "--policy must be sos or strict" ARGS triangulate square.txt --policy maybe)
dlab_case(bad_order RC 2 ERR "--order must be" ARGS triangulate square.txt --order sideways)
dlab_case(unknown_algorithm RC 2 ERR "unknown algorithm 'quickhull'" ARGS triangulate square.txt --algo quickhull)
dlab_case(unknown_kernel RC 2 ERR "unknown kernel 'quad'" ARGS triangulate square.txt --kernel quad)
dlab_case(unwritable RC 2 ERR "cannot write '${WORK}/no/such/dir/x.tri'" ARGS triangulate square.txt -o "${WORK}/no/such/dir/x.tri")
dlab_case(missing_input RC 2 ERR "missing INPUT" ARGS triangulate)
dlab_case(check_range RC 2 ERR "kite_range.txt:2: vertex index 9 out of range \\(4 points\\)" ARGS check kite.txt kite_range.txt)
dlab_case(check_count RC 2 ERR "kite_short.txt:1: expected 3 vertex indices" ARGS check kite.txt kite_short.txt)
dlab_case(check_nan RC 2 ERR "nan.txt:2: NaN" ARGS check nan.txt kite_delaunay.txt)
dlab_case(check_usage RC 2 ARGS check kite.txt)
dlab_case(predicate_count RC 2 ERR "orient2d takes 6 coordinates" ARGS predicate orient2d mp 0 0 1 0 0)
dlab_case(predicate_name RC 2 ERR "unknown predicate 'orient4d'" ARGS predicate orient4d mp 0 0 1 0 0 1)
dlab_case(predicate_kernel RC 2 ERR "unknown kernel 'quad'" ARGS predicate orient2d quad 0 0 1 0 0 1)
dlab_case(predicate_nan RC 2 ERR "NaN coordinate" ARGS predicate orient2d mp 0 0 1 nan 0 1)
dlab_case(gen_unknown RC 2 ERR "unknown generator 'nope'" ARGS gen nope)
dlab_case(gen_bad_dim RC 2 ERR "--dim" ARGS gen uniform --dim 4)
dlab_case(gen_2d_only RC 2 ERR "2D only" ARGS gen kettner-grid --dim 3)
dlab_case(demo_args RC 2 ERR "^dlab demo: unexpected argument 'extra'\n$" ARGS demo extra)

# ---- predicates: Shewchuk's signs, decimal and hex coordinates ----------------
foreach(k mp float epsilon adaptive integer)
  dlab_case(orient2d_${k} RC 0 OUT "^1\n$" ARGS predicate orient2d ${k} 0 0 1 0 0 1)
  dlab_case(orient2d_cw_${k} RC 0 OUT "^-1\n$" ARGS predicate orient2d ${k} 0 0 0 1 1 0)
  dlab_case(incircle_zero_${k} RC 0 OUT "^0\n$" ARGS predicate incircle ${k} 0 0 1 0 0 1 1 1)
  dlab_case(orient3d_${k} RC 0 OUT "^1\n$" ARGS predicate orient3d ${k} 0 0 0 1 0 0 0 1 0 0 0 -1)
  dlab_case(insphere_${k} RC 0 OUT "^1\n$" ARGS predicate insphere ${k} 0 0 0 1 0 0 0 1 0 0 0 -1 0.2 0.2 -0.2)
endforeach()
dlab_case(predicate_hex RC 0 OUT "^0\n$" ARGS predicate orient2d mp 0x1p-1 0x1p-1 0x1.8p+3 12 24 0x18p0)
# Kettner et al.: p = (0.5 + 2^-53, 0.5) is right of q=(12,12) -> r=(24,24): exactly -1.
dlab_case(predicate_kettner_exact RC 0 OUT "^-1\n$" ARGS predicate orient2d adaptive 0x1.0000000000001p-1 0.5 12 12 24 24)

# ---- triangulate and check ------------------------------------------------------
dlab_case(triangulate_square RC 0 OUT "^$" ARGS triangulate square.txt -o square.tri --points-out square.pts --stats square.json)
read_output(tri "${WORK}/square.tri")
if(NOT tri MATCHES "^([0-4] [0-4] [0-4]\n)+$")
  message(STATUS "FAIL square.tri: ${tri}")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(check_square RC 0 OUT "valid Delaunay" ARGS check square.txt square.tri)
dlab_case(points_out_roundtrip RC 0 ARGS check square.pts square.tri)
read_output(pts "${WORK}/square.pts")
if(NOT pts STREQUAL "0x0p+0 0x0p+0\n0x1p+0 0x0p+0\n0x1p+0 0x1p+0\n0x0p+0 0x1p+0\n0x1p-1 0x1p-1\n")
  message(STATUS "FAIL points_out: ${pts}")
  math(EXPR failures "${failures} + 1")
endif()
read_output(json "${WORK}/square.json")
foreach(key algorithm kernel policy order seed dimension input_points distinct_points simplices
            seconds cpu_seconds phase_seconds peak_rss_bytes predicates counters snapping outcome message)
  if(NOT json MATCHES "\"${key}\": ")
    message(STATUS "FAIL stats key ${key}: ${json}")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
if(NOT json MATCHES "\"simplices\": 4,")
  message(STATUS "FAIL stats: 4 simplices expected: ${json}")
  math(EXPR failures "${failures} + 1")
endif()
# Same input, options and seed: byte-identical output apart from the times and peak_rss_bytes.
dlab_case(repeat1 RC 0 ARGS triangulate hex.txt --order random --seed 5 -o r1.tri --stats r1.json)
dlab_case(repeat2 RC 0 ARGS triangulate hex.txt --order random --seed 5 -o r2.tri --stats r2.json)
foreach(f tri json)
  read_output(a "${WORK}/r1.${f}")
  read_output(b "${WORK}/r2.${f}")
  foreach(v a b)
    string(REGEX REPLACE "\"(seconds|cpu_seconds|peak_rss_bytes)\": [^,]*," "" ${v} "${${v}}")
    string(REGEX REPLACE "\"phase_seconds\": {[^}]*}," "" ${v} "${${v}}")
  endforeach()
  if(NOT a STREQUAL b)
    message(STATUS "FAIL repeat: r1.${f} and r2.${f} differ")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
dlab_case(node_input RC 0 OUT "^([0-9]+ [0-9]+ [0-9]+\n)+$" ARGS triangulate square.node)
dlab_case(stdin_input RC 0 OUT "^([0-9]+ [0-9]+ [0-9]+\n)+$" IN "${WORK}/square.txt" ARGS triangulate -)
dlab_case(stdin_nan RC 2 ERR "<stdin>:2: NaN" IN "${WORK}/nan.txt" ARGS triangulate -)
dlab_case(cube_3d RC 0 OUT "^([0-8] [0-8] [0-8] [0-8]\n)+$" ARGS triangulate cube.txt)
dlab_case(cube_3d_file RC 0 OUT "^$" ARGS triangulate cube.txt -o cube.tet)
dlab_case(check_cube RC 0 OUT "valid Delaunay" ARGS check cube.txt cube.tet)
dlab_case(lower_dimensional RC 0 OUT "^$" ERR "lower-dimensional" ARGS triangulate collinear.txt)
dlab_case(duplicates RC 0 OUT "^([0-2] [0-2] [0-2]\n)+$" ARGS triangulate dups.txt)
dlab_case(check_delaunay RC 0 ARGS check kite.txt kite_delaunay.txt)
dlab_case(check_not_delaunay RC 1 ARGS check kite.txt kite_bad.txt)
dlab_case(check_invalid RC 1 ARGS check kite.txt kite_cw.txt)
foreach(k mp integer adaptive)
  dlab_case(kite_${k} RC 0 ARGS triangulate kite.txt --kernel ${k} -o kite_${k}.tri)
  dlab_case(kite_${k}_check RC 0 ARGS check kite.txt kite_${k}.tri)
endforeach()

# ---- gen: reproducible, readable by triangulate -----------------------------------
dlab_case(gen1 RC 0 ARGS gen cocircular --n 64 --seed 3 -o g1.txt)
dlab_case(gen2 RC 0 ARGS gen cocircular --n 64 --seed 3 -o g2.txt)
read_output(a "${WORK}/g1.txt")
read_output(b "${WORK}/g2.txt")
if(NOT a STREQUAL b)
  message(STATUS "FAIL gen is not reproducible")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(gen_triangulate RC 0 ARGS triangulate g1.txt -o g1.tri)
dlab_case(gen_check RC 0 OUT "valid Delaunay" ARGS check g1.txt g1.tri)
dlab_case(gen_decimal RC 0 OUT "^0.375 0.5\n" ARGS gen cocircular --n 12 --decimal)
# Binade-edge generators: exact values, refused parameters (exit 2).
dlab_case(gen_binade RC 0 OUT "^-0x1.0000000000001p\\+51 -0x1.0000000000001p\\+51\n-0x1p\\+51 "
          ARGS gen binade-lattice --exp 51 --step-exp -1 --sign negative --n 9)
dlab_case(gen_binade_help RC 0 OUT "binade-lattice.*binade-doubles.*half-integers.*extreme-doubles" ARGS gen --help)
dlab_case(gen_binade_sign RC 2 ERR "--sign must be positive, negative or mixed" ARGS gen binade-doubles --sign up)
dlab_case(gen_binade_step RC 2 ERR "--step-exp must be in -1..51" ARGS gen binade-lattice --exp 51 --step-exp -2)
dlab_case(gen_binade_overflow RC 2 ERR "overflow" ARGS gen binade-lattice --exp 1023 --step-exp 1023 --n 100)
# The inexact baselines may fail on the Kettner grid, but only with status 0 or 1.
dlab_case(gen_kettner RC 0 ARGS gen kettner-grid --side 24 -o kettner.txt)
foreach(k float epsilon)
  execute_process(COMMAND "${DLAB}" triangulate kettner.txt --kernel ${k} -o /dev/null
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
  if(NOT rc MATCHES "^[01]$")
    message(STATUS "FAIL kettner_${k}: status ${rc}")
    math(EXPR failures "${failures} + 1")
  else()
    message(STATUS "ok   kettner_${k} (status ${rc})")
  endif()
endforeach()

# ---- flip: an existing triangulation toward Delaunay (cli/cmd_flip.cpp) -----------
# 2D: the kite's long diagonal 0-1 (kite_bad, non-Delaunay: check_not_delaunay
# above) flips to the short one; the independent checker accepts the result,
# and both triangles hold the short diagonal's ends 2 and 3.
dlab_case(flip_kite RC 0 ERR "^$" ARGS flip kite.txt kite_bad.txt -o kite_flipped.tri --stats flip_kite.json)
read_output(fk "${WORK}/flip_kite.json")
if(NOT fk MATCHES "\"flips_2_2\": 1,.*\"outcome\": \"ok\",\n  \"validated\": true,")
  message(STATUS "FAIL flip_kite stats: one 2-2 flip, outcome ok, validated: ${fk}")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(flip_kite_check RC 0 OUT "valid Delaunay" ARGS check kite.txt kite_flipped.tri)
read_output(kf "${WORK}/kite_flipped.tri")
if(NOT kf MATCHES "^([0-3] [0-3] [0-3]\n)([0-3] [0-3] [0-3]\n)$" OR kf MATCHES "(^|\n)[^\n]*0[^\n]*1[^\n]*\n"
   OR kf MATCHES "(^|\n)[^\n]*1[^\n]*0[^\n]*\n")
  message(STATUS "FAIL flip_kite: the long diagonal 0-1 is still there: ${kf}")
  math(EXPR failures "${failures} + 1")
endif()
# 2D: --make-start writes a valid triangulation that check rejects as
# non-Delaunay (status 1); flipping it ends Delaunay (status 0, checked).
dlab_case(flip_gen2 RC 0 ARGS gen uniform --n 300 --seed 4 -o flip2.txt)
dlab_case(flip_start2 RC 0 ARGS flip flip2.txt --make-start --seed 2 -o flip2_start.tri)
dlab_case(flip_start2_check RC 1 OUT "not_delaunay: [1-9]" ARGS check flip2.txt flip2_start.tri)
dlab_case(flip_run2 RC 0 ERR "^$" ARGS flip flip2.txt flip2_start.tri -o flip2_out.tri)
dlab_case(flip_run2_check RC 0 OUT "valid Delaunay" ARGS check flip2.txt flip2_out.tri)
# 3D: two tetrahedra 0123 and 1024 on the facet 012 with 4 inside the sphere
# of 0123: one 2-3 flip gives the three tetrahedra around edge 3-4.
file(WRITE "${WORK}/bipyramid.txt" "-2 -2 0\n4 -2 0\n-2 4 0\n0 0 1\n0 0 -1\n")
file(WRITE "${WORK}/bipyramid_bad.tet" "0 1 2 3\n1 0 2 4\n")
dlab_case(flip_3d_start_check RC 1 ARGS check bipyramid.txt bipyramid_bad.tet)
dlab_case(flip_3d RC 0 ERR "^$" ARGS flip bipyramid.txt bipyramid_bad.tet -o bipyramid.tet --stats flip3.json)
dlab_case(flip_3d_check RC 0 OUT "valid Delaunay" ARGS check bipyramid.txt bipyramid.tet)
read_output(bp "${WORK}/bipyramid.tet")
if(NOT bp MATCHES "^([0-4] [0-4] [0-4] [0-4]\n)([0-4] [0-4] [0-4] [0-4]\n)([0-4] [0-4] [0-4] [0-4]\n)$")
  message(STATUS "FAIL flip_3d: three tetrahedra expected: ${bp}")
  math(EXPR failures "${failures} + 1")
endif()
read_output(fj "${WORK}/flip3.json")
if(NOT fj MATCHES "\"flips_2_3\": 1,")
  message(STATUS "FAIL flip_3d stats: one 2-3 flip expected: ${fj}")
  math(EXPR failures "${failures} + 1")
endif()
# 3D from --make-start: the result is a valid triangulation either way; exit 0
# when it is Delaunay, 1 (not-delaunay) when the flips are stuck (never looped).
dlab_case(flip_gen3 RC 0 ARGS gen uniform --dim 3 --n 80 --seed 5 -o flip3.txt)
dlab_case(flip_start3 RC 0 ARGS flip flip3.txt --make-start --seed 1 -o flip3_start.tet)
dlab_case(flip_start3_check RC 1 OUT "not_delaunay: [1-9]" ARGS check flip3.txt flip3_start.tet)
execute_process(COMMAND "${DLAB}" flip flip3.txt flip3_start.tet -o flip3_out.tet WORKING_DIRECTORY "${WORK}"
                RESULT_VARIABLE rc ERROR_VARIABLE err OUTPUT_QUIET TIMEOUT 120)
if(rc STREQUAL "0" AND err STREQUAL "")
  dlab_case(flip_run3_check RC 0 OUT "valid Delaunay" ARGS check flip3.txt flip3_out.tet)
elseif(rc STREQUAL "1" AND err MATCHES "^dlab flip: not-delaunay: [1-9][0-9]* facets? not locally Delaunay .*; flips stuck after")
  dlab_case(flip_run3_check RC 1 ARGS check flip3.txt flip3_out.tet)
else()
  message(STATUS "FAIL flip_run3: status ${rc}: ${err}")
  math(EXPR failures "${failures} + 1")
endif()
# Lawson in 3D on a lattice (points on hull facets and edges, coplanar hull
# faces: inserted by flips) passes the checker.
dlab_case(lawson_gen3 RC 0 ARGS gen lattice --dim 3 --n 125 -o lattice3.txt)
dlab_case(lawson_lattice3 RC 0 ARGS triangulate lattice3.txt --algo lawson --order random -o lattice3.tet)
dlab_case(lawson_lattice3_check RC 0 OUT "valid Delaunay" ARGS check lattice3.txt lattice3.tet)
# Bad input: exit 2, the message names the file, the line of the bad simplex
# and the exact validator's reason.
file(WRITE "${WORK}/kite_cw2.txt" "# a comment line, then a blank one\n\n0 3 2\n3 2 1\n")
dlab_case(flip_clockwise RC 2 ERR "^dlab flip: kite_cw.txt:1: not a triangulation of kite.txt: orientation: 2 simplices not positively oriented \\(first: simplex 0\\)" ARGS flip kite.txt kite_cw.txt)
dlab_case(flip_clockwise_line RC 2 ERR "^dlab flip: kite_cw2.txt:4: not a triangulation of kite.txt: orientation: 1 simplex not positively oriented \\(first: simplex 1\\)" ARGS flip kite.txt kite_cw2.txt)
file(WRITE "${WORK}/kite_dup.txt" "0 3 2\n3 1 2\n0 3 2\n")
dlab_case(flip_duplicate RC 2 ERR "^dlab flip: kite_dup.txt:3: not a triangulation of kite.txt: overlap: 1 simplex listed twice \\(first: simplex 2\\)" ARGS flip kite.txt kite_dup.txt)
dlab_case(flip_range RC 2 ERR "kite_range.txt:2: vertex index 9 out of range" ARGS flip kite.txt kite_range.txt)
dlab_case(flip_nan RC 2 ERR "nan.txt:2: NaN" ARGS flip nan.txt kite_delaunay.txt)
dlab_case(flip_usage RC 2 ERR "^dlab flip: missing SIMPLICES \\(or --make-start\\)\n$" ARGS flip kite.txt)
dlab_case(flip_unknown_option RC 2 ERR "unknown option '--frob'" ARGS flip kite.txt kite_bad.txt --frob)

# ---- every algorithm through the same contract ----------------------------------
# The independent checker accepts each algorithm's result on the square (2D,
# cocircular) and the cube (3D, cospherical); the options of one algorithm are
# usage errors on another.
foreach(a bowyer-watson lawson tanemura george)
  dlab_case(algo_${a}_2d RC 0 ARGS triangulate square.txt --algo ${a} -o square_${a}.tri)
  dlab_case(algo_${a}_2d_check RC 0 OUT "valid Delaunay" ARGS check square.txt square_${a}.tri)
  dlab_case(algo_${a}_3d RC 0 ARGS triangulate cube.txt --algo ${a} --kernel integer -o cube_${a}.tet)
  dlab_case(algo_${a}_3d_check RC 0 OUT "valid Delaunay" ARGS check cube.txt cube_${a}.tet)
endforeach()
dlab_case(tanemura_lower_dimensional RC 0 OUT "^$" ERR "lower-dimensional" ARGS triangulate collinear.txt --algo tanemura)
dlab_case(sphere_option_elsewhere RC 2 ERR "options of --algo george only" ARGS triangulate square.txt --algo tanemura --exact-sphere)
# --threads T (the parallel Bowyer–Watson): the same bytes for every T, equal
# to the serial algorithm's and Lawson's with --canonical (the triangulation
# of the perturbed points is unique); what it cannot do is a usage error.
foreach(d 2 3)
  dlab_case(threads_gen_${d}d RC 0 ARGS gen lattice --dim ${d} --n 3000 --seed 3 -o lattice${d}.txt)
  dlab_case(threads_serial_${d}d RC 0 ARGS triangulate lattice${d}.txt --canonical -o lattice${d}_serial.tri)
  dlab_case(threads_lawson_${d}d RC 0 ARGS triangulate lattice${d}.txt --algo lawson --canonical -o lattice${d}_lawson.tri)
  file(SHA256 "${WORK}/lattice${d}_serial.tri" want)
  foreach(t 1 2 3 8)
    dlab_case(threads_${t}_${d}d RC 0 ARGS triangulate lattice${d}.txt --threads ${t} --stats threads${t}_${d}.json -o lattice${d}_t${t}.tri)
    file(SHA256 "${WORK}/lattice${d}_t${t}.tri" got)
    read_output(tj "${WORK}/threads${t}_${d}.json")
    if(NOT got STREQUAL want OR NOT tj MATCHES "\"threads\": ${t}")
      message(STATUS "FAIL threads_${t}_${d}d: output differs from the serial --canonical one, or no threads counter")
      math(EXPR failures "${failures} + 1")
    endif()
  endforeach()
  file(SHA256 "${WORK}/lattice${d}_lawson.tri" lawson)
  if(NOT lawson STREQUAL want)
    message(STATUS "FAIL threads_lawson_${d}d: lawson --canonical differs from bowyer-watson --canonical")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
dlab_case(threads_integer RC 0 ARGS triangulate lattice3.txt --threads 2 --kernel integer -o lattice3_int.tri)
file(SHA256 "${WORK}/lattice3_int.tri" got)
if(NOT got STREQUAL want)
  message(STATUS "FAIL threads_integer: --kernel integer --threads 2 differs")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(threads_lawson RC 2 ERR "--threads is an option of --algo bowyer-watson only" ARGS triangulate square.txt --algo lawson --threads 2)
dlab_case(threads_float RC 2 ERR "--threads needs an exact kernel" ARGS triangulate square.txt --kernel float --threads 2)
dlab_case(threads_strict RC 2 ERR "--threads needs --policy sos" ARGS triangulate square.txt --policy strict --threads 2)
dlab_case(threads_scan RC 2 ERR "--threads needs --location walk" ARGS triangulate square.txt --location scan --threads 2)
dlab_case(threads_too_many RC 2 ERR "--threads" ARGS triangulate square.txt --threads 256)
# George's enclosing box with the paper's integer kernel: the box is removed
# afterwards, and what that leaves missing is reported in the stats.
dlab_case(george_box_integer RC 0 ARGS triangulate cube.txt --algo george --kernel integer --enclosing-box --stats box.json -o box.tet)
read_output(bj "${WORK}/box.json")
if(NOT bj MATCHES "\"box_simplices_removed\": [1-9]" OR NOT bj MATCHES "\"hull_facets_missing\": ")
  message(STATUS "FAIL george_box_integer stats: ${bj}")
  math(EXPR failures "${failures} + 1")
endif()
# George with float volumes (the paper's claim that they must be exact): on 3D
# near-duplicates the corrections meet contradictory orientations, a reported
# failure (exit 1) naming the point; the same points with integer volumes give
# a valid mesh, not Delaunay (the floating sphere test), reported as such.
dlab_case(george_float_gen RC 0 ARGS gen near-duplicates --n 800 --dim 3 --seed 1 -o neardup3.txt)
dlab_case(george_float_fails RC 1 ERR "^dlab triangulate: reported: point [0-9]+: the correction would remove a base element [^\n]* \\(george, float kernel\\)\n$"
          ARGS triangulate neardup3.txt --algo george --kernel float -o /dev/null --stats george_float.json)
# Stats of the failed run: how far it got, apart from the distinct points.
read_output(gf "${WORK}/george_float.json")
if(NOT gf MATCHES "\"distinct_points\": ([0-9]+),\n  \"inserted_points\": ([0-9]+),"
   OR NOT CMAKE_MATCH_2 GREATER 0 OR NOT CMAKE_MATCH_2 LESS CMAKE_MATCH_1 OR NOT gf MATCHES "\"outcome\": \"reported\"")
  message(STATUS "FAIL george_float stats: 0 < inserted_points < distinct_points, outcome reported: ${gf}")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(george_integer_neardup RC 1 ERR "dlab triangulate: not-delaunay: [1-9][0-9]* facets not locally Delaunay [^\n]*\\(george, integer kernel\\)\n$"
          ARGS triangulate neardup3.txt --algo george --kernel integer -o /dev/null)

# ---- fitting the user's other tools -------------------------------------------------
# --version: CMake's project(VERSION) (passed in as VERSION), the commit, the compiler.
if(NOT DEFINED VERSION)
  set(VERSION "[0-9.]+")
endif()
set(version_re "^dlab ${VERSION} \\(delaunay-lab\\)\ncommit ([0-9a-f]+|unknown)[^\n]*\ncompiler [^\n]+\n$")
dlab_case(version RC 0 OUT "${version_re}" ARGS --version)
dlab_case(version_word RC 0 OUT "${version_re}" ARGS version)
dlab_case(version_args RC 2 ERR "^dlab --version: unexpected argument 'now'\n$" ARGS --version now)
dlab_case(help_lists_options RC 0 OUT "--orientation positive\\|any.*--decimal.*--version" ARGS --help)

# Numbers that are not what they say: 1e400 overflows, 1e-400 is not zero but
# rounds to zero; both are bad input (exit 2, file:line, the token), in INPUT and
# in `dlab predicate`. A subnormal that is not zero is kept.
file(WRITE "${WORK}/tiny.txt" "0 0\n1e-400 1\n1 0\n")
file(WRITE "${WORK}/tiny_hex.txt" "0 0\n1 0\n0 -0x1p-1075\n")
dlab_case(underflow RC 2 ERR "tiny.txt:2: coordinate '1e-400' is not zero but rounds to zero" ARGS triangulate tiny.txt)
dlab_case(underflow_hex RC 2 ERR "tiny_hex.txt:3: coordinate '-0x1p-1075' is not zero but rounds to zero" ARGS check tiny_hex.txt kite_delaunay.txt)
dlab_case(overflow RC 2 ERR "coordinate '1e400' overflows to infinity" ARGS predicate orient2d mp 0 0 1 0 0 1e400)
dlab_case(predicate_underflow RC 2 ERR "argument 6: coordinate '1e-400' is not zero but rounds to zero" ARGS predicate orient2d mp 0 0 1 0 0 1e-400)
dlab_case(predicate_zero_literal RC 0 OUT "^0\n$" ARGS predicate orient2d mp 0 0 1 0 0 -0e-400)
dlab_case(predicate_subnormal RC 0 OUT "^1\n$" ARGS predicate orient2d mp 0 0 1 0 0 4.9406564584124654e-324)

# A line longer than the reader's 1 MiB limit is refused (exit 2, file:line)
# before the rest of it is read; the reader's memory stays bounded
# (test_point_reader.cpp checks how much of an 8 MiB line it reads).
string(REPEAT "1 " 600000 long_line)
file(WRITE "${WORK}/long.txt" "0 0\n${long_line}\n")
dlab_case(long_line RC 2 ERR "long.txt:2: line longer than 1048576 bytes" ARGS triangulate long.txt)

# check --orientation any. scipy.spatial.Delaunay (scipy 1.10.1, Qhull) on 10
# random 3D points: 8 of its 17 tetrahedra are negatively oriented (counted
# with exact rational determinants in Python, outside dlab).
file(WRITE "${WORK}/scipy3.txt" "0.036 0.515 0.466\n0.917 0.629 0.514\n0.497 0.248 0.012\n0.192 0.692 0.201\n0.37 0.004 0.83\n0.154 0.268 0.88\n0.51 0.847 0.64\n0.742 0.091 0.541\n0.508 0.871 0.361\n0.598 0.059 0.388\n")
file(WRITE "${WORK}/scipy3.tet" "9 2 4 0\n5 6 4 1\n5 9 4 0\n5 9 6 0\n8 9 6 0\n8 9 2 1\n8 9 6 1\n7 5 6 4\n7 5 9 4\n7 5 9 6\n7 6 4 1\n7 9 6 1\n7 9 2 1\n3 9 2 0\n3 8 9 0\n3 8 9 2\n3 8 6 0\n")
dlab_case(scipy_positive RC 1 OUT "orientation: 8 " ARGS check scipy3.txt scipy3.tet)
dlab_case(scipy_any RC 0 OUT "\n8 simplices given negatively oriented[^\n]*\nvalid Delaunay\n$" ARGS check scipy3.txt scipy3.tet --orientation any)
dlab_case(kite_cw_any RC 0 OUT "\n2 simplices given negatively oriented[^\n]*\nvalid Delaunay\n$" ARGS check kite.txt kite_cw.txt --orientation any)
dlab_case(kite_ccw_any RC 0 OUT "\n0 simplices given negatively oriented[^\n]*\nvalid Delaunay\n$" ARGS check kite.txt kite_delaunay.txt --orientation any)
dlab_case(kite_bad_any RC 1 OUT "not_delaunay: 1 " ARGS check kite.txt kite_bad.txt --orientation any)
# A simplex of zero volume is refused in either orientation: 2 lies on the edge 0-1.
file(WRITE "${WORK}/flat.txt" "0 0\n2 0\n1 0\n1 1\n")
file(WRITE "${WORK}/flat_mixed.tri" "0 3 2\n2 1 3\n")
file(WRITE "${WORK}/flat_degenerate.tri" "0 3 2\n2 1 3\n0 2 1\n")
dlab_case(mixed_any RC 0 OUT "\n1 simplices given negatively oriented[^\n]*\nvalid Delaunay\n$" ARGS check flat.txt flat_mixed.tri --orientation any)
dlab_case(degenerate_any RC 1 OUT "orientation: 1 \\(first: simplex 2\\)" ARGS check flat.txt flat_degenerate.tri --orientation any)
read_output(cube_tets "${WORK}/cube.tet")
file(WRITE "${WORK}/cube_flat.tet" "${cube_tets}0 1 2 3\n")  # four coplanar corners
dlab_case(degenerate_any_3d RC 1 OUT "orientation: 1 " ARGS check cube.txt cube_flat.tet --orientation any)
dlab_case(orientation_value RC 2 ERR "--orientation must be positive or any, not 'sideways'" ARGS check kite.txt kite_cw.txt --orientation sideways)

# --decimal: shortest round-trip decimals (numpy.loadtxt reads no hex floats).
# Values at their edges: the smallest subnormal, -0, the largest double, 0.1,
# 2^53 and its neighbours, the largest subnormal and the smallest normal.
file(WRITE "${WORK}/edges.txt"
  "0x0.0000000000001p-1022 -0x0p+0\n0x1.fffffffffffffp+1023 0x1.999999999999ap-4\n"
  "-0x1.fffffffffffffp+1023 0x1p+53\n0x1.0000000000001p+53 -0x1.fffffffffffffp+52\n"
  "0x0.fffffffffffffp-1022 0x1p-1022\n")
dlab_case(decimal_out RC 0 ARGS triangulate edges.txt -o /dev/null --points-out edges_dec.txt --decimal)
dlab_case(hex_out RC 0 ARGS triangulate edges.txt -o /dev/null --points-out edges_hex.txt)
read_output(dec "${WORK}/edges_dec.txt")
if(NOT dec STREQUAL "5e-324 -0\n1.7976931348623157e+308 0.1\n-1.7976931348623157e+308 9007199254740992\n9007199254740994 -9007199254740991\n2.225073858507201e-308 2.2250738585072014e-308\n")
  message(STATUS "FAIL decimal_out: ${dec}")
  math(EXPR failures "${failures} + 1")
endif()
# Read back through our reader, bit for bit: the hex written from the decimal file
# equals the hex written from the original.
dlab_case(decimal_back RC 0 ARGS triangulate edges_dec.txt -o /dev/null --points-out edges_back.txt)
read_output(hex "${WORK}/edges_hex.txt")
read_output(back "${WORK}/edges_back.txt")
if(NOT hex STREQUAL back OR NOT hex MATCHES "^0x0.0000000000001p-1022 -0x0p\\+0\n")
  message(STATUS "FAIL decimal round trip:\n${hex}\n${back}")
  math(EXPR failures "${failures} + 1")
endif()
# gen --decimal on subnormals and on huge values: the same doubles as gen's hex.
foreach(g tiny huge)
  dlab_case(gen_${g}_hex RC 0 ARGS gen ${g} --n 40 --seed 2 -o gen_${g}_hex.txt)
  dlab_case(gen_${g}_dec RC 0 ARGS gen ${g} --n 40 --seed 2 --decimal -o gen_${g}_dec.txt)
  dlab_case(gen_${g}_back RC 0 ARGS triangulate gen_${g}_dec.txt -o /dev/null --points-out gen_${g}_back.txt)
  read_output(a "${WORK}/gen_${g}_hex.txt")
  read_output(b "${WORK}/gen_${g}_back.txt")
  read_output(c "${WORK}/gen_${g}_dec.txt")
  if(NOT a STREQUAL b OR c MATCHES "0x")
    message(STATUS "FAIL gen ${g} --decimal round trip")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
# numpy.loadtxt reads the decimal files to the same bits as Python's float.fromhex
# reads the hex ones (skipped where no python3 has numpy).
set(numpy_python "")
foreach(py python3 /usr/bin/python3)
  execute_process(COMMAND ${py} -c "import numpy" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if(rc STREQUAL "0")
    set(numpy_python ${py})
    break()
  endif()
endforeach()
if(numpy_python)
  set(numpy_check [=[
import struct, sys, numpy
def bits(x): return struct.pack('<d', float(x))
bad = 0
for dec, hexf in zip(sys.argv[1::2], sys.argv[2::2]):
    a = numpy.loadtxt(dec, dtype=numpy.float64, ndmin=2).ravel()
    b = [float.fromhex(t) for t in open(hexf).read().split()]
    if len(a) != len(b) or any(bits(x) != bits(y) for x, y in zip(a, b)):
        print('mismatch:', dec, hexf); bad += 1
sys.exit(bad)
]=])
  execute_process(COMMAND ${numpy_python} -c "${numpy_check}" edges_dec.txt edges_hex.txt
                          gen_tiny_dec.txt gen_tiny_hex.txt gen_huge_dec.txt gen_huge_hex.txt
                  WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(rc STREQUAL "0")
    message(STATUS "ok   numpy_loadtxt (${numpy_python})")
  else()
    message(STATUS "FAIL numpy_loadtxt: ${rc} ${out} ${err}")
    math(EXPR failures "${failures} + 1")
  endif()
else()
  message(STATUS "skip numpy_loadtxt: no python3 with numpy (Debian: python3-numpy)")
endif()

# ---- outcome classes (variants/outcome.hpp): one exit status and one stderr line each ----
# The stats file `path` must match `regex` (e.g. its outcome class).
function(expect_json name path regex)
  read_output(j "${path}")
  if(NOT j MATCHES "${regex}")
    message(STATUS "FAIL ${name}: ${path} does not match ${regex}: ${j}")
    math(EXPR n "${failures} + 1")
    set(failures ${n} PARENT_SCOPE)
  else()
    message(STATUS "ok   ${name}")
  endif()
endfunction()
# --location: scan (bowyer-watson, lawson) gives the walk's triangulation and says so in --stats.
dlab_case(location_unknown RC 2 ERR "--location must be walk or scan, not 'kd-tree'" ARGS triangulate square.txt --location kd-tree)
dlab_case(location_scan_elsewhere RC 2 ERR "available with bowyer-watson and lawson only" ARGS triangulate square.txt --algo tanemura --location scan)
dlab_case(location_scan RC 0 ARGS triangulate cube.txt --algo lawson --kernel integer --location scan --stats location_scan.json -o cube_scan.tet)
dlab_case(location_scan_check RC 0 OUT "valid Delaunay" ARGS check cube.txt cube_scan.tet)
expect_json(location_scan_stats "${WORK}/location_scan.json" "\"location\": \"scan\",.*\"walk_steps\": 0,\n *\"scan_tests\": [1-9]")
set(pair_re "\\(([a-z-]+( --[a-z-]+)*), (adaptive|integer|mp|float|epsilon) kernel\\)")

# The table is in every --help.
set(table_re "ok +0  nothing\n  lower-dimensional +0 .*not-delaunay +1 .*invalid +1 .*reported +1 .*bad input or usage 2")
dlab_case(outcome_help RC 0 OUT "${table_re}" ARGS --help)
dlab_case(outcome_help_triangulate RC 0 OUT "^usage: dlab triangulate.*--validate.*${table_re}" ARGS triangulate --help)
dlab_case(outcome_help_flip RC 0 OUT "^usage: dlab flip.*--kernel K.*${table_re}" ARGS flip --help)

# ok: nothing on stderr, outcome ok; --validate makes the validator judge an exact pair too.
dlab_case(outcome_ok RC 0 ERR "^$" ARGS triangulate square.txt -o /dev/null --stats oc_ok.json)
expect_json(outcome_ok_stats "${WORK}/oc_ok.json" "\"inserted_points\": 5,.*\"outcome\": \"ok\",\n  \"validated\": false,")
dlab_case(outcome_ok_validate RC 0 ERR "^$" ARGS triangulate square.txt -o /dev/null --validate --stats oc_okv.json)
expect_json(outcome_ok_validate_stats "${WORK}/oc_okv.json" "\"outcome\": \"ok\",\n  \"validated\": true,")

# lower-dimensional: exit 0, one line with the algorithm's reason; zero points inserted.
dlab_case(outcome_lower RC 0 OUT "^$" ERR "^dlab triangulate: lower-dimensional: all 4 points are collinear[^\n]* \\(bowyer-watson, adaptive kernel\\)\n$"
          ARGS triangulate collinear.txt --stats oc_lower.json)
expect_json(outcome_lower_stats "${WORK}/oc_lower.json" "\"inserted_points\": 0,.*\"outcome\": \"lower-dimensional\",")

# not-delaunay from George's floating sphere (the default variant, exact adaptive
# volumes): the kite scaled to subnormals. Its circumcircle's r^2 underflows, so
# the cavity is the base alone and the result keeps whichever diagonal came
# first. The kite's Delaunay triangulation uses the short diagonal 2-3 (kite.txt
# above, independent of scale); George's output holds the long one 0-1, which
# `dlab check` rejects as not Delaunay. With --exact-sphere: ok, short diagonal.
file(WRITE "${WORK}/kite_tiny.txt" "0 0\n0x4p-1074 0\n0x2p-1074 0x1p-1074\n0x2p-1074 -0x1p-1074\n")
dlab_case(outcome_george_sphere RC 1 ERR "^dlab triangulate: not-delaunay: 1 facet not locally Delaunay \\(first: simplex [0-9] facet [0-2]\\) \\(george, adaptive kernel\\)\n$"
          ARGS triangulate kite_tiny.txt --algo george --order input -o kite_tiny_george.tri --stats oc_george.json)
expect_json(outcome_george_stats "${WORK}/oc_george.json" "\"inserted_points\": 4,.*\"outcome\": \"not-delaunay\",\n  \"validated\": true,\n  \"message\": \"1 facet not locally Delaunay")
read_output(kt "${WORK}/kite_tiny_george.tri")
if(NOT kt MATCHES "(^|\n)(0 1 [23]|1 [23] 0|[23] 0 1)\n")
  message(STATUS "FAIL outcome_george_sphere: the long diagonal 0-1 expected: ${kt}")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(outcome_george_sphere_check RC 1 OUT "not_delaunay: 1" ARGS check kite_tiny.txt kite_tiny_george.tri)
dlab_case(outcome_george_exact_sphere RC 0 ERR "^$" ARGS triangulate kite_tiny.txt --algo george --exact-sphere -o kite_tiny_exact.tri)
dlab_case(outcome_george_exact_sphere_check RC 0 OUT "valid Delaunay" ARGS check kite_tiny.txt kite_tiny_exact.tri)

# The inexact baselines on near-degenerate sets (`dlab gen near-degenerate`, the
# exact cocircular / cospherical sets moved by 1 ulp; written out here so the
# cases do not depend on the generator). Each verdict is cross-checked by
# `dlab check` on the written simplices.
file(WRITE "${WORK}/nd2.txt" "-0x1p-1 0x1.7ffffffffffffp-2\n0x1.0000000000001p-1 -0x1.7ffffffffffffp-2\n0x1.3ffffffffffffp-1 0x0.0000000000001p-1022\n0x0p+0 0x1.3ffffffffffffp-1\n-0x1.4000000000001p-1 -0x0.0000000000001p-1022\n0x0.0000000000001p-1022 -0x1.3ffffffffffffp-1\n0x1.7ffffffffffffp-2 -0x1.0000000000001p-1\n-0x1.7ffffffffffffp-2 0x1.fffffffffffffp-2\n")
dlab_case(outcome_float_not_delaunay RC 1 ERR "^dlab triangulate: not-delaunay: 2 facets not locally Delaunay \\(first: simplex 0 facet 0\\) \\(tanemura, float kernel\\)\n$"
          ARGS triangulate nd2.txt --algo tanemura --kernel float -o nd2_float.tri --stats oc_float_nd.json)
expect_json(outcome_float_not_delaunay_stats "${WORK}/oc_float_nd.json" "\"outcome\": \"not-delaunay\",\n  \"validated\": true,")
dlab_case(outcome_float_not_delaunay_check RC 1 OUT "not_delaunay: 2 \\(first: simplex 0 facet 0\\)" ARGS check nd2.txt nd2_float.tri)
dlab_case(outcome_exact_nd2 RC 0 ERR "^$" ARGS triangulate nd2.txt --algo tanemura --kernel adaptive -o /dev/null)
file(WRITE "${WORK}/nd3.txt" "-0x1.0000000000001p-1 0x1p-2 0x1.0000000000001p-1\n-0x1.0000000000001p-2 -0x1.fffffffffffffp-2 0x1p-1\n0x1.fffffffffffffp-2 -0x1.fffffffffffffp-2 0x1.fffffffffffffp-3\n0x1p-1 -0x1.0000000000001p-1 -0x1p-2\n0x1.fffffffffffffp-2 -0x1p-2 0x1p-1\n0x1.fffffffffffffp-2 -0x1p-2 -0x1p-1\n0x1p-1 0x1.0000000000001p-1 0x1p-2\n0x1.fffffffffffffp-2 0x1.fffffffffffffp-2 -0x1.fffffffffffffp-3\n")
dlab_case(outcome_epsilon_invalid RC 1 ERR "^dlab triangulate: invalid: hull-coverage: 2 reflex boundary ridges \\(the union is not convex\\) \\(first: simplex [0-9]+ facet [0-3] point [0-7]\\) \\(bowyer-watson, epsilon kernel\\)\n$"
          ARGS triangulate nd3.txt --kernel epsilon -o nd3_eps.tet --stats oc_eps_invalid.json)
expect_json(outcome_epsilon_invalid_stats "${WORK}/oc_eps_invalid.json" "\"outcome\": \"invalid\",\n  \"validated\": true,\n  \"message\": \"hull-coverage: 2 reflex")
dlab_case(outcome_epsilon_invalid_check RC 1 OUT "boundary_convex: 2" ARGS check nd3.txt nd3_eps.tet)
file(WRITE "${WORK}/nd3b.txt" "-0x1p-1 0x1.fffffffffffffp-3 -0x1.fffffffffffffp-2\n-0x1.fffffffffffffp-3 -0x1.0000000000001p-1 0x1.0000000000001p-1\n-0x1p-2 -0x1.0000000000001p-1 -0x1.0000000000001p-1\n-0x1.0000000000001p-2 0x1.0000000000001p-1 0x1.0000000000001p-1\n0x1.fffffffffffffp-3 0x1.fffffffffffffp-2 -0x1.fffffffffffffp-2\n0x1.fffffffffffffp-2 -0x1p-1 0x1.fffffffffffffp-3\n0x1.fffffffffffffp-2 -0x1.fffffffffffffp-3 -0x1p-1\n0x1p-1 0x1p-2 -0x1.0000000000001p-1\n")
dlab_case(outcome_epsilon_reported RC 1 OUT "^$" ERR "^dlab triangulate: reported: a facet was met by a third simplex \\(inconsistent predicates\\) \\(tanemura, epsilon kernel\\)\n$"
          ARGS triangulate nd3b.txt --algo tanemura --kernel epsilon --stats oc_eps_reported.json)
expect_json(outcome_epsilon_reported_stats "${WORK}/oc_eps_reported.json" "\"simplices\": 0,.*\"outcome\": \"reported\",\n  \"validated\": false,\n  \"message\": \"a facet was met")
dlab_case(outcome_epsilon_nd3b_bw RC 1 ERR "^dlab triangulate: not-delaunay: 8 facets not locally Delaunay [^\n]*\\(bowyer-watson, epsilon kernel\\)\n$"
          ARGS triangulate nd3b.txt --kernel epsilon -o /dev/null)
# invalid, "indices": float Lawson keeps an exact duplicate (points 4 and 10) as
# a vertex of its own, which the contract forbids (duplicates refer to their first occurrence).
file(WRITE "${WORK}/ndup2.txt" "0x1.c6ed53634406bp-2 0x1.869a17ff202ap-1\n0x1.22145bd91204ap-1 0x1.7dd71b42cb1dep-1\n0x1.22145bd91204ap-1 0x1.7dd71b42cb1dcp-1\n0x1.f12745ddf664bp-1 0x1.c7061a43b90b3p-2\n0x1.f12745ddf6649p-1 0x1.c7061a43b90b3p-2\n0x1.22145bd91204bp-1 0x1.7dd71b42cb1ddp-1\n0x1.22145bd91204cp-1 0x1.7dd71b42cb1ddp-1\n0x1.f12745ddf664ap-1 0x1.c7061a43b90b1p-2\n0x1.c6ed53634406bp-2 0x1.869a17ff202ap-1\n0x1.f12745ddf664ap-1 0x1.c7061a43b90b2p-2\n0x1.f12745ddf6649p-1 0x1.c7061a43b90b3p-2\n0x1.c6ed53634406dp-2 0x1.869a17ff202ap-1\n")
dlab_case(outcome_float_indices RC 1 ERR "^dlab triangulate: invalid: indices: 3 indices naming a later copy of a duplicated point \\(first: simplex [0-9]+ point 10\\); also: [a-z_, ]+ \\(lawson, float kernel\\)\n$"
          ARGS triangulate ndup2.txt --algo lawson --kernel float -o /dev/null)

# Nothing changes silently: the integer kernel snaps the subnormal 2^-1074 to 0
# (grid step 2^-61 for this set) onto point 0: one point moved by exactly
# 2^-1074 (shortest decimal 5e-324), one merged; the run itself is ok.
file(WRITE "${WORK}/snap.txt" "0 0\n1 1\n0x1p-1074 0\n1 0\n")
dlab_case(outcome_snapped RC 0 ERR "^dlab triangulate: snapped: 1 of 4 points moved to the integer kernel's grid, 1 merged, largest displacement 5e-324\n$"
          ARGS triangulate snap.txt --kernel integer -o snap.tri --points-out snap_pts.txt --stats oc_snap.json)
expect_json(outcome_snapped_stats "${WORK}/oc_snap.json" "\"distinct_points\": 3,.*\"points_moved\": 1,\n    \"points_merged\": 1,\n    \"max_displacement\": 5e-324\n.*\"outcome\": \"ok\",")
# Moved without merging: (2^-1074, 1/2) -> (0, 1/2).
file(WRITE "${WORK}/snap_moved.txt" "0 0\n1 1\n0x1p-1074 0x1p-1\n1 0\n")
dlab_case(outcome_snapped_moved RC 0 ERR "^dlab triangulate: snapped: 1 of 4 points moved to the integer kernel's grid, 0 merged, largest displacement 5e-324\n$"
          ARGS triangulate snap_moved.txt --kernel integer -o /dev/null)
dlab_case(outcome_snapped_none RC 0 ERR "^$" ARGS triangulate square.txt --kernel integer -o /dev/null)

# flip checks what it is given: one tetrahedron over 500 points is not a
# triangulation of them (exit 2, the first missing point and its line).
dlab_case(flip_many_gen RC 0 ARGS gen uniform --dim 3 --n 496 --seed 7 -o flip_many_rest.txt)
read_output(rest "${WORK}/flip_many_rest.txt")
file(WRITE "${WORK}/flip_many.txt" "# a unit tetrahedron, then 496 uniform points\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n${rest}")
file(WRITE "${WORK}/one.tet" "0 1 2 3\n")
dlab_case(flip_one_tet RC 2 OUT "^$" ERR "^dlab flip: one.tet: not a triangulation of flip_many.txt: missing-point: 496 distinct points in no simplex \\(first: point 4\\) \\(flip_many.txt:6\\)\n$"
          ARGS flip flip_many.txt one.tet)
# Overlaps, holes and non-manifold facets (kite.txt: 0 (0,0), 1 (4,0), 2 (2,1), 3 (2,-1)).
file(WRITE "${WORK}/kite_overlap.txt" "0 3 2\n3 1 2\n0 1 2\n")
dlab_case(flip_overlap RC 2 ERR "^dlab flip: kite_overlap.txt:3: not a triangulation of kite.txt: overlap: 2 facets with both simplices on one side \\(first: simplex 2 facet [0-2]\\)"
          ARGS flip kite.txt kite_overlap.txt)
file(WRITE "${WORK}/square_hole.txt" "0 1 4\n1 2 4\n2 3 4\n")
dlab_case(flip_hole RC 2 ERR "^dlab flip: square_hole.txt:[1-3]: not a triangulation of square.txt: hull-coverage: 2 reflex boundary ridges"
          ARGS flip square.txt square_hole.txt)
file(WRITE "${WORK}/kite5.txt" "0 0\n4 0\n2 1\n2 -1\n1 0\n")
file(WRITE "${WORK}/kite5_fan.txt" "0 3 2\n3 1 2\n4 3 2\n")
dlab_case(flip_non_manifold RC 2 ERR "^dlab flip: kite5_fan.txt:[1-3]: not a triangulation of kite5.txt: adjacency: 1 facet in more than two simplices"
          ARGS flip kite5.txt kite5_fan.txt)
file(WRITE "${WORK}/empty.tri" "# no simplex\n")
dlab_case(flip_lower RC 0 OUT "^$" ERR "^dlab flip: lower-dimensional: [^\n]* \\(flip, adaptive kernel\\)\n$" ARGS flip collinear.txt empty.tri)
dlab_case(flip_empty RC 2 ERR "^dlab flip: empty.tri: not a triangulation of kite.txt: missing-point: 4 distinct points" ARGS flip kite.txt empty.tri)
# --kernel and --stats like triangulate: every kernel flips the kite's long
# diagonal to the short one (checked above for adaptive), and the predicate
# counters show which kernel answered (its stages; none for float and epsilon);
# unknown kernels are usage errors.
set(flip_stage_adaptive "orient2d.A")
set(flip_stage_integer "orient2d.filter")  # its filter, followed by its integers (below)
set(flip_stage_mp "orient2d.mp")
foreach(k adaptive integer mp float epsilon)
  dlab_case(flip_kernel_${k} RC 0 ERR "^$" ARGS flip kite.txt kite_bad.txt --kernel ${k} -o kite_flip_${k}.tri --stats flip_${k}.json)
  dlab_case(flip_kernel_${k}_check RC 0 OUT "valid Delaunay" ARGS check kite.txt kite_flip_${k}.tri)
  if(DEFINED flip_stage_${k})
    set(stage_re "\"${flip_stage_${k}}\": [1-9]")
  else()
    set(stage_re "\"orient2d\": [1-9][0-9]*,\n    \"incircle\"")
  endif()
  expect_json(flip_kernel_${k}_stats "${WORK}/flip_${k}.json" "\"algorithm\": \"flip\",\n  \"kernel\": \"${k}\",.*\"predicates\": \\{\n.*${stage_re}.*\"flips_total\": 1,.*\"outcome\": \"ok\",")
endforeach()
expect_json(flip_kernel_integer_stages "${WORK}/flip_integer.json" "\"orient2d.filter\": [1-9][0-9]*,\n    \"orient2d.integer\": [0-9]+,")
dlab_case(flip_kernel_unknown RC 2 ERR "unknown kernel 'quad'" ARGS flip kite.txt kite_bad.txt --kernel quad)
dlab_case(flip_stats_unwritable RC 2 ERR "cannot write '${WORK}/no/such/dir/f.json'" ARGS flip kite.txt kite_bad.txt --stats "${WORK}/no/such/dir/f.json")

# ---- dlab shrink: a failing set -> a smaller one with the same failure --------
# Case 24 of `dlab fuzz --kernel float,epsilon --algo lawson,bowyer-watson --gen mix
# --cases 2000` (seed 0): lawson x float, brio order seeded as below, is not Delaunay
# on these 20 near-duplicate points. The shrunk set is re-run by dlab triangulate.
set(lawson_seed 7275081841566860385)
set(lawson_pair --algo lawson --kernel float --seed ${lawson_seed})
file(WRITE "${WORK}/lawson_float.txt" "# a comment of the input, kept\n# replay: dlab gen near-duplicates | dlab triangulate - --algo lawson --kernel float --seed ${lawson_seed} --validate\n0x1.d74d6f5bc9035p-2 0x1.c9e6033d61ee9p-3\n0x1.d05cdf97733e1p-1 0x1.620f3ed408d3cp-1\n0x1.75da8bf216ap-1 0x1.3556b7e0111d4p-1\n0x1.d05cdf97733e2p-1 0x1.620f3ed408d3cp-1\n0x1.49b4c043f0da4p-1 0x1.06f2daebfd71bp-1\n0x1.537bd68ff2cep-4 0x1.ddfca1ff600fp-1\n0x1.d05cdf97733dfp-1 0x1.620f3ed408d39p-1\n0x1.537bd68ff2cdep-4 0x1.ddfca1ff600eep-1\n0x1.75da8bf2169fdp-1 0x1.3556b7e0111d7p-1\n0x1.75da8bf2169fcp-1 0x1.3556b7e0111d4p-1\n0x1.d74d6f5bc9039p-2 0x1.c9e6033d61eebp-3\n0x1.d74d6f5bc9039p-2 0x1.c9e6033d61eeep-3\n0x1.d74d6f5bc9038p-2 0x1.c9e6033d61ee9p-3\n0x1.75da8bf2169fep-1 0x1.3556b7e0111d8p-1\n0x1.49b4c043f0da6p-1 0x1.06f2daebfd71ap-1\n0x1.d74d6f5bc903bp-2 0x1.c9e6033d61eefp-3\n0x1.d05cdf97733ep-1 0x1.620f3ed408d38p-1\n0x1.537bd68ff2ce2p-4 0x1.ddfca1ff600f2p-1\n0x1.537bd68ff2ce1p-4 0x1.ddfca1ff600efp-1\n0x1.d74d6f5bc9037p-2 0x1.c9e6033d61eeap-3\n")
dlab_case(shrink_input_fails RC 1 ERR "^dlab triangulate: not-delaunay: " ARGS triangulate lawson_float.txt ${lawson_pair} --validate)
dlab_case(shrink RC 0 OUT "^$"
          ERR "^dlab shrink: lawson x float, not-delaunay: 20 points, [0-9]+ significant bits -> [2-9] points, [0-9]+ significant bits; [0-9]+ tests\n$"
          ARGS shrink lawson_float.txt ${lawson_pair} -o shrunk1.txt)
read_output(shrunk1 "${WORK}/shrunk1.txt")
file(STRINGS "${WORK}/shrunk1.txt" shrunk1_points REGEX "^[^#]")
list(LENGTH shrunk1_points shrunk1_n)
set(shrunk1_header "^# dlab shrink: lawson x float, 2D: not-delaunay\n# shrunk: yes: 20 points, [0-9]+ significant bits -> ${shrunk1_n} points, [0-9]+ significant bits; [0-9]+ tests\n# input: lawson_float.txt\n# detail: [0-9]+ facets? not locally Delaunay[^\n]*\n# replay: dlab triangulate shrunk1.txt --algo lawson --kernel float --seed ${lawson_seed} --validate\n# a comment of the input, kept\n# unshrunk replay: dlab gen near-duplicates [|] dlab triangulate - --algo lawson --kernel float --seed ${lawson_seed} --validate\n-?0x")
if(NOT shrunk1 MATCHES "${shrunk1_header}" OR shrunk1_n GREATER_EQUAL 20 OR shrunk1_n LESS 3)
  message(STATUS "FAIL shrink_file: ${shrunk1_n} points, want 3..19 and the header ${shrunk1_header}:\n${shrunk1}")
  math(EXPR failures "${failures} + 1")
else()
  message(STATUS "ok   shrink_file")
endif()
dlab_case(shrink_replay RC 1 ERR "^dlab triangulate: not-delaunay: " ARGS triangulate shrunk1.txt ${lawson_pair} --validate)
# Deterministic: a second run writes the same bytes.
dlab_case(shrink_again RC 0 ARGS shrink lawson_float.txt ${lawson_pair} -o shrunk2.txt)
file(READ "${WORK}/shrunk2.txt" shrunk2)
string(REPLACE "shrunk2.txt" "shrunk1.txt" shrunk2 "${shrunk2}")
if(NOT shrunk2 STREQUAL shrunk1)
  message(STATUS "FAIL shrink_deterministic: two runs differ:\n${shrunk1}\n${shrunk2}")
  math(EXPR failures "${failures} + 1")
else()
  message(STATUS "ok   shrink_deterministic")
endif()
# Without --seed, the seed of INPUT's replay line: the same result.
dlab_case(shrink_seed_from_input RC 0 ERR "^dlab shrink: --seed ${lawson_seed}, from the replay line of lawson_float.txt\n"
          ARGS shrink lawson_float.txt --algo lawson --kernel float -o shrunk4.txt)
file(STRINGS "${WORK}/shrunk4.txt" shrunk4_points REGEX "^[^#]")
if(NOT shrunk4_points STREQUAL shrunk1_points)
  message(STATUS "FAIL shrink_seed_points: ${shrunk4_points} differ from ${shrunk1_points}")
  math(EXPR failures "${failures} + 1")
endif()
dlab_case(shrink_stdout RC 0 OUT "^# dlab shrink: .*\n# replay: dlab triangulate FILE --algo lawson --kernel float --seed ${lawson_seed} --validate\n"
          ARGS shrink lawson_float.txt ${lawson_pair} --outcome not-delaunay --any-kind)
# A small budget: stops early, says so, and what it wrote still fails the same way.
dlab_case(shrink_budget RC 0 ERR "; 10 tests; test budget spent\n$" ARGS shrink lawson_float.txt ${lawson_pair} --max-tests 10 -o shrunk3.txt)
dlab_case(shrink_budget_replay RC 1 ERR "^dlab triangulate: not-delaunay: " ARGS triangulate shrunk3.txt ${lawson_pair} --validate)
# Bad input and usage: exit 2, a clear message.
dlab_case(shrink_help RC 0 OUT "^usage: dlab shrink INPUT --algo A --kernel K.*Zeller and Hildebrandt.*Examples:" ARGS shrink --help)
dlab_case(shrink_in_usage RC 0 OUT "dlab shrink INPUT --algo A --kernel K" ARGS --help)
dlab_case(shrink_missing RC 2 ERR "^dlab shrink: no_such.txt: cannot read" ARGS shrink no_such.txt ${lawson_pair})
dlab_case(shrink_nan RC 2 ERR "^dlab shrink: nan.txt:2: NaN coordinate 'nan'" ARGS shrink nan.txt ${lawson_pair})
dlab_case(shrink_not_failing RC 2 ERR "^dlab shrink: square.txt does not fail: bowyer-watson x adaptive gives ok: nothing to shrink\n$"
          ARGS shrink square.txt --algo bowyer-watson --kernel adaptive)
dlab_case(shrink_lower RC 2 ERR "does not fail: lawson x float gives lower-dimensional: nothing to shrink" ARGS shrink collinear.txt --algo lawson --kernel float)
dlab_case(shrink_bad_outcome RC 2 ERR "^dlab shrink: --outcome must be a failure class: not-delaunay, invalid, reported, differs, crash, timeout or out-of-memory, not 'broken'\n$"
          ARGS shrink lawson_float.txt ${lawson_pair} --outcome broken)
dlab_case(shrink_ok_outcome RC 2 ERR "--outcome must be a failure class.* not 'ok'" ARGS shrink lawson_float.txt ${lawson_pair} --outcome ok)
dlab_case(shrink_other_outcome RC 2 ERR "^dlab shrink: lawson_float.txt: lawson x float gives not-delaunay, not invalid: nothing to shrink\n$"
          ARGS shrink lawson_float.txt ${lawson_pair} --outcome invalid)
dlab_case(shrink_other_kind RC 2 ERR "gives not-delaunay, not not-delaunay \\(orientation\\): nothing to shrink" ARGS shrink lawson_float.txt ${lawson_pair} --kind orientation)
dlab_case(shrink_no_pair RC 2 ERR "give the pair that fails: --algo A --kernel K" ARGS shrink lawson_float.txt)
dlab_case(shrink_bad_kernel RC 2 ERR "quad" ARGS shrink lawson_float.txt --algo lawson --kernel quad)
dlab_case(shrink_dim RC 2 ERR "lawson_float.txt holds 2D points, not --dim 3" ARGS shrink lawson_float.txt ${lawson_pair} --dim 3)
dlab_case(shrink_kind_any RC 2 ERR "--kind and --any-kind exclude each other" ARGS shrink lawson_float.txt ${lawson_pair} --kind x --any-kind)
dlab_case(shrink_max_tests RC 2 ERR "--max-tests must be at least 2" ARGS shrink lawson_float.txt ${lawson_pair} --max-tests 1)
dlab_case(shrink_policy RC 2 ERR "--policy must be sos or strict, not 'fuzzy'" ARGS shrink lawson_float.txt ${lawson_pair} --policy fuzzy)
dlab_case(shrink_unwritable RC 2 ERR "cannot write '${WORK}/no/such/dir/x.txt'" ARGS shrink lawson_float.txt ${lawson_pair} -o "${WORK}/no/such/dir/x.txt")

# ---- every subcommand's command line (cli/cli_app.hpp, CLI11) -----------------
# --help: exit 0, on stdout the synopsis, the options with their descriptions
# and at least two example command lines; an unknown option: exit 2 and one
# stderr line naming it (before any missing argument). Words joined by ':'.
foreach(cmd triangulate check convert predicate gen flip draw demo plot fuzz fuzz:merge shrink
            corpus corpus:replay corpus:add study study:merge --version version)
  string(REPLACE ":" ";" words "${cmd}")
  list(GET words 0 prefix)
  if(prefix STREQUAL "version")
    set(prefix "--version")
  endif()
  dlab_case(help_${cmd} RC 0 OUT "^usage: dlab ${prefix}.*\nOptions:\n  -h,--help .*\nExamples:\n  dlab [^\n]+\n  dlab "
            ARGS ${words} --help)
  if(NOT cmd STREQUAL "corpus")
    dlab_case(unknown_option_${cmd} RC 2 ERR "^dlab ${prefix}: unknown option '--frobnicate'\n$" ARGS ${words} --frobnicate)
  endif()
endforeach()
# A bad number names its option (numbers.hpp's reason for a real); ':' joins words.
foreach(case triangulate:--seed gen:--n gen:--dim gen:--lo gen:--spacing flip:--flips fuzz:--cases fuzz:--jobs
             shrink:--max-tests corpus:replay:--jobs corpus:add:--memory study:--jobs)
  string(REPLACE ":" ";" words "${case}")
  list(POP_BACK words option)
  list(GET words 0 prefix)
  dlab_case(bad_number_${case} RC 2 ERR "^dlab ${prefix}: ${option}: [^\n]*'x1'[^\n]*\n$" ARGS ${words} ${option} x1)
endforeach()
dlab_case(number_underflow_option RC 2 ERR "^dlab gen: --lo: coordinate '1e-400' is not zero but rounds to zero" ARGS gen uniform --lo 1e-400)
dlab_case(number_overflow_option RC 2 ERR "^dlab gen: --hi: coordinate '1e400' overflows to infinity" ARGS gen uniform --hi 1e400)
dlab_case(number_range_option RC 2 ERR "^dlab fuzz: --jobs: '0' is not an integer in 1..256\n$" ARGS fuzz --jobs 0 --cases 1 --out x)
dlab_case(number_negative_value RC 0 OUT "^-0x1.[0-9a-f]+p[+]0 -0x1.[0-9a-f]+p[+]0\n$" ARGS gen uniform --n 1 --lo -2 --hi=-1)
dlab_case(number_hex_value RC 0 OUT "^0x1p[+]0 0x1p[+]0\n$" ARGS gen uniform --n 1 --lo 0x1p0 --hi 0x1p0)
dlab_case(option_twice_last RC 0 OUT "^0x1p[+]1 0x1p[+]1\n$" ARGS gen uniform --n 1 --lo 1 --hi 1 --lo 2 --hi 2)
dlab_case(flag_with_value RC 2 ERR "^dlab triangulate: option --validate takes no value \\(given 'maybe'\\)\n$" ARGS triangulate square.txt --validate=maybe)
dlab_case(missing_value_long RC 2 ERR "^dlab gen: option --seed needs a value\n$" ARGS gen uniform --seed)
dlab_case(stdin_positional RC 0 OUT "valid Delaunay" IN "${WORK}/square.txt" ARGS check - square.tri)
# Negative numbers are positional where no option has their name: "-.5", "-inf".
dlab_case(predicate_negative_coordinates RC 0 OUT "^-1\n$" ARGS predicate orient2d mp -.5 0 0.5 0 0 -0x1p-1)
dlab_case(predicate_negative_infinity RC 2 ERR "^dlab predicate: argument 1: infinite coordinate '-inf'\n$" ARGS predicate orient2d mp -inf 0 1 0 0 1)
dlab_case(after_double_dash RC 2 ERR "^dlab check: --x: cannot read" ARGS check -- --x square.tri)

if(failures GREATER 0)
  message(FATAL_ERROR "${failures} CLI case(s) failed")
endif()
