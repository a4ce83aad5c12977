// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_BUFFER_REPORT_H
#define CGAL_QUAD_MESHER_2_BUFFER_REPORT_H

#include <array>
#include <cstddef>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// What the buffer stages (paper §4.4-§5) did in the last refinement round of a run, as
/// `Quadtree_mesher_2::buffer_report()` gives it.
struct Buffer_report
{
  /// pieces of core at most two cells across that matched no loop of the domain, or one a
  /// larger piece matched, left to the buffer of the others (see the manual)
  std::size_t dropped_core_pieces = 0;
  /// core boundary vertices moved out into the buffer (notches opened), and in (corners cut)
  std::size_t moved_notches = 0;
  std::size_t cut_corners = 0;
  /// notches covered by a new core quad, and convex corners whose quad was split in three
  std::size_t filled_notches = 0;
  std::size_t split_corners = 0;
  /// after the templates: core boundary vertices whose buffer-side angle is outside
  /// [112.5°, 225°] (Lemma 2), and those of them not within 2h of an input corner
  std::size_t buffer_angles_out = 0;
  std::size_t buffer_angles_out_away_from_corners = 0;
  /// core boundary vertices moved by the plane search, and interior core vertices moved to
  /// give them room
  std::size_t searched_vertices = 0;
  std::size_t shaped_interior = 0;
  std::size_t first_layer_quads = 0;
  std::size_t second_layer_quads = 0;
  /// corners over 270° whose fan in the second layer may take four F points instead of three
  /// (see the manual), and those of them that took four: each is decided by the strip's quads
  /// about it
  std::size_t fans_that_may_take_four = 0;
  std::size_t fans_of_four = 0;
  /// quads the buffer stages made or changed that are not strictly convex, and valid ones
  /// with an angle outside [45°, 135°] that no input corner forces
  std::size_t invalid_quads = 0;
  std::size_t bad_angle_quads = 0;
  /// the bad-angle quads among the core's quads the templates changed, the first layer's
  /// (Lemma 3) and the second's (Lemma 4)
  std::array<std::size_t, 3> bad_angle_quads_by_layer{ { 0, 0, 0 } };
  /// the local moves of the templates' plane search, the first-layer smoothing and the
  /// optimiser that were searched, and those taken from a state seen in this round or the
  /// last (the same result, not searched again): after the first round most moves start
  /// where the round before left them
  std::size_t moves_searched = 0;
  std::size_t moves_recalled = 0;
  /// a message when the buffer could not be built (core loops not matching the domain's)
  std::string failure;
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_BUFFER_REPORT_H
