// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The shape of one quadrilateral (corner angles, scaled Jacobians, edge lengths, its deviation
// from a square's angles, and how two deviations compare within a tolerance without an
// arcsine) and the plane constructions the buffer stages search with that the
// kernel lacks (projection parameters, bisectors, turns by an angle), on the approximate
// kernel's points and vectors. Measures, computed in `double` by design (see STYLE.md,
// "Exactness"): no topological decision is taken here.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_QUAD_GEOMETRY_H
#define CGAL_QUAD_MESHER_2_INTERNAL_QUAD_GEOMETRY_H

#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// the mean of the points in [first, last), summed in order (a Laplacian step's target)
template <class Iterator>
inline Point_2d mean_2d(Iterator first, Iterator last)
{
  Vector_2d sum = NULL_VECTOR;
  double n = 0;
  for(; first != last; ++first, ++n) sum = sum + (*first - ORIGIN);
  return ORIGIN + sum / n;
}

/// The rounding of a coordinate of `a` or `b`: machine epsilon times the largest of their
/// coordinates' magnitudes. Far from the origin (map projections) it outgrows any tolerance
/// relative to an edge's length.
inline double coordinate_rounding_2d(const Point_2d& a, const Point_2d& b)
{
  return std::numeric_limits<double>::epsilon()
         * (std::max)({ std::abs(a.x()), std::abs(a.y()), std::abs(b.x()), std::abs(b.y()) });
}

/// the vector `v` turned counter-clockwise by `radians`
inline Vector_2d turned_2d(const Vector_2d& v, double radians)
{
  const double cs = std::cos(radians), sn = std::sin(radians);
  return Vector_2d(cs * v.x() - sn * v.y(), sn * v.x() + cs * v.y());
}
/// the point `p` turned counter-clockwise about `centre` by `radians`
inline Point_2d turned_about_2d(const Point_2d& p, const Point_2d& centre, double radians)
{
  const double cs = std::cos(radians), sn = std::sin(radians);
  const Vector_2d v = p - centre;
  return Point_2d(centre.x() + cs * v.x() - sn * v.y(), centre.y() + sn * v.x() + cs * v.y());
}

/// The angle in degrees, in [0, 360), swept counter-clockwise from a vector u to a vector v
/// with cross(u, v) = `cross` and dot(u, v) = `dot`.
inline double angle_degrees(double cross, double dot)
{
  double a = std::atan2(cross, dot) * (180.0 / CGAL_PI);
  if(a < 0)
    a += 360.0;
  if(a >= 360.0)
    a = 0.0;
  return a;
}

/// Interior angle in degrees, in [0, 360), at corner `p` of a counter-clockwise polygon whose
/// previous and next vertices are `prev` and `next`: the angle swept counter-clockwise from
/// `next - p` to `prev - p`. Convex corners give (0, 180), reflex corners (180, 360).
/// Returns 0 if one of the two edges has zero length.
inline double corner_angle_degrees(const Point_2d& prev, const Point_2d& p, const Point_2d& next)
{
  const Vector_2d e_next = next - p;
  const Vector_2d e_prev = prev - p;
  return angle_degrees(CGAL::determinant(e_next, e_prev), CGAL::scalar_product(e_next, e_prev));
}

/// the turning (degrees) from which a loop vertex is a feature, a vertex the mesh keeps; the
/// chord tolerance may leave the others out
constexpr double loop_feature_angle = 20.0;

/// how much a polyline turns (degrees, in [0, 180]) at its vertex `p` between `prev` and `next`
inline double turn_degrees(const Point_2d& prev, const Point_2d& p, const Point_2d& next)
{
  return std::abs(180.0 - corner_angle_degrees(prev, p, next));
}

/// whether the loop vertex `p`, between `prev` and `next`, is a feature
inline bool is_loop_feature(const Point_2d& prev, const Point_2d& p, const Point_2d& next)
{
  return turn_degrees(prev, p, next) >= loop_feature_angle;
}

