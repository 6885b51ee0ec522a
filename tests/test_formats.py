#!/usr/bin/env python3
"""ctest `formats` (label formats): `dlab convert` and the vertex-list readers.

Independent checks: Debian's meshio reads every file dlab writes and must get
the same points (bit for bit, from the hexadecimal floats of `dlab gen`) and
cells; the orientation of tetrahedra and hull facets is checked with exact
rational arithmetic (fractions); TetGen accepts our .node and, for points in
general position, builds the same Delaunay tetrahedra. Bad input exits 2 with
FILE:LINE in the message. --format / --input-format write and read any file
name and standard input/output: the same bytes as by extension, and what meshio
reads. Exit 77 (skip) without numpy/meshio.

usage: test_formats.py DLAB WORKDIR
"""
import os
import shutil
import subprocess
import sys
from fractions import Fraction

try:
    import meshio
    import numpy as np
except ImportError as e:
    print(f"SKIP: {e} (apt-get install python3-meshio)")
    sys.exit(77)

from cli_checks import DLAB, WORK, check, dlab, finish, fresh_work_dir, path  # noqa: E402


def read_hex_points(name):
    return [[float.fromhex(t) for t in line.split()] for line in open(path(name)) if line.strip()]


def read_ints(name, skip_header=False, drop_index=False):
    lines = (line.split("#")[0] for line in open(path(name)))
    rows = [[int(t) for t in line.split()] for line in lines if line.strip()]
    rows = rows[1:] if skip_header else rows
    return [r[1:] for r in rows] if drop_index else rows


def det3(a, b, c, d):
    u, v, w = ([Fraction(p[i]) - Fraction(a[i]) for i in range(3)] for p in (b, c, d))
    return (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
            + u[2] * (v[0] * w[1] - v[1] * w[0]))


def facet_counts(cells):
    counts = {}
    for s, c in enumerate(cells):
        for i in range(len(c)):
            key = tuple(sorted(c[:i] + c[i + 1:]))
            counts.setdefault(key, []).append((s, i))
    return counts


def same_points(got, want, what):
    got = np.asarray(got, dtype=float)
    want = np.asarray(want, dtype=float)
    if want.shape[1] == 2 and got.shape[1] == 3:
        check(np.all(got[:, 2] == 0), f"{what}: 2D points get z = 0")
        got = got[:, :2]
    check(got.shape == want.shape and np.array_equal(got, want), f"{what}: points differ from the input")


def same_cells(mesh, ctype, want, what):
    check(len(mesh.cells) == 1 and mesh.cells[0].type == ctype, f"{what}: one block of {ctype} cells")
    check(mesh.cells[0].data.tolist() == want, f"{what}: cells differ from SIMPLICES")


fresh_work_dir()

# --- writers, 2D: .node/.ele/.neigh (parsed here: meshio's tetgen reader is 3D only), .vtu, .off
dlab("gen", "uniform", "--n", "60", "--seed", "3", "-o", "p2.txt")
dlab("triangulate", "p2.txt", "-o", "t2.txt")
p2, t2 = read_hex_points("p2.txt"), read_ints("t2.txt")
dlab("convert", "p2.txt", "m2.node", "--simplices", "t2.txt")
node = [line.split() for line in open(path("m2.node")) if line.strip()]
check(node[0] == [str(len(p2)), "2", "0", "0"], "m2.node header")
check([int(r[0]) for r in node[1:]] == list(range(len(p2))), "m2.node numbered from 0")
same_points([[float(t) for t in r[1:]] for r in node[1:]], p2, "m2.node")
ele = read_ints("m2.ele")
check(ele[0] == [len(t2), 3, 0], "m2.ele header")
check([r[0] for r in ele[1:]] == list(range(len(t2))) and [r[1:] for r in ele[1:]] == t2, "m2.ele cells")
neigh = read_ints("m2.neigh")
check(neigh[0] == [len(t2), 3], "m2.neigh header")
counts = facet_counts(t2)
want_neigh = []
for s, c in enumerate(t2):
    row = []
    for i in range(3):
        users = counts[tuple(sorted(c[:i] + c[i + 1:]))]
        row.append(-1 if len(users) == 1 else next(u for u, _ in users if u != s))
    want_neigh.append(row)
