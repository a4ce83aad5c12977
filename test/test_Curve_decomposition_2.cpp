// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests of CGAL/Quad_mesher_2/Curve_decomposition_2.h (paper §4.1): the closed cubic spline
// (interpolation, C2 continuity across every knot including the wrap-around, closeness to a
// circle), the decomposition criteria measured independently of the implementation (turning
// angles, chord errors by dense sampling of the spline), curvature-driven density, orientation,
// domains with holes, every error, the point budget, self-intersection detection, and timing.

#include "qm2_test_kernel.h"
#include "qm2_time_bounds.h"

#include <CGAL/Quad_mesher_2/Curve_decomposition_2.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

namespace qm2_test_curves {

using K = qm2_test::K;
using Point_2 = K::Point_2;
using Domain = CGAL::Quad_mesher_2::Domain_2<K>;
using Spline = CGAL::Quad_mesher_2::Closed_cubic_spline_2<K>;
using Options = CGAL::Quad_mesher_2::Curve_decomposition_options;
using CGAL::Quad_mesher_2::Meshing_error;
using V = std::array<double, 2>;

const double pi = std::acos(-1.0);

inline V to_v(const Point_2& p) { return {CGAL::to_double(p.x()), CGAL::to_double(p.y())}; }

/// Points on an ellipse with semi-axes a, b centred at (cx, cy), counterclockwise unless `cw`.
inline std::vector<Point_2> ellipse(std::size_t n, double a, double b, bool cw = false, double cx = 0, double cy = 0)
{
  std::vector<Point_2> pts;
  for(std::size_t i = 0; i < n; ++i) {
    const double t = 2 * pi * double(i) / double(n) * (cw ? -1 : 1);
    pts.push_back(Point_2(cx + a * std::cos(t), cy + b * std::sin(t)));
  }
  return pts;
}

inline double seg_dist(const V& p, const V& a, const V& b)
{
  const double dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
  double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
  t = std::max(0.0, std::min(1.0, t));
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/// Turning angles (degrees) at every vertex of a closed polygon.
inline std::vector<double> turning_angles_deg(const std::vector<Point_2>& poly)
{
  std::vector<double> r;
  const std::size_t n = poly.size();
  for(std::size_t i = 0; i < n; ++i) {
    const V a = to_v(poly[(i + n - 1) % n]), b = to_v(poly[i]), c = to_v(poly[(i + 1) % n]);
    const V u = {b[0] - a[0], b[1] - a[1]}, w = {c[0] - b[0], c[1] - b[1]};
    r.push_back(std::atan2(std::abs(u[0] * w[1] - u[1] * w[0]), u[0] * w[0] + u[1] * w[1]) * 180 / pi);
  }
  return r;
}

inline double max_turning_deg(const std::vector<Point_2>& poly)
{
  const std::vector<double> t = turning_angles_deg(poly);
  return *std::max_element(t.begin(), t.end());
}

inline double signed_area(const std::vector<Point_2>& poly)
{
  double a = 0;
  for(std::size_t i = 0; i < poly.size(); ++i) {
    const V p = to_v(poly[i]), q = to_v(poly[(i + 1) % poly.size()]);
    a += p[0] * q[1] - p[1] * q[0];
  }
  return a / 2;
}

/// The output index of every control point (which must appear, exactly and in order).
inline std::vector<std::size_t> knot_positions(const std::vector<Point_2>& control, const std::vector<Point_2>& poly)
{
  std::vector<std::size_t> pos;
  std::size_t j = 0;
  for(const Point_2& c : control) {
    while(j < poly.size() && poly[j] != c) ++j;
    EXPECT_LT(j, poly.size()) << "control point " << c << " is not a vertex (in order)";
    pos.push_back(j);
  }
  return pos;
}

/// Chord errors measured independently of the implementation: each span of the spline is
/// sampled densely; each output vertex is matched to its nearest sample (searching forward,
/// so the order along the curve is checked too) and its parameter refined by ternary search
/// between the neighbouring samples; a chord's error is the largest distance to the chord of
/// 200 points of the spline between its two vertices. Also returns, in `off_curve`, the
/// largest distance of a vertex from the curve.
inline std::vector<double> chord_errors(const Spline& s, const std::vector<Point_2>& control,
                                        const std::vector<Point_2>& poly, double& off_curve)
{
  const std::vector<std::size_t> pos = knot_positions(control, poly);
  const std::size_t n = control.size(), m = poly.size();
  const int N = 2000;
  std::vector<double> errors;
  off_curve = 0;
  auto dist = [&](double u, const V& p) {
    const V q = s.point(u);
    return std::hypot(q[0] - p[0], q[1] - p[1]);
  };
  for(std::size_t i = 0; i < n; ++i) {
    const std::size_t a = pos[i], b = (i + 1 < n) ? pos[i + 1] : pos[0] + m;
    const double u0 = s.knot(i), u1 = s.knot(i + 1), du = (u1 - u0) / N;
    std::vector<double> at;  // parameter of each vertex a..b
    int k0 = 0;
    for(std::size_t v = a; v <= b; ++v) {
      const V p = to_v(poly[v % m]);
      int best = k0;
      for(int k = k0; k <= N; ++k)
        if(dist(u0 + k * du, p) < dist(u0 + best * du, p)) best = k;
      double lo = u0 + std::max(best - 1, 0) * du, hi = u0 + std::min(best + 1, N) * du;
      for(int it = 0; it < 100; ++it) {
        const double l = lo + (hi - lo) / 3, r = hi - (hi - lo) / 3;
        if(dist(l, p) < dist(r, p)) hi = r; else lo = l;
      }
      at.push_back(0.5 * (lo + hi));
      off_curve = std::max(off_curve, dist(at.back(), p));
      k0 = best;
    }
    for(std::size_t c = 0; c + 1 < at.size(); ++c) {
      const V p = to_v(poly[(a + c) % m]), q = to_v(poly[(a + c + 1) % m]);
      double e = 0;
      for(int k = 0; k <= 200; ++k) e = std::max(e, seg_dist(s.point(at[c] + (at[c + 1] - at[c]) * k / 200), p, q));
      errors.push_back(e);
    }
  }
  EXPECT_EQ(errors.size(), m);
  return errors;
}

inline double bbox_diagonal(const std::vector<Point_2>& pts)
{
  double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
  for(const Point_2& p : pts) {
    const V v = to_v(p);
    x0 = std::min(x0, v[0]); x1 = std::max(x1, v[0]);
    y0 = std::min(y0, v[1]); y1 = std::max(y1, v[1]);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

/// Checks both criteria and returns the polygon.
inline std::vector<Point_2> decompose_and_check(const std::vector<Point_2>& control, const Options& o = Options())
{
  const std::vector<Point_2> poly = CGAL::Quad_mesher_2::decompose_closed_spline<K>(control, o);
  const double tol = o.max_chord_error > 0 ? o.max_chord_error : 1e-3 * bbox_diagonal(control);
  EXPECT_LE(max_turning_deg(poly), o.max_turning_angle_deg + 1e-9);
  double off = 0;
  const std::vector<double> err = chord_errors(Spline(control), control, poly, off);
  EXPECT_LE(*std::max_element(err.begin(), err.end()), tol);
  EXPECT_LE(off, 1e-9 * bbox_diagonal(control)) << "a vertex is off the spline";
  return poly;
}

inline void add_loop(Domain& d, const std::vector<Point_2>& loop)
{
  const std::size_t first = d.points.size();
  for(std::size_t i = 0; i < loop.size(); ++i) {
    d.points.push_back(loop[i]);
    d.segments.push_back({first + i, first + (i + 1) % loop.size()});
  }
}

template <class F>
std::string error_of(F&& f)
{
  try {
    f();
  } catch(const Meshing_error& e) {
    return e.what();
  }
  return "(no Meshing_error)";
}

inline bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// ---- the spline ---------------------------------------------------------------------------

TEST(CurveDecomposition, SplineInterpolatesIsC2AndFollowsTheCircle)
{
  for(std::size_t n : {8u, 12u}) {
    const std::vector<Point_2> c = ellipse(n, 1, 1);
    const Spline s(c);
    ASSERT_EQ(s.number_of_points(), n);
    for(std::size_t i = 0; i < n; ++i) {  // through every point
      const V p = s.point(s.knot(i)), q = to_v(c[i]);
      EXPECT_NEAR(p[0], q[0], 1e-12);
      EXPECT_NEAR(p[1], q[1], 1e-12);
    }
    // C2 at every knot, including the one where the curve closes: the periodic system was
    // solved, not a natural or clamped one.
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t prev = (i + n - 1) % n;
      const double h = s.knot(prev + 1) - s.knot(prev);
      for(int order = 0; order <= 2; ++order) {
        const V l = s.eval(prev, h, order), r = s.eval(i, 0, order);
        EXPECT_NEAR(l[0], r[0], 1e-9) << "order " << order << " at knot " << i;
        EXPECT_NEAR(l[1], r[1], 1e-9) << "order " << order << " at knot " << i;
      }
    }
    // Derivatives agree with finite differences.
    for(double u : {0.1, 0.77, 1.9}) {
      const double e = 1e-6;
      const V p0 = s.point(u - e), p1 = s.point(u + e), d0 = s.derivative(u - e), d1 = s.derivative(u + e);
      const V d = s.derivative(u), dd = s.second_derivative(u);
      for(int k = 0; k < 2; ++k) {
        EXPECT_NEAR(d[k], (p1[k] - p0[k]) / (2 * e), 1e-6);
        EXPECT_NEAR(dd[k], (d1[k] - d0[k]) / (2 * e), 1e-5);
      }
    }
    // Within 1% of the radius everywhere; periodic in the parameter.
    double dev = 0;
    for(int k = 0; k < 20000; ++k) {
      const V p = s.point(s.period() * k / 20000.0);
      dev = std::max(dev, std::abs(std::hypot(p[0], p[1]) - 1));
    }
    EXPECT_LT(dev, 0.01) << n << " points";
    const V a = s.point(0.3), b = s.point(0.3 + 2 * s.period()), c2 = s.point(0.3 - s.period());
    EXPECT_NEAR(a[0], b[0], 1e-12);
    EXPECT_NEAR(a[1], c2[1], 1e-12);
  }
}

TEST(CurveDecomposition, CentripetalKnots)
{
  // Spans of chord lengths 1, 4, 1, 4 (a rectangle): centripetal knot spacing sqrt(d).
  const std::vector<Point_2> c = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 4), Point_2(0, 4)};
  const Spline s(c);
  EXPECT_DOUBLE_EQ(s.knot(1), 1);
  EXPECT_DOUBLE_EQ(s.knot(2), 3);
  EXPECT_DOUBLE_EQ(s.knot(3), 4);
  EXPECT_DOUBLE_EQ(s.period(), 6);
  const Spline chord(c, K(), 1.0);
  EXPECT_DOUBLE_EQ(chord.period(), 10);
  EXPECT_EQ(s.span(3.5), 2u);
  EXPECT_EQ(s.span(6.5), 0u);
}

// ---- the decomposition --------------------------------------------------------------------

TEST(CurveDecomposition, CircleMeetsBothCriteriaWithAboutTheNeededVertices)
{
  for(std::size_t n : {8u, 12u}) {
    const std::vector<Point_2> c = ellipse(n, 1, 1);
    const std::vector<Point_2> poly = decompose_and_check(c);
    // A closed convex curve turns by 360°: at 5° per vertex that takes >= 72 vertices.
    EXPECT_GE(poly.size(), 72u);
    EXPECT_LE(poly.size(), 100u) << "far more vertices than the turning angle needs";
    // Each control point is kept as the very same point.
    const std::vector<std::size_t> pos = knot_positions(c, poly);
    for(std::size_t i = 0; i < n; ++i) EXPECT_TRUE(poly[pos[i]] == c[i]);
    // Angle criterion binding at 2°, chord error binding with a tight tolerance.
    Options o;
    o.max_turning_angle_deg = 2;
    EXPECT_GE(decompose_and_check(c, o).size(), 180u);
    Options t;
    t.max_turning_angle_deg = 45;
    t.max_chord_error = 1e-5;  // sagitta 1 - cos(a/2) <= 1e-5 needs a <= 0.009: ~700 pieces
    const std::vector<Point_2> fine = decompose_and_check(c, t);
    EXPECT_GE(fine.size(), 600u);
    EXPECT_LE(fine.size(), 1400u);
  }
}

TEST(CurveDecomposition, RefinementAloneMeetsTheCriteria)
{
  // Step 2 of the decomposition (check, then halve what fails) without the placement by
  // curvature: it must reach both criteria by itself, and needs more vertices for it (halving
  // overshoots: 45° spans become 16 pieces of 2.8°, not 10 of 4.5°).
  for(const auto& limits : {std::array<double, 2>{5, 0}, std::array<double, 2>{60, 1e-5}}) {
    const std::vector<Point_2> c = ellipse(8, 1, 1);
    const Spline s(c);
    const double tol = limits[1] > 0 ? limits[1] : 1e-3 * bbox_diagonal(c);
    const std::vector<double> params = CGAL::Quad_mesher_2::internal::Spline_decomposition<K>(
        s, limits[0] * pi / 180, tol, 1u << 20, "test").parameters(false);
    std::vector<Point_2> poly;
    std::size_t knot = 0;
    for(double u : params) {
      if(knot < c.size() && u == s.knot(knot)) {
        poly.push_back(c[knot++]);
      } else {
        const V p = s.point(u);
        poly.push_back(Point_2(p[0], p[1]));
      }
    }
    ASSERT_EQ(knot, c.size());
    EXPECT_LE(max_turning_deg(poly), limits[0] + 1e-9);
    double off = 0;
    const std::vector<double> err = chord_errors(s, c, poly, off);
    EXPECT_LE(*std::max_element(err.begin(), err.end()), tol);
    Options o;
    o.max_turning_angle_deg = limits[0];
    o.max_chord_error = limits[1];
    const std::size_t placed = CGAL::Quad_mesher_2::decompose_closed_spline<K>(c, o).size();
    EXPECT_GT(poly.size(), placed) << "placement by curvature should need fewer vertices than halving";
    std::cout << "[ vertices ] circle of 8 points, " << limits[0] << " deg, tol " << tol << ": halving " << poly.size()
              << ", by curvature " << placed << "\n";
  }
}

TEST(CurveDecomposition, ThreePointsAreEnough)
{
  // The smallest closed spline: the cyclic system is then a full 3x3 matrix (corners and
  // off-diagonals coincide), which the Sherman-Morrison solve must still handle.
  const std::vector<Point_2> c = {Point_2(0, 0), Point_2(4, 0), Point_2(1, 3)};
  const Spline s(c);
  for(std::size_t i = 0; i < 3; ++i) {
    const std::size_t prev = (i + 2) % 3;
    for(int order = 1; order <= 2; ++order) {
      const V l = s.eval(prev, s.knot(prev + 1) - s.knot(prev), order), r = s.eval(i, 0, order);
      EXPECT_NEAR(l[0], r[0], 1e-9);
      EXPECT_NEAR(l[1], r[1], 1e-9);
    }
  }
  const std::vector<Point_2> poly = decompose_and_check(c);
  EXPECT_GE(poly.size(), 72u);
  EXPECT_GT(signed_area(poly), 0);
}

TEST(CurveDecomposition, EllipseIsDenseAtTheEnds)
{
  const std::vector<Point_2> c = ellipse(24, 10, 1);
  const std::vector<Point_2> poly = decompose_and_check(c);
  // Curvature is 100 times larger at the ends (a/b^2 = 10) than at the sides (b/a^2 = 0.01).
  std::size_t ends = 0, middle = 0;
  for(const Point_2& p : poly) {
    const double x = std::abs(to_v(p)[0]);
    if(x > 9) ++ends;
    if(x < 5) ++middle;
  }
  EXPECT_GT(ends, 2 * middle) << ends << " vertices with |x| > 9, " << middle << " with |x| < 5";
  double shortest_mid = HUGE_VAL, longest_end = 0;
  for(std::size_t i = 0; i < poly.size(); ++i) {
    const V a = to_v(poly[i]), b = to_v(poly[(i + 1) % poly.size()]);
    const double l = std::hypot(b[0] - a[0], b[1] - a[1]);
    if(std::abs(a[0]) < 5 && std::abs(b[0]) < 5) shortest_mid = std::min(shortest_mid, l);
    if(std::abs(a[0]) > 9.5 && std::abs(b[0]) > 9.5) longest_end = std::max(longest_end, l);
  }
  EXPECT_GT(shortest_mid, 4 * longest_end);
}

// Sizing follows the boundary's curvature as the paper's does (§4.1, §4.2): the decomposition
// puts the spline's points closer where it bends, and the quadtree sizes cells by the points'
// spacing. An ellipse 20 by 2 bends 100 times more at its ends than at its sides: the cells at
// its boundary points are several times smaller at the ends.
TEST(CurveDecomposition, QuadtreeCellsAreSmallerWhereTheCurveBends)
{
  Domain d;
  add_loop(d, ellipse(24, 10, 1));
  const Domain r = CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options());
  CGAL::Quad_mesher_2::Quadtree_mesher_2<K> mesher(r);
  mesher.build_quadtree();
  const auto& tree = mesher.quadtree();
  double ends = 0, middle = 0;
  std::size_t n_ends = 0, n_middle = 0;
  for(const Point_2& p : r.points) {
    const double side = tree.cell_side(tree.locate(p).level), x = std::abs(to_v(p)[0]);
    if(x > 9.5) { ends += side; ++n_ends; }
    if(x < 5) { middle += side; ++n_middle; }
  }
  ASSERT_GT(n_ends, 0u);
  ASSERT_GT(n_middle, 0u);
  EXPECT_GT(middle / double(n_middle), 4 * ends / double(n_ends))
      << "mean cell side at the boundary points: " << middle / double(n_middle) << " on the sides, "
      << ends / double(n_ends) << " at the ends";
}

