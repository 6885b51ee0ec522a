# Tests of the Python module `dlab` (python/README.md), run by ctest as
# python.pytest (label python, only with -DDLAB_PYTHON=ON). The independent
# checks: scipy.spatial.Delaunay (Qhull) on points in general position, the
# `dlab` command itself (DLAB_EXE: its simplices, --stats and error messages),
# and the exact validator on Qhull's answers to degenerate input.
import json
import os
import subprocess

import numpy as np
import pytest
import scipy.spatial

import dlab

DLAB_EXE = os.environ.get("DLAB_EXE")


def simplex_set(simplices):
    """The simplices as a sorted list of sorted index tuples (orientation and order ignored)."""
    return sorted(tuple(sorted(int(i) for i in s)) for s in simplices)


def write_points(path, pts):
    # float.hex() is exact and the command reads C99 hexadecimal floats.
    with open(path, "w") as f:
        for p in pts:
            f.write(" ".join(float(x).hex() if np.isfinite(x) else str(x) for x in p) + "\n")


def cli(*args):
    if not DLAB_EXE:
        pytest.skip("DLAB_EXE (the dlab command) not set: run through ctest")
    return subprocess.run([DLAB_EXE, *args], capture_output=True, text=True)


# Every pair dlab has for the dimension: 2D all four algorithms, 3D those available.
PAIRS = [(d, a, k) for d in (2, 3) for a in ("bowyer-watson", "lawson", "tanemura", "george")
         for k in ("adaptive", "mp")]


@pytest.mark.parametrize("dim,algo,kernel", PAIRS)
def test_general_position_equals_scipy(dim, algo, kernel):
    pts = np.random.default_rng(10 * dim + 1).random((200, dim))
    try:
        simplices, stats = dlab.triangulate(pts, algo=algo, kernel=kernel)
    except ValueError as e:
        assert "not available" in str(e)
        pytest.skip(str(e))
    assert simplices.dtype == np.int32 and simplices.shape[1] == dim + 1
    assert stats["outcome"] == "ok" and stats["simplices"] == len(simplices)
    ref = scipy.spatial.Delaunay(pts)
    # The exact validator certifies Qhull's answer and that no facet is cocircular /
    # cospherical: the Delaunay triangulation is unique, so equality is the claim.
    verdict = dlab.check(pts, ref.simplices, orientation="any")
    assert verdict["delaunay"] and verdict["cospherical_facets"] == 0
    assert simplex_set(simplices) == simplex_set(ref.simplices)


@pytest.mark.parametrize("dim", [2, 3])
def test_same_simplices_and_stats_as_the_command(tmp_path, dim):
    pts = dlab.generate("uniform", 300, dim, 7)
    write_points(tmp_path / "p.txt", pts)
    r = cli("triangulate", str(tmp_path / "p.txt"), "-o", str(tmp_path / "s.txt"), "--order", "hilbert",
            "--seed", "3", "--stats", str(tmp_path / "stats.json"))
    assert r.returncode == 0, r.stderr
    simplices, stats = dlab.triangulate(pts, order="hilbert", seed=3)
    expected = np.loadtxt(tmp_path / "s.txt", dtype=np.int64, ndmin=2)
    assert np.array_equal(simplices, expected)
    cli_stats = json.loads((tmp_path / "stats.json").read_text())
    assert list(stats) == list(cli_stats)
    for volatile in ("seconds", "cpu_seconds", "phase_seconds", "peak_rss_bytes"):
        del stats[volatile], cli_stats[volatile]
    assert stats == cli_stats


def test_generate_equals_the_command(tmp_path):
    r = cli("gen", "cospherical", "--n", "30", "--dim", "3", "--seed", "5", "-o", str(tmp_path / "g.txt"))
    assert r.returncode == 0, r.stderr
    expected = np.array([[float.fromhex(t) if t.startswith(("0x", "-0x")) else float(t) for t in line.split()]
                         for line in (tmp_path / "g.txt").read_text().splitlines()
                         if line.strip() and not line.startswith("#")])
    got = dlab.generate("cospherical", 30, 3, 5)
    assert got.shape == (30, 3) and np.array_equal(got, expected)


