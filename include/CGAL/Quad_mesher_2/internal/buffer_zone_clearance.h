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
//     no segment is wholly inside or wholly outside, and so is every quad joined to it by a
//     vertex through such quads: few point-locations suffice. (A quad that crosses the
//     boundary is thus counted as intersecting, never as outside.)
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
// Cost: O(Q + V + (Q + V) / 64 * log S + K) for Q quads, V vertices, S segments and K
// candidate pairs, in a few linear passes, no sort. Quad/segment and vertex/segment
// candidates come from a bounding-box hierarchy over the segments (`Box_tree`), one
// query per block of 64 consecutive quads or vertices: `templated_mesh` numbers both in
// Morton order, so a block is compact and most blocks, far from the boundary, get no
// candidate and no exact predicate. Inside/outside is passed from quad to quad through
// shared vertices; point location only for a quad without an earlier one at its vertices.
// Mesh adjacency is built only for the quads left by criteria 1-3.

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>

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
  /// `core_vertex[v]`: the index in the core of input vertex `v`, `std::size_t(-1)` if removed.
  std::vector<std::size_t, Huge_page_allocator<std::size_t>> core_vertex;
  /// Quads removed by criterion 1 (outside the domain, meeting no segment), criterion 2
  /// (meeting a segment), criterion 3 (sharing a vertex within eps_s of the boundary) and the
  /// single-element / manifold clean-up. They add up, with the kept quads, to the input count.
  std::size_t removed_outside = 0, removed_intersecting = 0, removed_near = 0, removed_single = 0;
};

// The domain's boundary segments, loop by loop, in a box hierarchy: the segments a box
// meets, and the side of the boundary a point on no segment lies on (exact predicates).
template <class K>
class Domain_segments
{
  typedef typename K::Point_2 Point_2;
  typedef typename K::Segment_2 Segment_2;

public:
  Domain_segments(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, const K& traits)
    : m_domain(domain), m_loops(loops), m_traits(traits)
  {
    const auto bbox = m_traits.construct_bbox_2_object();
    const auto seg = m_traits.construct_segment_2_object();
    for(std::size_t l = 0; l < m_loops.loops.size(); ++l) {
      const auto& v = m_loops.loops[l].vertices;
      for(std::size_t i = 0; i < v.size(); ++i) {
        if(is_second_side(m_loops, l, i)) continue; // a segment once, as the first loop along it has it
        const std::size_t twin = m_loops.loops[l].edge_twins[i][0];
        m_twin_loop.push_back(twin == l ? outside : twin);
        const Point_2& a = m_domain.points[v[i]];
        const Point_2& b = m_domain.points[v[(i + 1) % v.size()]];
        m_ends.push_back({v[i], v[(i + 1) % v.size()]});
        m_segments.push_back(seg(a, b));
        m_loop.push_back(l);
        m_boxes.push_back(bbox(a) + bbox(b));
      }
    }
    m_tree.reset(new Box_tree(m_boxes));
  }
  Domain_segments(const Domain_segments&) = delete;
  Domain_segments& operator=(const Domain_segments&) = delete;

  const Point_2& point(std::size_t s, int e) const { return m_domain.points[m_ends[s][e]]; }
  const Segment_2& segment(std::size_t s) const { return m_segments[s]; }
  const Bbox_2& box(std::size_t s) const { return m_boxes[s]; }
  /// the loop (index into `Domain_loops_2::loops`) segment `s` belongs to
  std::size_t loop_of(std::size_t s) const { return m_loop[s]; }
  /// the other loop along segment `s` (the other side of an interface), or `outside`
  std::size_t twin_loop_of(std::size_t s) const { return m_twin_loop[s]; }

  /// calls `f(s)` for every segment `s` whose box overlaps `b`
  template <class F>
  void query(const Bbox_2& b, F&& f) const { m_tree->query(b, std::forward<F>(f)); }

  /// `true` if `p`, which lies on no segment, is inside the domain: the innermost loop whose
  /// inside holds `p` (upward ray, half-open crossing rule) must be an outer loop.
  bool in_domain(const Point_2& p) const { return region_at(p) != outside; }

