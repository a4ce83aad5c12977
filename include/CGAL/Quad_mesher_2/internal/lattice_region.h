// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_LATTICE_REGION_H
#define CGAL_QUAD_MESHER_2_INTERNAL_LATTICE_REGION_H

#include <CGAL/Quad_mesher_2/Cell_key.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// The part of a quadtree's root grid a mesh covers: a rectangle of whole cells of one
// lattice level, from the grid's origin. A domain covers the whole grid (the clearance then
// cuts it to the domain); a point cloud covers its points' bounding box with a margin, much
// less than the grid, whose power-of-two side can reach almost twice the cloud's extent.
// The tree is split along the region's sides (split_along_region), so that every leaf lies
// inside it or outside, and the mesh is the templates of the leaves inside: a conforming
// sub-mesh of the whole grid's, tiling the rectangle exactly.
struct Lattice_region
{
  int level = 0;
  // the region is [0, nx] x [0, ny] in cells of `level` from the origin
  std::uint64_t nx = 0, ny = 0;
};

template <class Tree>
Lattice_region whole_grid(const Tree& tree)
{
  return { 0, tree.root_cells_x(), tree.root_cells_y() };
}

// `true` if the level-`level` cell (i, j) lies inside `r`
inline bool region_contains_cell(const Lattice_region& r, int level, std::int64_t i, std::int64_t j)
{
  if(i < 0 || j < 0)
    return false;
  // the cell's upper corner against the region's, on the finer of the two lattices (both
  // within the grid's 2^45 cells of the deepest level: no overflow)
  if(level >= r.level)
    return std::uint64_t(i) + 1 <= (r.nx << (level - r.level)) && std::uint64_t(j) + 1 <= (r.ny << (level - r.level));
  return (std::uint64_t(i) + 1) << (r.level - level) <= r.nx && (std::uint64_t(j) + 1) << (r.level - level) <= r.ny;
}

// The first line of the level-`level` lattice of one axis at or past `hi`, counted from
// the grid's origin `origin` (the lattice's lines are exact doubles).
template <class Tree>
std::uint64_t first_line_past(const Tree& tree, int level, double origin, double hi)
{
  const double side = tree.cell_side(level);
  std::uint64_t n = std::uint64_t((std::max)(std::ceil((hi - origin) / side), 1.0));
  while(n > 1 && origin + double(n - 1) * side >= hi)
    --n;
  while(origin + double(n) * side < hi)
    ++n;
  return n;
}

// A point cloud's region: its lower and left sides are the grid's, whose origin is the
// lower-left corner of the points' box widened by the margin; its upper and right sides lie
// at or past (`xmax`, `ymax`), past the box's other corner, by at most `slack`, each on the
// coarsest lattice that has a line there: the fewer cells split along it. If the tree's depth
// allows no such line, on the finest lattice's first line past the corner.
template <class Tree>
Lattice_region point_cloud_region(const Tree& tree, double xmax, double ymax, double slack)
{
  int level_x = -1, level_y = -1;
  std::uint64_t nx = 0, ny = 0;
  for(int level = 0; level <= tree.max_depth() && (level_x < 0 || level_y < 0); ++level) {
    const std::uint64_t lx = first_line_past(tree, level, tree.origin_x(), xmax);
    const std::uint64_t ly = first_line_past(tree, level, tree.origin_y(), ymax);
    if(level_x < 0 && tree.lattice_x(level, std::int64_t(lx)) <= xmax + slack) {
      level_x = level;
      nx = lx;
    }
    if(level_y < 0 && tree.lattice_y(level, std::int64_t(ly)) <= ymax + slack) {
      level_y = level;
      ny = ly;
    }
  }
  const int deepest = tree.max_depth();
  if(level_x < 0) {
    level_x = deepest;
    nx = first_line_past(tree, deepest, tree.origin_x(), xmax);
  }
  if(level_y < 0) {
    level_y = deepest;
    ny = first_line_past(tree, deepest, tree.origin_y(), ymax);
  }
  Lattice_region r;
  r.level = (std::max)(level_x, level_y);
  r.nx = nx << (r.level - level_x);
  r.ny = ny << (r.level - level_y);
  CGAL_postcondition(r.nx <= tree.cells_x(r.level) && r.ny <= tree.cells_y(r.level));
  return r;
}

// Splits the leaves that cross the lattice line `at` cells of `level` from the origin,
// vertical (x = const) if `vertical`, within its first `length` cells. On the coarsest
// lattice that holds the line, the cells beside it are those that crossed it.
template <class Tree>
void split_along_line(Tree& tree, int level, std::uint64_t at, std::uint64_t length, bool vertical)
{
  while(level > 0 && at % 2 == 0) {
    at /= 2;
    length = (length + 1) / 2;
    --level;
  }
  for(std::uint64_t k = 0; k < length; ++k)
    tree.ensure_node(vertical ? Cell_key(level, at - 1, k) : Cell_key(level, k, at - 1));
}

// Makes every leaf of `tree` lie inside `r` or outside it (the grid's own sides need no
// split).
template <class Tree>
void split_along_region(Tree& tree, const Lattice_region& r)
{
  split_along_line(tree, r.level, r.nx, r.ny, true);
  split_along_line(tree, r.level, r.ny, r.nx, false);
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_LATTICE_REGION_H
