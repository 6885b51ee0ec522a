"""Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in
geometric computations", CGTA 40 (2008), section 3: the sign of orient2d(p, q, r) on a
256 x 256 grid of points p = (0.5 + x u, 0.5 + y u), u = 2^-53, q = (12, 12), r = (24, 24).

Usage: sign_maps.py DLAB OUT_DIR. The signs come from `dlab demo --sign-map K`
(predicates/ decides them); this script only reads, counts and colours them:
OUT_DIR/sign_map_<kernel>.png per kernel, sign_maps.png (all of them), sign_maps.md
(the counts). Exact sign for the counts: sign(y - x), since p, q, r are collinear
exactly when y = x and p lies left of qr when y > x.
"""
import pathlib
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.colors import ListedColormap  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

plt.rcParams.update({"font.family": "DejaVu Sans", "font.size": 8, "svg.hashsalt": "dlab"})

SIDE = 256
# (file name, dlab demo options, title)
MAPS = [
    ("float", ["--sign-map", "float"], "float: orient2d(p, q, r)"),
    ("float-kettner", ["--sign-map", "float", "--qrp"], "float: orient2d(q, r, p)\n(Kettner et al.'s formula)"),
    ("epsilon", ["--sign-map", "epsilon"], "epsilon (tol 1e-12)"),
    ("adaptive", ["--sign-map", "adaptive"], "adaptive"),
    ("integer", ["--sign-map", "integer"], "integer"),
    ("mp", ["--sign-map", "mp"], "mp"),
]
# -1, 0, +1: right of qr (below the diagonal), on it, left of it.
COLOURS = ListedColormap(["#f4a582", "#000000", "#4393c3"])
LEGEND = [Patch(color="#4393c3", label="+1 (left of qr)"), Patch(color="#000000", label="0 (on qr)"),
          Patch(color="#f4a582", label="−1 (right of qr)")]


def read_map(dlab, options):
    """The signs as rows y = 0..255 of 256 ints; error on anything else."""
    out = subprocess.run([dlab, "demo"] + options, capture_output=True, text=True, check=True).stdout
    lines = [l for l in out.splitlines() if not l.startswith("#")]
    if len(lines) != SIDE or any(len(l) != SIDE or set(l) - set("+-0") for l in lines):
        raise SystemExit("sign_maps.py: dlab demo %s: expected %d lines of %d signs"
                         % (" ".join(options), SIDE, SIDE))
    return [[{"+": 1, "-": -1, "0": 0}[c] for c in l] for l in lines]


def counts(grid):
    wrong = opposite = false_zero = 0
    for y, row in enumerate(grid):
        for x, s in enumerate(row):
            exact = (y > x) - (y < x)
            wrong += s != exact
            opposite += s * exact < 0
            false_zero += s == 0 and exact != 0
    return wrong, opposite, false_zero


def draw(ax, grid, title, wrong):
    ax.imshow(grid, cmap=COLOURS, vmin=-1, vmax=1, origin="lower", interpolation="nearest",
              extent=(-0.5, SIDE - 0.5, -0.5, SIDE - 0.5))
    ax.set_title("%s\n%d of %d signs wrong" % (title, wrong, SIDE * SIDE))
    ax.set_xlabel("x   (p_x = 0.5 + x·2⁻⁵³)")
    ax.set_ylabel("y   (p_y = 0.5 + y·2⁻⁵³)")
    ax.set_xticks(range(0, SIDE + 1, 64))
    ax.set_yticks(range(0, SIDE + 1, 64))


def main(dlab, out_dir):
    out_dir = pathlib.Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    grids, table = {}, []
    for name, options, title in MAPS:
        grid = read_map(dlab, options)
        grids[name] = grid
        wrong, opposite, false_zero = counts(grid)
        table.append((name, "dlab demo " + " ".join(options), wrong, opposite, false_zero))
        fig, ax = plt.subplots(figsize=(3.6, 4.0))
        draw(ax, grid, title, wrong)
        ax.legend(handles=LEGEND, loc="upper center", bbox_to_anchor=(0.5, -0.2), ncol=3,
                  fontsize=6.5, frameon=False, handlelength=1)
        fig.savefig(out_dir / ("sign_map_%s.png" % name), dpi=150, bbox_inches="tight",
                    metadata={"Software": None})
        plt.close(fig)
    fig, axes = plt.subplots(2, 3, figsize=(10.5, 8.4))
    for ax, (name, _, title), row in zip(axes.flat, MAPS, table):
        draw(ax, grids[name], title, row[2])
    fig.legend(handles=LEGEND, loc="lower center", ncol=3, frameon=False)
    fig.suptitle("orient2d(p, q, r), q = (12, 12), r = (24, 24): sign per kernel "
                 "(Kettner et al. 2008, section 3)")
    fig.tight_layout(rect=(0, 0.04, 1, 0.97), h_pad=2.5)
    fig.savefig(out_dir / "sign_maps.png", dpi=110, metadata={"Software": None})
    plt.close(fig)
    with open(out_dir / "sign_maps.md", "w", encoding="utf-8") as f:
        f.write("| map | command | wrong | opposite sign | false zero |\n|---|---|---:|---:|---:|\n")
        for name, command, wrong, opposite, false_zero in table:
            f.write("| %s | `%s` | %d | %d | %d |\n" % (name, command, wrong, opposite, false_zero))
        f.write("\nOf %d signs; exact sign: sign(y − x).\n" % (SIDE * SIDE))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit("usage: sign_maps.py DLAB OUT_DIR")
    main(sys.argv[1], sys.argv[2])
