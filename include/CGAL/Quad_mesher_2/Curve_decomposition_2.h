// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_CURVE_DECOMPOSITION_2_H
#define CGAL_QUAD_MESHER_2_CURVE_DECOMPOSITION_2_H

// Curve decomposition (Liang, Ebeida and Zhang, IMR 2009, section 4.1): a closed smooth curve
// given as a cubic spline is replaced by a polygon whose neighbouring segments turn by at most
// a few degrees and whose segments stay within a tolerance of the curve, so that the vertices
// are dense where the curve bends and sparse where it is straight. The mesher then treats the
// polygon like any other boundary.

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The closed (periodic) C2 cubic spline that interpolates a cyclic sequence of points
/// `P_0, ..., P_{n-1}` (it passes through every point, in order, and closes from `P_{n-1}`
/// back to `P_0`).
///
/// **Parameterisation.** The knot spacing of the span `P_i -> P_{i+1}` is
/// `h_i = |P_{i+1} - P_i|^exponent`. The default exponent 0.5 is the *centripetal*
/// parameterisation (E. T. Y. Lee, CAD 21(6), 1989); 1 is chord-length, 0 uniform. Why
/// centripetal: with uneven spacing (a short span next to a long one), a uniform spline
/// overshoots into loops and cusps at the short span; chord-length removes most of that but
/// gives the long spans so much parameter that the curve bulges at sharp turns; centripetal
/// sits between the two and, for Catmull-Rom curves, provably has no cusps or
/// self-intersections within a span (Yuksel, Schaefer and Keyser, CAD 43(7), 2011). For the
/// global C2 spline used here that is a tendency, not a guarantee, which is why
/// `decompose_closed_spline()` checks the resulting polygon with exact predicates.
///
/// **Arithmetic.** The spline is computed and evaluated in `double` (coordinates converted with
/// `CGAL::to_double`): it is a smooth approximation of the user's curve, not a combinatorial
/// object, and the mesher only needs its vertices. The polygons built from it hold kernel
/// points (the user's own points, exactly, plus points constructed from doubles), and every
/// decision on them (simplicity, orientation) is made with the kernel's exact predicates.
///
/// **Solver.** The second derivatives at the knots solve a cyclic tridiagonal system
/// (strictly diagonally dominant), solved in O(n) by the Thomas algorithm with a
/// Sherman-Morrison correction for the two corner entries.
///
/// \throws Meshing_error naming the point for fewer than 3 points, fewer than 3 distinct
/// points, two consecutive points at the same place (including the last and the first: do not
/// repeat the first point at the end), or a non-finite coordinate.
template <class GeomTraits>
class Closed_cubic_spline_2
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename Geom_traits::Point_2 Point_2;
  /// A point or a derivative, `{x, y}`, in double.
  typedef std::array<double, 2> Vector;

  /// The spline through `points` (in order, closed). `exponent` in [0, 1] selects the
  /// parameterisation: 0.5 centripetal (default), 1 chord-length, 0 uniform.
  explicit Closed_cubic_spline_2(const std::vector<Point_2>& points, const Geom_traits& traits = Geom_traits(),
                                 double exponent = 0.5)
  {
    const std::size_t n = points.size();
    if(!(exponent >= 0 && exponent <= 1))
      throw Meshing_error("closed cubic spline: the parameterisation exponent must be in [0, 1], got " +
                          internal::loops_format_double(exponent));
    if(n < 3)
      throw Meshing_error("a closed cubic spline needs at least 3 points, got " + std::to_string(n));
    m_p.resize(n);
    for(std::size_t i = 0; i < n; ++i) {
      const double x = CGAL::to_double(traits.compute_x_2_object()(points[i]));
      const double y = CGAL::to_double(traits.compute_y_2_object()(points[i]));
      if(!std::isfinite(x) || !std::isfinite(y))
        throw Meshing_error("closed cubic spline: point " + std::to_string(i) + " (" + internal::loops_format_double(x) +
                            ", " + internal::loops_format_double(y) + ") has a non-finite coordinate");
      m_p[i] = {x, y};
    }
    // Consecutive points must differ, exactly and in double: a zero-length span has no
    // parameter interval (h = 0) and the system would divide by zero.
    const auto equal = traits.equal_2_object();
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      if(equal(points[i], points[j]) || (m_p[i][0] == m_p[j][0] && m_p[i][1] == m_p[j][1]))
        throw Meshing_error("closed cubic spline: consecutive points " + std::to_string(i) + " and " + std::to_string(j) +
                            " are both at " + internal::loops_format_point(points[i], traits) +
                            (j == 0 ? " (the loop closes by itself: do not repeat the first point at the end)"
                                    : " (remove the repeated point)"));
    }
    {
      std::vector<std::size_t> order(n);
      for(std::size_t i = 0; i < n; ++i) order[i] = i;
      const auto less = traits.less_xy_2_object();
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return less(points[a], points[b]); });
      std::size_t distinct = 1;
      for(std::size_t k = 1; k < n; ++k)
        if(!equal(points[order[k - 1]], points[order[k]])) ++distinct;
      if(distinct < 3)
        throw Meshing_error("a closed cubic spline needs at least 3 distinct points; the " + std::to_string(n) +
                            " points (point 0 at " + internal::loops_format_point(points[0], traits) + ") have only " +
                            std::to_string(distinct));
    }
    // Knots.
    m_h.resize(n);
    m_u.resize(n + 1);
    m_u[0] = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const double d = std::hypot(m_p[j][0] - m_p[i][0], m_p[j][1] - m_p[i][1]);
      m_h[i] = std::pow(d, exponent);
      if(!(m_h[i] > 0) || !std::isfinite(m_h[i]))
        throw Meshing_error("closed cubic spline: the span from point " + std::to_string(i) + " " +
                            internal::loops_format_point(points[i], traits) + " to point " + std::to_string(j) +
                            " has no usable length in double");
      m_u[i + 1] = m_u[i] + m_h[i];
    }
    solve_second_derivatives();
  }

  /// The number of interpolated points, which is also the number of spans.
  std::size_t number_of_points() const { return m_p.size(); }
  /// The parameter of point `i`, for `i` in [0, n]; `knot(n) == period()`. Span `i` runs over
  /// `[knot(i), knot(i+1)]` from point `i` to point `(i+1) % n`.
  double knot(std::size_t i) const { return m_u[i]; }
  /// The parameter length of the closed curve; parameters are taken modulo it.
  double period() const { return m_u.back(); }
  /// The span that contains parameter `u` (after reduction modulo the period).
  std::size_t span(double u) const { return locate(u).first; }

  /// The point at parameter `u`.
  Vector point(double u) const { const auto s = locate(u); return eval(s.first, s.second, 0); }
  /// The first derivative with respect to the parameter at `u`.
  Vector derivative(double u) const { const auto s = locate(u); return eval(s.first, s.second, 1); }
  /// The second derivative with respect to the parameter at `u`.
  Vector second_derivative(double u) const { const auto s = locate(u); return eval(s.first, s.second, 2); }

  /// \cond SKIP_IN_MANUAL
  /// Span-local evaluation without the search: `t` in [0, h_i] from the start of span `i`;
  /// `order` 0, 1 or 2 for the point or a derivative.
  Vector eval(std::size_t i, double t, int order) const
  {
    const std::size_t j = (i + 1 == m_p.size()) ? 0 : i + 1;
    const double h = m_h[i], s = h - t;
    Vector r;
    for(int c = 0; c < 2; ++c) {
      const double Mi = m_m[i][c], Mj = m_m[j][c];
      const double A = m_p[i][c] / h - Mi * h / 6, B = m_p[j][c] / h - Mj * h / 6;
      if(order == 0)
        r[c] = (Mi * s * s * s + Mj * t * t * t) / (6 * h) + A * s + B * t;
      else if(order == 1)
        r[c] = (Mj * t * t - Mi * s * s) / (2 * h) - A + B;
      else
        r[c] = (Mi * s + Mj * t) / h;
    }
    return r;
  }
  /// \endcond

