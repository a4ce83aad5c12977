// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_CLEARANCE_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_CLEARANCE_H

// Buffer zone clearance (paper §4.3): from the quadtree mesh of the domain's bounding grid,
// keep the "core" quads that lie inside the domain and far enough from its boundary for the
// later stages (templates §4.4, buffer layers §4.5) to fill the gap with good quads.
//
// Rules implemented, in this order (each quad is counted once, by the first rule that removes
// it):
//  1. (Criterion 2) every quad whose CLOSED outline meets a boundary segment (crossing or only
//     touching) -> `removed_intersecting`. Done first because it splits the rest cleanly.
//  2. (Criterion 1) every other quad outside the domain -> `removed_outside`. A quad that meets
//     no segment is wholly inside or wholly outside, and so is every quad joined to it by an
//     edge through such quads: one point-location per connected component suffices. (A quad
//     that crosses the boundary is thus counted as intersecting, never as outside.)
//  3. (Criterion 3) for every vertex v of the remaining quads: if dist(v, boundary) <= eps_s(v)
//     = 0.5 * max(quad_size[q]) over ALL input quads q sharing v, every quad sharing v is
//     removed -> `removed_near`. All vertices are judged on the mesh left by rules 1-2, at
//     once (no cascade): a vertex that survives had its own test passed. Taking the max over
//     all input quads (not only the remaining ones) gives the larger, safer eps_s, and makes
//     eps_s a property of the quadtree's local size, independent of what was removed.
//  4. (Single elements and manifold clean-up) to a fixed point:
//     - a kept quad sharing at most one edge with other kept quads is removed (paper
//       Fig. 4(c)); its other edges are then boundary edges, which already touch all four of
//       its vertices, so the paper's "four boundary points" condition holds automatically.
//       This also removes isolated quads (no shared edge), and peels dangling one-quad-wide
//       strips from their ends (each end is again a single element);
//     - at a vertex where the kept quads form two or more fans (they touch there only at the
//       vertex; the core boundary would pass twice through it), the quads of every fan but
//       the largest (most quads; tie: the fan holding the lowest quad index) are removed.
//     Both count in `removed_single`. After this every vertex of the core mesh has 0 or 2
//     boundary edges, so the core boundary is a set of simple closed loops, which the buffer
//     layers need.
//
// Left out: the exception of paper Fig. 4(b) (keep two boundary points closer than eps_s to
// the boundary when the edge between them is "almost parallel" to it). The paper gives no
// threshold for "almost parallel" nor a bound on how close such points may be, and keeping
// them breaks the invariant every later stage relies on and that the template analysis of
// Tab. 1 assumes (the circles of radius half the largest surrounding element around each
// kept point stay clear of the boundary). Without a precise rule we cannot test, the
// invariant wins.
//
// Exactness: every decision (segment meets quad, inside/outside, distance <= eps_s) is an
// exact predicate of the traits (`orientation_2`, `compare_x_2`,
// `compare_squared_distance_2`); doubles are used only as conservative box filters (box
// hierarchy over the segments, from `construct_bbox_2`, which over-approximates under lazy
// exact kernels). eps_s^2 is formed in `FT`: exact with exact constructions, and exact under
// Epick too for quadtree cell sizes, which are powers of two.
//
// Cost: O((Q + V) log S + K) for Q quads, V vertices, S segments and K candidate pairs:
// quad/segment and vertex/segment candidates come from a bounding-box hierarchy over the
// segments (`Loops_box_tree`), and mesh adjacency from one sort of the quad edges.

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/assertions.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The core mesh left by `clear_buffer_zone()` and what was removed.
template <class K>
struct Clearance_result
{
  /// The kept quads, in input order, with their vertices renumbered compactly (kept vertices
  /// keep their relative input order).
  Quad_mesh_2<typename K::Point_2> core;
  /// `core_to_input_quad[i]`: the index in the input mesh of core quad `i`.
  std::vector<std::size_t> core_to_input_quad;
  /// Quads removed by criterion 1 (outside the domain, meeting no segment), criterion 2
  /// (meeting a segment), criterion 3 (sharing a vertex within eps_s of the boundary) and the
  /// single-element / manifold clean-up. They add up, with the kept quads, to the input count.
  std::size_t removed_outside = 0, removed_intersecting = 0, removed_near = 0, removed_single = 0;
};