check([r[1:] for r in neigh[1:]] == want_neigh, "m2.neigh: neighbour i across the edge opposite vertex i")
check(any(-1 in r for r in want_neigh), "m2.neigh: the hull is marked -1")
dlab("convert", "p2.txt", "m2.vtu", "--simplices", "t2.txt")
m = meshio.read(path("m2.vtu"))
same_points(m.points, p2, "m2.vtu")
same_cells(m, "triangle", t2, "m2.vtu")
dlab("convert", "p2.txt", "m2.off", "--simplices", "t2.txt")
m = meshio.read(path("m2.off"))
same_points(m.points, p2, "m2.off")
same_cells(m, "triangle", t2, "m2.off")

# --- writers, 3D: .node/.ele via meshio's tetgen reader, .face, .vtu
dlab("gen", "uniform", "--n", "80", "--dim", "3", "--seed", "5", "-o", "p3.txt")
dlab("triangulate", "p3.txt", "-o", "t3.txt")
p3, t3 = read_hex_points("p3.txt"), read_ints("t3.txt")
dlab("convert", "p3.txt", "m3.node", "--simplices", "t3.txt")
m = meshio.read(path("m3.node"))
same_points(m.points, p3, "m3.node")
same_cells(m, "tetra", t3, "m3.node/.ele")
hull = {k: v for k, v in facet_counts(t3).items() if len(v) == 1}
face = read_ints("m3.face")
check(face[0] == [len(hull), 0], "m3.face header: the number of hull facets")
faces = [r[1:] for r in face[1:]]
check(sorted(tuple(sorted(f)) for f in faces) == sorted(hull), "m3.face: exactly the hull facets")
for f in faces:
    (s, i), = hull[tuple(sorted(f))]
    inner = p3[t3[s][i]]
    check(det3(p3[f[0]], p3[f[1]], p3[f[2]], inner) < 0, f"m3.face {f}: not oriented outward")
dlab("convert", "p3.txt", "m3.vtu", "--simplices", "t3.txt")
m = meshio.read(path("m3.vtu"))
same_points(m.points, p3, "m3.vtu")
same_cells(m, "tetra", t3, "m3.vtu")
check(all(len(c) == 4 and det3(*(p3[v] for v in c)) > 0 for c in m.cells[0].data.tolist()),
      "m3.vtu: VTK_TETRA cells have positive volume")
dlab("convert", "p3.txt", "pts3.vtu")
m = meshio.read(path("pts3.vtu"))
same_points(m.points, p3, "pts3.vtu (points only)")
same_cells(m, "vertex", [[i] for i in range(len(p3))], "pts3.vtu (points only)")

# Same input, same bytes.
for out in ("m2.node", "m2.neigh", "m2.vtu", "m2.off", "m3.face", "m3.vtu"):
    first = open(path(out), "rb").read()
    base, ext = os.path.splitext(out)
    dlab("convert", "p2.txt" if out.startswith("m2") else "p3.txt", base + "_rerun" + (".node" if ext in (
        ".node", ".neigh", ".face") else ext), "--simplices", "t2.txt" if out.startswith("m2") else "t3.txt")
    check(open(path(base + "_rerun" + ext), "rb").read() == first, f"{out}: not byte-identical on a rerun")

# --- TetGen accepts our .node and builds the same Delaunay tetrahedra (general position)
if shutil.which("tetgen"):
    r = subprocess.run(["tetgen", "-zQ", "m3.node"], cwd=WORK, capture_output=True, text=True, timeout=60)
    check(r.returncode == 0, f"tetgen -zQ m3.node: exit {r.returncode}\n{r.stdout}{r.stderr}")
    tg = read_ints("m3.1.ele")
    check(tg[0][0] == len(t3), f"tetgen: {tg[0][0]} tetrahedra, dlab {len(t3)}")
    check(sorted(tuple(sorted(c[1:])) for c in tg[1:]) == sorted(tuple(sorted(c)) for c in t3),
          "tetgen: other tetrahedra than dlab's")
else:
    print("note: tetgen not installed, TetGen check skipped")

# --- readers: .xyz, .off, .ply vertex lists, compared with what meshio reads from the same text
xyz = [[0.1, 0.2, 0.3], [1.5, -2.25, 1e-300], [3.0, 4.0, 5.0], [-0.0, 7.0, 0.5], [2.0, 2.0, 9.0]]
with open(path("v.xyz"), "w") as f:
    f.write("# x y z\n\n" + "".join(" ".join(repr(c) for c in p) + "\n" for p in xyz))