private:
  std::pair<std::size_t, double> locate(double u) const
  {
    const double L = period();
    double w = std::fmod(u, L);
    if(w < 0) w += L;
    std::size_t i = static_cast<std::size_t>(std::upper_bound(m_u.begin(), m_u.end(), w) - m_u.begin());
    i = (i == 0) ? 0 : i - 1;
    if(i >= m_p.size()) i = m_p.size() - 1;
    return {i, (std::min)(w - m_u[i], m_h[i])};
  }

  // C2 continuity at knot i with second derivatives M:
  //   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1}
  //     = 6 ((P_{i+1} - P_i) / h_i - (P_i - P_{i-1}) / h_{i-1}),   indices modulo n.
  // Cyclic tridiagonal: sub-diagonal a_i = h_{i-1}, diagonal b_i, super-diagonal c_i = h_i,
  // corners A[0][n-1] = A[n-1][0] = h_{n-1}. Sherman-Morrison (Numerical Recipes, `cyclic`):
  // solve the tridiagonal matrix with b_0 and b_{n-1} modified, once for the right-hand side
  // and once for the correction vector, then combine. The matrix is strictly diagonally
  // dominant (b_i = 2 (a_i + c_i)) before and after the modification, so the Thomas algorithm
  // needs no pivoting.
  void solve_second_derivatives()
  {
    const std::size_t n = m_p.size();
    std::vector<double> a(n), b(n), c(n);
    std::vector<std::array<double, 3> > r(n);  // x, y, and the correction vector
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t im = (i + n - 1) % n, ip = (i + 1) % n;
      a[i] = m_h[im];
      c[i] = m_h[i];
      b[i] = 2 * (m_h[im] + m_h[i]);
      for(int k = 0; k < 2; ++k)
        r[i][k] = 6 * ((m_p[ip][k] - m_p[i][k]) / m_h[i] - (m_p[i][k] - m_p[im][k]) / m_h[im]);
      r[i][2] = 0;
    }
    const double alpha = m_h[n - 1], beta = m_h[n - 1];  // A[n-1][0], A[0][n-1]
    const double gamma = -b[0];
    b[0] -= gamma;
    b[n - 1] -= alpha * beta / gamma;
    r[0][2] = gamma;
    r[n - 1][2] = alpha;
    // Thomas algorithm on the three right-hand sides at once (a[0] and c[n-1] unused).
    std::vector<double> cp(n);
    cp[0] = c[0] / b[0];
    for(int k = 0; k < 3; ++k) r[0][k] /= b[0];
    for(std::size_t i = 1; i < n; ++i) {
      const double m = b[i] - a[i] * cp[i - 1];
      cp[i] = c[i] / m;
      for(int k = 0; k < 3; ++k) r[i][k] = (r[i][k] - a[i] * r[i - 1][k]) / m;
    }
    for(std::size_t i = n - 1; i-- > 0;)
      for(int k = 0; k < 3; ++k) r[i][k] -= cp[i] * r[i + 1][k];
    const double denom = 1 + r[0][2] + beta * r[n - 1][2] / gamma;
    m_m.resize(n);
    for(int k = 0; k < 2; ++k) {
      const double fact = (r[0][k] + beta * r[n - 1][k] / gamma) / denom;
      for(std::size_t i = 0; i < n; ++i) m_m[i][k] = r[i][k] - fact * r[i][2];
    }
  }

  std::vector<Vector> m_p;  // the points, in double
  std::vector<Vector> m_m;  // second derivatives at the knots
  std::vector<double> m_h;  // span parameter lengths
  std::vector<double> m_u;  // knots, n + 1 of them
};

