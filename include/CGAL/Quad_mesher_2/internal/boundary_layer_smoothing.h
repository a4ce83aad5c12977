// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The stacks' local min-max angle smoothing, after the extrusion (not in the paper, whose
// templates place their points once). Where a stack quad has an angle outside [45°, 135°]
// (fans over unevenly spaced rays, 1-to-3 steps between rays of unequal spacing, bands where
// a thinned offset bends), the stack nodes around it move one at a time while that lowers
// the worst quads at the node, compared worst first. Nodes on the wall and on the offset (the
// outer mesh's) stay, so nothing outside the stacks changes; no move makes a quad non-convex
// or folds the quads about a node.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_SMOOTHING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_SMOOTHING_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>
#include <CGAL/Quad_mesher_2/internal/boundary_layer_extrusion.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <functional>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

template <class Point_2>
class Layer_smoothing
{
public:
  typedef Quad_mesh_2<Point_2> Mesh;

  /// `nodes[v]`: whether node v stays, or moves as a band's or a fan's; the stack quads are
  /// those from `first_quad` on
  Layer_smoothing(Mesh& mesh, std::size_t first_quad, std::vector<Stack_node> nodes)
    : m_mesh(mesh), m_first_quad(first_quad), m_nodes(std::move(nodes)), m_quads_at(mesh.quads, mesh.points.size())
  {
    for(const Point_2& p : mesh.points) m_xy.push_back(to_point_2d(p));
    m_floor.assign(m_xy.size(), 0);
    for(std::size_t v = 0; v < m_xy.size(); ++v)
      if(m_nodes[v] != Stack_node::fixed) m_floor[v] = reach(v) / 3;
  }

  /// Moves the nodes about the stack quads outside [45°, 135°] and their neighbours, each at
  /// most `visits` times.
  void run(int visits = 16)
  {
    std::deque<std::size_t> queue;
    std::vector<char> queued(m_xy.size(), 0);
    std::vector<int> visited(m_xy.size(), 0);
    auto push = [&](std::size_t v) {
      if(m_nodes[v] != Stack_node::fixed && queued[v] == 0 && visited[v] < visits) {
        queued[v] = 1;
        queue.push_back(v);
      }
    };
    for(std::size_t q = m_first_quad; q < m_mesh.quads.size(); ++q)
      if(badness(q) > 45)
        for(std::size_t v : m_mesh.quads[q]) push_with_neighbours(v, push);
    while(!queue.empty()) {
      const std::size_t v = queue.front();
      queue.pop_front();
      queued[v] = 0;
      ++visited[v];
      if(improve(v)) push_with_neighbours(v, push);
    }
    for(std::size_t v = 0; v < m_xy.size(); ++v)
      if(m_nodes[v] != Stack_node::fixed) m_mesh.points[v] = Point_2(m_xy[v].x(), m_xy[v].y());
  }

private:
  template <class Push>
  void push_with_neighbours(std::size_t v, Push& push) const
  {
    for(std::uint32_t q : m_quads_at[v])
      for(std::size_t u : m_mesh.quads[q]) push(u);
  }

  std::array<Point_2d, 4> corners(std::size_t q) const
  {
    std::array<Point_2d, 4> p;
    for(int c = 0; c < 4; ++c) p[c] = m_xy[m_mesh.quads[q][c]];
    return p;
  }

  double badness(std::size_t q) const { return quad_badness(corners(q)); }

  // the shortest distance from v to another corner of its quads
  double reach(std::size_t v) const
  {
    double d = HUGE_VAL;
    for(std::uint32_t q : m_quads_at[v])
      for(std::size_t u : m_mesh.quads[q])
        if(u != v) d = (std::min)(d, length_2d(m_xy[u] - m_xy[v]));
    return d;
  }

  // the badness of the quads at v in the order of m_quads_at[v]; empty if they fold about v
  // or v comes nearer than `floor` to one of their corners
  std::vector<double> local(std::size_t v, double floor = 0) const
  {
    std::vector<double> b;
    double turn = 0;
    for(std::uint32_t q : m_quads_at[v]) {
      const std::array<Point_2d, 4> p = corners(q);
      const int c = corner_of(m_mesh.quads[q], v);
      for(int k = 1; k < 4; ++k)
        if(length_2d(p[(c + k) % 4] - p[c]) < floor) return {};
      b.push_back(quad_badness(p));
      turn += corner_angle_degrees(p[(c + 3) % 4], p[c], p[(c + 1) % 4]);
    }
    if(std::abs(turn - 360) > 1) return {}; // folded, or v is not inside the mesh
    return b;
  }

  // Whether the quads at a node with badness `a` are better than with `b` (same order):
  // better worst first by more than rounding, and for a band's node, worse than 45 in no
  // quad that was not. A fan's quads are the fan's own construction, spreading the skew
  // among them is what mends it; a band's bad quad is forced by a sharp corner or by the
  // thinning, and spreading its skew along the band only multiplies it.
  static bool better(const std::vector<double>& a, const std::vector<double>& b, Stack_node node)
  {
    if(a.empty()) return false;
    if(node == Stack_node::band)
      for(std::size_t k = 0; k < a.size(); ++k)
        if(a[k] > 45 && a[k] > b[k]) return false;
    std::vector<double> sa = a, sb = b;
    std::sort(sa.begin(), sa.end(), std::greater<double>());
    std::sort(sb.begin(), sb.end(), std::greater<double>());
    for(std::size_t k = 0; k < sa.size(); ++k)
      if(std::abs(sa[k] - sb[k]) > 1e-9) return sa[k] < sb[k];
    return false;
  }

  // A pattern search: the best of eight directions at a step from half the distance to
  // v's nearest quad corner down to 1/1024 of it, kept while it betters the quads at v and
  // keeps v from coming nearer to their corners than a third of that distance at the start
  // (a worst-first order alone would collapse edges: a short edge can have good angles).
  bool improve(std::size_t v)
  {
    const Point_2d start = m_xy[v];
    std::vector<double> current = local(v);
    if(current.empty() || *std::max_element(current.begin(), current.end()) <= 45)
      return false; // nothing to mend, or not inside
    const double reach = this->reach(v), floor = m_floor[v];
    const double directions[8][2] = { { 1, 0 }, { 0.70710678118654752, 0.70710678118654752 }, { 0, 1 },
                                      { -0.70710678118654752, 0.70710678118654752 }, { -1, 0 },
                                      { -0.70710678118654752, -0.70710678118654752 }, { 0, -1 },
                                      { 0.70710678118654752, -0.70710678118654752 } };
    double step = reach / 2;
    for(int tries = 0; step > reach / 1024 && tries < 256; ++tries) {
      const Point_2d from = m_xy[v];
      Point_2d best = from;
      std::vector<double> best_local = current;
      for(const auto& d : directions) {
        m_xy[v] = Point_2d(from.x() + step * d[0], from.y() + step * d[1]);
        const std::vector<double> b = local(v, floor);
        if(better(b, best_local, m_nodes[v])) {
          best = m_xy[v];
          best_local = b;
        }
      }
      m_xy[v] = best;
      if(best_local == current) step /= 2;
      current = best_local;
    }
    return !(m_xy[v] == start);
  }

  Mesh& m_mesh;
  std::size_t m_first_quad;
  std::vector<Stack_node> m_nodes;
  Vertex_quads m_quads_at;
  std::vector<Point_2d> m_xy;
  std::vector<double> m_floor; // by node: the nearest it may come to a corner of its quads
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_SMOOTHING_H
