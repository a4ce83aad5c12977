// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.4, templates that change the core's connectivity ("templates also fill the buffer
// with new quads"): a notch that no move opens gets a new core quad over it (fill_notch()), and
// a convex corner whose one quad a transition template jams has that quad split in three
// (split_corner()), after which the plane search (template_search.h) moves the vertices about
// them again.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_CONNECTIVITY_TEMPLATES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_CONNECTIVITY_TEMPLATES_H

#include <CGAL/Quad_mesher_2/internal/buffer_side_angles.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/sharp_corner_fans.h>
#include <CGAL/Quad_mesher_2/internal/template_search.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The templates that add core points and quads, on one buffer zone (see the file comment).
template <class K>
class Connectivity_templates : Buffer_tolerances
{
  typedef Quad_vertices Quad;

public:
  explicit Connectivity_templates(Buffer_zone<K>& zone) : m_zone(zone), m_fans(zone) {}

  // A notch (buffer-side angle under 112.5 degrees) that apply_boundary_templates() left
  // cannot move: a core angle of 45 degrees at it (the centre of a cell's template, or a
  // transition template's corner) would go below, and its two first-layer quads would split
  // 90 degrees at best. A new core quad B A Y C over it (paper §4.4: templates also fill the
  // buffer with new quads) takes B off the boundary: with Y where the quad has a little under
  // 135 degrees, A and C lose about 67.5 degrees of buffer side each and Y has about 225, the
  // angles template 1(a) gives by moving B there. Kept if the quad is within [45, 135], its
  // new edges keep the clearance, and the buffer-side angles at A, Y and C come nearer
  // [112.5, 225] than before. Not every notch is filled: see may_fill().
  void fill_notch(std::size_t c, std::size_t i)
  {
    auto& cyc = m_zone.cycles[c];
    const std::size_t n = cyc.size();
    const std::size_t a = cyc[(i + n - 1) % n], b = cyc[i], c1 = cyc[(i + 1) % n];
    if(!may_fill(b, right_side_angle(m_zone.xy[a], m_zone.xy[b], m_zone.xy[c1]))) return;
    Notch notch(m_zone, cyc[(i + n - 2) % n], a, b, c1, cyc[(i + 2) % n]);
    auto consider = [&notch](const Point_2d& y) { return notch.consider(y); };
    // |BY| = 1.01 s: at s (template 1(a)'s 0.71 s diagonal) a lattice notch's quad has exactly
    // 135 degrees at Y, in or out by rounding, and a scaled domain's choice would differ
    for(double f : { 1.01, 1.1, 0.9, 1.2, 0.8 })
      consider(notch.along(f, notch.d));
    // Beside an adaptive core the quad's other corners are not a lattice notch's: Y then
    // needs to lie off the bisector
    if(!notch.found)
      for(double f : { 0.7, 0.85, 1.0, 1.15, 1.3 })
        for(int k = -2; k <= 2; ++k)
          consider(notch.off_bisector(f, k));
    // Not beside an input corner, whose buffer is §5's: a quad there over a notch near the
    // range made the round invalid.
    if(!notch.found && !m_zone.near_input_corner(notch.b))
      consider(notch.barely_out_start());
    if(!notch.found) return;
    pattern_search(notch.best_y, notch.s, notch.best, consider);
    // Y is a core point like the others (the first buffer points come after the core's)
    const std::size_t y = m_zone.add_core_point(notch.best_y, m_zone.local_size[notch.b], true);
    m_zone.on_cycle_mark[notch.b] = 0;
    m_zone.core_points = m_zone.mesh.points.size();
    m_zone.add_quad({ notch.b, notch.a, y, notch.c1 });
    cyc[i] = y;
    ++m_zone.report.filled_notches;
  }