/// \ingroup PkgQuadMesher2Ref
/// The criteria of the curve decomposition (paper, section 4.1).
struct Curve_decomposition_options
{
  /// The largest angle, in degrees, by which a segment of the polygon may turn from the
  /// previous one (the paper's criterion 1). In (0, 90].
  double max_turning_angle_deg = 5;
  /// The largest distance between a piece of the curve and the segment that replaces it (the
  /// paper's criterion 2). 0 means 1e-3 of the diagonal of the bounding box of the input
  /// points (of the control points for `decompose_closed_spline()`, of all the domain's
  /// points for `decompose_domain_curves()`).
  double max_chord_error = 0;
  /// A guard against a tolerance far too small for the domain: decomposing one loop into more
  /// vertices than this is an error rather than an exhausted memory.
  std::size_t max_points_per_loop = std::size_t(1) << 20;
};

namespace internal {

template <class K>
double curves_bbox_diagonal(const std::vector<typename K::Point_2>& pts, const K& traits)
{
  if(pts.empty()) return 0;
  const auto bbox = traits.construct_bbox_2_object();
  Bbox_2 b = bbox(pts[0]);
  for(const auto& p : pts) b += bbox(p);
  return std::hypot(b.xmax() - b.xmin(), b.ymax() - b.ymin());
}

/// Orientation of a simple polygon, from its lexicographically smallest vertex (where a simple
/// polygon turns strictly), with the kernel's exact predicate.
template <class K>
Orientation curves_simple_polygon_orientation(const std::vector<typename K::Point_2>& poly, const K& traits)
{
  const auto less_xy = traits.less_xy_2_object();
  const std::size_t n = poly.size();
  std::size_t k = 0;
  for(std::size_t i = 1; i < n; ++i)
    if(less_xy(poly[i], poly[k])) k = i;
  return traits.orientation_2_object()(poly[(k + n - 1) % n], poly[k], poly[(k + 1) % n]);
}

/// A polygon (no repeated closing vertex) as a one-loop domain, for `extract_loops()`.
template <class K>
Domain_2<K> curves_polygon_domain(const std::vector<typename K::Point_2>& poly)
{
  Domain_2<K> d;
  d.points = poly;
  const std::size_t n = poly.size();
  d.segments.reserve(n);
  for(std::size_t i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n});
  return d;
}