TEST(CurveDecomposition, RoundedSquareIsSparseOnTheSides)
{
  // Square [-5, 5]^2 with corners of radius 1: three points on each straight side, the arc
  // midpoint at each corner.
  std::vector<Point_2> c;
  const double r2 = 4 + std::sqrt(0.5);
  for(int side = 0; side < 4; ++side) {
    // Rotate the bottom side's points by side * 90°.
    const double pts[4][2] = {{-4, -5}, {0, -5}, {4, -5}, {r2, -r2}};
    for(const auto& p : pts) {
      double x = p[0], y = p[1];
      for(int k = 0; k < side; ++k) { const double t = x; x = -y; y = t; }
      c.push_back(Point_2(x, y));
    }
  }
  const std::vector<Point_2> poly = decompose_and_check(c);
  std::size_t side_middle = 0, corners = 0;
  for(const Point_2& p : poly) {
    const V v = to_v(p);
    if(std::min(std::abs(v[0]), std::abs(v[1])) < 3) ++side_middle;
    if(std::abs(v[0]) > 4 && std::abs(v[1]) > 4) ++corners;
  }
  // The corners turn by 90° each: >= 18 vertices each at 5°. The middles of the sides (6 of
  // the 8 units of straight line) carry the control points and little else.
  EXPECT_GE(corners, 4u * 15u);
  EXPECT_LE(side_middle, 4u * 6u) << side_middle << " vertices on the straight parts";
  EXPECT_GT(corners, 3 * side_middle);
}