def test_nan_raises_the_commands_message(tmp_path):
    pts = np.random.default_rng(0).random((10, 2))
    pts[4, 1] = np.nan
    write_points(tmp_path / "nan.txt", pts)
    r = cli("triangulate", str(tmp_path / "nan.txt"))
    assert r.returncode == 2
    # "dlab triangulate: FILE:5: NaN coordinate 'nan'" -> "NaN coordinate 'nan'"
    problem = r.stderr.strip().split(": ", 3)[-1]
    assert problem == "NaN coordinate 'nan'"
    with pytest.raises(ValueError) as e:
        dlab.triangulate(pts)
    assert str(e.value) == "points[4, 1]: " + problem


def test_bad_input_raises_value_error(tmp_path):
    pts = np.random.default_rng(0).random((10, 2))
    with pytest.raises(ValueError, match=r"infinite coordinate '-inf'"):
        dlab.triangulate(np.vstack([pts, [[0.5, -np.inf]]]))
    with pytest.raises(ValueError, match=r"must be an \(n, 2\) or \(n, 3\) array, not of shape \(10, 4\)"):
        dlab.triangulate(np.zeros((10, 4)))
    with pytest.raises(ValueError, match=r"shape \(10,\)"):
        dlab.triangulate(np.zeros(10))
    write_points(tmp_path / "p.txt", pts)
    for option, value in (("--algo", "delaunator"), ("--kernel", "exactish"), ("--order", "zigzag"),
                          ("--policy", "lenient")):
        r = cli("triangulate", str(tmp_path / "p.txt"), option, value)
        assert r.returncode == 2
        message = r.stderr.strip().removeprefix("dlab triangulate: ")
        keyword = {"--algo": "algo", "--kernel": "kernel", "--order": "order", "--policy": "policy"}[option]
        with pytest.raises(ValueError) as e:
            dlab.triangulate(pts, **{keyword: value})
        assert str(e.value) == message


def test_other_errors_are_the_commands():
    z = np.zeros((1, 2))
    for call, args in ((lambda: dlab.predicate("orient2d", "bogus", z, z, z),
                        ("predicate", "orient2d", "bogus", "0", "0", "1", "1", "2", "2")),
                       (lambda: dlab.predicate("orient4d", "mp", z, z, z),
                        ("predicate", "orient4d", "mp", "0", "0", "1", "1", "2", "2")),
                       (lambda: dlab.generate("nosuch", 10), ("gen", "nosuch", "--n", "10")),
                       (lambda: dlab.generate("coplanar", 10, 2), ("gen", "coplanar", "--n", "10", "--dim", "2"))):
        r = cli(*args)
        assert r.returncode == 2
        with pytest.raises(ValueError) as e:
            call()
        assert str(e.value) == r.stderr.strip().split(": ", 1)[1]


def test_check_summary_is_the_commands(tmp_path):
    pts = np.array([[0, 0], [1, 0], [0, 1], [1, 1.0]])
    simplices = [[0, 3, 1], [0, 3, 2]]
    write_points(tmp_path / "p.txt", pts)
    (tmp_path / "s.txt").write_text("".join(" ".join(map(str, s)) + "\n" for s in simplices))
    r = cli("check", str(tmp_path / "p.txt"), str(tmp_path / "s.txt"))
    assert r.returncode == 1
    assert r.stdout.strip().endswith(dlab.check(pts, simplices)["summary"])


def lattice(side, dim):
    axes = np.meshgrid(*[np.arange(side, dtype=float)] * dim, indexing="ij")
    return np.stack([a.ravel() for a in axes], axis=1)


