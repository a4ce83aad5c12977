// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The walls of a boundary-layer mesh and their offsets (paper §5, Fig. 9): each wall loop is
// offset into the domain by its stack's thickness, and the rest of the pipeline meshes the
// domain bounded by these offsets, so that the stacks are extruded between a wall and its
// offset (boundary_layer_extrusion.h) rather than squeezed into the buffer's quads.
//
// A wall vertex turning the domain's boundary by at most 45 degrees outward (or any angle
// inward) is offset along its angle's bisector, to the point at the stack's thickness from
// both of its edges' lines (a mitre). A vertex turning outward by more (a trailing edge, a
// reflex corner of the domain) is offset by a circular arc of 2 ceil(turn / 90°) steps
// around it, whose rays become a fan of quads around the corner (Fig. 9(a) generalised).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_OFFSET_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_OFFSET_H

#include <CGAL/Quad_mesher_2/Boundary_layer_criteria_2.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/Box_tree.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/intersections.h>

#include <boost/variant/get.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// One wall loop of the domain, its stack's thickness at each vertex and its offset.
struct Wall_offset
{
  std::size_t loop = 0;                      // in the domain's `Domain_loops_2`
  std::vector<std::size_t> vertices;         // the loop's domain points, in loop order
  std::vector<Point_2d> wall;                // their doubles
  std::vector<int> markers;                  // of wall edge k (vertex k to k + 1)
  std::vector<double> thickness;             // the stack's thickness at vertex k
  std::vector<std::vector<Point_2d>> offset; // of vertex k: one mitre point, or an arc's points
  double apart = 0; // a distance the mesh's validity check tells apart, with a margin
  double mitre_turn = 0; // outward turns up to this are mitred, larger ones get an arc

  std::size_t size() const { return wall.size(); }
  std::size_t next(std::size_t k) const { return (k + 1) % wall.size(); }
  std::size_t prev(std::size_t k) const { return (k + wall.size() - 1) % wall.size(); }
};

/// the turn of the boundary at wall vertex k, radians, positive to the left (inward: the
/// domain's angle there is 180° minus the turn)
inline double wall_turn(const Wall_offset& w, std::size_t k)
{
  const Vector_2d e_in = w.wall[k] - w.wall[w.prev(k)], e_out = w.wall[w.next(k)] - w.wall[k];
  return std::atan2(CGAL::determinant(e_in, e_out), CGAL::scalar_product(e_in, e_out));
}

/// How near to wall vertex k a ray's foot of its own may stand on its edges: so far that it
/// lies `w.apart` from the other edge at k; nearer, it would be a node on that edge or a near
/// duplicate of k (at a needle's tip, on a short edge), and stands on k itself.
inline double nearest_foot(const Wall_offset& w, std::size_t k)
{
  const Vector_2d a = w.wall[w.prev(k)] - w.wall[k], b = w.wall[w.next(k)] - w.wall[k];
  if(CGAL::scalar_product(a, b) <= 0) return w.apart; // the other edge is nearest at k
  const double sine = std::abs(CGAL::determinant(a, b)) / (length_2d(a) * length_2d(b));
  return sine > 0 ? w.apart / sine : HUGE_VAL;
}

/// the unit normal of wall edge (a, b) into the domain (on its left)
inline Vector_2d wall_normal(const Point_2d& a, const Point_2d& b)
{
  return normalized_2d((b - a).perpendicular(COUNTERCLOCKWISE));
}

/// the steps of an arc turn by at most twice this
constexpr double wall_arc_turn = 3.14159265358979323846 / 4;

/// Outward turns up to this are offset by a mitre: 45° with two layers or more, whose fans
/// keep [45°, 135°]; 135° with one, whose fans have only their kites, with tips under 45°
/// where the outer mesh puts several nodes on an arc's step, while the bands about a mitre
/// of a turn t have angles 90° ± t / 2, and the outer mesh's nodes near the corner stand on
/// its two edges.
inline double mitre_turn(int layers)
{
  return layers == 1 ? 3 * wall_arc_turn : wall_arc_turn;
}

