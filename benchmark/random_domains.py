#!/usr/bin/python3
"""random_domains.py -- seeded random valid domains, the inputs a user meets (issue 24).

Usage:
    random_domains.py OUT_DIR --seed S --count N [--kinds star,twoopt,convex,rectilinear] [--far-field]

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
With --far-field (boundary layers, issue 25), domain i is instead a far field holding bodies,
OUT_DIR/farfield_<kind>_<S>_<i>.poly, drawn from the same generator:
  * 1 to 3 bodies, the holes (CW, segment markers 2, 3, 4): each an outer loop of the kind
    above with its own random feature (a body's spike is a domain corner of 355 to 359
    degrees, its notch one of 1 to 5 degrees), scaled to a diameter (its farthest two
    points apart) of BODY_SIZE = 1 and turned at random; the first one about the origin,
    each next one moved from a point inside one before it, in a random direction, until its
    gap to those before it is 0.05 to 2 body sizes (log-uniform) -- or, in a tenth of the
    domains (then 2 or 3 bodies), the second one's gap is 0.01 to 0.03 body sizes: a slot;
  * the far field (CCW, marker 1): a square of side 20 to 40 body sizes, or in a quarter of
    the domains a rectangle twice as wide, centred on the bodies' bounding box;
  * one hole point inside each body; no scaling or move.
It is checked, and drawn again, as above; its first line also gives the least gap between
bodies and the domain's sharpest corner.
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
BODY_SIZE = 1.0                  # a far field's bodies' diameter
FAR_FIELD_SIDE = (20, 40)        # the far field's shorter side, in body sizes
RECTANGLE_CHANCE = 0.25          # a far field twice as wide as tall
BODY_GAP = (0.05, 2.0)           # a body's gap to those before it, in body sizes (log-uniform)
SLOT_CHANCE = 0.1                # the second body's gap is then a narrow slot
SLOT_GAP = (0.01, 0.03)


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


def turned(loop, turn):
    c, s = np.cos(turn), np.sin(turn)
    return loop @ np.array([[c, s], [-s, c]])


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
    return counter_clockwise(turned(loop, rng.uniform(0, 2 * np.pi)))


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
        loop = turned(loop, rng.uniform(0, 2 * np.pi))
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


def corner_angles(loop):
    """The domain's angle at each corner of a loop that has the domain on its left (an outer
    loop CCW, a hole CW), in degrees."""
    back, ahead = np.roll(loop, 1, axis=0) - loop, np.roll(loop, -1, axis=0) - loop
    return np.degrees(np.arctan2(back[:, 1], back[:, 0]) - np.arctan2(ahead[:, 1], ahead[:, 0])) % 360


def diameter(loop):
    """The largest distance between two of the loop's points."""
    return np.sqrt(np.max(np.sum((loop[:, None, :] - loop[None, :, :]) ** 2, axis=2)))


def random_body(rng, kind):
    """A body for a far field: an outer loop of the kind with its random feature, of diameter
    BODY_SIZE and turned at random, CCW; (loop, shape, feature, its description), or None if
    the feature found no place."""
    loop, shape = outer_loop(rng, kind)
    loop, feature, detail = with_random_feature(rng, loop)
    if loop is None:
        return None
    return turned(loop * (BODY_SIZE / diameter(loop)), rng.uniform(0, 2 * np.pi)), shape, feature, detail


