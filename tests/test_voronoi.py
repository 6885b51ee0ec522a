#!/usr/bin/env python3
"""ctest `voronoi` (label formats): `dlab voronoi`, checked independently.

* the circumcentres written (points with point data simplex >= 0) are the
  vertices scipy.spatial.Voronoi finds (Qhull, inexact: relative 1e-9), 2D and 3D;
* each is the correctly rounded exact centre: with fractions.Fraction, the
  exact centre is no farther from the written double than from its two
  neighbours (math.nextafter up and down);
* 2D: the cells' areas sum to the box's area, each cell holds its site, the
  default box is the bounding box enlarged by 10 % each side; 3D: the cells'
  volumes (divergence theorem over the faces) sum to the box's volume;
* cocircular / cospherical points (a lattice): cells stay valid (no repeated
  consecutive vertex, areas / volumes still sum to the box's);
* the .vtu is parsed with the standard library (xml.etree); meshio is asked
  to read it too and what it does is checked (see meshio_reads below);
* same input -> byte-identical files; SIMPLICES that are not Delaunay, and
  bad usage, exit 2 with FILE:LINE.
Exit 77 (skip) without numpy/scipy.

usage: test_voronoi.py DLAB WORKDIR
"""
import math
import sys
import xml.etree.ElementTree as ET
from fractions import Fraction

try:
    import numpy as np
    from scipy.spatial import Voronoi, cKDTree
except ImportError as e:
    print(f"SKIP: {e}")
    sys.exit(77)

from cli_checks import check, dlab, finish, fresh_work_dir, path  # noqa: E402


def read_points(name):
    return [[float.fromhex(t) if "x" in t else float(t) for t in line.split()]
            for line in open(path(name)) if line.strip() and not line.startswith("#")]


def read_ints(name):
    return [[int(t) for t in line.split()] for line in open(path(name)) if line.strip()]


def read_vtu(name):
    """Points, point data, cell data, and per cell its faces (2D: one)."""
    piece = ET.parse(path(name)).getroot().find("UnstructuredGrid/Piece")
    arr = {}
    for group in ("PointData", "CellData", "Points", "Cells"):
        for a in piece.find(group).findall("DataArray"):
            arr[(group, a.get("Name"))] = a.text.split()
    pts = [[float(x) for x in arr[("Points", None)][i:i + 3]] for i in range(0, len(arr[("Points", None)]), 3)]
    conn = [int(x) for x in arr[("Cells", "connectivity")]]
    offs = [int(x) for x in arr[("Cells", "offsets")]]
    types = [int(x) for x in arr[("Cells", "types")]]
    cells = []
    if ("Cells", "faces") in arr:
        faces = [int(x) for x in arr[("Cells", "faces")]]
        foffs = [int(x) for x in arr[("Cells", "faceoffsets")]]
        start = 0
        for end in foffs:
            k, i, fs = faces[start], start + 1, []
            for _ in range(k):
                fs.append(faces[i + 1:i + 1 + faces[i]])
                i += 1 + faces[i]
            check(i == end, f"{name}: faceoffsets disagree with the faces array")
            cells.append(fs)
            start = end
    else:
        start = 0
        for end in offs:
            cells.append([conn[start:end]])
            start = end
    return dict(points=pts, simplex=[int(x) for x in arr[("PointData", "simplex")]],
                site=[int(x) for x in arr[("CellData", "site")]],
                clipped=[int(x) for x in arr[("CellData", "clipped")]], cells=cells, types=types)


def exact_centre(vs):
    """Circumcentre with rationals: solve 2 (v - a).c = |v - a|^2 (Gaussian elimination)."""
    a = [Fraction(x) for x in vs[0]]
    d = len(a)
    rows = []
    for v in vs[1:]:
        u = [Fraction(x) - y for x, y in zip(v, a)]
        rows.append([2 * x for x in u] + [sum(x * x for x in u)])
    for c in range(d):
        p = next(r for r in range(c, d) if rows[r][c] != 0)
        rows[c], rows[p] = rows[p], rows[c]
        for r in range(d):
            if r != c and rows[r][c] != 0:
                f = rows[r][c] / rows[c][c]
                rows[r] = [x - f * y for x, y in zip(rows[r], rows[c])]
    return [a[i] + rows[i][d] / rows[i][i] for i in range(d)]


