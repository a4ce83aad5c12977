// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_DOMAIN_LOOPS_2_H
#define CGAL_QUAD_MESHER_2_DOMAIN_LOOPS_2_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/Box_tree.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// One closed boundary curve of a domain, as indices into `Domain_2::points`.
///
/// The vertices are listed in order, the first one not repeated at the end, and oriented so
/// that the domain lies on the LEFT of every edge `vertices[i] -> vertices[i+1]`: outer
/// boundaries run counterclockwise, hole boundaries clockwise.
template <class GeomTraits>
struct Boundary_loop_2
{
  /// Indices into `Domain_2::points`, in order; the loop closes from the last to the first.
  std::vector<std::size_t> vertices;
  /// `true` if the domain is inside the loop (counterclockwise), `false` if the loop bounds a
  /// hole (the domain is outside it; clockwise).
  bool is_outer = true;
  /// Nesting depth: 0 for a loop inside no other loop, 1 for a loop directly inside a depth-0
  /// loop, and so on.
  int depth = 0;
  /// The region the loop bounds: the face of the domain inside its outer loop and outside the
  /// holes within; regions are numbered from 0 in the order of their outer loops.
  std::size_t region = 0;
  /// For a loop of an interface (the domain on both sides: a boundary between two regions),
  /// the index of its twin, the loop of the same vertices in the opposite order that bounds
  /// the region on the other side; `std::size_t(-1)` for a loop of the domain's boundary.
  /// The twin of an interface's outer loop (counterclockwise, the region inside) is the
  /// hole loop of the region around it, listed right after it. A crack (an open polyline
  /// v0 ... vk inside the domain) is the hole loop v0 ... vk ... v1 that runs along it and back,
  /// enclosing nothing: the domain is on both of its sides, and it is its own twin.
  std::size_t twin = std::size_t(-1);
  /// Per edge k (from vertex k to vertex k + 1): the loop and the edge that run along the same
  /// segment the other way, where the domain lies on both sides of it (an interface, a crack,
  /// or a segment between two faces that meet at junctions); `{-1, -1}` on the domain's
  /// boundary. Unlike `twin`, it is per edge: a face of a junction's arrangement shares each
  /// stretch of its boundary with another face.
  std::vector<std::array<std::size_t, 2>> edge_twins;
};

/// \ingroup PkgQuadMesher2Ref
/// The boundary of a `Domain_2` as oriented loops, plus the input points that lie on no
/// segment (which later become mesh vertices). Loops are sorted by depth (outermost first),
/// and in order of their lowest segment index within a depth.
template <class GeomTraits>
struct Domain_loops_2
{
  std::vector<Boundary_loop_2<GeomTraits> > loops;
  /// Indices into `Domain_2::points` of the points on no segment, increasing. All lie strictly
  /// inside the domain.
  std::vector<std::size_t> isolated_points;
  /// Per region (see `Boundary_loop_2::region`), the index into `Domain_2::region_attributes`
  /// of the regional attribute whose point lies in it, or `std::size_t(-1)` if none does.
  std::vector<std::size_t> region_attributes;
};

namespace internal {

inline std::string loops_format_double(double v)
{
  char buf[64];
  const std::to_chars_result r = std::to_chars(buf, buf + sizeof(buf), v);
  return std::string(buf, r.ptr);
}

template <class K>
std::string loops_format_point(const typename K::Point_2& p, const K& traits)
{
  return "(" + loops_format_double(CGAL::to_double(traits.compute_x_2_object()(p))) + ", " +
         loops_format_double(CGAL::to_double(traits.compute_y_2_object()(p))) + ")";
}

/// The work of `extract_loops()`: every check in the order documented there.
template <class K>
class Loop_extractor
{
  typedef typename K::Point_2 Point_2;
  typedef typename K::Segment_2 Segment_2;
  static constexpr std::size_t none = (std::numeric_limits<std::size_t>::max)();

public:
  Loop_extractor(const Domain_2<K>& d, const K& traits) : m_d(d), m_traits(traits) {}

  Domain_loops_2<K> run()
  {
    Domain_loops_2<K> out;
    const std::size_t np = m_d.points.size();
    if(m_d.segments.empty()) {  // a point cloud
      if(!m_d.holes.empty())
        throw Meshing_error("hole point " + m_d.hole_label(0) + " " + pt(m_d.holes[0]) +
                            " lies outside every boundary loop: the domain has no segments, so there is nothing to make a hole in");
      if(!m_d.region_attributes.empty())
        throw Meshing_error("regional attribute " + m_d.region_attribute_label(0) + " " + pt(m_d.region_attributes[0].point) +
                            " lies outside every boundary loop: the domain has no segments, so it has no regions");
      for(std::size_t i = 0; i < np; ++i) out.isolated_points.push_back(i);
      return out;
    }
    check_segments();
    compute_loops();
    check_degenerate_loops();
    check_intersections();
    orient_loops();
    build_point_locator();
    nest_loops();
    locate_holes();
    classify_loops();

    // Isolated points: strictly inside the domain.
    for(std::size_t i = 0; i < np; ++i) {
      if(m_degree[i] != 0) continue;
      const Point_2& p = m_d.points[i];
      std::size_t on_seg = none;
      const std::size_t region = locate(p, none, on_seg);
      if(on_seg != none)
        throw Meshing_error("point " + m_d.point_label(i) + " " + pt(p) + " is on no segment but lies on segment " +
                            seg_str(on_seg) + ": split the segment there or remove the point");
      if(!m_in_domain[region == none ? m_loops.size() : region])
        throw Meshing_error("point " + m_d.point_label(i) + " " + pt(p) + " is on no segment and lies outside the domain (" +
                            where_region(region) + ")");
      out.isolated_points.push_back(i);
    }

    // Output: by depth, then by discovery order (lowest segment index).
    std::vector<std::size_t> order(m_loops.size());
    for(std::size_t l = 0; l < order.size(); ++l) order[l] = l;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return m_depth[a] < m_depth[b]; });
    number_regions(order);
    out.region_attributes = locate_region_attributes();
    for(std::size_t l : order) {
      if(!m_kept[l]) continue; // a face of a junction's arrangement in a hole, or the outside
      Boundary_loop_2<K> loop;
      loop.vertices = m_loops[l];
      loop.is_outer = m_is_outer[l];
      loop.depth = static_cast<int>(m_depth[l]);
      loop.region = m_region[l];
      // Domain on the left: an outer loop must turn left (CCW), a hole right (CW).
      if(m_ccw[l] != loop.is_outer) std::reverse(loop.vertices.begin() + 1, loop.vertices.end());
      out.loops.push_back(loop);
      if(m_crack[l]) out.loops.back().twin = out.loops.size() - 1;
      if(!m_interface[l] || m_crack[l]) continue;
      // the hole of the region around it, in the opposite direction from the same first vertex
      loop.is_outer = false;
      loop.region = m_region[m_parent[l]];
      std::reverse(loop.vertices.begin() + 1, loop.vertices.end());
      loop.twin = out.loops.size() - 1;
      out.loops.back().twin = out.loops.size();
      out.loops.push_back(std::move(loop));
    }
    find_edge_twins(out.loops);
    return out;
  }

