#!/usr/bin/python3
"""transform_sweep.py -- the angle guarantee under rotations and scalings, case by case.

Usage:
    transform_sweep.py QUAD_MESHER DATA_DIR OUT_DIR {airfoils,arms,blobs,stars} [--jobs N] [--blobs N]
                       [--airfoils NAME,...] [--turns FIRST:LAST:STEP] [--scales S,...]

Meshes each input with `QUAD_MESHER IN.poly -o OUT.msh --report OUT.json` and counts the quads
the report gives as having an angle outside [45, 135] that no input corner forces
(`buffer.quads_outside_45_135_not_forced`). A mesh is right or wrong in its given position
only, so the guarantee is judged over many positions:
  * airfoils: DATA_DIR's airfoil_30p30n, naca0012 and naca0012_sharp, each turned about its
    points' centroid by 11, 37, 59, 83, 101, 123, 149 and 172 degrees and scaled by 1, 1.37,
    3.1 and 7.3 (96 runs: air foils at angles of attack). --airfoils takes other shared
    cases (by file name, e.g. airfoil_3elem_jigsaw), --turns other angles (degrees FIRST,
    FIRST+STEP, ... up to LAST) and --scales other scales: `--airfoils
    airfoil_30p30n,airfoil_3elem_jigsaw --turns 1:179:2 --scales 1.37,3.1,7.3` is 540 runs;
  * arms: an L, a cross and a rectangle with arms 0.03 to 0.21 wide turned 0.37 to 45.37
    degrees, and an L and a cross 0.126 to 0.15 wide turned 20.37 to 45.87 degrees (504 runs:
    narrow regions across the quadtree's axes);
  * blobs: 80 random smooth domains (seeds 0 to 79; --blobs N for seeds 0 to N-1): a blob
    r = 1 + a sum of 2 to 6 cosine terms of orders 2 up, sampled at 200, 400 or 800 points,
    with 0 to 3 smaller blob holes, turned, scaled by 0.013 to 250 and moved up to 10
    (smooth curves of every kind, paper §4). For these the templates stage is run too (`--stop-after
    templates`), and its buffer-side angles outside [112.5, 225] (Lemma 2,
    `buffer.buffer_angles_out`) are counted;
  * stars: 200 random star polygons (seeds 0 to 199): 6 to 40 corners at jittered angles and
    radii, with 0 to 2 star holes, turned and scaled by 0.01 to 130 (sharp and reflex corners
    of every size, paper §5).
Prints each run with quads out (the tool's exit status 4, or a failed exit, or Lemma 2 misses)
and a summary line: runs, runs with quads out, failed runs, quads in all (and Lemma 2 misses in
all). The inputs are
written to OUT_DIR. Needs nothing beyond Python 3.
"""
import argparse
import json
import math
import os
import random
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor


def read_poly(path):
    rows = [line.split('#')[0].split() for line in open(path)]
    rows = [r for r in rows if r]
    nv = int(rows[0][0])
    vertices = [(r[0], float(r[1]), float(r[2]), r[3:]) for r in rows[1:1 + nv]]
    ns = int(rows[1 + nv][0])
    segments = rows[2 + nv:2 + nv + ns]
    nh = int(rows[2 + nv + ns][0])
    holes = [(r[0], float(r[1]), float(r[2])) for r in rows[3 + nv + ns:3 + nv + ns + nh]]
    return rows[0], vertices, rows[1 + nv], segments, holes


def write_transformed(path, poly, move):
    header, vertices, segment_header, segments, holes = poly
    with open(path, 'w') as out:
        out.write(' '.join(header) + '\n')
        for i, x, y, rest in vertices:
            out.write('%s %.17g %.17g %s\n' % ((i,) + move(x, y) + (' '.join(rest),)))
        out.write(' '.join(segment_header) + '\n')
        for s in segments:
            out.write(' '.join(s) + '\n')
        out.write('%d\n' % len(holes))
        for i, x, y in holes:
            out.write('%s %.17g %.17g\n' % ((i,) + move(x, y)))


def write_loops(path, loops, holes, scale, turn, ox, oy):
    """Writes `loops` (and a hole point at each (x, y, r) of `holes`) scaled, turned and moved."""
    c, s = math.cos(turn), math.sin(turn)

    def move(x, y):
        return ox + scale * (c * x - s * y), oy + scale * (s * x + c * y)

    with open(path, 'w') as out:
        out.write('%d 2 0 0\n' % sum(len(loop) for loop in loops))
        k = 0
        for loop in loops:
            for x, y in loop:
                out.write('%d %r %r\n' % ((k,) + move(x, y)))
                k += 1
        out.write('%d 0\n' % k)
        k = 0
        for loop in loops:
            for i in range(len(loop)):
                out.write('%d %d %d\n' % (k + i, k + i, k + (i + 1) % len(loop)))
            k += len(loop)
        out.write('%d\n' % len(holes))
        for i, (x, y, _) in enumerate(holes):
            out.write('%d %r %r\n' % ((i,) + move(x, y)))
    return path


