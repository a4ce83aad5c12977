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

/// One boundary vertex's slide: the input segment (a, b) it lies on, and where the loop
/// vertices that the boundary edge from its previous boundary neighbour, and the one to its
/// next, leave out are in `Boundary_slides`' list of them: [before, after) and [after, end).
struct Boundary_slide
{
  Point_2d a, b;
  std::size_t before = 0, after = 0, end = 0;
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
    std::vector<std::size_t> prev(xy.size(), none), next(xy.size(), none);
    for_each_boundary_edge(quads, quads_at, xy.size(), [&](std::size_t a, std::size_t b) {
      ++boundary_edges[a];
      ++boundary_edges[b];
      next[a] = b;
      prev[b] = a;
    });
    std::vector<Loop_locator::Hit> hit(xy.size());
    std::vector<char> on_loop(xy.size(), 0);
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(boundary_edges[v] == 2) on_loop[v] = on_the_loops(locator, xy[v], hit[v]);
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(on_loop[v] != 0 && !at_a_loop_vertex(locator, xy[v], hit[v])) {
        const auto& loop = locator.loop(hit[v].loop);
        m_slide_of[v] = m_slides.size();
        m_slides.push_back({ loop[hit[v].edge], loop[(hit[v].edge + 1) % loop.size()] });
      }
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(m_slide_of[v] != none) add_left_out(locator, v, prev[v], next[v], hit, on_loop);
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
  bool keeps_chords(std::size_t v, const Point_2d& from, const Point_2d& p, const Point_2d& prev,
                    const Point_2d& next) const
  {
    const Boundary_slide& s = m_slides[m_slide_of[v]];
    for(std::size_t k = s.before; k < s.after; ++k)
      if(further(m_left_out[k], prev, p, prev, from)) return false;
    for(std::size_t k = s.after; k < s.end; ++k)
      if(further(m_left_out[k], p, next, from, next)) return false;
    return true;
  }

private:
  static constexpr std::size_t none = std::size_t(-1);

  // whether g is beyond the tolerance of edge (a, b), and further than from edge (c, d)
  bool further(const Point_2d& g, const Point_2d& a, const Point_2d& b, const Point_2d& c, const Point_2d& d) const
  {
    return point_segment_distance(g, a, b) > (std::max)(m_tolerance, point_segment_distance(g, c, d));
  }

  // an edge leaving out more loop vertices than this follows the loop too loosely to judge
  static constexpr std::size_t max_left_out = 64;

  // whether p lies on an input segment (to rounding, 1e-10 of the diagonal); fills `h`
  static bool on_the_loops(const Loop_locator& locator, const Point_2d& p, Loop_locator::Hit& h)
  {
    const double near = 1e-10 * locator.diagonal();
    h = locator.closest(p, near);
    const auto& loop = locator.loop(h.loop);
    const Point_2d& a = loop[h.edge];
    const Point_2d& b = loop[(h.edge + 1) % loop.size()];
    return h.dist <= (std::max)(near, 16 * coordinate_rounding_2d(a, b));
  }

  static bool at_a_loop_vertex(const Loop_locator& locator, const Point_2d& p, const Loop_locator::Hit& h)
  {
    const auto& loop = locator.loop(h.loop);
    return p == loop[h.edge] || p == loop[(h.edge + 1) % loop.size()];
  }

  // v's lists: the loop vertices between its boundary neighbours u and w and itself, along
  // their loop the shorter way round. Where a neighbour is off the loops, on another loop, or
  // far from v along theirs, v does not slide.
  void add_left_out(const Loop_locator& locator, std::size_t v, std::size_t u, std::size_t w,
                    const std::vector<Loop_locator::Hit>& hit, const std::vector<char>& on_loop)
  {
    auto beside = [&](std::size_t n) { return n != none && on_loop[n] != 0 && hit[n].loop == hit[v].loop; };
    Boundary_slide& s = m_slides[m_slide_of[v]];
    s.before = m_left_out.size();
    bool follows = beside(u) && loop_vertices_between(locator, hit[u], hit[v], m_left_out);
    s.after = m_left_out.size();
    follows = follows && beside(w) && loop_vertices_between(locator, hit[v], hit[w], m_left_out);
    s.end = m_left_out.size();
    if(follows) return;
    m_left_out.resize(s.before);
    m_slide_of[v] = none;
  }

  // appends the loop vertices strictly between two points of one loop, the shorter way round,
  // to `between`; false if that is over a quarter of the loop or leaves out too many
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
    const std::size_t start = between.size();
    std::size_t k = (first.edge + 1) % loop.size();
    for(std::size_t step = 0; step < loop.size(); ++step, k = (k + 1) % loop.size()) {
      const double s = std::fmod(locator.arc(l, k) - s0 + L, L);
      if(s == 0) continue; // the vertex `first` lies on
      if(!(s < span)) break;
      if(between.size() - start == max_left_out) return false;
      between.push_back(loop[k]);
    }
    return true;
  }

  std::vector<std::size_t> m_slide_of;
  std::vector<Boundary_slide> m_slides;
  std::vector<Point_2d> m_left_out; // the loop vertices of each slide's lists, slide after slide
  double m_tolerance;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_SLIDES_H