/// the offset points of wall vertex k at thickness t (see the file's comment)
inline std::vector<Point_2d> wall_vertex_offset(const Wall_offset& w, std::size_t k, double t)
{
  const double turn = wall_turn(w, k);
  const Point_2d& v = w.wall[k];
  const Vector_2d n_in = wall_normal(w.wall[w.prev(k)], v);
  if(turn >= -w.mitre_turn)
    return { v + turned_2d(n_in, turn / 2) * (t / std::cos(turn / 2)) };
  const int steps = 2 * int(std::ceil(-turn / (2 * wall_arc_turn) - 1e-9));
  const double step = turn / steps;
  std::vector<Point_2d> arc;
  for(int i = 0; i <= steps; ++i)
    arc.push_back(v + turned_2d(n_in, step * i) * t);
  return arc;
}

/// the wall loops of `domain`: those whose segments carry one of `markers` (every segment of
/// such a loop must: a stack ending on a loop is not supported); with no markers, the hole
/// loops, or the outer loop when there is none. Throws `Meshing_error` for a marker that no
/// segment carries or a loop only partly a wall.
template <class K>
std::vector<Wall_offset> wall_loops(const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                                    const std::vector<int>& markers)
{
  const std::vector<std::vector<int>> edge_markers = loop_edge_markers(domain, loops);
  std::set<int> wanted(markers.begin(), markers.end()), seen;
  const std::size_t none = std::size_t(-1);
  bool any_hole = false;
  for(const auto& l : loops.loops) any_hole = any_hole || (!l.is_outer && l.twin == none);
  std::vector<Wall_offset> walls;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    std::size_t on_wall = 0;
    for(int m : edge_markers[l])
      if(wanted.count(m) != 0) { ++on_wall; seen.insert(m); }
    // an interface or a crack has the domain on both sides: no wall (a stack would face its
    // own twin)
    const bool on_interface = loops.loops[l].twin != none;
    if(on_interface && on_wall > 0) {
      std::ostringstream msg;
      msg << "boundary layers: loop " << l + 1 << " (through input point "
          << domain.point_label(loops.loops[l].vertices.front())
          << (loops.loops[l].twin == l ? ") is a crack" : ") is an interface between two regions")
          << ", not a wall: boundary layers on interfaces and cracks are not supported";
      throw Meshing_error(msg.str());
    }
    const bool is_wall = !on_interface && (markers.empty() ? (any_hole ? !loops.loops[l].is_outer : true) : on_wall > 0);
    if(!is_wall) continue;
    if(!markers.empty() && on_wall != edge_markers[l].size()) {
      std::ostringstream msg;
      msg << "boundary layers: loop " << l + 1 << " (through input point "
          << domain.point_label(loops.loops[l].vertices.front())
          << ") is only partly a wall; every segment of a wall loop must carry a wall marker";
      throw Meshing_error(msg.str());
    }
    Wall_offset w;
    w.loop = l;
    w.vertices = loops.loops[l].vertices;
    for(std::size_t v : w.vertices) w.wall.push_back(to_point_2d(domain.points[v]));
    w.markers = edge_markers[l];
    walls.push_back(std::move(w));
  }
  for(int m : wanted)
    if(seen.count(m) == 0)
      throw Meshing_error("boundary layers: no segment carries wall marker " + std::to_string(m));
  if(walls.empty())
    throw Meshing_error("boundary layers: the domain has no wall");
  return walls;
}