template <class K>
class Buffer_zone_clearance
{
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Segment_2 Segment_2;
  typedef Quad_mesh_2<Point_2> Mesh;
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

  enum State : unsigned char { KEPT, OUTSIDE, INTERSECTING, NEAR, SINGLE };

public:
  Buffer_zone_clearance(const Mesh& mesh, const std::vector<double>& quad_size, const Domain_2<K>& domain,
                        const Domain_loops_2<K>& loops, const K& traits)
    : m_mesh(mesh), m_size(quad_size), m_domain(domain), m_loops(loops), m_traits(traits)
  {
    CGAL_precondition(quad_size.size() == mesh.quads.size());
  }

  Clearance_result<K> run()
  {
    const std::size_t nq = m_mesh.quads.size();
    m_state.assign(nq, KEPT);
    build_segments();
    build_adjacency();
    remove_intersecting();
    remove_outside();
    remove_near();
    remove_singles();
    return output();
  }

private:
  // ---- boundary segments and their box hierarchy -------------------------------------------
  void build_segments()
  {
    const auto bbox = m_traits.construct_bbox_2_object();
    const auto seg = m_traits.construct_segment_2_object();
    for(std::size_t l = 0; l < m_loops.loops.size(); ++l) {
      const auto& v = m_loops.loops[l].vertices;
      for(std::size_t i = 0; i < v.size(); ++i) {
        const Point_2& a = m_domain.points[v[i]];
        const Point_2& b = m_domain.points[v[(i + 1) % v.size()]];
        m_seg_ends.push_back({v[i], v[(i + 1) % v.size()]});
        m_segments.push_back(seg(a, b));
        m_seg_loop.push_back(l);
        m_seg_boxes.push_back(bbox(a) + bbox(b));
      }
    }
    m_tree.reset(new Loops_box_tree(m_seg_boxes));
  }

  const Point_2& seg_point(std::size_t s, int e) const { return m_domain.points[m_seg_ends[s][e]]; }

  // ---- mesh adjacency ----------------------------------------------------------------------
  // m_nb[4q+e]: the quad across edge e (from corner e to corner e+1) of quad q, or `none`.
  // m_vq / m_vq_begin: the quads around each vertex (CSR).
  void build_adjacency()
  {
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    std::vector<std::pair<std::uint64_t, std::size_t>> edges;  // (min<<32|max, 4q+e)
    edges.reserve(4 * nq);
    bool small = nv < (std::size_t(1) << 32);
    CGAL_precondition(small);
    CGAL_USE(small);
    for(std::size_t q = 0; q < nq; ++q)
      for(int e = 0; e < 4; ++e) {
        std::uint64_t a = m_mesh.quads[q][e], b = m_mesh.quads[q][(e + 1) % 4];
        if(a > b) std::swap(a, b);
        edges.emplace_back((a << 32) | b, 4 * q + e);
      }
    std::sort(edges.begin(), edges.end());
    m_nb.assign(4 * nq, none);
    for(std::size_t i = 0; i + 1 < edges.size(); ++i)
      if(edges[i].first == edges[i + 1].first) {
        // A conforming mesh has at most two quads per edge.
        CGAL_precondition(i + 2 >= edges.size() || edges[i + 2].first != edges[i].first);
        m_nb[edges[i].second] = edges[i + 1].second / 4;
        m_nb[edges[i + 1].second] = edges[i].second / 4;
      }
    m_vq_begin.assign(nv + 1, 0);
    for(const auto& quad : m_mesh.quads)
      for(int c = 0; c < 4; ++c) ++m_vq_begin[quad[c] + 1];
    for(std::size_t v = 0; v < nv; ++v) m_vq_begin[v + 1] += m_vq_begin[v];
    m_vq.resize(4 * nq);
    std::vector<std::size_t> fill(m_vq_begin.begin(), m_vq_begin.end() - 1);
    for(std::size_t q = 0; q < nq; ++q)
      for(int c = 0; c < 4; ++c) m_vq[fill[m_mesh.quads[q][c]]++] = q;
  }

  int corner_of(std::size_t q, std::size_t v) const
  {
    for(int c = 0; c < 4; ++c)
      if(m_mesh.quads[q][c] == v) return c;
    CGAL_unreachable();
    return -1;
  }

