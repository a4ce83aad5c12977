#!/usr/bin/python3
"""compare_boundary_layers.py -- quad-mesher's boundary layers side by side with Gmsh's BoundaryLayer field.

Usage:
    compare_boundary_layers.py QUAD_MESHER OUT_DIR [--cases CASE ...] [--recipes NAME,...]
                               [--timeout S] [--samples K] [--bench DIR]

Rerun (about 2 minutes on 2 cores, plus --timeout for each Gmsh run that hangs instead of crashing):
    /usr/bin/python3 benchmark/compare_boundary_layers.py build/src/quad-mesher /tmp/blbench/out

Cases (--cases takes their names, default all three, or a spec NAME=POLY:walls=M1,M2:n=N:h=H:r=R[:fan=X/Y;X/Y]):
  naca0012   ../shared/data/naca0012/naca0012_sharp.poly, walls marker 2, N 20, H 1e-4, R 1.15,
             Gmsh fan point at the trailing edge (1, 0)
  30p30n     ../shared/data/airfoil_30p30n/airfoil_30p30n.poly, walls markers 2,3,4, N 20, H 1e-4, R 1.15
  cylinder   a cylinder of radius 0.5 (64 sides, marker 2) in the channel [-2,6]x[-1,1] (sides cut into
             0.125-long segments, marker 1), walls 1 and 2 (every boundary), N 8, H 5e-4, R 1.2; the
             .poly is written to OUT_DIR/cylinder/cylinder.poly
For every case, on the same .poly and the same layer parameters, one process per run, each
killed after --timeout seconds (default 300):
  * ours:  QUAD_MESHER POLY -o ours.msh --report ours.json --boundary-layers N --first-height H
           --growth R --wall-markers M1,M2;
  * Gmsh:  this script with --worker in a fresh Python: the geometry of peer_gmsh.py (every input
           vertex a point with size = its shortest incident segment, every segment a line), a
           BoundaryLayer field on the wall curves (Size=H, Ratio=R, Thickness = H (R^N - 1)/(R - 1),
           the N layers' sum, Quads=1, FanPointsList = the case's fan points) set with
           setAsBoundaryLayer, then one recipe of options (RECIPES below: the triangles left as
           they are, Blossom recombination of the whole mesh with Mesh.RecombineAll=1 under
           several Mesh.Algorithm / Mesh.RecombinationAlgorithm, and Mesh.SubdivisionAlgorithm=1,
           which splits every element into quads and so halves the layers' heights).  A worker
           killed by a signal (crash), one that times out and a Gmsh error are rows too.
Every mesh written is checked by verify_mesh.py MESH --domain POLY --no-overlap --json.

Columns:
  exit        exit status, "signal N" (crash), "timeout" or Gmsh's error
  quads / tris left   2D cells of the mesh (any other 2D cell is counted under tris left)
  valid       every verify_mesh.py check but angles_45_135 passed, else the failed ones
  1st height  measured here, not taken from a report: every boundary edge of the mesh lying on a
              wall segment of the .poly (midpoint within 1e-9 of the bbox diagonal of it), and each
              vertex of its cell off that edge: its distance to the edge's line.  min/median/max
              over those vertices, divided by the target H (1.00 = exact).
  layers      at K (--samples, default 12) wall edges spread evenly over the wall edges (in the
              .poly's segment order): walk from the wall cell to the cell across its opposite edge,
              and on, counting cells while the cell is a quad, its top edge is parallel to its
              bottom edge (heights of its top corners above the bottom edge's line within 20 %),
              its height (the mean of those two) is R or 1 times the one below to 2 % (1: the halves
              of a subdivided layer), and its two side edges turn by at most 15 degrees from the cell
              below's: a stack of layers continuing the requested progression.  min/median/max over
              the samples; the target is N (2N after subdivision).
  stacked     the same walk, looser: quads whose side edges turn by at most 15 degrees and whose
              height is 1/1.6 to 1.6 R times the one below (layers that lost the progression, e.g. to
              Gmsh's smoothing after recombination; it may take a cell or two of the mesh beyond).
  angles      min .. max quad angle from verify_mesh.py (quads only)
  time s      meshing / whole process: ours seconds.total of its report / wall clock of the CLI
              (read, mesh, write); Gmsh gmsh.model.mesh.generate(2) / the worker process (Python
              start, import, geometry, meshing, writing).
The table goes to stdout and OUT_DIR/table.md; every figure to OUT_DIR/results.json (with the
commands that rerun each mesh and check).  Needs Debian's gmsh, python3-gmsh, numpy and meshio
(and what peer_gmsh.py and verify_mesh.py import); run with /usr/bin/python3.
"""
import argparse
import contextlib
import io
import json
import os
import shlex
import signal
import subprocess
import sys
import time