/// The segment labels of a decomposed loop whose control point `k` is at position `knots[k]`
/// (`knots[0] == 0`) of its `size` vertices: each segment is named by the span of the spline it
/// lies on, from one control point to the next as `control_labels` name them.
inline std::vector<std::string> curves_span_labels(const std::vector<std::size_t>& knots, std::size_t size,
                                                   const std::vector<std::string>& control_labels)
{
  CGAL_precondition(!knots.empty() && knots[0] == 0);
  const std::size_t n = knots.size();
  std::vector<std::string> labels;
  labels.reserve(size);
  for(std::size_t k = 0; k < n; ++k) {
    const std::string span = "on the spline from " + control_labels[k] + " to " + control_labels[(k + 1) % n];
    const std::size_t end = k + 1 < n ? knots[k + 1] : size;
    for(std::size_t v = knots[k]; v < end; ++v) labels.push_back(span);
  }
  return labels;
}

/// The work of `decompose_closed_spline()`, on validated options with a resolved tolerance,
/// in two steps: vertices placed by curvature, then chords split until they pass. Works on
/// the spline's points and derivatives as the approximate kernel's, in doubles.
template <class K>
class Spline_decomposition
{
  typedef Approximate_kernel::Point_2 P;
  typedef Approximate_kernel::Vector_2 V;
  typedef Closed_cubic_spline_2<K> Spline;

public:
  Spline_decomposition(const Spline& spline, double max_angle, double tol, std::size_t max_points,
                       const std::string& what)
    : m_spline(spline), m_max_angle(max_angle), m_tol(tol), m_max_points(max_points), m_what(what)
  {}

  /// For each output vertex in order, its parameter on the spline; the vertex of parameter
  /// `knot(i)` is control point `i`. `place_by_curvature == false` skips step 1 (the spans are
  /// then only halved until they pass: a test of step 2 alone).
  std::vector<double> parameters(bool place_by_curvature = true) const
  {
    std::vector<double> params = placed_by_curvature(place_by_curvature);
    for(;;) {
      const std::vector<char> split = chords_to_split(params);
      if(std::find(split.begin(), split.end(), 1) == split.end()) return params;
      params = split_chords(params, split);
    }
  }

private:
  V as_vector(const typename Spline::Vector& d) const { return V(d[0], d[1]); }
  P point_at(double u) const
  {
    const auto p = m_spline.point(u);
    return P(p[0], p[1]);
  }
  // the parameter where chord c, from vertex c, ends
  double param_end(const std::vector<double>& params, std::size_t c) const
  {
    return c + 1 < params.size() ? params[c + 1] : m_spline.period();
  }

  // ---- 1. placement by curvature --------------------------------------------------------
  // A chord over a piece of curve turns from its neighbour by about the tangent turning over
  // the piece (exactly so on a circle), and deviates from the piece by about k L^2 / 8 (k the
  // curvature, L the length). So the number of pieces needed per unit parameter is about
  //   g(u) = max( k |S'| / angle,  |S'| sqrt(k / (8 tol)) ),
  // and placing vertices at equal increments of the integral of g puts them densely where
  // the curve bends and sparsely where it is straight. The targets get a 10% margin so that
  // the check in step 2 rarely has to refine.
  static constexpr int samples = 32; // per span, for the integral of g (trapezoid rule)

  // the integral of g over span i at its samples, from 0
  std::vector<double> integral_of_pieces(std::size_t i) const
  {
    const double angle_target = 0.9 * m_max_angle, tol_target = 0.9 * m_tol;
    std::vector<double> cumulative(samples + 1, 0.0);
    const double h = m_spline.knot(i + 1) - m_spline.knot(i);
    double prev = 0;
    for(int k = 0; k <= samples; ++k) {
      const double t = h * k / samples;
      const V d1 = as_vector(m_spline.eval(i, t, 1)), d2 = as_vector(m_spline.eval(i, t, 2));
      const double squared_speed = d1.squared_length(), speed = std::sqrt(squared_speed);
      double g = 0;
      if(speed > 0) {
        const double kappa_speed = std::abs(CGAL::determinant(d1, d2)) / squared_speed; // k |S'|
        g = (std::max)(kappa_speed / angle_target, std::sqrt(kappa_speed * speed / (8 * tol_target)));
      }
      if(k > 0) cumulative[k] = cumulative[k - 1] + 0.5 * (prev + g) * (h / samples);
      prev = g;
    }
    return cumulative;
  }