  Bbox_2 quad_box(std::size_t q) const
  {
    const auto bbox = m_traits.construct_bbox_2_object();
    const auto& quad = m_mesh.quads[q];
    return bbox(m_mesh.points[quad[0]]) + bbox(m_mesh.points[quad[1]]) + bbox(m_mesh.points[quad[2]]) +
           bbox(m_mesh.points[quad[3]]);
  }

  // ---- criterion 2 -------------------------------------------------------------------------
  // Separating axes, with orientation predicates only: a closed convex CCW quad and a closed
  // segment [a,b] are disjoint iff both ends lie strictly right of one quad edge's line, or all
  // four corners lie strictly on one side of the line ab (the edge normals of both shapes are
  // the only candidate axes in 2D). Touching counts as meeting.
  bool quad_meets_segment(std::size_t q, std::size_t s) const
  {
    const auto orient = m_traits.orientation_2_object();
    const auto& quad = m_mesh.quads[q];
    const Point_2& a = seg_point(s, 0);
    const Point_2& b = seg_point(s, 1);
    for(int e = 0; e < 4; ++e) {
      const Point_2& p = m_mesh.points[quad[e]];
      const Point_2& r = m_mesh.points[quad[(e + 1) % 4]];
      if(orient(p, r, a) == RIGHT_TURN && orient(p, r, b) == RIGHT_TURN) return false;
    }
    int left = 0, right = 0;
    for(int c = 0; c < 4; ++c) {
      const Orientation o = orient(a, b, m_mesh.points[quad[c]]);
      if(o == LEFT_TURN) ++left;
      else if(o == RIGHT_TURN) ++right;
    }
    return !(left == 4 || right == 4);
  }

  void remove_intersecting()
  {
    for(std::size_t q = 0; q < m_mesh.quads.size(); ++q) {
      bool meets = false;
      m_tree->query(quad_box(q), [&](std::size_t s) {
        if(!meets && quad_meets_segment(q, s)) meets = true;
      });
      if(meets) m_state[q] = INTERSECTING;
    }
  }

  // ---- criterion 1 -------------------------------------------------------------------------
  // `true` if `p`, which lies on no segment, is inside the domain: the innermost loop whose
  // inside holds `p` (upward ray, half-open crossing rule) must be an outer loop.
  bool in_domain(const Point_2& p) const
  {
    const auto cmp_x = m_traits.compare_x_2_object();
    const auto orient = m_traits.orientation_2_object();
    const Bbox_2 pb = m_traits.construct_bbox_2_object()(p);
    const Bbox_2 ray(pb.xmin(), pb.ymin(), pb.xmax(), std::numeric_limits<double>::infinity());
    std::vector<unsigned char> parity(m_loops.loops.size(), 0);
    m_tree->query(ray, [&](std::size_t s) {
      const Point_2& a = seg_point(s, 0);
      const Point_2& b = seg_point(s, 1);
      const Comparison_result ca = cmp_x(a, p), cb = cmp_x(b, p);
      const bool spans = (ca != LARGER && cb == LARGER) || (cb != LARGER && ca == LARGER);
      if(!spans) return;
      const Point_2& left = (ca == LARGER) ? b : a;
      const Point_2& right = (ca == LARGER) ? a : b;
      const Orientation o = orient(left, right, p);
      CGAL_assertion(o != COLLINEAR);  // p is on no segment
      if(o == RIGHT_TURN) parity[m_seg_loop[s]] ^= 1;  // p below the segment
    });
    int depth = -1;
    bool inside = false;
    for(std::size_t l = 0; l < parity.size(); ++l)
      if(parity[l] && m_loops.loops[l].depth > depth) {
        depth = m_loops.loops[l].depth;
        inside = m_loops.loops[l].is_outer;
      }
    return inside;
  }

  void remove_outside()
  {
    // Flood fill over edges between quads that meet no segment; one location per component.
    const std::size_t nq = m_mesh.quads.size();
    std::vector<bool> seen(nq, false);
    std::vector<std::size_t> stack, component;
    for(std::size_t q0 = 0; q0 < nq; ++q0) {
      if(seen[q0] || m_state[q0] != KEPT) continue;
      component.clear();
      stack.push_back(q0);
      seen[q0] = true;
      while(!stack.empty()) {
        const std::size_t q = stack.back();
        stack.pop_back();
        component.push_back(q);
        for(int e = 0; e < 4; ++e) {
          const std::size_t n = m_nb[4 * q + e];
          if(n != none && !seen[n] && m_state[n] == KEPT) {
            seen[n] = true;
            stack.push_back(n);
          }
        }
      }
      if(!in_domain(m_mesh.points[m_mesh.quads[q0][0]]))
        for(std::size_t q : component) m_state[q] = OUTSIDE;
    }
  }