/// Chooses each wall vertex's thickness and offsets the walls: the full stack where it fits,
/// a third of the facing distance where another part of the boundary faces the wall closer
/// than three stacks, graded along the wall, then halved wherever an offset, a ray from a wall
/// vertex to its offset or an isolated point still meets the boundary or another offset.
template <class K>
class Wall_offsetter
{
public:
  /// `layers`, `thickness`: the stack's; `first_fraction`: its first layer's height over its
  /// thickness
  Wall_offsetter(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, std::vector<Wall_offset>& walls,
                 int layers, double thickness, double first_fraction)
    : m_domain(domain), m_loops(loops), m_walls(walls), m_layers(layers), m_T(thickness),
      m_first_fraction(first_fraction)
  {
    for(std::size_t l = 0; l < loops.loops.size(); ++l) {
      const auto& lv = loops.loops[l].vertices;
      for(std::size_t e = 0; e < lv.size(); ++e) {
        m_edges.push_back({ Segment_2d(to_point_2d(domain.points[lv[e]]), to_point_2d(domain.points[lv[(e + 1) % lv.size()]])),
                            l, e });
        m_edge_boxes.push_back(m_edges.back().s.bbox());
      }
    }
    m_edge_tree = std::make_unique<Box_tree>(m_edge_boxes);
    Bbox_2 box = m_edge_boxes.empty() ? Bbox_2() : m_edge_boxes.front();
    for(const Bbox_2& b : m_edge_boxes) box += b;
    m_diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  }

  /// at most this many halvings before a stack is reported as unable to fit
  static constexpr int max_halvings = 60;
  /// how fast a thinned stack grows back along its wall (thickness per unit length)
  static constexpr double grading = 0.25;

  void run()
  {
    for(Wall_offset& w : m_walls) {
      w.apart = 4e-9 * m_diagonal; // four times the validity check's 1e-9 of the diagonal
      w.mitre_turn = mitre_turn(m_layers);
      w.thickness.assign(w.size(), m_T);
      for(std::size_t k = 0; k < w.size(); ++k) {
        w.thickness[k] = (std::min)(m_T, facing_distance(w, k) / 3);
        // a needle's stack reaches beyond the stretch of its sides too close together for
        // feet: the outer mesh's nodes there then stand on the tip at angles a fan can take
        if(wall_turn(w, k) < -2 * wall_arc_turn) w.thickness[k] = (std::max)(w.thickness[k], nearest_foot(w, k));
      }
      grade(w);
    }
    check_first_layers();
    for(int round = 0;; ++round) {
      offset_all();
      const std::vector<std::vector<char>> thin = crossings();
      bool any = false;
      for(const auto& t : thin) any = any || std::find(t.begin(), t.end(), 1) != t.end();
      if(!any) return;
      if(round == max_halvings) throw Meshing_error(no_fit_message(thin));
      for(std::size_t i = 0; i < m_walls.size(); ++i) {
        for(std::size_t k = 0; k < m_walls[i].size(); ++k)
          if(thin[i][k] != 0) m_walls[i].thickness[k] /= 2;
        grade(m_walls[i]);
      }
      check_first_layers();
    }
  }

private:
  // the boundary's segments, the offsets' and the rays', each with the wall vertices whose
  // thickness moves it (none for an input segment of no wall)
  struct Piece
  {
    Segment_2d s;
    std::size_t wall, k0, k1; // wall none: an input segment of no wall
    bool input;               // input segments meet none of their own (extract_loops() checked)
  };
  static constexpr std::size_t none = std::size_t(-1);