/// Scaled Jacobian at corner `p` of a counter-clockwise polygon:
/// cross(e_next, e_prev) / (|e_next| |e_prev|), the sine of the corner angle, in [-1, 1].
/// Returns 0 if one of the two edges has zero length.
inline double corner_scaled_jacobian(const Point_2d& prev, const Point_2d& p, const Point_2d& next)
{
  const Vector_2d e_next = next - p;
  const Vector_2d e_prev = prev - p;
  const double l = length_2d(e_next) * length_2d(e_prev);
  if(!(l > 0))
    return 0.0;
  double s = CGAL::determinant(e_next, e_prev) / l;
  return (std::max)(-1.0, (std::min)(1.0, s));
}

/// The four interior angles (degrees) of the quad `q`, listed counter-clockwise.
inline std::array<double, 4> quad_corner_angles(const std::array<Point_2d, 4>& q)
{
  std::array<double, 4> a;
  for(int k = 0; k < 4; ++k)
    a[k] = corner_angle_degrees(q[(k + 3) % 4], q[k], q[(k + 1) % 4]);
  return a;
}

/// Edge lengths of `q`: entry k is the length of edge (q[k], q[k+1]).
inline std::array<double, 4> quad_edge_lengths(const std::array<Point_2d, 4>& q)
{
  std::array<double, 4> l;
  for(int k = 0; k < 4; ++k)
    l[k] = length_2d(q[(k + 1) % 4] - q[k]);
  return l;
}

/// The four corner scaled Jacobians of the quad `q` (see `corner_scaled_jacobian()`) from
/// `len`, its `quad_edge_lengths()`: a corner's edges are edge k and edge k-1 reversed, whose
/// lengths are the same to the bit, so callers that have the lengths do not take them again.
inline std::array<double, 4> quad_corner_scaled_jacobians(const std::array<Point_2d, 4>& q,
                                                          const std::array<double, 4>& len)
{
  std::array<double, 4> s;
  for(int k = 0; k < 4; ++k) {
    const double l = len[k] * len[(k + 3) % 4];
    s[k] = 0.0;
    if(l > 0)
      s[k] = (std::max)(-1.0, (std::min)(1.0, CGAL::determinant(q[(k + 1) % 4] - q[k], q[(k + 3) % 4] - q[k]) / l));
  }
  return s;
}

/// The four corner scaled Jacobians of the quad `q`.
inline std::array<double, 4> quad_corner_scaled_jacobians(const std::array<Point_2d, 4>& q)
{
  return quad_corner_scaled_jacobians(q, quad_edge_lengths(q));
}

/// The scaled Jacobian of a quad: the minimum over its four corners.
inline double quad_scaled_jacobian(const std::array<Point_2d, 4>& q)
{
  const std::array<double, 4> s = quad_corner_scaled_jacobians(q);
  return (std::min)((std::min)(s[0], s[1]), (std::min)(s[2], s[3]));
}

/// The largest deviation |angle - 90| (degrees) over the four corners of `q`.
inline double quad_max_angle_deviation(const std::array<Point_2d, 4>& q)
{
  const std::array<double, 4> a = quad_corner_angles(q);
  double d = 0;
  for(double x : a)
    d = (std::max)(d, std::abs(x - 90.0));
  return d;
}

/// Longest over shortest edge of `q`; +infinity if some edge has zero length.
inline double quad_aspect_ratio(const std::array<Point_2d, 4>& q)
{
  const std::array<double, 4> l = quad_edge_lengths(q);
  const double lo = (std::min)((std::min)(l[0], l[1]), (std::min)(l[2], l[3]));
  const double hi = (std::max)((std::max)(l[0], l[1]), (std::max)(l[2], l[3]));
  if(!(lo > 0))
    return std::numeric_limits<double>::infinity();
  return hi / lo;
}

