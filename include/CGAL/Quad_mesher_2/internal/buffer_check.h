// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The buffer's final check: every quad the buffer stages made or changed is checked with the
// kernel's exact predicates (strictly convex, counter-clockwise). Quads that are invalid, or have
// an angle outside [45°, 135°] that no input corner forces (only a corner under 45° does), are
// reported as refinement requests: the mesher refines the quadtree there and starts again.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_CHECK_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_CHECK_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The final check of one buffer zone (see the file comment).
template <class K>
class Buffer_check : Buffer_tolerances
{
  typedef Quad_vertices Quad;

public:
  explicit Buffer_check(Buffer_zone<K>& zone) : m_zone(zone) {}

  /// Checks every quad the buffer stages made or changed with exact predicates and counts
  /// those with an angle outside [45, 135] that no sharp input corner forces; records
  /// refinement requests at both, but at those within two quads of an invalid one: a broken
  /// strip's angles are not the finished buffer's (an invalid round is refined for both).
  void check_quads()
  {
    std::vector<char> valid(m_zone.mesh.quads.size(), 1);
    for(std::size_t q = 0; q < valid.size(); ++q)
      if(m_zone.made_or_changed(m_zone.mesh.quads[q])) valid[q] = m_zone.is_valid_quad(m_zone.mesh.quads[q]);
    const std::vector<char> near_invalid = near_invalid_vertices(valid);
    for(std::size_t q = 0; q < m_zone.mesh.quads.size(); ++q) {
      const Quad& Q = m_zone.mesh.quads[q];
      if(!m_zone.made_or_changed(Q)) continue;
      const bool valid_quad = valid[q] != 0;
      std::array<Point_2d, 4> P;
      for(int c = 0; c < 4; ++c) P[c] = m_zone.xy[Q[c]];
      bool bad_angle = false;
      if(valid_quad) {
        std::array<double, 4> a;
        for(int c = 0; c < 4; ++c) a[c] = corner_angle_degrees(P[(c + 3) % 4], P[c], P[(c + 1) % 4]);
        // only the angle of a corner under 45 degrees is forced, as the verifier has it: the
        // other three of the quad spanning it, not the paper's [alpha, 180 - alpha]
        for(int c = 0; c < 4; ++c)
          if(angle_out_of_range(a[c]) && !m_zone.forced_angle(Q[c], a[c]))
            bad_angle = true;
      }
      if(!valid_quad) ++m_zone.report.invalid_quads;
      if(bad_angle) {
        ++m_zone.report.bad_angle_quads;
        ++m_zone.report.bad_angle_quads_by_layer[q < m_zone.layer_begin[0] ? 0 : q < m_zone.layer_begin[1] ? 1 : 2];
      }
      const bool near = std::any_of(Q.begin(), Q.end(), [&](std::size_t v) { return near_invalid[v] != 0; });
      if(!valid_quad || (bad_angle && !near)) {
        auto& requests = valid_quad ? m_zone.requests.for_angles : m_zone.requests.for_validity;
        double size = HUGE_VAL; // of the finest cells the quad hangs from
        for(int c = 0; c < 4; ++c)
          if(Q[c] < m_zone.core_points) {
            requests.emplace_back(m_zone.xy[Q[c]], m_zone.local_size[Q[c]]);
            size = (std::min)(size, m_zone.local_size[Q[c]]);
          }
        for(int c = 0; c < 4; ++c)
          if(Q[c] >= m_zone.core_points && Q[c] - m_zone.core_points < m_zone.first_core.size()) {
            const std::size_t b = m_zone.first_core[Q[c] - m_zone.core_points];
            requests.emplace_back(m_zone.xy[b], m_zone.local_size[b]);
            size = (std::min)(size, m_zone.local_size[b]);
          }
        // not for an invalid quad: a broken buffer's quads can span tens of cells each, and
        // their corners' cells suffice (their whole areas would ask for far more cells)
        if(valid_quad) request_over_area(P, size, requests);
        // and under the quad itself: at an input corner a poor quad's core vertices may all lie
        // on one side of it, and refining at them alone brought the same poor quad back a level
        // nearer the corner, round after round
        if(valid_quad && std::isfinite(size)) requests.emplace_back(mean_2d(P.begin(), P.end()), size);
      }
    }
  }

private:
  // by point: whether it is within two quads of a quad not `valid`
  std::vector<char> near_invalid_vertices(const std::vector<char>& valid) const
  {
    std::vector<char> near(m_zone.mesh.points.size(), 0);
    if(std::find(valid.begin(), valid.end(), 0) == valid.end()) return near;
    for(std::size_t q = 0; q < valid.size(); ++q)
      if(!valid[q])
        for(std::size_t v : m_zone.mesh.quads[q]) near[v] = 1;
    const Vertex_quads quads_at(m_zone.mesh.quads, m_zone.mesh.points.size());
    for(int ring = 0; ring < 2; ++ring) {
      std::vector<char> next = near;
      for(std::size_t v = 0; v < near.size(); ++v)
        if(near[v])
          for(std::size_t q : quads_at[v])
            for(std::size_t w : m_zone.mesh.quads[q]) next[w] = 1;
      near.swap(next);
    }
    return near;
  }

  // A buffer quad is about as large as the cells it hangs from. One far larger spans a stretch
  // the core does not reach (the clearance peeled a strip one cell thick from a dead end), and
  // refining at its corners does not bring the core back: requests at cells' spacing over the
  // quad's box do.
  void request_over_area(const std::array<Point_2d, 4>& P, double size,
                         std::vector<std::pair<Point_2d, double>>& requests) const
  {
    if(!(size > 0) || !std::isfinite(size)) return;
    double x0 = P[0].x(), x1 = P[0].x(), y0 = P[0].y(), y1 = P[0].y();
    for(const Point_2d& p : P) {
      x0 = (std::min)(x0, p.x()); x1 = (std::max)(x1, p.x());
      y0 = (std::min)(y0, p.y()); y1 = (std::max)(y1, p.y());
    }
    // a cell's few times: the corners' requests suffice; and at most 64 requests a quad
    const double span = (std::max)(x1 - x0, y1 - y0);
    if(span <= 4 * size) return;
    const double step = (std::max)(size, span / 8);
    for(double x = x0 + step / 2; x < x1; x += step)
      for(double y = y0 + step / 2; y < y1; y += step)
        requests.emplace_back(Point_2d(x, y), size);
  }

  Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_CHECK_H
