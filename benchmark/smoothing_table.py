#!/usr/bin/python3
"""smoothing_table.py -- the bulk quality and the time of each shared case before and after the smoothing stage.

Usage:
    smoothing_table.py QUAD_MESHER DATA_DIR OUT_DIR [CASE ...] [--runs N]

DATA_DIR is the shared data folder (DATA_DIR/*/CASE.poly). Without CASE names every .poly
there is run but the multi-region cgal_butterfly and face and the slow bahamas_islands. Each case
runs N times (default 3) both ways, alternating: `QUAD_MESHER CASE.poly --stop-after buffer2`
(before) and `QUAD_MESHER CASE.poly` (after, through the smoothing), each with -o and --report
into OUT_DIR. Prints a markdown table from the reports: quads, the share of angles in
[60, 120], the largest aspect ratio and its 99th percentile, the shortest edge over the
diagonal, the angle range after, and the shortest wall time of each (whole processes).
"""
import argparse
import glob
import json
import os
import subprocess
import sys
import time

SKIP = {"cgal_butterfly", "face", "bahamas_islands"}


def run(mesher, poly, out, stage):
    msh, rep = out + ".msh", out + ".json"
    cmd = [mesher, poly, "-o", msh, "--report", rep] + (["--stop-after", stage] if stage else [])
    t0 = time.perf_counter()
    p = subprocess.run(cmd, capture_output=True, text=True)
    seconds = time.perf_counter() - t0
    if p.returncode not in (0, 4):
        sys.exit("%s exited %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()))
    with open(rep) as f:
        return json.load(f), seconds


def figures(r):
    ar = r["aspect_ratio"]
    return "%.1f%%, %.1f (%.1f), %.1e" % (100 * r["share_in_60_120"], ar["max"], ar["p99"], r["min_edge_over_diagonal"])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesher")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("cases", nargs="*")
    ap.add_argument("--runs", type=int, default=3)
    a = ap.parse_args()
    polys = {os.path.splitext(os.path.basename(p))[0]: p for p in glob.glob(os.path.join(a.data, "*", "*.poly"))}
    cases = a.cases or sorted(c for c in polys if c not in SKIP)
    os.makedirs(a.out, exist_ok=True)
    print("| case | quads | before: in [60°,120°], max AR (p99), shortest edge / diagonal | after | angles after "
          "| time before | time after |")
    print("| --- | ---: | ---: | ---: | ---: | ---: | ---: |")
    for case in cases:
        poly = polys[case]
        best = {"buffer2": float("inf"), None: float("inf")}
        reports = {}
        for _ in range(a.runs):
            for stage in ("buffer2", None):
                reports[stage], seconds = run(a.mesher, poly, os.path.join(a.out, case + "_" + (stage or "smoothing")), stage)
                best[stage] = min(best[stage], seconds)
        b, s = reports["buffer2"], reports[None]
        print("| %s | %d | %s | %s | [%.1f°, %.1f°] | %.2f s | %.2f s |" % (
            case, s["quads"], figures(b), figures(s), s["min_angle"], s["max_angle"], best["buffer2"], best[None]))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