/// the parameter in [0, 1] of the point of segment (a, b) nearest to p
inline double nearest_segment_parameter(const Point_2d& p, const Point_2d& a, const Point_2d& b)
{
  const Vector_2d ab = b - a;
  const double len2 = ab.squared_length();
  const double t = len2 > 0 ? CGAL::scalar_product(p - a, ab) / len2 : 0.0;
  return (std::min)(1.0, (std::max)(0.0, t));
}

/// a + t (b - a)
inline Point_2d along_2d(const Point_2d& a, const Point_2d& b, double t)
{
  return a + t * (b - a);
}

/// The point from which each side of triangle abc is seen under 120 degrees (its Fermat
/// point), if every angle of the triangle is under 120 degrees; else false. It is where the
/// lines from a and from b to the apexes of the equilateral triangles raised on the opposite
/// sides, outwards, meet.
inline bool fermat_point_2d(const Point_2d& a, const Point_2d& b, const Point_2d& c, Point_2d& f)
{
  const double area2 = CGAL::determinant(b - a, c - a);
  if(area2 == 0) return false;
  auto under_120 = [](const Vector_2d& u, const Vector_2d& v) {
    return CGAL::scalar_product(u, v) > -0.5 * length_2d(u) * length_2d(v);
  };
  if(!under_120(b - a, c - a) || !under_120(c - b, a - b) || !under_120(a - c, b - c)) return false;
  const double outwards = (area2 > 0 ? -1 : 1) * CGAL_PI / 3; // right of b -> c in a ccw abc
  const Point_2d apex_a = turned_about_2d(c, b, outwards), apex_b = turned_about_2d(a, c, outwards);
  const Vector_2d da = apex_a - a, db = apex_b - b;
  const double denominator = CGAL::determinant(da, db);
  if(denominator == 0) return false;
  f = a + (CGAL::determinant(b - a, db) / denominator) * da;
  return true;
}

/// the distance from p to segment (a, b)
inline double point_segment_distance(const Point_2d& p, const Point_2d& a, const Point_2d& b)
{
  return length_2d((p - along_2d(a, b, nearest_segment_parameter(p, a, b))));
}

/// v scaled to unit length (zero stays zero)
inline Vector_2d normalized_2d(const Vector_2d& v)
{
  const double l = length_2d(v);
  return l > 0 ? v / l : NULL_VECTOR;
}

/// the angle (degrees, in [0, 360)) on the right of the path a -> b -> c, at b
inline double right_side_angle(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  const Vector_2d t1 = b - a, t2 = c - b;
  const double turn = std::atan2(CGAL::determinant(t1, t2), CGAL::scalar_product(t1, t2)) * 180.0 / CGAL_PI;
  return 180.0 + turn;
}

/// the unit bisector of the angle on the right of a -> b -> c
inline Vector_2d right_bisector(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  const Vector_2d t1 = normalized_2d(b - a), t2 = normalized_2d(c - b);
  const Vector_2d s = t1 + t2;
  if(length_2d(s) < 1e-9) // a spike: the bisector points back along the incoming edge
    return -t1;
  return normalized_2d(s.perpendicular(CLOCKWISE));
}

/// Whether every corner of q is strictly convex beyond quad_badness()'s flat threshold with
/// |cos| squared below `max_cos2`, by products alone (no root, no arcsine): then
/// quad_badness(q) is below asin(sqrt(max_cos2)), a test the buffer's inner loops make first.
inline bool quad_well_within(const std::array<Point_2d, 4>& q, double max_cos2)
{
  std::array<Vector_2d, 4> e;
  for(int k = 0; k < 4; ++k) e[k] = q[(k + 1) % 4] - q[k];
  for(int c = 0; c < 4; ++c) {
    const Vector_2d& in = e[(c + 3) % 4];
    const Vector_2d& out = e[c];
    const double cross = CGAL::determinant(in, out), dot = CGAL::scalar_product(in, out);
    const double ll = in.squared_length() * out.squared_length();
    if(!(cross > 0 && cross * cross > 1e-12 * ll && dot * dot < max_cos2 * ll)) return false;
  }
  return true;
}

