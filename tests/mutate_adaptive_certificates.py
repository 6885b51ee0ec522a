#!/usr/bin/env python3
"""Mutation checks of the adaptive kernel's certificates (issue 17, section 1).

Each mutation loosens one certificate by one binade (a filter or stage constant
halved, a floor halved, an overflow factor halved, a guard threshold doubled) or
drops one sign case of a two-sided test. For each, this script copies the kernel
and its tests to a scratch directory (the shared tree is never edited), applies the
exact textual edit listed below, builds a small test executable (the adaptive
kernel, mp and tests/test_certificate_edges_adaptive.cpp; with --all also
tests/test_adaptive_kernel.cpp and tests/test_gappa_constants.cpp), runs its "[edges]"
tests ("[adaptive]" and "[gappa]" with --all) and prints the test cases that fail. A mutation that no test catches is printed as
"NOT CAUGHT".

Usage: tests/mutate_adaptive_certificates.py [--only NAME ...] [--all] [--opt -O1]
(from the repository root; needs g++, Catch2, RapidCheck, GMP, Boost).
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

HPP = "predicates/adaptive_kernel.hpp"
CPP = "predicates/adaptive_kernel.cpp"

# (name, [(file, old text, new text), ...]); each old text must occur exactly once.
MUTATIONS = [
    # --- orient3d per-call filter (error_bounds.md 3.4) ---
    ("o3 filter: bound / 2 (SSE2 path)", [(HPP,
        "return o3_ss8 * ((_mm_cvtsd_f64(mxy) * high_lane(mxy)) * _mm_cvtsd_f64(mz8));",
        "return o3_ss8 / 2 * ((_mm_cvtsd_f64(mxy) * high_lane(mxy)) * _mm_cvtsd_f64(mz8));")]),
    ("o3 filter: bound / 2 (scalar twin)", [(HPP,
        "return o3_ss8 * ((mx * my) * (mz * 8));", "return o3_ss8 / 2 * ((mx * my) * (mz * 8));")]),
    ("o3 filter: constant o3_ss / 2", [(HPP,
        "inline constexpr double o3_ss = filter_constant(o3_half(), o3_half(), 3);",
        "inline constexpr double o3_ss = filter_constant(o3_half(), o3_half(), 3) / 2;")]),
    ("o3 filter: floor o3_ss_lo / 2", [(HPP, "o3_ss_lo = 0x1p-320;", "o3_ss_lo = 0x1p-321;")]),
    ("o3 filter: overflow factor 8 -> 4 (same bound)", [
        (HPP, "o3_ss8 = o3_ss / 8,", "o3_ss8 = o3_ss / 4,"),
        (HPP, "_mm_set1_pd(8.0));", "_mm_set1_pd(4.0));"),
        (HPP, "return o3_ss8 * ((mx * my) * (mz * 8));", "return o3_ss8 * ((mx * my) * (mz * 4));"),
        (HPP, "return o3_ss8 * ((m * m) * (m * 8));", "return o3_ss8 * ((m * m) * (m * 4));")]),
    ("o3 filter: overflow factor 8 -> 2 (same bound)", [
        (HPP, "o3_ss8 = o3_ss / 8,", "o3_ss8 = o3_ss / 2,"),
        (HPP, "_mm_set1_pd(8.0));", "_mm_set1_pd(2.0));"),
        (HPP, "return o3_ss8 * ((mx * my) * (mz * 8));", "return o3_ss8 * ((mx * my) * (mz * 2));"),
        (HPP, "return o3_ss8 * ((m * m) * (m * 8));", "return o3_ss8 * ((m * m) * (m * 2));")]),
    ("o3 filter: negative case without its bound", [(HPP,
        "if (-f.det > bound) return {Sign::negative, adaptive::stage_filter};",
        "if (f.det < bound) return {Sign::negative, adaptive::stage_filter};")]),
    # --- static orient3d filter (3.5) ---
    ("static: W = 2 G instead of 4 G", [(HPP,
        "orient3d_static_bound(4 * width);", "orient3d_static_bound(2 * width);")]),
    ("static: fitted bound / 2", [(HPP,
        "return o3_ss8 * ((m * m) * (m * 8));", "return o3_ss8 / 2 * ((m * m) * (m * 8));")]),
    ("static: floor / 2", [(HPP,
        "const double m = std::max(w, o3_ss_lo);", "const double m = std::max(w, o3_ss_lo / 2);")]),
    ("static: negative case without its bound", [(HPP,
        "if (-f.det > o3_static_) return {Sign::negative, adaptive::stage_static};",
        "if (f.det < o3_static_) return {Sign::negative, adaptive::stage_static};")]),
    # --- incircle lift filter (3.3) ---
    ("ic lift filter: bound / 2 (SSE2 path)", [(HPP,
        "return {det, ic_lift_filter * (lifts * lifts)};\n}\n#endif",
        "return {det, ic_lift_filter / 2 * (lifts * lifts)};\n}\n#endif")]),
    ("ic lift filter: bound / 2 (scalar twin)", [(HPP,
        "return {det, ic_lift_filter * (lifts * lifts)};\n}\n#if defined(__SSE2__)",
        "return {det, ic_lift_filter / 2 * (lifts * lifts)};\n}\n#if defined(__SSE2__)")]),
    ("ic lift filter: constant / 2", [(HPP,
        "icA * pow_int(1 + eps, 7) / (3 * pow_int(1 - eps, 10)) * (1 + 0x1p-40);",
        "icA * pow_int(1 + eps, 7) / (3 * pow_int(1 - eps, 10)) * (1 + 0x1p-40) / 2;")]),
    ("ic lift filter: floor / 2", [(HPP, "ic_lift_lo = 0x1p-480;", "ic_lift_lo = 0x1p-481;")]),
    ("ic lift filter: c S' first (overflow order)", [(HPP,
        "return {det, ic_lift_filter * (lifts * lifts)};\n}\n#endif",
        "return {det, ic_lift_filter * lifts * lifts};\n}\n#endif")]),
    ("ic lift filter: negative case without its bound", [(HPP,
        "if (-det > bound) return {Sign::negative, adaptive::stage_filter};\n    return rest(a, b, c, d);",
        "if (det < bound) return {Sign::negative, adaptive::stage_filter};\n    return rest(a, b, c, d);")]),
    # --- insphere lift filter (3.1-3.2) ---
    ("is lift filter: bound / 2 (SSE2 path)", [(HPP,
        "return {det, is_lift128 * (((L * 128) * L) * mz)};\n}\n#endif",
        "return {det, is_lift128 / 2 * (((L * 128) * L) * mz)};\n}\n#endif")]),
    ("is lift filter: bound / 2 (scalar twin)", [(HPP,
        "return {det, is_lift128 * (((L * 128) * L) * mz)};\n}\n#if defined(__SSE2__)",
        "return {det, is_lift128 / 2 * (((L * 128) * L) * mz)};\n}\n#if defined(__SSE2__)")]),
    ("is lift filter: is_lift_filter / 2 (constant too small)", [(HPP,
        "is_lift_filter = is_filter * (1 + 0x1p-50);", "is_lift_filter = is_filter * (1 + 0x1p-50) / 2;")]),
    ("is lift filter: is_filter / 2", [(HPP,
        "add(mul(lift3(), minor3()), mul(lift3(), minor3())), 5);",
        "add(mul(lift3(), minor3()), mul(lift3(), minor3())), 5) / 2;")]),
    ("is lift filter: floor is_lo / 2", [(HPP, "is_lo = 0x1p-185,", "is_lo = 0x1p-186,")]),
    ("is lift filter: no factor 128, order (L*L)*mz kept", [(HPP,
        "return {det, is_lift128 * (((L * 128) * L) * mz)};\n}\n#endif",
        "return {det, is_lift_filter * ((L * L) * mz)};\n}\n#endif")]),
    ("is lift filter: factor 128 -> 64 (same bound)", [
        (HPP, "is_lift128 = is_lift_filter / 128;", "is_lift128 = is_lift_filter / 64;"),
        (HPP, "return {det, is_lift128 * (((L * 128) * L) * mz)};\n}\n#endif", "return {det, is_lift128 * (((L * 64) * L) * mz)};\n}\n#endif"),
        (HPP, "return {det, is_lift128 * (((L * 128) * L) * mz)};\n}\n#if defined(__SSE2__)", "return {det, is_lift128 * (((L * 64) * L) * mz)};\n}\n#if defined(__SSE2__)")]),
    ("is lift filter: negative case without its bound", [(HPP,
        "if (-det > bound) return {Sign::negative, adaptive::stage_filter};\n    return rest(a, b, c, d, e);",
        "if (det < bound) return {Sign::negative, adaptive::stage_filter};\n    return rest(a, b, c, d, e);")]),
    # --- orient2d inline stage A (4.6) ---
    ("o2 inline A: bound / 2", [(HPP,
        "const double bound = adaptive::o2_fast * std::fabs(dl + dr) + adaptive::o2_fast_abs;",
        "const double bound = adaptive::o2_fast / 2 * std::fabs(dl + dr) + adaptive::o2_fast_abs;")]),
    ("o2 inline A: additive 2^-1072 / 2", [(HPP, "o2_fast_abs = 0x1p-1072;", "o2_fast_abs = 0x1p-1073;")]),
    ("o2 inline A: negative case without its bound", [(HPP,
        "if (-det > bound) return {Sign::negative, adaptive::stage_a};",
        "if (det < bound) return {Sign::negative, adaptive::stage_a};")]),
    # --- stages A, B, C (section 4), at their use ---
    ("o2 stage A / 2", [(CPP, "double bound = o2A * detsum;", "double bound = o2A / 2 * detsum;")]),
    ("o2 stage B / 2", [(CPP, "bound = o2B * detsum;", "bound = o2B / 2 * detsum;")]),
    ("o2 stage C / 2", [(CPP, "bound = o2C * detsum + result_err", "bound = o2C / 2 * detsum + result_err")]),
    ("o3 stage A / 2", [(CPP, "double bound = o3A * perm;", "double bound = o3A / 2 * perm;")]),
    ("o3 stage A: negative case without its bound", [(CPP,
        "double bound = o3A * perm;\n  if (det > bound || -det > bound)",
        "double bound = o3A * perm;\n  if (det > bound || det < bound)")]),
    ("o3 stage B / 2", [(CPP, "bound = o3B * perm;", "bound = o3B / 2 * perm;")]),
    ("o3 stage C / 2", [(CPP, "bound = o3C * perm + result_err", "bound = o3C / 2 * perm + result_err")]),
    ("ic stage A / 2", [(CPP, "double bound = icA * perm;", "double bound = icA / 2 * perm;")]),
    ("ic stage B / 2", [(CPP, "bound = icB * perm;", "bound = icB / 2 * perm;")]),
    ("ic stage C / 2", [(CPP, "bound = icC * perm + result_err", "bound = icC / 2 * perm + result_err")]),
    ("is stage A / 2", [(CPP, "const double bound = isA * perm;", "const double bound = isA / 2 * perm;")]),
    ("is stage B / 2", [(CPP, "double bound = isB * perm;", "double bound = isB / 2 * perm;")]),
    ("is stage C / 2", [(CPP, "bound = isC * perm + result_err", "bound = isC / 2 * perm + result_err")]),
    ("stage C: result_err / 2", [(HPP,
        "result_err = (3.0 + 8.0 * eps) * eps;", "result_err = (3.0 + 8.0 * eps) * eps / 2;")]),
    # --- exponent guards (section 2) ---
    ("guard: grid -900 -> -910", [(CPP, "constexpr long grid_floor = -900;", "constexpr long grid_floor = -910;")]),
    ("guard: o2_hi x 2", [(HPP, "o2_hi = 0x1p+490", "o2_hi = 0x1p+491")]),
    ("guard: o3_hi x 2", [(HPP, "o3_hi = 0x1p+325", "o3_hi = 0x1p+326")]),
    ("guard: ic_hi x 2", [(HPP, "ic_hi = 0x1p+245", "ic_hi = 0x1p+246")]),
    ("guard: is_hi x 2", [(HPP, "is_hi = 0x1p+195", "is_hi = 0x1p+196")]),
    ("guard: stage D raw coordinates x 2", [(CPP,
        "if (!(std::fabs(x) <= is_hi)) return", "if (!(std::fabs(x) <= 2 * is_hi)) return")]),
]

EDGE_TESTS = ["tests/test_certificate_edges_adaptive.cpp"]
ALL_TESTS = EDGE_TESTS + ["tests/test_adaptive_kernel.cpp", "tests/test_gappa_constants.cpp"]
# Heavy headers, precompiled once.
PCH = """#include <boost/multiprecision/gmp.hpp>
#include <catch2/catch.hpp>
#include <rapidcheck/catch.h>
"""


def run(cmd, cwd):
    return subprocess.run(cmd, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", nargs="*", default=None, help="substrings of mutation names")
    ap.add_argument("--opt", default="-O0")  # IEEE results do not depend on it (SSE2, no contraction)
    ap.add_argument("--keep", action="store_true")
    ap.add_argument("--all", action="store_true",
                    help="also build and run tests/test_adaptive_kernel.cpp and test_gappa_constants.cpp")
    args = ap.parse_args()
    repo = os.getcwd()
    work = tempfile.mkdtemp(prefix="dlab-mutate-")
    for d in ["predicates", "tests"]:
        shutil.copytree(os.path.join(repo, d), os.path.join(work, d))
    tests = [t for t in (ALL_TESTS if args.all else EDGE_TESTS) if os.path.exists(os.path.join(work, t))]
    flags = [args.opt, "-DNDEBUG", "-std=c++20", "-ffp-contract=off", "-fno-fast-math", "-I", work]
    build = os.path.join(work, "build")
    os.makedirs(build)
    open(os.path.join(build, "pch.hpp"), "w").write(PCH)
    r = run(["g++"] + flags + ["-x", "c++-header", "pch.hpp", "-o", "pch.hpp.gch"], build)
    if r.returncode:
        sys.exit(r.stdout)
    for src, obj in [("tests/main.cpp", "main.o"), ("predicates/mp_kernel.cpp", "mp.o")]:
        r = run(["g++", "-O0" if "main" in src else args.opt, "-std=c++20", "-I", work, "-c",
                 os.path.join(work, src), "-o", obj], build)
        if r.returncode:
            sys.exit(r.stdout)
    pristine = {f: open(os.path.join(work, f)).read() for f in [HPP, CPP]}
    env = dict(os.environ, RC_PARAMS="seed=20261122")
    selected = [m for m in MUTATIONS if args.only is None or any(s in m[0] for s in args.only)]
    caught_all = True
    for name, edits in [("(none: the unmutated kernel)", [])] + selected:
        text = dict(pristine)
        for f, old, new in edits:
            if text[f].count(old) != 1:
                sys.exit(f"{name}: '{old}' occurs {text[f].count(old)} times in {f}")
            text[f] = text[f].replace(old, new)
        for f, t in text.items():
            open(os.path.join(work, f), "w").write(t)
        objs = []
        procs = []
        for src in [CPP] + tests:
            # A test object depends on the header only; the kernel's on both files.
            tag = hash(text[HPP]) if src != CPP else hash(text[HPP] + text[CPP])
            obj = f"{os.path.basename(src)}.{tag & 0xffffffffffff:x}.o"
            objs.append(obj)
            if os.path.exists(os.path.join(build, obj)):
                continue
            pch = ["-include", "pch.hpp"] if src.startswith("tests/") else []
            procs.append(subprocess.Popen(["g++"] + flags + pch + ["-c", os.path.join(work, src), "-o", obj],
                                          cwd=build, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True))
            if len(procs) == 2:
                for p in procs:
                    out, _ = p.communicate()
                    if p.returncode:
                        print(f"{name}: BUILD FAILED\n{out[-3000:]}")
                procs = []
        for p in procs:
            out, _ = p.communicate()
            if p.returncode:
                print(f"{name}: BUILD FAILED\n{out[-3000:]}")
        r = run(["g++", "-o", "t", "main.o", "mp.o"] + objs + ["-lrapidcheck", "-lgmp"], build)
        if r.returncode:
            print(f"{name}: LINK FAILED\n{r.stdout[-3000:]}")
            continue
        r = subprocess.run(["./t", "[adaptive],[gappa]" if args.all else "[edges]", "-r", "junit"], cwd=build, env=env,
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        failed = []
        try:
            root = ET.fromstring(r.stdout[r.stdout.index("<?xml"):])
            for tc in root.iter("testcase"):
                if tc.find("failure") is not None or tc.find("error") is not None:
                    failed.append(tc.get("name"))
        except (ValueError, ET.ParseError):
            failed.append(f"(exit {r.returncode}, no report)")
        failed = sorted(set(failed))
        if not edits:
            print(f"{name}: {'FAILS: ' + '; '.join(failed) if failed else 'all pass'}", flush=True)
            continue
        if not failed:
            caught_all = False
        print(f"{name}: {'caught by: ' + '; '.join(failed) if failed else 'NOT CAUGHT'}", flush=True)
    if not args.keep:
        shutil.rmtree(work)
    sys.exit(0 if caught_all else 1)


if __name__ == "__main__":
    main()
