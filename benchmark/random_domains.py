#!/usr/bin/python3
"""random_domains.py -- seeded random valid domains, the inputs a user meets (issue 24).

Usage:
    random_domains.py OUT_DIR --seed S --count N [--kinds star,twoopt,convex,rectilinear]

Writes N domains OUT_DIR/<kind>_<S>_<i>.poly (i = 0 to N-1, the kind cycling through --kinds)
in Triangle's .poly format: 1-based, full double precision, vertex and segment marker = loop
id, the outer loop first and counter-clockwise, holes clockwise, one hole point inside each
hole. Domain i is drawn from numpy.random.default_rng([S, i]) alone: it is the same whatever N
is, and rerunning with the same seed rewrites the same files. Each file's first line says how
it was made. A domain is:
  * an outer loop of its kind, inside the square [-1, 1]^2:
      star:   3 to 200 corners at jittered angles, radii jittered in [0.3, 1] or [0.05, 1];
      twoopt: 3 to 60 random points joined in a random order, untangled by 2-opt moves
              until simple (digitised shapes);
      convex: 3 to 100 corners (Valtr's random convex polygon), stretched up to 10 times
              and turned;
      rectilinear (only when asked for): the outline of 3 to 15 random axis-aligned
              rectangles of sides 0.03 to 0.5 about the origin, turned in half the domains (CAD parts: steps,
              slots and thin walls of every width);
  * with it, in 3 domains out of 5, one feature: a spike (outward) or a notch (inward) of
    1 to 5 degrees, a near-collinear run (3 to 10 points off an edge by 1e-12 to 1e-4 of its
    length) or a short edge (a corner cut 1e-6 to 1e-2 of its shorter edge from it);
  * 0 to 5 star holes of 3 to 30 corners, strictly inside the outer loop and apart from it
    and from each other by at least 2% of the outer loop's bounding-box diagonal;
  * scaled by 10^U(-6, 6) and, in 2 domains out of 3, moved by up to 1e7 in x and y (but
    at most 1e6 times the scale, so that the domain spans at least 1e-6 of its coordinates).
The domain is checked with shapely on its written coordinates (each loop simple, no point
twice, the holes strictly inside the outer loop and disjoint, each hole point strictly inside
its hole) and drawn again, from the same generator, until it passes.
Needs Debian's python3-numpy and python3-shapely; run with /usr/bin/python3.
"""
import argparse
import os
import sys

import numpy as np
from shapely.geometry import LinearRing, Point, Polygon, box
from shapely.ops import unary_union

KINDS = ('star', 'twoopt', 'convex')  # the default; drawn in turn, so seeds stay reproducible
ALL_KINDS = KINDS + ('rectilinear',)
FEATURES = ('none', 'spike', 'notch', 'collinear', 'short_edge')
FEATURE_CHANCES = (0.4, 0.15, 0.15, 0.15, 0.15)
HOLE_GAP = 0.02            # least gap between loops, times the outer loop's bbox diagonal
MAX_OFFSET_PER_SCALE = 1e6
MAX_ATTEMPTS = 1000


def signed_area(loop):
    x, y = loop[:, 0], loop[:, 1]
    return 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)


def counter_clockwise(loop):
    return loop if signed_area(loop) > 0 else loop[::-1].copy()


def fit_in_unit_square(loop):
    """The loop centred on its bounding box and scaled to fit [-1, 1]^2."""
    lo, hi = loop.min(axis=0), loop.max(axis=0)
    return (loop - (lo + hi) / 2) / (np.max(hi - lo) / 2)


def star_loop(rng, corners, low_radius, centre=(0.0, 0.0), radius=1.0):
    """Corners at jittered angles (in order) and radii in [low_radius, 1] times radius; CCW."""
    t = 2 * np.pi * (np.arange(corners) + rng.uniform(-0.4, 0.4, corners)) / corners
    r = radius * rng.uniform(low_radius, 1.0, corners)
    return counter_clockwise(np.column_stack([centre[0] + r * np.cos(t), centre[1] + r * np.sin(t)]))


def edges_crossing(points, i):
    """Indices j > i + 1 of the edges (j, j + 1) of the closed polyline that cross edge (i, i + 1)."""
    n = len(points)
    a, b = points[i], points[(i + 1) % n]
    j = np.arange(i + 2, n - (i == 0))
    c, d = points[j], points[(j + 1) % n]

    def side(p, q, r):
        return np.sign((q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1])
                       - (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0]))

    crossing = (side(a, b, c) * side(a, b, d) < 0) & (side(c, d, a) * side(c, d, b) < 0)
    return j[crossing]


