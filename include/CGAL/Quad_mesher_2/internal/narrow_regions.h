// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_NARROW_REGIONS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_NARROW_REGIONS_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Narrow regions (paper §4.2): wherever two parts of the boundary face each other across a
// gap of the domain of width w, the quadtree must have more than two cells across the gap, or
// a loop could merge with another or vanish when the buffer zone is cleared. We sample the
// boundary, find for each sample the nearest boundary point on the domain's side of its
// segment that is not just its neighbour along the same loop, and ask for cells of side
// <= w/4 at the sample, at that nearest point and halfway between them. Parts facing each
// other across the outside (a slit between two prongs) need only cells no wider than the
// slit, which no cell then spans: the clearance removes the cells beside it, and the buffer
// fills each side on its own. So a slit of width d counts as a gap of width 4d. A point
// beside the segment's line, to rounding, counts as outside, as one exactly on it does: the
// next prong's top, collinear with this one's, lies across the slit's mouth however turned.
// A size field: measured in doubles (the approximate kernel); what it decides on the input,
// which segments are neighbours and which corners are convex, it decides on vertex indices
// and with the traits' exact orientation.
//
// "Not its neighbour": a point r on the same loop counts only if the way from the sample to r
// along the loop is more than `detour` times the straight distance; a smooth curve bending
// back on itself (a channel, a fjord) qualifies, a gently curving wall does not. The two
// sides of a corner count for each other only if it is a needle (sharper than 10 degrees) and
// only beyond the corner zone (an eighth of the shorter side from the corner): the tip of the
// wedge is left to the corner quad of paper §5, which no cell size could resolve, but farther
// out a needle's sides face each other across a narrowing channel.
struct Size_sample
{
  Approximate_kernel::Point_2 point;
  double size;
};

class Boundary_gap_finder
{
public:
  typedef Approximate_kernel::Point_2 P;
  typedef Approximate_kernel::Vector_2 V;
  typedef Approximate_kernel::Segment_2 S;

  // A loop's segment from domain vertex `source_vertex` to `target_vertex`: which segments
  // are neighbours is decided on these indices, not on the rounded positions.
  struct Segment
  {
    S segment;
    std::size_t source_vertex, target_vertex;
    std::size_t loop;
    double arc_a;  // arc length along the loop at the source
    double length;
    bool needle_at_source; // the corner at the source (with the loop's previous segment) is a needle
    bool two_sided = false; // on an interface: the domain on both sides
  };

  // a vertex where loops meet (a junction), and its arc length along one of them
  typedef std::pair<std::size_t, double> Junction;

  // `junctions[l]`: the junctions on loop l (none if empty), through which the way along the
  // boundary passes from one loop to another
  explicit Boundary_gap_finder(std::vector<Segment> segments, std::vector<double> loop_lengths,
                               std::vector<std::vector<Junction>> junctions = {}, double detour = 2.0)
    : m_segments(std::move(segments)), m_loop_lengths(std::move(loop_lengths)), m_junctions(std::move(junctions)),
      m_detour(detour), m_boxes(boxes(m_segments)), m_tree(m_boxes)
  {
    m_junctions.resize(m_loop_lengths.size());
  }
  Boundary_gap_finder(const Boundary_gap_finder&) = delete;
  Boundary_gap_finder& operator=(const Boundary_gap_finder&) = delete;

  // The gap at point q lying on segment `on` at arc length `arc` of its loop: the distance to
  // the nearest boundary point that is not q's neighbour along the loop, and that point; or
  // infinity if there is none within `reach`.
  // The search box grows from `first_radius` (the gap at the walk's last sample, say) by
  // fours up to `reach`: the nearest point within a box's radius is the nearest of all, and a
  // box of the whole reach held thousands of segments per sample on long, spiky loops.
  double gap(const P& q, std::size_t on, double arc, double reach, P& nearest,
             double first_radius = HUGE_VAL) const
  {
    double best = HUGE_VAL;
    for(double r = (std::min)(first_radius, reach);; r = (std::min)(4 * r, reach)) {
      best = gap_within(q, on, arc, reach, r, nearest);
      if(best <= r || r >= reach) return best;
    }
  }

  const std::vector<Segment>& segments() const { return m_segments; }

  // true if the angle at `corner` between its sides to `before` and to `after` is smaller
  // than `needle_angle`. A threshold on a measure, so in doubles; whether the corner is
  // convex (a reflex corner's sides face each other across the outside, which the domain's
  // cells never need to resolve) is the caller's exact decision on the input.
  static bool sharper_than_needle(const P& before, const P& corner, const P& after)
  {
    const V u = before - corner, v = after - corner;
    const double angle = std::atan2(std::abs(CGAL::determinant(v, u)), CGAL::scalar_product(u, v));
    return angle < needle_angle * CGAL_PI / 180;
  }

