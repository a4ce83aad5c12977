#!/usr/bin/python3
"""speed_vs_gmsh.py -- issue 29's speed bars: quad-mesher against Gmsh, alternating runs in one go.

Usage:
    speed_vs_gmsh.py QUAD_MESHER DATA_DIR [--cases CASE ...] [--with-bahamas] [--repeat R]
                     [--timeout S] [--out DIR]

DATA_DIR is the shared data folder (DATA_DIR/CASE/CASE.poly); peer_gmsh.py is taken from
DATA_DIR/../bench.  The bars (ours / Gmsh, in CPU time):
  * lake_superior: <= 0.1 x Gmsh's a-fdq-blossomfull (Frontal-quad + Blossom full-quad) at
    peer_gmsh's default sizes (size factor 1: the shortest incident segment at each point);
  * greenland, bahamas_islands: <= 1 x Gmsh's c-del-blossom-subdiv (Delaunay + Blossom +
    subdivision) at 4x coarser sizes (--size-factor 4), ours at its defaults.  These Gmsh runs
    also get --set Mesh.MeshSizeExtendFromBoundary=0 (peer_gmsh's only switch for it): the point
    sizes then hold at the boundary and are not carried across the interior, which Gmsh coarsens
    inward, as ours does.  Under Gmsh's default (1), greenland at 4x coarser sizes had run over
    10 CPU minutes without ending when stopped (December 2026, this machine).
For each case, R times in turn (ours, Gmsh, ours, Gmsh, ...), one process at a time:
  * ours: OUT/quad-mesher CASE.poly -o OUT/CASE/ours.msh (read, mesh, write), OUT/quad-mesher
    being a copy of QUAD_MESHER made at the start, so a rebuild during the run changes nothing;
  * Gmsh: peer_gmsh.py's worker alone, as its "cmd_worker" shows: /usr/bin/python3 peer_gmsh.py
    --worker VARIANT CASE.poly --msh OUT/CASE/gmsh.VARIANT.msh --size-factor F [--set ...]
    (Python start, import of gmsh, numpy, scipy and shapely, geometry, meshing, writing; no
    verification, no parent process).  When the worker dies of a signal under Gmsh's defaults
    (Debian's 4.8.4 segfaults with Mesh.Algorithm=8), it is rerun at once with peer_gmsh's
    workaround (Mesh.CrossFieldClosestPoint=0), which is kept for the case's later runs.
Timed: wall clock from spawn to reaping, and CPU = user + sys from os.wait4's rusage (the
process and every descendant it waited for).  Reported: medians (and ranges) per tool, the
ratios of the medians ours/Gmsh, whether the bar holds, and for scale the median wall time
of gmsh.model.mesh.generate(2) alone, as the worker reports it.  A Gmsh run killed at --timeout
ends that case: Gmsh's times are then lower bounds ("> T s") and the ratios upper bounds
("< r").  Writes OUT/speed.json (every run's figures, machine, load, commit) and OUT/speed.md.
Absolute times on a shared machine swing by half; ratios measured in one run hold better.
"""
import argparse
import datetime
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import threading
import time

NO_EXTEND = "Mesh.MeshSizeExtendFromBoundary=0"
# case -> (peer_gmsh variant, its --size-factor, its extra --set options, bar: largest ours/Gmsh)
BARS = {"lake_superior": ("a-fdq-blossomfull", 1.0, [], 0.1),
        "greenland": ("c-del-blossom-subdiv", 4.0, [NO_EXTEND], 1.0),
        "bahamas_islands": ("c-del-blossom-subdiv", 4.0, [NO_EXTEND], 1.0)}
SLOW = "bahamas_islands"