def placed_at_gap(rng, loop, bodies, gap):
    """The loop moved, in a random direction from a point inside one of the bodies (shapely
    polygons), until its distance to them is `gap` (to 1e-4 of it, not under it): the distance
    is 0 where its own inner point sits on that point and more than `gap` far enough away, and
    it changes no faster than the move, so bisection finds such a place."""
    anchor = np.array(bodies[int(rng.integers(len(bodies)))].representative_point().coords[0])
    start = anchor - np.array(Polygon(loop).representative_point().coords[0])
    turn = rng.uniform(0, 2 * np.pi)
    direction = np.array([np.cos(turn), np.sin(turn)])
    others = unary_union(bodies)
    lo_x, lo_y, hi_x, hi_y = others.bounds
    near, far = 0.0, np.hypot(hi_x - lo_x, hi_y - lo_y) + diameter(loop) + 2 * gap
    while far - near > 1e-4 * gap:
        middle = (near + far) / 2
        if Polygon(loop + start + middle * direction).distance(others) < gap:
            near = middle
        else:
            far = middle
    return loop + start + far * direction


def far_field_domain(rng, kind):
    """A valid far field: (far field loop, bodies (CW), hole points, how it was made: a dict)."""
    for attempt in range(1, MAX_ATTEMPTS + 1):
        slot = rng.random() < SLOT_CHANCE
        drawn = [random_body(rng, kind) for _ in range(int(rng.integers(2 if slot else 1, 4)))]
        if any(body is None for body in drawn):
            continue
        loops = [drawn[0][0]]
        for body in drawn[1:]:
            gap = rng.uniform(*SLOT_GAP) if slot and len(loops) == 1 else 10 ** rng.uniform(*np.log10(BODY_GAP))
            loops.append(placed_at_gap(rng, body[0], [Polygon(loop) for loop in loops], gap * BODY_SIZE))
        every = np.concatenate(loops)
        centre = (every.min(axis=0) + every.max(axis=0)) / 2
        height = rng.uniform(*FAR_FIELD_SIDE) * BODY_SIZE
        width = height * (2 if rng.random() < RECTANGLE_CHANCE else 1)
        outer = centre + np.array([[-width, -height], [width, -height], [width, height], [-width, height]]) / 2
        holes = [loop[::-1].copy() for loop in loops]
        points, inside = hole_points(holes)
        if inside and is_valid_domain(outer, holes):
            polygons = [Polygon(h) for h in holes]
            gaps = [h.distance(g) for i, h in enumerate(polygons) for g in polygons[:i]]
            made = {'kind': kind, 'shape': '+'.join(body[1] for body in drawn), 'bodies': len(holes),
                    'body_vertices': len(every), 'feature': '+'.join(body[2] for body in drawn),
                    'feature_detail': '; '.join(body[3] for body in drawn), 'far_field_width': width,
                    'far_field_height': height, 'least_gap': min(gaps) if gaps else '', 'slot': slot,
                    'sharpest_corner': min(np.min(corner_angles(loop)) for loop in [outer] + holes),
                    'attempt': attempt}
            return outer, holes, points, made
    raise RuntimeError('no valid far field of %s bodies in %d attempts' % (kind, MAX_ATTEMPTS))


def description(made):
    if 'bodies' in made:
        return ('far field %.3g x %.3g holding %d %s bod%s (%s) of diameter %g, %d vertices, least gap %s%s, '
                '%s, sharpest corner %.3g deg, attempt %d'
                % (made['far_field_width'], made['far_field_height'], made['bodies'], made['kind'],
                   'y' if made['bodies'] == 1 else 'ies', made['shape'], BODY_SIZE, made['body_vertices'],
                   '%.3g' % made['least_gap'] if made['bodies'] > 1 else '-', ' (a slot)' if made['slot'] else '',
                   made['feature_detail'], made['sharpest_corner'], made['attempt']))
    return ('%(kind)s (%(shape)s), %(outer_vertices)d outer vertices, %(holes)d holes of %(hole_vertices)d '
            'vertices, %(feature_detail)s, scale %(scale).3g, offset (%(offset_x).3g, %(offset_y).3g), '
            'attempt %(attempt)d' % made)


