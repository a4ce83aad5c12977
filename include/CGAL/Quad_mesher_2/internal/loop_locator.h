// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Closest points on a domain's boundary loops, and points at an arclength along them, in
// doubles: the buffer stages search with it; the points they add on the boundary are then
// constructed in the kernel from a segment's end points.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_LOOP_LOCATOR_H
#define CGAL_QUAD_MESHER_2_INTERNAL_LOOP_LOCATOR_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/internal/Box_tree.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Closest points on the domain's loops, in doubles (search only; new points on the boundary
/// are then constructed from a segment's end points in the kernel).
class Loop_locator
{
public:
  struct Hit
  {
    std::size_t loop = 0, edge = 0; // edge k joins loop vertex k to k+1
    double t = 0, dist = std::numeric_limits<double>::infinity();
    Point_2d point = ORIGIN;
  };

  typedef std::array<std::size_t, 2> Edge; // loop, edge

  /// `twins[l][k]`: the loop edge along edge k of loop l the other way (the domain on both
  /// sides: see Boundary_loop_2::edge_twins), or {none, none}; empty if no edge has one
  Loop_locator(std::vector<std::vector<Point_2d>> loops, std::vector<std::vector<Edge>> twins = {})
    : m_loops(std::move(loops)), m_twin(std::move(twins))
  {
    m_twin.resize(m_loops.size());
    m_neighbors.resize(m_loops.size());
    for(std::size_t l = 0; l < m_loops.size(); ++l) {
      m_twin[l].resize(m_loops[l].size(), Edge{ { none, none } });
      for(const Edge& e : m_twin[l])
        if(e[0] != none) m_neighbors[l].push_back(e[0]);
      std::sort(m_neighbors[l].begin(), m_neighbors[l].end());
      m_neighbors[l].erase(std::unique(m_neighbors[l].begin(), m_neighbors[l].end()), m_neighbors[l].end());
    }
    std::vector<Bbox_2>& boxes = m_boxes; // the box tree keeps a reference
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    m_arc.resize(m_loops.size());
    for(std::size_t l = 0; l < m_loops.size(); ++l) {
      const auto& v = m_loops[l];
      m_arc[l].assign(v.size() + 1, 0.0);
      for(std::size_t k = 0; k < v.size(); ++k) {
        const Point_2d& a = v[k];
        const Point_2d& b = v[(k + 1) % v.size()];
        boxes.emplace_back((std::min)(a.x(), b.x()), (std::min)(a.y(), b.y()), (std::max)(a.x(), b.x()),
                           (std::max)(a.y(), b.y()));
        m_edge_of.push_back({l, k});
        m_arc[l][k + 1] = m_arc[l][k] + length_2d(b - a);
        xmin = (std::min)(xmin, a.x()); xmax = (std::max)(xmax, a.x());
        ymin = (std::min)(ymin, a.y()); ymax = (std::max)(ymax, a.y());
      }
    }
    m_diag = std::hypot(xmax - xmin, ymax - ymin);
    m_tree = std::make_unique<Box_tree>(boxes);
  }

  const std::vector<Point_2d>& loop(std::size_t l) const { return m_loops[l]; }
  std::size_t number_of_loops() const { return m_loops.size(); }
  /// arclength from loop vertex 0 to vertex k (k = size: the loop's length)
  double arc(std::size_t l, std::size_t k) const { return m_arc[l][k]; }
  double length(std::size_t l) const { return m_arc[l].back(); }
  double diagonal() const { return m_diag; }
  double param(const Hit& h) const
  {
    return m_arc[h.loop][h.edge] + h.t * (m_arc[h.loop][h.edge + 1] - m_arc[h.loop][h.edge]);
  }

  /// the loop edge along edge k of loop l the other way, or {none, none}
  const Edge& edge_twin(std::size_t l, std::size_t k) const { return m_twin[l][k]; }