def spawn(cmd, log, timeout):
    """Run cmd in a session of its own, stdout and stderr to log; its status ("ok", "exit N",
    "signal N" or "timeout"), wall and CPU seconds, peak memory and output."""
    t0 = time.perf_counter()
    pid = os.posix_spawn(cmd[0], cmd, os.environ, setsid=True, file_actions=[
        (os.POSIX_SPAWN_OPEN, 1, log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644), (os.POSIX_SPAWN_DUP2, 1, 2)])
    killed = []

    def kill():
        try:
            os.killpg(pid, signal.SIGKILL)
            killed.append(True)
        except ProcessLookupError:   # ended and reaped meanwhile
            pass
    timer = threading.Timer(timeout, kill)
    timer.start()
    _, st, ru = os.wait4(pid, 0)
    wall = time.perf_counter() - t0
    timer.cancel()
    code = os.waitstatus_to_exitcode(st)
    status = "timeout" if killed else "ok" if code == 0 else "exit %d" % code if code > 0 else "signal %d" % -code
    return {"status": status, "wall_s": wall, "cpu_s": ru.ru_utime + ru.ru_stime, "user_s": ru.ru_utime,
            "sys_s": ru.ru_stime, "maxrss_mb": ru.ru_maxrss / 1024, "output": open(log).read()}


def run_ours(cmd, log, timeout):
    R = spawn(cmd, log, timeout)
    m = re.search(r"(\d+) quads, (\d+) vertices", R["output"])
    if m:
        R.update(quads=int(m.group(1)), vertices=int(m.group(2)))
    R["output"] = R["output"].strip()[-300:]
    return R


def run_gmsh(cmd, log, timeout):
    R = spawn(cmd, log, timeout)
    lines = [l for l in R["output"].splitlines() if l.startswith("{")]
    W = json.loads(lines[-1]) if lines else {}
    if W:
        counts = W["gmsh_element_counts_2d"]
        R.update(gmsh_version=W["gmsh_version"], mesh_s=W["t_mesh_s"], quads=counts.get("Quadrilateral 4"),
                 vertices=W["gmsh_n_nodes"], other_cells=sum(n for t, n in counts.items() if t != "Quadrilateral 4"),
                 messages=W["gmsh_messages"])
    R["output"] = (W.get("error", "") if W else R["output"]).strip()[-300:]
    return R


def measure(a, case, poly, cdir, peer):
    """R alternating runs of ours and Gmsh on one case; every run's figures."""
    import peer_gmsh
    variant, factor, sets, bar = BARS[case]
    ours_cmd = [a.mesher, poly, "-o", os.path.join(cdir, "ours.msh")]
    gmsh_cmd = [sys.executable, peer, "--worker", variant, poly, "--msh", os.path.join(cdir, "gmsh.%s.msh" % variant),
                "--size-factor", repr(factor)] + sum((["--set", s] for s in sets), [])
    algorithm = {n: o for n, _, o in peer_gmsh.VARIANTS}[variant]["Mesh.Algorithm"]
    C = {"case": case, "poly": poly, "variant": variant, "size_factor": factor, "sets": sets, "bar": bar,
         "cmd_ours": ours_cmd, "runs": [], "workaround": None}
    for i in range(a.repeat):
        o = dict(tool="ours", repeat=i, **run_ours(ours_cmd, os.path.join(cdir, "ours.log"), a.timeout))
        g = dict(tool="gmsh", repeat=i, **run_gmsh(gmsh_cmd, os.path.join(cdir, "gmsh.log"), a.timeout))
        if g["status"].startswith("signal") and C["workaround"] is None and algorithm in peer_gmsh.WORKAROUNDS:
            wopts, why = peer_gmsh.WORKAROUNDS[algorithm]
            C["workaround"] = {"set": wopts, "why": why, "defaults_run": g}
            gmsh_cmd += sum((["--set", "%s=%g" % kv] for kv in wopts.items()), [])
            g = dict(tool="gmsh", repeat=i, **run_gmsh(gmsh_cmd, os.path.join(cdir, "gmsh.log"), a.timeout))
        C["runs"] += [o, g]
        print("%s %d: ours %s cpu %.2f s wall %.2f s; Gmsh %s cpu %.2f s wall %.2f s" % (
            case, i + 1, o["status"], o["cpu_s"], o["wall_s"], g["status"], g["cpu_s"], g["wall_s"]),
            file=sys.stderr, flush=True)
        if o["status"] != "ok" or g["status"] != "ok":
            break
    C["cmd_gmsh"] = gmsh_cmd
    return C