import numpy as np

# ../shared beside the project: the shared data and the verifier
SHARED = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "shared"))
BENCH = os.path.join(SHARED, "bench")
TIMEOUT = 300.0

DEFAULT_CASES = {
    "naca0012": {"poly": os.path.join(SHARED, "data", "naca0012", "naca0012_sharp.poly"), "walls": [2], "n": 20, "h": 1e-4,
                 "r": 1.15, "fans": [(1.0, 0.0)]},
    "30p30n": {"poly": os.path.join(SHARED, "data", "airfoil_30p30n", "airfoil_30p30n.poly"), "walls": [2, 3, 4], "n": 20,
               "h": 1e-4, "r": 1.15, "fans": []},
    "cylinder": {"poly": None, "walls": [1, 2], "n": 8, "h": 5e-4, "r": 1.2, "fans": []},
}

# name, what it is, Gmsh options set before generate(2) (everything else at Gmsh's defaults), and
# what is done after it: "recombine" = gmsh.model.mesh.recombine() (Blossom recombination of the
# whole mesh, Mesh.RecombinationAlgorithm of the options), "refine" = gmsh.model.mesh.refine()
# under Mesh.SubdivisionAlgorithm=1 (every cell split into quads, so the layers' heights halve).
RECIPES = [
    ("hybrid", "BL quads, triangles elsewhere (Frontal-Delaunay, no recombination)",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 0}, []),
    ("fd-blossom", "Frontal-Delaunay, RecombineAll=1, Blossom",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1}, []),
    ("del-blossom", "Delaunay, RecombineAll=1, Blossom",
     {"Mesh.Algorithm": 5, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1}, []),
    ("fdq-blossom", "Frontal-Delaunay for quads, RecombineAll=1, Blossom",
     {"Mesh.Algorithm": 8, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1}, []),
    ("fdq-blossom-cfcp0", "fdq-blossom with Mesh.CrossFieldClosestPoint=0 (peer_gmsh.py's workaround for a crash)",
     {"Mesh.Algorithm": 8, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1,
      "Mesh.CrossFieldClosestPoint": 0}, []),
    ("fd-simplefull", "Frontal-Delaunay, RecombineAll=1, simple full-quad",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 2}, []),
    ("fd-blossomfull", "Frontal-Delaunay, RecombineAll=1, Blossom full-quad",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 3}, []),
    ("fd-blossom-subdiv", "Frontal-Delaunay, RecombineAll=1, Blossom, SubdivisionAlgorithm=1",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1,
      "Mesh.SubdivisionAlgorithm": 1}, []),
    ("del-blossom-subdiv", "Delaunay, RecombineAll=1, Blossom, SubdivisionAlgorithm=1",
     {"Mesh.Algorithm": 5, "Mesh.RecombineAll": 1, "Mesh.RecombinationAlgorithm": 1,
      "Mesh.SubdivisionAlgorithm": 1}, []),
    ("fd+recombine", "hybrid, then mesh.recombine() with Blossom",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 0, "Mesh.RecombinationAlgorithm": 1}, ["recombine"]),
    ("del+recombine", "Delaunay hybrid, then mesh.recombine() with Blossom",
     {"Mesh.Algorithm": 5, "Mesh.RecombineAll": 0, "Mesh.RecombinationAlgorithm": 1}, ["recombine"]),
    ("fd+recombine-full", "hybrid, then mesh.recombine() with Blossom full-quad",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 0, "Mesh.RecombinationAlgorithm": 3}, ["recombine"]),
    ("fd+recombine+subdiv", "fd+recombine, then mesh.refine() with SubdivisionAlgorithm=1",
     {"Mesh.Algorithm": 6, "Mesh.RecombineAll": 0, "Mesh.RecombinationAlgorithm": 1}, ["recombine", "refine"]),
]


