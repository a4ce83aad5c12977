#!/usr/bin/python3
"""valence_table.py -- where a quad mesh's angles outside [60, 120] degrees are, by vertex valence.

Usage:
    valence_table.py MESH.off

MESH.off is a quad-mesher output (`quad-mesher CASE.poly -o MESH.off`). Prints, for the
interior vertices (on no boundary edge) of each number of quads k and for the boundary
vertices together: how many vertices, how many of their corner angles are outside [60, 120]
(the verifier's 1e-7 degree slack), and that per vertex. The angles at an interior vertex of
k quads add up to 360 degrees, so at k = 3 one is at least 120 and at k >= 6 one is at most
60: these are the vertices the smoothing stage's splits are for (doc: QM2Smoothing).
"""
import collections
import math
import sys

SLACK = 1e-7


def read_off(path):
    words = open(path).read().split()
    if not words or words[0] != "OFF":
        sys.exit("%s: not an OFF file" % path)
    n_vertices, n_faces = int(words[1]), int(words[2])
    at = 4
    points = []
    for _ in range(n_vertices):
        points.append((float(words[at]), float(words[at + 1])))
        at += 3
    quads = []
    for _ in range(n_faces):
        n = int(words[at])
        quads.append([int(w) for w in words[at + 1:at + 1 + n]])
        at += 1 + n
    return points, quads


def corner_angle(p, q, r):
    u = (p[0] - q[0], p[1] - q[1])
    v = (r[0] - q[0], r[1] - q[1])
    return math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1]))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    points, quads = read_off(sys.argv[1])
    valence = collections.Counter()
    edge_uses = collections.Counter()
    for f in quads:
        for c in range(len(f)):
            valence[f[c]] += 1
            edge_uses[tuple(sorted((f[c], f[(c + 1) % len(f)])))] += 1
    boundary = set()
    for e, uses in edge_uses.items():
        if uses == 1:
            boundary.update(e)

    def kind(v):
        return "boundary" if v in boundary else "interior %d" % valence[v]

    vertices = collections.Counter(kind(v) for v in valence)
    out = collections.Counter()
    total = 0
    for f in quads:
        for c in range(len(f)):
            a = corner_angle(points[f[c - 1]], points[f[c]], points[f[(c + 1) % len(f)]])
            if a < 60 - SLACK or a > 120 + SLACK:
                out[kind(f[c])] += 1
                total += 1
    print("| vertices | count | angles outside [60, 120] | per vertex |")
    print("| --- | ---: | ---: | ---: |")
    order = sorted(vertices, key=lambda k: (k == "boundary", int(k.split()[1]) if k != "boundary" else 0))
    for k in order:
        print("| %s | %d | %d | %.2f |" % (k, vertices[k], out[k], out[k] / vertices[k]))
    print("| all | %d | %d of %d angles | |" % (sum(vertices.values()), total, 4 * len(quads)))


if __name__ == "__main__":
    main()