private:
  // Boundary_loop_2::edge_twins: the loop edges along one segment, either way
  static void find_edge_twins(std::vector<Boundary_loop_2<K> >& loops)
  {
    std::vector<std::array<std::size_t, 4> > edges; // from, to, loop, edge
    for(std::size_t l = 0; l < loops.size(); ++l) {
      const auto& v = loops[l].vertices;
      loops[l].edge_twins.assign(v.size(), {none, none});
      for(std::size_t k = 0; k < v.size(); ++k) edges.push_back({v[k], v[(k + 1) % v.size()], l, k});
    }
    std::sort(edges.begin(), edges.end());
    for(const auto& e : edges) {
      const std::array<std::size_t, 4> back{{e[1], e[0], 0, 0}};
      const auto it = std::lower_bound(edges.begin(), edges.end(), back);
      if(it != edges.end() && (*it)[0] == e[1] && (*it)[1] == e[0]) loops[e[2]].edge_twins[e[3]] = {(*it)[2], (*it)[3]};
    }
  }

  // ---- messages -------------------------------------------------------------------------
  // whether loop l is a cycle of a component with junctions, traced by trace_faces()
  bool traced(std::size_t l) const { return m_has_junction[m_component[l]]; }

  std::string pt(const Point_2& p) const { return loops_format_point(p, m_traits); }
  std::string vtx(std::size_t v) const { return "vertex " + m_d.point_label(v) + " " + pt(m_d.points[v]); }
  std::string seg_str(std::size_t s) const
  {
    const auto& sg = m_d.segments[s];
    return m_d.segment_label(s) + " (vertices " + m_d.point_label(sg[0]) + " " + pt(m_d.points[sg[0]]) + " and " +
           m_d.point_label(sg[1]) + " " + pt(m_d.points[sg[1]]) + ")";
  }
  std::string loop_str(std::size_t l) const
  {
    if(m_envelope[l])
      return "the outline of the segments that meet at junctions, from " + vtx(m_loops[l][0]) + " (segment " +
             m_d.segment_label(m_loop_first_segment[l]) + ")";
    if(traced(l))
      return "the face of " + std::to_string(m_loops[l].size()) + " vertices starting at " + vtx(m_loops[l][0]) +
             " (segment " + m_d.segment_label(m_loop_first_segment[l]) + ")";
    if(m_crack[l])
      return "the open polyline of " + std::to_string(m_loops[l].size() / 2) +
             (m_loops[l].size() == 2 ? " segment from " : " segments from ") + vtx(m_loops[l][0]) +
             " to " + vtx(m_loops[l][m_loops[l].size() / 2]) + " (segment " +
             m_d.segment_label(m_loop_first_segment[l]) + ")";
    return "the loop of " + std::to_string(m_loops[l].size()) + " vertices starting at " + vtx(m_loops[l][0]) +
           " (segment " + m_d.segment_label(m_loop_first_segment[l]) + ")";
  }
  std::string where_region(std::size_t region) const
  {
    if(region == none) return "outside every boundary loop";
    return "inside " + loop_str(region) + ", which bounds a hole there";
  }

  // ---- 1. per-segment checks and degrees ----------------------------------------------------
  void check_segments()
  {
    const std::size_t np = m_d.points.size(), ns = m_d.segments.size();
    if(!m_d.segment_markers.empty() && m_d.segment_markers.size() != ns)
      throw Meshing_error("the domain has " + std::to_string(m_d.segment_markers.size()) + " segment markers for " +
                          std::to_string(ns) + " segments: give one per segment, or none");
    m_degree.assign(np, 0);
    for(std::size_t s = 0; s < ns; ++s) {
      const auto& sg = m_d.segments[s];
      for(int e = 0; e < 2; ++e)
        if(sg[e] >= np)
          throw Meshing_error("segment " + std::to_string(s) + " refers to vertex " + std::to_string(sg[e]) +
                              ", but there are only " + std::to_string(np) + " points (indices are 0-based)");
      if(sg[0] == sg[1])
        throw Meshing_error("zero-length segment " + m_d.segment_label(s) + ": both ends are " + vtx(sg[0]));
      if(m_traits.equal_2_object()(m_d.points[sg[0]], m_d.points[sg[1]]))
        throw Meshing_error("zero-length segment " + seg_str(s) + ": its two vertices are at the same place");
      ++m_degree[sg[0]];
      ++m_degree[sg[1]];
    }
    // Repeated segments (either direction).
    std::vector<std::array<std::size_t, 3> > keys(ns);
    for(std::size_t s = 0; s < ns; ++s) {
      const auto& sg = m_d.segments[s];
      keys[s] = {(std::min)(sg[0], sg[1]), (std::max)(sg[0], sg[1]), s};
    }
    std::sort(keys.begin(), keys.end());
    for(std::size_t k = 1; k < ns; ++k) {
      if(keys[k][0] != keys[k - 1][0] || keys[k][1] != keys[k - 1][1]) continue;
      const std::size_t a = keys[k][0], b = keys[k][1];
      const std::string both = "segments " + m_d.segment_label(keys[k - 1][2]) + " and " + m_d.segment_label(keys[k][2]) +
                               " both join " + vtx(a) + " and " + vtx(b);
      if(m_degree[a] == 2 && m_degree[b] == 2)
        throw Meshing_error("a loop with fewer than 3 vertices (a repeated segment): " + both);
      throw Meshing_error("repeated segment: " + both);
    }
  }

  // ---- 2. loops -------------------------------------------------------------------------
  // The segments joined at their ends make components: a closed loop, an open polyline (a
  // crack), or, where a vertex has three segments or more, an arrangement traced face by face
  // (trace_faces()).
  void compute_loops()
  {
    const std::size_t np = m_d.points.size(), ns = m_d.segments.size();
    find_components();
    std::vector<std::array<std::size_t, 2> > inc(np, {none, none}); // at vertices of one or two segments
    for(std::size_t s = 0; s < ns; ++s)
      for(int e = 0; e < 2; ++e) {
        auto& slot = inc[m_d.segments[s][e]];
        slot[slot[0] == none ? 0 : 1] = s;
      }
    m_loop_of_segment.assign(ns, none);
    m_counted.assign(ns, {none, none});
    m_sides.assign(ns, {none, none});
    for(std::size_t s0 = 0; s0 < ns; ++s0) {
      if(m_loop_of_segment[s0] != none) continue;
      if(m_has_junction[m_component_of_segment[s0]]) {
        trace_faces(m_component_of_segment[s0]);
        continue;
      }
      const std::size_t l = m_loops.size();
      std::size_t s = s0, v = m_d.segments[s0][0];
      const bool crack = walk_to_crack_end(inc, s, v);
      const std::size_t start = v;
      std::vector<std::size_t> verts;
      do {
        m_loop_of_segment[s] = l;
        if(!crack) m_counted[s][0] = l;
        verts.push_back(v);
        const auto& sg = m_d.segments[s];
        v = (sg[0] == v) ? sg[1] : sg[0];
        s = (inc[v][0] == s) ? inc[v][1] : inc[v][0];
      } while(v != start && s != none);
      add_loop(m_component_of_segment[s0], crack, false, s0);
      if(crack) { // along the polyline and back: v0 ... vk ... v1
        verts.push_back(v);
        for(std::size_t k = verts.size() - 2; k > 0; --k) verts.push_back(verts[k]);
        m_loops.push_back(std::move(verts));
        continue;
      }
      if(verts.size() < 3) {
        std::string vs;
        for(std::size_t u : verts) vs += " " + vtx(u);
        throw Meshing_error("a loop with fewer than 3 vertices (segment " + m_d.segment_label(s0) + "):" + vs);
      }
      m_loops.push_back(std::move(verts));
    }
  }

  // the per-loop facts of a loop about to be pushed onto m_loops
  void add_loop(std::size_t component, bool crack, bool envelope, std::size_t first_segment)
  {
    m_component.push_back(component);
    m_crack.push_back(crack);
    m_envelope.push_back(envelope);
    m_loop_first_segment.push_back(first_segment);
  }

  // m_component_of_segment: the segments joined through shared vertices, numbered by their
  // lowest segment; m_has_junction: whether a vertex of the component has three or more;
  // m_junction_segments: the segments of each component with a junction, increasing
  void find_components()
  {
    const std::size_t np = m_d.points.size(), ns = m_d.segments.size();
    std::vector<std::size_t> parent(np);
    for(std::size_t v = 0; v < np; ++v) parent[v] = v;
    auto find = [&](std::size_t v) {
      while(parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    for(const auto& sg : m_d.segments) parent[find(sg[0])] = find(sg[1]);
    std::vector<std::size_t> number(np, none);
    m_component_of_segment.resize(ns);
    for(std::size_t s = 0; s < ns; ++s) {
      std::size_t& c = number[find(m_d.segments[s][0])];
      if(c == none) { c = m_has_junction.size(); m_has_junction.push_back(false); }
      m_component_of_segment[s] = c;
      for(std::size_t v : m_d.segments[s])
        if(m_degree[v] > 2) m_has_junction[c] = true;
    }
    m_junction_segments.resize(m_has_junction.size());
    for(std::size_t s = 0; s < ns; ++s)
      if(m_has_junction[m_component_of_segment[s]]) m_junction_segments[m_component_of_segment[s]].push_back(s);
  }

  // ---- 2b. the faces of a component with junctions ---------------------------------------
  // Half-edge 2s runs along segment s from its vertex 0, 2s + 1 back. Walking a face with it
  // on the left, the next half-edge leaves the far end as the first one clockwise from the
  // way back. Every cycle but one bounds a face (counterclockwise); the one around the
  // component, its envelope, runs along the half-edge most counterclockwise of those leaving
  // its lexicographically smallest vertex. A cycle starts at its lowest half-edge.
  void trace_faces(std::size_t component)
  {
    const std::vector<std::size_t>& segs = m_junction_segments[component];
    std::map<std::size_t, std::vector<std::size_t> > around; // per vertex, its half-edges counterclockwise
    for(std::size_t s : segs)
      for(std::size_t e = 0; e < 2; ++e) around[m_d.segments[s][e]].push_back(2 * s + e);
    std::map<std::size_t, std::size_t> position; // of each half-edge in its vertex's ring
    for(auto& [v, ring] : around) {
      sort_counterclockwise(v, ring);
      for(std::size_t k = 0; k < ring.size(); ++k) position[ring[k]] = k;
    }
    auto next = [&](std::size_t h) {
      const std::vector<std::size_t>& ring = around[target(h)];
      return ring[(position[h ^ 1] + ring.size() - 1) % ring.size()];
    };
    const auto less_xy = m_traits.less_xy_2_object();
    auto lowest = around.begin();
    for(auto it = around.begin(); it != around.end(); ++it)
      if(less_xy(m_d.points[it->first], m_d.points[lowest->first])) lowest = it;
    const std::size_t envelope_edge = most_counterclockwise(lowest->first, lowest->second);
    std::map<std::size_t, std::size_t> cycle_of; // half-edge -> loop
    for(std::size_t s : segs)
      for(std::size_t h0 : {2 * s, 2 * s + 1}) {
        if(cycle_of.count(h0) != 0) continue;
        const std::size_t l = m_loops.size();
        std::vector<std::size_t> verts;
        bool envelope = false;
        std::size_t h = h0;
        do {
          cycle_of[h] = l;
          envelope = envelope || h == envelope_edge;
          verts.push_back(m_d.segments[h / 2][h % 2]);
          h = next(h);
        } while(h != h0);
        m_loops.push_back(std::move(verts));
        add_loop(component, false, envelope, s);
      }
    for(std::size_t s : segs) {
      m_loop_of_segment[s] = cycle_of[2 * s];
      const std::size_t a = cycle_of[2 * s], b = cycle_of[2 * s + 1];
      m_sides[s] = {a, b};
      if(a == b) continue; // a segment with one face on both sides crosses a ray into it twice
      std::size_t k = 0;
      for(std::size_t c : {a, b})
        if(!m_envelope[c]) m_counted[s][k++] = c;
    }
  }

  std::size_t target(std::size_t h) const { return m_d.segments[h / 2][1 - h % 2]; }

  // the half-edges leaving v, by their angle from the x axis (exact predicates: no two leave
  // in one direction, the overlap check has rejected that)
  void sort_counterclockwise(std::size_t v, std::vector<std::size_t>& ring) const
  {
    const Point_2& o = m_d.points[v];
    const auto less_y = m_traits.less_y_2_object();
    const auto cmp_x = m_traits.compare_x_2_object();
    const auto orient = m_traits.orientation_2_object();
    auto upper = [&](const Point_2& q) { // angle in [0, 180)
      return less_y(o, q) || (!less_y(q, o) && cmp_x(q, o) == LARGER);
    };
    std::sort(ring.begin(), ring.end(), [&](std::size_t g, std::size_t h) {
      const Point_2& a = m_d.points[target(g)];
      const Point_2& b = m_d.points[target(h)];
      const bool ua = upper(a), ub = upper(b);
      if(ua != ub) return ua;
      return orient(o, a, b) == LEFT_TURN;
    });
  }

  // of the half-edges leaving v, the lexicographically smallest vertex of its component (all
  // point into less than a half-plane), the most counterclockwise: the outer face on its left
  std::size_t most_counterclockwise(std::size_t v, const std::vector<std::size_t>& ring) const
  {
    const auto orient = m_traits.orientation_2_object();
    std::size_t best = ring.front();
    for(std::size_t h : ring)
      if(orient(m_d.points[v], m_d.points[target(best)], m_d.points[target(h)]) == LEFT_TURN) best = h;
    return best;
  }

  // Walks from segment s back through v to the end of an open polyline (a vertex of one
  // segment), leaving there s, its first segment, and v, its end; false, s and v unchanged,
  // if s is on a closed loop.
  bool walk_to_crack_end(const std::vector<std::array<std::size_t, 2> >& inc, std::size_t& s, std::size_t& v) const
  {
    std::size_t at = s, u = v;
    do {
      const std::size_t next = (inc[u][0] == at) ? inc[u][1] : inc[u][0];
      if(next == none) { s = at; v = u; return true; }
      at = next;
      const auto& sg = m_d.segments[at];
      u = (sg[0] == u) ? sg[1] : sg[0];
    } while(at != s);
    return false;
  }

  // ---- 3. zero-area loops -----------------------------------------------------------------
  void check_degenerate_loops()
  {
    for(std::size_t l = 0; l < m_loops.size(); ++l) {
      if(m_crack[l] || traced(l)) continue; // encloses nothing by design; a face has area
      const auto& L = m_loops[l];
      const Point_2& a = m_d.points[L[0]];
      const Point_2& b = m_d.points[L[1]];  // differs from a: no zero-length segments
      bool flat = true;
      for(std::size_t k = 2; k < L.size() && flat; ++k)
        flat = (m_traits.orientation_2_object()(a, b, m_d.points[L[k]]) == COLLINEAR);
      if(flat)
        throw Meshing_error("degenerate loop: all the vertices of " + loop_str(l) +
                            " are collinear, so it encloses zero area");
    }
  }

  // ---- 4. segment intersections -----------------------------------------------------------
  Bbox_2 seg_box(std::size_t s) const
  {
    const auto bbox = m_traits.construct_bbox_2_object();
    return bbox(m_d.points[m_d.segments[s][0]]) + bbox(m_d.points[m_d.segments[s][1]]);
  }

  bool on_closed_segment(const Point_2& a, const Point_2& b, const Point_2& p) const
  {
    return m_traits.orientation_2_object()(a, b, p) == COLLINEAR &&
           m_traits.collinear_are_ordered_along_line_2_object()(a, p, b);
  }

  void check_intersections()
  {
    const std::size_t ns = m_d.segments.size();
    m_seg_boxes.resize(ns);
    for(std::size_t s = 0; s < ns; ++s) m_seg_boxes[s] = seg_box(s);
    m_tree.reset(new Box_tree(m_seg_boxes));
    std::vector<std::size_t> cand;
    for(std::size_t i = 0; i < ns; ++i) {
      cand.clear();
      m_tree->query(m_seg_boxes[i], [&](std::size_t j) {
        if(j > i) cand.push_back(j);
      });
      std::sort(cand.begin(), cand.end());  // the error names the first bad pair, whatever the tree
      for(std::size_t j : cand) check_pair(i, j);
    }
  }

  void check_pair(std::size_t i, std::size_t j) const
  {
    const auto& si = m_d.segments[i];
    const auto& sj = m_d.segments[j];
    const auto orient = m_traits.orientation_2_object();
    const Point_2 &a = m_d.points[si[0]], &b = m_d.points[si[1]];
    const Point_2 &c = m_d.points[sj[0]], &d = m_d.points[sj[1]];
    // Consecutive segments (one shared vertex; never two, as repeats are rejected): they may
    // only meet at that vertex, i.e. must not run back along each other.
    for(int e = 0; e < 2; ++e)
      for(int f = 0; f < 2; ++f) {
        if(si[e] != sj[f]) continue;
        const Point_2& v = m_d.points[si[e]];
        const Point_2& p = m_d.points[si[1 - e]];
        const Point_2& q = m_d.points[sj[1 - f]];
        if(orient(p, v, q) == COLLINEAR && !m_traits.collinear_are_ordered_along_line_2_object()(p, v, q))
          throw Meshing_error("segments " + seg_str(i) + " and " + seg_str(j) + " overlap: they leave their shared " +
                              vtx(si[e]) + " in the same direction" + end_inside(i, j));
        return;
      }
    const Segment_2 s1 = m_traits.construct_segment_2_object()(a, b);
    const Segment_2 s2 = m_traits.construct_segment_2_object()(c, d);
    if(!m_traits.do_intersect_2_object()(s1, s2)) return;
    const std::string both = "segments " + seg_str(i) + " and " + seg_str(j);
    if(orient(a, b, c) == COLLINEAR && orient(a, b, d) == COLLINEAR)
      throw Meshing_error(both + " overlap (they are collinear and share more than a point, or touch end to end)" +
                          end_inside(i, j));
    const std::string inside = end_inside(i, j);
    if(!inside.empty()) throw Meshing_error(both + " touch" + inside);
    throw Meshing_error(both + " cross");
  }

  // ": vertex v lies on segment s (...)" for the first end of segment i or j on the other one
  // but at its ends, or "" if none is
  std::string end_inside(std::size_t i, std::size_t j) const
  {
    const std::size_t ends[4][2] = {{m_d.segments[i][0], j}, {m_d.segments[i][1], j},
                                    {m_d.segments[j][0], i}, {m_d.segments[j][1], i}};
    for(const auto& e : ends) {
      const auto& s = m_d.segments[e[1]];
      if(e[0] != s[0] && e[0] != s[1] && on_closed_segment(m_d.points[s[0]], m_d.points[s[1]], m_d.points[e[0]]))
        return ": " + vtx(e[0]) + " lies on segment " + m_d.segment_label(e[1]) +
               " (segments may meet only at their ends: split that segment there)";
    }
    return "";
  }

  // ---- 5. orientation ---------------------------------------------------------------------
  void orient_loops()
  {
    const auto less_xy = m_traits.less_xy_2_object();
    m_ccw.resize(m_loops.size());
    for(std::size_t l = 0; l < m_loops.size(); ++l) {
      const auto& L = m_loops[l];
      m_ccw[l] = traced(l) && !m_envelope[l]; // a crack reads the same either way
      if(m_crack[l] || traced(l)) continue;
      std::size_t k = 0;
      for(std::size_t i = 1; i < L.size(); ++i)
        if(less_xy(m_d.points[L[i]], m_d.points[L[k]])) k = i;
      const Point_2& prev = m_d.points[L[(k + L.size() - 1) % L.size()]];
      const Point_2& next = m_d.points[L[(k + 1) % L.size()]];
      const Orientation o = m_traits.orientation_2_object()(prev, m_d.points[L[k]], next);
      // A simple polygon turns strictly at its lexicographically smallest vertex.
      CGAL_assertion(o != COLLINEAR);
      m_ccw[l] = (o == LEFT_TURN);
    }
  }

  // ---- 6. point location by ray crossing (upward vertical ray) ----------------------------
  void build_point_locator() { m_crossings.assign(m_loops.size(), 0); }

  /// Fills `m_inside` with the loops that contain `p` strictly (of components other than
  /// `skip_component`; a crack or an envelope contains nothing), and returns the innermost one
  /// (`none` if none) once the depths are known, else `none`. Sets `on_seg` if `p` lies on a
  /// segment (of a component other than `skip_component`).
  std::size_t locate(const Point_2& p, std::size_t skip_component, std::size_t& on_seg)
  {
    const auto cmp_x = m_traits.compare_x_2_object();
    const auto orient = m_traits.orientation_2_object();
    const Bbox_2 pb = m_traits.construct_bbox_2_object()(p);
    const Bbox_2 ray(pb.xmin(), pb.ymin(), pb.xmax(), std::numeric_limits<double>::infinity());
    std::vector<std::size_t> touched;
    on_seg = none;
    m_tree->query(ray, [&](std::size_t s) {
      if(m_component_of_segment[s] == skip_component || on_seg != none) return;
      const Point_2& a = m_d.points[m_d.segments[s][0]];
      const Point_2& b = m_d.points[m_d.segments[s][1]];
      const Comparison_result ca = cmp_x(a, p), cb = cmp_x(b, p);
      if(!(ca == LARGER && cb == LARGER) && !(ca == SMALLER && cb == SMALLER) && on_closed_segment(a, b, p)) {
        on_seg = s;
        return;
      }
      if(m_counted[s][0] == none) return; // encloses nothing
      // Half-open rule: the segment counts if one end has x <= p.x and the other x > p.x.
      const bool spans = (ca != LARGER && cb == LARGER) || (cb != LARGER && ca == LARGER);
      if(!spans) return;
      const Point_2& left = (ca == LARGER) ? b : a;
      const Point_2& right = (ca == LARGER) ? a : b;
      if(orient(left, right, p) != RIGHT_TURN) return;  // p is not below the segment
      for(std::size_t l : m_counted[s])
        if(l != none && m_crossings[l]++ == 0) touched.push_back(l);
    });
    m_inside.clear();
    for(std::size_t l : touched) {
      if(m_crossings[l] % 2 == 1) m_inside.push_back(l);
      m_crossings[l] = 0;
    }
    if(on_seg != none || m_depth.size() != m_loops.size()) return none;
    std::size_t inner = none;
    for(std::size_t l : m_inside)
      if(inner == none || m_depth[l] > m_depth[inner]) inner = l;
    return inner;
  }

  void nest_loops()
  {
    const std::size_t nl = m_loops.size();
    std::vector<std::vector<std::size_t> > containers(nl);
    for(std::size_t l = 0; l < nl; ++l) {
      std::size_t on_seg = none;
      locate(m_d.points[m_loops[l][0]], m_component[l], on_seg);
      CGAL_assertion(on_seg == none);  // excluded by the intersection checks
      containers[l] = m_inside;
    }
    m_depth.resize(nl);
    for(std::size_t l = 0; l < nl; ++l) m_depth[l] = containers[l].size();
    m_parent.assign(nl, none);
    for(std::size_t l = 0; l < nl; ++l)
      for(std::size_t c : containers[l])
        if(m_depth[c] + 1 == m_depth[l]) m_parent[l] = c;
  }

  // ---- 7. hole points ---------------------------------------------------------------------
  void locate_holes()
  {
    m_hole_in.assign(m_loops.size() + 1, none);  // region l: inside loop l, outside its children
    for(std::size_t h = 0; h < m_d.holes.size(); ++h) {
      const Point_2& p = m_d.holes[h];
      std::size_t on_seg = none;
      const std::size_t region = locate(p, none, on_seg);
      if(on_seg != none)
        throw Meshing_error("hole point " + m_d.hole_label(h) + " " + pt(p) + " lies exactly on segment " +
                            seg_str(on_seg) + ": it must be strictly inside the hole it marks");
      if(region == none) {
        std::string which;
        std::vector<std::size_t> top;
        for(std::size_t l = 0; l < m_loops.size(); ++l)
          if(m_depth[l] == 0) top.push_back(l);
        if(top.size() == 1)
          which = "it is not inside " + loop_str(top[0]) + ", the outermost loop";
        else
          which = "it is inside none of the " + std::to_string(top.size()) + " outermost loops, e.g. not inside " +
                  loop_str(top[0]);
        throw Meshing_error("hole point " + m_d.hole_label(h) + " " + pt(p) + " lies outside every boundary loop: " + which);
      }
      if(m_hole_in[region] == none) m_hole_in[region] = h;
    }
  }

  // ---- 8. which side of each loop is the domain -------------------------------------------
  void classify_loops()
  {
    const std::size_t nl = m_loops.size();
    m_in_domain.assign(nl + 1, false);  // index nl: the unbounded region, never in the domain
    const bool parity = m_d.holes.empty() && !m_d.every_hole_marked;
    for(std::size_t l = 0; l < nl; ++l)
      m_in_domain[l] = parity ? (m_depth[l] % 2 == 0) : m_hole_in[l] == none;
    m_is_outer.resize(nl);
    m_interface.assign(nl, false);
    m_kept.assign(nl, true);
    for(std::size_t l = 0; l < nl; ++l) {
      if(m_crack[l] || m_envelope[l]) m_in_domain[l] = false; // nothing lies inside it
      if(traced(l)) {
        m_is_outer[l] = !m_envelope[l];
        m_kept[l] = m_envelope[l] ? m_in_domain[m_parent[l] == none ? nl : m_parent[l]] : m_in_domain[l];
        continue;
      }
      const bool inside = m_in_domain[l];
      const bool outside = m_in_domain[m_parent[l] == none ? nl : m_parent[l]];
      if(m_crack[l] && !outside)
        throw Meshing_error(loop_str(l) + " lies " + where_region(m_parent[l]) +
                            ": a polyline with free ends is a crack, which must lie in the domain");
      m_interface[l] = inside && outside; // never by depth parity, which alternates
      if(!inside && !outside) {
        // Hole points on both sides (outside a top loop is the unbounded region): one of them
        // is in no hole. Name the one on the side of even depth, where nesting puts the domain
        // (inside a top loop, in an island), not the loop, which is fine.
        const std::size_t region = m_depth[l] % 2 == 0 ? l : m_parent[l];
        const std::size_t h = m_hole_in[region];
        bool has_inner = false;
        for(std::size_t c = 0; c < nl; ++c) has_inner = has_inner || m_parent[c] == region;
        throw Meshing_error("hole point " + m_d.hole_label(h) + " " + pt(m_d.holes[h]) + " is in no hole: it lies inside " +
                            loop_str(region) + (has_inner ? " and outside the loops within it" : "") +
                            ", in the domain, which would then lie on neither side of " +
                            (region == l ? std::string("that loop") : loop_str(l)) +
                            "; a hole point must lie inside the loop of the hole it marks");
      }
      m_is_outer[l] = inside;
    }
    for(std::size_t s = 0; s < m_d.segments.size(); ++s)
      if(m_has_junction[m_component_of_segment[s]]) check_domain_beside(s);
  }

  // A segment of a component with junctions must have the domain on one side at least: the
  // face of each of its half-edges (found as the cycles holding them) or, for the envelope,
  // the region around the component.
  void check_domain_beside(std::size_t s) const
  {
    const std::array<std::size_t, 2>& sides = m_sides[s];
    if(m_kept[sides[0]] || m_kept[sides[1]]) return;
    auto side = [&](std::size_t l) {
      if(m_envelope[l]) return where_region(m_parent[l]);
      const std::size_t h = m_hole_in[l];
      return "inside " + loop_str(l) + (h != none ? ", which holds hole point " + m_d.hole_label(h) + " " + pt(m_d.holes[h])
                                                  : ", which nesting makes a hole");
    };
    throw Meshing_error("segment " + seg_str(s) + " has the domain on neither side: it lies " + side(sides[0]) +
                        (sides[1] == sides[0] ? std::string() : " and " + side(sides[1])) +
                        "; a segment must bound the domain or lie in it");
  }

  // ---- 9. regions and their attributes ----------------------------------------------------
  // The outer loops in output order are regions 0, 1, ...; a hole loop bounds its parent's.
  void number_regions(const std::vector<std::size_t>& order)
  {
    m_region.assign(m_loops.size(), none);
    std::size_t regions = 0;
    for(std::size_t l : order)
      if(m_kept[l]) m_region[l] = m_is_outer[l] ? regions++ : m_region[m_parent[l]];
    m_regions = regions;
  }

  // Per region, its regional attribute's index; each point strictly inside the domain, and
  // no two different attributes in one region.
  std::vector<std::size_t> locate_region_attributes()
  {
    std::vector<std::size_t> attribute_of(m_regions, none);
    for(std::size_t r = 0; r < m_d.region_attributes.size(); ++r) {
      const auto& a = m_d.region_attributes[r];
      const std::string name = "regional attribute " + m_d.region_attribute_label(r) + " " + pt(a.point);
      if(!std::isfinite(a.attribute) || !(a.max_area >= 0) || !std::isfinite(a.max_area))
        throw Meshing_error(name + " has attribute " + loops_format_double(a.attribute) + " and maximum area " +
                            loops_format_double(a.max_area) + ": both must be finite, the area not negative");
      std::size_t on_seg = none;
      const std::size_t loop = locate(a.point, none, on_seg);
      if(on_seg != none)
        throw Meshing_error(name + " lies on segment " + seg_str(on_seg) + ": it must be strictly inside the region it marks");
      if(!m_in_domain[loop == none ? m_loops.size() : loop])
        throw Meshing_error(name + " lies outside the domain (" + where_region(loop) + ")");
      std::size_t& first = attribute_of[m_region[loop]];
      if(first != none && (m_d.region_attributes[first].attribute != a.attribute
                           || m_d.region_attributes[first].max_area != a.max_area))
        throw Meshing_error(name + " and regional attribute " + m_d.region_attribute_label(first) + " " +
                            pt(m_d.region_attributes[first].point) + " lie in the same region (inside " + loop_str(loop) +
                            ") but differ: a region takes one attribute and one maximum area");
      if(first == none) first = r;
    }
    return attribute_of;
  }

  const Domain_2<K>& m_d;
  const K& m_traits;
  std::vector<std::size_t> m_degree;
  std::vector<std::vector<std::size_t> > m_loops;     // in discovery order, unoriented
  std::vector<std::size_t> m_loop_first_segment;
  std::vector<std::size_t> m_loop_of_segment;
  std::vector<std::size_t> m_component_of_segment;
  std::vector<bool> m_has_junction;    // per component: a vertex of three segments or more
  std::vector<std::vector<std::size_t> > m_junction_segments; // per component with a junction
  // per segment: the loops whose inside a ray crossing it enters or leaves (none, one or two)
  std::vector<std::array<std::size_t, 2> > m_counted;
  // per segment of a component with junctions: the cycles of its half-edges, along and back
  std::vector<std::array<std::size_t, 2> > m_sides;
  std::vector<std::size_t> m_component; // per loop
  std::vector<bool> m_envelope;         // per loop: the cycle around a component with junctions
  std::vector<bool> m_kept;             // per loop: with the domain on its left, so returned
  std::vector<Bbox_2> m_seg_boxes;
  std::unique_ptr<Box_tree> m_tree;
  std::vector<bool> m_ccw;
  std::vector<std::size_t> m_crossings;
  std::vector<std::size_t> m_inside;
  std::vector<std::size_t> m_depth;
  std::vector<std::size_t> m_parent;
  std::vector<std::size_t> m_hole_in;  // per region (index nl: unbounded), its first hole point or none
  std::vector<bool> m_in_domain;
  std::vector<bool> m_is_outer;
  std::vector<bool> m_interface; // per loop: the domain on both sides
  std::vector<bool> m_crack;     // per loop: an open polyline, along and back
  std::vector<std::size_t> m_region;  // per loop, the region it bounds
  std::size_t m_regions = 0;
};

/// Sums `v` pairwise, keeping the expression depth logarithmic (lazy exact numbers).
template <class FT>
FT loops_balanced_sum(std::vector<FT> v)
{
  if(v.empty()) return FT(0);
  while(v.size() > 1) {
    std::size_t k = 0;
    for(std::size_t i = 0; i + 1 < v.size(); i += 2) v[k++] = v[i] + v[i + 1];
    if(v.size() % 2 == 1) v[k++] = v.back();
    v.resize(k);
  }
  return v[0];
}

} // namespace internal

