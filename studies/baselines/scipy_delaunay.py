#!/usr/bin/python3
"""scipy.spatial.Delaunay on a point file, for dlab's scipy baseline
(studies/baselines_scipy.cpp runs it; studies/README.md).

usage: scipy_delaunay.py POINTS SIMPLICES

POINTS: a first line "D N", then N lines of D coordinates written with 17
significant digits (float() reads each back exactly). SIMPLICES: written
here, one simplex per line, D+1 zero-based input indices as Qhull gives them
(either orientation). Standard output: one line "seconds WALL CPU" -- the
Delaunay() call alone, time.perf_counter() and time.process_time(), printed
with repr so nothing is rounded. A QhullError prints "reported: MESSAGE" (its
first line) and exits 3; bad input exits 2. scipy's defaults are Qhull's
options "Qbb Qc Qz Q12" with "Qt" (scipy.spatial.Delaunay's documentation).
"""
import sys
import time


def main():
    if len(sys.argv) != 3:
        print("usage: scipy_delaunay.py POINTS SIMPLICES", file=sys.stderr)
        return 2
    import numpy as np
    from scipy.spatial import Delaunay, QhullError

    with open(sys.argv[1]) as f:
        d, n = (int(x) for x in f.readline().split())
        values = [float(x) for x in f.read().split()]
    if d not in (2, 3) or len(values) != d * n:
        print(f"{sys.argv[1]}: expected {n} points of dimension {d}", file=sys.stderr)
        return 2
    points = np.array(values, dtype=np.float64).reshape(n, d)

    wall0, cpu0 = time.perf_counter(), time.process_time()
    try:
        tri = Delaunay(points)
    except QhullError as e:
        lines = [line for line in str(e).splitlines() if line.strip()]
        print("reported: " + (lines[0] if lines else "QhullError"))
        return 3
    cpu, wall = time.process_time() - cpu0, time.perf_counter() - wall0

    np.savetxt(sys.argv[2], tri.simplices, fmt="%d")
    print(f"seconds {wall!r} {cpu!r}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