  // the nearest boundary point another part of the boundary puts in front of vertex k: rays
  // along its offset directions (and 30° either side), its own edges left out
  double facing_distance(const Wall_offset& w, std::size_t k) const
  {
    const Point_2d v = w.wall[k];
    std::vector<Vector_2d> dirs;
    for(const Point_2d& p : wall_vertex_offset(w, k, 1.0)) dirs.push_back(normalized_2d(p - v));
    const std::size_t n = dirs.size();
    for(std::size_t i = 0; i < n; ++i) {
      dirs.push_back(turned_2d(dirs[i], 3.14159265358979323846 / 6));
      dirs.push_back(turned_2d(dirs[i], -3.14159265358979323846 / 6));
    }
    const double reach = 3 * m_T;
    double best = HUGE_VAL;
    for(const Vector_2d& d : dirs) {
      const Segment_2d ray(v, v + d * reach);
      m_edge_tree->query(ray.bbox(), [&](std::size_t i) {
        const Edge& e = m_edges[i];
        if(e.loop == w.loop && (e.e == k || e.e == w.prev(k))) return;
        const auto hit = CGAL::intersection(ray, e.s);
        if(!hit) return;
        if(const Point_2d* p = boost::get<Point_2d>(&*hit))
          best = (std::min)(best, length_2d(*p - v));
        else if(const Segment_2d* s = boost::get<Segment_2d>(&*hit)) // running along the ray
          best = (std::min)(best, (std::min)(length_2d(s->source() - v), length_2d(s->target() - v)));
      });
    }
    return best;
  }

  // no vertex's thickness more than `grading` times its distance along the wall above a
  // neighbour's: thinning spreads smoothly along the wall
  static void grade(Wall_offset& w)
  {
    const std::size_t n = w.size();
    for(int pass = 0; pass < 2; ++pass)
      for(std::size_t i = 0; i < 2 * n; ++i) {
        const std::size_t k = pass == 0 ? i % n : (2 * n - 1 - i) % n;
        const std::size_t j = pass == 0 ? w.prev(k) : w.next(k);
        const double cap = w.thickness[j] + grading * length_2d(w.wall[k] - w.wall[j]);
        w.thickness[k] = (std::min)(w.thickness[k], cap);
      }
  }

  void offset_all()
  {
    for(Wall_offset& w : m_walls) {
      w.offset.resize(w.size());
      for(std::size_t k = 0; k < w.size(); ++k)
        w.offset[k] = wall_vertex_offset(w, k, w.thickness[k]);
    }
  }

  std::vector<Piece> pieces() const
  {
    std::vector<Piece> p;
    std::vector<std::size_t> wall_of_loop(m_loops.loops.size(), none);
    for(std::size_t i = 0; i < m_walls.size(); ++i) wall_of_loop[m_walls[i].loop] = i;
    for(const Edge& e : m_edges)
      p.push_back({ e.s, wall_of_loop[e.loop], e.e, (e.e + 1) % m_loops.loops[e.loop].vertices.size(), true });
    for(std::size_t i = 0; i < m_walls.size(); ++i) {
      const Wall_offset& w = m_walls[i];
      for(std::size_t k = 0; k < w.size(); ++k) {
        const auto& o = w.offset[k];
        for(const Point_2d& q : o) p.push_back({ Segment_2d(w.wall[k], q), i, k, k, false });
        for(std::size_t a = 0; a + 1 < o.size(); ++a) p.push_back({ Segment_2d(o[a], o[a + 1]), i, k, k, false });
        p.push_back({ Segment_2d(o.back(), w.offset[w.next(k)].front()), i, k, w.next(k), false });
      }
    }
    return p;
  }

  // two pieces meet other than at a shared end (a point in one or an overlap)
  static bool meet(const Segment_2d& a, const Segment_2d& b)
  {
    if(!CGAL::do_intersect(a, b)) return false;
    const Point_2d ends[2][2] = { { a.source(), a.target() }, { b.source(), b.target() } };
    for(int i = 0; i < 2; ++i)
      for(int j = 0; j < 2; ++j)
        if(ends[0][i] == ends[1][j]) {
          // touching at the shared end only, unless the other ends run along each other
          const Point_2d& pa = ends[0][1 - i];
          const Point_2d& pb = ends[1][1 - j];
          if(CGAL::orientation(ends[0][i], pa, pb) != COLLINEAR) return false;
          return CGAL::scalar_product(pa - ends[0][i], pb - ends[0][i]) > 0;
        }
    return true;
  }

