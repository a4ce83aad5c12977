// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.6, what a quad costs in the second buffer layer's pairing: its deviation from
// right angles (Buffer_zone::quad_cost()), more where the boundary fixes an angle out of
// range. Not cached: a hash map of the quads tried cost twice what it saved.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_STRIP_COSTS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_STRIP_COSTS_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/state_hash.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The costs of the quads one strip's pairing tries (see the file comment).
template <class K>
class Strip_quad_costs : Buffer_tolerances
{
  typedef Quad_vertices Quad;

public:
  explicit Strip_quad_costs(const Buffer_zone<K>& zone) : m_zone(zone) {}

  // A quad's cost (Buffer_zone::quad_cost()); 1000, as a flat corner, where a boundary node
  // between two others has an angle out of [45, 135] that no input corner forces (the middle of
  // a fan of boundary edges): that angle is the boundary's own, which no later move changes (an
  // input vertex stays; a point on an input edge only slides along it, so its angle stays nearly
  // straight though rounding far from the origin lets it pass as convex).
  double cost(const Quad& q) const
  {
    if(q[0] == none) return 2000.0;
    const double b = m_zone.quad_cost(q);
    return b > 45.0 + angle_tolerance && b < 1000.0 && fixed_angle_out_of_range(q) >= 0 ? 1000.0 : b;
  }

  // A quad's cost in the strip's pairing: cost(), and a hundred degrees more for a quad over
  // 135 degrees on a side of a corner over 270 degrees (wide_side_of_reflex_fan()), so that the
  // pairing opens such a fan rather than keep a side that no later move straightens.
  double strip_cost(const Quad& q) const
  {
    const double b = cost(q);
    if(b <= 45.0 + angle_tolerance || b >= 1000.0) return b;
    return wide_side_of_reflex_fan(q) >= 0 ? b + 100.0 : b;
  }

  // everything strip_cost() reads of vertex v: its position, its input corner angle if any,
  // whether it lies on the boundary chain
  void describe(std::size_t v, State_hash& h) const
  {
    h.add(m_zone.xy[v]);
    h.add(m_zone.input_corner_angle(v));
    h.add(std::uint64_t(on_boundary_chain(v)));
  }

  // the corner (0 to 3) of q at a boundary node between two others whose angle is out of
  // [45, 135] and not forced, or -1
  int fixed_angle_out_of_range(const Quad& q) const
  {
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = q[k], u = q[(k + 3) % 4], w = q[(k + 1) % 4];
      if(!on_boundary_chain(v) || !on_boundary_chain(u) || !on_boundary_chain(w)) continue;
      const double angle = corner_angle_degrees(m_zone.xy[u], m_zone.xy[v], m_zone.xy[w]);
      if(std::abs(angle - 90.0) > 45.0 + angle_tolerance && !m_zone.forced_angle(v, angle)) return k;
    }
    return -1;
  }

  // the corner (0 to 3) of q with over 135 degrees at an input corner of 270 degrees or more
  // (270 to rounding: a fan of two fits exactly 270 only as 135 + 135), between a boundary node
  // and an F point, or -1: a side of a fan of two there, or of a fan of three with an F point
  // off to one side. A fan of two at such a corner keeps over 135 degrees in one of its quads
  // however its F point moves, unlike a fan of three whose middle F point is flat for now: the
  // later moves open that one.
  int wide_side_of_reflex_fan(const Quad& q) const
  {
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = q[k], u = q[(k + 3) % 4], w = q[(k + 1) % 4];
      if(!(m_zone.wide_corner_angle(v) > 270.0 - angle_tolerance) || on_boundary_chain(u) == on_boundary_chain(w)) continue;
      if(corner_angle_degrees(m_zone.xy[u], m_zone.xy[v], m_zone.xy[w]) > 135.0 + angle_tolerance) return k;
    }
    return -1;
  }

  // an input vertex, a point on an input edge, or a gap's candidate extra node (an id past the
  // mesh's points while the strip is paired)
  bool on_boundary_chain(std::size_t v) const
  {
    return m_zone.is_input_vertex(v) || m_zone.slide(v) != nullptr || v >= m_zone.mesh.points.size();
  }

private:
  const Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_STRIP_COSTS_H
