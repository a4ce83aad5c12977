#!/usr/bin/env python3
# The bounds of the tents of internal/insert_points.h, by sampling the displacement d = P - W
# over its whole range (a 81 x 81 grid, corners included) on a block of unit squares (g = 1).
# Ring r (Chebyshev distance r from W) moves by factor[r] * d; rings beyond the list stay.
# Prints the angle range of all quads of the block, and the largest aspect ratio (longest
# over shortest edge) of the quads at P and of the other quads.
#   python3 doc/Quad_mesher_2/fig/tent_bounds.py
import math


def quad(P):
    angles, lengths = [], []
    for k in range(4):
        a, b, c = P[k - 1], P[k], P[(k + 1) % 4]
        u = (a[0] - b[0], a[1] - b[1])
        v = (c[0] - b[0], c[1] - b[1])
        angles.append(math.degrees(math.atan2(abs(u[0] * v[1] - u[1] * v[0]), u[0] * v[0] + u[1] * v[1])))
        lengths.append(math.hypot(*v))
    return min(angles), max(angles), max(lengths) / min(lengths)


def tent(factors, reach, steps=40):
    R = len(factors)
    lo, hi, at_p, other = 180.0, 0.0, 0.0, 0.0
    for sx in range(-steps, steps + 1):
        for sy in range(-steps, steps + 1):
            d = (reach * sx / steps, reach * sy / steps)

            def pos(X, Y):
                r = max(abs(X), abs(Y))
                f = factors[r] if r < R else 0.0
                return (X + f * d[0], Y + f * d[1])

            for X in range(-R - 1, R + 1):
                for Y in range(-R - 1, R + 1):
                    corners = [(X, Y), (X + 1, Y), (X + 1, Y + 1), (X, Y + 1)]
                    a, b, asp = quad([pos(*c) for c in corners])
                    lo, hi = min(lo, a), max(hi, b)
                    if (0, 0) in corners:
                        at_p = max(at_p, asp)
                    else:
                        other = max(other, asp)
    return lo, hi, at_p, other


cases = [
    ("radius 1, |dx|,|dy| <= 3g/16", [1.0], 3 / 16),
    ("radius 1, |dx|,|dy| <= 0.2g", [1.0], 0.2),
    ("radius 1, |dx|,|dy| <= g/4 (paper's B1)", [1.0], 1 / 4),
    ("radius 3, factors 1, 3/4, 3/8, |dx|,|dy| <= g/2", [1.0, 0.75, 0.375], 1 / 2),
    ("radius 2, factors 1, 1/2, |dx|,|dy| <= g/2", [1.0, 0.5], 1 / 2),
    ("radius 2, factors 1, 0.582, |dx|,|dy| <= g/2", [1.0, 0.582], 1 / 2),
    ("radius 2, factors 1, 0.585, |dx|,|dy| <= g/2", [1.0, 0.585], 1 / 2),
    ("radius 2, factors 1, 5/8, |dx|,|dy| <= g/2", [1.0, 0.625], 1 / 2),
]
print("%-48s %18s %10s %10s" % ("tent", "angles (deg)", "aspect@P", "aspect"))
for name, factors, reach in cases:
    lo, hi, at_p, other = tent(factors, reach)
    print("%-48s [%6.2f, %6.2f] %10.4f %10.4f" % (name, lo, hi, at_p, other))