  // the part of a corner's sides, as a share of the shorter, left to the corner quad
  static constexpr double corner_zone = 0.125;
  // corners sharper than this (degrees) are needles: their sides count for each other
  static constexpr double needle_angle = 10;
  // a slit of the outside d wide counts as a gap of the domain this many times as wide
  static constexpr double outside_gap_weight = 4;

private:
  // gap() within the box of radius r around q
  double gap_within(const P& q, std::size_t on, double arc, double reach, double r, P& nearest) const
  {
    double best = HUGE_VAL;
    const Segment& here = m_segments[on];
    m_tree.query(Bbox_2(q.x() - r, q.y() - r, q.x() + r, q.y() + r), [&](std::size_t k) {
      const Segment& s = m_segments[k];
      if(k == on || meet_on_a_crack(s, here))
        return;
      // a corner's two sides: near the corner a wedge that no cell size resolves (the corner
      // quad of paper §5 fills it); farther out, an acute corner's sides face each other
      // across a narrowing gap like any channel's (a needle)
      if(consecutive(s, here)) {
        const Segment& leaving = leaving_the_corner(s, here);
        if(!leaving.needle_at_source ||
           std::sqrt(CGAL::squared_distance(q, leaving.segment.source())) < corner_zone * (std::min)(s.length, here.length))
          return;
      }
      double t;
      const P c = closest(s.segment, q, t);
      const double d = std::sqrt(CGAL::squared_distance(c, q));
      if(!(d > 0) || d > reach)
        return;
      // on the segment's line to rounding: outside (see the file comment)
      const V dir = here.segment.to_vector();
      const double side = CGAL::determinant(dir, c - q);
      const bool outside = !here.two_sided && side <= 1e-9 * std::sqrt(dir.squared_length()) * d;
      const double width = outside ? outside_gap_weight * d : d;
      if(width >= best)
        return;
      if(along_the_boundary(here.loop, arc, s.loop, s.arc_a + t * s.length) <= m_detour * d)
        return; // a neighbour along the boundary, not the other side of a gap
      best = width;
      nearest = c;
    });
    return best;
  }

  // The way along the boundary from arc length `a` of loop `la` to `b` of loop `lb`: along
  // the loop, or through a junction on both; infinite if the loops meet at none.
  double along_the_boundary(std::size_t la, double a, std::size_t lb, double b) const
  {
    auto along = [&](std::size_t l, double x, double y) {
      const double d = std::abs(x - y);
      return (std::min)(d, m_loop_lengths[l] - d);
    };
    if(la == lb) return along(la, a, b);
    double best = HUGE_VAL;
    for(const Junction& ja : m_junctions[la])
      for(const Junction& jb : m_junctions[lb])
        if(ja.first == jb.first) best = (std::min)(best, along(la, a, ja.second) + along(lb, jb.second, b));
    return best;
  }

  // Each vertex is the target of one of its loop's segments and the source of the next (on a
  // crack, twice: see meet_on_a_crack(); at a junction, once in each loop about it).
  static bool consecutive(const Segment& s, const Segment& r)
  {
    return s.target_vertex == r.source_vertex || r.target_vertex == s.source_vertex;
  }

  // A crack's loop passes its inner vertices twice: segments that meet there without being
  // consecutive are one side of the crack against the other, which face each other across
  // nothing (its own twin) or across a corner of the crack (the corner quad's wedge).
  static bool meet_on_a_crack(const Segment& s, const Segment& r)
  {
    return !consecutive(s, r) && (s.source_vertex == r.source_vertex || s.target_vertex == r.target_vertex);
  }

  // of two consecutive segments, the one whose source is their shared vertex
  static const Segment& leaving_the_corner(const Segment& s, const Segment& r)
  {
    return s.target_vertex == r.source_vertex ? r : s;
  }

  // the point of s nearest to q, a share t of the way from its source to its target
  static P closest(const S& s, const P& q, double& t)
  {
    const V d = s.to_vector();
    const double l2 = d.squared_length();
    t = l2 > 0 ? CGAL::scalar_product(q - s.source(), d) / l2 : 0;
    t = (std::min)((std::max)(t, 0.0), 1.0);
    return s.source() + t * d;
  }

  static std::vector<Bbox_2> boxes(const std::vector<Segment>& segments)
  {
    std::vector<Bbox_2> result;
    result.reserve(segments.size());
    for(const Segment& s : segments)
      result.push_back(s.segment.bbox());
    return result;
  }

  std::vector<Segment> m_segments;
  std::vector<double> m_loop_lengths;
  std::vector<std::vector<Junction>> m_junctions;
  double m_detour;
  std::vector<Bbox_2> m_boxes; // before m_tree, which keeps a reference to it
  Box_tree m_tree;             // the box tree the loop validation uses
};