TEST(CurveDecomposition, OrientationIsKept)
{
  for(bool cw : {false, true}) {
    const std::vector<Point_2> c = ellipse(12, 3, 2, cw);
    const std::vector<Point_2> poly = decompose_and_check(c);
    EXPECT_EQ(signed_area(poly) > 0, !cw);
    EXPECT_EQ(signed_area(c) > 0, !cw);
    EXPECT_NEAR(signed_area(poly), (cw ? -1 : 1) * pi * 3 * 2, 0.05);
  }
}

TEST(CurveDecomposition, DomainWithHole)
{
  Domain d;
  // Outer circle of radius 10 given clockwise, hole circle of radius 3 given counterclockwise:
  // extract_loops() orients them (domain on the left), and so must the result.
  const std::vector<Point_2> outer = ellipse(12, 10, 10, true), hole = ellipse(8, 3, 3, false, 1, 0);
  add_loop(d, outer);
  add_loop(d, hole);
  d.segment_markers.assign(outer.size(), 7);
  d.segment_markers.insert(d.segment_markers.end(), hole.size(), 9);
  d.points.push_back(Point_2(-6, 0.5));  // a point on no segment
  d.holes.push_back(Point_2(1, 0.25));
  d.region_attributes = { { Point_2(-6, -0.5), 3, 0.5 } };
  d.region_attribute_labels = { "1 (line 40)" };

  const Domain r = CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options());
  ASSERT_EQ(r.region_attributes.size(), 1u); // kept, and how the user knows it
  EXPECT_TRUE(r.region_attributes[0].point == d.region_attributes[0].point);
  EXPECT_EQ(r.region_attributes[0].attribute, 3);
  EXPECT_EQ(r.region_attributes[0].max_area, 0.5);
  EXPECT_EQ(r.region_attribute_labels, d.region_attribute_labels);
  ASSERT_GT(r.points.size(), d.points.size());
  for(std::size_t i = 0; i < d.points.size(); ++i) EXPECT_TRUE(r.points[i] == d.points[i]) << "point " << i << " moved";
  ASSERT_EQ(r.holes.size(), 1u);
  EXPECT_TRUE(r.holes[0] == d.holes[0]);
  EXPECT_EQ(r.segments.size(), r.points.size() - 1);  // every point but the isolated one on a loop

  const CGAL::Quad_mesher_2::Domain_loops_2<K> loops = CGAL::Quad_mesher_2::extract_loops(r);
  ASSERT_EQ(loops.loops.size(), 2u);
  // each loop's segments keep its marker (the segments are rebuilt loop by loop, outer first)
  ASSERT_EQ(r.segment_markers.size(), r.segments.size());
  for(std::size_t s = 0; s < r.segments.size(); ++s)
    EXPECT_EQ(r.segment_markers[s], s < loops.loops[0].vertices.size() ? 7 : 9) << "segment " << s;
  ASSERT_EQ(loops.isolated_points.size(), 1u);
  EXPECT_EQ(loops.isolated_points[0], d.points.size() - 1);
  const double tol = 1e-3 * bbox_diagonal(d.points);  // one absolute tolerance for both loops
  for(const auto& loop : loops.loops) {
    std::vector<Point_2> poly;
    for(std::size_t v : loop.vertices) poly.push_back(r.points[v]);
    // The segments as given run with the domain on the left: extract_loops() found them so
    // oriented and did not reverse them (it keeps the first vertex and reverses the rest).
    std::vector<Point_2> as_given;
    std::size_t v = loop.vertices[0];
    for(std::size_t k = 0; k < loop.vertices.size(); ++k) {
      as_given.push_back(r.points[v]);
      for(const auto& s : r.segments)
        if(s[0] == v) { v = s[1]; break; }
    }
    EXPECT_EQ(signed_area(as_given) > 0, loop.is_outer);
    EXPECT_EQ(signed_area(poly) > 0, loop.is_outer);
    EXPECT_LE(max_turning_deg(poly), 5 + 1e-9);
    const std::vector<Point_2>& control = loop.is_outer ? outer : hole;
    std::vector<Point_2> control_oriented(control);
    if((signed_area(control) > 0) != loop.is_outer)
      std::reverse(control_oriented.begin() + 1, control_oriented.end());
    // Start the polygon at the first control point for the measurement.
    const auto it = std::find(poly.begin(), poly.end(), control_oriented[0]);
    ASSERT_NE(it, poly.end());
    std::rotate(poly.begin(), it, poly.end());
    double off = 0;
    const std::vector<double> err = chord_errors(Spline(control_oriented), control_oriented, poly, off);
    EXPECT_LE(*std::max_element(err.begin(), err.end()), tol);
    EXPECT_LE(poly.size(), loop.is_outer ? 100u : 110u);
  }
  // A point cloud passes through unchanged.
  Domain cloud;
  cloud.points = outer;
  const Domain same = CGAL::Quad_mesher_2::decompose_domain_curves<K>(cloud, Options());
  EXPECT_EQ(same.points.size(), outer.size());
  EXPECT_TRUE(same.segments.empty());
}

