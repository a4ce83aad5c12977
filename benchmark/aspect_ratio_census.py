#!/usr/bin/python3
"""aspect_ratio_census.py -- the quads over an aspect ratio, and whether an input corner forces them.

Usage:
    aspect_ratio_census.py DIR [DIR ...] [--over 5]

For every DIR/NAME.msh with its input DIR/NAME.poly beside it (what transform_sweep.py and
random_sweep.py leave in their OUT_DIR; `.core.` meshes are left out), counts the quads whose
longest edge is more than --over (default 5) times their shortest, in two kinds: those with a
corner at an input vertex whose two segments meet at under 45 degrees (on either side: a
sharp corner or a reflex one over 315 degrees; the input forces a thin quad there), and the
others (issue 26 asks for none of these). Prints per DIR the quads and runs of each kind and
the largest ratio of each, and with -v every such quad. Needs meshio and numpy (Debian's
python3-meshio, python3-numpy).
"""
import argparse
import contextlib
import glob
import io
import math
import os

import meshio
import numpy as np

import transform_sweep  # beside this script: its .poly reader


def read_poly(path):
    """the input's points (an array) and its segments (pairs of indices into it)"""
    _, vertices, _, segments, _ = transform_sweep.read_poly(path)
    index = {label: k for k, (label, _, _, _) in enumerate(vertices)}
    return (np.array([[x, y] for _, x, y, _ in vertices]),
            [(index[r[1]], index[r[2]]) for r in segments])


def sharp_input_vertices(points, segments):
    """{(x, y)} of the input vertices whose two segments meet at under 45 degrees"""
    neighbours = {}
    for a, b in segments:
        neighbours.setdefault(a, []).append(b)
        neighbours.setdefault(b, []).append(a)
    sharp = set()
    for v, nb in neighbours.items():
        if len(nb) != 2:
            continue
        u, w = points[nb[0]] - points[v], points[nb[1]] - points[v]
        cos = np.dot(u, w) / (np.linalg.norm(u) * np.linalg.norm(w))
        if math.degrees(math.acos(max(-1.0, min(1.0, cos)))) < 45:
            sharp.add((points[v][0], points[v][1]))
    return sharp


def census(msh, poly, over):
    """(ratio, centre, forced) of each quad over the ratio"""
    with contextlib.redirect_stdout(io.StringIO()):  # meshio's reader prints blank lines
        mesh = meshio.read(msh)
    xy = mesh.points[:, :2]
    quads = np.concatenate([c.data for c in mesh.cells if c.type.startswith('quad')])
    corners = xy[quads]
    edges = np.linalg.norm(np.roll(corners, -1, axis=1) - corners, axis=2)
    ratio = edges.max(axis=1) / edges.min(axis=1)
    sharp = sharp_input_vertices(*read_poly(poly))
    found = []
    for q in np.where(ratio > over)[0]:
        forced = any((p[0], p[1]) in sharp for p in corners[q])
        found.append((ratio[q], corners[q].mean(axis=0), forced))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('dirs', nargs='+')
    parser.add_argument('--over', type=float, default=5.0)
    parser.add_argument('-v', '--verbose', action='store_true')
    args = parser.parse_args()
    for d in args.dirs:
        kinds = {True: [0, set(), 0.0], False: [0, set(), 0.0]}
        runs = 0
        for msh in sorted(glob.glob(os.path.join(d, '*.msh'))):
            poly = msh[:-len('.msh')] + '.poly'
            if '.core.' in msh or not os.path.exists(poly):
                continue
            runs += 1
            name = os.path.basename(msh)[:-len('.msh')]
            for ratio, centre, forced in census(msh, poly, args.over):
                kind = kinds[forced]
                kind[0] += 1
                kind[1].add(name)
                kind[2] = max(kind[2], ratio)
                if args.verbose:
                    print('%s: %.2f at (%.6g, %.6g)%s' % (name, ratio, centre[0], centre[1],
                                                        ', at a sharp input corner' if forced else ''))
        for forced, label in ((False, 'not at a sharp input corner'), (True, 'at a sharp input corner')):
            n, names, worst = kinds[forced]
            print('%s: %d runs; %d quads over %g in %d runs %s (largest %.2f)'
                  % (d, runs, n, args.over, len(names), label, worst))


if __name__ == '__main__':
    main()
