// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// How many times the corners of the quads at a vertex wind around it: the fold test of the
// stages that move vertices (the buffer's optimiser, the smoothing), exact where doubles are
// not certain.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_WEDGE_WINDING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_WEDGE_WINDING_H

#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Whether the directions from `c` to `a` and to `b` are the same, exactly.
inline bool same_direction(const Point_2d& c, const Point_2d& a, const Point_2d& b)
{
  const Approximate_kernel kernel;
  return kernel.orientation_2_object()(c, a, b) == COLLINEAR && kernel.angle_2_object()(a, c, b) == ACUTE;
}

/// Whether the direction from `c` to `r` lies strictly inside the wedge swept
/// counter-clockwise from the direction to `f` to the direction to `t` (not the same).
/// Exact: orientations and angle signs of the points (the approximate kernel's predicates).
inline bool strictly_between(const Point_2d& c, const Point_2d& r, const Point_2d& f, const Point_2d& t)
{
  const auto orientation = Approximate_kernel().orientation_2_object();
  const Orientation wedge = orientation(c, f, t);
  if(wedge == LEFT_TURN) // under 180 degrees: the intersection of two half-planes
    return orientation(c, f, r) == LEFT_TURN && orientation(c, r, t) == LEFT_TURN;
  if(wedge == COLLINEAR) // 180 degrees: the half-plane on the left of f
    return orientation(c, f, r) == LEFT_TURN;
  // over 180: outside the closed wedge from t to f
  return !((orientation(c, t, r) == LEFT_TURN && orientation(c, r, f) == LEFT_TURN) || same_direction(c, r, t)
           || same_direction(c, r, f));
}

/// How many times a closed chain of wedges at `centre` winds around it: once if its corners
/// do not fold. Each wedge is swept counter-clockwise from the direction to its `first` point
/// to the direction to its `second`; a wedge whose two points lie in one direction from
/// `centre` (a corner of angle zero) adds nothing. No point may be at `centre`.
/// Its angles in doubles decide when every wedge's side of 180 degrees is certain (the
/// common case: the sum is then within rounding of 360 times the winding); else the exact
/// count: how many wedges cover the direction to the end of the first, each from its start
/// (excluded) to its end (included), which a closed chain does as often as it winds.
inline std::size_t times_wedges_cover(const Point_2d& centre, const std::vector<std::pair<Point_2d, Point_2d>>& wedges)
{
  double sum = 0;
  bool certain = true;
  for(const auto& w : wedges) {
    const Vector_2d u = w.first - centre, v = w.second - centre;
    const double cross = CGAL::determinant(u, v);
    // the sign of a cross product this far from zero survives the rounding of u, v and it
    if(!(cross * cross > 1e-24 * u.squared_length() * v.squared_length())) {
      certain = false;
      break;
    }
    sum += angle_degrees(cross, CGAL::scalar_product(u, v));
  }
  if(certain) return std::size_t(std::lround(sum / 360.0));
  const Point_2d& reference = wedges.front().second;
  std::size_t covered = 0;
  for(const auto& w : wedges) {
    if(same_direction(centre, w.first, w.second)) continue; // a corner of angle zero
    if(same_direction(centre, reference, w.second) || strictly_between(centre, reference, w.first, w.second))
      ++covered;
  }
  return covered;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_WEDGE_WINDING_H