  // ---- criterion 3 -------------------------------------------------------------------------
  void remove_near()
  {
    const std::size_t nv = m_mesh.points.size();
    const auto bbox = m_traits.construct_bbox_2_object();
    const auto cmp_dist = m_traits.compare_squared_distance_2_object();
    std::vector<bool> near(nv, false);
    for(std::size_t v = 0; v < nv; ++v) {
      bool used = false;
      double smax = 0;
      for(std::size_t k = m_vq_begin[v]; k < m_vq_begin[v + 1]; ++k) {
        used = used || m_state[m_vq[k]] == KEPT;
        smax = (std::max)(smax, m_size[m_vq[k]]);
      }
      if(!used) continue;
      const double eps = 0.5 * smax;
      const FT eps_ft(eps);
      const FT eps2 = eps_ft * eps_ft;
      const Point_2& p = m_mesh.points[v];
      const Bbox_2 pb = bbox(p);
      const double pad = eps * (1 + 1e-9);  // the filter only needs to be conservative
      const Bbox_2 query(pb.xmin() - pad, pb.ymin() - pad, pb.xmax() + pad, pb.ymax() + pad);
      bool is_near = false;
      m_tree->query(query, [&](std::size_t s) {
        if(!is_near && cmp_dist(p, m_segments[s], eps2) != LARGER) is_near = true;
      });
      near[v] = is_near;
    }
    for(std::size_t v = 0; v < nv; ++v)
      if(near[v])
        for(std::size_t k = m_vq_begin[v]; k < m_vq_begin[v + 1]; ++k)
          if(m_state[m_vq[k]] == KEPT) m_state[m_vq[k]] = NEAR;
  }

  // ---- single elements and non-manifold vertices -------------------------------------------
  bool kept(std::size_t q) const { return q != none && m_state[q] == KEPT; }

  int kept_neighbours(std::size_t q) const
  {
    int n = 0;
    for(int e = 0; e < 4; ++e) n += kept(m_nb[4 * q + e]) ? 1 : 0;
    return n;
  }

  // The fans of kept quads around v, each as a list of quads. A fan is a maximal run of kept
  // quads joined by kept-kept edges at v.
  void fans_at(std::size_t v, std::vector<std::vector<std::size_t>>& fans) const
  {
    fans.clear();
    std::vector<std::size_t> local;
    for(std::size_t k = m_vq_begin[v]; k < m_vq_begin[v + 1]; ++k)
      if(kept(m_vq[k])) local.push_back(m_vq[k]);
    std::vector<bool> done(local.size(), false);
    for(std::size_t i = 0; i < local.size(); ++i) {
      if(done[i]) continue;
      fans.emplace_back();
      std::vector<std::size_t> stack(1, i);
      done[i] = true;
      while(!stack.empty()) {
        const std::size_t j = stack.back();
        stack.pop_back();
        const std::size_t q = local[j];
        fans.back().push_back(q);
        const int c = corner_of(q, v);
        const std::size_t across[2] = {m_nb[4 * q + c], m_nb[4 * q + (c + 3) % 4]};  // the edges at v
        for(std::size_t n : across)
          for(std::size_t t = 0; t < local.size(); ++t)
            if(!done[t] && local[t] == n && kept(n)) {
              done[t] = true;
              stack.push_back(t);
            }
      }
    }
  }

