#!/usr/bin/python3
"""compare_with_gmsh.py -- quad-mesher side by side with Gmsh's all-quad meshers on the shared cases.

Usage:
    compare_with_gmsh.py QUAD_MESHER DATA_DIR OUT_DIR [CASE ...] [--timeout S] [--gmsh-size-factor F]
                         [--with-bahamas] [--gmsh-from PREVIOUS/comparison.json]

DATA_DIR is the shared data folder (DATA_DIR/CASE/CASE.poly); the tools are taken from
DATA_DIR/../bench.  Without CASE names every .poly there is run except the multi-region
cgal_butterfly and face, and except bahamas_islands (minutes per run) unless --with-bahamas.
For each case, one process at a time:
  * QUAD_MESHER CASE.poly -o OUT_DIR/CASE/ours.msh --report OUT_DIR/CASE/ours.json, timed;
  * peer_gmsh.py CASE.poly --out OUT_DIR/CASE/gmsh --variants GMSH_VARIANTS --no-verify
    --timeout S --size-factor F (Gmsh's sizes: F times the shortest incident segment at each
    input point; F = --gmsh-size-factor, default 1);
  * verify_mesh.py MESH --domain CASE.poly --no-overlap --json on every mesh, ours and Gmsh's.
Writes OUT_DIR/comparison.json (every figure of every mesh) and OUT_DIR/comparison.md (one row
per case: ours / Gmsh's best variant; H is the boundary's Hausdorff distance over the
domain's diagonal).  Gmsh's best variant is the all-quad mesh with, in turn:
every check but angles_45_135 passed ("valid"), the smallest worst angle (largest distance
of an angle from 90 deg, to 0.01 deg), the fewest angles outside [45, 135] that no input
corner forces ("unforced": not at an input corner below 45 or above 270 deg).  With --gmsh-from,
Gmsh's runs of the cases found in an earlier comparison.json are taken from it (not rerun,
not re-verified): only ours runs again, in a minute or two instead of about 25.  Times are wall
clock of whole processes: our CLI (read, mesh, write) and Gmsh's worker (Python start,
geometry, meshing, writing).  Needs Debian's python3-gmsh, numpy, scipy, shapely and meshio.
"""
import argparse
import datetime
import glob
import json
import os
import platform
import subprocess
import sys
import time

# peer_gmsh.py's variants that make quads only: full-quad recombination or subdivision
# (plain Blossom leaves triangles; the quasi-structured one needs Gmsh >= 4.9).
GMSH_VARIANTS = ["a-fdq-simplefull", "a-fdq-blossomfull", "c-fdq-blossom-subdiv", "c-del-blossom-subdiv"]
MULTI_REGION = {"cgal_butterfly", "face"}   # our tool meshes one region
SLOW = "bahamas_islands"


def verify(bench, msh, poly):
    """verify_mesh.py's figures of one mesh, or {"error": ...}."""
    p = subprocess.run([sys.executable, os.path.join(bench, "verify_mesh.py"), msh, "--domain", poly,
                        "--no-overlap", "--json"], capture_output=True, text=True)
    try:
        V = json.loads(p.stdout)
    except ValueError:
        return {"error": "verify_mesh.py gave no JSON: " + p.stderr.strip()[-300:]}
    if "error" in V:
        return {"error": V["error"]}
    failed = [c for c in V["failed_checks"] if c != "angles_45_135"]
    return {"quads": V["n_quads"], "other_cells": V["n_other_cells"],
            "vertices": V["n_points"] - V["n_points_unused"],
            "angle_min": V["angle_min"], "angle_max": V["angle_max"],
            "share_45_135": V["frac_angles_45_135"], "share_60_120": V["frac_angles_60_120"],
            "aspect_ratio_max": V["aspect_ratio_max"], "out": V["n_angles_outside_45_135"],
            "out_unforced": V["n_angles_outside_45_135_unexcused"], "hausdorff_rel": V["hausdorff_rel"],
            "failed_checks": failed, "valid": not failed}