// The domain's boundary as the gap finder's segments, loop after loop, each segment once
// (is_second_side()), each loop's length, and the junctions on each loop (vertices of three
// segments or more).
template <class K>
std::vector<Boundary_gap_finder::Segment> gap_finder_segments(const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                                                              const K& traits, std::vector<double>& loop_lengths,
                                                              std::vector<std::vector<Boundary_gap_finder::Junction>>& junctions)
{
  const std::vector<std::size_t> degree = segment_degrees(domain);
  typedef Boundary_gap_finder::P P;
  auto x_of = traits.compute_x_2_object();
  auto y_of = traits.compute_y_2_object();
  auto orientation = traits.orientation_2_object();
  auto xy = [&](std::size_t v) {
    return P(CGAL::to_double(x_of(domain.points[v])), CGAL::to_double(y_of(domain.points[v])));
  };
  std::vector<Boundary_gap_finder::Segment> segments;
  junctions.assign(loops.loops.size(), {});
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& vs = loops.loops[l].vertices;
    const std::size_t n = vs.size();
    double arc = 0;
    for(std::size_t k = 0; k < n; ++k) {
      const std::size_t before = vs[(k + n - 1) % n], source = vs[k], target = vs[(k + 1) % n];
      if(degree[source] > 2) junctions[l].emplace_back(source, arc);
      const Boundary_gap_finder::S segment(xy(source), xy(target));
      const double length = std::sqrt(segment.squared_length());
      if(!is_second_side(loops, l, k)) {
        // convex with the domain on the left: decided on the input points, exactly
        const bool convex = orientation(domain.points[before], domain.points[source], domain.points[target]) == LEFT_TURN;
        const bool needle = convex && Boundary_gap_finder::sharper_than_needle(xy(before), segment.source(), segment.target());
        segments.push_back({ segment, source, target, l, arc, length, needle, has_edge_twin(loops.loops[l], k) });
      }
      arc += length;
    }
    loop_lengths.push_back(arc);
  }
  return segments;
}

// Size samples for every narrow region of the domain: see above. Each segment is sampled
// densely enough that no stretch of a narrow channel goes without samples, but never in steps
// shorter than `finest_side`, the finest cell the quadtree makes: finer samples would ask for
// the same cells. A gap needing cells finer than that ends the walk, its samples last (the
// caller's depth error names it). A gap is sampled every third of its width with three
// samples (its two walls and its middle), each asking for a cell a quarter of its width: no
// two samples of a walk share a cell, and each gap is walked from both walls, so more than
// 2 `max_cells` samples ask for more leaves than the quadtree may make. That is an error
// naming where, found before the samples fill the memory (a channel 1e-7 wide along a unit
// side).
template <class K>
std::vector<Size_sample> narrow_region_samples(const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                                               double finest_side, std::size_t max_cells,
                                               const K& traits = K())
{
  typedef Boundary_gap_finder::P P;
  std::vector<double> loop_lengths;
  std::vector<std::vector<Boundary_gap_finder::Junction>> junctions;
  std::vector<Boundary_gap_finder::Segment> segments = gap_finder_segments(domain, loops, traits, loop_lengths, junctions);
  std::vector<Size_sample> samples;
  if(segments.empty())
    return samples;
  const Boundary_gap_finder finder(std::move(segments), std::move(loop_lengths), std::move(junctions));
  // Gaps wider than this many times the local segment length leave the cells to the point
  // spacing: they cannot make a region narrow.
  const double reach_factor = 4;
  // samples on a stretch of segment without any gap in reach
  const double no_gap_samples = 8;
  auto add = [&](const P& q, std::size_t on, double arc, double first_radius) {
    P r;
    const double w = finder.gap(q, on, arc, reach_factor * finder.segments()[on].length, r, first_radius);
    if(!std::isfinite(w))
      return w;
    const double size = w / 4;
    samples.push_back({ q, size });
    samples.push_back({ r, size });
    samples.push_back({ CGAL::midpoint(q, r), size });
    return w;
  };
  for(std::size_t k = 0; k < finder.segments().size(); ++k) {
    const auto& s = finder.segments()[k];
    // walk along the segment in steps of a third of the gap just found, so that a channel
    // is sampled all along however its width varies
    double last_gap = HUGE_VAL; // the next sample's gap is about the same: search near it first
    for(double t = 0; t < s.length;) {
      const double u = t / s.length;
      const double w = add(s.segment.source() + u * s.segment.to_vector(), k, s.arc_a + t, 2 * last_gap);
      last_gap = w;
      // a gap needing cells finer than the quadtree makes: the caller's depth error names it
      // now (walking on at the finest step ran into the cell budget, a misleading error)
      if(w / 4 < finest_side)
        return samples;
      if(samples.size() > 2 * max_cells) {
        std::ostringstream msg;
        msg << "the narrow regions need more than " << max_cells << " quadtree cells (the cell budget): the gap near ("
            << samples.back().point.x() << ", " << samples.back().point.y() << ") is " << w
            << " wide; coarsen the input there or raise the cell budget";
        throw Meshing_error(msg.str());
      }
      // no gap here: near a corner the far side still counts as its neighbour along the loop
      // (a thin rectangle's long sides, seen from its corners), so look again farther on; a
      // needle's sides have no gap in reach within the corner zone: the walk steps past it
      t += std::isfinite(w)                ? (std::max)(w / 3, finest_side)
           : s.needle_at_source && t == 0 ? Boundary_gap_finder::corner_zone * s.length
                                          : s.length / no_gap_samples;
    }
  }
  return samples;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_NARROW_REGIONS_H