def write_poly(path, loops, points, comments, polylines=()):
    """Triangle's .poly: the comment lines, then 1-based vertices (%.17g; a point at the place
    of one written before is that one: a polyline may end on a loop's vertex) and segments with
    marker = loop id (the open `polylines`, cracks, numbered after the loops), then the hole
    points."""
    chains = [(loop, True) for loop in loops] + [(line, False) for line in polylines]
    vertices, index_of, chain_indices = [], {}, []
    for marker, (chain, _) in enumerate(chains, 1):
        indices = []
        for x, y in chain:
            key = (float(x), float(y))
            if key not in index_of:
                index_of[key] = len(vertices) + 1
                vertices.append((key, marker))
            indices.append(index_of[key])
        chain_indices.append(indices)
    segments = []
    for marker, ((chain, closed), indices) in enumerate(zip(chains, chain_indices), 1):
        for i in range(len(chain) if closed else len(chain) - 1):
            segments.append((indices[i], indices[(i + 1) % len(chain)], marker))
    with open(path, 'w') as out:
        out.write(''.join('# %s\n' % line for line in comments))
        out.write('%d 2 0 1\n' % len(vertices))
        for k, ((x, y), marker) in enumerate(vertices, 1):
            out.write('%d %.17g %.17g %d\n' % (k, x, y, marker))
        out.write('%d 1\n' % len(segments))
        for s, (a, b, marker) in enumerate(segments, 1):
            out.write('%d %d %d %d\n' % (s, a, b, marker))
        out.write('%d\n' % len(points))
        for i, (x, y) in enumerate(points, 1):
            out.write('%d %.17g %.17g\n' % (i, x, y))


def write_domain(out_dir, seed, index, kinds=KINDS, far_field=False):
    """Draws domain `index` of `seed` (kind: kinds[index % len(kinds)]), a far field if asked,
    and writes it: (path, how it was made: a dict)."""
    kind = kinds[index % len(kinds)]
    rng = np.random.default_rng([seed, index])
    if far_field:
        outer, holes, points, made = far_field_domain(rng, kind)
        path = os.path.join(out_dir, 'farfield_%s_%d_%d.poly' % (kind, seed, index))
        how = ('random_domains.py --far-field --seed %d, domain %d; loops the far field first (CCW), then the '
               'bodies (CW), marker = loop id' % (seed, index))
    else:
        outer, holes, points, made = random_domain(rng, kind)
        path = os.path.join(out_dir, '%s_%d_%d.poly' % (kind, seed, index))
        how = ('random_domains.py --seed %d, domain %d; loops outer first (CCW), holes CW, marker = loop id'
               % (seed, index))
    write_poly(path, [outer] + holes, points, [description(made), how])
    return path, made


def kinds_list(text):
    kinds = tuple(text.split(','))
    unknown = [k for k in kinds if k not in ALL_KINDS]
    if unknown:
        raise argparse.ArgumentTypeError('unknown kind(s) %s: use %s' % (','.join(unknown), ','.join(ALL_KINDS)))
    return kinds


def add_domain_arguments(parser, kinds=KINDS):
    """--seed, --count and --kinds (default: `kinds`), shared with random_sweep.py and
    boundary_layer_sweep.py."""
    parser.add_argument('--seed', type=int, required=True)
    parser.add_argument('--count', type=int, required=True, help='how many domains (indices 0 to N-1)')
    parser.add_argument('--kinds', type=kinds_list, default=kinds, help='comma-separated, of ' + ','.join(ALL_KINDS) + ' (default: ' + ','.join(kinds) + ')')


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('out_dir')
    add_domain_arguments(parser)
    parser.add_argument('--far-field', action='store_true', help='far fields holding 1 to 3 bodies of the kinds')
    args = parser.parse_args()
    os.makedirs(args.out_dir, exist_ok=True)
    for index in range(args.count):
        path, made = write_domain(args.out_dir, args.seed, index, args.kinds, args.far_field)
        print('%s: %s' % (os.path.basename(path), description(made)))
    return 0


if __name__ == '__main__':
    sys.exit(main())
