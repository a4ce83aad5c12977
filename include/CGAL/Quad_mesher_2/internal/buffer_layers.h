// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Filling the buffer zone between the core mesh and the domain boundary (paper §4.4-§5), one
// stage per header:
// - buffer_zone.h: the stages' shared state; the core's boundary cycles matched with the
//   domain's loops (each core loop to the loop nearest most of its vertices, one to one, the
//   orientation agreeing);
// - boundary_templates.h (§4.4, with template_search.h and connectivity_templates.h): the core
//   boundary's buffer-side angles brought into [112.5°, 225°] (Lemma 2);
// - first_buffer_layer.h (§4.5): one first buffer point per core boundary vertex;
// - second_buffer_layer.h (§4.6, with strip_pairing.h and sharp_corner_fans.h for §5): the strip
//   from the first buffer points to the boundary;
// - buffer_optimizer.h (not in the paper): a local min-max angle optimisation;
// - buffer_check.h: the exact check and the refinement requests.
// Input: the core mesh left by the clearance (every core vertex has 0 or 2 boundary edges, so
// the core boundary is simple loops, core on the left), with the local size h of every vertex
// (the largest side of its quadtree cells).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H

#include <CGAL/Quad_mesher_2/Buffer_report.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/boundary_templates.h>
#include <CGAL/Quad_mesher_2/internal/buffer_check.h>
#include <CGAL/Quad_mesher_2/internal/buffer_optimizer.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/first_buffer_layer.h>
#include <CGAL/Quad_mesher_2/internal/second_buffer_layer.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The buffer stages on a core mesh, in order. The mesh's points are the core's;
/// `local_size[v]` the side of the largest quadtree cell at core vertex `v`.
template <class K>
class Buffer_layers
{
  typedef Quad_mesh_2<typename K::Point_2> Mesh;

public:
  /// `memo`, if not null, keeps the results of local moves from one refinement round to the
  /// next (see move_memo.h); `chord_tolerance`: how far from a loop vertex the boundary may
  /// pass where it leaves the vertex out, over the domain's diagonal
  Buffer_layers(Mesh& mesh, const std::vector<double>& local_size, const Domain_2<K>& domain,
                const Domain_loops_2<K>& loops, const K& traits, Move_memo* memo = nullptr,
                double chord_tolerance = 1e-3)
    : m_zone(mesh, local_size, domain, loops, traits)
  {
    m_zone.memo = memo;
    m_zone.chord_tolerance = chord_tolerance * m_zone.locator->diagonal();
  }

  const Buffer_report& report() const { return m_zone.report; }
  const Refinement_requests& requests() const { return m_zone.requests; }

  /// Matches the core's boundary loops with the domain's, after dropping the pieces of core
  /// at most two cells across that would not match and hold none of `fixed_points` (a
  /// domain's isolated points); false (with `report().failure` and `requests()`) if they do
  /// not match one to one.
  bool match_loops(const std::vector<std::size_t>& fixed_points = {}) { return m_zone.match_loops(fixed_points); }
  /// Stage "templates": core boundary vertices (and interior ones, but `fixed_points`, a
  /// domain's isolated points) move so that their buffer-side angles meet Lemma 2 where the
  /// core allows.
  void apply_boundary_templates(const std::vector<std::size_t>& fixed_points)
  {
    Boundary_templates<K>(m_zone).apply_boundary_templates(fixed_points);
  }
  /// Stage "templates", after apply_boundary_templates(): new core quads over notches that
  /// could not move, jammed corners split.
  void apply_connectivity_templates() { Boundary_templates<K>(m_zone).apply_connectivity_templates(); }
  /// Stage "buffer1": the first buffer points and the quads B_i F_i F_{i+1} B_{i+1}.
  void build_first_layer() { First_buffer_layer<K>(m_zone).build_first_layer(); }
  /// Stage "buffer2": the strip between the first buffer points and the boundary.
  void build_second_layer() { Second_buffer_layer<K>(m_zone).build_second_layer(); }
  /// The optimisation after stage "buffer2"; `fixed_points` never move.
  void optimize(const std::vector<std::size_t>& fixed_points) { Buffer_optimizer<K>(m_zone).optimize(fixed_points); }
  /// Checks the quads the stages made or changed, counting the invalid and bad-angle ones and
  /// asking for refinement at them.
  void check_quads() { Buffer_check<K>(m_zone).check_quads(); }
  /// Drops the points no quad uses; returns the new index of every old point (`none` for a
  /// dropped one).
  std::vector<std::size_t> remove_unused_points() { return m_zone.remove_unused_points(); }

private:
  Buffer_zone<K> m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H