def summarize(C):
    """Medians, ratios and the bar's verdict of one case; a Gmsh timeout gives lower bounds."""
    S = {}
    for tool in ("ours", "gmsh"):
        runs = [r for r in C["runs"] if r["tool"] == tool]
        late = [r for r in runs if r["status"] == "timeout"] if tool == "gmsh" else []
        timed = late or [r for r in runs if r["status"] == "ok"]
        T = {"runs": len(timed), "lower_bound": bool(late), "quads": timed[-1].get("quads") if timed else None,
             "failed": next(("%s: %s" % (r["status"], r["output"]) for r in runs
                             if r["status"] != "ok" and r not in late), None)}
        for k in ("cpu_s", "wall_s"):
            v = [r[k] for r in timed]
            T[k], T[k + "_range"] = (statistics.median(v), [min(v), max(v)]) if v else (None, None)
        S[tool] = T
    meshing = [r["mesh_s"] for r in C["runs"] if r["tool"] == "gmsh" and r["status"] == "ok"]
    S["gmsh"]["mesh_s"] = statistics.median(meshing) if meshing else None   # generate(2) alone, wall
    for k in ("cpu_s", "wall_s"):
        o, g = S["ours"][k], S["gmsh"][k]
        r = o / g if o is not None and g else None
        S["ratio_" + k] = r   # an upper bound when Gmsh's time is a lower bound
        S["holds_" + k] = None if r is None else r <= C["bar"] or (None if S["gmsh"]["lower_bound"] else False)
    return S


