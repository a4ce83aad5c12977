// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The paper's exception of Fig. 4(b) (core edges on the boundary need no buffer) carried to a
// whole domain: where every boundary segment lies on sides of the quadtree's cells (an
// axis-parallel domain whose corners are lattice points), the cells inside the domain mesh it
// as they are. No buffer is built, and every angle is the core's: 90 degrees where the cells
// are uniform, 45 or 135 in the 2-refinement transitions.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_GRID_ALIGNED_DOMAIN_H
#define CGAL_QUAD_MESHER_2_INTERNAL_GRID_ALIGNED_DOMAIN_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone_clearance.h>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// whether every boundary segment of the domain is parallel to an axis, exactly (the only
/// boundaries that can lie on cell sides)
template <class K>
bool is_axis_parallel(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, const K& traits)
{
  const auto compare_x = traits.compare_x_2_object();
  const auto less_y = traits.less_y_2_object();
  for(const auto& loop : loops.loops)
    for(std::size_t i = 0; i < loop.vertices.size(); ++i) {
      const auto& a = domain.points[loop.vertices[i]];
      const auto& b = domain.points[loop.vertices[(i + 1) % loop.vertices.size()]];
      if(compare_x(a, b) != EQUAL && (less_y(a, b) || less_y(b, a))) return false;
    }
  return true;
}

/// The quads of a templated quadtree mesh that mesh the domain with no buffer, if its
/// boundary lies on their sides.
template <class K>
class Grid_aligned_cells
{
  typedef typename K::Point_2 Point_2;
  typedef Quad_mesh_2<Point_2> Mesh;

public:
  Grid_aligned_cells(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, const K& traits)
    : m_domain(domain), m_loops(loops), m_traits(traits), m_segments(domain, loops, traits)
  {}

  /// Keeps in `mesh` the quads whose centre is inside the domain, if the boundary of their
  /// union is the domain's: each of its edges lies on an input segment, and every input
  /// vertex is one of its vertices (then its loops cover the input's). Returns false, and
  /// leaves `mesh` as it was, if not. `removed`: the quads left out.
  bool keep_cells_inside(Mesh& mesh, std::size_t& removed) const
  {
    std::vector<typename Mesh::Quad> inside;
    for(const auto& q : mesh.quads) {
      // a point strictly inside the quad: the middle of a diagonal, to rounding
      const Point_2d a = to_point_2d(mesh.points[q[0]]), c = to_point_2d(mesh.points[q[2]]);
      const Point_2 centre = m_traits.construct_point_2_object()(0.5 * (a.x() + c.x()), 0.5 * (a.y() + c.y()));
      if(on_boundary(centre)) return false; // a segment crosses the quad
      if(m_segments.in_domain(centre)) inside.push_back(q);
    }
    if(!boundary_is_the_domains(mesh.points, inside)) return false;
    removed = mesh.quads.size() - inside.size();
    mesh.quads = std::move(inside);
    drop_unused_points(mesh);
    return true;
  }

private:
  bool on_segment(const Point_2& p, std::size_t s) const
  {
    const Point_2& a = m_segments.point(s, 0);
    const Point_2& b = m_segments.point(s, 1);
    return m_traits.orientation_2_object()(a, b, p) == COLLINEAR
           && m_traits.collinear_are_ordered_along_line_2_object()(a, p, b);
  }

  bool on_boundary(const Point_2& p) const
  {
    bool on = false;
    m_segments.query(m_traits.construct_bbox_2_object()(p), [&](std::size_t s) { on = on || on_segment(p, s); });
    return on;
  }

  bool edge_on_a_segment(const Point_2& p, const Point_2& q) const
  {
    const auto bbox = m_traits.construct_bbox_2_object();
    bool on = false;
    m_segments.query(bbox(p) + bbox(q), [&](std::size_t s) { on = on || (on_segment(p, s) && on_segment(q, s)); });
    return on;
  }

  // every edge of one quad only lies on a segment, and every input vertex is on such an edge
  bool boundary_is_the_domains(const std::vector<Point_2>& points, const std::vector<typename Mesh::Quad>& quads) const
  {
    if(quads.empty()) return false;
    std::vector<std::pair<std::size_t, std::size_t>> edges; // undirected, smaller end first
    for(const auto& q : quads)
      for(int k = 0; k < 4; ++k) edges.emplace_back((std::min)(q[k], q[(k + 1) % 4]), (std::max)(q[k], q[(k + 1) % 4]));
    std::sort(edges.begin(), edges.end());
    std::vector<Point_2d> on_boundary;
    for(std::size_t i = 0; i < edges.size();) {
      std::size_t j = i + 1;
      while(j < edges.size() && edges[j] == edges[i]) ++j;
      if(j - i == 1) {
        const auto [a, b] = edges[i];
        if(!edge_on_a_segment(points[a], points[b])) return false;
        on_boundary.push_back(to_point_2d(points[a]));
        on_boundary.push_back(to_point_2d(points[b]));
      }
      i = j;
    }
    std::sort(on_boundary.begin(), on_boundary.end());
    for(const auto& loop : m_loops.loops)
      for(std::size_t v : loop.vertices)
        if(!std::binary_search(on_boundary.begin(), on_boundary.end(), to_point_2d(m_domain.points[v]))) return false;
    return true;
  }

  static void drop_unused_points(Mesh& mesh)
  {
    std::vector<std::size_t> index(mesh.points.size(), std::size_t(-1));
    std::vector<Point_2> kept;
    for(auto& q : mesh.quads)
      for(std::size_t& v : q) {
        if(index[v] == std::size_t(-1)) {
          index[v] = kept.size();
          kept.push_back(mesh.points[v]);
        }
        v = index[v];
      }
    mesh.points = std::move(kept);
  }

  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  const K& m_traits;
  Domain_segments<K> m_segments;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_GRID_ALIGNED_DOMAIN_H