  // the wall vertices to thin: those of every pair of pieces that meet, and of every stack
  // holding an isolated point
  std::vector<std::vector<char>> crossings() const
  {
    std::vector<std::vector<char>> thin(m_walls.size());
    for(std::size_t i = 0; i < m_walls.size(); ++i) thin[i].assign(m_walls[i].size(), 0);
    const std::vector<Piece> p = pieces();
    std::vector<Bbox_2> boxes;
    for(const Piece& q : p) boxes.push_back(q.s.bbox());
    const Box_tree tree(boxes);
    auto mark = [&](const Piece& q) {
      if(q.wall == none) return;
      const Wall_offset& w = m_walls[q.wall];
      for(std::size_t k : { w.prev(q.k0), q.k0, q.k1, w.next(q.k1) }) thin[q.wall][k] = 1;
    };
    for(std::size_t a = 0; a < p.size(); ++a)
      tree.query(boxes[a], [&](std::size_t b) {
        if(b <= a || (p[a].input && p[b].input)) return;
        if(!meet(p[a].s, p[b].s)) return;
        mark(p[a]);
        mark(p[b]);
      });
    // each wall edge's stack, from its vertices' rays, must be a convex quad: its bands are
    // cut from it
    for(std::size_t i = 0; i < m_walls.size(); ++i) {
      const Wall_offset& w = m_walls[i];
      for(std::size_t k = 0; k < w.size(); ++k) {
        const Point_2d q[4] = { w.wall[k], w.wall[w.next(k)], w.offset[w.next(k)].front(), w.offset[k].back() };
        for(int c = 0; c < 4; ++c)
          if(CGAL::orientation(q[c], q[(c + 1) % 4], q[(c + 2) % 4]) != LEFT_TURN)
            thin[i][k] = thin[i][w.next(k)] = 1;
      }
    }
    for(std::size_t v : m_loops.isolated_points) {
      const Point_2d x = to_point_2d(m_domain.points[v]);
      for(std::size_t i = 0; i < m_walls.size(); ++i)
        for(std::size_t k = 0; k < m_walls[i].size(); ++k)
          if(in_stack(m_walls[i], k, x)) thin[i][k] = thin[i][m_walls[i].next(k)] = 1;
    }
    return thin;
  }

  // x in the stack of wall edge k or of the fan at its vertex k
  static bool in_stack(const Wall_offset& w, std::size_t k, const Point_2d& x)
  {
    std::vector<Point_2d> poly = { w.wall[k], w.wall[w.next(k)], w.offset[w.next(k)].front() };
    for(auto it = w.offset[k].rbegin(); it != w.offset[k].rend(); ++it) poly.push_back(*it);
    return CGAL::bounded_side_2(poly.begin(), poly.end(), x, Approximate_kernel()) != ON_UNBOUNDED_SIDE;
  }

  // A first layer under 1e-8 of the domain's diagonal would put vertices closer than the
  // whole-mesh check tells apart (1e-9 of it): an error naming the place, not a bad mesh.
  void check_first_layers() const
  {
    const double least = 1e-8 * m_diagonal;
    for(const Wall_offset& w : m_walls)
      for(std::size_t k = 0; k < w.size(); ++k)
        if(w.thickness[k] * m_first_fraction < least) {
          std::ostringstream msg;
          msg << "boundary layers: at (" << w.wall[k].x() << ", " << w.wall[k].y() << ") (input point "
              << m_domain.point_label(w.vertices[k]) << ") the stack must be thinned to " << w.thickness[k]
              << " (of " << m_T << ") to fit beside the boundary it faces, which makes its first layer "
              << w.thickness[k] * m_first_fraction << " thick, under 1e-8 of the domain's diagonal; "
              << "use fewer layers, a smaller growth or a thinner stack";
          throw Meshing_error(msg.str());
        }
  }