def test_qhull_without_joggle_on_a_3d_lattice():
    # Observed with scipy 1.10 (default options "Qbb Qc Qz Q12", no QJ): on the
    # 6x6x6 lattice Qhull's triangulated output (Qt) keeps flat tetrahedra of
    # cospherical cube corners, which the exact validator refuses.
    pts = lattice(6, 3)
    qhull = dlab.check(pts, scipy.spatial.Delaunay(pts).simplices, orientation="any")
    assert not qhull["valid"]
    assert "orientation" in [p["check"] for p in qhull["problems"]]
    for algo in ("bowyer-watson", "lawson", "tanemura"):  # George's floating sphere test is not exact
        simplices, stats = dlab.triangulate(pts, algo=algo, validate=True)
        assert stats["outcome"] == "ok" and stats["validated"]
        assert dlab.check(pts, simplices)["delaunay"]
        assert len(simplices) in range(5 * 125, 6 * 125 + 1)  # 5 or 6 tetrahedra per cube


def test_qhull_without_joggle_on_kettners_grid():
    # Kettner et al. (CGTA 2008): p = (0.5 + x 2^-53, 0.5 + y 2^-53), then (12,12), (24,24).
    side = 32
    grid = 0.5 + lattice(side, 2)[:, ::-1] * 2.0**-53
    pts = np.vstack([grid, [[12, 12], [24, 24]]])
    # Observed: Qhull stops with QH6154 "Initial simplex is flat".
    with pytest.raises(scipy.spatial.QhullError, match="QH6154"):
        scipy.spatial.Delaunay(pts)
    for algo in ("bowyer-watson", "lawson"):
        simplices, stats = dlab.triangulate(pts, algo=algo, validate=True)
        assert stats["outcome"] == "ok" and dlab.check(pts, simplices)["delaunay"]


def test_cocircular_points_stay_valid_delaunay():
    pts = dlab.generate("cocircular", 60, 2, 1)
    r = np.hypot(pts[:, 0], pts[:, 1])
    assert np.all(r == r[0])  # exactly on one circle (integer coordinates times a power of two)
    for algo in ("bowyer-watson", "lawson", "tanemura", "george"):
        simplices, stats = dlab.triangulate(pts, algo=algo)
        verdict = dlab.check(pts, simplices)
        assert verdict["delaunay"] and len(simplices) == 58
        assert verdict["cospherical_facets"] == 57  # every interior edge


def test_check_reports_problems():
    pts = np.array([[0, 0], [1, 0], [0, 1], [1, 1.0]])
    good = dlab.check(pts, [[0, 1, 3], [0, 3, 2]])
    assert good["valid"] and good["delaunay"] and good["problems"] == []
    flipped = dlab.check(pts, [[0, 3, 1], [0, 3, 2]])
    assert not flipped["valid"] and flipped["problems"][0]["check"] == "orientation"
    assert dlab.check(pts, [[0, 3, 1], [0, 3, 2]], orientation="any")["reoriented"] == 1
    thin = np.array([[0, 0], [4, 0], [2, 1], [2, -0.1]])
    nd = dlab.check(thin, [[0, 1, 2], [0, 3, 1]])  # edge 0-1 is not locally Delaunay
    assert nd["valid"] and not nd["delaunay"]
    assert [p["check"] for p in nd["problems"]] == ["not_delaunay"]
    with pytest.raises(ValueError, match="out of range"):
        dlab.check(pts, [[0, 1, -1]])


@pytest.mark.parametrize("name,dim,count", [("orient2d", 2, 3), ("incircle", 2, 4),
                                              ("orient3d", 3, 4), ("insphere", 3, 5)])
@pytest.mark.parametrize("kernel", ["adaptive", "integer", "mp", "float", "epsilon"])
def test_predicate_vectorised_equals_per_call(name, dim, count, kernel):
    rng = np.random.default_rng(count)
    # Half the rows exactly degenerate: small integers, the last point copied from the first.
    arrays = [rng.integers(-3, 4, size=(40, dim)).astype(float) for _ in range(count)]
    arrays[-1][:20] = arrays[0][:20]
    for a in arrays:
        a[20:] = rng.random((20, dim))
    signs = dlab.predicate(name, kernel, *arrays)
    assert signs.dtype == np.int8 and signs.shape == (40,)
    assert np.all(signs[:20] == 0) or kernel in ("float", "epsilon")
    for row in range(40):
        one = dlab.predicate(name, kernel, *[a[row:row + 1] for a in arrays])
        assert signs[row] == one[0]
    # and per call of the command, for a few rows
    for row in (0, 21, 39):
        coords = [float(x).hex() for a in arrays for x in a[row]]
        r = cli("predicate", name, kernel, *coords)
        assert r.returncode == 0, r.stderr
        assert int(r.stdout) == signs[row]