  // the knots and, between them, the vertices at equal increments of each span's integral
  std::vector<double> placed_by_curvature(bool by_curvature) const
  {
    const std::size_t n = m_spline.number_of_points();
    std::vector<std::vector<double>> cumulative(n);
    std::vector<std::size_t> pieces(n);
    double total = 0;
    for(std::size_t i = 0; i < n; ++i) {
      cumulative[i] = integral_of_pieces(i);
      const double need = by_curvature ? std::ceil(cumulative[i][samples]) : 1.0;
      total += (std::max)(1.0, need);
      if(!(total <= static_cast<double>(m_max_points))) // also catches NaN
        throw Meshing_error(m_what + ": decomposing it needs more than max_points_per_loop = " + std::to_string(m_max_points) +
                            " vertices (estimated before refinement); raise the limit or loosen max_chord_error / max_turning_angle_deg");
      pieces[i] = static_cast<std::size_t>((std::max)(1.0, need));
    }
    std::vector<double> params;
    params.reserve(static_cast<std::size_t>(total));
    for(std::size_t i = 0; i < n; ++i)
      place_in_span(i, cumulative[i], pieces[i], params);
    return params;
  }

  // appends span i's knot and its other `pieces - 1` vertices to params
  void place_in_span(std::size_t i, const std::vector<double>& c, std::size_t pieces, std::vector<double>& params) const
  {
    const double u0 = m_spline.knot(i), u1 = m_spline.knot(i + 1), h = u1 - u0;
    params.push_back(u0);
    int k = 0;
    for(std::size_t m = 1; m < pieces; ++m) {
      const double target = c[samples] * static_cast<double>(m) / static_cast<double>(pieces);
      while(k < samples - 1 && c[k + 1] < target) ++k;
      const double dc = c[k + 1] - c[k];
      const double f = dc > 0 ? (target - c[k]) / dc : 0.5;
      const double u = u0 + h * (k + (std::min)(1.0, (std::max)(0.0, f))) / samples;
      if(u > params.back() && u < u1) params.push_back(u); // strictly increasing, knots apart
    }
  }

  // ---- 2. check and refine ----------------------------------------------------------------
  // Each chord: its error, sampled at interior points (the pieces turn by a few degrees at
  // most, so the curve is a shallow arc over a chord and the samples find its maximum
  // distance); each pair of consecutive chords: the angle between them. A chord whose error
  // is too large, and both chords at a vertex that turns too much, are split at their
  // parameter midpoint. Vertices are only ever added, so the control points stay. Both are
  // measures against thresholds, taken in doubles.
  std::vector<char> chords_to_split(const std::vector<double>& params) const
  {
    const int error_samples = 16;
    const std::size_t m = params.size();
    std::vector<P> pts(m);
    for(std::size_t v = 0; v < m; ++v) pts[v] = point_at(params[v]);
    std::vector<char> split(m, 0);
    for(std::size_t c = 0; c < m; ++c) {
      const std::size_t d = (c + 1) % m;
      const double ua = params[c], ub = param_end(params, c);
      const Approximate_kernel::Segment_2 chord(pts[c], pts[d]);
      double squared_err = 0;
      for(int k = 1; k < error_samples; ++k)
        squared_err = (std::max)(squared_err, CGAL::squared_distance(point_at(ua + (ub - ua) * k / error_samples), chord));
      if(squared_err > m_tol * m_tol) split[c] = 1;
      const std::size_t e = (d + 1) % m;
      const V c1 = pts[d] - pts[c], c2 = pts[e] - pts[d];
      const double turn = std::atan2(std::abs(CGAL::determinant(c1, c2)), CGAL::scalar_product(c1, c2)); // in [0, pi]
      if(turn > m_max_angle) split[c] = split[d] = 1;
    }
    return split;
  }

  // params with the chords marked in `split` halved at their parameter midpoint
  std::vector<double> split_chords(const std::vector<double>& params, const std::vector<char>& split) const
  {
    const double min_piece = m_spline.period() * std::ldexp(1.0, -45);
    std::vector<double> np;
    np.reserve(2 * params.size());
    for(std::size_t c = 0; c < params.size(); ++c) {
      np.push_back(params[c]);
      if(!split[c]) continue;
      const double ua = params[c], ub = param_end(params, c), mid = 0.5 * (ua + ub);
      if(ub - ua < min_piece || !(mid > ua && mid < ub)) {
        const P p = point_at(ua);
        throw Meshing_error(m_what + ": cannot meet the turning angle or the chord error near (" + loops_format_double(p.x()) +
                            ", " + loops_format_double(p.y()) +
                            "), where the spline has a cusp or a kink; move or add control points there");
      }
      np.push_back(mid);
    }
    if(np.size() > m_max_points)
      throw Meshing_error(m_what + ": decomposing it needs more than max_points_per_loop = " + std::to_string(m_max_points) +
                          " vertices; raise the limit or loosen max_chord_error / max_turning_angle_deg");
    return np;
  }