def run_ours(mesher, bench, poly, cdir, timeout):
    msh, rep = os.path.join(cdir, "ours.msh"), os.path.join(cdir, "ours.json")
    for f in (msh, rep):
        if os.path.exists(f):
            os.remove(f)
    t0 = time.perf_counter()
    try:
        p = subprocess.run([mesher, poly, "-o", msh, "--report", rep], capture_output=True, text=True,
                           timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"status": "timeout after %g s" % timeout}
    R = {"seconds": time.perf_counter() - t0, "exit": p.returncode, "stderr": p.stderr.strip()[-600:]}
    if not os.path.exists(msh):
        return dict(R, status="failed (exit %d)" % p.returncode)
    R.update(status="ok", **verify(bench, msh, poly))
    if os.path.exists(rep):
        report = json.load(open(rep))
        R.update(quadtree_depth=report["quadtree_depth"], rounds=report["buffer"]["refinement_rounds"],
                 stage_seconds=report["seconds"])
    return R


def run_gmsh(bench, poly, cdir, timeout, size_factor):
    out = os.path.join(cdir, "gmsh")
    subprocess.run([sys.executable, os.path.join(bench, "peer_gmsh.py"), poly, "--out", out, "--no-verify",
                    "--variants", ",".join(GMSH_VARIANTS), "--timeout", str(timeout),
                    "--size-factor", str(size_factor)],
                   capture_output=True, text=True)
    runs = {}
    for line in open(os.path.join(out, "results.jsonl")):
        r = json.loads(line)
        R = {"status": r["status"], "seconds": r.get("t_process_s"), "mesh_seconds": r.get("t_mesh_s"),
             "gmsh_version": r.get("gmsh_version"), "workaround": (r.get("workaround") or {}).get("set"),
             "error": r.get("error", "")[-300:]}
        if r["status"] == "ok":
            R.update(verify(bench, r["msh"], poly))
        runs[r["variant"]] = R
    return runs


def best_gmsh(runs):
    ok = [(v, R) for v, R in runs.items() if R["status"] == "ok" and R.get("other_cells") == 0]
    if not ok:
        return None
    worst = lambda R: round(max(90 - R["angle_min"], R["angle_max"] - 90), 2)
    return min(ok, key=lambda vR: (not vR[1]["valid"], worst(vR[1]), vR[1]["out_unforced"]))[0]


def cell(R, what):
    """One figure of one mesh as the table shows it."""
    if R is None or R.get(what) is None:
        return "—"
    v = R[what]
    if what in ("share_45_135", "share_60_120"):
        return "%.2f%%" % (100 * v)
    if what == "out":
        return "%d (%d)" % (v, R["out_unforced"])
    if what == "valid":
        return "yes" if v else "no: " + ", ".join(R["failed_checks"])
    return {"angle_min": "%.1f°", "angle_max": "%.1f°", "hausdorff_rel": "%.1e", "seconds": "%.1f s",
            "aspect_ratio_max": "%.1f"}.get(
        what, "%s") % v


