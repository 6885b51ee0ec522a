#!/bin/bash
# `dlab draw` (issue 14, pictures), run by ctest as
#   test_draw.sh DLAB WORKDIR PYTHON3
# on hand-made 2D meshes whose faults are known without dlab: a rhombus
# (0,0) (10,0) (5,1) (5,-1), whose Delaunay diagonal is the short one 2-3
# (the circle through 0,1,2 has centre (5,-12) and radius 13, and holds point
# 3 at distance 11; the circle through 0,3,2 has centre (2.6,0), radius 2.6,
# and misses point 1), drawn
#   Delaunay          -> one polygon per simplex, nothing marked, exit 0
#   long diagonal 0-1 -> exactly edge "0 1" marked non-Delaunay, exit 1
#   + unused point 4  -> exactly point 4 marked missing
#   one simplex reversed -> exactly that simplex marked inverted (and edge 2-3
#                           as an overlap)
# a flipped 30-point mesh (dlab flip --make-start) -> as many marked edges as
# `dlab check` counts; every SVG parses as XML (xml.etree); output repeats
# byte for byte; bad input (3D as SVG, index out of range, missing file)
# exits 2; a 3D mesh gives a .vtu whose cell flags are checked on hand-made
# tetrahedra (below).
set -u
DLAB=$1
WORK=$2
PY=$3
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# summary SVG: "polygons=N nd=[edges] inverted=[simplices] overlap=[...] missing=[points]"
summary() {
  "$PY" - "$1" <<'EOF'
import sys, xml.etree.ElementTree as ET
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[1]).getroot()
polys = [e for e in root.iter(ns + "polygon") if "data-simplex" in e.attrib]
nd = sorted(e.get("data-edge") for e in root.iter(ns + "line") if "non-delaunay" in e.get("class", "").split())
ov = sorted(e.get("data-edge") for e in root.iter(ns + "line") if "overlap" in e.get("class", "").split())
inv = [e.get("data-simplex") for e in polys if "inverted" in e.get("class", "").split()]
ovt = [e.get("data-simplex") for e in polys if "overlap" in e.get("class", "").split()]
miss = [e.get("data-point") for e in root.iter(ns + "circle") if "missing" in e.get("class", "").split()]
print("polygons=%d nd=%s inverted=%s overlap=%s/%s missing=%s" % (len(polys), nd, inv, ovt, ov, miss))
EOF
}
# expect NAME WANT_RC WANT_SUMMARY DRAW_ARGS...
expect() {
  local name=$1 want_rc=$2 want=$3
  shift 3
  "$DLAB" draw "$@" -o "$name.svg" 2>"$name.err"
  local rc=$?
  [ "$rc" = "$want_rc" ] || fail "$name: exit $rc, want $want_rc ($(cat "$name.err"))"
  local got
  got=$(summary "$name.svg") || { fail "$name: not well-formed XML"; return; }
  [ "$got" = "$want" ] || fail "$name: got '$got', want '$want'"
}

printf '0 0\n10 0\n5 1\n5 -1\n' > rhombus.txt
# Independent check of which diagonal is Delaunay: 3 strictly inside the
# circle through 0 1 2 (incircle > 0) means edge 0-1 is not locally Delaunay.
[ "$("$DLAB" predicate incircle mp 0 0 10 0 5 1 5 -1)" = 1 ] || fail "rhombus: 3 not inside circle(0,1,2)"
printf '0 3 2\n3 1 2\n' > delaunay.txt
printf '0 3 1\n0 1 2\n' > long.txt
expect delaunay 0 "polygons=2 nd=[] inverted=[] overlap=[]/[] missing=[]" rhombus.txt delaunay.txt
expect long 1 "polygons=2 nd=['0 1'] inverted=[] overlap=[]/[] missing=[]" rhombus.txt long.txt
expect labelled 0 "polygons=2 nd=[] inverted=[] overlap=[]/[] missing=[]" rhombus.txt delaunay.txt --labels --circles

printf '0 0\n10 0\n5 1\n5 -1\n5 0\n' > five.txt
expect missing 1 "polygons=2 nd=[] inverted=[] overlap=[]/[] missing=['4']" five.txt delaunay.txt

# Second simplex clockwise: inverted; as given, it induces the same orientation
# on edge 2-3 as simplex 0, so the validator also reports that edge as an
# overlap (facet_same_side), and simplex 0 is drawn overlapping.
printf '0 3 2\n1 3 2\n' > inverted.txt
expect inverted 1 "polygons=2 nd=[] inverted=['1'] overlap=['0']/['2 3'] missing=[]" rhombus.txt inverted.txt

# A bigger mesh made non-Delaunay by random flips: marked edges = check's count.
"$DLAB" gen uniform --n 30 --seed 3 > p30.txt || fail "gen"
"$DLAB" flip p30.txt --make-start --seed 5 --flips 4 -o f30.txt || fail "make-start"
want=$("$DLAB" check p30.txt f30.txt | sed -n 's/^not_delaunay: \([0-9]*\) .*/\1/p')
"$DLAB" draw p30.txt f30.txt -o f30.svg
got=$(summary f30.svg | sed -n "s/.*nd=\[\([^]]*\)\].*/\1/p" | tr ',' '\n' | grep -c .)
[ -n "$want" ] && [ "$want" -gt 0 ] && [ "$got" = "$want" ] || fail "flipped 30: $got edges marked, check says '$want'"
"$DLAB" draw p30.txt f30.txt -o f30b.svg --labels
"$DLAB" draw p30.txt f30.txt -o f30c.svg --labels
cmp -s f30b.svg f30c.svg || fail "same input, different bytes"

