// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_INSERT_POINTS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_INSERT_POINTS_H

#include <CGAL/Quad_mesher_2/Cell_key.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Point_anchor.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/Key_map.h>
#include <CGAL/Quad_mesher_2/internal/lattice_region.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Making input points mesh vertices (paper §3, Lemma 1), with a construction of our own
// where the paper's Fig. 2 is missing.
//
// Each point P gets an anchor: a vertex W of the level-M lattice near P, d = P - W, and a
// radius R. The tree is refined until the 2R x 2R level-M cells around W are leaves and no
// level-M cell of the (2R+2)^2 block around W is split; then those cells are plain squares
// after templating (no active corner touches them). W moves onto P, the lattice vertices at
// Chebyshev distance r < R from W move by factor(R, r) d, the block's rim stays (a "tent").
//  - R = 1, when |dx|, |dy| <= 3g/16 (g the level-M cell side) at level M0 or M0+1 (M0 from
//    the sizing): only W moves, the paper's case B1. The four quads at P are squares with one
//    corner moved by at most 3g/16 per axis: angles in [72.05°, 115.99°], aspect ratio at most
//    1.442. (The paper's g/4 allows aspect 1.61 when dx and dy have opposite signs.)
//  - R = 3 otherwise, at level M0 with the nearest W (|dx|, |dy| <= g/2): ring 1 moves by
//    3d/4, ring 2 by 3d/8. Relative to any quad the displacement is at most 3g/16 per axis:
//    angles in [72.05°, 115.99°], aspect ratio at most 1.281 at P (Lemma 1 asks for 1.5) and
//    1.442 elsewhere. A radius-2 tent barely can: moving ring 1 by d/2 gives aspect 1.61 at
//    P, only factors near 0.58-0.59 meet both bounds there, and then other quads reach 1.73.
// test_insert_points.cpp samples d to check these bounds. Blocks of different anchors never
// share a cell, so no vertex moves twice; crowded blocks go one level deeper until none is.
// Under Epick the moved vertices carry a few roundings of their coordinates; the bounds have
// degrees of room for them. Under Epeck they are exact.
inline double tent_factor(int radius, int ring)
{
  static const double three[3] = { 1.0, 0.75, 0.375 };
  return radius == 1 ? (ring == 0 ? 1.0 : 0.0) : (ring < 3 ? three[ring] : 0.0);
}

// `true` if the block and rim of `a` lie in the region the mesh covers
inline bool block_in_region(const Point_anchor& a, const Lattice_region& region)
{
  return region_contains_cell(region, a.level, a.X - a.radius - 1, a.Y - a.radius - 1)
         && region_contains_cell(region, a.level, a.X + a.radius, a.Y + a.radius);
}

// The anchor of point p for base level `level`: a radius-1 tent at level or level+1 if p is
// within 3g/16 of a lattice vertex there, else a radius-3 tent at level.
// Returns false if the block does not fit in `region`.
template <class Tree, class Point_2>
bool choose_anchor(const Tree& tree, const Point_2& p, int level, const Lattice_region& region, Point_anchor& a)
{
  const auto& traits = tree.geom_traits();
  const double px = CGAL::to_double(traits.compute_x_2_object()(p));
  const double py = CGAL::to_double(traits.compute_y_2_object()(p));
  for(int m = level; m <= (std::min)(level + 1, tree.max_depth()); ++m) {
    auto w = tree.nearest_vertex(p, m);
    const double reach = tree.cell_side(m) * 3 / 16;
    a.level = m;
    a.radius = 1;
    a.X = w.first;
    a.Y = w.second;
    // decided in doubles: the bounds above hold with room to spare up to 0.2 g
    if(std::abs(px - tree.lattice_x(m, w.first)) <= reach
       && std::abs(py - tree.lattice_y(m, w.second)) <= reach && block_in_region(a, region))
      return true;
  }
  auto w = tree.nearest_vertex(p, level);
  a.level = level;
  a.radius = 3;
  a.X = w.first;
  a.Y = w.second;
  return block_in_region(a, region);
}