def markdown(rows, meta):
    head = ["case", "quads", "quads ours/Gmsh", "vertices", "min angle", "max angle", "in [45°,135°]", "in [60°,120°]",
            "max aspect ratio", "out (unforced)", "H", "valid", "wall time", "our depth", "Gmsh variant"]
    L = ["%s; %s; Gmsh %s, variants %s, sizes %g x the shortest incident segment, timeout %g s per run%s. "
         "Each cell: ours / Gmsh's best." % (meta["date"], meta["machine"], meta["gmsh_version"],
                                              ", ".join(GMSH_VARIANTS), meta["gmsh_size_factor"], meta["timeout"],
                                              "; Gmsh's runs from " + meta["gmsh_from"] if "gmsh_from" in meta else ""),
         "",
        "| " + " | ".join(head) + " |", "| --- |" + " ---: |" * 10 + " --- | ---: | ---: | --- |"]
    for r in rows:
        o, g = r["ours"], r["gmsh"].get(r["gmsh_best"]) if r["gmsh_best"] else None
        if r["gmsh_best"]:
            variant = r["gmsh_best"] + (" (workaround)" if g["workaround"] else "")
        else:
            variant = "none: " + ", ".join("%s %s" % (v, R["status"] if R["status"] != "ok" else "not all-quad")
                                           for v, R in r["gmsh"].items())
        if o["status"] != "ok":
            variant += "; ours: " + o["status"]
        ratio = "%.2f" % (o["quads"] / g["quads"]) if g and o.get("quads") and g.get("quads") else "—"
        figures = ["%s / %s" % (cell(o, w), cell(g, w)) for w in
                   ("quads", "vertices", "angle_min", "angle_max", "share_45_135", "share_60_120", "aspect_ratio_max",
                    "out", "hausdorff_rel", "valid", "seconds")]
        L.append("| " + " | ".join([r["case"], figures[0], ratio] + figures[1:]
                                   + [str(o.get("quadtree_depth", "—")), variant]) + " |")
    return "\n".join(L) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesher", help="the quad-mesher binary")
    ap.add_argument("data", help="shared data folder (holds CASE/CASE.poly; the tools are in ../bench)")
    ap.add_argument("out", help="output folder")
    ap.add_argument("cases", nargs="*", help="case names (default: every single-region case)")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per mesher run (ours and each Gmsh's)")
    ap.add_argument("--gmsh-size-factor", type=float, default=1.0,
                    help="peer_gmsh.py --size-factor: Gmsh's sizes times this (default 1)")
    ap.add_argument("--with-bahamas", action="store_true", help="also run %s" % SLOW)
    ap.add_argument("--gmsh-from", metavar="JSON", help="an earlier comparison.json: reuse its Gmsh runs")
    a = ap.parse_args()
    earlier = {}
    if a.gmsh_from:
        prev = json.load(open(a.gmsh_from))
        for key in ("timeout", "gmsh_size_factor"):
            if prev["meta"][key] != getattr(a, key):
                ap.error("%s has %s %s, this run %s" % (a.gmsh_from, key, prev["meta"][key], getattr(a, key)))
        earlier = {r["case"]: r["gmsh"] for r in prev["cases"]}
    data, bench = os.path.abspath(a.data), os.path.abspath(os.path.join(a.data, "..", "bench"))
    polys = {os.path.basename(p)[:-5]: p for p in glob.glob(os.path.join(data, "*", "*.poly"))}
    cases = a.cases or sorted(c for c in polys if c not in MULTI_REGION and (c != SLOW or a.with_bahamas))
    unknown = [c for c in cases if c not in polys]
    if unknown:
        ap.error("no %s in %s" % (", ".join(unknown), data))
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for case in cases:
        cdir = os.path.join(a.out, case)
        os.makedirs(cdir, exist_ok=True)
        print(case, "...", file=sys.stderr, flush=True)
        r = {"case": case, "poly": polys[case], "ours": run_ours(os.path.abspath(a.mesher), bench, polys[case],
                                                                 cdir, a.timeout),
             "gmsh": earlier[case] if case in earlier else run_gmsh(bench, polys[case], cdir, a.timeout,
                                                                    a.gmsh_size_factor)}
        r["gmsh_best"] = best_gmsh(r["gmsh"])
        rows.append(r)
    cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")]
    meta = {"date": datetime.date.today().isoformat(), "timeout": a.timeout, "gmsh_size_factor": a.gmsh_size_factor,
            "machine": "%s, %d cores available (%s)" % (cpu[0] if cpu else platform.machine(),
                                                        len(os.sched_getaffinity(0)), platform.system()),
            "gmsh_version": next((R["gmsh_version"] for r in rows for R in r["gmsh"].values()
                                  if R["gmsh_version"]), "?"),
            "command": " ".join(sys.argv)}
    if a.gmsh_from:
        meta["gmsh_from"] = "%s (of %s)" % (a.gmsh_from, prev["meta"]["date"])
    with open(os.path.join(a.out, "comparison.json"), "w") as f:
        json.dump({"meta": meta, "cases": rows}, f, indent=1)
    md = markdown(rows, meta)
    with open(os.path.join(a.out, "comparison.md"), "w") as f:
        f.write(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