/// \ingroup PkgQuadMesher2Ref
/// Validates the segments of `domain` and returns them as closed, oriented boundary loops,
/// with the points that lie on no segment.
///
/// **Semantics** (Triangle's): the segments, which may meet only at their end points, form
/// components joined at shared vertices. A component whose vertices each have two segments
/// is a closed loop; one whose vertices have one or two is an open polyline, a crack: it must
/// lie in the domain, and it is returned as a hole loop along it and back (v0 ... vk ... v1),
/// its own twin (`Boundary_loop_2::twin`), which encloses nothing. A component with a
/// junction (a vertex of three segments or more: a square split by a segment, a T, a
/// checkerboard, cracks from a loop or meeting at a point) is an arrangement: each of its
/// bounded faces is a region bounded by a counterclockwise loop, the cycle of segments with
/// the face on its left (a crack inside the face walked along and back), and the outline of
/// the whole component is a clockwise loop bounding the region around it. Loops of faces on
/// both sides of a segment share it as twin edges (`Boundary_loop_2::edge_twins`). The loops
/// cut the plane into regions: the unbounded one, and for each loop (each face) the part
/// inside it but outside the loops directly nested in it.
/// - With hole points (or `Domain_2::every_hole_marked`), a region is in the domain iff it is
///   bounded and contains no hole point (Triangle's rule). A loop with the domain on both sides is an interface between two
///   regions: it is returned twice, as the outer loop of the region inside it and, right
///   after, as a hole loop of the region around it (`Boundary_loop_2::twin`). A loop with the
///   domain on neither side is an error.
/// - Otherwise, regions alternate with nesting depth: inside a depth-0 loop is
///   domain, inside a depth-1 loop a hole, inside a depth-2 loop (an island in a hole) domain
///   again, and so on.
///
/// Each returned loop has the domain on its left (outer boundaries counterclockwise, holes
/// clockwise): a loop is reversed (keeping its first vertex) where needed; points are never
/// changed. A loop starts at the first vertex of its lowest-index segment. A domain without
/// segments is a point cloud: no loops, every point isolated.
///
/// Every decision uses exact predicates of `traits`; candidate segment pairs come from a
/// bounding-box hierarchy, so the cost is O(n log n) on ordinary inputs.
///
/// \throws Meshing_error naming the problem, with 0-based indices and coordinates, for: a
/// segment index out of range; a zero-length segment; a repeated segment; a loop of fewer
/// than 3 vertices; an open polyline outside the domain; a segment of a component with
/// junctions that has the domain on neither side; a loop whose vertices are all collinear; two segments
/// that cross, overlap, or touch (a vertex on another segment, or two vertices at the same
/// place); a hole point on a segment or outside every loop; hole points on both sides of a
/// loop (named by the one on the side nesting puts in the domain: inside a top loop, in an
/// island); a point on no segment that lies on a segment
/// or outside the domain; a regional attribute's point on a segment or outside the domain, or
/// two different attributes (or maximum areas) in one region.
template <class K>
Domain_loops_2<K> extract_loops(const Domain_2<K>& domain, const K& traits = K())
{
  internal::Loop_extractor<K> x(domain, traits);
  return x.run();
}