dlab("convert", "v.xyz", "v_xyz.vtu")
same_points(meshio.read(path("v_xyz.vtu")).points, xyz, "v.xyz")
dlab("triangulate", "v.xyz", "-o", "v_xyz_tets.txt")  # every command reads vertex lists
check(len(read_ints("v_xyz_tets.txt")) >= 1, "dlab triangulate v.xyz: tetrahedra")

for name, binary in (("v.ply", False),):
    mesh = meshio.Mesh(np.array(xyz), [("triangle", np.array([[0, 1, 2], [1, 2, 3]], dtype=np.int32))])
    meshio.write(path(name), mesh, binary=binary)
    dlab("convert", name, "v_ply.vtu")
    same_points(meshio.read(path("v_ply.vtu")).points, meshio.read(path(name)).points, name)
meshio.write(path("v.off"), meshio.Mesh(np.array(xyz), [("triangle", np.array([[0, 1, 2]]))]))
dlab("convert", "v.off", "v_off.vtu")
same_points(meshio.read(path("v_off.vtu")).points, meshio.read(path("v.off")).points, "v.off")
# Our own 2D .off reads back as the same 2D points (every z is 0).
dlab("convert", "m2.off", "m2_again.node")
node = [line.split() for line in open(path("m2_again.node")) if line.strip()]
check(node[0][1] == "2", "m2.off read back as 2D")
same_points([[float(t) for t in r[1:]] for r in node[1:]], p2, "m2.off read back")
with open(path("v2.ply"), "w") as f:  # no z property, a list property, an element before vertex
    f.write("ply\nformat ascii 1.0\ncomment hand-written\nelement camera 1\nproperty float f\n"
            "element vertex 3\nproperty double x\nproperty list uchar int tags\nproperty double y\n"
            "end_header\n1.0\n0.5 2 7 8 0.25\n1 0 3\n0 1 9 4\n")
dlab("convert", "v2.ply", "v2.vtu")
same_points(meshio.read(path("v2.vtu")).points, [[0.5, 0.25], [1, 3], [0, 4]], "v2.ply (2D, list skipped)")

# --- bad input: exit 2, message "FILE:LINE: problem"
bad = {
    "b1.xyz": ("0 0 0\n1 1\n", "b1.xyz:2:"),
    "b2.xyz": ("0 0 0\n1 nan 1\n", "b2.xyz:2:"),
    "b3.off": ("COFF\n1 0 0\n0 0 0\n", "b3.off:1:"),
    "b4.off": ("OFF\n3 1 0\n0 0 0\n1 1 1\n", "b4.off:4:"),
    "b5.ply": ("ply\nformat binary_little_endian 1.0\nelement vertex 1\nproperty float x\nend_header\n",
               "b5.ply:2:"),
    "b6.ply": ("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nend_header\n"
               "1 2\n3\n", "b6.ply:8:"),
    "b7.ply": ("ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
               "end_header\n3 0 1 2\n", "b7.ply:6:"),  # no vertex element
    "b8.ply": ("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nend_header\n"
               "1 2\n", "b8.ply:7:"),  # one vertex short
}
for name, (text, where) in bad.items():
    with open(path(name), "w") as f:
        f.write(text)
    r = dlab("convert", name, "out.vtu", expect=2)
    check(where in r.stderr, f"{name}: message should contain '{where}': {r.stderr.strip()}")
r = dlab("convert", "p3.txt", "m3.off", "--simplices", "t3.txt", expect=2)
check("OFF holds triangles only" in r.stderr, f"3D simplices to .off: {r.stderr.strip()}")
dlab("convert", "p2.txt", "m2.stl", expect=2)
with open(path("bad_tri.txt"), "w") as f:
    f.write("0 1 2\n0 1 999\n")
r = dlab("convert", "p2.txt", "x.vtu", "--simplices", "bad_tri.txt", expect=2)
check("bad_tri.txt:2:" in r.stderr, f"out-of-range simplex: {r.stderr.strip()}")
r = dlab("convert", "--help")
check("Examples" in r.stdout and ".vtu" in r.stdout, "dlab convert --help")

# --- --format / --input-format: any name, standard input and output; what is written or read
# is checked against meshio and against the files written by extension above.
def dlab_bytes(*args, stdin=b""):
    r = subprocess.run([DLAB, *args], cwd=WORK, input=stdin, capture_output=True, timeout=120)
    check(r.returncode == 0, f"dlab {' '.join(args)}: exit {r.returncode}\n{r.stderr.decode()}")
    return r.stdout