# ----------------------------------------------------------------------------- inputs
def read_poly(path):
    """Triangle .poly with its segment markers: (vertices (N,2), segments (M,2) 0-based, markers (M,))."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split("#", 1)[0].split()
            if line:
                rows.append(line)
    nv = int(rows[0][0])
    ids = [int(r[0]) for r in rows[1:1 + nv]]
    V = np.array([(float(r[1]), float(r[2])) for r in rows[1:1 + nv]]).reshape(-1, 2)
    row_of = {v: i for i, v in enumerate(ids)}
    i = 1 + nv
    ns, smark = int(rows[i][0]), int(rows[i][1])
    S = [(row_of[int(r[1])], row_of[int(r[2])]) for r in rows[i + 1:i + 1 + ns]]
    M = [int(r[3]) if smark else 0 for r in rows[i + 1:i + 1 + ns]]
    return V, np.array(S, np.int64).reshape(-1, 2), np.array(M, np.int64)


def write_cylinder_poly(path, radius=0.5, sides=64, box=(-2.0, 6.0, -1.0, 1.0), step=0.125):
    """The cylinder-in-a-channel case: channel loop (marker 1, counter-clockwise, sides cut
    into `step`-long segments), cylinder loop (marker 2, clockwise), a hole point at its centre."""
    x0, x1, y0, y1 = box
    corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
    outer = []
    for (ax, ay), (bx, by) in zip(corners, corners[1:] + corners[:1]):
        k = max(1, int(round(np.hypot(bx - ax, by - ay) / step)))
        outer += [(ax + (bx - ax) * j / k, ay + (by - ay) * j / k) for j in range(k)]
    t = -2 * np.pi * np.arange(sides) / sides
    inner = [(radius * np.cos(a), radius * np.sin(a)) for a in t]
    pts = [(p, 1) for p in outer] + [(p, 2) for p in inner]
    segs = [(j, (j + 1) % len(outer), 1) for j in range(len(outer))]
    segs += [(len(outer) + j, len(outer) + (j + 1) % sides, 2) for j in range(sides)]
    with open(path, "w") as f:
        f.write("# cylinder r %g (%d sides, marker 2) in the channel [%g,%g]x[%g,%g] (marker 1)\n"
                "# written by compare_boundary_layers.py\n" % ((radius, sides) + tuple(box)))
        f.write("%d 2 0 1\n" % len(pts))
        f.writelines("%d %.17g %.17g %d\n" % (j + 1, p[0], p[1], m) for j, (p, m) in enumerate(pts))
        f.write("%d 1\n" % len(segs))
        f.writelines("%d %d %d %d\n" % (j + 1, a + 1, b + 1, m) for j, (a, b, m) in enumerate(segs))
        f.write("1\n1 0 0\n")


def parse_case(text):
    """A built-in case name, or NAME=POLY:walls=M1,M2:n=N:h=H:r=R[:fan=X/Y;X/Y]."""
    if text in DEFAULT_CASES:
        return text, dict(DEFAULT_CASES[text])
    if "=" not in text:
        raise ValueError("unknown case %r (built-in: %s)" % (text, ", ".join(DEFAULT_CASES)))
    name, rest = text.split("=", 1)
    poly, *fields = rest.split(":")
    c = {"poly": os.path.abspath(poly), "walls": None, "n": None, "h": None, "r": 1.2, "fans": []}
    for fld in fields:
        k, v = fld.split("=", 1)
        if k == "walls":
            c["walls"] = [int(m) for m in v.split(",")]
        elif k in ("n",):
            c[k] = int(v)
        elif k in ("h", "r"):
            c[k] = float(v)
        elif k == "fan":
            c["fans"] = [tuple(float(x) for x in p.split("/")) for p in v.split(";") if p]
        else:
            raise ValueError("case %s: unknown field %r" % (name, k))
    if c["walls"] is None or c["n"] is None or c["h"] is None:
        raise ValueError("case %s: walls=, n= and h= are required" % name)
    return name, c


def parse_set(text):
    k, v = text.split("=", 1)
    return k.strip(), float(v)


def thickness(c):
    """The N layers' total height."""
    n, h, r = c["n"], c["h"], c["r"]
    return h * n if r == 1 else h * (r ** n - 1) / (r - 1)