  void remove_singles()
  {
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    std::vector<std::size_t> quad_work, vertex_work;
    std::vector<bool> in_qwork(nq, false), in_vwork(nv, false);
    for(std::size_t q = 0; q < nq; ++q)
      if(kept(q)) {
        quad_work.push_back(q);
        in_qwork[q] = true;
        for(int c = 0; c < 4; ++c)
          if(!in_vwork[m_mesh.quads[q][c]]) {
            in_vwork[m_mesh.quads[q][c]] = true;
            vertex_work.push_back(m_mesh.quads[q][c]);
          }
      }
    std::reverse(quad_work.begin(), quad_work.end());  // popped from the back: input order
    std::reverse(vertex_work.begin(), vertex_work.end());
    auto remove = [&](std::size_t q) {
      m_state[q] = SINGLE;
      for(int e = 0; e < 4; ++e) {
        const std::size_t n = m_nb[4 * q + e];
        if(kept(n) && !in_qwork[n]) {
          in_qwork[n] = true;
          quad_work.push_back(n);
        }
      }
      for(int c = 0; c < 4; ++c) {
        const std::size_t v = m_mesh.quads[q][c];
        if(!in_vwork[v]) {
          in_vwork[v] = true;
          vertex_work.push_back(v);
        }
      }
    };
    std::vector<std::vector<std::size_t>> fans;
    // Quads first (cheap, and removing singles often resolves a pinch by itself), then one
    // vertex at a time, back to quads whenever a vertex fix removed something.
    while(!quad_work.empty() || !vertex_work.empty()) {
      if(!quad_work.empty()) {
        const std::size_t q = quad_work.back();
        quad_work.pop_back();
        in_qwork[q] = false;
        if(kept(q) && kept_neighbours(q) <= 1) remove(q);
        continue;
      }
      const std::size_t v = vertex_work.back();
      vertex_work.pop_back();
      in_vwork[v] = false;
      fans_at(v, fans);
      if(fans.size() <= 1) continue;
      std::size_t best = 0;
      auto min_index = [](const std::vector<std::size_t>& f) { return *std::min_element(f.begin(), f.end()); };
      for(std::size_t f = 1; f < fans.size(); ++f)
        if(fans[f].size() > fans[best].size() ||
           (fans[f].size() == fans[best].size() && min_index(fans[f]) < min_index(fans[best])))
          best = f;
      for(std::size_t f = 0; f < fans.size(); ++f)
        if(f != best)
          for(std::size_t q : fans[f]) remove(q);
    }
  }

  // ---- output ------------------------------------------------------------------------------
  Clearance_result<K> output() const
  {
    Clearance_result<K> r;
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    std::vector<std::size_t> new_index(nv, none);
    for(std::size_t q = 0; q < nq; ++q) {
      switch(m_state[q]) {
      case OUTSIDE: ++r.removed_outside; break;
      case INTERSECTING: ++r.removed_intersecting; break;
      case NEAR: ++r.removed_near; break;
      case SINGLE: ++r.removed_single; break;
      case KEPT:
        for(int c = 0; c < 4; ++c) new_index[m_mesh.quads[q][c]] = 0;
        break;
      }
    }
    for(std::size_t v = 0; v < nv; ++v)
      if(new_index[v] != none) {
        new_index[v] = r.core.points.size();
        r.core.points.push_back(m_mesh.points[v]);
      }
    for(std::size_t q = 0; q < nq; ++q)
      if(m_state[q] == KEPT) {
        typename Mesh::Quad quad;
        for(int c = 0; c < 4; ++c) quad[c] = new_index[m_mesh.quads[q][c]];
        r.core.quads.push_back(quad);
        r.core_to_input_quad.push_back(q);
      }
    return r;
  }

  const Mesh& m_mesh;
  const std::vector<double>& m_size;
  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  const K& m_traits;
  std::vector<State> m_state;
  std::vector<std::array<std::size_t, 2>> m_seg_ends;
  std::vector<Segment_2> m_segments;
  std::vector<std::size_t> m_seg_loop;
  std::vector<Bbox_2> m_seg_boxes;
  std::unique_ptr<Loops_box_tree> m_tree;
  std::vector<std::size_t> m_nb;
  std::vector<std::size_t> m_vq_begin, m_vq;
};

/// Buffer zone clearance (paper §4.3), see the rules at the top of this file.
///
/// \param mesh a conforming all-quad mesh, convex CCW quads, covering the domain's bounding
///   grid (e.g. `templated_mesh(tree, &quad_cells)`)
/// \param quad_size `quad_size[q]`: the size s_q of quad q, the side of the quadtree cell it
///   came from (`tree.cell_side(quad_cells[q].level)`)
/// \param domain, loops the domain and its validated loops (`extract_loops(domain)`)
template <class K>
Clearance_result<K> clear_buffer_zone(const Quad_mesh_2<typename K::Point_2>& mesh,
                                      const std::vector<double>& quad_size, const Domain_2<K>& domain,
                                      const Domain_loops_2<K>& loops, const K& traits = K())
{
  Buffer_zone_clearance<K> c(mesh, quad_size, domain, loops, traits);
  return c.run();
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_CLEARANCE_H
