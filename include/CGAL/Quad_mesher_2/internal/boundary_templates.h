// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.4, boundary templates: Lemma 2 asks every buffer-side angle beta of the core boundary
// to lie in [112.5°, 225°]. A vertex B out of it moves along the bisector of beta, e being
// the mean length of its two boundary edges: a notch (beta below 112.5°) out into the buffer
// by 0.71, 0.5 or 0.35 e (Template 1(a): a lattice notch opens to 180°), a convex corner
// (beta above 225°) in by 0.41, 0.3 or 0.2 e (Template 1(b): a lattice corner's quad becomes
// a kite, beta 225° at B and 202.5° at its neighbours). Of the steps that keep every core
// angle at B in [45°, 135°] and B's boundary edges h(B)/4 from the boundary, the one that
// most lowers the worst distance of the three betas at B and its neighbours from
// [112.5°, 225°] is taken. In the paper's order of priority (Table 2): first the vertices
// whose quads are not squares of one size (the adaptive templates), then the corners, then
// the notches; last, a vertex within range moves either way if a neighbour is still out.
// On a 45° staircase the corners cut first leave 225° and 135°; notches opened first would
// flatten the corners between them and leave every other notch at 90°.
// Where a vertex stays out, the plane search (template_search.h) moves it, and the templates
// that change the core's connectivity (connectivity_templates.h) fill the notches and split the
// corners that no move brings in; the vertices about them are searched again.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_TEMPLATES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_TEMPLATES_H

#include <CGAL/Quad_mesher_2/internal/buffer_side_angles.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/connectivity_templates.h>
#include <CGAL/Quad_mesher_2/internal/template_search.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Stage "templates" (paper §4.4) on one buffer zone: see the file comment.
template <class K>
class Boundary_templates : Buffer_tolerances
{
  typedef typename K::FT FT;
  typedef Quad_vertices Quad;

public:
  explicit Boundary_templates(Buffer_zone<K>& zone) : m_zone(zone) {}

  /// Stage "templates": moves core boundary vertices (and interior ones, but `fixed_points`,
  /// a domain's isolated points) so that their buffer-side angles meet Lemma 2 where the core
  /// allows (see the file comment).
  void apply_boundary_templates(const std::vector<std::size_t>& fixed_points)
  {
    CGAL_precondition(m_zone.quads_at != nullptr);
    m_zone.fixed_mark.assign(m_zone.mesh.points.size(), 0);
    for(std::size_t v : fixed_points) if(v < m_zone.fixed_mark.size()) m_zone.fixed_mark[v] = 1;
    m_zone.shaped_mark.assign(m_zone.mesh.points.size(), 0);
    const Vertex_quads& quads_at = *m_zone.quads_at;
    std::vector<char> adaptive(m_zone.mesh.points.size(), 0);
    for(const auto& cyc : m_zone.cycles)
      for(std::size_t b : cyc)
        adaptive[b] = !on_square_lattice(b, quads_at);
    m_zone.cleared_xy = m_zone.xy;
    for(Template_pass pass : { ADAPTIVE, CORNERS, NOTCHES, NEIGHBOURS })
      for(int round = 0; round < 3; ++round) {
        bool changed = false;
        for(const auto& cyc : m_zone.cycles) {
          const std::size_t n = cyc.size();
          for(std::size_t i = 0; i < n; ++i)
            if((pass != ADAPTIVE || adaptive[cyc[i]])
               && try_move_boundary_vertex(cyc[(i + n - 2) % n], cyc[(i + n - 1) % n], cyc[i],
                                           cyc[(i + 1) % n], cyc[(i + 2) % n], pass, quads_at))
              changed = true;
        }
        if(!changed) break;
      }
    Template_search<K>(m_zone).search_boundary_vertices(quads_at);
    m_zone.quads_at.reset(); // the later stages add quads
  }

  /// Stage "templates", after apply_boundary_templates(): a new core quad over each notch that could not
  /// move (see fill_notch()), then the vertices about them searched again.
  void apply_connectivity_templates()
  {
    Connectivity_templates<K> connectivity(m_zone);
    const std::size_t changed = m_zone.report.filled_notches + m_zone.report.split_corners;
    for(std::size_t c = 0; c < m_zone.cycles.size(); ++c)
      for(std::size_t i = 0; i < m_zone.cycles[c].size(); ++i)
        connectivity.fill_notch(c, i);
    {
      std::optional<Vertex_quads> quads_at; // made for the first corner over 225 degrees, if any
      std::size_t known = 0;
      std::vector<char> split;
      for(std::size_t c = 0; c < m_zone.cycles.size(); ++c)
        for(std::size_t i = 0; i < m_zone.cycles[c].size(); ++i)
          if(connectivity.split_corner(c, i, quads_at, known, split)) ++i; // past the corner, now between its new points
    }
    if(m_zone.report.filled_notches + m_zone.report.split_corners > changed)
      Template_search<K>(m_zone).search_boundary_vertices(Vertex_quads(m_zone.mesh.quads, m_zone.mesh.points.size()));
    m_zone.cleared_xy = std::vector<Point_2d>();
    count_lemma_2_misses();
  }

