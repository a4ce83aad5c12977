#!/usr/bin/python3
"""junction_sweep.py -- random domains cut into faces that meet at junctions (issue 27).

Usage:
    junction_sweep.py QUAD_MESHER OUT_DIR --seed S --count N [--kinds star,twoopt,convex]
                      [--min-corner 45] [--jobs 2] [--timeout 60] [--verifier PATH] [--keep-meshes]

Domain i is random_domains.py's domain i of seed S cut by one to three random cuts
(OUT_DIR/junctions_<kind>_<S>_<i>.poly): each cut runs from a hub, a random point inside the
domain, straight to two or three vertices of its loops (a kinked chord through the domain, or
a Y whose hub is a junction of three segments), so the vertices it ends on become junctions
of three segments or more. Cuts keep 2% of the domain's diameter from each other and from the
loops but at their ends; their ends are distinct. The faces are regions meshed together,
sharing the nodes of every cut. The corner between a cut and a loop's edge at its end may be
sharp: the runs are tabled by the sharpest corner of any face at a junction (under 45
degrees, the corner's quad keeps it; interface corners under 45 degrees are the open case of
the issue). Each domain is meshed and verified as random_sweep.py does (`verify_mesh.py
--domain --no-overlap --excuse-above 360`: `constraints_present` checks that every cut
segment is a chain of mesh edges). Writes OUT_DIR/results.csv and copies the inputs that do
not pass into OUT_DIR/failing/. Needs Debian's python3-numpy, python3-shapely (and the
verifier's python3-scipy and python3-meshio); run with /usr/bin/python3.
"""
import os
import sys

import numpy as np
from shapely.geometry import LineString, Point, Polygon

import random_domains
import random_sweep

CSV_FIELDS = ('file', 'kind', 'shape', 'outer_vertices', 'holes', 'cuts', 'junctions', 'sharpest_junction_corner',
              'corner_class', 'outcome', 'exit', 'seconds', 'quads', 'mesher_unforced_quads',
              'verifier_unexcused_angles', 'failed_checks', 'message')
MAX_TRIES = 1000
CLEARANCE = 0.02  # of the diameter, between a cut and anything it does not end on


def sharpest_corner_at(domain, point, directions):
    """The smallest angle between consecutive `directions` (vectors) around `point` that
    opens into `domain`."""
    angles = sorted(np.degrees(np.arctan2(d[1], d[0])) % 360.0 for d in directions)
    reach = 1e-6 * min(np.hypot(d[0], d[1]) for d in directions)
    sharpest = 360.0
    for a, b in zip(angles, angles[1:] + [angles[0] + 360.0]):
        middle = np.radians(0.5 * (a + b))
        if domain.contains(Point(point[0] + reach * np.cos(middle), point[1] + reach * np.sin(middle))):
            sharpest = min(sharpest, b - a)
    return sharpest


def random_cut(rng, domain, loops, taken, cuts, diameter, min_corner):
    """A hub inside `domain` and two or three loop vertices not in `taken`, joined to it by
    straight spokes that keep clear of the loops and the other `cuts`: (hub, ends), or None."""
    hub = random_domains.random_point_in(rng, domain)
    if hub is None:
        return None
    hub = np.array([hub.x, hub.y])
    candidates = [tuple(v) for loop in loops for v in loop if tuple(v) not in taken]
    if len(candidates) < 3:
        return None
    picks = rng.choice(len(candidates), size=int(rng.integers(2, 4)), replace=False)
    ends = [np.array(candidates[k]) for k in picks]
    clearance = CLEARANCE * diameter
    boundary = domain.boundary
    spokes = []
    for end in ends:
        spoke = LineString([hub, end])
        # the spoke but its last 3 clearances, where it meets the edges at its end
        inner = LineString([hub, end + 3 * clearance / spoke.length * (hub - end)]) if spoke.length > 6 * clearance else None
        if inner is None or not domain.contains(spoke) or inner.distance(boundary) < clearance:
            return None
        if any(spoke.distance(LineString(other)) < clearance for cut in cuts for other in cut):
            return None
        spokes.append((hub, end))
    for i in range(len(spokes)):  # spokes leave the hub apart
        for j in range(i + 1, len(spokes)):
            if LineString(spokes[i]).distance(Point(spokes[j][1])) < clearance:
                return None
    if sharpest_junction_corner(domain, loops, cuts + [spokes]) < min_corner:
        return None
    return spokes


def loop_neighbours(loops, vertex):
    """The directions from `vertex` to its neighbours along the loops it lies on."""
    out = []
    for loop in loops:
        for k, v in enumerate(loop):
            if tuple(v) == vertex:
                out += [np.array(loop[k - 1]) - v, np.array(loop[(k + 1) % len(loop)]) - v]
    return out


def sharpest_junction_corner(domain, loops, cuts):
    """The smallest corner between segments at any junction of the cut domain, degrees."""
    sharpest = 360.0
    ends = {}
    for cut in cuts:
        hub = tuple(cut[0][0])
        ends.setdefault(hub, [])
        for h, end in cut:
            ends[hub].append(np.array(end) - np.array(h))
            ends.setdefault(tuple(end), []).append(np.array(h) - np.array(end))
    for point, directions in ends.items():
        around = directions + loop_neighbours(loops, point)
        if len(around) >= 2:
            sharpest = min(sharpest, sharpest_corner_at(domain, point, around))
    return sharpest


def write_junctions(out_dir, seed, index, kinds, min_corner):
    """Draws domain `index` of `seed` and writes it with its cuts: (path, how it was made)."""
    kind = kinds[index % len(kinds)]
    rng = np.random.default_rng([seed, index])
    outer, holes, points, made = random_domains.random_domain(rng, kind)
    loops = [np.asarray(outer)] + [np.asarray(h) for h in holes]
    domain = Polygon(outer, holes)
    diameter = random_domains.diameter(outer)
    wanted = int(rng.integers(1, 4))
    cuts, taken = [], set()
    for _ in range(MAX_TRIES):
        if len(cuts) == wanted:
            break
        cut = random_cut(rng, domain, loops, taken, cuts, diameter, min_corner)
        if cut is not None:
            cuts.append(cut)
            taken.update(tuple(end) for _, end in cut)
    corner = sharpest_junction_corner(domain, loops, cuts)
    made = dict(made, cuts=len(cuts), junctions=sum(len(c) for c in cuts) + sum(len(c) == 3 for c in cuts),
                sharpest_junction_corner='%.1f' % corner,
                corner_class='all corners >= 45' if corner >= 45.0 else 'a corner < 45')
    path = os.path.join(out_dir, 'junctions_%s_%d_%d.poly' % (kind, seed, index))
    how = ('junction_sweep.py --seed %d, domain %d: loops outer first (CCW), holes CW, then %d cuts (spokes from a '
           'hub to loop vertices), marker = loop or spoke id' % (seed, index, len(cuts)))
    spokes = [np.array([hub, end]) for cut in cuts for hub, end in cut]
    random_domains.write_poly(path, [outer] + holes, points, [random_domains.description(made), how], spokes)
    return path, made


def main():
    return random_sweep.sweep_written_domains(
        __doc__, write_junctions, CSV_FIELDS, [('kind', 'kind'), ('corner_class', 'sharpest corner at a junction')],
        options=[('--min-corner', dict(type=float, default=45.0,
                                       help='degrees a corner at a junction must reach (default %(default)s)'))])


if __name__ == '__main__':
    sys.exit(main())