  std::string no_fit_message(const std::vector<std::vector<char>>& thin) const
  {
    std::ostringstream msg;
    msg << "boundary layers: the stack cannot fit";
    for(std::size_t i = 0; i < m_walls.size(); ++i)
      for(std::size_t k = 0; k < m_walls[i].size(); ++k)
        if(thin[i][k] != 0) {
          msg << " at (" << m_walls[i].wall[k].x() << ", " << m_walls[i].wall[k].y() << ") (input point "
              << m_domain.point_label(m_walls[i].vertices[k]) << "): its offset meets the boundary or another stack "
              << "even when thinned to " << m_walls[i].thickness[k];
          return msg.str();
        }
    return msg.str();
  }

  struct Edge
  {
    Segment_2d s;
    std::size_t loop, e;
  };

  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  std::vector<Wall_offset>& m_walls;
  int m_layers;
  double m_T;
  double m_first_fraction;
  double m_diagonal = 0; // of the input's loops
  std::vector<Edge> m_edges; // the input's, by loop
  std::vector<Bbox_2> m_edge_boxes;
  std::unique_ptr<Box_tree> m_edge_tree;
};

/// The domain bounded by the offsets: `domain` with each wall loop replaced by its offset
/// (the same holes, regional attributes, isolated points and other loops). `offset_first[i]`
/// is the index in the result's points of wall `i`'s first offset point; its points follow in
/// offset order.
template <class K>
Domain_2<K> offset_domain(const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                          const std::vector<Wall_offset>& walls, std::vector<std::size_t>& offset_first)
{
  std::vector<char> on_wall(domain.points.size(), 0);
  for(const Wall_offset& w : walls)
    for(std::size_t v : w.vertices) on_wall[v] = 1;
  Domain_2<K> out;
  std::vector<std::size_t> index(domain.points.size(), std::size_t(-1));
  for(std::size_t v = 0; v < domain.points.size(); ++v)
    if(on_wall[v] == 0) {
      index[v] = out.points.size();
      out.points.push_back(domain.points[v]);
      out.point_labels.push_back(domain.point_label(v));
    }
  const std::vector<std::vector<int>> markers = loop_edge_markers(domain, loops);
  std::vector<char> is_wall(loops.loops.size(), 0);
  for(const Wall_offset& w : walls) is_wall[w.loop] = 1;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    if(is_wall[l] != 0 || loops.loops[l].twin < l) continue; // an interface's segments once
    const auto& lv = loops.loops[l].vertices;
    const std::size_t edges = loops.loops[l].twin == l ? lv.size() / 2 : lv.size(); // a crack along, not back
    for(std::size_t e = 0; e < edges; ++e) {
      out.segments.push_back({ { index[lv[e]], index[lv[(e + 1) % lv.size()]] } });
      out.segment_markers.push_back(markers[l][e]);
    }
  }
  offset_first.clear();
  for(const Wall_offset& w : walls) {
    offset_first.push_back(out.points.size());
    for(std::size_t k = 0; k < w.size(); ++k)
      for(const Point_2d& p : w.offset[k]) {
        out.points.push_back(typename K::Point_2(p.x(), p.y()));
        out.point_labels.push_back("on the stack of input point " + domain.point_label(w.vertices[k]));
      }
    const std::size_t first = offset_first.back(), n = out.points.size() - first;
    std::size_t k = 0, a = 0; // the wall vertex and arc point of offset point first + j
    for(std::size_t j = 0; j < n; ++j) {
      out.segments.push_back({ { first + j, first + (j + 1) % n } });
      out.segment_markers.push_back(w.markers[k]);
      if(++a == w.offset[k].size()) { a = 0; ++k; }
    }
  }
  out.holes = domain.holes;
  out.every_hole_marked = domain.every_hole_marked;
  out.hole_labels = domain.hole_labels;
  // their maximum areas size the cells beyond the layers; a point within them is an error
  out.region_attributes = domain.region_attributes;
  for(std::size_t r = 0; r < domain.region_attributes.size(); ++r)
    out.region_attribute_labels.push_back(domain.region_attribute_label(r) + " (it must lie beyond the boundary layers)");
  return out;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_OFFSET_H