  static constexpr std::size_t outside = std::size_t(-1);
  /// The region (`Boundary_loop_2::region`) holding `p`, or `outside`; a point on a segment
  /// that is not vertical is in the region of the segment's loop.
  std::size_t region_at(const Point_2& p) const
  {
    const auto cmp_x = m_traits.compare_x_2_object();
    const auto orient = m_traits.orientation_2_object();
    const Bbox_2 pb = m_traits.construct_bbox_2_object()(p);
    const Bbox_2 ray(pb.xmin(), pb.ymin(), pb.xmax(), std::numeric_limits<double>::infinity());
    std::vector<unsigned char> parity(m_loops.loops.size(), 0);
    std::size_t on = outside;
    m_tree->query(ray, [&](std::size_t s) {
      const Point_2& a = point(s, 0);
      const Point_2& b = point(s, 1);
      const Comparison_result ca = cmp_x(a, p), cb = cmp_x(b, p);
      const bool spans = (ca != LARGER && cb == LARGER) || (cb != LARGER && ca == LARGER);
      if(!spans) return;
      const Point_2& left = (ca == LARGER) ? b : a;
      const Point_2& right = (ca == LARGER) ? a : b;
      const Orientation o = orient(left, right, p);
      if(o == COLLINEAR) on = s; // on a vertical segment p is found inside or outside
      if(o == RIGHT_TURN) { // p below the segment
        parity[m_loop[s]] ^= 1;
        if(m_twin_loop[s] != outside) parity[m_twin_loop[s]] ^= 1;
      }
    });
    if(on != outside)
      return m_loops.loops[m_loop[on]].region;
    // the deepest loop holding p; of an outer loop and a hole loop of one depth (twins along
    // an interface, or a junction's face and the outline of its faces), the outer one
    int depth = -1;
    bool outer = false;
    std::size_t region = outside;
    for(std::size_t l = 0; l < parity.size(); ++l) {
      const auto& loop = m_loops.loops[l];
      if(parity[l] && (loop.depth > depth || (loop.depth == depth && loop.is_outer && !outer))) {
        depth = loop.depth;
        outer = loop.is_outer;
        region = outer ? loop.region : outside;
      }
    }
    return region;
  }

private:
  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  const K& m_traits;
  std::vector<std::array<std::size_t, 2>> m_ends;
  std::vector<Segment_2> m_segments;
  std::vector<std::size_t> m_loop;
  std::vector<std::size_t> m_twin_loop;
  std::vector<Bbox_2> m_boxes;
  std::unique_ptr<Box_tree> m_tree; // keeps a reference to m_boxes
};

template <class K>
class Buffer_zone_clearance
{
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef typename K::Segment_2 Segment_2;
  typedef Quad_mesh_2<Point_2> Mesh;
  // Quad and vertex indices, and corners 4q+c: 32 bits halve the memory traffic of the
  // adjacency arrays.
  typedef std::uint32_t Index;
  static constexpr Index none = (std::numeric_limits<Index>::max)();
  static constexpr std::size_t removed_vertex = std::size_t(-1);
  // Consecutive quads (or vertices) that share one box-tree query (see "Cost" above).
  static constexpr std::size_t block = 64;
  // The arrays of an entry per input quad, corner or vertex (millions), written once: 2 MB
  // pages, as the quadtree's.
  template <class T>
  using Array = std::vector<T, Huge_page_allocator<T>>;

  enum State : unsigned char { KEPT, OUTSIDE, INTERSECTING, NEAR, SINGLE };

public:
  Buffer_zone_clearance(Mesh mesh, const std::vector<double>& quad_size, const Domain_2<K>& domain,
                        const Domain_loops_2<K>& loops, const K& traits)
    : m_mesh(std::move(mesh)), m_size(quad_size), m_domain(domain), m_loops(loops), m_traits(traits),
      m_boundary(domain, loops, traits)
  {
    CGAL_precondition(quad_size.size() == m_mesh.quads.size());
    CGAL_precondition(m_mesh.quads.size() < none / 4 && m_mesh.points.size() < none);
  }

