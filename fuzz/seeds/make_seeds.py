#!/usr/bin/env python3
"""Writes the seed inputs of the fuzz targets (fuzz/README.md) into this folder.

Triangulation seeds are programs of fuzz/byte_decoder.hpp's format: byte 0 the
insertion order and its seed, then instructions (low nibble opcode, high
nibble argument). Reader seeds: byte 0 selects the format (odd: .node), then
the text. Run from anywhere; the output is the same every time.
"""
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
INPUT, RANDOM, BRIO, HILBERT = range(4)


def op(code, arg=0, *data):
    return bytes([code | (arg << 4)]) + bytes(b & 0xFF for b in data)


def header(order, seed=0):
    return bytes([order | (seed << 2)])


def scale(e):  # instruction 6, two-byte form: e = -1074 + u
    u = e + 1074
    return op(6, 8, u & 0xFF, u >> 8)


def origin_raw(*coords):  # instruction 7, a = 3
    return op(7, 3) + b"".join(struct.pack("<d", c) for c in coords)


def raw_point(*coords):  # instruction 8
    return op(8) + b"".join(struct.pack("<d", c) for c in coords)


def seeds(dim):
    lat = lambda *v: op(0, 0, *v)
    s = {}
    # The 4 x 4 grid: every cell cocircular (instruction 14, nibbles).
    s["grid4"] = header(INPUT) + b"".join(op(14, 0, x | (y << 4), *( [x] if dim == 3 else [])) for x in range(4) for y in range(4))
    # Eight points of the circle / sphere of radius 65 / 9 (instruction 13), its centre, and a repeat.
    s["circle"] = header(BRIO, 5) + op(13, 5, 3, 0) + lat(*[0] * dim) + op(3, 0, 2)
    # Kettner et al. 2008: origin 0.5, step 2^-53, a few grid points and a collinear line.
    s["kettner"] = (header(INPUT) + origin_raw(*[0.5] * dim) + scale(-53) +
                    op(1, 6, *([0] * dim), *([1] * dim)) + lat(*[17, 3, 5][:dim]) + lat(*[24, 24, 24][:dim]))
    # Subnormal cocircular points (e = -1074) and the same moved by ulps.
    s["subnormal"] = header(HILBERT, 1) + scale(-1074) + op(13, 4, 1, 2) + op(4, 0, 0, 1) + op(4, 1, 3, 0xFF)
    # Near the top of the range: e = 1000, a circle of radius 25 / 9, sign flips.
    s["huge"] = header(RANDOM, 7) + scale(1000) + op(13, 3, 2, 5) + op(5, 0, 1) + op(5, 1, 2)
    # Binade-edge values and their power-of-two scalings.
    s["binade"] = header(BRIO) + b"".join(op(9, 0, *[b + 17 * j for j in range(dim)]) for b in range(0, 240, 24)) + op(11, 0, 2, 3)
    # A collinear (coplanar) set plus affine combinations of its points.
    s["collinear"] = (header(INPUT) + op(1, 9, *([1] * dim), *[2, 3, 5][:dim]) + lat(*[7, -4, 1][:dim]) +
                      op(10, 0, 0, 3, *([5] if dim == 3 else []), 6, *([2] if dim == 3 else [])))
    # Raw doubles: an irregular triangle (tetrahedron) and points near it.
    pts = [[0.1, 0.7, 0.3], [1.3, 0.2, 0.9], [0.4, 1.9, 0.1], [1.1, 1.2, 1.7]][: dim + 1]
    s["raw"] = header(BRIO, 3) + b"".join(raw_point(*p[:dim]) for p in pts) + op(4, 0, 1, 3) + op(12, 1, 2)
    return s


def reader_seeds():
    return {
        "plain2d": b"\x00" + b"# comment\n0 0\n1 0\n0.5 0.866\n\n1e-300, 2.5\n",
        "hex3d": b"\x00" + b"0x1.8p-3 0 0\n0x1p+0 0x1p-1074 0\n-0x1.fffffffffffffp+1023 1 2\n0 0 1\n",
        "node2d": b"\x01" + b"# Triangle .node\n4 2 1 0\n1 0 0 7\n2 1 0 7\n3 0 1 7\n4 1 1 7\n",
        "simplices": b"\x02" + b"0 0\n1 0\n0 1\n0 1 2\n",
    }


def write(folder, files):
    os.makedirs(folder, exist_ok=True)
    for name, data in files.items():
        with open(os.path.join(folder, name), "wb") as f:
            f.write(data)


write(os.path.join(HERE, "triangulate_2d"), seeds(2))
write(os.path.join(HERE, "triangulate_3d"), seeds(3))
write(os.path.join(HERE, "point_reader"), reader_seeds())