def twoopt_loop(rng, corners):
    """Random points in a random order, each crossing undone by reversing the path between
    the two edges (a 2-opt move, which shortens the loop) until none is left; CCW."""
    points = rng.uniform(-1.0, 1.0, (corners, 2))
    untangled = False
    while not untangled:
        untangled = True
        for i in range(corners - 2):
            crossing = edges_crossing(points, i)
            if len(crossing):
                j = crossing[0]
                points[i + 1:j + 1] = points[i + 1:j + 1][::-1].copy()
                untangled = False
    return counter_clockwise(points)


def valtr_steps(rng, coordinates):
    """Valtr's split of sorted random coordinates into two chains from the least to the
    greatest: the steps along one chain and back along the other (they add up to 0)."""
    v = np.sort(coordinates)
    on_first = rng.random(len(v) - 2) < 0.5
    first = np.concatenate([[v[0]], v[1:-1][on_first], [v[-1]]])
    second = np.concatenate([[v[0]], v[1:-1][~on_first], [v[-1]]])
    return np.concatenate([np.diff(first), -np.diff(second)])


def convex_loop(rng, corners):
    """Valtr's uniformly random convex polygon, stretched by up to 10 and turned; CCW."""
    steps = np.column_stack([valtr_steps(rng, rng.random(corners)),
                             rng.permutation(valtr_steps(rng, rng.random(corners)))])
    steps = steps[np.argsort(np.arctan2(steps[:, 1], steps[:, 0]))]
    loop = np.cumsum(steps, axis=0) * [10 ** rng.uniform(0, 1), 1.0]
    turn = rng.uniform(0, 2 * np.pi)
    c, s = np.cos(turn), np.sin(turn)
    return counter_clockwise(loop @ np.array([[c, s], [-s, c]]))


def rectilinear_loop(rng, rectangles):
    """The outer boundary of the largest piece of a union of random axis-aligned rectangles,
    without its collinear points, turned in half the draws; CCW."""
    while True:
        corners = rng.uniform(-0.5, 0.5, (rectangles, 2))
        sides = 10 ** rng.uniform(-1.5, -0.3, (rectangles, 2))
        union = unary_union([box(x, y, x + w, y + h) for (x, y), (w, h) in zip(corners, sides)])
        piece = max(getattr(union, 'geoms', [union]), key=lambda g: g.area)
        loop = np.array(piece.simplify(0).exterior.coords[:-1])
        if len(loop) >= 4:
            break
    if rng.random() < 0.5:
        turn = rng.uniform(0, 2 * np.pi)
        c, s = np.cos(turn), np.sin(turn)
        loop = loop @ np.array([[c, s], [-s, c]])
    return counter_clockwise(loop)


def outer_loop(rng, kind):
    """The outer loop of a domain of the given kind, in [-1, 1]^2, and its description."""
    if kind == 'star':
        corners, low = int(rng.integers(3, 201)), float(rng.choice([0.3, 0.05]))
        return fit_in_unit_square(star_loop(rng, corners, low)), 'radii %g-1' % low
    if kind == 'twoopt':
        return fit_in_unit_square(twoopt_loop(rng, int(rng.integers(3, 61)))), '2-opt'
    if kind == 'rectilinear':
        return fit_in_unit_square(rectilinear_loop(rng, int(rng.integers(3, 16)))), 'rectangles'
    return fit_in_unit_square(convex_loop(rng, int(rng.integers(3, 101)))), 'Valtr'


def edge_frame(loop, k):
    """Start, direction (unit), length and outward normal of edge (k, k + 1) of a CCW loop."""
    a, b = loop[k], loop[(k + 1) % len(loop)]
    length = np.hypot(*(b - a))
    d = (b - a) / length
    return a, d, length, np.array([d[1], -d[0]])


def insert_after(loop, k, points):
    return np.concatenate([loop[:k + 1], points, loop[k + 1:]])


def with_spike(rng, loop, inward):
    """A thin triangle of apex 1 to 5 degrees and height 0.5 to 5 times the edge's length
    (at most 0.5) on the middle part of a random edge, outward (a spike: a sharp domain
    corner) or inward (a notch: a domain corner of 355 to 359 degrees)."""
    k = int(rng.integers(len(loop)))
    a, d, length, normal = edge_frame(loop, k)
    apex = np.radians(rng.uniform(1, 5))
    height = min(rng.uniform(0.5, 5) * length, 0.5)
    width = 2 * height * np.tan(apex / 2)
    base = a + rng.uniform(0.35, 0.65) * length * d
    tip = base + (-height if inward else height) * normal
    feature = '%s of %.3g deg' % ('notch' if inward else 'spike', np.degrees(apex))
    return insert_after(loop, k, [base - width / 2 * d, tip, base + width / 2 * d]), feature


