// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Lemma 2's measure: how far the buffer-side angles beta of the core boundary lie outside
// [112.5°, 225°], the range from which the first buffer layer splits each into two angles within
// [45°, 135°]. The boundary templates (boundary_templates.h, template_search.h,
// connectivity_templates.h) move and add core points to lower it.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_SIDE_ANGLES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_SIDE_ANGLES_H

#include <CGAL/Quad_mesher_2/internal/buffer_tolerances.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// how far a buffer-side angle lies outside [112.5, 225], the range the paper's templates
// leave (Lemma 2): there the first layer's two quads at the vertex split it within [45, 135]
inline double buffer_angle_excess(double beta)
{
  return (std::max)(0.0, beta - 225.0) + (std::max)(0.0, 112.5 - beta);
}

// how far a buffer-side angle lies outside [112.5, 225] widened by half the angle tolerance
// (what is within the tolerance counts as in)
inline double widened_excess(double beta)
{
  return (std::max)(0.0, beta - (225.0 + Buffer_tolerances::angle_tolerance / 2))
         + (std::max)(0.0, (112.5 - Buffer_tolerances::angle_tolerance / 2) - beta);
}

// widened_excess() of the angle on the right of a -> b -> c, 180 degrees plus the turn at b.
// A turn well within (-67.5, 45) degrees (its tangent within the range's by more than the
// rounding of an atan2) has none, told by its cross and dot products alone: the searches
// cost this at every point they try, and most of the angles they watch are in range.
inline double widened_excess_at(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  const Vector_2d t1 = b - a, t2 = c - b;
  const double cross = CGAL::determinant(t1, t2), dot = CGAL::scalar_product(t1, t2);
  const double tan_45 = 1.0, tan_67_5 = 2.414213562373095; // 1 + sqrt(2)
  if(dot > 0 && cross < dot * (tan_45 * (1 - 1e-10)) && cross > -dot * (tan_67_5 * (1 - 1e-10))) return 0.0;
  return widened_excess(right_side_angle(a, b, c));
}

// Lemma 2's measure of buffer-side angles out of range, from their widened_excess()es.
template <class Excesses>
double score_of_excesses(const Excesses& excesses, bool count_first)
{
  double out = 0, worst = 0, sum = 0;
  for(double x : excesses) {
    out += x > 0 ? 1 : 0;
    worst = (std::max)(worst, x);
    sum += x;
  }
  return (count_first ? 1000.0 * out : 0.0) + worst + 0.1 * sum;
}

// How far the buffer-side angles at a, b and c (consecutive on a core cycle between a2 and
// c2) lie outside [112.5, 225] widened by half the angle tolerance, in one number, so that
// a search lowering it by more than rounding ends: how many are out first if `count_first`
// (a step of b that lets a neighbour out for a smaller worst one leaves more out), then the
// worst, then a tenth of their sum.
inline double buffer_angle_excesses(const Point_2d& a2, const Point_2d& a, const Point_2d& b,
                             const Point_2d& c, const Point_2d& c2, bool count_first = true)
{
  const std::array<double, 3> excesses{ widened_excess_at(a2, a, b), widened_excess_at(a, b, c), widened_excess_at(b, c, c2) };
  return score_of_excesses(excesses, count_first);
}

// the largest buffer_angle_excess() of the three buffer-side angles at a, b and c, which
// are consecutive on a core cycle between a2 and c2 (what a template step at b changes)
inline double worst_buffer_angle_excess(const Point_2d& a2, const Point_2d& a, const Point_2d& b,
                                 const Point_2d& c, const Point_2d& c2)
{
  return (std::max)({ buffer_angle_excess(right_side_angle(a2, a, b)),
                      buffer_angle_excess(right_side_angle(a, b, c)),
                      buffer_angle_excess(right_side_angle(b, c, c2)) });
}

// how far the angle at b (between a and c) may be off by the rounding of their coordinates
// to doubles, in degrees, and at least angle_tolerance: far from the origin a double holds
// few digits of a small domain's edges (a kite of exactly 225 degrees may come out over it,
// and must not count as out of Lemma 2's range nor be split as if jammed)
inline double rounding_tolerance(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  double scale = 0;
  for(const Point_2d* p : { &a, &b, &c }) scale = (std::max)({ scale, std::abs(p->x()), std::abs(p->y()) });
  const double edge = (std::min)(length_2d(a - b), length_2d(c - b));
  return (std::max)(Buffer_tolerances::angle_tolerance,
                    64 * std::numeric_limits<double>::epsilon() * scale / edge * 180 / Buffer_tolerances::pi);
}

// whether the buffer-side angle at b (between a and c on a core cycle) is out of Lemma 2's
// range by more than rounding the coordinates can change it by
inline bool out_of_lemma_2_range(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  return buffer_angle_excess(right_side_angle(a, b, c)) > rounding_tolerance(a, b, c);
}

// The least lowering of buffer_angle_excesses() at a, b and c (consecutive on a core cycle
// between a2 and c2) that a search may take for a gain: a tenth of the angle tolerance, or of
// the rounding of the three angles where it is larger. Below that, far from the origin, a
// search would follow the rounding of the coordinates, step by step, for nothing.
inline double least_search_gain(const Point_2d& a2, const Point_2d& a, const Point_2d& b, const Point_2d& c,
                                const Point_2d& c2)
{
  return (std::max)({ rounding_tolerance(a2, a, b), rounding_tolerance(a, b, c), rounding_tolerance(b, c, c2) }) / 10;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_SIDE_ANGLES_H
