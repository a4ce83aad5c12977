// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_POINT_ANCHOR_H
#define CGAL_QUAD_MESHER_2_POINT_ANCHOR_H

#include <cstddef>
#include <cstdint>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// Where the points stage (paper §3, Lemma 1) makes an input point `P` a mesh vertex, as
/// `Quadtree_mesher_2::anchors()` gives it: the vertex `W` of the level-`level` lattice that
/// moves onto `P`, and the radius `R` of its tent (see the user manual's definitions). The
/// tree is refined so that the `2R x 2R` cells of that level around `W` are leaves; `W` moves
/// onto `P` and the lattice vertices of the block nearer `W` move part of the way.
struct Point_anchor
{
  /// the index of `P` in `Quadtree_mesher_2::anchored_points()`
  std::size_t point;
  /// the quadtree level `M` of `W`'s lattice
  int level;
  /// the tent's radius `R`: 1 (only `W` moves) or 3 (two rings around it move too)
  int radius;
  /// `W` on the level's lattice: the vertex at `(X, Y)` times the level's cell side from the
  /// root grid's origin
  std::int64_t X, Y;
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_POINT_ANCHOR_H