namespace internal {

/// the number of segments at each point of `domain` (three or more: a junction)
template <class K>
std::vector<std::size_t> segment_degrees(const Domain_2<K>& domain)
{
  std::vector<std::size_t> degree(domain.points.size(), 0);
  for(const auto& sg : domain.segments) ++degree[sg[0]], ++degree[sg[1]];
  return degree;
}

/// Throws Meshing_error naming the first vertex of three segments or more, for `stage` (what
/// does not take junctions yet: "boundary layers", "curve decompositions").
template <class K>
void reject_junctions(const Domain_2<K>& domain, const std::string& stage)
{
  const std::vector<std::size_t> degree = segment_degrees(domain);
  for(std::size_t v = 0; v < degree.size(); ++v)
    if(degree[v] > 2)
      throw Meshing_error("vertex " + domain.point_label(v) + " " + loops_format_point(domain.points[v], K()) + " joins " +
                          std::to_string(degree[v]) + " segments: " + stage +
                          " do not take junctions (a vertex on three segments or more) yet");
}

/// whether edge k of `loop` has the domain on both sides (Boundary_loop_2::edge_twins)
template <class K>
bool has_edge_twin(const Boundary_loop_2<K>& loop, std::size_t k)
{
  return loop.edge_twins[k][0] != std::size_t(-1);
}

/// whether edge k of loop l runs along a segment that a loop listed before it has the other
/// way: a pass over the domain's segments that takes each once leaves it out
template <class K>
bool is_second_side(const Domain_loops_2<K>& loops, std::size_t l, std::size_t k)
{
  const std::size_t t = loops.loops[l].edge_twins[k][0];
  return t != std::size_t(-1) && t < l;
}

/// whether vertex k of `loop` ends an edge with the domain on both sides: the mesh keeps it
template <class K>
bool on_edge_twin(const Boundary_loop_2<K>& loop, std::size_t k)
{
  const std::size_t n = loop.vertices.size();
  return has_edge_twin(loop, k) || has_edge_twin(loop, (k + n - 1) % n);
}

/// whether any loop edge of `loops` has the domain on both sides (an interface, a crack, two
/// faces at a junction)
template <class K>
bool has_interfaces(const Domain_loops_2<K>& loops)
{
  for(const Boundary_loop_2<K>& loop : loops.loops)
    for(std::size_t k = 0; k < loop.vertices.size(); ++k)
      if(has_edge_twin(loop, k)) return true;
  return false;
}

/// the sum of the signed areas of the loops `take(loop)` picks, in `FT`
template <class K, class Take>
typename K::FT loops_area(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, Take take, const K& traits)
{
  typedef typename K::FT FT;
  const auto area = traits.compute_area_2_object();
  std::vector<FT> terms;
  for(const auto& loop : loops.loops) {
    if(!take(loop)) continue;
    const auto& v = loop.vertices;
    std::vector<FT> t;
    for(std::size_t i = 1; i + 1 < v.size(); ++i)
      t.push_back(area(domain.points[v[0]], domain.points[v[i]], domain.points[v[i + 1]]));
    terms.push_back(loops_balanced_sum(std::move(t)));
  }
  return loops_balanced_sum(std::move(terms));
}

} // namespace internal

