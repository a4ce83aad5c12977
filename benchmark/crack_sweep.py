#!/usr/bin/python3
"""crack_sweep.py -- cracks on random domains: open polylines kept as mesh edges (issue 27).

Usage:
    crack_sweep.py QUAD_MESHER OUT_DIR --seed S --count N [--kinds star,twoopt,convex]
                   [--jobs 2] [--timeout 60] [--verifier PATH] [--keep-meshes]

Domain i is random_domains.py's domain i of seed S with one to three random cracks added
(OUT_DIR/cracks_<kind>_<S>_<i>.poly): open polylines of one to four segments, each 4% to 15%
of the domain's diameter long, turning by at most `MAX_TURN` degrees at a kink (so that either
side's corner is 45 degrees or more), kept a tenth of their length from the boundary and from
each other. Each is meshed and verified as random_sweep.py does (`verify_mesh.py --domain
--no-overlap --excuse-above 360`: `constraints_present` checks that every crack segment is a
chain of mesh edges). The runs are tabled by kind and by the number of crack segments.
Writes OUT_DIR/results.csv and copies the inputs that do not pass into OUT_DIR/failing/.
Needs Debian's python3-numpy, python3-shapely (and the verifier's python3-scipy and
python3-meshio); run with /usr/bin/python3.
"""
import os
import sys

import numpy as np
from shapely.geometry import LineString, Polygon

import random_domains
import random_sweep

CSV_FIELDS = ('file', 'kind', 'shape', 'outer_vertices', 'holes', 'cracks', 'crack_segments', 'outcome', 'exit',
              'seconds', 'quads', 'mesher_unforced_quads', 'verifier_unexcused_angles', 'failed_checks', 'message')
MAX_TURN = 135.0  # degrees a crack may turn at a kink: its corners are then 45 degrees or more on either side
MAX_TRIES = 200


def random_crack(rng, domain, others, diameter):
    """An open polyline in `domain` (a shapely polygon) apart from the `others`, or None."""
    segments = int(rng.integers(1, 5))
    start = random_domains.random_point_in(rng, domain)
    if start is None:
        return None
    points = [np.array([start.x, start.y])]
    heading = rng.uniform(0, 2 * np.pi)
    for k in range(segments):
        if k > 0:
            heading += np.radians(rng.uniform(-MAX_TURN, MAX_TURN))
        length = rng.uniform(0.04, 0.15) * diameter
        points.append(points[-1] + length * np.array([np.cos(heading), np.sin(heading)]))
    line = LineString(points)
    clearance = 0.1 * line.length
    if not line.is_simple or not domain.buffer(-clearance).contains(line):
        return None
    if any(line.distance(other) < clearance for other in others):
        return None
    return np.array(points)


def write_cracks(out_dir, seed, index, kinds):
    """Draws domain `index` of `seed` and writes it with its cracks: (path, how it was made)."""
    kind = kinds[index % len(kinds)]
    rng = np.random.default_rng([seed, index])
    outer, holes, points, made = random_domains.random_domain(rng, kind)
    domain = Polygon(outer, holes)
    diameter = random_domains.diameter(outer)
    wanted = int(rng.integers(1, 4))
    cracks = []
    for _ in range(MAX_TRIES):
        if len(cracks) == wanted:
            break
        crack = random_crack(rng, domain, [LineString(c) for c in cracks], diameter)
        if crack is not None:
            cracks.append(crack)
    made = dict(made, cracks=len(cracks), crack_segments=sum(len(c) - 1 for c in cracks))
    path = os.path.join(out_dir, 'cracks_%s_%d_%d.poly' % (kind, seed, index))
    how = ('crack_sweep.py --seed %d, domain %d: loops outer first (CCW), holes CW, then %d cracks (open polylines), '
           'marker = loop or crack id' % (seed, index, len(cracks)))
    random_domains.write_poly(path, [outer] + holes, points, [random_domains.description(made), how], cracks)
    return path, made


def main():
    return random_sweep.sweep_written_domains(__doc__, write_cracks, CSV_FIELDS,
                                              [('kind', 'kind'), ('crack_segments', 'crack segments')])


if __name__ == '__main__':
    sys.exit(main())
