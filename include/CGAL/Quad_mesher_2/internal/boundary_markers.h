// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The boundary edges of a whole domain's mesh with the boundary marker of the input segment
// each lies on (`Quad_mesh_2::boundary_edges`). The segment is found by the edge's midpoint:
// every boundary edge of the finished mesh lies on an input segment (up to the rounding of
// its ends), or within the chord tolerance of two where it leaves out an input vertex. The
// buffer stages know the segment of each boundary point too, but their records change with
// every move, round and renumbering; the geometry does not.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_MARKERS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_MARKERS_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>
#include <CGAL/Quad_mesher_2/internal/loop_locator.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// the edges of `mesh`, the mesh of the domain whose loops are `loops`, that belong to one
/// quad only, in the order of the quads, each with the marker of the input segment nearest
/// its midpoint (`loop_edge_markers()`); `edge_loops` gets the loop of that segment, per edge
template <class K>
std::vector<typename Quad_mesh_2<typename K::Point_2>::Boundary_edge>
marked_boundary_edges(const Quad_mesh_2<typename K::Point_2>& mesh, const Domain_2<K>& domain,
                      const Domain_loops_2<K>& loops, std::vector<std::size_t>& edge_loops)
{
  edge_loops.clear();
  const std::vector<std::vector<int>> markers = loop_edge_markers(domain, loops);
  const std::unique_ptr<Loop_locator> locator = make_loop_locator(domain, loops);
  const Vertex_quads quads_at(mesh.quads, mesh.points.size());
  std::vector<typename Quad_mesh_2<typename K::Point_2>::Boundary_edge> edges;
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) {
      const std::size_t a = mesh.quads[q][c], b = mesh.quads[q][(c + 1) % 4];
      // an inner edge a -> b is b -> a in the other quad at a
      bool inner = false;
      for(std::size_t other : quads_at[a])
        inner = inner || (other != q && mesh.quads[other][(corner_of(mesh.quads[other], a) + 3) % 4] == b);
      if(inner) continue;
      const Point_2d pa = to_point_2d(mesh.points[a]), pb = to_point_2d(mesh.points[b]);
      const Loop_locator::Hit h = locator->closest(CGAL::midpoint(pa, pb), length_2d(pb - pa));
      edges.push_back({ a, b, markers[h.loop][h.edge] });
      edge_loops.push_back(h.loop);
    }
  return edges;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_MARKERS_H