/// \ingroup PkgQuadMesher2Ref
/// The area of the domain: the signed areas of the loops (holes negative), summed in `FT`
/// (exact with an exact-constructions kernel).
template <class K>
typename K::FT domain_area(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, const K& traits = K())
{
  return internal::loops_area(domain, loops, [](const Boundary_loop_2<K>&) { return true; }, traits);
}

/// \ingroup PkgQuadMesher2Ref
/// The area of region `region` of the domain (`Boundary_loop_2::region`), as `domain_area()`.
template <class K>
typename K::FT region_area(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, std::size_t region,
                           const K& traits = K())
{
  return internal::loops_area(domain, loops, [&](const Boundary_loop_2<K>& loop) { return loop.region == region; }, traits);
}

/// \ingroup PkgQuadMesher2Ref
/// The loop as a polygon, in the loop's orientation (domain on the left).
template <class K>
Polygon_2<K> loop_polygon_2(const Domain_2<K>& domain, const Boundary_loop_2<K>& loop, const K& traits = K())
{
  Polygon_2<K> poly(traits);
  for(std::size_t v : loop.vertices) poly.push_back(domain.points[v]);
  return poly;
}

namespace internal {

/// The boundary marker of every loop edge: `[l][k]` for the edge from vertex k to vertex k + 1
/// of loop l, the `Domain_2::segment_markers` entry of its segment or, where the domain has
/// none, the loop's number (the loops numbered from 1 as `extract_loops()` orders them,
/// outermost first, an interface's twin taking the number of the loop it follows).
template <class K>
std::vector<std::vector<int>> loop_edge_markers(const Domain_2<K>& domain, const Domain_loops_2<K>& loops)
{
  // the segments by their ends, lower first: extract_loops() has rejected repeated ones
  std::vector<std::array<std::size_t, 3>> by_ends;
  by_ends.reserve(domain.segment_markers.size());
  for(std::size_t s = 0; s < domain.segment_markers.size(); ++s) {
    const auto& sg = domain.segments[s];
    by_ends.push_back({ (std::min)(sg[0], sg[1]), (std::max)(sg[0], sg[1]), s });
  }
  std::sort(by_ends.begin(), by_ends.end());
  std::vector<std::vector<int>> markers(loops.loops.size());
  int number = 0;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& v = loops.loops[l].vertices;
    if(loops.loops[l].twin >= l) ++number; // an interface's twin follows it: one number
    markers[l].assign(v.size(), number);
    if(by_ends.empty()) continue;
    for(std::size_t k = 0; k < v.size(); ++k) {
      const std::size_t a = v[k], b = v[(k + 1) % v.size()];
      const std::array<std::size_t, 3> key{ { (std::min)(a, b), (std::max)(a, b), 0 } };
      const auto it = std::lower_bound(by_ends.begin(), by_ends.end(), key);
      CGAL_assertion(it != by_ends.end() && (*it)[0] == key[0] && (*it)[1] == key[1]);
      markers[l][k] = domain.segment_markers[(*it)[2]];
    }
  }
  return markers;
}

} // namespace internal

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_DOMAIN_LOOPS_2_H