def test_predicate_signs_by_hand():
    a = np.array([[0.0, 0.0]] * 3)
    b = np.array([[1.0, 0.0]] * 3)
    c = np.array([[0.0, 1.0], [0.0, -1.0], [2.0, 0.0]])
    assert dlab.predicate("orient2d", "adaptive", a, b, c).tolist() == [1, -1, 0]
    with pytest.raises(ValueError, match="unknown predicate"):
        dlab.predicate("orient4d", "adaptive", a, b, c)
    with pytest.raises(ValueError, match="same number of rows"):
        dlab.predicate("orient2d", "adaptive", a, b, c[:2])


def longest_stall_beside(call):
    """Seconds of the longest pause of a Python loop in this thread while call() runs in another."""
    import threading
    import time
    worker = threading.Thread(target=call)
    ticks = [time.perf_counter()]
    worker.start()
    while worker.is_alive():
        ticks.append(time.perf_counter())
    worker.join()
    ticks.append(time.perf_counter())
    return max(np.diff(ticks))


def test_the_gil_is_released_while_triangulating():
    import time
    pts = dlab.generate("uniform", 200000, 2, 3)
    start = time.perf_counter()
    dlab.triangulate(pts)
    alone = time.perf_counter() - start
    assert alone > 0.05
    # Holding the GIL the call would stall the loop for the whole run, every time;
    # released, the loop waits only for the worker's short Python parts (switch
    # interval 5 ms) and for the scheduler: on a loaded machine one of three tries
    # has to show it.
    stalls = []
    for _ in range(3):
        stalls.append(longest_stall_beside(lambda: dlab.triangulate(pts)))
        if stalls[-1] < alone / 2:
            break
    assert min(stalls) < alone / 2, (alone, stalls)


@pytest.mark.parametrize("dim", [2, 3])
def test_threads_give_the_serial_canonical_simplices_and_the_commands(tmp_path, dim):
    # A lattice: degenerate everywhere, so only the perturbation makes the answer unique.
    pts = dlab.generate("lattice", 3000, dim, 5)
    serial, _ = dlab.triangulate(pts, canonical=True)
    for t in (1, 2, 4):
        simplices, stats = dlab.triangulate(pts, threads=t)
        assert np.array_equal(simplices, serial) and stats["counters"]["threads"] == t
    write_points(tmp_path / "p.txt", pts)
    r = cli("triangulate", str(tmp_path / "p.txt"), "--threads", "2", "-o", str(tmp_path / "s.txt"))
    assert r.returncode == 0, r.stderr
    assert np.array_equal(np.loadtxt(tmp_path / "s.txt", dtype=np.int64, ndmin=2), serial)
    r = cli("triangulate", str(tmp_path / "p.txt"), "--threads", "2", "--algo", "lawson")
    with pytest.raises(ValueError) as e:
        dlab.triangulate(pts, threads=2, algo="lawson")
    assert r.returncode == 2 and str(e.value) == r.stderr.strip().split(": ", 1)[1]


def test_canonical_order_by_an_independent_sort():
    # Each simplex rotated by an even permutation to start at its smallest index, the
    # rows sorted: written here in Python, not with the sort under test.
    def canonical(row):
        s = [int(v) for v in row]
        order = sorted(range(len(s)), key=lambda i: s[i])
        inversions = sum(1 for a in range(len(order)) for b in range(a + 1, len(order)) if order[a] > order[b])
        c = [s[i] for i in order]
        if inversions % 2:
            c[-1], c[-2] = c[-2], c[-1]
        return tuple(c)
    for dim in (2, 3):
        pts = dlab.generate("uniform", 2000, dim, 11)
        plain, _ = dlab.triangulate(pts)
        canon, _ = dlab.triangulate(pts, canonical=True)
        assert [tuple(int(v) for v in r) for r in canon] == sorted(canonical(r) for r in plain)