  const Spline& m_spline;
  const double m_max_angle, m_tol;
  const std::size_t m_max_points;
  const std::string m_what;
};

/// Decomposes one closed spline into a polygon (kernel points) and checks the polygon with
/// exact predicates: simple, and oriented like the control polygon. `tol` 0 means 1e-3 of the
/// control points' bounding-box diagonal. `what` names the loop in messages, `control_labels`
/// its control points (new vertices are "new", segments named by their span). `check_control` validates the control polygon first (the domain path has done
/// that already with `extract_loops()`). `knot_index`, if given, receives the output index of
/// every control point.
template <class K>
std::vector<typename K::Point_2> curves_decompose_loop(const std::vector<typename K::Point_2>& control, double max_angle_deg,
                                                       double tol, std::size_t max_points, const K& traits,
                                                       const std::string& what,
                                                       const std::vector<std::string>& control_labels, bool check_control,
                                                       std::vector<std::size_t>* knot_index)
{
  typedef typename K::Point_2 Point_2;
  const Closed_cubic_spline_2<K> spline(control, traits);  // validates the points
  const std::size_t n = control.size();
  {
    // A flat control polygon has a flat spline (each coordinate is a linear function of the
    // other), which encloses nothing.
    const auto orient = traits.orientation_2_object();
    bool flat = true;
    for(std::size_t k = 2; k < n && flat; ++k) flat = (orient(control[0], control[1], control[k]) == COLLINEAR);
    if(flat)
      throw Meshing_error(what + ": all " + std::to_string(n) +
                          " control points are collinear, so the closed spline through them encloses no area");
  }
  if(check_control) {
    try {
      extract_loops(curves_polygon_domain<K>(control), traits);
    } catch(const Meshing_error& e) {
      throw Meshing_error(what + ": the control polygon is not a simple polygon: " + e.what());
    }
  }
  if(n > max_points)
    throw Meshing_error(what + ": " + std::to_string(n) + " control points are more than max_points_per_loop = " +
                        std::to_string(max_points));
  if(tol == 0) tol = 1e-3 * curves_bbox_diagonal(control, traits);  // > 0: not all collinear
  const double max_angle = max_angle_deg * std::acos(-1.0) / 180;
  const std::vector<double> params = Spline_decomposition<K>(spline, max_angle, tol, max_points, what).parameters();

  std::vector<Point_2> poly;
  poly.reserve(params.size());
  std::vector<std::size_t> knots;
  knots.reserve(n);
  const auto construct = traits.construct_point_2_object();
  std::size_t next_knot = 0;
  for(double u : params) {
    if(next_knot < n && u == spline.knot(next_knot)) {  // the user's point, exactly
      knots.push_back(poly.size());
      poly.push_back(control[next_knot++]);
    } else {
      const std::array<double, 2> p = spline.point(u);
      poly.push_back(construct(p[0], p[1]));
    }
  }
  CGAL_postcondition(next_knot == n);

  // The spline of a simple control polygon can still cross itself where the points are
  // very unevenly spaced (the overshoot of a C2 curve at a hairpin), and the rounding of the
  // double evaluation can make two nearby pieces touch. Either way the polygon is not a
  // boundary: check it with the exact predicates of extract_loops(), whose messages name the
  // user's points and the spans between them.
  Domain_2<K> decomposed = curves_polygon_domain<K>(poly);
  decomposed.point_labels.assign(poly.size(), "new");
  for(std::size_t k = 0; k < n; ++k) decomposed.point_labels[knots[k]] = control_labels[k];
  decomposed.segment_labels = curves_span_labels(knots, poly.size(), control_labels);
  try {
    extract_loops(decomposed, traits);
  } catch(const Meshing_error& e) {
    throw Meshing_error(what + ": the cubic spline through the control points crosses or touches itself (its control "
                        "polygon is simple, but the curve overshoots where the points are unevenly spaced); add control "
                        "points there or space them more evenly. In the decomposition into " +
                        std::to_string(poly.size()) + " segments: " + e.what());
  }
  // Same cyclic order of the control points on both simple polygons; check that the curve did
  // not turn inside out all the same (it would reverse the loop's side of the domain).
  if(curves_simple_polygon_orientation(poly, traits) != curves_simple_polygon_orientation(control, traits))
    throw Meshing_error(what + ": the cubic spline through the control points runs around the other way than its "
                        "control polygon; add control points or space them more evenly");
  if(knot_index) *knot_index = std::move(knots);
  return poly;
}