def machine():
    cpu = [l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")]
    return {"cpu": cpu[0] if cpu else "?", "nproc": os.cpu_count(), "available": len(os.sched_getaffinity(0))}


def git_commit():
    repo = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    git = lambda *args: subprocess.run(["git", "-C", repo] + list(args), capture_output=True, text=True).stdout.strip()
    dirty = git("status", "--porcelain", "--untracked-files=no")
    return git("rev-parse", "--short", "HEAD") + (" + uncommitted changes" if dirty else "")


def markdown(cases, meta):
    s = lambda v, rng: "—" if v is None else "%.2f s (%.2f–%.2f)" % (v, *rng)
    yn = {True: "yes", False: "no", None: "?"}
    L = ["%s; %s, %d cores (%d available); load %s before, %s after; commit %s; binary built %s; Gmsh %s. "
         "Medians of %d alternating runs (range); CPU = user + sys of the whole process; ours: quad-mesher "
         "(read, mesh, write); Gmsh: peer_gmsh.py's worker (Python start, geometry, meshing, writing); "
         "the last column: the wall time of gmsh.model.mesh.generate(2) inside Gmsh's runs, for scale."
         % (meta["date"], meta["machine"]["cpu"], meta["machine"]["nproc"], meta["machine"]["available"],
            meta["load_before"], meta["load_after"], meta["commit"], meta["mesher_built"], meta["gmsh_version"],
            meta["repeat"]), "",
         "| case | bar | Gmsh run | CPU ours | CPU Gmsh | CPU ours/Gmsh | wall ours | wall Gmsh | wall ours/Gmsh "
         "| bar holds (CPU, wall) | quads ours / Gmsh | Gmsh generate(2) alone |",
         "| --- | --- | --- |" + " ---: |" * 6 + " --- | ---: | ---: |"]
    for C in cases:
        S, O, G = C["summary"], C["summary"]["ours"], C["summary"]["gmsh"]
        fixes = ["workaround %s=%g" % kv for kv in C["workaround"]["set"].items()] if C["workaround"] else []
        run = ", ".join(["%s, size factor %g" % (C["variant"], C["size_factor"])] + C["sets"] + fixes)
        gcell = lambda k: ("> %.2f s" % G[k]) if G["lower_bound"] else s(G[k], G[k + "_range"])
        ratio = lambda k: "—" if S[k] is None else ("< " if G["lower_bound"] else "") + "%.3f" % S[k]
        notes = "; ".join("%s: %s" % (t, T["failed"]) for t, T in (("ours", O), ("Gmsh", G)) if T["failed"])
        L.append("| " + " | ".join([C["case"], "≤ %g" % C["bar"], run + ("; " + notes if notes else ""),
                                    s(O["cpu_s"], O["cpu_s_range"]), gcell("cpu_s"), ratio("ratio_cpu_s"),
                                    s(O["wall_s"], O["wall_s_range"]), gcell("wall_s"), ratio("ratio_wall_s"),
                                    "%s, %s" % (yn[S["holds_cpu_s"]], yn[S["holds_wall_s"]]),
                                    "%s / %s" % (O["quads"] or "—", G["quads"] or "—"),
                                    "—" if G["mesh_s"] is None else "%.2f s" % G["mesh_s"]]) + " |")
    return "\n".join(L) + "\n"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesher", help="the quad-mesher binary")
    ap.add_argument("data", help="shared data folder (holds CASE/CASE.poly; peer_gmsh.py is in ../bench)")
    ap.add_argument("--cases", nargs="+", choices=sorted(BARS), metavar="CASE", default=["lake_superior", "greenland"],
                    help="cases with a bar (default: lake_superior greenland)")
    ap.add_argument("--with-bahamas", action="store_true", help="also run %s (Gmsh takes minutes)" % SLOW)
    ap.add_argument("--repeat", type=int, default=3, help="runs of each tool per case (default 3)")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per run of either tool (default 300)")
    ap.add_argument("--out", default="/tmp/speed_vs_gmsh", help="output folder (default /tmp/speed_vs_gmsh)")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)   # every run uses one copy: the build may change under a long run
    a.mesher = shutil.copy2(a.mesher, os.path.join(a.out, "quad-mesher"))
    data, bench = os.path.abspath(a.data), os.path.abspath(os.path.join(a.data, "..", "bench"))
    sys.path.insert(0, bench)
    cases = a.cases + ([SLOW] if a.with_bahamas and SLOW not in a.cases else [])
    meta = {"date": datetime.datetime.now().isoformat(timespec="seconds"), "machine": machine(),
            "load_before": "%.2f %.2f %.2f" % os.getloadavg(), "commit": git_commit(), "repeat": a.repeat,
            "timeout": a.timeout, "mesher": a.mesher, "command": " ".join(sys.argv),
            "mesher_built": datetime.datetime.fromtimestamp(os.path.getmtime(a.mesher)).isoformat(timespec="seconds")}
    rows = []
    for case in cases:
        cdir = os.path.join(a.out, case)
        os.makedirs(cdir, exist_ok=True)
        C = measure(a, case, os.path.join(data, case, case + ".poly"), cdir, os.path.join(bench, "peer_gmsh.py"))
        C["summary"] = summarize(C)
        rows.append(C)
    meta["load_after"] = "%.2f %.2f %.2f" % os.getloadavg()
    meta["gmsh_version"] = next((r["gmsh_version"] for C in rows for r in C["runs"] if "gmsh_version" in r), "?")
    with open(os.path.join(a.out, "speed.json"), "w") as f:
        json.dump({"meta": meta, "cases": rows}, f, indent=1)
    md = markdown(rows, meta)
    with open(os.path.join(a.out, "speed.md"), "w") as f:
        f.write(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
