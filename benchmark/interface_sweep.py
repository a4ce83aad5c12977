#!/usr/bin/python3
"""interface_sweep.py -- interfaces on random domains: inclusions meshed with the land around (issue 27).

Usage:
    interface_sweep.py QUAD_MESHER OUT_DIR --seed S --count N [--kinds star,twoopt,convex]
                       [--jobs 2] [--timeout 60] [--verifier PATH] [--keep-meshes]

Domain i is random_domains.py's domain i of seed S with at least two holes (drawn again from
the same generator until it has them): the first hole keeps its hole point, the others lose
theirs and become inclusions, interfaces between the land and their inside, which Triangle's
rule puts in the domain too (OUT_DIR/inclusions_<kind>_<S>_<i>.poly). Each is meshed and
verified as random_sweep.py does (`verify_mesh.py --domain --no-overlap --excuse-above 360`:
`constraints_present` checks that every segment of an inclusion is a chain of mesh edges).
The runs are tabled by kind and by the sharpest corner of the inclusions on either side,
min(a, 360 - a) over their corners: below 43 degrees one side of the interface is a wedge
whose tip quad the other side's fan must share. Writes OUT_DIR/results.csv and copies the
inputs that do not pass into OUT_DIR/failing/. Needs Debian's python3-numpy,
python3-shapely (and the verifier's python3-scipy and python3-meshio); run with
/usr/bin/python3.
"""
import os
import sys

import numpy as np

import random_domains
import random_sweep

CSV_FIELDS = ('file', 'kind', 'shape', 'outer_vertices', 'holes', 'inclusions', 'sharpest_interface_corner',
              'corner_class', 'outcome', 'exit', 'seconds', 'quads', 'mesher_unforced_quads',
              'verifier_unexcused_angles', 'failed_checks', 'message')
SHARP = 43.0  # degrees: inclusions with a corner sharper than this on either side are tabled apart
MAX_DRAWS = 1000


def sharpest_corner(loops):
    """min(a, 360 - a) over the corners of the loops, degrees."""
    return min(float(np.min(np.minimum(a, 360 - a))) for a in map(random_domains.corner_angles, loops))


def write_inclusions(out_dir, seed, index, kinds):
    """Draws domain `index` of `seed` with two holes or more and writes it with all holes but
    the first made inclusions: (path, how it was made: a dict)."""
    kind = kinds[index % len(kinds)]
    rng = np.random.default_rng([seed, index])
    for draw in range(1, MAX_DRAWS + 1):
        outer, holes, points, made = random_domains.random_domain(rng, kind)
        if len(holes) >= 2:
            break
    else:
        raise RuntimeError('no %s domain with two holes in %d draws' % (kind, MAX_DRAWS))
    inclusions = holes[1:]
    corner = sharpest_corner(inclusions)
    made = dict(made, inclusions=len(inclusions), sharpest_interface_corner='%.3f' % corner,
                corner_class='below %g' % SHARP if corner < SHARP else '%g or more' % SHARP)
    path = os.path.join(out_dir, 'inclusions_%s_%d_%d.poly' % (kind, seed, index))
    how = ('interface_sweep.py --seed %d, domain %d (draw %d): loops outer first (CCW), holes CW, marker = loop id; '
           'only the first hole has a hole point, the %d others are inclusions, sharpest corner %.3g degrees'
           % (seed, index, draw, len(inclusions), corner))
    random_domains.write_poly(path, [outer] + holes, points[:1], [random_domains.description(made), how])
    return path, made


def main():
    return random_sweep.sweep_written_domains(__doc__, write_inclusions, CSV_FIELDS,
                                              [('kind', 'kind'), ('corner_class', 'corners')])


if __name__ == '__main__':
    sys.exit(main())