/// the |cos| of a quad's corner farthest from 90 degrees (at most 1); a large penalty, 1000 or
/// more, if it is not strictly convex and counter-clockwise (quad_badness() without its arcsine)
inline double quad_worst_cos(const std::array<Point_2d, 4>& q)
{
  // edge k runs from corner k to corner k + 1; each length is taken once
  std::array<Vector_2d, 4> e;
  std::array<double, 4> len;
  for(int k = 0; k < 4; ++k) {
    e[k] = q[(k + 1) % 4] - q[k];
    len[k] = length_2d(e[k]);
  }
  double worst_cos = 0;
  for(int c = 0; c < 4; ++c) {
    const Vector_2d& in = e[(c + 3) % 4];
    const Vector_2d& out = e[c];
    const double cr = CGAL::determinant(in, out);
    const double l1 = len[c], l2 = len[(c + 3) % 4];
    if(!(cr > 1e-6 * l1 * l2) || l1 == 0 || l2 == 0) // flat corners count as invalid
      return 1000.0 + (cr < 0 ? 100.0 : 0.0);
    worst_cos = (std::max)(worst_cos, std::abs(CGAL::scalar_product(out, in)) / (l1 * l2));
  }
  return (std::min)(worst_cos, 1.0);
}

/// the deviation from 90 degrees of a corner whose |cos| is `c`: at a convex corner
/// |angle - 90| = asin(|cos angle|), increasing in |cos|
inline double deviation_of_cos(double c) { return std::asin(c) * (180.0 / CGAL_PI); }

/// A deviation from 90 degrees held as the |cos| it is the arcsine of (`deviation_of_cos()`),
/// or as degrees (a penalty, or one found otherwise): the arcsine is taken only when a
/// comparison needs it. It grows by over 57 degrees per unit of cosine, so two cosines more
/// than a fiftieth of a tolerance apart decide a comparison within that tolerance alone.
struct Deviation
{
  double value = 0;
  bool is_cos = true;

  static Deviation of_cos(double c) { return Deviation{ c, true }; }
  static Deviation degrees(double d) { return Deviation{ d, false }; }
  double in_degrees() const { return is_cos ? deviation_of_cos(value) : value; }
  bool is_penalty() const { return !is_cos && value >= 1000.0; }

  /// whether this is below `o` by more than `tolerance` degrees
  bool below(const Deviation& o, double tolerance) const
  {
    if(is_cos && o.is_cos) {
      if(value < o.value - tolerance / 50) return true;
      if(value >= o.value) return false;
    }
    return in_degrees() < o.in_degrees() - tolerance;
  }
  /// whether this is above `o` by more than `tolerance` degrees (not `o.below(*this)`: the
  /// degrees round otherwise, and near ties the two can differ)
  bool above(const Deviation& o, double tolerance) const
  {
    if(is_cos && o.is_cos) {
      if(value > o.value + tolerance / 50) return true;
      if(value <= o.value) return false;
    }
    return in_degrees() > o.in_degrees() + tolerance;
  }
  static Deviation larger(const Deviation& a, const Deviation& b)
  {
    if(a.is_cos && b.is_cos) return a.value < b.value ? b : a;
    return a.in_degrees() < b.in_degrees() ? b : a;
  }
};

/// largest deviation of a quad's angles from 90 degrees; a large penalty if it is not strictly
/// convex and counter-clockwise
inline double quad_badness(const std::array<Point_2d, 4>& q)
{
  const double c = quad_worst_cos(q);
  return c < 1000.0 ? deviation_of_cos(c) : c;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_QUAD_GEOMETRY_H