def with_collinear_run(rng, loop):
    """3 to 10 points along a random edge, each off it by 0.5 to 1 times a relative offset
    of 1e-12 to 1e-4 of its length, to either side."""
    k = int(rng.integers(len(loop)))
    a, d, length, normal = edge_frame(loop, k)
    count, offset = int(rng.integers(3, 11)), 10 ** rng.uniform(-12, -4)
    along = np.sort(rng.uniform(0.05, 0.95, count))
    off = offset * rng.uniform(0.5, 1, count) * rng.choice([-1, 1], count)
    points = a + length * (along[:, None] * d + off[:, None] * normal)
    return insert_after(loop, k, points), 'collinear run of %d, offset %.2g' % (count, offset)


def with_short_edge(rng, loop):
    """A random corner cut off by a short edge: its two new ends lie 1e-6 to 1e-2 of the
    corner's shorter edge from it."""
    k = int(rng.integers(len(loop)))
    v = loop[k]
    sides = [loop[k - 1] - v, loop[(k + 1) % len(loop)] - v]
    lengths = [np.hypot(*side) for side in sides]
    share = 10 ** rng.uniform(-6, -2)
    ends = [v + share * min(lengths) * side / length for side, length in zip(sides, lengths)]
    return (np.concatenate([loop[:k], ends, loop[k + 1:]]),
            'short edge: a corner cut %.2g of its shorter side from it' % share)


def with_feature(rng, loop, feature):
    """The loop with the feature and its description."""
    if feature == 'spike' or feature == 'notch':
        return with_spike(rng, loop, feature == 'notch')
    if feature == 'collinear':
        return with_collinear_run(rng, loop)
    if feature == 'short_edge':
        return with_short_edge(rng, loop)
    return loop, 'no feature'


def with_random_feature(rng, loop, tries=20):
    """The loop with one random feature (or none), placed again until the loop stays simple:
    (loop, feature, its description), or (None, feature, None) if `tries` placements fail."""
    feature = str(rng.choice(FEATURES, p=FEATURE_CHANCES))
    for _ in range(tries):
        featured, description = with_feature(rng, loop, feature)
        if LinearRing(featured).is_simple:
            return featured, feature, description
    return None, feature, None


def random_point_in(rng, region, tries=1000):
    """A uniformly random point of the region, or None if `tries` draws in its bounds miss it."""
    lo_x, lo_y, hi_x, hi_y = region.bounds
    for _ in range(tries):
        p = Point(rng.uniform(lo_x, hi_x), rng.uniform(lo_y, hi_y))
        if region.contains(p):
            return p
    return None


def star_holes(rng, outer):
    """0 to 5 star holes (CW), each in a disc that keeps the gap to the outer loop and to the
    holes before it, of radius 0.3 to 0.9 times the room there (at most 0.3) and at least 0.3
    times the gap; a hole is left out when 50 tries find no room."""
    lo, hi = outer.min(axis=0), outer.max(axis=0)
    gap = HOLE_GAP * np.hypot(*(hi - lo))
    room = Polygon(outer).buffer(-gap)
    holes = []
    for _ in range(int(rng.integers(0, 6)) if not room.is_empty else 0):
        for _ in range(50):
            centre = random_point_in(rng, room)
            if centre is None:
                break
            free = min([room.boundary.distance(centre)] + [Polygon(h).distance(centre) - gap for h in holes])
            if free > gap:
                radius = min(free, 0.3) * rng.uniform(0.3, 0.9)
                hole = star_loop(rng, int(rng.integers(3, 31)), 0.3, (centre.x, centre.y), radius)
                holes.append(hole[::-1].copy())
                break
    return holes


def scale_and_offset(rng):
    scale = 10 ** rng.uniform(-6, 6)
    reach = min(1e7, MAX_OFFSET_PER_SCALE * scale) if rng.random() < 2 / 3 else 0.0
    return scale, rng.uniform(-reach, reach, 2)


def hole_points(holes):
    """A point strictly inside each hole (shapely's representative point, checked)."""
    points = [Polygon(h).representative_point() for h in holes]
    return [(p.x, p.y) for p in points], all(Polygon(h).contains(p) for h, p in zip(holes, points))