inline void curves_check_options(const Curve_decomposition_options& o)
{
  if(!(o.max_turning_angle_deg > 0 && o.max_turning_angle_deg <= 90))
    throw Meshing_error("curve decomposition: max_turning_angle_deg must be in (0, 90], got " +
                        loops_format_double(o.max_turning_angle_deg));
  if(!(o.max_chord_error >= 0 && std::isfinite(o.max_chord_error)))
    throw Meshing_error("curve decomposition: max_chord_error must be finite and >= 0 (0: 1e-3 of the bounding-box "
                        "diagonal), got " + loops_format_double(o.max_chord_error));
}

/// Copies the segments of crack `loop` (an open polyline, see `Boundary_loop_2::twin`) into
/// `out` with their markers: the decomposition rounds closed loops only.
template <class K>
void curves_keep_crack(const Domain_2<K>& domain, const Boundary_loop_2<K>& loop, const std::vector<int>& markers,
                       Domain_2<K>& out)
{
  const std::vector<std::size_t>& v = loop.vertices;
  for(std::size_t k = 0; k < v.size() / 2; ++k) { // along the polyline, not back
    out.segments.push_back({ v[k], v[k + 1] });
    out.segment_labels.push_back("on the crack from " + domain.point_label(v[k]) + " to " + domain.point_label(v[k + 1]));
    if(!domain.segment_markers.empty()) out.segment_markers.push_back(markers[k]);
  }
}

} // namespace internal

/// \ingroup PkgQuadMesher2Ref
/// Decomposes the closed cubic spline through `control` (see `Closed_cubic_spline_2`,
/// centripetal parameterisation) into a polygon (paper, section 4.1), returned as its
/// vertices in order without the first repeated at the end:
/// - consecutive segments turn by at most `options.max_turning_angle_deg`;
/// - each segment stays within `options.max_chord_error` of the piece of spline it replaces
///   (measured by sampling the piece);
/// - the vertices follow the control points' order, so the polygon has the control polygon's
///   orientation, and every control point is a vertex, exactly (the user's points are kept,
///   not recomputed from the spline); the other vertices are computed in double and
///   converted to kernel points.
///
/// The vertices are placed by curvature (dense where the spline bends, sparse where it is
/// straight), then every segment and every pair of consecutive segments is checked and the
/// pieces that fail are halved until all pass.
///
/// The control polygon must be simple. The result is checked with exact predicates
/// (`extract_loops()`) to be a simple polygon with the control polygon's orientation.
///
/// \throws Meshing_error for invalid points (see `Closed_cubic_spline_2`), collinear
/// points, a control polygon that is not simple, invalid options, more than
/// `options.max_points_per_loop` vertices, a cusp where the criteria cannot be met, and a
/// spline that crosses or touches itself.
template <class K>
std::vector<typename K::Point_2> decompose_closed_spline(const std::vector<typename K::Point_2>& control,
                                                         const Curve_decomposition_options& options,
                                                         const K& traits = K())
{
  internal::curves_check_options(options);
  std::vector<std::string> positions;  // as `Closed_cubic_spline_2` names the points
  positions.reserve(control.size());
  for(std::size_t i = 0; i < control.size(); ++i) positions.push_back(std::to_string(i));
  return internal::curves_decompose_loop(control, options.max_turning_angle_deg, options.max_chord_error,
                                         options.max_points_per_loop,
                                         traits, "closed spline of " + std::to_string(control.size()) + " points",
                                         positions, true, nullptr);
}