# Bad input: exit 2 with file (and line) named.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' > p3.txt
printf '0 1 2 3\n' > t3.txt
"$DLAB" draw p3.txt t3.txt -o x.svg 2>err.txt
[ $? = 2 ] && grep -q 'p3.txt.*\.vtu' err.txt || fail "3D as SVG: $(cat err.txt)"

# 3D: a .vtu with per-cell flags. A bipyramid over the triangle (0,0,0)
# (10,0,0) (0,10,0) with apexes 3 = (3,3,1) and 4 = (3,3,-1), split by the
# triangle into two tetrahedra (both positive: det = 100): the sphere through
# the triangle and 3 has centre (5,5,-20.5), R^2 = 470.25, and holds 4 at
# squared distance 388.25 (by symmetry the other sphere holds 3), so each
# tetrahedron has exactly one non-Delaunay facet.
printf '0 0 0\n10 0 0\n0 10 0\n3 3 1\n3 3 -1\n' > bi.txt
printf '0 1 2 3\n0 2 1 4\n' > bi2.txt
# cells FILE: "faulty inverted overlapping non_delaunay_facets" per cell, then "missing=[...]"
cells() {
  "$PY" - "$1" <<'EOF'
import sys, xml.etree.ElementTree as ET
piece = ET.parse(sys.argv[1]).getroot().find("UnstructuredGrid/Piece")
arr = {a.get("Name"): a.text.split() for a in piece.find("CellData")}
pts = {a.get("Name"): a.text.split() for a in piece.find("PointData")}
for c in range(int(piece.get("NumberOfCells"))):
    print(*(arr[k][c] for k in ("faulty", "inverted", "overlapping", "non_delaunay_facets")))
print("missing=[" + ",".join(str(i) for i, v in enumerate(pts["missing"]) if v != "0") + "]")
EOF
}
"$DLAB" draw bi.txt bi2.txt -o bi2.vtu; rc=$?
got=$(cells bi2.vtu | tr '\n' ';')
[ $rc = 1 ] && [ "$got" = "1 0 0 1;1 0 0 1;missing=[];" ] || fail "3D two tets: rc=$rc $got"
# The second tetrahedron reversed (det = -100): inverted; point 5 = (1,1,0) on
# the shared triangle is no vertex: missing.
printf '0 0 0\n10 0 0\n0 10 0\n3 3 1\n3 3 -1\n1 1 0\n' > bi5.txt
printf '0 1 2 3\n0 1 2 4\n' > bi2r.txt
"$DLAB" draw bi5.txt bi2r.txt -o bi2r.vtu; rc=$?
got=$(cells bi2r.vtu | sed -n '2p;3p' | cut -d' ' -f1,2 | tr '\n' ';')
[ $rc = 1 ] && [ "$got" = "1 1;missing=[5];" ] || fail "3D inverted + missing: rc=$rc $got"
# One reversed tetrahedron alone: only "inverted" (and so "faulty") set.
printf '0 0 0\n1 0 0\n0 1 0\n0 0 1\n' > u.txt
printf '0 2 1 3\n' > ur.txt
"$DLAB" draw u.txt ur.txt -o ur.vtu; rc=$?
got=$(cells ur.vtu | tr '\n' ';')
[ $rc = 1 ] && [ "$got" = "1 1 0 0;missing=[];" ] || fail "3D reversed tetrahedron: rc=$rc $got"
# The Delaunay tetrahedralisation (three tetrahedra around edge 3-4): no flag.
"$DLAB" triangulate bi.txt -o bi3.txt && "$DLAB" draw bi.txt bi3.txt -o bi3.vtu; rc=$?
got=$(cells bi3.vtu | tr '\n' ';')
[ $rc = 0 ] && [ "$got" = "0 0 0 0;0 0 0 0;0 0 0 0;missing=[];" ] || fail "3D Delaunay: rc=$rc $got"
"$PY" -c "import meshio; m = meshio.read('bi2.vtu'); assert m.cells[0].type == 'tetra' and len(m.cells[0].data) == 2" ||
  fail "meshio cannot read the 3D picture"
printf '0 3 2\n3 1 7\n' > range.txt
"$DLAB" draw rhombus.txt range.txt -o x.svg 2>err.txt
[ $? = 2 ] && grep -q 'range.txt:2' err.txt || fail "index out of range: $(cat err.txt)"
"$DLAB" draw nonexistent.txt delaunay.txt -o x.svg 2>err.txt
[ $? = 2 ] && grep -q 'nonexistent.txt' err.txt || fail "unreadable: $(cat err.txt)"
"$DLAB" draw rhombus.txt -o x.svg 2>err.txt
[ $? = 2 ] || fail "missing SIMPLICES accepted"
"$DLAB" draw --help | grep -q 'Example' || fail "--help without example"

[ $failures = 0 ] && echo "all draw checks passed"
exit $((failures > 0))