AIRFOILS = ['airfoil_30p30n', 'naca0012', 'naca0012_sharp']
TURNS = [11, 37, 59, 83, 101, 123, 149, 172]
SCALES = [1.0, 1.37, 3.1, 7.3]


def shared_poly(data_dir, name):
    """DATA_DIR/FOLDER/NAME.poly, FOLDER the one that holds it (naca0012_sharp is in naca0012)."""
    for folder in sorted(os.listdir(data_dir)):
        path = os.path.join(data_dir, folder, name + '.poly')
        if os.path.isfile(path):
            return path
    sys.exit('transform_sweep.py: no %s.poly in a folder of %s' % (name, data_dir))


def airfoil_inputs(data_dir, out_dir, names=AIRFOILS, turns=TURNS, scales=SCALES):
    inputs = []
    for name in names:
        poly = read_poly(shared_poly(data_dir, name))
        xs = [v[1] for v in poly[1]]
        ys = [v[2] for v in poly[1]]
        cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
        for degrees in turns:
            for scale in scales:
                c, s = scale * math.cos(math.radians(degrees)), scale * math.sin(math.radians(degrees))
                path = os.path.join(out_dir, '%s_turned%d_x%g.poly' % (name, degrees, scale))
                write_transformed(path, poly, lambda x, y: (cx + c * (x - cx) - s * (y - cy),
                                                            cy + s * (x - cx) + c * (y - cy)))
                inputs.append(path)
    return inputs


def arm_inputs(out_dir):
    def ell(w):
        return [(0, 0), (1, 0), (1, w), (w, w), (w, 1), (0, 1)]

    def cross(w):
        a = w / 2
        return [(-1, -a), (-a, -a), (-a, -1), (a, -1), (a, -a), (1, -a),
                (1, a), (a, a), (a, 1), (-a, 1), (-a, a), (-1, a)]

    def rectangle(w):
        return [(0, 0), (1, 0), (1, w), (0, w)]

    shapes = {'ell': ell, 'cross': cross, 'rectangle': rectangle}
    runs = [(name, w, k + 0.37) for name in ('rectangle', 'cross', 'ell')
            for w in (0.03, 0.07, 0.1, 0.13, 0.16, 0.21) for k in range(0, 46, 3)]
    runs += [(name, w, 20 + 1.5 * k + 0.37) for name in ('cross', 'ell')
             for w in (0.126, 0.13, 0.135, 0.14, 0.145, 0.15) for k in range(18)]
    inputs = []
    for name, w, degrees in runs:
        path = os.path.join(out_dir, '%s_%g_turned%g.poly' % (name, w, degrees))
        inputs.append(write_loops(path, [shapes[name](w)], [], 1, math.radians(degrees), 0, 0))
    return inputs


def blob_inputs(out_dir, count):
    def blob(cx, cy, r, terms, rng, n):
        amplitudes = [(rng.uniform(-0.12, 0.12) / (j ** 0.7), rng.uniform(0, 2 * math.pi))
                      for j in range(2, terms + 2)]
        points = []
        for i in range(n):
            t = 2 * math.pi * i / n
            radius = r * (1 + sum(a * math.cos(j * t + p) for j, (a, p) in enumerate(amplitudes, 2)))
            points.append((cx + radius * math.cos(t), cy + radius * math.sin(t)))
        return points

    inputs = []
    for seed in range(count):
        rng = random.Random(seed)
        scale = rng.choice([1, 3.7, 0.013, 250, 17])
        loops = [blob(0, 0, 1, rng.randint(2, 6), rng, rng.choice([200, 400, 800]))]
        holes = []
        for _ in range(rng.randint(0, 3)):
            for _ in range(50):
                cx, cy, r = rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(0.05, 0.25)
                apart = all(math.hypot(cx - x, cy - y) > r + q + 0.08 for x, y, q in holes)
                if apart and math.hypot(cx, cy) + r < 0.6:
                    holes.append((cx, cy, r))
                    break
        for cx, cy, r in holes:
            loops.append(blob(cx, cy, r, rng.randint(2, 4), rng, rng.choice([100, 200]))[::-1])
        turn = rng.uniform(0, 2 * math.pi)
        ox, oy = rng.uniform(-10, 10), rng.uniform(-10, 10)
        inputs.append(write_loops(os.path.join(out_dir, 'blob_%d.poly' % seed), loops, holes, scale, turn, ox, oy))
    return inputs