  /// the closest point to `p` on loop `l` (any loop if `l` is none), searching first within
  /// `radius` of `p` (with `other_than`: on any loop but `l` and those sharing an edge with
  /// it). Of an edge and its twin (the same segment the other way), the one that has `p` on
  /// its left; of other equally near edges, the one of the lower loop index.
  Hit closest(const Point_2d& p, double radius, std::size_t l = none, bool other_than = false) const
  {
    Hit best;
    double r = (std::max)(radius, 1e-300);
    for(;;) {
      m_tree->query(Bbox_2(p.x() - r, p.y() - r, p.x() + r, p.y() + r), [&](std::size_t s) {
        const std::size_t on = m_edge_of[s][0];
        if(l != none && (other_than ? on == l || std::binary_search(m_neighbors[l].begin(), m_neighbors[l].end(), on) : on != l))
          return;
        Hit h = on_edge(p, m_edge_of[s][0], m_edge_of[s][1]);
        // equally near edges (a point on a symmetry axis) by their index, not by rounding:
        // the same choice on a scaled or moved domain
        const double tie = 1e-9 * m_diag;
        if(h.dist < best.dist - tie || (h.dist <= best.dist + tie && tie_order(p, h) < tie_order(p, best)))
          best = h;
      });
      if(best.dist <= r || r > 4 * m_diag + 1e-300) return best;
      r *= 4;
    }
  }

  /// calls `f(l, k)` for every edge k of loop l (vertex k to k + 1) whose box meets `box`
  template <class F>
  void edges_meeting(const Bbox_2& box, F&& f) const
  {
    m_tree->query(box, [&](std::size_t s) { f(m_edge_of[s][0], m_edge_of[s][1]); });
  }

  /// the point of loop `l` at arclength `s` from its vertex 0 (modulo the loop's length)
  Hit point_at_arclength(std::size_t l, double s) const
  {
    const double L = length(l);
    s = std::fmod(s, L);
    if(s < 0) s += L;
    const auto& v = loop(l);
    std::size_t lo = 0, hi = v.size();
    while(hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if(arc(l, mid) <= s) lo = mid; else hi = mid;
    }
    const double len = arc(l, lo + 1) - arc(l, lo);
    Hit h;
    h.loop = l;
    h.edge = lo;
    h.t = len > 0 ? (std::min)(1.0, (std::max)(0.0, (s - arc(l, lo)) / len)) : 0.0;
    const Point_2d& a = v[lo];
    const Point_2d& b = v[(lo + 1) % v.size()];
    h.point = along_2d(a, b, h.t);
    h.dist = 0;
    return h;
  }

  static constexpr std::size_t none = std::size_t(-1);

private:
  // equally near edges: of twins the side facing p first, then by loop and index
  std::array<std::size_t, 3> tie_order(const Point_2d& p, const Hit& h) const
  {
    if(h.dist == std::numeric_limits<double>::infinity()) return { none, none, none };
    bool facing = true;
    if(m_twin[h.loop][h.edge][0] != none) {
      const auto& v = m_loops[h.loop];
      facing = CGAL::determinant(v[(h.edge + 1) % v.size()] - v[h.edge], p - v[h.edge]) > 0;
    }
    return { facing ? 0u : 1u, h.loop, h.edge };
  }

  Hit on_edge(const Point_2d& p, std::size_t l, std::size_t k) const
  {
    const auto& v = m_loops[l];
    const Point_2d& a = v[k];
    const Point_2d& b = v[(k + 1) % v.size()];
    Hit h;
    h.loop = l;
    h.edge = k;
    h.t = nearest_segment_parameter(p, a, b);
    h.point = along_2d(a, b, h.t);
    h.dist = length_2d(p - h.point);
    return h;
  }

  std::vector<std::vector<Point_2d>> m_loops;
  std::vector<std::vector<Edge>> m_twin;
  std::vector<std::vector<std::size_t>> m_neighbors; // per loop, the loops sharing an edge with it
  std::vector<std::array<std::size_t, 2>> m_edge_of;
  std::vector<std::vector<double>> m_arc;
  std::vector<Bbox_2> m_boxes;
  std::unique_ptr<Box_tree> m_tree;
  double m_diag = 0;
};

/// the locator of a domain's boundary loops (the box tree refers to the locator's own boxes:
/// it stays where it is made)
template <class K>
std::unique_ptr<Loop_locator> make_loop_locator(const Domain_2<K>& domain, const Domain_loops_2<K>& loops)
{
  std::vector<std::vector<Point_2d>> pts(loops.loops.size());
  std::vector<std::vector<Loop_locator::Edge>> twins(loops.loops.size());
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    for(std::size_t v : loops.loops[l].vertices)
      pts[l].push_back(to_point_2d(domain.points[v]));
    twins[l] = loops.loops[l].edge_twins;
  }
  return std::make_unique<Loop_locator>(std::move(pts), std::move(twins));
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_LOOP_LOCATOR_H