/// \ingroup PkgQuadMesher2Ref
/// Reads every boundary loop of `domain` (as found and oriented by `extract_loops()`) as the
/// control points of a closed cubic spline and returns the domain with each loop replaced by
/// the spline's decomposition (`decompose_closed_spline()`).
///
/// The returned domain keeps all of `domain.points` at their indices and with their labels
/// (so control points and points on no segment keep their numbers and lines in messages) and
/// appends the new vertices, labelled `new`; its segments are rebuilt loop by loop, with the
/// domain on the left of each (outer loops counterclockwise, holes clockwise; the paper lists
/// its curves clockwise, this package's convention is the one `extract_loops()` normalises
/// to), each labelled by the span of the spline it lies on (`on the spline from 1 (line 2) to
/// 2 (line 3)`) and carrying the marker of the control polygon's segment its span replaces
/// (if `domain.segment_markers` is not empty), and its hole points are `domain.holes`, with
/// their labels. A point cloud (no segments) is returned unchanged. The default tolerance is
/// 1e-3 of the diagonal of the bounding box of all the domain's points, so that every loop is
/// held to the same absolute error.
///
/// A crack (an open polyline, see `Boundary_loop_2::twin`) keeps its segments as they are,
/// labelled `on the crack from 1 (line 2) to 2 (line 3)`.
///
/// The result is validated with `extract_loops()`: each spline alone must be simple, and the
/// splines must not cross one another or pass over a hole point or a point on no segment
/// (possible where the curve bulges beyond its control polygon).
///
/// \throws Meshing_error from `extract_loops()` on the input, from the decomposition of a loop
/// (naming the loop by its first vertex), or when the decomposed loops are not a valid
/// boundary.
template <class K>
Domain_2<K> decompose_domain_curves(const Domain_2<K>& domain, const Curve_decomposition_options& options,
                                    const K& traits = K())
{
  internal::curves_check_options(options);
  const Domain_loops_2<K> loops = extract_loops(domain, traits);
  internal::reject_junctions(domain, "curve decompositions");
  if(loops.loops.empty()) return domain;
  double tol = options.max_chord_error;
  if(tol == 0) tol = 1e-3 * internal::curves_bbox_diagonal(domain.points, traits);

  // Messages name the input's points, segments and hole points as the user knows them (its
  // labels), the new vertices "new", and the new segments by the span they lie on.
  Domain_2<K> out;
  out.points = domain.points;
  out.holes = domain.holes;
  out.every_hole_marked = domain.every_hole_marked;
  out.hole_labels = domain.hole_labels;
  out.region_attributes = domain.region_attributes;
  out.region_attribute_labels = domain.region_attribute_labels;
  out.point_labels.reserve(domain.points.size());
  for(std::size_t i = 0; i < domain.points.size(); ++i) out.point_labels.push_back(domain.point_label(i));
  // each new segment keeps the marker of the control polygon's edge its span replaces
  const std::vector<std::vector<int>> edge_markers = internal::loop_edge_markers(domain, loops);
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const Boundary_loop_2<K>& loop = loops.loops[l];
    if(loop.twin < l) continue; // an interface is one curve, decomposed from its first side
    if(loop.twin == l) { // a crack is no closed curve: its segments stay as they are
      internal::curves_keep_crack(domain, loop, edge_markers[l], out);
      continue;
    }
    std::vector<typename K::Point_2> control;
    std::vector<std::string> control_labels;
    control.reserve(loop.vertices.size());
    control_labels.reserve(loop.vertices.size());
    for(std::size_t v : loop.vertices) {
      control.push_back(domain.points[v]);
      control_labels.push_back(out.point_labels[v]);
    }
    const std::string what = std::string(loop.is_outer ? "outer" : "hole") + " loop of " +
                             std::to_string(control.size()) + " control points starting at point " +
                             control_labels[0] + " " + internal::loops_format_point(control[0], traits);
    std::vector<std::size_t> knot_index;
    const std::vector<typename K::Point_2> poly = internal::curves_decompose_loop(
        control, options.max_turning_angle_deg, tol, options.max_points_per_loop, traits, what, control_labels, false,
        &knot_index);
    // Output index of each polygon vertex: the control points keep theirs, new ones append.
    std::vector<std::size_t> index(poly.size(), 0);
    std::vector<char> is_knot(poly.size(), 0);
    for(std::size_t k = 0; k < knot_index.size(); ++k) {
      index[knot_index[k]] = loop.vertices[k];
      is_knot[knot_index[k]] = 1;
    }
    for(std::size_t v = 0; v < poly.size(); ++v) {
      if(is_knot[v]) continue;
      index[v] = out.points.size();
      out.points.push_back(poly[v]);
      out.point_labels.push_back("new");
    }
    for(std::size_t v = 0; v < poly.size(); ++v) out.segments.push_back({index[v], index[(v + 1) % poly.size()]});
    const std::vector<std::string> spans = internal::curves_span_labels(knot_index, poly.size(), control_labels);
    out.segment_labels.insert(out.segment_labels.end(), spans.begin(), spans.end());
    if(!domain.segment_markers.empty())
      for(std::size_t k = 0; k < knot_index.size(); ++k) {
        const std::size_t end = k + 1 < knot_index.size() ? knot_index[k + 1] : poly.size();
        out.segment_markers.insert(out.segment_markers.end(), end - knot_index[k], edge_markers[l][k]);
      }
  }
  // Each loop is simple on its own; the whole must still be a boundary: a spline that bulges
  // beyond its control polygon may cross another loop or pass over a hole point or a point on
  // no segment.
  try {
    const Domain_loops_2<K> check = extract_loops(out, traits);
    CGAL_assertion(check.loops.size() == loops.loops.size());
    for(std::size_t l = 0; l < check.loops.size(); ++l) CGAL_assertion(check.loops[l].is_outer == loops.loops[l].is_outer);
    CGAL_USE(check);
  } catch(const Meshing_error& e) {
    throw Meshing_error(std::string("after curve decomposition the boundary is not valid (a spline bulges beyond its "
                                    "control polygon into another loop or over a point; add control points there): ") +
                        e.what());
  }
  return out;
}

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_CURVE_DECOMPOSITION_2_H