def is_valid_domain(outer, holes):
    """True if every loop is simple and oriented (outer CCW, holes CW), no point is given
    twice and the holes lie strictly inside the outer loop and apart from each other."""
    loops = [outer] + holes
    every = np.concatenate(loops)
    if len(np.unique(every, axis=0)) < len(every):
        return False
    if not all(LinearRing(loop).is_valid and LinearRing(loop).is_simple for loop in loops):
        return False
    if not LinearRing(outer).is_ccw or any(LinearRing(h).is_ccw for h in holes):
        return False
    outline = Polygon(outer)
    hole_polygons = [Polygon(h) for h in holes]
    if not all(outline.contains(h) and h.distance(outline.exterior) > 0 for h in hole_polygons):
        return False
    return all(h.distance(g) > 0 for i, h in enumerate(hole_polygons) for g in hole_polygons[:i])


def random_domain(rng, kind):
    """A valid domain: (outer loop, holes, hole points, how it was made: a dict)."""
    for attempt in range(1, MAX_ATTEMPTS + 1):
        outer, shape = outer_loop(rng, kind)
        outer, feature, detail = with_random_feature(rng, outer)
        if outer is None:
            continue
        holes = star_holes(rng, outer)
        scale, offset = scale_and_offset(rng)
        outer, holes = outer * scale + offset, [h * scale + offset for h in holes]
        points, inside = hole_points(holes)
        if inside and is_valid_domain(outer, holes):
            made = {'kind': kind, 'shape': shape, 'outer_vertices': len(outer), 'holes': len(holes),
                    'hole_vertices': sum(len(h) for h in holes), 'feature': feature, 'feature_detail': detail,
                    'scale': scale, 'offset_x': offset[0], 'offset_y': offset[1], 'attempt': attempt}
            return outer, holes, points, made
    raise RuntimeError('no valid %s domain in %d attempts' % (kind, MAX_ATTEMPTS))


def description(made):
    return ('%(kind)s (%(shape)s), %(outer_vertices)d outer vertices, %(holes)d holes of %(hole_vertices)d '
            'vertices, %(feature_detail)s, scale %(scale).3g, offset (%(offset_x).3g, %(offset_y).3g), '
            'attempt %(attempt)d' % made)


def write_poly(path, loops, points, comments):
    """Triangle's .poly: the comment lines, then 1-based vertices (%.17g) and segments with
    marker = loop id, then the hole points."""
    with open(path, 'w') as out:
        out.write(''.join('# %s\n' % line for line in comments))
        out.write('%d 2 0 1\n' % sum(len(loop) for loop in loops))
        k = 1
        for marker, loop in enumerate(loops, 1):
            for x, y in loop:
                out.write('%d %.17g %.17g %d\n' % (k, x, y, marker))
                k += 1
        out.write('%d 1\n' % (k - 1))
        k = 1
        for marker, loop in enumerate(loops, 1):
            for i in range(len(loop)):
                out.write('%d %d %d %d\n' % (k + i, k + i, k + (i + 1) % len(loop), marker))
            k += len(loop)
        out.write('%d\n' % len(points))
        for i, (x, y) in enumerate(points, 1):
            out.write('%d %.17g %.17g\n' % (i, x, y))


def write_domain(out_dir, seed, index, kinds=KINDS):
    """Draws domain `index` of `seed` (kind: kinds[index % len(kinds)]) and writes it:
    (path, how it was made: a dict)."""
    kind = kinds[index % len(kinds)]
    outer, holes, points, made = random_domain(np.random.default_rng([seed, index]), kind)
    path = os.path.join(out_dir, '%s_%d_%d.poly' % (kind, seed, index))
    write_poly(path, [outer] + holes, points,
               [description(made), 'random_domains.py --seed %d, domain %d; loops outer first (CCW), holes CW, '
                                   'marker = loop id' % (seed, index)])
    return path, made


def kinds_list(text):
    kinds = tuple(text.split(','))
    unknown = [k for k in kinds if k not in ALL_KINDS]
    if unknown:
        raise argparse.ArgumentTypeError('unknown kind(s) %s: use %s' % (','.join(unknown), ','.join(ALL_KINDS)))
    return kinds


def add_domain_arguments(parser):
    """--seed, --count and --kinds, shared with random_sweep.py."""
    parser.add_argument('--seed', type=int, required=True)
    parser.add_argument('--count', type=int, required=True, help='how many domains (indices 0 to N-1)')
    parser.add_argument('--kinds', type=kinds_list, default=KINDS, help='comma-separated, of ' + ','.join(ALL_KINDS) + ' (default: ' + ','.join(KINDS) + ')')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('out_dir')
    add_domain_arguments(parser)
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    for index in range(args.count):
        path, made = write_domain(args.out_dir, args.seed, index, args.kinds)
        print('%s: %s' % (os.path.basename(path), description(made)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