// ---- errors -------------------------------------------------------------------------------

// An interface (a loop with no hole point, given hole points elsewhere) is one curve: its
// spline is decomposed once, and the result keeps it an interface.
TEST(CurveDecomposition, AnInterfaceIsDecomposedOnce)
{
  Domain d;
  add_loop(d, ellipse(12, 10, 10, true));
  const std::vector<Point_2> inclusion = ellipse(8, 3, 3, false, 1, 0);
  add_loop(d, inclusion);
  add_loop(d, { Point_2(-7, -1), Point_2(-6, -1), Point_2(-6, 0), Point_2(-7, 0) });
  d.holes.push_back(Point_2(-6.5, -0.5));
  const Domain r = CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options());
  const CGAL::Quad_mesher_2::Domain_loops_2<K> loops = CGAL::Quad_mesher_2::extract_loops(r);
  ASSERT_EQ(loops.loops.size(), 4u); // the outer loop, the interface and its twin, the hole
  EXPECT_EQ(loops.loops[1].twin, 2u);
  EXPECT_GT(loops.loops[1].vertices.size(), inclusion.size());
  EXPECT_EQ(r.segments.size(), r.points.size());
}

TEST(CurveDecomposition, ACrackKeepsItsSegments)
{
  Domain d;
  add_loop(d, ellipse(12, 10, 10, true));
  const std::size_t first = d.points.size();
  d.points.insert(d.points.end(), { Point_2(-3, 0), Point_2(0, 1), Point_2(3, 0) });
  d.segments.push_back({ first + 1, first + 2 });
  d.segments.push_back({ first, first + 1 });
  d.segment_markers.assign(d.segments.size(), 1);
  d.segment_markers.back() = 7;
  const Domain r = CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options());
  const CGAL::Quad_mesher_2::Domain_loops_2<K> loops = CGAL::Quad_mesher_2::extract_loops(r);
  ASSERT_EQ(loops.loops.size(), 2u); // the outer loop, then the crack
  EXPECT_EQ(loops.loops[1].twin, 1u);
  EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{ first, first + 1, first + 2, first + 1 }));
  ASSERT_EQ(r.segment_markers.size(), r.segments.size());
  EXPECT_EQ(r.segment_markers[r.segments.size() - 2], 7); // the crack's first segment, as given
  EXPECT_EQ(r.segment_labels.back(), "on the crack from " + std::to_string(first + 1) + " to " + std::to_string(first + 2));
}

