// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SIZING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SIZING_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Narrow regions (paper §4.2): wherever two parts of the boundary face each other across a
// gap of width w, the quadtree must have more than two cells across the gap, or a loop could
// merge with another or vanish when the buffer zone is cleared. We sample the boundary, find
// for each sample the nearest boundary point that is not just its neighbour along the same
// loop, and ask for cells of side <= w/3 at the sample, at that nearest point and halfway
// between them. A size field only: computed in doubles.
//
// "Not its neighbour": a point r on the same loop counts only if the way from the sample to r
// along the loop is more than `detour` times the straight distance; a smooth curve bending
// back on itself (a channel, a fjord) qualifies, a gently curving wall does not. The two
// segments at a corner never count for each other: a sharp corner is a wedge that no cell
// size resolves (sharp features are treated apart, paper §5).
struct Size_sample
{
  std::array<double, 2> point;
  double size;
};

class Boundary_gap_finder
{
public:
  typedef std::array<double, 2> P;

  struct Segment
  {
    P a, b;
    std::size_t loop;
    double arc_a;  // arc length along the loop at a
    double length;
  };

  explicit Boundary_gap_finder(std::vector<Segment> segments, std::vector<double> loop_lengths,
                               double detour = 2.0)
    : m_segments(std::move(segments)), m_loop_lengths(std::move(loop_lengths)), m_detour(detour),
      m_order(m_segments.size()), m_boxes(m_segments.size())
  {
    for(std::size_t k = 0; k < m_order.size(); ++k)
      m_order[k] = k;
    build(0, m_order.size());
  }

  // The gap at point q lying on segment `on` at arc length `arc` of its loop: the distance to
  // the nearest boundary point that is not q's neighbour along the loop, and that point; or
  // infinity if there is none within `reach`.
  double gap(const P& q, std::size_t on, double arc, double reach, P& nearest) const
  {
    double best = reach;
    bool found = false;
    search(0, m_order.size(), q, on, arc, best, found, nearest);
    return found ? best : HUGE_VAL;
  }

  const std::vector<Segment>& segments() const { return m_segments; }

private:
  static bool adjacent(const Segment& s, const Segment& r)
  {
    return s.a == r.a || s.a == r.b || s.b == r.a || s.b == r.b;
  }

  static P closest(const Segment& s, const P& q, double& t)
  {
    const double dx = s.b[0] - s.a[0], dy = s.b[1] - s.a[1];
    const double l2 = dx * dx + dy * dy;
    t = l2 > 0 ? ((q[0] - s.a[0]) * dx + (q[1] - s.a[1]) * dy) / l2 : 0;
    t = (std::min)((std::max)(t, 0.0), 1.0);
    return { s.a[0] + t * dx, s.a[1] + t * dy };
  }

  typedef std::array<double, 4> Box; // xmin, ymin, xmax, ymax

  static double distance(const Box& b, const P& q)
  {
    const double dx = (std::max)({ b[0] - q[0], 0.0, q[0] - b[2] });
    const double dy = (std::max)({ b[1] - q[1], 0.0, q[1] - b[3] });
    return std::hypot(dx, dy);
  }

  // A bounding-box tree over the segments, stored implicitly like a k-d tree: the node of
  // range [b, e) keeps its box at m_boxes[(b + e) / 2].
  void build(std::size_t b, std::size_t e)
  {
    if(b >= e)
      return;
    Box box{ { HUGE_VAL, HUGE_VAL, -HUGE_VAL, -HUGE_VAL } };
    for(std::size_t k = b; k < e; ++k) {
      const Segment& s = m_segments[m_order[k]];
      box[0] = (std::min)({ box[0], s.a[0], s.b[0] });
      box[1] = (std::min)({ box[1], s.a[1], s.b[1] });
      box[2] = (std::max)({ box[2], s.a[0], s.b[0] });
      box[3] = (std::max)({ box[3], s.a[1], s.b[1] });
    }
    const std::size_t m = b + (e - b) / 2;
    m_boxes[m] = box;
    if(e - b == 1)
      return;
    const int axis = box[2] - box[0] >= box[3] - box[1] ? 0 : 1;
    std::nth_element(m_order.begin() + b, m_order.begin() + m, m_order.begin() + e,
                     [&](std::size_t u, std::size_t v) {
                       return m_segments[u].a[axis] + m_segments[u].b[axis]
                              < m_segments[v].a[axis] + m_segments[v].b[axis];
                     });
    build(b, m);
    build(m + 1, e);
  }

