#!/usr/bin/python3
"""lemma2_count.py -- Lemma 2's buffer-side angles on a core mesh (paper section 4.4).

Usage:
    quad-mesher CASE.poly --stop-after templates -o core.msh
    lemma2_count.py core.msh [N]

For every vertex on the core mesh's boundary, the buffer-side angle beta is 360 degrees minus
the sum of the core quads' angles there. Lemma 2 asks beta in [112.5, 225]. Prints how many
boundary vertices there are and how many are out, then the most common kinds of the out ones
(beta and the core angles at the vertex, rounded); with N, the first N out ones with their
coordinates. Needs Debian's python3-meshio and numpy.
"""
import collections
import sys

import meshio
import numpy as np


def main():
    mesh = meshio.read(sys.argv[1])
    points = mesh.points[:, :2]
    quads = np.vstack([c.data for c in mesh.cells if c.type == "quad"])
    angles = collections.defaultdict(list)
    edges = collections.Counter()
    for q in quads:
        for k in range(4):
            a, b, c = q[k - 1], q[k], q[(k + 1) % 4]
            u, v = points[a] - points[b], points[c] - points[b]
            cosine = u @ v / np.linalg.norm(u) / np.linalg.norm(v)
            angles[b].append(np.degrees(np.arccos(np.clip(cosine, -1, 1))))
            edges[tuple(sorted((q[k], q[(k + 1) % 4])))] += 1
    boundary = sorted({v for e, n in edges.items() if n == 1 for v in e})
    out = [(v, 360 - sum(angles[v])) for v in boundary]
    out = [(v, beta) for v, beta in out if beta < 112.5 - 1e-6 or beta > 225 + 1e-6]
    share = 100 * len(out) / max(1, len(boundary))
    print(f"{sys.argv[1]}: {len(boundary)} boundary vertices, {len(out)} with beta outside [112.5, 225] ({share:.2f}%)")
    kinds = collections.Counter((round(beta), tuple(sorted(round(a) for a in angles[v]))) for v, beta in out)
    for (beta, core), n in kinds.most_common(20):
        print(f"  {n} x beta {beta}, core angles {core}")
    for v, beta in out[: int(sys.argv[2]) if len(sys.argv) > 2 else 0]:
        print(f"  vertex {v} at ({points[v][0]:.9g}, {points[v][1]:.9g}): beta {beta:.2f}")


if __name__ == "__main__":
    main()