TEST(CurveDecomposition, AJunctionIsNamedAsNotTakenYet)
{
  Domain d;
  add_loop(d, ellipse(12, 10, 10, true));
  d.segments.push_back({ 0, 6 }); // across the ellipse, between two of its vertices
  const std::string e = error_of([&] { CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options()); });
  EXPECT_NE(e.find("vertex 0 "), std::string::npos) << e;
  EXPECT_NE(e.find("joins 3 segments: curve decompositions do not take junctions"), std::string::npos) << e;
}

TEST(CurveDecomposition, DegenerateInputsAreNamed)
{
  const Options o;
  auto run = [&](const std::vector<Point_2>& c) {
    return error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(c, o); });
  };
  std::string e = run({Point_2(0, 0), Point_2(1, 0)});
  EXPECT_TRUE(contains(e, "at least 3 points, got 2")) << e;
  e = run({Point_2(0, 0), Point_2(1, 0), Point_2(1, 0), Point_2(0, 1)});
  EXPECT_TRUE(contains(e, "consecutive points 1 and 2 are both at (1, 0)")) << e;
  e = run({Point_2(0, 0), Point_2(1, 0), Point_2(0, 1), Point_2(0, 0)});
  EXPECT_TRUE(contains(e, "points 3 and 0")) << e;
  EXPECT_TRUE(contains(e, "do not repeat the first point")) << e;
  e = run({Point_2(0, 0), Point_2(1, 0), Point_2(0, 0), Point_2(1, 0)});
  EXPECT_TRUE(contains(e, "only 2")) << e;
  e = run({Point_2(0, 0), Point_2(1, 1), Point_2(3, 3), Point_2(2, 2)});
  EXPECT_TRUE(contains(e, "collinear")) << e;
  e = run({Point_2(0, 0), Point_2(2, 0), Point_2(0, 2), Point_2(2, 2)});  // a bow tie
  EXPECT_TRUE(contains(e, "control polygon is not a simple polygon")) << e;
  Options bad;
  bad.max_turning_angle_deg = 0;
  e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(ellipse(8, 1, 1), bad); });
  EXPECT_TRUE(contains(e, "max_turning_angle_deg")) << e;
  bad = Options();
  bad.max_chord_error = -1;
  e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(ellipse(8, 1, 1), bad); });
  EXPECT_TRUE(contains(e, "max_chord_error")) << e;
}