def correctly_rounded(x, exact):
    e = abs(Fraction(x) - exact)
    return all(e <= abs(Fraction(math.nextafter(x, t)) - exact) for t in (math.inf, -math.inf))


def check_centres(name, pts, simplices, vtu, dim):
    bad = 0
    for i, s in enumerate(simplices):
        c = exact_centre([pts[j] for j in s])
        bad += not all(correctly_rounded(vtu["points"][i][k], c[k]) for k in range(dim))
    check(bad == 0, f"{name}: {bad} of {len(simplices)} circumcentres are not the correctly rounded exact centre")
    check(vtu["simplex"][:len(simplices)] == list(range(len(simplices))), f"{name}: point data simplex")


def check_against_scipy(name, pts, vtu, dim):
    ours = np.array([p[:dim] for p, s in zip(vtu["points"], vtu["simplex"]) if s >= 0])
    ours = np.unique(ours, axis=0)
    theirs = np.unique(Voronoi(np.array(pts)).vertices, axis=0)
    check(len(ours) == len(theirs), f"{name}: {len(ours)} centres, scipy has {len(theirs)} Voronoi vertices")
    scale = np.abs(theirs).max()
    dist, _ = cKDTree(theirs).query(ours)
    check(dist.max() <= 1e-9 * scale, f"{name}: a centre is {dist.max():.3g} from scipy's nearest vertex")
    dist, _ = cKDTree(ours).query(theirs)
    check(dist.max() <= 1e-9 * scale, f"{name}: a scipy vertex is {dist.max():.3g} from our nearest centre")


def polygon_area(p):
    return sum(p[i][0] * p[(i + 1) % len(p)][1] - p[(i + 1) % len(p)][0] * p[i][1] for i in range(len(p))) / 2


def check_2d_cells(name, pts, vtu, box):
    area = 0.0
    for cell, site in zip(vtu["cells"], vtu["site"]):
        poly = [vtu["points"][v][:2] for v in cell[0]]
        check(all(poly[i] != poly[(i + 1) % len(poly)] for i in range(len(poly))) and len(poly) >= 3,
              f"{name}: cell of site {site} repeats a vertex")
        a = polygon_area(poly)
        check(a > 0, f"{name}: cell of site {site} not counterclockwise (area {a})")
        area += a
        s = pts[site]
        size = math.hypot(box[2] - box[0], box[3] - box[1])
        inside = all((q[0] - p[0]) * (s[1] - p[1]) - (q[1] - p[1]) * (s[0] - p[0]) >= -1e-9 * size * size
                     for p, q in zip(poly, poly[1:] + poly[:1]))
        check(inside, f"{name}: site {site} outside its cell")
    box_area = (box[2] - box[0]) * (box[3] - box[1])
    check(abs(area - box_area) <= 1e-9 * box_area, f"{name}: cell areas sum to {area!r}, box {box_area!r}")
    check(vtu["types"] == [7] * len(vtu["cells"]), f"{name}: cells are not VTK_POLYGON")


def polyhedron_volume(points, faces):
    vol = 0.0
    for f in faces:  # divergence theorem: fans of the faces with the origin
        a = points[f[0]]
        for b, c in zip((points[v] for v in f[1:-1]), (points[v] for v in f[2:])):
            vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6
    return vol


def check_3d_cells(name, vtu, box):
    total = 0.0
    for faces, site in zip(vtu["cells"], vtu["site"]):
        v = polyhedron_volume(vtu["points"], faces)
        check(v > 0, f"{name}: cell of site {site} has volume {v} (faces not outward?)")
        for f in faces:
            check(len(f) >= 3 and all(f[i] != f[(i + 1) % len(f)] for i in range(len(f))),
                  f"{name}: a face of site {site} repeats a vertex")
        total += v
    box_vol = (box[3] - box[0]) * (box[4] - box[1]) * (box[5] - box[2])
    check(abs(total - box_vol) <= 1e-9 * box_vol, f"{name}: cell volumes sum to {total!r}, box {box_vol!r}")
    check(vtu["types"] == [42] * len(vtu["cells"]), f"{name}: cells are not VTK_POLYHEDRON")