def star_inputs(out_dir):
    def star(cx, cy, r, corners, rng, jitter):
        points = []
        for i in range(corners):
            t = 2 * math.pi * (i + rng.uniform(-0.3, 0.3)) / corners
            radius = r * rng.uniform(1 - jitter, 1)
            points.append((cx + radius * math.cos(t), cy + radius * math.sin(t)))
        return points

    inputs = []
    for seed in range(200):
        rng = random.Random(seed)
        jitter = rng.uniform(0.1, 0.6)
        loops = [star(0, 0, 1, rng.randint(6, 40), rng, jitter)]
        holes = []
        for _ in range(rng.randint(0, 2)):
            for _ in range(50):
                cx, cy, r = rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(0.05, 0.15)
                apart = all(math.hypot(cx - x, cy - y) > r + q + 0.05 for x, y, q in holes)
                if apart and math.hypot(cx, cy) + r < 0.9 * (1 - jitter):
                    holes.append((cx, cy, r))
                    break
        for cx, cy, r in holes:
            loops.append(star(cx, cy, r, rng.randint(5, 12), rng, 0.3)[::-1])
        inputs.append(write_loops(os.path.join(out_dir, 'star_%d.poly' % seed), loops, holes,
                                  rng.choice([1, 7.3, 0.01, 130]), rng.uniform(0, 2 * math.pi), 0, 0))
    return inputs


QUADS_OUT = 4  # the tool's exit status for a mesh written with unforced angles out


def mesh(mesher, path, templates_too=False):
    stem = path[:-len('.poly')]
    run = subprocess.run([mesher, path, '-o', stem + '.msh', '--report', stem + '.json'],
                         capture_output=True, text=True)
    if run.returncode not in (0, QUADS_OUT):
        return path, None, run.stderr.strip().splitlines()[-1:]
    report = json.load(open(stem + '.json'))
    if templates_too:
        run = subprocess.run([mesher, path, '--stop-after', 'templates', '-o', stem + '.core.msh',
                              '--report', stem + '.core.json'], capture_output=True, text=True)
        if run.returncode != 0:
            return path, None, run.stderr.strip().splitlines()[-1:]
        report['lemma_2_misses'] = json.load(open(stem + '.core.json'))['buffer']['buffer_angles_out']
    return path, report, []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('mesher')
    parser.add_argument('data_dir')
    parser.add_argument('out_dir')
    parser.add_argument('set', choices=['airfoils', 'arms', 'blobs', 'stars'])
    parser.add_argument('--jobs', type=int, default=1)
    parser.add_argument('--blobs', type=int, default=80, help='how many blobs (seeds 0 to N-1)')
    parser.add_argument('--airfoils', default=','.join(AIRFOILS), help='airfoils: the shared cases, by file name')
    parser.add_argument('--turns', help='airfoils: degrees FIRST:LAST:STEP (default %s)' % TURNS)
    parser.add_argument('--scales', default=','.join('%g' % s for s in SCALES), help='airfoils: the scales')
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    turns = TURNS
    if args.turns:
        first, last, step = (int(t) for t in args.turns.split(':'))
        turns = list(range(first, last + 1, step))
    inputs = {'airfoils': lambda: airfoil_inputs(args.data_dir, args.out_dir, args.airfoils.split(','), turns,
                                                 [float(x) for x in args.scales.split(',')]),
              'arms': lambda: arm_inputs(args.out_dir),
              'blobs': lambda: blob_inputs(args.out_dir, args.blobs), 'stars': lambda: star_inputs(args.out_dir)}[args.set]()
    with_out = failed = quads = misses = 0
    with ThreadPoolExecutor(args.jobs) as pool:
        for path, report, error in pool.map(lambda p: mesh(args.mesher, p, args.set == 'blobs'), inputs):
            name = os.path.basename(path)
            if report is None:
                failed += 1
                print('%s: failed: %s' % (name, ' '.join(error)))
                continue
            quads += report['quads']
            out = report['buffer']['quads_outside_45_135_not_forced']
            if out > 0:
                with_out += 1
                print('%s: %d quads out, angles [%.2f, %.2f], rounds end: %s'
                      % (name, out, report['min_angle'], report['max_angle'], report['buffer'].get('rounds_end')))
            if report.get('lemma_2_misses', 0) > 0:
                misses += report['lemma_2_misses']
                print('%s: %d buffer-side angles outside [112.5, 225] after the templates'
                      % (name, report['lemma_2_misses']))
            sys.stdout.flush()
    print('%d runs, %d with quads out, %d failed, %d quads' % (len(inputs), with_out, failed, quads)
          + (', %d Lemma 2 misses' % misses if args.set == 'blobs' else ''))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