# ----------------------------------------------------------------------------- Gmsh worker
def nearest_vertex(V, p):
    d = np.hypot(*(V - np.asarray(p)).T)
    return int(np.argmin(d)), float(d.min())


def gmsh_worker(a):
    """One Gmsh run in this process; prints one JSON line."""
    t0 = time.perf_counter()
    import gmsh
    sys.path.insert(0, a.bench)
    import peer_gmsh
    c = json.loads(a.case_json)
    name, desc, opts, post = next(r for r in RECIPES if r[0] == a.worker)
    gmsh.initialize(readConfigFiles=False)
    gmsh.option.setNumber("General.Terminal", 1)     # Gmsh's messages on stdout: the last ones tell a crash
    gmsh.logger.start()
    R = {"gmsh_version": gmsh.option.getString("General.Version")}
    gmsh.model.add(os.path.splitext(os.path.basename(c["poly"]))[0])
    R["geometry"] = peer_gmsh.build_geometry(gmsh, c["poly"])
    # wall curves: lines whose two ends are the ends of one wall segment of the .poly
    V, S, M = read_poly(c["poly"])
    wall = {frozenset(s) for s, m in zip(S.tolist(), M.tolist()) if m in c["walls"]}
    diag = float(np.hypot(*np.ptp(V, axis=0)))
    ptv = {}
    for _, p in gmsh.model.getEntities(0):
        k, d = nearest_vertex(V, gmsh.model.getValue(0, p, [])[:2])
        if d <= 1e-9 * diag:
            ptv[p] = k
    curves = []
    for _, cv in gmsh.model.getEntities(1):
        ends = [abs(t) for _, t in gmsh.model.getBoundary([(1, cv)], oriented=False)]
        if len(ends) == 2 and all(e in ptv for e in ends) and frozenset(ptv[e] for e in ends) in wall:
            curves.append(cv)
    fans = []
    for p in c["fans"]:
        k, _ = nearest_vertex(V, p)
        fans += [t for t, v in ptv.items() if v == k]
    R.update(wall_curves=len(curves), fan_points=fans, thickness=thickness(c))
    f = gmsh.model.mesh.field.add("BoundaryLayer")
    gmsh.model.mesh.field.setNumbers(f, "CurvesList", curves)
    gmsh.model.mesh.field.setNumber(f, "Size", c["h"])
    gmsh.model.mesh.field.setNumber(f, "Ratio", c["r"])
    gmsh.model.mesh.field.setNumber(f, "Thickness", thickness(c))
    gmsh.model.mesh.field.setNumber(f, "Quads", 1)
    if fans:
        gmsh.model.mesh.field.setNumbers(f, "FanPointsList", fans)
    gmsh.model.mesh.field.setAsBoundaryLayer(f)
    opts = dict(opts, **dict(parse_set(x) for x in a.gmsh_set or []))
    for k, v in opts.items():
        gmsh.option.setNumber(k, v)
    R["options"], R["post"] = opts, list(post)
    t1 = time.perf_counter()
    try:
        gmsh.model.mesh.generate(2)
        for step in post:
            if step == "recombine":
                gmsh.model.mesh.recombine()
            elif step == "refine":
                gmsh.option.setNumber("Mesh.SubdivisionAlgorithm", 1)
                gmsh.model.mesh.refine()
        R["status"] = "ok"
    except Exception as e:  # Gmsh raises on its meshing errors
        R["status"], R["error"] = "error", str(e)
    R["t_mesh_s"] = time.perf_counter() - t1
    if R["status"] == "ok":
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.write(a.msh)
        R["msh"] = a.msh
    log = gmsh.logger.get()
    R["messages"] = ([m for m in log if m.startswith("Error")] + [m for m in log if m.startswith("Warning")])[:10]
    gmsh.logger.stop()
    gmsh.finalize()
    R["t_worker_s"] = time.perf_counter() - t0
    print(json.dumps(R), flush=True)
    return 0 if R["status"] == "ok" else 1


# ----------------------------------------------------------------------------- runs
def run(cmd, timeout):
    """Run a process; returns (CompletedProcess or None on timeout, wall seconds)."""
    t0 = time.perf_counter()
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return None, time.perf_counter() - t0
    return p, time.perf_counter() - t0