  // A convex corner that no move brought into range (buffer-side angle over 225 degrees) whose
  // core angle is a single quad's, jammed by its other corners: a transition template's 45
  // degrees at a neighbour, 135 opposite.
  // The quad B C X A is split in three through the midpoints of its two boundary edges and its
  // centre O: B Mc O Ma, Mc C X O, Ma O X A (on a square, three rectangles of right angles,
  // the new points' betas 180). B's quad then shares no corner with the template that jammed
  // it, and the search moves B in as template 1(b) would, O giving way: a kite at B. Not where
  // no centre keeps the three quads within [45, 135].
  // (`quads_at`, made at the first candidate, knows the first `known` points: a million-quad
  // core seldom has a candidate; `split` marks the quads split before.)
  bool split_corner(std::size_t c, std::size_t i, std::optional<Vertex_quads>& quads_at, std::size_t& known,
                    std::vector<char>& split)
  {
    auto& cyc = m_zone.cycles[c];
    const std::size_t n = cyc.size();
    const std::size_t a = cyc[(i + n - 1) % n], b = cyc[i], c1 = cyc[(i + 1) % n];
    if(n < 8 || m_zone.fixed_mark[b] || right_side_angle(m_zone.xy[a], m_zone.xy[b], m_zone.xy[c1]) <= 225.0 + rounding_tolerance(m_zone.xy[a], m_zone.xy[b], m_zone.xy[c1])
       || m_zone.near_input_corner(b))
      return false;
    if(!quads_at) {
      quads_at.emplace(m_zone.mesh.quads, m_zone.mesh.points.size());
      known = m_zone.mesh.points.size();
      split.assign(m_zone.mesh.quads.size(), 0);
    }
    if(a >= known || b >= known || c1 >= known || (*quads_at)[b].size() != 1) return false;
    const std::size_t q = *(*quads_at)[b].begin();
    if(split[q]) return false;
    split[q] = 1;
    const Quad Q = m_zone.mesh.quads[q];
    const int k = corner_of(Q, b);
    if(Q[(k + 1) % 4] != c1 || Q[(k + 3) % 4] != a) return false;
    const std::size_t x = Q[(k + 2) % 4];
    const Point_2d pa = CGAL::midpoint(m_zone.xy[a], m_zone.xy[b]), pc = CGAL::midpoint(m_zone.xy[b], m_zone.xy[c1]);
    // O from the centre where the three quads' worst angle is least: a quad far from a
    // square (a tongue's tip) left one under 45 degrees
    auto worst = [&](const Point_2d& o) {
      return (std::max)({ quad_badness({ m_zone.xy[b], pc, o, pa }), quad_badness({ pc, m_zone.xy[c1], m_zone.xy[x], o }),
                          quad_badness({ pa, o, m_zone.xy[x], m_zone.xy[a] }) });
    };
    Point_2d centre = CGAL::midpoint(CGAL::midpoint(m_zone.xy[a], m_zone.xy[c1]), CGAL::midpoint(m_zone.xy[b], m_zone.xy[x]));
    double least = worst(centre);
    pattern_search(centre, length_2d(m_zone.xy[x] - m_zone.xy[b]), least, [&](const Point_2d& o) {
      const double w = worst(o);
      if(!(w < least)) return false;
      least = w;
      centre = o;
      return true;
    });
    if(least > 45.0 + core_slack) return false;
    const std::size_t ma = m_zone.add_core_point(pa, m_zone.local_size[b], true);
    const std::size_t mc = m_zone.add_core_point(pc, m_zone.local_size[b], true);
    const std::size_t o = m_zone.add_core_point(centre, m_zone.local_size[b], false);
    m_zone.core_points = m_zone.mesh.points.size();
    m_zone.mesh.quads[q] = { b, mc, o, ma };
    m_zone.add_quad({ mc, c1, x, o });
    m_zone.add_quad({ ma, o, x, a });
    cyc.insert(cyc.begin() + std::ptrdiff_t(i) + 1, mc);
    cyc.insert(cyc.begin() + std::ptrdiff_t(i), ma);
    ++m_zone.report.split_corners;
    return true;
  }

private:

  // The search for the fourth corner Y of a quad over the notch at b (a2, a, b, c1, c2
  // consecutive on its cycle): the best admissible Y so far, `best_y`, if `found`.
  struct Notch
  {
    Notch(const Buffer_zone<K>& zone, std::size_t a2_, std::size_t a_, std::size_t b_, std::size_t c1_, std::size_t c2_)
      : z(zone), a2(a2_), a(a_), b(b_), c1(c1_), c2(c2_),
        d(right_bisector(z.xy[a], z.xy[b], z.xy[c1])),
        s(0.5 * (length_2d(z.xy[a] - z.xy[b]) + length_2d(z.xy[c1] - z.xy[b]))),
        clear(0.25 * z.local_size[b]),
        least_gain(least_search_gain(z.xy[a2], z.xy[a], z.xy[b], z.xy[c1], z.xy[c2]))
    {}