  Clearance_result<K> run()
  {
    const std::size_t nq = m_mesh.quads.size();
    m_state.assign(nq, KEPT);
    remove_intersecting();
    remove_outside();
    remove_near();
    build_kept_adjacency();
    remove_singles();
    return output();
  }

private:
  // The segments whose box overlaps `box`, into m_candidates.
  void find_candidates(const Bbox_2& box)
  {
    m_candidates.clear();
    m_boundary.query(box, [&](std::size_t s) { m_candidates.push_back(s); });
  }

  // ---- adjacency of the quads kept by criteria 1-3 ----------------------------------------
  // Only these matter to the clean-up, and a neighbour removed by criteria 1-3 counts as none.
  // m_vq[m_vq_begin[v] .. m_vq_begin[v+1]): the corners 4q+c of the kept quads around v, in
  // quad order. m_nb[4q+e]: the kept quad across edge e (corner e to corner e+1) of kept quad
  // q, or `none`; quads are CCW, so it has the edge the other way round and is found at v.
  void build_kept_adjacency()
  {
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    m_vq_begin.assign(nv + 1, 0);
    m_quads_at.assign(nv, 0);
    for(std::size_t q = 0; q < nq; ++q) {
      for(int c = 0; c < 4; ++c) ++m_quads_at[m_mesh.quads[q][c]];
      if(m_state[q] == KEPT)
        for(int c = 0; c < 4; ++c) ++m_vq_begin[m_mesh.quads[q][c] + 1];
    }
    for(std::size_t v = 0; v < nv; ++v) m_vq_begin[v + 1] += m_vq_begin[v];
    m_vq.resize(m_vq_begin[nv]);
    // m_vq_begin[v] serves as v's fill cursor, then is shifted back.
    for(std::size_t q = 0; q < nq; ++q)
      if(m_state[q] == KEPT)
        for(int c = 0; c < 4; ++c) m_vq[m_vq_begin[m_mesh.quads[q][c]]++] = Index(4 * q + c);
    for(std::size_t v = nv; v > 0; --v) m_vq_begin[v] = m_vq_begin[v - 1];
    m_vq_begin[0] = 0;
    m_nb.assign(4 * nq, none);
    for(std::size_t k = 0; k < m_vq.size(); ++k) {
      const Index corner = m_vq[k];
      const std::size_t a = m_mesh.quads[corner / 4][corner % 4], b = m_mesh.quads[corner / 4][(corner + 1) % 4];
      for(std::size_t j = m_vq_begin[a]; j < m_vq_begin[a + 1]; ++j)
        if(m_vq[j] != corner && previous_vertex(m_vq[j]) == b) {
          // A conforming mesh has at most two quads per edge.
          CGAL_precondition(m_nb[corner] == none);
          m_nb[corner] = m_vq[j] / 4;
        }
    }
  }