def exit_text(p):
    if p is None:
        return "timeout"
    if p.returncode < 0:
        try:
            return "crash: signal %d (%s)" % (-p.returncode, signal.Signals(-p.returncode).name)
        except ValueError:
            return "crash: signal %d" % -p.returncode
    return str(p.returncode)


def run_ours(qm, c, cdir, timeout):
    msh, rep = os.path.join(cdir, "ours.msh"), os.path.join(cdir, "ours.json")
    for f in (msh, rep):
        if os.path.exists(f):
            os.remove(f)
    cmd = [qm, c["poly"], "-o", msh, "--report", rep, "--boundary-layers", str(c["n"]),
           "--first-height", repr(c["h"]), "--growth", repr(c["r"]),
           "--wall-markers", ",".join(map(str, c["walls"]))]
    p, wall = run(cmd, timeout)
    R = {"mesher": "ours", "recipe": "quad-mesher --boundary-layers", "cmd": shlex.join(cmd),
         "exit": exit_text(p), "t_process_s": wall}
    if p is not None and p.returncode != 0:
        R["error"] = p.stderr.strip()[-400:]
    if os.path.exists(rep):
        rp = json.load(open(rep))
        R["t_mesh_s"] = rp.get("seconds", {}).get("total")
        R["report"] = {k: rp.get(k) for k in ("quads", "validity", "boundary_layers")}
    if p is not None and p.returncode == 0 and os.path.exists(msh):
        R["msh"] = msh
    return R


def run_gmsh(recipe, c, cdir, timeout, bench, gmsh_set):
    name, desc, opts, post = recipe
    msh = os.path.join(cdir, "gmsh-%s.msh" % name)
    if os.path.exists(msh):
        os.remove(msh)
    cmd = [sys.executable, os.path.abspath(__file__), "--worker", name, "--msh", msh, "--bench", bench,
           "--case-json", json.dumps(c)] + sum((["--gmsh-set", x] for x in gmsh_set or []), [])
    p, wall = run(cmd, timeout)
    R = {"mesher": "gmsh", "recipe": name, "description": desc, "cmd": shlex.join(cmd),
         "exit": exit_text(p), "t_process_s": wall}
    lines = [l for l in (p.stdout if p else "").splitlines() if l.startswith("{")]
    if lines:
        W = json.loads(lines[-1])
        R.update(W)
        if W["status"] != "ok":
            R["exit"] = "error: " + W.get("error", "")
    elif p is not None:   # a crash: Gmsh's errors, the C++ abort, the last messages it printed
        out = (p.stdout + "\n" + p.stderr).splitlines()
        errs = [l.strip() for l in out if l.startswith("Error") or l.startswith("terminate called")]
        R["error"] = " / ".join(errs[:3]) or p.stderr.strip()[-300:]
        R["last_messages"] = [l for l in p.stdout.splitlines() if l.strip()][-3:]
    return R


def verify(bench, msh, poly):
    cmd = [sys.executable, os.path.join(bench, "verify_mesh.py"), msh, "--domain", poly, "--no-overlap", "--json"]
    p = subprocess.run(cmd, capture_output=True, text=True)
    try:
        V = json.loads(p.stdout)
    except ValueError:
        return {"cmd_verify": shlex.join(cmd), "error": "verify_mesh.py gave no JSON: " + p.stderr.strip()[-300:]}
    if "error" in V:
        return {"cmd_verify": shlex.join(cmd), "error": V["error"]}
    return {"cmd_verify": shlex.join(cmd), "quads": V["n_quads"], "other_cells": V["n_other_cells"],
            "angle_min": V["angle_min"], "angle_max": V["angle_max"],
            "failed_checks": [k for k in V["failed_checks"] if k != "angles_45_135"]}


# ----------------------------------------------------------------------------- measurement
def read_cells(msh):
    """Points (N,2) and the 2D cells as lists of corner indices (quads and triangles)."""
    import meshio
    with contextlib.redirect_stdout(io.StringIO()):      # meshio prints a blank line per .msh read
        m = meshio.read(msh)
    P = np.asarray(m.points, float)[:, :2]
    cells = []
    for blk in m.cells:
        t = blk.type
        if t.startswith("quad"):
            cells += blk.data[:, :4].tolist()
        elif t.startswith("triangle"):
            cells += blk.data[:, :3].tolist()
        elif t == "polygon":
            cells += blk.data.tolist()
    return P, cells