def meshio_reads(name, cells):
    """What Debian's meshio (5.3) makes of the file; None without meshio."""
    try:
        import meshio
    except ImportError:
        return None
    m = meshio.read(path(name))
    n = sum(len(b.data) for b in m.cells)
    check(n == cells, f"meshio reads {n} cells of {name}, expected {cells}")
    return [b.type for b in m.cells]


def same_bytes(args, out):
    """Runs `dlab ARGS -o again_OUT` and compares with OUT, written before with the same ARGS."""
    dlab(*args, "-o", "again_" + out)
    check(open(path(out), "rb").read() == open(path("again_" + out), "rb").read(), f"{out}: not byte-identical")


fresh_work_dir()

# 2D, general position; the box by default and given.
with open(path("p2.txt"), "w") as f:
    f.write(dlab("gen", "uniform", "--n", "80", "--seed", "5").stdout)
dlab("triangulate", "p2.txt", "-o", "t2.txt")
p2, t2 = read_points("p2.txt"), read_ints("t2.txt")
dlab("voronoi", "p2.txt", "t2.txt", "-o", "v2.vtu")
v2 = read_vtu("v2.vtu")
lo, hi = np.min(p2, axis=0), np.max(p2, axis=0)
box2 = [*(lo - (hi - lo) / 10), *(hi + (hi - lo) / 10)]
check_centres("v2.vtu", p2, t2, v2, 2)
check_against_scipy("v2.vtu", p2, v2, 2)
check_2d_cells("v2.vtu", p2, v2, box2)
check(sorted(v2["site"]) == list(range(len(p2))), "v2.vtu: not one cell per site")
check(sum(v2["clipped"]) < len(p2), "v2.vtu: every cell clipped")
types = meshio_reads("v2.vtu", len(p2))
print("meshio reads the 2D .vtu as", sorted(set(types or [])))
same_bytes(["voronoi", "p2.txt", "t2.txt"], "v2.vtu")
dlab("voronoi", "p2.txt", "-o", "v2b.vtu")  # triangulated by dlab itself
check(open(path("v2b.vtu")).read() == open(path("v2.vtu")).read(), "triangulating here differs from SIMPLICES")
dlab("voronoi", "p2.txt", "-o", "v2.svg", "--box", "-0.5,-0.5,1.5,1.5")
svg = ET.parse(path("v2.svg")).getroot()
check(len(svg.findall(".//{http://www.w3.org/2000/svg}polygon")) == len(p2), "v2.svg: not one polygon per site")
dlab("voronoi", "p2.txt", "-o", "v2box.vtu", "--box", "-0.5,-0.5,1.5,1.5")
check_2d_cells("v2box.vtu", p2, read_vtu("v2box.vtu"), [-0.5, -0.5, 1.5, 1.5])
same_bytes(["voronoi", "p2.txt", "--box", "-0.5,-0.5,1.5,1.5"], "v2.svg")

# 2D cocircular: a 5 x 5 lattice (every square's four corners share a centre).
with open(path("grid.txt"), "w") as f:
    f.writelines(f"{i} {j}\n" for i in range(5) for j in range(5))
dlab("voronoi", "grid.txt", "-o", "grid.vtu")
grid = read_vtu("grid.vtu")
check_2d_cells("grid.vtu", read_points("grid.txt"), grid, [-0.4, -0.4, 4.4, 4.4])
inner = [c for c, s in zip(grid["cells"], grid["site"]) if s == 12][0][0]
check(len(inner) == 4, f"grid.vtu: the centre site's cell has {len(inner)} vertices, not the 4 of a square")

# 3D, general position.
with open(path("p3.txt"), "w") as f:
    f.write(dlab("gen", "uniform", "--dim", "3", "--n", "60", "--seed", "7").stdout)
dlab("triangulate", "p3.txt", "-o", "t3.txt")
p3, t3 = read_points("p3.txt"), read_ints("t3.txt")
dlab("voronoi", "p3.txt", "t3.txt", "-o", "v3.vtu")
v3 = read_vtu("v3.vtu")
lo, hi = np.min(p3, axis=0), np.max(p3, axis=0)
box3 = [*(lo - (hi - lo) / 10), *(hi + (hi - lo) / 10)]
check_centres("v3.vtu", p3, t3, v3, 3)
check_against_scipy("v3.vtu", p3, v3, 3)
check_3d_cells("v3.vtu", v3, box3)
check(sorted(v3["site"]) == list(range(len(p3))), "v3.vtu: not one cell per site")
check(0 < sum(v3["clipped"]) < len(p3), "v3.vtu: no interior (unclipped) cell, or no clipped one")
# meshio 5.3 reads VTK_POLYHEDRON cells into one block per face count
# ("polyhedron12", ...) but then rejects cell data of the whole grid ("Incompatible
# cell data"): it must read the file without the CellData block.
with open(path("v3_nodata.vtu"), "w") as f:
    text = open(path("v3.vtu")).read()
    f.write(text[:text.index("      <CellData>")] + text[text.index("</CellData>\n") + 12:])
