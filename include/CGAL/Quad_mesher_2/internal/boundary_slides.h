// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Where the smoothing may move a boundary vertex on a curved stretch of the boundary (not in
// the paper): along the input segment it lies on. The vertex stays on the input, and the two
// boundary edges at it keep the loop vertices they leave out within the chord tolerance, the
// rule the second buffer layer chose its nodes by (second_buffer_layer.h).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SLIDES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SLIDES_H

#include <CGAL/Quad_mesher_2/internal/loop_locator.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// One boundary vertex's slide: the input segment it lies on, and the loop vertices that the
/// boundary edge from its previous boundary neighbour, and the one to its next, leave out.
struct Boundary_slide
{
  Point_2d a, b;
  std::vector<Point_2d> left_out_before, left_out_after;
};

/// The slides of a quad mesh's boundary vertices (see the file comment).
class Boundary_slides
{
public:
  /// `xy`, `quads`: the mesh, whose boundary lies on the loops `locator` holds;
  /// `tolerance`: how far the boundary may pass from a loop vertex it leaves out (absolute)
  Boundary_slides(const std::vector<Point_2d>& xy, const std::vector<Quad_vertices>& quads,
                  const Loop_locator& locator, double tolerance)
    : m_slide_of(xy.size(), none), m_tolerance(tolerance)
  {
    const Vertex_quads quads_at(quads, xy.size());
    std::vector<int> boundary_edges(xy.size(), 0);
    std::vector<std::array<std::size_t, 2>> edges;
    for_each_boundary_edge(quads, quads_at, xy.size(), [&](std::size_t a, std::size_t b) {
      ++boundary_edges[a];
      ++boundary_edges[b];
      edges.push_back({ a, b });
    });
    std::vector<Loop_locator::Hit> hit(xy.size());
    std::vector<char> on_loop(xy.size(), 0), inside_segment(xy.size(), 0);
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(boundary_edges[v] == 2) {
        on_loop[v] = on_the_loops(locator, xy[v], hit[v]);
        const auto& loop = locator.loop(hit[v].loop);
        inside_segment[v] = on_loop[v] != 0 && xy[v] != loop[hit[v].edge] && xy[v] != loop[(hit[v].edge + 1) % loop.size()];
      }
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(inside_segment[v] != 0) {
        m_slide_of[v] = m_slides.size();
        const auto& loop = locator.loop(hit[v].loop);
        m_slides.push_back({ loop[hit[v].edge], loop[(hit[v].edge + 1) % loop.size()], {}, {} });
      }
    for(const auto& e : edges) add_left_out(locator, e[0], e[1], hit, on_loop);
  }

  /// v's slide, or null if v stays (not inside an input segment, its boundary edges do not
  /// follow one loop closely, or v came after the mesh the slides were made for)
  const Boundary_slide* slide(std::size_t v) const
  {
    return v >= m_slide_of.size() || m_slide_of[v] == none ? nullptr : &m_slides[m_slide_of[v]];
  }

  /// whether v at `p`, between boundary neighbours at `prev` and `next`, keeps each loop
  /// vertex its boundary edges leave out within the tolerance, or no further than `from`
  /// (v's place now) kept it
  bool keeps_chords(std::size_t v, const Point_2d& from, const Point_2d& p, const Point_2d& prev, const Point_2d& next) const
  {
    const Boundary_slide& s = m_slides[m_slide_of[v]];
    for(const Point_2d& g : s.left_out_before)
      if(point_segment_distance(g, prev, p) > (std::max)(m_tolerance, point_segment_distance(g, prev, from))) return false;
    for(const Point_2d& g : s.left_out_after)
      if(point_segment_distance(g, p, next) > (std::max)(m_tolerance, point_segment_distance(g, from, next))) return false;
    return true;
  }

private:
  static constexpr std::size_t none = std::size_t(-1);
  // an edge leaving out more loop vertices than this follows the loop too loosely to judge
  static constexpr std::size_t max_left_out = 64;

  // whether p lies on an input segment (to rounding, 1e-10 of the diagonal); fills `h`
  static bool on_the_loops(const Loop_locator& locator, const Point_2d& p, Loop_locator::Hit& h)
  {
    const double near = 1e-10 * locator.diagonal();
    h = locator.closest(p, near);
    const auto& loop = locator.loop(h.loop);
    return h.dist <= (std::max)(near, 16 * coordinate_rounding_2d(loop[h.edge], loop[(h.edge + 1) % loop.size()]));
  }

  // The boundary edge u -> w: the loop vertices between u and w along their loop, the shorter
  // way round, join u's and w's lists. Where u or w is off the loops, they lie on different
  // loops, or far apart along theirs, neither slides.
  void add_left_out(const Loop_locator& locator, std::size_t u, std::size_t w, const std::vector<Loop_locator::Hit>& hit,
                    const std::vector<char>& on_loop)
  {
    if(m_slide_of[u] == none && m_slide_of[w] == none) return;
    const Loop_locator::Hit& hu = hit[u];
    const Loop_locator::Hit& hw = hit[w];
    const bool same_loop = on_loop[u] != 0 && on_loop[w] != 0 && hu.loop == hw.loop;
    std::vector<Point_2d> between;
    if(!same_loop || !loop_vertices_between(locator, hu, hw, between)) {
      m_slide_of[u] = m_slide_of[w] = none;
      return;
    }
    if(m_slide_of[u] != none) m_slides[m_slide_of[u]].left_out_after = between;
    if(m_slide_of[w] != none) m_slides[m_slide_of[w]].left_out_before = between;
  }

  // the loop vertices strictly between two points of one loop, the shorter way round; false
  // if that is over a quarter of the loop or leaves out too many
  static bool loop_vertices_between(const Loop_locator& locator, const Loop_locator::Hit& p, const Loop_locator::Hit& q,
                                    std::vector<Point_2d>& between)
  {
    const std::size_t l = p.loop;
    const double L = locator.length(l);
    const double forward = std::fmod(locator.param(q) - locator.param(p) + L, L);
    const bool p_first = forward <= L / 2;
    const Loop_locator::Hit& first = p_first ? p : q;
    const double span = p_first ? forward : L - forward;
    if(!(span < L / 4)) return false;
    const auto& loop = locator.loop(l);
    const double s0 = locator.param(first);
    std::size_t k = (first.edge + 1) % loop.size();
    for(std::size_t step = 0; step < loop.size(); ++step, k = (k + 1) % loop.size()) {
      const double s = std::fmod(locator.arc(l, k) - s0 + L, L);
      if(s == 0) continue; // the vertex `first` lies on
      if(!(s < span)) break;
      if(between.size() == max_left_out) return false;
      between.push_back(loop[k]);
    }
    return true;
  }

  std::vector<std::size_t> m_slide_of;
  std::vector<Boundary_slide> m_slides;
  double m_tolerance;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SLIDES_H