  void search(std::size_t b, std::size_t e, const P& q, std::size_t on, double arc, double& best,
              bool& found, P& nearest) const
  {
    if(b >= e)
      return;
    const std::size_t m = b + (e - b) / 2;
    if(distance(m_boxes[m], q) >= best)
      return;
    const std::size_t k = m_order[m];
    const Segment& s = m_segments[k];
    if(k != on && !adjacent(s, m_segments[on])) { // a corner's two sides are a wedge
      double t;
      const P c = closest(s, q, t);
      const double d = std::hypot(c[0] - q[0], c[1] - q[1]);
      bool counts = d > 0 && d < best;
      if(counts && s.loop == m_segments[on].loop) {
        double along = std::abs(s.arc_a + t * s.length - arc);
        along = (std::min)(along, m_loop_lengths[s.loop] - along);
        counts = along > m_detour * d; // else a neighbour along the loop, not across a gap
      }
      if(counts) {
        best = d;
        found = true;
        nearest = c;
      }
    }
    // the nearer half first, so that the other is more often pruned
    const std::size_t lb = b, le = m, rb = m + 1, re = e;
    const double dl = lb < le ? distance(m_boxes[lb + (le - lb) / 2], q) : HUGE_VAL;
    const double dr = rb < re ? distance(m_boxes[rb + (re - rb) / 2], q) : HUGE_VAL;
    if(dl <= dr) {
      search(lb, le, q, on, arc, best, found, nearest);
      search(rb, re, q, on, arc, best, found, nearest);
    } else {
      search(rb, re, q, on, arc, best, found, nearest);
      search(lb, le, q, on, arc, best, found, nearest);
    }
  }

  std::vector<Segment> m_segments;
  std::vector<double> m_loop_lengths;
  double m_detour;
  std::vector<std::size_t> m_order;
  std::vector<Box> m_boxes;
};

// Size samples for every narrow region of the domain: see above. Each segment is sampled
// densely enough that no stretch of a narrow channel goes without samples.
template <class K>
std::vector<Size_sample> narrow_region_samples(const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                                               const K& traits = K())
{
  typedef Boundary_gap_finder::P P;
  auto x_of = traits.compute_x_2_object();
  auto y_of = traits.compute_y_2_object();
  auto xy = [&](std::size_t v) {
    return P{ { CGAL::to_double(x_of(domain.points[v])), CGAL::to_double(y_of(domain.points[v])) } };
  };
  std::vector<Boundary_gap_finder::Segment> segments;
  std::vector<double> loop_lengths;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& vs = loops.loops[l].vertices;
    double arc = 0;
    for(std::size_t k = 0; k < vs.size(); ++k) {
      P a = xy(vs[k]), b = xy(vs[(k + 1) % vs.size()]);
      const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
      segments.push_back({ a, b, l, arc, len });
      arc += len;
    }
    loop_lengths.push_back(arc);
  }
  std::vector<Size_sample> samples;
  if(segments.empty())
    return samples;
  Boundary_gap_finder finder(segments, loop_lengths);
  // Gaps wider than this many times the local segment length leave the cells to the point
  // spacing: they cannot make a region narrow.
  const double reach_factor = 4;
  auto add = [&](const P& q, std::size_t on, double arc) {
    P r;
    const double w = finder.gap(q, on, arc, reach_factor * finder.segments()[on].length, r);
    if(!std::isfinite(w))
      return w;
    const double size = w / 3;
    samples.push_back({ q, size });
    samples.push_back({ r, size });
    samples.push_back({ P{ { (q[0] + r[0]) / 2, (q[1] + r[1]) / 2 } }, size });
    return w;
  };
  for(std::size_t k = 0; k < finder.segments().size(); ++k) {
    const auto& s = finder.segments()[k];
    // walk along the segment in steps of a third of the gap just found, so that a channel
    // is sampled all along however its width varies
    const double min_step = s.length / 65536;
    for(double t = 0; t < s.length;) {
      const double u = t / s.length;
      const double w = add(P{ { s.a[0] + u * (s.b[0] - s.a[0]), s.a[1] + u * (s.b[1] - s.a[1]) } }, k,
                           s.arc_a + t);
      t += std::isfinite(w) ? (std::max)(w / 3, min_step) : s.length;
    }
  }
  return samples;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SIZING_H