    // the buffer-side angles' excess with Y at y, the worst first: a filled notch is off the
    // boundary, and Y has its own angle (a lattice notch at 90 degrees beside a corner at 270
    // leaves two just out, far nearer)
    double excess(const Point_2d& y) const
    {
      return buffer_angle_excesses(z.xy[a2], z.xy[a], y, z.xy[c1], z.xy[c2], false);
    }
    double quad_badness_with(const Point_2d& y) const { return quad_badness({ z.xy[b], z.xy[a], y, z.xy[c1] }); }

    // Y at y if that lowers the excess by more than rounding (the same choice on a scaled
    // domain, no steps that follow the rounding far from the origin), keeps the quad within
    // [45, 135] and its new edges clear of the boundary
    bool consider(const Point_2d& y)
    {
      const double after = excess(y);
      if(!(after < best - least_gain) || quad_badness_with(y) > 45.0 + core_slack
         || !z.clear_of_boundary(z.xy[a], y, clear) || !z.clear_of_boundary(y, z.xy[c1], clear))
        return false;
      best = after;
      best_y = y;
      found = true;
      return true;
    }

    // f s from b along the unit vector u
    Point_2d along(double f, const Vector_2d& u) const { return z.xy[b] + (f * s) * u; }
    // f s from b, turned by k 15 degrees from the bisector
    Point_2d off_bisector(double f, int k) const { return along(f, turned_2d(d, k * pi / 12)); }

    // A notch barely out at a transition template's corner has its Y on a thin band far off
    // the bisector: the quad's angle at Y exactly 135 (a lone quad's corner has beta 225 at
    // least), and at a neighbour little enough to keep its beta in range. The ring misses the
    // band; a search of the quad's excess over [45, 135] plus the betas' reaches it.
    Point_2d barely_out_start() const
    {
      auto penalty = [&](const Point_2d& y) { return (std::max)(0.0, quad_badness_with(y) - 45.0) + excess(y); };
      Point_2d start = z.xy[b];
      double least = std::numeric_limits<double>::infinity();
      for(double f : { 0.7, 0.85, 1.0, 1.15, 1.3 })
        for(int k = -5; k <= 5; ++k) {
          const Point_2d y = off_bisector(f, k);
          const double p = penalty(y);
          if(p < least) { least = p; start = y; }
        }
      pattern_search(start, s, least, [&](const Point_2d& y) {
        const double p = penalty(y);
        if(!(p < least)) return false;
        least = p;
        start = y;
        return true;
      });
      return start;
    }

    const Buffer_zone<K>& z;
    const std::size_t a2, a, b, c1, c2;
    const Vector_2d d; // the unit bisector of beta, into the buffer
    const double s;   // the mean length of the notch's two edges
    const double clear;
    const double least_gain; // least_search_gain() about b
    double best = excess(z.xy[b]);
    Point_2d best_y = ORIGIN;
    bool found = false;
  };

  // Within 2h of an input corner only notches under 95 degrees are filled: from there the
  // first layer splits beta in two quads over 45 degrees each, and a new quad over such a
  // notch changed the strip's pairing for the worse. Nor is a notch over 90 degrees that
  // faces a corner needing a fan of three (its nearest boundary point is that corner): the
  // notch is the fan's room, and filling it squeezes the fan's quads. At 90 degrees or less
  // the first layer would leave 45 degrees at most to each of its two quads at b: no room.
  // (b: the notch's vertex, beta: its buffer-side angle)
  bool may_fill(std::size_t b, double beta) const
  {
    if(beta >= 112.5 - angle_tolerance || (beta >= 95.0 && m_zone.near_input_corner(b))) return false;
    if(beta <= 90.0 + angle_tolerance) return true;
    const Loop_locator::Hit h = m_zone.locator->closest(m_zone.xy[b], 2 * m_zone.local_size[b]);
    const std::size_t nv = m_zone.locator->loop(h.loop).size();
    return !((h.t <= 0 && m_fans.needs_fan_of_three(h.loop, h.edge))
             || (h.t >= 1 && m_fans.needs_fan_of_three(h.loop, (h.edge + 1) % nv)));
  }

  Buffer_zone<K>& m_zone;
  Sharp_corner_fans<K> m_fans;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_CONNECTIVITY_TEMPLATES_H
