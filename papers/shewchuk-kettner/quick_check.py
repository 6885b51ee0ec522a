"""ctest papers.shewchuk-kettner (label papers): the direction of both claims, quickly.
Usage: quick_check.py DLAB WORK_DIR. Standard library only.

Kettner et al. 2008: dlab's float orient2d gets signs wrong on the 256 x 256 grid, and
with their formula even the opposite sign; the exact kernels' maps equal the sign
computed here with rational arithmetic (fractions.Fraction), independently of dlab.
The float maps are also recomputed here in Python floats (IEEE binary64, no fused
operations): they must be dlab's bit for bit.
Shewchuk 1997: on random input every call of the adaptive kernel is answered by its
floating-point stages (static, filter, A), which is why it costs about what float
costs; near-degenerate input does reach the exact stages.
"""
import json
import pathlib
import subprocess
import sys
from fractions import Fraction

DLAB, WORK = sys.argv[1], pathlib.Path(sys.argv[2])
WORK.mkdir(parents=True, exist_ok=True)
SIDE = 256
U = 2.0 ** -53
Q, R = (12.0, 12.0), (24.0, 24.0)
failures = []


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what)
    if not cond:
        failures.append(what)


def sign(v):
    return (v > 0) - (v < 0)


def dlab_map(*options):
    out = subprocess.run([DLAB, "demo", "--sign-map"] + list(options), capture_output=True,
                         text=True, check=True).stdout
    rows = [l for l in out.splitlines() if not l.startswith("#")]
    assert len(rows) == SIDE and all(len(r) == SIDE for r in rows), "256 rows of 256 signs"
    return [[{"+": 1, "-": -1, "0": 0}[c] for c in r] for r in rows]


def p_of(x, y):
    return (0.5 + x * U, 0.5 + y * U)  # exact in binary64: 0.5's ulp is 2^-53


def orient_float(a, b, c):
    """Shewchuk's orient2d formula in doubles: differences from the last point."""
    acx, acy, bcx, bcy = a[0] - c[0], a[1] - c[1], b[0] - c[0], b[1] - c[1]
    return sign(acx * bcy - acy * bcx)


def orient_exact(a, b, c):
    a, b, c = [tuple(Fraction(v) for v in t) for t in (a, b, c)]
    return sign((a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0]))


exact = [[orient_exact(p_of(x, y), Q, R) for x in range(SIDE)] for y in range(SIDE)]
check(all(exact[y][x] == sign(y - x) for y in range(SIDE) for x in range(SIDE)),
      "rational orient2d(p, q, r) = sign(y - x) on the grid (the paper's setting)")

for kernel in ["adaptive", "integer", "mp"]:
    m = dlab_map(kernel)
    bad = sum(m[y][x] != exact[y][x] for y in range(SIDE) for x in range(SIDE))
    check(bad == 0, "%s: all %d signs equal the rational ones (%d differ)" % (kernel, SIDE * SIDE, bad))

m = dlab_map("float")
wrong = sum(m[y][x] != exact[y][x] for y in range(SIDE) for x in range(SIDE))
same = all(m[y][x] == orient_float(p_of(x, y), Q, R) for y in range(SIDE) for x in range(SIDE))
check(wrong > 0, "float orient2d(p, q, r): %d wrong signs (> 0)" % wrong)
check(same, "float orient2d(p, q, r) = the same formula in Python doubles, every sign")

m = dlab_map("float", "--qrp")
opposite = sum(m[y][x] * exact[y][x] < 0 for y in range(SIDE) for x in range(SIDE))
same = all(m[y][x] == orient_float(Q, R, p_of(x, y)) for y in range(SIDE) for x in range(SIDE))
check(opposite > 0, "float orient2d(q, r, p): %d opposite signs (> 0)" % opposite)
check(same, "float orient2d(q, r, p) = the same formula in Python doubles, every sign")

m = dlab_map("epsilon")
opposite = sum(m[y][x] * exact[y][x] < 0 for y in range(SIDE) for x in range(SIDE))
check(opposite == 0, "epsilon: never the opposite sign (%d)" % opposite)


def past_filters(generator, dim, n, extra=()):
    """Share of the adaptive kernel's calls answered past static / filter / A."""
    pts, stats = WORK / ("%s%d.txt" % (generator, dim)), WORK / ("%s%d.json" % (generator, dim))
    subprocess.run([DLAB, "gen", generator, "--dim", str(dim), "--n", str(n), "--seed", "1",
                    "-o", str(pts)] + list(extra), check=True)
    subprocess.run([DLAB, "triangulate", str(pts), "--kernel", "adaptive", "--stats", str(stats),
                    "-o", str(WORK / "t.txt")], check=True)
    pred = json.loads(stats.read_text())["predicates"]
    calls = sum(v for k, v in pred.items() if "." not in k)
    past = sum(v for k, v in pred.items()
               if "." in k and k.split(".", 1)[1] not in ("static", "filter", "A"))
    return past, calls


for dim, n in [(2, 3000), (3, 1000)]:
    past, calls = past_filters("uniform", dim, n)
    check(calls > 0 and past == 0,
          "uniform %dD, n = %d: %d of %d adaptive calls past the filters (= 0)" % (dim, n, past, calls))
    past, calls = past_filters("near-degenerate", dim, 300)
    check(past > 0, "near-degenerate %dD: %d of %d adaptive calls past the filters (> 0)"
          % (dim, past, calls))

print("%d failure(s)" % len(failures))
sys.exit(1 if failures else 0)