TEST(CurveDecomposition, NonFinitePointIsNamed)
{
  if(qm2_test::exact_constructions)
    GTEST_SKIP() << "EPECK cannot hold a non-finite coordinate at all (its interval filter asserts on construction)";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point_2> c = {Point_2(0, 0), Point_2(1, 0), Point_2(1, nan), Point_2(0, 1)};
  const std::string e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(c, Options()); });
  EXPECT_TRUE(contains(e, "point 2 (1, nan) has a non-finite coordinate")) << e;
  const std::vector<Point_2> inf = {Point_2(0, 0), Point_2(HUGE_VAL, 0), Point_2(0, 1)};
  EXPECT_TRUE(contains(error_of([&] { Spline s(inf); }), "point 1")) << error_of([&] { Spline s(inf); });
}

TEST(CurveDecomposition, PointBudget)
{
  Options o;
  o.max_points_per_loop = 50;  // a circle needs >= 72 at 5°
  std::string e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(ellipse(12, 1, 1), o); });
  EXPECT_TRUE(contains(e, "max_points_per_loop = 50")) << e;
  o = Options();
  o.max_chord_error = 1e-14;  // ~1e7 vertices: refused before anything is allocated
  o.max_turning_angle_deg = 90;
  o.max_points_per_loop = 100000;
  const auto t0 = std::chrono::steady_clock::now();
  e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(ellipse(12, 1, 1), o); });
  EXPECT_TRUE(contains(e, "max_points_per_loop = 100000")) << e;
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), qm2_test::time_bound(1.0));
  o.max_points_per_loop = 8;  // fewer than the control points
  e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(ellipse(12, 1, 1), o); });
  EXPECT_TRUE(contains(e, "max_points_per_loop = 8")) << e;
}