def wall_edges(P, cells, poly, walls):
    """Boundary edges of the mesh on a wall segment: list of (cell, i) meaning the edge from
    corner i to corner i+1 of that cell, with the wall segment's index."""
    V, S, M = read_poly(poly)
    uses = {}
    for ci, cell in enumerate(cells):
        k = len(cell)
        for i in range(k):
            e = (min(cell[i], cell[(i + 1) % k]), max(cell[i], cell[(i + 1) % k]))
            uses.setdefault(e, []).append((ci, i))
    bnd = [u[0] for u in uses.values() if len(u) == 1]
    if not bnd:
        return [], np.zeros(0, np.int64), uses
    a = np.array([P[cells[ci][i]] for ci, i in bnd])
    b = np.array([P[cells[ci][(i + 1) % len(cells[ci])]] for ci, i in bnd])
    mid = 0.5 * (a + b)
    A, B = V[S[:, 0]], V[S[:, 1]]
    d = B - A
    L2 = np.maximum((d * d).sum(1), 1e-300)
    best = np.full(len(mid), np.inf)
    seg = np.zeros(len(mid), np.int64)
    for j in range(0, len(S), 256):   # point-segment distances in blocks
        w = mid[:, None, :] - A[None, j:j + 256]
        t = np.clip((w * d[None, j:j + 256]).sum(2) / L2[None, j:j + 256], 0, 1)
        dist = np.hypot(*(w - t[..., None] * d[None, j:j + 256]).transpose(2, 0, 1))
        k = dist.argmin(1)
        dk = dist[np.arange(len(mid)), k]
        better = dk < best
        best[better], seg[better] = dk[better], k[better] + j
    tol = 1e-9 * float(np.hypot(*np.ptp(V, axis=0)))
    keep = (best <= tol) & np.isin(M[seg], walls)
    t = ((mid - A[seg]) * d[seg]).sum(1) / L2[seg]
    order = [j for j in np.lexsort((t, seg)) if keep[j]]       # along the .poly's wall segments
    return [bnd[j] for j in order], seg[order], uses


def height_above(P, a, b, pts):
    """Distances of the points to the line through P[a], P[b]."""
    d = P[b] - P[a]
    w = P[pts] - P[a]
    return np.abs(d[0] * w[:, 1] - d[1] * w[:, 0]) / np.hypot(*d)


def unit(v):
    return v / np.hypot(*v)


def layer_stack(P, cells, uses, ci, i, r, strict=True, cap=1000):
    """Heights of the cells stacked on the wall edge (corner i to i+1 of cell ci) that pass as
    layers: a quad whose top edge is parallel to its bottom one (its top corners' heights above
    the bottom edge's line within 20 % of each other), whose height is R or 1 times the one below
    (to 2 %; 1 for the halves of subdivided layers), and whose two side edges turn by at most 15
    degrees from those of the cell below.  Not strict: any quad whose side edges turn by at most
    15 degrees and whose height is 1/1.6 to 1.6 R times the one below (a stack of layers that
    lost the progression, e.g. to smoothing)."""
    hs, sides = [], None
    cos_max = np.cos(np.radians(15.0))
    while len(hs) < cap:
        cell = cells[ci]
        if len(cell) != 4:
            break
        a, b = cell[i], cell[(i + 1) % 4]
        c, d = cell[(i + 2) % 4], cell[(i + 3) % 4]        # top edge c -> d; sides b -> c and a -> d
        h2 = height_above(P, a, b, [c, d])
        h = float(h2.mean())
        if h <= 0 or (strict and h2.max() - h2.min() > 0.2 * h):
            break
        if hs and strict and not any(abs(h / hs[-1] / g - 1) <= 0.02 for g in (r, 1.0)):
            break
        if hs and not strict and not hs[-1] / 1.6 <= h <= 1.6 * r * hs[-1]:
            break
        new_sides = (unit(P[c] - P[b]), unit(P[d] - P[a]))
        if sides and min(float(u @ v) for u, v in zip(sides, new_sides)) < cos_max:
            break
        hs.append(h)
        top = (min(c, d), max(c, d))
        nxt = [u for u in uses.get(top, []) if u[0] != ci]
        if not nxt:
            break
        ci, j = nxt[0]          # the top edge is the next cell's bottom, from its corner j
        # keep b -> c and a -> d the same way round: the next cell's edge runs d -> c (corner j = d)
        i = j
        sides = new_sides if cells[ci][j] == d else (new_sides[1], new_sides[0])
    return hs