// Refines `tree` until every anchor's block is as required, deepening the anchors whose
// block is crowded (split cells, another anchor's cells, or the edge of `region`, the part of
// the grid the mesh covers). Balances the tree. `levels[i]` is the first base level tried for
// points[i]; `name(i)` is how the user knows it, for messages.
template <class Tree, class PointRange, class PointName>
std::vector<Point_anchor> anchor_points(Tree& tree, const PointRange& points, std::vector<int> levels,
                                        const Lattice_region& region, const PointName& name)
{
  const std::size_t n = points.size();
  std::vector<Point_anchor> anchors(n);
  std::vector<bool> settled(n, false);
  for(std::size_t i = 0; i < n; ++i)
    anchors[i].point = i;
  auto too_deep = [&](std::size_t i) {
    std::ostringstream msg;
    msg << "input point " << name(i) << " cannot be made a mesh vertex within "
        << tree.depth_limit() << ": it is too close to another input point";
    return Meshing_error(msg.str());
  };
  for(;;) {
    std::size_t cells = 0;
    for(std::size_t i = 0; i < n; ++i) {
      Point_anchor& a = anchors[i];
      if(!settled[i]) {
        for(;;) {
          if(levels[i] > tree.max_depth())
            throw too_deep(i);
          if(choose_anchor(tree, points[i], levels[i], region, a))
            break;
          ++levels[i];
        }
        for(std::int64_t j = a.Y - a.radius; j < a.Y + a.radius; ++j)
          for(std::int64_t k = a.X - a.radius; k < a.X + a.radius; ++k)
            tree.ensure_node(Cell_key(a.level, std::uint64_t(k), std::uint64_t(j)));
      }
      cells += 4 * a.radius * a.radius;
    }
    tree.balance();

    // Check every anchor: a settled block can still be crowded by a later refinement.
    Key_map owner(cells);
    std::vector<bool> crowded(n, false);
    for(std::size_t i = 0; i < n; ++i) {
      const Point_anchor& a = anchors[i];
      const int r = a.radius;
      for(std::int64_t j = a.Y - r - 1; j < a.Y + r + 1; ++j)
        for(std::int64_t k = a.X - r - 1; k < a.X + r + 1; ++k) {
          Cell_key c(a.level, std::uint64_t(k), std::uint64_t(j));
          const bool inner = j >= a.Y - r && j < a.Y + r && k >= a.X - r && k < a.X + r;
          if(tree.is_split(c) || (inner && !tree.is_leaf(c)))
            crowded[i] = true;
          if(inner) {
            auto ins = owner.insert(c.code(), std::uint32_t(i));
            if(!ins.second && *ins.first != i) {
              crowded[i] = true;
              crowded[*ins.first] = true;
            }
          }
        }
    }
    bool changed = false;
    for(std::size_t i = 0; i < n; ++i) {
      settled[i] = !crowded[i];
      if(crowded[i]) {
        ++levels[i];
        changed = true;
      }
    }
    if(!changed)
      return anchors;
  }
}

// Moves each anchor's vertex W onto its point and the lattice vertices around it as the tent
// says. `vertex_keys[v]` is the key of mesh vertex v on the tree's vertex lattice. Returns
// the vertex of each anchor's point.
template <class Tree, class PointRange>
std::vector<std::size_t> move_anchors(const Tree& tree, Quad_mesh_2<typename Tree::Point_2>& mesh,
                  const std::vector<Key_code>& vertex_keys,
                  const std::vector<Point_anchor>& anchors, const PointRange& points)
{
  typedef typename Tree::FT FT;
  const auto& traits = tree.geom_traits();
  auto x_of = traits.compute_x_2_object();
  auto y_of = traits.compute_y_2_object();
  auto make_point = traits.construct_point_2_object();
  if(anchors.empty()) // a domain without isolated points: no index of every vertex to build
    return {};
  Key_map index(vertex_keys.size());
  for(std::size_t v = 0; v < vertex_keys.size(); ++v)
    index.insert(vertex_keys[v], std::uint32_t(v));
  const int top = tree.vertex_level();
  std::vector<std::size_t> point_vertices;
  point_vertices.reserve(anchors.size());
  for(const Point_anchor& a : anchors) {
    const int shift = top - a.level;
    auto vertex = [&](std::int64_t X, std::int64_t Y) {
      const std::uint32_t* v = index.find(lattice_key(std::uint64_t(X) << shift, std::uint64_t(Y) << shift));
      CGAL_assertion(v != nullptr);
      return *v;
    };
    const auto& p = points[a.point];
    const std::uint32_t w = vertex(a.X, a.Y);
    const FT dx = x_of(p) - x_of(mesh.points[w]);
    const FT dy = y_of(p) - y_of(mesh.points[w]);
    for(int oy = 1 - a.radius; oy < a.radius; ++oy)
      for(int ox = 1 - a.radius; ox < a.radius; ++ox) {
        const int ring = (std::max)(std::abs(ox), std::abs(oy));
        if(ring == 0)
          continue;
        const std::uint32_t v = vertex(a.X + ox, a.Y + oy);
        const FT f(tent_factor(a.radius, ring));
        mesh.points[v] = make_point(x_of(mesh.points[v]) + f * dx, y_of(mesh.points[v]) + f * dy);
      }
    mesh.points[w] = p; // the input point itself: exact under any kernel
    point_vertices.push_back(w);
  }
  return point_vertices;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_INSERT_POINTS_H