def same_bytes(a, b, what):
    check(open(path(a), "rb").read() == open(path(b), "rb").read(), f"{what}: {a} differs from {b}")


dlab("convert", "p2.txt", "m2_vtu.dat", "--simplices", "t2.txt", "--format", "vtu")
m = meshio.read(path("m2_vtu.dat"), file_format="vtu")
same_points(m.points, p2, "--format vtu")
same_cells(m, "triangle", t2, "--format vtu")
same_bytes("m2_vtu.dat", "m2.vtu", "--format vtu")
dlab("convert", "p2.txt", "m2_off.vtu", "--simplices", "t2.txt", "--format", "off")  # the option wins
same_bytes("m2_off.vtu", "m2.off", "--format off over the .vtu extension")
out = dlab_bytes("convert", "p2.txt", "-", "--simplices", "t2.txt", "--format", "off")
check(out == open(path("m2.off"), "rb").read(), "--format off to standard output: not m2.off's bytes")
out = dlab_bytes("convert", "p3.txt", "-", "--simplices", "t3.txt", "--format", "vtu")
check(out == open(path("m3.vtu"), "rb").read(), "--format vtu to standard output: not m3.vtu's bytes")
dlab("convert", "p3.txt", "m3_named", "--simplices", "t3.txt", "--format", "node")  # BASE without .node
for ext in (".node", ".ele", ".face"):
    same_bytes("m3_named" + ext, "m3" + ext, "--format node, OUT without extension")
shutil.copy(path("v.xyz"), path("v_xyz.dat"))
dlab("convert", "v_xyz.dat", "v_dat.vtu", "--input-format", "xyz")
same_points(meshio.read(path("v_dat.vtu")).points, xyz, "--input-format xyz")
with open(path("flat.dat"), "w") as f:  # every z is 0: 2D as .xyz, 3D as plain text
    f.write("0 0 0\n1 0 0\n0 1 0\n")
dlab("convert", "flat.dat", "flat.node", "--input-format", "xyz")
check(open(path("flat.node")).readline().split()[:2] == ["3", "2"], "--input-format xyz: flat.dat not read as 2D")
out = dlab_bytes("convert", "-", "-", "--input-format", "ply", "--format", "vtu", stdin=open(path("v.ply"), "rb").read())
with open(path("v_stdin.vtu"), "wb") as f:
    f.write(out)
same_points(meshio.read(path("v_stdin.vtu")).points, meshio.read(path("v.ply")).points, "--input-format ply from stdin")
shutil.copy(path("m3.node"), path("m3_node.dat"))
dlab("triangulate", "m3_node.dat", "--input-format", "node", "-o", "t3_again.txt")
same_bytes("t3_again.txt", "t3.txt", "dlab triangulate --input-format node")
# Every command that reads points takes --input-format (m3_node.dat is a .node file).
for cmd in (["check", "m3_node.dat", "t3.txt"], ["flip", "m3_node.dat", "t3.txt", "-o", "f3.txt"],
            ["draw", "m3_node.dat", "t3.txt", "-o", "d3.vtu"], ["voronoi", "m3_node.dat", "t3.txt", "-o", "v3.vtu"]):
    dlab(*cmd, "--input-format", "node")
    r = dlab(*cmd, expect=2)  # by its extension: plain text, whose first line has 4 numbers
    check("m3_node.dat:" in r.stderr, f"dlab {cmd[0]} without --input-format: {r.stderr.strip()}")
r = dlab("convert", "m2.node", "x.vtu", "--input-format", "text", expect=2)  # its header: 4 numbers
check("m2.node:1:" in r.stderr, f"--input-format text on a .node file: {r.stderr.strip()}")
r = dlab("convert", "p2.txt", "x.vtu", "--format", "stl", expect=2)
check("unknown format 'stl'" in r.stderr and "node, vtu, off" in r.stderr, f"--format stl: {r.stderr.strip()}")
r = dlab("triangulate", "p2.txt", "--input-format", "stl", expect=2)
check("unknown input format 'stl'" in r.stderr and "text, node, xyz, off, ply" in r.stderr,
      f"--input-format stl: {r.stderr.strip()}")
r = dlab("convert", "p2.txt", "mesh", expect=2)
check("--format" in r.stderr, f"OUT without extension, no --format: {r.stderr.strip()}")
r = dlab("convert", "p2.txt", "-", "--format", "node", expect=2)
check("several files" in r.stderr, f"--format node to standard output: {r.stderr.strip()}")

finish("formats")