def measure(msh, c, samples):
    """First heights over the target and layer counts, measured on the mesh."""
    P, cells = read_cells(msh)
    edges, _, uses = wall_edges(P, cells, c["poly"], c["walls"])
    if not edges:
        return {"wall_edges": 0}
    fh = []
    for ci, i in edges:
        cell = cells[ci]
        k = len(cell)
        a, b = cell[i], cell[(i + 1) % k]
        fh += height_above(P, a, b, [v for v in cell if v not in (a, b)]).tolist()
    fh = np.array(fh) / c["h"]
    pick = np.unique(np.linspace(0, len(edges) - 1, min(samples, len(edges))).round().astype(int))
    stacks = [layer_stack(P, cells, uses, *edges[j], c["r"]) for j in pick]
    n = np.array([len(s) for s in stacks])
    loose = np.array([len(layer_stack(P, cells, uses, *edges[j], c["r"], strict=False)) for j in pick])
    return {"wall_edges": len(edges), "first_height_rel": [float(fh.min()), float(np.median(fh)), float(fh.max())],
            "layers": [int(n.min()), float(np.median(n)), int(n.max())], "layers_per_sample": n.tolist(),
            "stacked": [int(loose.min()), float(np.median(loose)), int(loose.max())],
            "stacked_per_sample": loose.tolist(),
            "sample_heights": [s[:3] + ["..."] + s[-2:] if len(s) > 5 else s for s in stacks]}


# ----------------------------------------------------------------------------- table
def fmt3(v, spec):
    return "—" if not v else "/".join(format(x, spec) for x in v)


def table_row(case, c, R):
    V = R.get("verify") or {}
    Mz = R.get("measure") or {}
    if "error" in V:
        valid = "verify error"
    elif V:
        valid = "yes" if not V["failed_checks"] else "no: " + ", ".join(V["failed_checks"])
    else:
        valid = "—"
    exit_ = R["exit"]
    if len(exit_) > 70:
        exit_ = exit_[:67] + "..."
    t = lambda k: "—" if R.get(k) is None else "%.2f" % R[k]
    return "| " + " | ".join([
        case, "%s / %s" % (R["mesher"], R["recipe"]) if R["mesher"] == "gmsh" else "ours",
        exit_.replace("|", "\\|"), str(V.get("quads", "—")), str(V.get("other_cells", "—")), valid,
        fmt3(Mz.get("first_height_rel"), ".2f"),
        "—" if not Mz.get("layers") else "%d/%g/%d" % tuple(Mz["layers"]),
        "—" if not Mz.get("stacked") else "%d/%g/%d" % tuple(Mz["stacked"]),
        "—" if "angle_min" not in V else "%.1f .. %.1f" % (V["angle_min"], V["angle_max"]),
        "%s / %s" % (t("t_mesh_s"), t("t_process_s"))]) + " |"