  std::size_t previous_vertex(Index corner) const { return m_mesh.quads[corner / 4][(corner + 3) % 4]; }

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
    const Point_2& a = m_boundary.point(s, 0);
    const Point_2& b = m_boundary.point(s, 1);
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
    const std::size_t nq = m_mesh.quads.size();
    std::array<Bbox_2, block> boxes;
    for(std::size_t q0 = 0; q0 < nq; q0 += block) {
      const std::size_t n = (std::min)(block, nq - q0);
      Bbox_2 all;
      for(std::size_t i = 0; i < n; ++i) all += (boxes[i] = quad_box(q0 + i));
      find_candidates(all);
      if(m_candidates.empty()) continue;
      // The candidates of each quad are those the tree would give it alone.
      for(std::size_t i = 0; i < n; ++i)
        for(std::size_t s : m_candidates)
          if(CGAL::do_overlap(boxes[i], m_boundary.box(s)) && quad_meets_segment(q0 + i, s)) {
            m_state[q0 + i] = INTERSECTING;
            break;
          }
    }
  }

  // ---- criterion 1 -------------------------------------------------------------------------
  void remove_outside()
  {
    // Two quads that meet no segment and share a vertex are on the same side of the boundary
    // (the vertex is on no segment). So, in quad order, a quad takes the side of an earlier
    // one at one of its vertices (`owner`), and only a quad without one needs a location.
    const std::size_t nq = m_mesh.quads.size();
    Array<Index> owner(m_mesh.points.size(), none);
    for(std::size_t q = 0; q < nq; ++q) {
      if(m_state[q] != KEPT) continue;
      const auto& quad = m_mesh.quads[q];
      int c = 0;
      while(c < 4 && owner[quad[c]] == none) ++c;
      if(c < 4) m_state[q] = m_state[owner[quad[c]]];
      else if(!m_boundary.in_domain(m_mesh.points[quad[0]])) m_state[q] = OUTSIDE;
      for(c = 0; c < 4; ++c) owner[quad[c]] = Index(q);
    }
  }

  // ---- criterion 3 -------------------------------------------------------------------------
  void remove_near()
  {
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    const auto bbox = m_traits.construct_bbox_2_object();
    const auto cmp_dist = m_traits.compare_squared_distance_2_object();
    // eps_s(v) = 0.5 * max size of ALL quads at v; tested only if v is `used` by a kept quad
    Array<double> eps(nv, 0);
    Array<unsigned char> used(nv, 0);
    for(std::size_t q = 0; q < nq; ++q)
      for(int c = 0; c < 4; ++c) {
        const std::size_t v = m_mesh.quads[q][c];
        eps[v] = (std::max)(eps[v], 0.5 * m_size[q]);
        used[v] |= (m_state[q] == KEPT);
      }
    Array<unsigned char> near(nv, 0);
    std::array<Bbox_2, block> boxes;
    for(std::size_t v0 = 0; v0 < nv; v0 += block) {
      const std::size_t n = (std::min)(block, nv - v0);
      Bbox_2 all;
      for(std::size_t i = 0; i < n; ++i) {
        if(!used[v0 + i]) continue;
        const Bbox_2 pb = bbox(m_mesh.points[v0 + i]);
        const double pad = eps[v0 + i] * (1 + 1e-9);  // the filter only needs to be conservative
        boxes[i] = Bbox_2(pb.xmin() - pad, pb.ymin() - pad, pb.xmax() + pad, pb.ymax() + pad);
        all += boxes[i];
      }
      find_candidates(all);
      for(std::size_t i = 0; i < n && !m_candidates.empty(); ++i) {
        if(!used[v0 + i]) continue;
        const FT eps_ft(eps[v0 + i]);
        const FT eps2 = eps_ft * eps_ft;
        for(std::size_t s : m_candidates)
          if(CGAL::do_overlap(boxes[i], m_boundary.box(s)) && cmp_dist(m_mesh.points[v0 + i], m_boundary.segment(s), eps2) != LARGER) {
            near[v0 + i] = 1;
            break;
          }
      }
    }
    for(std::size_t q = 0; q < nq; ++q) {
      const auto& quad = m_mesh.quads[q];
      if(m_state[q] == KEPT && (near[quad[0]] || near[quad[1]] || near[quad[2]] || near[quad[3]])) m_state[q] = NEAR;
    }
  }

  // ---- single elements and non-manifold vertices -------------------------------------------
  bool kept(std::size_t q) const { return q != none && m_state[q] == KEPT; }

  int kept_neighbours(std::size_t q) const
  {
    int n = 0;
    for(int e = 0; e < 4; ++e) n += kept(m_nb[4 * q + e]) ? 1 : 0;
    return n;
  }

  // `true` if every input quad at v is still kept (most vertices: the fan search is skipped)
  bool keeps_all_its_quads(std::size_t v) const
  {
    if(m_vq_begin[v + 1] - m_vq_begin[v] != m_quads_at[v]) return false;
    for(std::size_t k = m_vq_begin[v]; k < m_vq_begin[v + 1]; ++k)
      if(!kept(m_vq[k] / 4)) return false;
    return true;
  }

  // The fans of kept quads around v: fan f is m_fan_quads[m_fan_begin[f] .. m_fan_begin[f+1]),
  // in the order of a depth-first walk. A fan is a maximal run of kept quads joined by
  // kept-kept edges at v. Member buffers: no allocation per vertex.
  void fans_at(std::size_t v)
  {
    m_local.clear();
    m_fan_quads.clear();
    m_fan_begin.clear();
    for(std::size_t k = m_vq_begin[v]; k < m_vq_begin[v + 1]; ++k)
      if(kept(m_vq[k] / 4)) m_local.push_back(m_vq[k]);
    m_done.assign(m_local.size(), 0);
    for(std::size_t i = 0; i < m_local.size(); ++i) {
      if(m_done[i]) continue;
      m_fan_begin.push_back(m_fan_quads.size());
      m_stack.assign(1, i);
      m_done[i] = 1;
      while(!m_stack.empty()) {
        const std::size_t j = m_stack.back();
        m_stack.pop_back();
        const std::size_t q = m_local[j] / 4, c = m_local[j] % 4;
        m_fan_quads.push_back(Index(q));
        const Index across[2] = {m_nb[4 * q + c], m_nb[4 * q + (c + 3) % 4]};  // the edges at v
        for(Index n : across)
          for(std::size_t t = 0; t < m_local.size(); ++t)
            if(!m_done[t] && m_local[t] / 4 == n) {
              m_done[t] = 1;
              m_stack.push_back(t);
            }
      }
    }
    m_fan_begin.push_back(m_fan_quads.size());
  }

  void remove_singles()
  {
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    Array<Index> quad_work, vertex_work;
    Array<unsigned char> in_qwork(nq, 0), in_vwork(nv, 0);
    // Peeling quads with at most one kept neighbour reaches the same fixed point in any order,
    // and queues no vertex (all are queued here): only the quads removable now start the queue.
    for(std::size_t q = 0; q < nq; ++q)
      if(kept(q)) {
        if(kept_neighbours(q) <= 1) {
          quad_work.push_back(Index(q));
          in_qwork[q] = 1;
        }
        for(int c = 0; c < 4; ++c)
          if(!in_vwork[m_mesh.quads[q][c]]) {
            in_vwork[m_mesh.quads[q][c]] = 1;
            vertex_work.push_back(Index(m_mesh.quads[q][c]));
          }
      }
    std::reverse(vertex_work.begin(), vertex_work.end());  // popped from the back: input order
    auto remove = [&](std::size_t q) {
      m_state[q] = SINGLE;
      for(int e = 0; e < 4; ++e) {
        const Index n = m_nb[4 * q + e];
        if(kept(n) && !in_qwork[n]) {
          in_qwork[n] = 1;
          quad_work.push_back(n);
        }
      }
      for(int c = 0; c < 4; ++c) {
        const std::size_t v = m_mesh.quads[q][c];
        if(!in_vwork[v]) {
          in_vwork[v] = 1;
          vertex_work.push_back(Index(v));
        }
      }
    };
    // Quads first (cheap, and removing singles often resolves a pinch by itself), then one
    // vertex at a time, back to quads whenever a vertex fix removed something.
    while(!quad_work.empty() || !vertex_work.empty()) {
      if(!quad_work.empty()) {
        const std::size_t q = quad_work.back();
        quad_work.pop_back();
        in_qwork[q] = 0;
        if(kept(q) && kept_neighbours(q) <= 1) remove(q);
        continue;
      }
      const std::size_t v = vertex_work.back();
      vertex_work.pop_back();
      in_vwork[v] = 0;
      if(keeps_all_its_quads(v)) continue; // one fan: the quads around a vertex of a
                                            // conforming mesh are joined by their edges there
      fans_at(v);
      const std::size_t nf = m_fan_begin.size() - 1;
      if(nf <= 1) continue;
      auto fan_size = [&](std::size_t f) { return m_fan_begin[f + 1] - m_fan_begin[f]; };
      auto min_index = [&](std::size_t f) {
        return *std::min_element(m_fan_quads.begin() + m_fan_begin[f], m_fan_quads.begin() + m_fan_begin[f + 1]);
      };
      std::size_t best = 0;
      for(std::size_t f = 1; f < nf; ++f)
        if(fan_size(f) > fan_size(best) || (fan_size(f) == fan_size(best) && min_index(f) < min_index(best)))
          best = f;
      for(std::size_t f = 0; f < nf; ++f)
        if(f != best)
          for(std::size_t k = m_fan_begin[f]; k < m_fan_begin[f + 1]; ++k) remove(m_fan_quads[k]);
    }
  }

  // ---- output ------------------------------------------------------------------------------
  // The core is the input mesh compacted in place: its memory is already paged in, where a
  // fresh copy cost a page fault per 4 kB written.
  Clearance_result<K> output()
  {
    Clearance_result<K> r;
    const std::size_t nq = m_mesh.quads.size(), nv = m_mesh.points.size();
    auto& new_index = r.core_vertex;
    new_index.assign(nv, removed_vertex);
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
    // The buffer layers add a few quads and points per core boundary edge (see
    // Buffer_layers::match_loops()): room for them now, or the first one added copies the
    // whole core into fresh memory.
    std::size_t boundary_edges = 0;
    for(std::size_t q = 0; q < nq; ++q)
      if(m_state[q] == KEPT)
        for(int e = 0; e < 4; ++e) boundary_edges += kept(m_nb[4 * q + e]) ? 0 : 1;
    const std::size_t room = 4 * boundary_edges;
    // A kept vertex or quad moves to an index no larger than its own: forward copies are safe.
    std::size_t kept_points = 0;
    for(std::size_t v = 0; v < nv; ++v)
      if(new_index[v] != removed_vertex) {
        new_index[v] = kept_points;
        m_mesh.points[kept_points++] = m_mesh.points[v];
      }
    m_mesh.points.resize(kept_points);
    const std::size_t kept_quads = nq - r.removed_outside - r.removed_intersecting - r.removed_near - r.removed_single;
    r.core_to_input_quad.reserve(kept_quads);
    for(std::size_t q = 0; q < nq; ++q)
      if(m_state[q] == KEPT) {
        typename Mesh::Quad& quad = m_mesh.quads[r.core_to_input_quad.size()];
        for(int c = 0; c < 4; ++c) quad[c] = new_index[m_mesh.quads[q][c]];
        r.core_to_input_quad.push_back(q);
      }
    m_mesh.quads.resize(kept_quads);
    m_mesh.points.reserve(kept_points + room);
    m_mesh.quads.reserve(kept_quads + room);
    r.core = std::move(m_mesh);
    return r;
  }

  Mesh m_mesh; // the input, compacted into the core by output()
  const std::vector<double>& m_size;
  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  const K& m_traits;
  Array<State> m_state;
  Domain_segments<K> m_boundary;
  std::vector<std::size_t> m_candidates;
  Array<Index> m_nb;
  Array<Index> m_vq_begin, m_vq;
  Array<Index> m_quads_at; // the number of input quads at each vertex
  // fans_at()'s buffers; m_local holds corners 4q+c
  std::vector<Index> m_local, m_fan_quads;
  std::vector<std::size_t> m_fan_begin, m_stack;
  std::vector<unsigned char> m_done;
};

/// Buffer zone clearance (paper §4.3), see the rules at the top of this file.
///
/// \param mesh a conforming all-quad mesh, convex CCW quads, covering the domain's bounding
///   grid (e.g. `templated_mesh(tree, &quad_cells)`); moved in, it becomes the core
/// \param quad_size `quad_size[q]`: the size s_q of quad q, the side of the quadtree cell it
///   came from (`tree.cell_side(quad_cells[q].level)`)
/// \param domain, loops the domain and its validated loops (`extract_loops(domain)`)
template <class K>
Clearance_result<K> clear_buffer_zone(Quad_mesh_2<typename K::Point_2> mesh,
                                      const std::vector<double>& quad_size, const Domain_2<K>& domain,
                                      const Domain_loops_2<K>& loops, const K& traits = K())
{
  Buffer_zone_clearance<K> c(std::move(mesh), quad_size, domain, loops, traits);
  return c.run();
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_CLEARANCE_H
