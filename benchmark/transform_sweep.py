#!/usr/bin/python3
"""transform_sweep.py -- the angle guarantee under rotations and scalings, case by case.

Usage:
    transform_sweep.py QUAD_MESHER DATA_DIR OUT_DIR {airfoils,arms} [--jobs N]

Meshes each input with `QUAD_MESHER IN.poly -o OUT.msh --report OUT.json` and counts the quads
the report gives as having an angle outside [45, 135] that no input corner forces
(`buffer.quads_outside_45_135_not_forced`). A mesh is right or wrong in its given position
only, so the guarantee is judged over many positions:
  * airfoils: DATA_DIR's airfoil_30p30n, naca0012 and naca0012_sharp, each turned about its
    points' centroid by 11, 37, 59, 83, 101, 123, 149 and 172 degrees and scaled by 1, 1.37,
    3.1 and 7.3 (96 runs: air foils at angles of attack);
  * arms: an L, a cross and a rectangle with arms 0.03 to 0.21 wide turned 0.37 to 45.37
    degrees, and an L and a cross 0.126 to 0.15 wide turned 20.37 to 45.87 degrees (504 runs:
    narrow regions across the quadtree's axes).
Prints each run with quads out (or a failed exit) and a summary line: runs, runs with quads
out, failed runs, quads in all. The transformed inputs are written to OUT_DIR. Needs nothing
beyond Python 3.
"""
import argparse
import json
import math
import os
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


def write_loop(path, points):
    n = len(points)
    with open(path, 'w') as out:
        out.write('%d 2 0 0\n' % n)
        for k, (x, y) in enumerate(points):
            out.write('%d %.17g %.17g\n' % (k + 1, x, y))
        out.write('%d 0\n' % n)
        for k in range(n):
            out.write('%d %d %d\n' % (k + 1, k + 1, (k + 1) % n + 1))
        out.write('0\n')


def airfoil_inputs(data_dir, out_dir):
    cases = [('airfoil_30p30n', 'airfoil_30p30n'), ('naca0012', 'naca0012'), ('naca0012', 'naca0012_sharp')]
    inputs = []
    for folder, name in cases:
        poly = read_poly(os.path.join(data_dir, folder, name + '.poly'))
        xs = [v[1] for v in poly[1]]
        ys = [v[2] for v in poly[1]]
        cx, cy = sum(xs) / len(xs), sum(ys) / len(ys)
        for degrees in (11, 37, 59, 83, 101, 123, 149, 172):
            for scale in (1.0, 1.37, 3.1, 7.3):
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
        c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
        path = os.path.join(out_dir, '%s_%g_turned%g.poly' % (name, w, degrees))
        write_loop(path, [(c * x - s * y, s * x + c * y) for x, y in shapes[name](w)])
        inputs.append(path)
    return inputs


def mesh(mesher, path):
    stem = path[:-len('.poly')]
    run = subprocess.run([mesher, path, '-o', stem + '.msh', '--report', stem + '.json'],
                         capture_output=True, text=True)
    if run.returncode != 0:
        return path, None, run.stderr.strip().splitlines()[-1:]
    report = json.load(open(stem + '.json'))
    return path, report, []


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('mesher')
    parser.add_argument('data_dir')
    parser.add_argument('out_dir')
    parser.add_argument('set', choices=['airfoils', 'arms'])
    parser.add_argument('--jobs', type=int, default=1)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    inputs = airfoil_inputs(args.data_dir, args.out_dir) if args.set == 'airfoils' else arm_inputs(args.out_dir)
    with_out = failed = quads = 0
    with ThreadPoolExecutor(args.jobs) as pool:
        for path, report, error in pool.map(lambda p: mesh(args.mesher, p), inputs):
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
            sys.stdout.flush()
    print('%d runs, %d with quads out, %d failed, %d quads' % (len(inputs), with_out, failed, quads))
    return 1 if failed else 0


if __name__ == '__main__':
    sys.exit(main())