def markdown(rows, cases, meta):
    head = ["case", "mesher / recipe", "exit", "quads", "tris left", "valid", "1st height / H (min/med/max)",
            "layers (min/med/max)", "stacked (min/med/max)",
            "angles", "time s (mesh / process)"]
    L = ["Boundary layers, ours vs Gmsh %s's BoundaryLayer field; %s; timeout %g s per run." % (
        meta["gmsh_version"], meta["date"], meta["timeout"]), ""]
    for name, c in cases:
        L.append("- %s: %s, walls %s, N %d, H %g, R %g (thickness %.4g)%s" % (
            name, c["poly"], ",".join(map(str, c["walls"])), c["n"], c["h"], c["r"], thickness(c),
            ", Gmsh fan points at " + "; ".join("(%g, %g)" % p for p in c["fans"]) if c["fans"] else ""))
    L += ["", "| " + " | ".join(head) + " |", "|" + " --- |" * 3 + " ---: |" * 2 + " --- |" + " ---: |" * 5]
    L += [table_row(r["case"], dict(cases)[r["case"]], r) for r in rows]
    notes = []
    for r in rows:
        if r["exit"] != "0" or r.get("measure", {}).get("error"):
            why = r.get("error") or r.get("measure", {}).get("error") or ""
            last = " | ".join(r.get("last_messages") or [])
            notes.append("- %s, %s: %s%s%s" % (r["case"], r["recipe"], r["exit"].split(":")[0],
                                              ": " + " ".join(why.split())[:300] if why else "",
                                              "; last messages: " + " ".join(last.split())[:400] if last else ""))
    if notes:
        L += ["", "Failures:"] + notes
    return "\n".join(L) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("mesher", nargs="?", help="the quad-mesher binary")
    ap.add_argument("out", nargs="?", help="output folder")
    ap.add_argument("--cases", nargs="+", default=list(DEFAULT_CASES),
                    help="built-in case names (%s) or NAME=POLY:walls=M1,M2:n=N:h=H:r=R[:fan=X/Y;...]"
                         % ", ".join(DEFAULT_CASES))
    ap.add_argument("--recipes", default="all", help="comma-separated Gmsh recipes, 'all' or 'none' (%s)"
                    % ", ".join(r[0] for r in RECIPES))
    ap.add_argument("--timeout", type=float, default=TIMEOUT, help="seconds per run, ours and each Gmsh recipe")
    ap.add_argument("--samples", type=int, default=12, help="wall edges where layers are counted")
    ap.add_argument("--gmsh-set", action="append", metavar="OPTION=VALUE",
                    help="a numeric Gmsh option added to every recipe (repeatable)")
    ap.add_argument("--bench", default=BENCH, help="folder of peer_gmsh.py and verify_mesh.py")
    ap.add_argument("--worker", help=argparse.SUPPRESS)
    ap.add_argument("--msh", help=argparse.SUPPRESS)
    ap.add_argument("--case-json", help=argparse.SUPPRESS)
    a = ap.parse_args(argv)
    if a.worker:
        return gmsh_worker(a)
    if not a.mesher or not a.out:
        ap.error("give QUAD_MESHER and OUT_DIR")
    names = [r[0] for r in RECIPES]
    chosen = names if a.recipes == "all" else [] if a.recipes == "none" else a.recipes.split(",")
    if set(chosen) - set(names):
        ap.error("unknown recipe(s) %s" % ", ".join(sorted(set(chosen) - set(names))))
    try:
        cases = [parse_case(x) for x in a.cases]
    except ValueError as e:
        ap.error(str(e))
    out = os.path.abspath(a.out)
    os.makedirs(out, exist_ok=True)
    qm = os.path.abspath(a.mesher)
    rows = []
    for name, c in cases:
        cdir = os.path.join(out, name)
        os.makedirs(cdir, exist_ok=True)
        if c["poly"] is None:
            c["poly"] = os.path.join(cdir, name + ".poly")
            write_cylinder_poly(c["poly"])
        runs = [("ours", lambda: run_ours(qm, c, cdir, a.timeout))]
        runs += [(r[0], lambda r=r: run_gmsh(r, c, cdir, a.timeout, a.bench, a.gmsh_set)) for r in RECIPES if r[0] in chosen]
        for label, go in runs:
            print("%s: %s ..." % (name, label), file=sys.stderr, flush=True)
            R = go()
            R["case"] = name
            if R.get("msh") and os.path.exists(R["msh"]):
                R["verify"] = verify(a.bench, R["msh"], c["poly"])
                try:
                    R["measure"] = measure(R["msh"], c, a.samples)
                except Exception as e:   # an unreadable mesh is a row, not the end of the benchmark
                    R["measure"] = {"error": repr(e)}
            rows.append(R)
    meta = {"date": time.strftime("%Y-%m-%d"), "timeout": a.timeout, "command": shlex.join(sys.argv),
            "gmsh_version": next((r["gmsh_version"] for r in rows if r.get("gmsh_version")), "?")}
    with open(os.path.join(out, "results.json"), "w") as f:
        json.dump({"meta": meta, "cases": dict(cases), "runs": rows}, f, indent=1)
    md = markdown(rows, cases, meta)
    with open(os.path.join(out, "table.md"), "w") as f:
        f.write(md)
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