TEST(CurveDecomposition, SelfIntersectingSplineIsDetected)
{
  // A simple control polygon with a narrow slit: the spline overshoots at the slit's top
  // corners and its two sides cross.
  const std::vector<Point_2> c = {Point_2(0, 0),   Point_2(10, 0),  Point_2(10, 10), Point_2(5.1, 10),
                                  Point_2(5.1, 1), Point_2(4.9, 1), Point_2(4.9, 10), Point_2(0, 10)};
  const std::string e = error_of([&] { CGAL::Quad_mesher_2::decompose_closed_spline<K>(c, Options()); });
  EXPECT_TRUE(contains(e, "crosses or touches itself")) << e;
  EXPECT_TRUE(contains(e, "cross")) << e;

  // The same loop in a domain: named by its first point.
  Domain d;
  add_loop(d, c);
  const std::string e2 = error_of([&] { CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options()); });
  EXPECT_TRUE(contains(e2, "outer loop of 8 control points starting at point 0 (0, 0)")) << e2;
  EXPECT_TRUE(contains(e2, "crosses or touches itself")) << e2;
}

TEST(CurveDecomposition, SplinesCrossingEachOtherAreDetected)
{
  // The hole's control polygon, the square [1, 3]^2, lies inside the outer one, whose left
  // side x = 0.8 is held straight by many points; the hole's spline bulges out to x ~ 0.6.
  Domain d;
  std::vector<Point_2> outer = {Point_2(0.8, 0), Point_2(10, 0), Point_2(10, 10), Point_2(0.8, 10)};
  for(int y = 9; y >= 1; --y) outer.push_back(Point_2(0.8, y));
  const std::vector<Point_2> hole = {Point_2(1, 1), Point_2(3, 1), Point_2(3, 3), Point_2(1, 3)};
  add_loop(d, outer);
  add_loop(d, hole);
  d.holes.push_back(Point_2(2, 2));
  ASSERT_NO_THROW(CGAL::Quad_mesher_2::extract_loops(d));
  const std::string e = error_of([&] { CGAL::Quad_mesher_2::decompose_domain_curves<K>(d, Options()); });
  EXPECT_TRUE(contains(e, "after curve decomposition the boundary is not valid")) << e;
  EXPECT_TRUE(contains(e, "cross")) << e;
}

// ---- size and time ------------------------------------------------------------------------

TEST(CurveDecomposition, ThousandPointsTiming)
{
  std::vector<Point_2> c;
  for(int i = 0; i < 1000; ++i) {
    const double t = 2 * pi * i / 1000, r = 1 + 0.3 * std::sin(7 * t);
    c.push_back(Point_2(r * std::cos(t), r * std::sin(t)));
  }
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<Point_2> poly = CGAL::Quad_mesher_2::decompose_closed_spline<K>(c, Options());
  const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::cout << "[ timing   ] decompose_closed_spline, 1000 control points -> " << poly.size() << " vertices: " << secs
            << " s\n";
  EXPECT_LT(secs, qm2_test::time_bound(5.0));
  EXPECT_GE(poly.size(), 1000u);
  EXPECT_LE(max_turning_deg(poly), 5 + 1e-9);
  // The same with 100 control points: far fewer user points, the criteria still hold.
  std::vector<Point_2> c100;
  for(std::size_t i = 0; i < 1000; i += 10) c100.push_back(c[i]);
  const std::vector<Point_2> p100 = decompose_and_check(c100);
  EXPECT_GE(p100.size(), 100u);
}

} // namespace qm2_test_curves