  // The templates' result against Lemma 2: the core boundary vertices whose buffer-side
  // angle is outside [112.5, 225] by more than rounding, and those of them not within 2h of an
  // input corner (whose buffer is the corner's, §5).
  void count_lemma_2_misses()
  {
    m_zone.report.buffer_angles_out = m_zone.report.buffer_angles_out_away_from_corners = 0;
    for(const auto& cyc : m_zone.cycles) {
      const std::size_t n = cyc.size();
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t a = cyc[(i + n - 1) % n], b = cyc[i], c = cyc[(i + 1) % n];
        if(out_of_lemma_2_range(m_zone.xy[a], m_zone.xy[b], m_zone.xy[c])) {
          ++m_zone.report.buffer_angles_out;
          if(!m_zone.near_input_corner(b)) ++m_zone.report.buffer_angles_out_away_from_corners;
        }
      }
    }
  }

private:
  enum Template_pass { ADAPTIVE, CORNERS, NOTCHES, NEIGHBOURS };

  // every quad at core vertex v a square, all of one side (the uniform grid of §4.4)
  bool on_square_lattice(std::size_t v, const Vertex_quads& quads_at) const
  {
    double side = -1;
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = m_zone.mesh.quads[q];
      for(int k = 0; k < 4; ++k) {
        const Vector_2d e = m_zone.xy[Q[(k + 1) % 4]] - m_zone.xy[Q[k]];
        const Vector_2d f = (m_zone.xy[Q[(k + 2) % 4]] - (m_zone.xy[Q[(k + 1) % 4]]));
        if(side < 0) side = length_2d(e);
        if(std::abs(length_2d(e) - side) > 1e-6 * side || std::abs(CGAL::scalar_product(e, f)) > 1e-6 * side * side)
          return false;
      }
    }
    return true;
  }

  // Moves core boundary vertex b (a2, a, b, c, c2 consecutive on its cycle) along the bisector
  // of its buffer-side angle, if `pass` applies to it and a step lowers the worst distance of
  // the betas at a, b and c from [112.5, 225] (see the file comment).
  bool try_move_boundary_vertex(std::size_t a2, std::size_t a, std::size_t b, std::size_t c,
                                std::size_t c2, Template_pass pass, const Vertex_quads& quads_at)
  {
    const double beta = right_side_angle(m_zone.xy[a], m_zone.xy[b], m_zone.xy[c]);
    const bool notch = beta < 112.5 - angle_tolerance, corner = beta > 225.0 + angle_tolerance;
    const bool applies = pass == CORNERS ? corner : pass == NOTCHES ? notch
                         : pass == ADAPTIVE ? notch || corner : !notch && !corner;
    if(!applies)
      return false;
    const Point_2d old = m_zone.xy[b];
    auto worst = [&](const Point_2d& p) { return worst_buffer_angle_excess(m_zone.xy[a2], m_zone.xy[a], p, m_zone.xy[c], m_zone.xy[c2]); };
    double best = worst(old);
    if(best <= angle_tolerance)
      return false;
    // in units of e, out along the bisector if positive: on the lattice a notch opens to 180
    // degrees at 0.71 e, a corner is cut to 225 degrees at 0.41 e
    static const std::vector<double> notch_steps{ 0.70710678118654752, 0.5, 0.35 };
    static const std::vector<double> corner_steps{ -0.41421356237309505, -0.3, -0.2 };
    static const std::vector<double> neighbour_steps{ 0.5, 0.35, 0.2, -0.3, -0.2 };
    const double e = 0.5 * (length_2d(old - m_zone.xy[a]) + length_2d(m_zone.xy[c] - old));
    const Vector_2d d = right_bisector(m_zone.xy[a], old, m_zone.xy[c]);
    const double clear = 0.25 * m_zone.local_size[b];
    double best_f = 0;
    for(double f : notch ? notch_steps : corner ? corner_steps : neighbour_steps) {
      const Point_2d p = old + (f * e) * d;
      m_zone.xy[b] = p;
      bool ok = worst(p) < best - angle_tolerance;
      for(auto q = quads_at[b].begin(); ok && q != quads_at[b].end(); ++q) {
        std::array<Point_2d, 4> P;
        for(int k = 0; k < 4; ++k) P[k] = m_zone.xy[m_zone.mesh.quads[*q][k]];
        ok = quad_badness(P) <= 45.0 + angle_tolerance;
      }
      if(ok && m_zone.clear_of_boundary(m_zone.xy[a], p, clear)
         && m_zone.clear_of_boundary(p, m_zone.xy[c], clear)) {
        best = worst(p);
        best_f = f;
      }
    }
    if(best_f == 0) {
      m_zone.xy[b] = old;
      return false;
    }
    m_zone.xy[b] = old + (best_f * e) * d;
    m_zone.mesh.points[b] = m_zone.mesh_point(m_zone.xy[b]);
    ++(best_f > 0 ? m_zone.report.moved_notches : m_zone.report.cut_corners);
    return true;
  }

  Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_TEMPLATES_H