types = meshio_reads("v3_nodata.vtu", len(p3))
check(types is None or all(t.startswith("polyhedron") for t in types), f"meshio: {types}")
try:
    meshio_reads("v3.vtu", len(p3))
    print("meshio reads the 3D .vtu with its cell data")
except Exception as e:  # noqa: BLE001 -- report what meshio does with polyhedra and cell data
    print(f"meshio, 3D .vtu with cell data: {type(e).__name__}: {e}")
same_bytes(["voronoi", "p3.txt", "t3.txt"], "v3.vtu")

# 3D cospherical: a 4 x 4 x 4 lattice.
with open(path("cube.txt"), "w") as f:
    f.writelines(f"{i} {j} {k}\n" for i in range(4) for j in range(4) for k in range(4))
dlab("voronoi", "cube.txt", "-o", "cube.vtu")
check_3d_cells("cube.vtu", read_vtu("cube.vtu"), [-0.3, -0.3, -0.3, 3.3, 3.3, 3.3])

# round_quotient's boundaries (voronoi/circumcentre.hpp), one triangle each: exact ties
# (ties to even, down and up), subnormal centres (a tie to 2^-1073, one to 0), overflow.
for name, pts, want in [
    ("tie_down", ["1 0", f"{float(2**53).hex()} 0", "1 1"], (2.0**52, 0.5)),
    ("tie_up", ["1 0", f"{float(2**53 + 2).hex()} 0", "1 1"], (2.0**52 + 2, 0.5)),
    ("subnormal", ["0 0", "0x0.0000000000003p-1022 0", "0 0x1p-1070"], (2.0**-1073, 2.0**-1071)),
    ("to_zero", ["0 0", "0x0.0000000000001p-1022 0", "0 0x1p-1073"], (0.0, 2.0**-1074)),
    ("overflow", ["0 0", "0x1p+1000 0", "0x1p+999 0x1p-1000"], (None, -math.inf)),
]:
    with open(path(name + ".txt"), "w") as f:
        f.write("\n".join(pts) + "\n")
    with open(path(name + ".tri"), "w") as f:
        f.write("0 1 2\n")
    dlab("voronoi", name + ".txt", name + ".tri", "-o", name + ".vtu")
    got = read_vtu(name + ".vtu")["points"][0]
    check(all(w is None or g == w for g, w in zip(got, want)), f"{name}: centre {got[:2]}, expected {want}")

# Bad input: a non-Delaunay diagonal (line 2, after a comment), bad usage.
with open(path("sq.txt"), "w") as f:
    f.write("0 0\n4 0\n4 1\n0 1.5\n")
with open(path("sq_bad.txt"), "w") as f:
    f.write("# the long diagonal\n1 2 3\n0 1 3\n")
r = dlab("voronoi", "sq.txt", "sq_bad.txt", "-o", "x.svg", expect=2)
check("sq_bad.txt:2: not a Delaunay triangulation" in r.stderr or "sq_bad.txt:3: not a Delaunay" in r.stderr,
      f"non-Delaunay SIMPLICES: {r.stderr!r}")
r = dlab("voronoi", "sq.txt", "-o", "x.png", expect=2)
check("-o must end in .svg or .vtu" in r.stderr, f"bad -o: {r.stderr!r}")
r = dlab("voronoi", "sq.txt", "-o", "x.svg", "--box", "0,0,1", expect=2)
check("--box needs 4 numbers" in r.stderr, f"bad --box: {r.stderr!r}")
r = dlab("voronoi", "p3.txt", "-o", "x.svg", expect=2)
check("3D points" in r.stderr, f"3D to SVG: {r.stderr!r}")
check(dlab("voronoi", "--help").stdout.count("dlab voronoi ") >= 3, "--help without two examples")

finish("voronoi")
