// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H

// Filling the buffer zone between the core mesh and the domain boundary (paper §4.4-§4.6).
//
// Input: the core mesh left by the clearance (every core vertex has 0 or 2 boundary edges, so
// the core boundary is simple loops B_0..B_{n-1}, core on the left), with the local size h(B)
// of every vertex (the largest side of its quadtree cells).
//
// 1. Core loops are matched one to one with the domain's loops (each core loop to the loop
//    nearest most of its vertices; the orientation must agree).
// 2. Boundary templates (§4.4): Lemma 2 asks every buffer-side angle beta of the core boundary
//    to lie in [112.5°, 225°]. A vertex B out of it moves along the bisector of beta, e being
//    the mean length of its two boundary edges: a notch (beta below 112.5°) out into the buffer
//    by 0.71, 0.5 or 0.35 e (Template 1(a): a lattice notch opens to 180°), a convex corner
//    (beta above 225°) in by 0.41, 0.3 or 0.2 e (Template 1(b): a lattice corner's quad becomes
//    a kite, beta 225° at B and 202.5° at its neighbours). Of the steps that keep every core
//    angle at B in [45°, 135°] and B's boundary edges h(B)/4 from the boundary, the one that
//    most lowers the worst distance of the three betas at B and its neighbours from
//    [112.5°, 225°] is taken. In the paper's order of priority (Table 2): first the vertices
//    whose quads are not squares of one size (the adaptive templates), then the corners, then
//    the notches; last, a vertex within range moves either way if a neighbour is still out.
//    On a 45° staircase the corners cut first leave 225° and 135°; notches opened first would
//    flatten the corners between them, and every other notch stayed at 90°.
//    On adaptive cores the bisector and the lattice's steps leave about 1% of the vertices out
//    (quads that are not squares, transition templates' 45° corners): each vertex still out
//    then searches the plane around it (a ring of points, then a pattern search) for where the
//    three betas come nearest the range, and if its own is still out, the interior core
//    vertices within two quads of it may give way (they move to keep their quads within
//    [45°, 135°]); still out, it moves with its two neighbours each side (search_window()).
//    Not near an input corner: its buffer is the corner's (§5).
//    A notch that still cannot move (a core angle of 45° at it) gets a new core quad over it
//    (within 2h of an input corner only under 95°), its fourth corner on the bisector or,
//    beside an adaptive core, searched for off it, which leaves about the angles the move
//    would have; not where the notch faces a corner that needs a fan of three (it is the fan's
//    room). A convex corner that cannot move, its one quad jammed by a transition template,
//    has that quad split in three (split_corner()). The vertices around are searched again.
// 3. First buffer layer (§4.5): B's first buffer point F lies halfway (in distance to the
//    boundary) between B and the boundary, along the mean of the bisector of beta and the
//    direction to the nearest boundary point, turned back towards the bisector where B's two
//    first-layer angles would leave [45°, 135°]; each F then moves alone to improve its two
//    first-layer quads and its two projection quads (smooth_first_points). Quads
//    B_i F_i F_{i+1} B_{i+1}.
// 4. Second buffer layer (§4.6): F_i is projected onto its boundary loop; the projections,
//    together with the loop's vertices (those turning by less than 20 degrees may be left out
//    within the chord tolerance), form the boundary chain G. The strip between the F loop and
//    G is cut into triangles, each with one F edge or one G edge, and consecutive triangles
//    are paired into quads: F/G pairs are the paper's projection quads, G/G pairs fan around
//    an F point (the paper's corner quad P-N-M-L of Fig. 8(b)), F/F pairs around a reflex
//    corner fan at the corner (Fig. 8(d)); a corner over 225 degrees keeps three F points on
//    its node, so that its fan has three quads (four over 270 degrees where three left it a
//    fan of two: see may_take_four_fan_points()). Where the F edges meet the G edges and how the
//    triangles pair is chosen by dynamic programming around each loop, minimising the sum of
//    the quads' squared deviations from 90 degrees, with a heavy penalty outside [45, 135] and
//    a prohibitive one for invalid quads. Each gap may also take one more chain node (the
//    middle of its longest edge): the pairing decides where, which is how an odd triangle
//    count is made even and how a long ladder switches between its two phases (a ladder can
//    only switch at a gap with an even number of G edges; without one it shears end to end).
// 5. Optimisation: buffer vertices move (boundary ones slide along their edge) while that
//    lowers the invalid, out-of-range and worst quads around them.
//
// Every new quad is then checked with exact predicates (strictly convex, counter-clockwise).
// Quads that are invalid, or have an angle outside [45°, 135°] that no input corner forces (only
// a corner under 45° does), are reported as refinement requests: the mesher refines the
// quadtree there and starts again.

#include <CGAL/Quad_mesher_2/Buffer_report.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The quads at each vertex of a quad mesh, in increasing order: compressed rows (two arrays
/// for the whole mesh, not a vector per vertex, which cost more than the buffer's own work on
/// large cores), of 32-bit indices, which halve the arrays' memory and its page faults.
class Vertex_quads
{
public:
  struct Range
  {
    const std::uint32_t* first;
    const std::uint32_t* last;
    const std::uint32_t* begin() const { return first; }
    const std::uint32_t* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
  };

  Vertex_quads(const std::vector<std::array<std::size_t, 4>>& quads, std::size_t n_points)
    : m_offsets(n_points + 1, 0), m_quads(4 * quads.size())
  {
    CGAL_precondition(4 * quads.size() <= (std::numeric_limits<std::uint32_t>::max)());
    for(const auto& q : quads)
      for(std::size_t v : q) ++m_offsets[v + 1];
    for(std::size_t v = 0; v < n_points; ++v) m_offsets[v + 1] += m_offsets[v];
    Array fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t q = 0; q < quads.size(); ++q)
      for(std::size_t v : quads[q]) m_quads[fill[v]++] = std::uint32_t(q);
  }

  Range operator[](std::size_t v) const
  {
    return Range{ m_quads.data() + m_offsets[v], m_quads.data() + m_offsets[v + 1] };
  }

private:
  // an entry per vertex or corner of a million-quad mesh, built twice a run: 2 MB pages
  typedef std::vector<std::uint32_t, Huge_page_allocator<std::uint32_t>> Array;
  Array m_offsets;
  Array m_quads;
};

/// the oriented boundary loops of a quad mesh whose boundary vertices all have two boundary
/// edges (the core after the clearance): each loop has the mesh on its left
/// (`quads_at`: the quads at each vertex)
inline std::vector<std::vector<std::size_t>>
mesh_boundary_cycles(const std::vector<std::array<std::size_t, 4>>& quads, const Vertex_quads& quads_at,
                     std::size_t n_points)
{
  // edge a -> b lies on the boundary if it is the only one of a -> b and b -> a; both are
  // edges of quads at a. Where several leave one vertex, the largest target wins (they cannot:
  // see the precondition).
  std::vector<std::size_t> next(n_points, std::size_t(-1));
  std::vector<std::array<std::size_t, 2>> around; // a's next and previous vertex in each quad at a
  for(std::size_t a = 0; a < n_points; ++a) {
    around.clear();
    for(std::size_t q : quads_at[a]) {
      int c = 0;
      while(quads[q][c] != a) ++c;
      around.push_back({ quads[q][(c + 1) % 4], quads[q][(c + 3) % 4] });
    }
    for(const auto& e : around) {
      const std::size_t b = e[0];
      std::size_t uses = 0;
      for(const auto& f : around) uses += (f[0] == b ? 1 : 0) + (f[1] == b ? 1 : 0);
      if(uses == 1 && (next[a] == std::size_t(-1) || b > next[a])) next[a] = b;
    }
  }
  std::vector<std::vector<std::size_t>> cycles;
  std::vector<bool> seen(n_points, false);
  for(std::size_t v = 0; v < n_points; ++v) {
    if(next[v] == std::size_t(-1) || seen[v]) continue;
    std::vector<std::size_t> c;
    for(std::size_t u = v; !seen[u]; u = next[u]) {
      seen[u] = true;
      c.push_back(u);
      if(next[u] == std::size_t(-1)) break;
    }
    cycles.push_back(std::move(c));
  }
  return cycles;
}

inline std::vector<std::vector<std::size_t>>
mesh_boundary_cycles(const std::vector<std::array<std::size_t, 4>>& quads, std::size_t n_points)
{
  return mesh_boundary_cycles(quads, Vertex_quads(quads, n_points), n_points);
}

/// the parameter in [0, 1] of the point of segment (a, b) nearest to p
inline double nearest_segment_parameter(const Point_2d& p, const Point_2d& a, const Point_2d& b)
{
  const Point_2d ab = minus_2d(b, a);
  const double len2 = dot_2d(ab, ab);
  const double t = len2 > 0 ? dot_2d(minus_2d(p, a), ab) / len2 : 0.0;
  return (std::min)(1.0, (std::max)(0.0, t));
}

/// a + t (b - a)
inline Point_2d along_2d(const Point_2d& a, const Point_2d& b, double t)
{
  return Point_2d{ a.x + t * (b.x - a.x), a.y + t * (b.y - a.y) };
}

inline double point_segment_distance(const Point_2d& p, const Point_2d& a, const Point_2d& b)
{
  return length_2d(minus_2d(p, along_2d(a, b, nearest_segment_parameter(p, a, b))));
}

/// Closest points on the domain's loops, in doubles (search only; new points on the boundary
/// are then constructed from a segment's end points in the kernel).
class Loop_locator
{
public:
  struct Hit
  {
    std::size_t loop = 0, edge = 0; // edge k joins loop vertex k to k+1
    double t = 0, dist = std::numeric_limits<double>::infinity();
    Point_2d point{0, 0};
  };

  Loop_locator(std::vector<std::vector<Point_2d>> loops) : m_loops(std::move(loops))
  {
    std::vector<Bbox_2>& boxes = m_boxes; // the box tree keeps a reference
    double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
    m_arc.resize(m_loops.size());
    for(std::size_t l = 0; l < m_loops.size(); ++l) {
      const auto& v = m_loops[l];
      m_arc[l].assign(v.size() + 1, 0.0);
      for(std::size_t k = 0; k < v.size(); ++k) {
        const Point_2d& a = v[k];
        const Point_2d& b = v[(k + 1) % v.size()];
        boxes.emplace_back((std::min)(a.x, b.x), (std::min)(a.y, b.y), (std::max)(a.x, b.x),
                           (std::max)(a.y, b.y));
        m_edge_of.push_back({l, k});
        m_arc[l][k + 1] = m_arc[l][k] + length_2d(minus_2d(b, a));
        xmin = (std::min)(xmin, a.x); xmax = (std::max)(xmax, a.x);
        ymin = (std::min)(ymin, a.y); ymax = (std::max)(ymax, a.y);
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

  /// the closest point to `p` on loop `l` (any loop if `l` is none), searching first within
  /// `radius` of `p`
  /// (with `other_than`: on any loop but `l`)
  Hit closest(const Point_2d& p, double radius, std::size_t l = none, bool other_than = false) const
  {
    Hit best;
    double r = (std::max)(radius, 1e-300);
    for(;;) {
      m_tree->query(Bbox_2(p.x - r, p.y - r, p.x + r, p.y + r), [&](std::size_t s) {
        if(l != none && (m_edge_of[s][0] != l) != other_than) return;
        Hit h = on_edge(p, m_edge_of[s][0], m_edge_of[s][1]);
        // equally near edges (a point on a symmetry axis) by their index, not by rounding:
        // the same choice on a scaled or moved domain
        const double tie = 1e-9 * m_diag;
        if(h.dist < best.dist - tie
           || (h.dist <= best.dist + tie && std::make_pair(h.loop, h.edge) < std::make_pair(best.loop, best.edge)))
          best = h;
      });
      if(best.dist <= r || r > 4 * m_diag + 1e-300) return best;
      r *= 4;
    }
  }

  /// the distance from segment (a, b) to the nearest loop edge, if below `radius` (else
  /// `radius` or more)
  double segment_distance(const Point_2d& a, const Point_2d& b, double radius) const
  {
    double best = HUGE_VAL;
    const double r = radius;
    Bbox_2 box((std::min)(a.x, b.x) - r, (std::min)(a.y, b.y) - r, (std::max)(a.x, b.x) + r,
               (std::max)(a.y, b.y) + r);
    m_tree->query(box, [&](std::size_t s) {
      const auto& v = m_loops[m_edge_of[s][0]];
      const std::size_t k = m_edge_of[s][1];
      best = (std::min)(best, segment_segment_distance(a, b, v[k], v[(k + 1) % v.size()]));
    });
    return best;
  }

  static constexpr std::size_t none = std::size_t(-1);

private:
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
    h.dist = length_2d(minus_2d(p, h.point));
    return h;
  }

  static double segment_segment_distance(const Point_2d& a, const Point_2d& b, const Point_2d& c,
                                         const Point_2d& d)
  {
    const double o1 = cross_2d(minus_2d(b, a), minus_2d(c, a)), o2 = cross_2d(minus_2d(b, a), minus_2d(d, a));
    const double o3 = cross_2d(minus_2d(d, c), minus_2d(a, c)), o4 = cross_2d(minus_2d(d, c), minus_2d(b, c));
    if(((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
      return 0;
    return (std::min)((std::min)(point_segment_distance(a, c, d), point_segment_distance(b, c, d)),
                      (std::min)(point_segment_distance(c, a, b), point_segment_distance(d, a, b)));
  }

  std::vector<std::vector<Point_2d>> m_loops;
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
  for(std::size_t l = 0; l < loops.loops.size(); ++l)
    for(std::size_t v : loops.loops[l].vertices)
      pts[l].push_back(to_point_2d(domain.points[v]));
  return std::make_unique<Loop_locator>(std::move(pts));
}

/// the angle (degrees, in [0, 360)) on the right of the path a -> b -> c, at b
inline double right_side_angle(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  const Point_2d t1 = minus_2d(b, a), t2 = minus_2d(c, b);
  const double turn = std::atan2(cross_2d(t1, t2), dot_2d(t1, t2)) * 180.0 / 3.14159265358979323846;
  return 180.0 + turn;
}

inline Point_2d normalized_2d(const Point_2d& v)
{
  const double l = length_2d(v);
  return l > 0 ? Point_2d{v.x / l, v.y / l} : Point_2d{0, 0};
}

/// the unit bisector of the angle on the right of a -> b -> c
inline Point_2d right_bisector(const Point_2d& a, const Point_2d& b, const Point_2d& c)
{
  const Point_2d t1 = normalized_2d(minus_2d(b, a)), t2 = normalized_2d(minus_2d(c, b));
  Point_2d s{t1.x + t2.x, t1.y + t2.y};
  if(length_2d(s) < 1e-9) // a spike: the bisector points back along the incoming edge
    return Point_2d{-t1.x, -t1.y};
  return normalized_2d(Point_2d{s.y, -s.x});
}

/// largest deviation of a quad's angles from 90 degrees; a large penalty if it is not strictly
/// convex and counter-clockwise
inline double quad_badness(const std::array<Point_2d, 4>& q)
{
  // at a convex corner |angle - 90| = asin(|cos angle|), increasing in |cos|: one asin for
  // the worst corner instead of an atan2 per corner (the buffer's inner loops call this)
  // edge k runs from corner k to corner k + 1; each length is taken once
  std::array<Point_2d, 4> e;
  std::array<double, 4> len;
  for(int k = 0; k < 4; ++k) {
    e[k] = minus_2d(q[(k + 1) % 4], q[k]);
    len[k] = length_2d(e[k]);
  }
  double worst_cos = 0;
  for(int c = 0; c < 4; ++c) {
    const Point_2d& in = e[(c + 3) % 4];
    const Point_2d& out = e[c];
    const double cr = cross_2d(in, out);
    const double l1 = len[c], l2 = len[(c + 3) % 4];
    if(!(cr > 1e-6 * l1 * l2) || l1 == 0 || l2 == 0) // flat corners count as invalid
      return 1000.0 + (cr < 0 ? 100.0 : 0.0);
    worst_cos = (std::max)(worst_cos, std::abs(dot_2d(out, in)) / (l1 * l2));
  }
  return std::asin((std::min)(worst_cos, 1.0)) * (180.0 / 3.14159265358979323846);
}

/// where the quadtree should be finer: points with the local size there
struct Refinement_requests
{
  /// where a finer quadtree would make the buffer valid
  std::vector<std::pair<Point_2d, double>> for_validity;
  /// where it would bring angles into [45, 135]
  std::vector<std::pair<Point_2d, double>> for_angles;
};

/// The buffer stages on a core mesh. The mesh's points are the core's; `local_size[v]` the
/// side of the largest quadtree cell at core vertex `v`.
template <class K>
class Buffer_layers
{
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Quad_mesh_2<Point_2> Mesh;
  typedef std::array<std::size_t, 4> Quad;

public:
  Buffer_layers(Mesh& mesh, const std::vector<double>& local_size, const Domain_2<K>& domain,
                const Domain_loops_2<K>& loops, const K& traits)
    : m_mesh(mesh), m_size(local_size), m_domain(domain), m_loops(loops), m_traits(traits)
  {
    m_locator = make_loop_locator(domain, loops);
    m_chord_tolerance = 1e-3 * m_locator->diagonal();
    m_xy.reserve(mesh.points.capacity()); // the room the clearance left for the layers' points
    m_xy.resize(mesh.points.size());
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      m_xy[v] = to_point_2d(mesh.points[v]);
    m_core_points = mesh.points.size();
  }

  const Buffer_report& report() const { return m_report; }
  const Refinement_requests& requests() const { return m_requests; }

  /// Matches the core's boundary loops with the domain's; false (with `report().failure` and
  /// refinement requests) if they do not match one to one.
  bool match_loops()
  {
    m_quads_at = std::make_unique<Vertex_quads>(m_mesh.quads, m_mesh.points.size());
    m_cycles = mesh_boundary_cycles(m_mesh.quads, *m_quads_at, m_mesh.points.size());
    // The layers add a few quads and points per core boundary vertex (about two each on a
    // disc): room for four each now (the clearance's core has it already), or the first one
    // added copies the whole core's arrays into fresh memory.
    std::size_t boundary_vertices = 0;
    for(const auto& cyc : m_cycles)
      boundary_vertices += cyc.size();
    m_mesh.quads.reserve(m_mesh.quads.size() + 4 * boundary_vertices);
    m_mesh.points.reserve(m_mesh.points.size() + 4 * boundary_vertices);
    m_xy.reserve(m_xy.size() + 4 * boundary_vertices);
    m_cycle_loop.assign(m_cycles.size(), none);
    m_on_cycle.assign(m_mesh.points.size(), 0);
    std::vector<std::size_t> owner(m_loops.loops.size(), none);
    bool ok = true;
    for(std::size_t c = 0; c < m_cycles.size(); ++c) {
      std::vector<std::size_t> votes(m_loops.loops.size(), 0);
      for(std::size_t v : m_cycles[c])
        ++votes[m_locator->closest(m_xy[v], 2 * m_size[v]).loop];
      const std::size_t l = std::size_t(std::max_element(votes.begin(), votes.end()) - votes.begin());
      const bool same_turn = (cycle_area(c) > 0) == m_loops.loops[l].is_outer;
      if(owner[l] != none || !same_turn || 2 * votes[l] <= m_cycles[c].size()) {
        ok = false;
        // the smaller of two cycles following one loop is a piece of core cut off by a
        // narrow passage: refine along it
        std::size_t cut = c;
        if(owner[l] != none && m_cycles[owner[l]].size() < m_cycles[c].size()) std::swap(cut, owner[l]);
        request_all(cut);
        m_report.failure = "the core mesh's boundary does not follow the domain's loops one to one";
        continue;
      }
      owner[l] = c;
      m_cycle_loop[c] = l;
      for(std::size_t v : m_cycles[c]) m_on_cycle[v] = 1;
    }
    for(std::size_t l = 0; l < owner.size(); ++l)
      if(owner[l] == none) {
        ok = false;
        m_report.failure = "no core mesh is left near loop " + std::to_string(l)
                           + " of the domain: its cells are too coarse";
        // cells a quarter of its gap to the other loops, on it and halfway across the gap
        for(const Point_2d& p : m_locator->loop(l)) {
          const Loop_locator::Hit h = m_locator->closest(p, 1e-6 * m_locator->diagonal(), l, true);
          const double size = std::isfinite(h.dist) ? 0.25 * h.dist : 0.0;
          m_requests.for_validity.emplace_back(p, 2 * size);
          if(size > 0)
            m_requests.for_validity.emplace_back(Point_2d{ 0.5 * (p.x + h.point.x), 0.5 * (p.y + h.point.y) }, 2 * size);
        }
      }
    return ok;
  }

  /// Stage "templates": moves core boundary vertices (and interior ones, but `fixed_points`,
  /// a domain's isolated points) so that their buffer-side angles meet Lemma 2 where the core
  /// allows (see the file comment).
  void apply_boundary_templates(const std::vector<std::size_t>& fixed_points)
  {
    CGAL_precondition(m_quads_at != nullptr);
    m_fixed.assign(m_mesh.points.size(), 0);
    for(std::size_t v : fixed_points) if(v < m_fixed.size()) m_fixed[v] = 1;
    m_shaped.assign(m_mesh.points.size(), 0);
    const Vertex_quads& quads_at = *m_quads_at;
    std::vector<char> adaptive(m_mesh.points.size(), 0);
    for(const auto& cyc : m_cycles)
      for(std::size_t b : cyc)
        adaptive[b] = !on_square_lattice(b, quads_at);
    m_cleared_xy = m_xy;
    for(Template_pass pass : { ADAPTIVE, CORNERS, NOTCHES, NEIGHBOURS })
      for(int round = 0; round < 3; ++round) {
        bool changed = false;
        for(const auto& cyc : m_cycles) {
          const std::size_t n = cyc.size();
          for(std::size_t i = 0; i < n; ++i)
            if((pass != ADAPTIVE || adaptive[cyc[i]])
               && try_move_boundary_vertex(cyc[(i + n - 2) % n], cyc[(i + n - 1) % n], cyc[i],
                                           cyc[(i + 1) % n], cyc[(i + 2) % n], pass, quads_at))
              changed = true;
        }
        if(!changed) break;
      }
    search_boundary_vertices(quads_at);
    m_quads_at.reset(); // the later stages add quads
  }

  /// Stage "templates", after apply_boundary_templates(): a new core quad over each notch that could not
  /// move (see fill_notch()), then the vertices about them searched again.
  void apply_connectivity_templates()
  {
    const std::size_t changed = m_report.filled_notches + m_report.split_corners;
    for(std::size_t c = 0; c < m_cycles.size(); ++c)
      for(std::size_t i = 0; i < m_cycles[c].size(); ++i)
        fill_notch(c, i);
    {
      std::optional<Vertex_quads> quads_at; // made for the first corner over 225 degrees, if any
      std::size_t known = 0;
      std::vector<char> split;
      for(std::size_t c = 0; c < m_cycles.size(); ++c)
        for(std::size_t i = 0; i < m_cycles[c].size(); ++i)
          if(split_corner(c, i, quads_at, known, split)) ++i; // past the corner, now between its new points
    }
    if(m_report.filled_notches + m_report.split_corners > changed)
      search_boundary_vertices(Vertex_quads(m_mesh.quads, m_mesh.points.size()));
    m_cleared_xy = std::vector<Point_2d>();
    count_lemma_2_misses();
  }

  // The templates' result against Lemma 2: the core boundary vertices whose buffer-side
  // angle is outside [112.5, 225] by more than rounding, and those of them not within 2h of an
  // input corner (whose buffer is the corner's, §5).
  void count_lemma_2_misses()
  {
    m_report.buffer_angles_out = m_report.buffer_angles_out_away_from_corners = 0;
    for(const auto& cyc : m_cycles) {
      const std::size_t n = cyc.size();
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t a = cyc[(i + n - 1) % n], b = cyc[i], c = cyc[(i + 1) % n];
        if(buffer_angle_excess(right_side_angle(m_xy[a], m_xy[b], m_xy[c])) > rounding_tolerance(a, b, c)) {
          ++m_report.buffer_angles_out;
          if(!near_input_corner(b)) ++m_report.buffer_angles_out_away_from_corners;
        }
      }
    }
  }

  /// Stage "buffer1": the first buffer points and the quads B_i F_i F_{i+1} B_{i+1}.
  void build_first_layer()
  {
    m_layer_begin[0] = m_mesh.quads.size();
    m_first.assign(m_cycles.size(), {});
    for(std::size_t c = 0; c < m_cycles.size(); ++c) {
      const auto& cyc = m_cycles[c];
      const std::size_t n = cyc.size(), l = m_cycle_loop[c];
      auto& F = m_first[c];
      F.resize(n);
      for(std::size_t i = 0; i < n; ++i) {
        const Point_2d& a = m_xy[cyc[(i + n - 1) % n]];
        const Point_2d& b = m_xy[cyc[i]];
        const Point_2d& nb = m_xy[cyc[(i + 1) % n]];
        const Loop_locator::Hit h = m_locator->closest(b, 2 * m_size[cyc[i]], l);
        const Point_2d toward = normalized_2d(minus_2d(h.point, b));
        // halfway between the bisector of beta and the direction to the nearest boundary
        // point: bisectors alone converge in the core's notches and cross
        const Point_2d bis = right_bisector(a, b, nb);
        Point_2d d = normalized_2d(Point_2d{ 0.5 * (bis.x + toward.x), 0.5 * (bis.y + toward.y) });
        // but no farther from the bisector than leaves B's two first-layer angles, beta / 2
        // plus and minus the deviation, within [45, 135] with a fifth to spare (Lemma 3: the
        // nearest boundary point across a narrow channel turned a tongue tip's F point until
        // its quad had 164 degrees at B). A notch of 90 degrees or less (beside a sharp
        // corner, where Lemma 2 failed) has no such room: on its bisector alone its F point
        // and its neighbours' crossed (the guitar's (11.53, 7.93)).
        const double beta = right_side_angle(a, b, nb) * pi / 180;
        const double limit = 0.8 * (std::min)(beta / 2 - pi / 4, 3 * pi / 4 - beta / 2);
        const double dev = std::atan2(cross_2d(bis, d), dot_2d(bis, d));
        if(limit > 0 && std::abs(dev) > limit) {
          const double t = dev > 0 ? limit : -limit;
          d = turned_2d(bis, t);
        }
        const double c_dn = (std::max)(dot_2d(d, toward), 0.5);
        const double lambda = 0.5 * h.dist / c_dn;
        F[i] = Point_2d{b.x + lambda * d.x, b.y + lambda * d.y};
      }
      smooth_first_points(c);
      const std::size_t base = m_mesh.points.size();
      for(std::size_t i = 0; i < n; ++i) {
        add_point(F[i]);
        m_f_core.push_back(cyc[i]);
      }
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        add_quad({cyc[i], base + i, base + j, cyc[j]});
      }
      m_first_base.push_back(base);
      m_first_built = true;
      m_report.first_layer_quads += n;
    }
  }

  // The first buffer points of cycle c, moved one at a time to improve the two layers they
  // will bound: their quads B_i F_i F_{i+1} B_{i+1} and the projection quads
  // F_i G_i G_{i+1} F_{i+1}, G the nearest boundary point (Lemmas 3 and 4 ask that the F
  // chain run nearly parallel to the boundary, so that the projections make right angles).
  // A move is kept if it lowers (invalid quads, quads outside [45, 135], worst deviation from
  // 90 degrees, sum of squared deviations) of the four quads at F_i; F_i stays within half
  // its distance from B_i of where it started, so it cannot wander across the buffer, and
  // does not move within twice the local size of a loop corner.
  void smooth_first_points(std::size_t c)
  {
    const auto& cyc = m_cycles[c];
    const std::size_t n = cyc.size(), l = m_cycle_loop[c];
    auto& F = m_first[c];
    if(n < 3) return;
    const std::vector<Point_2d> start = F;
    std::vector<double> reach(n);
    std::vector<Point_2d> G(n);
    const auto& loop_xy = m_locator->loop(l);
    const std::size_t nv = loop_xy.size();
    for(std::size_t i = 0; i < n; ++i) {
      const Loop_locator::Hit hit = m_locator->closest(F[i], 2 * m_size[cyc[i]], l);
      G[i] = hit.point;
      reach[i] = 0.5 * length_2d(minus_2d(F[i], m_xy[cyc[i]]));
      // near a corner the strip fans and its nodes are not the projections: F stays put
      const double near = 2 * m_size[cyc[i]];
      for(std::size_t step : { nv - 1, std::size_t(1) }) // backwards from the edge's start, forwards from its end
        for(std::size_t k = step == 1 ? (hit.edge + 1) % nv : hit.edge, walked = 0;
            reach[i] > 0 && walked < nv && length_2d(minus_2d(loop_xy[k], hit.point)) <= near;
            k = (k + step) % nv, ++walked)
          if(is_feature(l, k)) reach[i] = 0;
    }
    struct Local
    {
      int invalid = 0, out = 0;
      double worst = 0, sum = 0;
      bool operator<(const Local& o) const
      {
        if(invalid != o.invalid) return invalid < o.invalid;
        if(out != o.out) return out < o.out;
        if(worst < o.worst - angle_tolerance) return true;
        if(worst > o.worst + angle_tolerance) return false;
        return sum < o.sum - angle_tolerance * (1 + o.sum);
      }
      void add(double b)
      {
        if(b >= 1000.0) ++invalid;
        else if(b > 45.0 + angle_tolerance) ++out;
        worst = (std::max)(worst, b);
        sum += b * b;
      }
    };
    // F_i at f, its boundary point from g_at(f) (asked only when needed). With `bound`, stops
    // once the result cannot be below it: each quad only adds.
    auto local = [&](std::size_t i, const Point_2d& f, auto&& g_at, const Local* bound) {
      const std::size_t p = (i + n - 1) % n, q = (i + 1) % n;
      Local r;
      auto add = [&](const std::array<Point_2d, 4>& quad) {
        r.add(quad_badness(quad));
        return bound == nullptr || r < *bound;
      };
      if(!add({ m_xy[cyc[p]], F[p], f, m_xy[cyc[i]] }) || !add({ m_xy[cyc[i]], f, F[q], m_xy[cyc[q]] }))
        return r;
      const Point_2d g = g_at(f);
      if(add({ F[p], G[p], g, f }))
        add({ f, g, G[q], F[q] });
      return r;
    };
    // the eight directions the tries step in, and the tries, made once
    std::array<Point_2d, 8> direction;
    for(int k = 0; k < 8; ++k) {
      const double a = k * pi / 4;
      direction[k] = Point_2d{ std::cos(a), std::sin(a) };
    }
    std::vector<Point_2d> tries;
    for(int pass = 0; pass < 8; ++pass) {
      bool moved = false;
      for(std::size_t i = 0; i < n; ++i) {
        if(reach[i] == 0) continue;
        Local best = local(i, F[i], [&](const Point_2d&) { return G[i]; }, nullptr);
        if(best.invalid == 0 && best.out == 0 && best.worst <= 20.0) continue;
        const double h = m_size[cyc[i]];
        Point_2d best_f = F[i], best_g = G[i];
        const Point_2d mid{ 0.5 * (F[(i + n - 1) % n].x + F[(i + 1) % n].x),
                            0.5 * (F[(i + n - 1) % n].y + F[(i + 1) % n].y) };
        tries.clear();
        for(double s : { 1.0, 0.5, 0.25 })
          tries.push_back(Point_2d{ F[i].x + s * (mid.x - F[i].x), F[i].y + s * (mid.y - F[i].y) });
        for(double s : { 0.2, 0.1, 0.05 })
          for(const Point_2d& d : direction)
            tries.push_back(Point_2d{ F[i].x + s * h * d.x, F[i].y + s * h * d.y });
        for(const Point_2d& f : tries) {
          if(length_2d(minus_2d(f, start[i])) > reach[i]) continue;
          Point_2d g{ 0, 0 };
          auto boundary_point = [&](const Point_2d& at) { return g = m_locator->closest(at, 2 * h, l).point; };
          const Local r = local(i, f, boundary_point, &best);
          if(r < best) { best = r; best_f = f; best_g = g; }
        }
        if(best_f.x != F[i].x || best_f.y != F[i].y) {
          F[i] = best_f;
          G[i] = best_g;
          moved = true;
        }
      }
      if(!moved) break;
    }
  }

  /// Stage "buffer2": the strip between the first buffer points and the boundary.
  void build_second_layer()
  {
    m_layer_begin[1] = m_mesh.quads.size();
    for(std::size_t c = 0; c < m_cycles.size(); ++c)
      build_strip(c);
  }

  /// Checks every quad the buffer stages made or changed with exact predicates and counts
  /// those with an angle outside [45, 135] that no sharp input corner forces; records
  /// refinement requests at both.
  void check_quads()
  {
    for(std::size_t q = 0; q < m_mesh.quads.size(); ++q) {
      const Quad& Q = m_mesh.quads[q];
      if(!made_or_changed(Q)) continue;
      const bool valid = is_valid_quad(Q);
      std::array<Point_2d, 4> P;
      for(int c = 0; c < 4; ++c) P[c] = m_xy[Q[c]];
      bool bad_angle = false;
      if(valid) {
        std::array<double, 4> a;
        for(int c = 0; c < 4; ++c) a[c] = corner_angle_degrees(P[(c + 3) % 4], P[c], P[(c + 1) % 4]);
        // a quad spanning a corner alpha under 45 degrees may have angles in [alpha, 180 - alpha]
        double lo = 45.0;
        for(int c = 0; c < 4; ++c)
          if(forced_angle(Q[c], a[c])) lo = (std::min)(lo, input_corner_angle(Q[c]));
        for(int c = 0; c < 4; ++c)
          if((a[c] < lo - verifier_slack || a[c] > 180.0 - lo + verifier_slack) && !forced_angle(Q[c], a[c]))
            bad_angle = true;
      }
      if(!valid) ++m_report.invalid_quads;
      if(bad_angle) {
        ++m_report.bad_angle_quads;
        ++m_report.bad_angle_quads_by_layer[q < m_layer_begin[0] ? 0 : q < m_layer_begin[1] ? 1 : 2];
      }
      if(!valid || bad_angle) {
        auto& requests = valid ? m_requests.for_angles : m_requests.for_validity;
        double size = HUGE_VAL; // of the finest cells the quad hangs from
        for(int c = 0; c < 4; ++c)
          if(Q[c] < m_core_points) {
            requests.emplace_back(m_xy[Q[c]], m_size[Q[c]]);
            size = (std::min)(size, m_size[Q[c]]);
          }
        for(int c = 0; c < 4; ++c)
          if(Q[c] >= m_core_points && Q[c] - m_core_points < m_f_core.size()) {
            const std::size_t b = m_f_core[Q[c] - m_core_points];
            requests.emplace_back(m_xy[b], m_size[b]);
            size = (std::min)(size, m_size[b]);
          }
        // not for an invalid quad: a broken buffer's quads can span tens of cells each, and
        // their corners' cells suffice (a disc with thin elliptic holes asked for 1.8 million)
        if(valid) request_over_area(P, size, requests);
      }
    }
  }

  // A buffer quad is about as large as the cells it hangs from. One far larger spans a stretch
  // the core does not reach: the clearance peeled a strip one cell thick from its dead end (an
  // arm 0.13 wide turned 45.37 degrees, whose cells had 4.2 per width, lost its core for 0.3
  // of its length, and refining at the quad's corners never brought it back). Requests at
  // cells' spacing over the quad's box bring the core there.
  void request_over_area(const std::array<Point_2d, 4>& P, double size,
                         std::vector<std::pair<Point_2d, double>>& requests) const
  {
    if(!(size > 0) || !std::isfinite(size)) return;
    double x0 = P[0].x, x1 = P[0].x, y0 = P[0].y, y1 = P[0].y;
    for(const Point_2d& p : P) {
      x0 = (std::min)(x0, p.x); x1 = (std::max)(x1, p.x);
      y0 = (std::min)(y0, p.y); y1 = (std::max)(y1, p.y);
    }
    // a cell's few times: the corners' requests suffice; and at most 64 requests a quad
    const double span = (std::max)(x1 - x0, y1 - y0);
    if(span <= 4 * size) return;
    const double step = (std::max)(size, span / 8);
    for(double x = x0 + step / 2; x < x1; x += step)
      for(double y = y0 + step / 2; y < y1; y += step)
        requests.emplace_back(Point_2d{ x, y }, size);
  }

  // strictly convex and counter-clockwise by the kernel's predicate, and no corner nearly flat
  // (the quality check rejects those)
  bool is_valid_quad(const Quad& Q) const
  {
    auto orient = m_traits.orientation_2_object();
    for(int c = 0; c < 4; ++c)
      if(orient(m_mesh.points[Q[c]], m_mesh.points[Q[(c + 1) % 4]], m_mesh.points[Q[(c + 2) % 4]]) != CGAL::LEFT_TURN)
        return false;
    for(int c = 0; c < 4; ++c)
      if(!(corner_scaled_jacobian(m_xy[Q[(c + 3) % 4]], m_xy[Q[c]], m_xy[Q[(c + 1) % 4]]) > 1e-9))
        return false;
    return true;
  }

  /// Drops the points no quad uses (boundary nodes the pairing took out again); returns the
  /// new index of every old point (`none` for a dropped one).
  std::vector<std::size_t> remove_unused_points()
  {
    std::vector<std::size_t> index(m_mesh.points.size(), none);
    for(const Quad& q : m_mesh.quads)
      for(std::size_t v : q) index[v] = 0;
    std::size_t next = 0;
    for(std::size_t v = 0; v < index.size(); ++v)
      if(index[v] == 0) {
        m_mesh.points[next] = m_mesh.points[v];
        index[v] = next++;
      }
    m_mesh.points.resize(next);
    for(Quad& q : m_mesh.quads)
      for(std::size_t& v : q) v = index[v];
    return index;
  }

  /// Local min-max angle optimisation of the buffer: the first buffer points move freely, the
  /// new boundary points slide along their input edge, the core's boundary vertices move too;
  /// a move is kept only if it lowers the largest deviation from 90° of the quads around the
  /// vertex and keeps them convex and unfolded. Then, around each quad still outside
  /// [45°, 135°], the core vertices within two quads of it may move too. Input vertices and
  /// `fixed_points` (a domain's isolated points) never move.
  // `targets`: for each quad at v, where v would make it a parallelogram (the corners beside v
  // plus one side); returns the mean of those corners, v's neighbours (a Laplacian step)
  Point_2d parallelogram_targets(std::size_t v, const Vertex_quads& quads_at, std::vector<Point_2d>& targets) const
  {
    targets.clear();
    Point_2d lap{0, 0};
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = m_mesh.quads[q];
      const int c = corner_of(Q, v);
      const Point_2d& prev = m_xy[Q[(c + 3) % 4]];
      const Point_2d& next = m_xy[Q[(c + 1) % 4]];
      const Point_2d& opp = m_xy[Q[(c + 2) % 4]];
      targets.push_back(Point_2d{prev.x + next.x - opp.x, prev.y + next.y - opp.y});
      lap.x += prev.x + next.x; lap.y += prev.y + next.y;
    }
    const int corners = 2 * int(quads_at[v].size());
    lap.x /= corners; lap.y /= corners;
    return lap;
  }

  void optimize(const std::vector<std::size_t>& fixed_points, int passes = 12)
  {
    const Vertex_quads quads_at(m_mesh.quads, m_mesh.points.size());
    std::vector<std::size_t> movable;
    for(const auto& cyc : m_cycles)
      movable.insert(movable.end(), cyc.begin(), cyc.end());
    for(std::size_t v = m_core_points; v < m_mesh.points.size(); ++v)
      if(!is_input_vertex(v))
        movable.push_back(v);
    // (invalid quads around v, quads outside [45, 135] around it, the worst deviation from
    // 90 degrees), compared in this order: no move may make a quad invalid. A move must lower
    // the worst by more than rounding: 1e-9 degrees is within it on small cells far from the
    // origin, where moves that gain nothing made a translated domain's mesh differ.
    struct Local
    {
      int invalid = 0, out = 0;
      double worst = 0;
      bool operator<(const Local& o) const
      {
        if(invalid != o.invalid) return invalid < o.invalid;
        if(out != o.out) return out < o.out;
        return worst < o.worst - angle_tolerance;
      }
    };
    // above the whole-mesh check's merge distance (1e-9 of the diagonal), and well below the
    // edges of the finest cells, so that a domain's smallest features keep room to move
    double finest = HUGE_VAL;
    for(double h : m_size)
      if(h > 0) finest = (std::min)(finest, h);
    const double min_edge = (std::max)(2e-9 * m_locator->diagonal(),
                                       (std::min)(1e-8 * m_locator->diagonal(), finest / 4));
    const double min_edge2 = min_edge * min_edge;
    // With `bound`, the caller keeps the result only if it is below *bound: every quad only adds
    // to the cost, so the sum stops as soon as it cannot be (same decisions, far fewer quads).
    auto local_cost = [&](std::size_t v, const Local* bound) {
      Local r;
      for(std::size_t q : quads_at[v]) {
        const double b = cost(m_mesh.quads[q]);
        r.worst = (std::max)(r.worst, b);
        if(b >= 1000.0) ++r.invalid;
        else if(b > 45.0 + angle_tolerance) ++r.out;
        const Quad& Q = m_mesh.quads[q];
        const int c = corner_of(Q, v);
        // an edge collapsing to a point keeps the angles fine but merges two vertices: the
        // whole-mesh check rejects vertices within 1e-9 of the diagonal
        for(int side : { 1, 3 }) {
          const Point_2d d = minus_2d(m_xy[Q[(c + side) % 4]], m_xy[v]);
          if(dot_2d(d, d) <= min_edge2) ++r.invalid;
        }
        if(bound != nullptr && !(r < *bound)) return r;
      }
      const double expected = m_slide.count(v) ? 180.0 : (is_core_boundary(v) ? -1 : 360.0);
      if(expected > 0) {
        double angle_sum = 0;
        for(std::size_t q : quads_at[v]) {
          const Quad& Q = m_mesh.quads[q];
          const int c = corner_of(Q, v);
          angle_sum += corner_angle_degrees(m_xy[Q[(c + 3) % 4]], m_xy[v], m_xy[Q[(c + 1) % 4]]);
        }
        if(std::abs(angle_sum - expected) > 1e-6)
          r.invalid += 1 << 20; // folded
      }
      return r;
    };
    // a vertex whose quads have not changed since it was last tried would not move: only
    // vertices sharing a quad with a moved one are tried again (same result, far fewer tries)
    std::vector<char> dirty(m_mesh.points.size(), 1), dirty_next(m_mesh.points.size(), 0);
    std::vector<Point_2d> targets;
    auto run_passes = [&](const std::vector<std::size_t>& vertices) {
      for(int pass = 0; pass < passes; ++pass) {
        bool improved = false;
        for(std::size_t v : vertices) {
          if(!dirty[v]) continue;
          const Local current = local_cost(v, nullptr);
          if(current.worst <= 30.0) continue; // within [60, 120]: good enough
          const Point_2d old = m_xy[v];
          targets.push_back(parallelogram_targets(v, quads_at, targets));
          add_turns_about_corners(v, quads_at, targets);
          Point_2d mean{0, 0};
          for(std::size_t k = 0; k + 1 < targets.size(); ++k) { mean.x += targets[k].x; mean.y += targets[k].y; }
          mean.x /= double(targets.size() - 1); mean.y /= double(targets.size() - 1);
          targets.push_back(mean);
          Local best = current;
          Point_2d best_p = old;
          for(const Point_2d& t : targets)
            for(double step : { 1.0, 0.5, 0.25, 0.1 }) {
              Point_2d p{old.x + step * (t.x - old.x), old.y + step * (t.y - old.y)};
              if(!slide_to(v, p)) continue;
              m_xy[v] = p;
              const Local c = local_cost(v, &best);
              m_xy[v] = old;
              if(c < best) {
                best = c;
                best_p = p;
              }
            }
          if(best_p.x != old.x || best_p.y != old.y) {
            m_xy[v] = best_p;
            improved = true;
            for(std::size_t q : quads_at[v])
              for(std::size_t w : m_mesh.quads[q])
                dirty[w] = dirty_next[w] = 1;
          }
        }
        if(!improved) break;
        dirty.swap(dirty_next);
        std::fill(dirty_next.begin(), dirty_next.end(), 0);
      }
    };
    run_passes(movable);
    // A quad still outside [45, 135] (often just: a core quad beside a moved notch) may be
    // mended by moving the core vertices within two quads of it too: the core keeps its
    // connectivity, and no move may put one of its angles out of range.
    auto ring = [&](const std::vector<std::size_t>& from) { // the vertices of their quads
      std::vector<std::size_t> out;
      for(std::size_t u : from)
        for(std::size_t q : quads_at[u])
          out.insert(out.end(), m_mesh.quads[q].begin(), m_mesh.quads[q].end());
      std::sort(out.begin(), out.end());
      out.erase(std::unique(out.begin(), out.end()), out.end());
      return out;
    };
    std::vector<std::size_t> near_bad;
    for(const Quad& q : m_mesh.quads) {
      const double b = made_or_changed(q) ? cost(q) : 0.0;
      if(b > 45.0 + angle_tolerance && b < 1000.0) near_bad.insert(near_bad.end(), q.begin(), q.end());
    }
    near_bad = ring(ring(near_bad));
    std::vector<char> fixed(m_mesh.points.size(), 0);
    for(std::size_t v : fixed_points) if(v < fixed.size()) fixed[v] = 1;
    near_bad.erase(std::remove_if(near_bad.begin(), near_bad.end(), [&](std::size_t x) {
                     return x >= m_core_points || on_cycle(x) || is_input_vertex(x) || fixed[x];
                   }), near_bad.end());
    std::vector<Point_2d> before(near_bad.size());
    for(std::size_t k = 0; k < near_bad.size(); ++k) before[k] = m_xy[near_bad[k]];
    if(!near_bad.empty()) {
      std::vector<std::size_t> all = near_bad;
      all.insert(all.end(), movable.begin(), movable.end());
      // the first passes left every clean vertex where a try would leave it again: only the
      // repair's own vertices join the dirty ones (same moves, far fewer tries)
      for(std::size_t v : near_bad) dirty[v] = 1;
      run_passes(all);
    }
    write_back(movable);
    std::vector<std::size_t> moved;
    std::vector<Point_2d> moved_from;
    std::vector<Point_2> exact_before; // for undoing: the core's points are not all doubles
    for(std::size_t k = 0; k < near_bad.size(); ++k)
      if(m_xy[near_bad[k]].x != before[k].x || m_xy[near_bad[k]].y != before[k].y) {
        moved.push_back(near_bad[k]);
        moved_from.push_back(before[k]);
        exact_before.push_back(m_mesh.points[near_bad[k]]);
      }
    write_back(moved);
    // the kernel's predicates have the last word: a core quad the repair moves left nearly flat
    // or not strictly convex undoes them all
    bool valid = true;
    for(std::size_t v : moved)
      for(std::size_t q : quads_at[v]) valid = valid && is_valid_quad(m_mesh.quads[q]);
    m_repaired.assign(m_mesh.points.size(), 0);
    for(std::size_t k = 0; k < moved.size(); ++k) {
      if(valid) {
        m_repaired[moved[k]] = 1; // check_quads() looks at its quads too
      } else {
        m_xy[moved[k]] = moved_from[k];
        m_mesh.points[moved[k]] = exact_before[k];
      }
    }
  }

private:
  // how far a buffer-side angle lies outside [112.5, 225], the range the paper's templates
  // leave (Lemma 2): there the first layer's two quads at the vertex split it within [45, 135]
  static double buffer_angle_excess(double beta)
  {
    return (std::max)(0.0, beta - 225.0) + (std::max)(0.0, 112.5 - beta);
  }
  // how far the angle at b (between a and c) may be off by the rounding of their coordinates
  // to doubles, in degrees, and at least angle_tolerance: far from the origin a double holds
  // few digits of a small domain's edges (a disc 1e-4 across at 1e5: kites of exactly 225
  // degrees came out 6e-4 over, and were split as if jammed)
  double rounding_tolerance(std::size_t a, std::size_t b, std::size_t c) const
  {
    double scale = 0;
    for(std::size_t v : { a, b, c }) scale = (std::max)({ scale, std::abs(m_xy[v].x), std::abs(m_xy[v].y) });
    const double edge = (std::min)(length_2d(minus_2d(m_xy[a], m_xy[b])), length_2d(minus_2d(m_xy[c], m_xy[b])));
    return (std::max)(angle_tolerance, 64 * std::numeric_limits<double>::epsilon() * scale / edge * 180 / pi);
  }
  // the largest buffer_angle_excess() of the three buffer-side angles at a, b and c, which
  // are consecutive on a core cycle between a2 and c2 (what a template step at b changes)
  double worst_buffer_angle_excess(const Point_2d& a2, const Point_2d& a, const Point_2d& b,
                                   const Point_2d& c, const Point_2d& c2) const
  {
    return (std::max)({ buffer_angle_excess(right_side_angle(a2, a, b)),
                        buffer_angle_excess(right_side_angle(a, b, c)),
                        buffer_angle_excess(right_side_angle(b, c, c2)) });
  }

  // A notch (buffer-side angle under 112.5 degrees) that apply_boundary_templates() left cannot move: a
  // core angle of 45 degrees at it (the centre of a cell's template, or a transition
  // template's corner) would go below. Its two first-layer quads would split 90 degrees, 45
  // each at best (Lake Superior's (0.8877, -0.6432): 44.9). A new core quad B A Y C over it,
  // Y on the bisector (paper §4.4: templates also fill the buffer with new quads), takes B off
  // the boundary: with Y where the quad has a little under 135 degrees, A and C lose about
  // 67.5 degrees of buffer side each and Y has about 225, the angles template 1(a) gives by
  // moving B there. Kept if the quad is within [45, 135], its new edges keep the clearance,
  // and the buffer-side angles at A, Y and C come nearer [112.5, 225] than before.
  // Within 2h of an input corner only notches under 95 degrees are filled: from there the
  // first layer splits beta in two quads over 45 degrees each, and a new quad over such a notch
  // (100 to 112 degrees, most of them transition templates) changed the strip's pairing for
  // the worse (airfoil_3elem_jigsaw's (0.5, 0.906): a sheared ladder at the nearby corner).
  // Away from corners every notch is (the guitar's 99.7 degrees at (35.28, 6.18)). Nor is a notch
  // that faces a corner needing a fan of three (its nearest boundary point is that corner): the
  // notch is the fan's room, and filling it left the fan's quads squeezed (the 30P30N main
  // element's trailing edge, bird's tip).
  void fill_notch(std::size_t c, std::size_t i)
  {
    auto& cyc = m_cycles[c];
    const std::size_t n = cyc.size();
    const std::size_t a2 = cyc[(i + n - 2) % n], a = cyc[(i + n - 1) % n], b = cyc[i];
    const std::size_t c1 = cyc[(i + 1) % n], c2 = cyc[(i + 2) % n];
    const double beta = right_side_angle(m_xy[a], m_xy[b], m_xy[c1]);
    if(beta >= 112.5 - angle_tolerance || (beta >= 95.0 && near_input_corner(b))) return;
    {
      const Loop_locator::Hit h = m_locator->closest(m_xy[b], 2 * m_size[b]);
      const std::size_t nv = m_locator->loop(h.loop).size();
      if((h.t <= 0 && needs_fan_of_three(h.loop, h.edge))
         || (h.t >= 1 && needs_fan_of_three(h.loop, (h.edge + 1) % nv)))
        return;
    }
    // the worst first: a filled notch is off the boundary, and Y has its own angle (a
    // lattice notch at 90 degrees beside a corner at 270 leaves two just out, far nearer)
    auto excess = [&](const Point_2d& y) { return buffer_angle_excesses(m_xy[a2], m_xy[a], y, m_xy[c1], m_xy[c2], false); };
    const Point_2d d = right_bisector(m_xy[a], m_xy[b], m_xy[c1]);
    const double s = 0.5 * (length_2d(minus_2d(m_xy[a], m_xy[b])) + length_2d(minus_2d(m_xy[c1], m_xy[b])));
    const double clear = 0.25 * m_size[b];
    // a candidate must gain more than rounding: the choice is the same on a scaled domain
    double best = excess(m_xy[b]);
    Point_2d best_y{ 0, 0 };
    bool found = false;
    auto consider = [&](const Point_2d& y) {
      const double after = excess(y);
      if(!(after < best - angle_tolerance / 10) || quad_badness({ m_xy[b], m_xy[a], y, m_xy[c1] }) > 45.0 + core_slack
         || !(m_locator->segment_distance(m_xy[a], y, clear) > clear) || !(m_locator->segment_distance(y, m_xy[c1], clear) > clear))
        return false;
      best = after;
      best_y = y;
      found = true;
      return true;
    };
    // |BY| = 1.01 s: at s (template 1(a)'s 0.71 s diagonal) a lattice notch's quad has exactly
    // 135 degrees at Y, in or out by rounding, and the runs of a scaled domain differed
    for(double f : { 1.01, 1.1, 0.9, 1.2, 0.8 })
      consider(Point_2d{ m_xy[b].x + f * s * d.x, m_xy[b].y + f * s * d.y });
    // Beside an adaptive core the quad's other corners are not a lattice notch's: Y then
    // needs to lie off the bisector (a pattern search as for a vertex, search_boundary_vertex())
    // f s from b, turned by k 15 degrees from the bisector
    auto off_bisector = [&](double f, int k) {
      const Point_2d u = turned_2d(d, k * pi / 12);
      return Point_2d{ m_xy[b].x + f * s * u.x, m_xy[b].y + f * s * u.y };
    };
    if(!found)
      for(double f : { 0.7, 0.85, 1.0, 1.15, 1.3 })
        for(int k = -2; k <= 2; ++k)
          consider(off_bisector(f, k));
    // A notch barely out (111.65 degrees at a transition template's corner, core angles 45,
    // 45, 68, 90, blob_37's (-0.1252, 9.0710)) has its Y on a thin band, far off the bisector:
    // the quad's angle at Y exactly 135 (a lone quad's corner has beta 225 at least), and at a
    // neighbour little enough to keep its beta in range. The ring misses the band; a search of
    // the quad's excess over [45, 135] plus the betas' reaches it, then consider() checks.
    // Not beside an input corner, whose buffer is §5's (naca0012's trailing edge: such a quad
    // made the round invalid).
    if(!found && !near_input_corner(b)) {
      auto penalty = [&](const Point_2d& y) {
        return (std::max)(0.0, quad_badness({ m_xy[b], m_xy[a], y, m_xy[c1] }) - 45.0) + excess(y);
      };
      Point_2d start = m_xy[b];
      double least = std::numeric_limits<double>::infinity();
      for(double f : { 0.7, 0.85, 1.0, 1.15, 1.3 })
        for(int k = -5; k <= 5; ++k) {
          const Point_2d y = off_bisector(f, k);
          const double p = penalty(y);
          if(p < least) { least = p; start = y; }
        }
      pattern_search(start, s, [&](const Point_2d& y) {
        const double p = penalty(y);
        if(!(p < least)) return false;
        least = p;
        start = y;
        return true;
      });
      consider(start);
    }
    if(!found) return;
    pattern_search(best_y, s, consider);
    // Y is a core point like the others (the first buffer points come after the core's)
    const std::size_t y = add_core_point(best_y, m_size[b], true);
    m_on_cycle[b] = 0;
    m_core_points = m_mesh.points.size();
    add_quad({ b, a, y, c1 });
    cyc[i] = y;
    ++m_report.filled_notches;
  }

  // A convex corner that no move brought into range (buffer-side angle over 225 degrees) whose
  // core angle is a single quad's, jammed by its other corners: a transition template's 45
  // degrees at a neighbour, 135 opposite (naca0012's (0.0710, -0.0456): 108 degrees, beta 252).
  // The quad B C X A is split in three through the midpoints of its two boundary edges and its
  // centre O: B Mc O Ma, Mc C X O, Ma O X A (on a square, three rectangles of right angles,
  // the new points' betas 180). B's quad then shares no corner with the template that jammed
  // it, and the search moves B in as template 1(b) would, O giving way: a kite at B. Not where
  // no centre keeps the three quads within [45, 135].
  // (`quads_at`, made at the first candidate, knows the first `known` points: a million-quad
  // core seldom has a candidate; `split` marks the quads split before.)
  bool split_corner(std::size_t c, std::size_t i, std::optional<Vertex_quads>& quads_at, std::size_t& known,
                    std::vector<char>& split)
  {
    auto& cyc = m_cycles[c];
    const std::size_t n = cyc.size();
    const std::size_t a = cyc[(i + n - 1) % n], b = cyc[i], c1 = cyc[(i + 1) % n];
    if(n < 8 || m_fixed[b] || right_side_angle(m_xy[a], m_xy[b], m_xy[c1]) <= 225.0 + rounding_tolerance(a, b, c1)
       || near_input_corner(b))
      return false;
    if(!quads_at) {
      quads_at.emplace(m_mesh.quads, m_mesh.points.size());
      known = m_mesh.points.size();
      split.assign(m_mesh.quads.size(), 0);
    }
    if(a >= known || b >= known || c1 >= known || (*quads_at)[b].size() != 1) return false;
    const std::size_t q = *(*quads_at)[b].begin();
    if(split[q]) return false;
    split[q] = 1;
    const Quad Q = m_mesh.quads[q];
    const int k = corner_of(Q, b);
    if(Q[(k + 1) % 4] != c1 || Q[(k + 3) % 4] != a) return false;
    const std::size_t x = Q[(k + 2) % 4];
    auto mid = [&](const Point_2d& u, const Point_2d& v) { return Point_2d{ (u.x + v.x) / 2, (u.y + v.y) / 2 }; };
    const Point_2d pa = mid(m_xy[a], m_xy[b]), pc = mid(m_xy[b], m_xy[c1]);
    // O from the centre where the three quads' worst angle is least: a quad far from a
    // square (a tongue's tip) left one under 45 degrees
    auto worst = [&](const Point_2d& o) {
      return (std::max)({ quad_badness({ m_xy[b], pc, o, pa }), quad_badness({ pc, m_xy[c1], m_xy[x], o }),
                          quad_badness({ pa, o, m_xy[x], m_xy[a] }) });
    };
    Point_2d centre = mid(mid(m_xy[a], m_xy[c1]), mid(m_xy[b], m_xy[x]));
    double least = worst(centre);
    pattern_search(centre, length_2d(minus_2d(m_xy[x], m_xy[b])), [&](const Point_2d& o) {
      const double w = worst(o);
      if(!(w < least)) return false;
      least = w;
      centre = o;
      return true;
    });
    if(least > 45.0 + core_slack) return false;
    const std::size_t ma = add_core_point(pa, m_size[b], true);
    const std::size_t mc = add_core_point(pc, m_size[b], true);
    const std::size_t o = add_core_point(centre, m_size[b], false);
    m_core_points = m_mesh.points.size();
    m_mesh.quads[q] = { b, mc, o, ma };
    add_quad({ mc, c1, x, o });
    add_quad({ ma, o, x, a });
    cyc.insert(cyc.begin() + std::ptrdiff_t(i) + 1, mc);
    cyc.insert(cyc.begin() + std::ptrdiff_t(i), ma);
    ++m_report.split_corners;
    return true;
  }

  // Beside an input corner, v turns about it to share the corner's angle evenly between the
  // two quads it separates there (the paper's rotated bisectors, §5): one target per corner.
  void add_turns_about_corners(std::size_t v, const Vertex_quads& quads_at,
                               std::vector<Point_2d>& targets) const
  {
    const Point_2d old = m_xy[v];
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = m_mesh.quads[q];
      const int c = corner_of(Q, v);
      for(int side : { 1, 3 }) {
        const std::size_t corner = Q[(c + side) % 4];
        if(!is_input_vertex(corner)) continue;
        const Point_2d& P = m_xy[corner];
        const Point_2d& w = m_xy[Q[(c + 2 * side) % 4]]; // the corner's other neighbour in q
        double other = -1; // the corner's angle in the other quad at v
        for(std::size_t q2 : quads_at[v]) {
          if(q2 == q) continue;
          const Quad& R = m_mesh.quads[q2];
          for(int j = 0; j < 4; ++j)
            if(R[j] == corner && (R[(j + 1) % 4] == v || R[(j + 3) % 4] == v))
              other = corner_angle_degrees(m_xy[R[(j + 3) % 4]], P, m_xy[R[(j + 1) % 4]]);
        }
        const double here = corner_angle_degrees(w, P, old);
        if(other < 0 || here <= 135.0) continue;
        // turn v towards w by half the difference
        const double turn = (here - other) / 2 * pi / 180;
        const Point_2d d = minus_2d(old, P), e = minus_2d(w, P);
        const double sense = cross_2d(d, e) > 0 ? 1.0 : -1.0;
        targets.push_back(turned_about_2d(old, P, sense * turn));
      }
    }
  }

  // the optimised positions back into the kernel: boundary points exactly on their edge
  void write_back(const std::vector<std::size_t>& movable)
  {
    for(std::size_t v : movable) {
      auto it = m_slide.find(v);
      if(it == m_slide.end()) {
        m_mesh.points[v] = m_traits.construct_point_2_object()(FT(m_xy[v].x), FT(m_xy[v].y));
      } else {
        const auto& lv = m_loops.loops[it->second.loop].vertices;
        const Point_2& a = m_domain.points[lv[it->second.edge]];
        const Point_2& b = m_domain.points[lv[(it->second.edge + 1) % lv.size()]];
        const Point_2d A = to_point_2d(a), B = to_point_2d(b);
        const Point_2d ab = minus_2d(B, A);
        const double t = dot_2d(minus_2d(m_xy[v], A), ab) / dot_2d(ab, ab);
        m_mesh.points[v] = point_between(a, b, t);
        m_xy[v] = to_point_2d(m_mesh.points[v]);
      }
    }
  }

  static constexpr std::size_t none = std::size_t(-1);
  static constexpr double pi = 3.14159265358979323846;

  // the corner of quad Q that is vertex v (a corner of it)
  static int corner_of(const Quad& Q, std::size_t v)
  {
    int c = 0;
    while(Q[c] != v) ++c;
    return c;
  }
  // Angles within this many degrees of a bound count as on it, and closer ones as equal:
  // doubles hold an angle only to about 1e-8 degrees where the coordinates are 2^20 cell
  // sides, and a choice made by rounding differs on a scaled or moved domain (a cut corner's
  // core angle is exactly 135 degrees: a disc scaled by 2^-14 and moved to (3, 0.5) was
  // refined elsewhere)
  static constexpr double angle_tolerance = 1e-6;
  // The final check of the buffer quads is no looser than verify_mesh.py's range slack: a
  // quad passed here is one it passes.
  static constexpr double verifier_slack = 1e-7;
  // How far the templates' searches let a core angle leave [45, 135]: rounding only, well
  // below verifier_slack (nothing later need mend it).
  static constexpr double core_slack = 1e-9;

  // for a sliding boundary point, moves `p` onto its edge strictly between its neighbours;
  // false if there is no room
  bool slide_to(std::size_t v, Point_2d& p) const
  {
    auto it = m_slide.find(v);
    if(it == m_slide.end()) return true;
    const std::size_t a = it->second.neighbors[0], b = it->second.neighbors[1];
    if(a == none || b == none) return false;
    const Point_2d A = m_xy[a], B = m_xy[b];
    const Point_2d ab = minus_2d(B, A);
    const double len2 = dot_2d(ab, ab);
    if(!(len2 > 0)) return false;
    const double t = (std::min)(0.9, (std::max)(0.1, dot_2d(minus_2d(p, A), ab) / len2));
    // the neighbours must lie on this point's edge (or be its ends) for the chain to stay on it
    const auto& lv = m_loops.loops[it->second.loop].vertices;
    const Point_2d E0 = to_point_2d(m_domain.points[lv[it->second.edge]]);
    const Point_2d E1 = to_point_2d(m_domain.points[lv[(it->second.edge + 1) % lv.size()]]);
    const Point_2d e = minus_2d(E1, E0);
    const double el = length_2d(e);
    if(std::abs(cross_2d(e, minus_2d(A, E0))) > 1e-9 * el * el || std::abs(cross_2d(e, minus_2d(B, E0))) > 1e-9 * el * el)
      return false;
    p = along_2d(A, B, t);
    return true;
  }

  bool on_cycle(std::size_t v) const { return v < m_on_cycle.size() && m_on_cycle[v] != 0; }

  // a core vertex the repair moves of optimize() moved
  bool repaired(std::size_t v) const { return v < m_repaired.size() && m_repaired[v] != 0; }

  // an interior core vertex the templates moved (relax_interior())
  bool shaped(std::size_t v) const { return v < m_shaped.size() && m_shaped[v] != 0; }

  // a quad the buffer stages made or changed: a vertex new, on the core boundary or moved by
  // the templates or the repair (the other core quads keep their lattice angles, in [45, 135])
  bool made_or_changed(const Quad& Q) const
  {
    for(std::size_t v : Q)
      if(v >= m_core_points || on_cycle(v) || repaired(v) || shaped(v)) return true;
    return false;
  }

  bool is_core_boundary(std::size_t v) const
  {
    return v < m_core_points && on_cycle(v) && !m_first_built;
  }

  double cycle_area(std::size_t c) const
  {
    double a = 0;
    const auto& cyc = m_cycles[c];
    const Point_2d& o = m_xy[cyc[0]]; // relative to a vertex: far from the origin, absolute
                                       // coordinates would cancel
    for(std::size_t i = 0; i < cyc.size(); ++i)
      a += cross_2d(minus_2d(m_xy[cyc[i]], o), minus_2d(m_xy[cyc[(i + 1) % cyc.size()]], o));
    return a / 2;
  }

  void request_all(std::size_t c)
  {
    for(std::size_t v : m_cycles[c])
      m_requests.for_validity.emplace_back(m_xy[v], m_size[v]);
  }

  std::size_t add_point(const Point_2d& p)
  {
    m_mesh.points.push_back(m_traits.construct_point_2_object()(FT(p.x), FT(p.y)));
    m_xy.push_back(p);
    return m_mesh.points.size() - 1;
  }

  void add_quad(const Quad& q) { m_mesh.quads.push_back(q); }

  // a new core point of local size `size` (the templates' new quads: the first buffer points
  // come after every core point)
  std::size_t add_core_point(const Point_2d& p, double size, bool on_boundary)
  {
    const std::size_t v = add_point(p);
    m_size.push_back(size);
    m_on_cycle.push_back(on_boundary ? 1 : 0);
    m_fixed.push_back(0);
    m_shaped.push_back(0);
    m_cleared_xy.push_back(p);
    return v;
  }

  double input_corner_angle(std::size_t v) const
  {
    return v < m_corner_angle.size() ? m_corner_angle[v] : std::numeric_limits<double>::quiet_NaN();
  }

  // every input vertex on the chain has its corner angle
  bool is_input_vertex(std::size_t v) const { return !std::isnan(input_corner_angle(v)); }

  // true if `angle`, a quad's angle at mesh vertex v, is forced: v is an input corner sharper
  // than 45 degrees and the quad spans all of it (one quad there keeps its angles in
  // [alpha, 180 - alpha]; a split corner has less). A corner over 270 degrees forces nothing:
  // a fan of three quads splits it within [45, 135].
  bool forced_angle(std::size_t v, double angle) const
  {
    const double alpha = input_corner_angle(v);
    return alpha < 45.0 && angle >= alpha - 1e-3; // false for NaN
  }

  enum Template_pass { ADAPTIVE, CORNERS, NOTCHES, NEIGHBOURS };

  // every quad at core vertex v a square, all of one side (the uniform grid of §4.4)
  bool on_square_lattice(std::size_t v, const Vertex_quads& quads_at) const
  {
    double side = -1;
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = m_mesh.quads[q];
      for(int k = 0; k < 4; ++k) {
        const Point_2d e = minus_2d(m_xy[Q[(k + 1) % 4]], m_xy[Q[k]]);
        const Point_2d f = minus_2d(m_xy[Q[(k + 2) % 4]], m_xy[Q[(k + 1) % 4]]);
        if(side < 0) side = length_2d(e);
        if(std::abs(length_2d(e) - side) > 1e-6 * side || std::abs(dot_2d(e, f)) > 1e-6 * side * side)
          return false;
      }
    }
    return true;
  }

  // Moves core boundary vertex b (a2, a, b, c, c2 consecutive on its cycle) along the bisector
  // of its buffer-side angle, if `pass` applies to it and a step lowers the worst distance of
  // the betas at a, b and c from [112.5, 225] (see the file comment).
  bool try_move_boundary_vertex(std::size_t a2, std::size_t a, std::size_t b, std::size_t c,
                                std::size_t c2, Template_pass pass, const Vertex_quads& quads_at)
  {
    const double beta = right_side_angle(m_xy[a], m_xy[b], m_xy[c]);
    const bool notch = beta < 112.5 - angle_tolerance, corner = beta > 225.0 + angle_tolerance;
    const bool applies = pass == CORNERS ? corner : pass == NOTCHES ? notch
                         : pass == ADAPTIVE ? notch || corner : !notch && !corner;
    if(!applies)
      return false;
    const Point_2d old = m_xy[b];
    auto worst = [&](const Point_2d& p) { return worst_buffer_angle_excess(m_xy[a2], m_xy[a], p, m_xy[c], m_xy[c2]); };
    double best = worst(old);
    if(best <= angle_tolerance)
      return false;
    // in units of e, out along the bisector if positive: on the lattice a notch opens to 180
    // degrees at 0.71 e, a corner is cut to 225 degrees at 0.41 e
    static const std::vector<double> notch_steps{ 0.70710678118654752, 0.5, 0.35 };
    static const std::vector<double> corner_steps{ -0.41421356237309505, -0.3, -0.2 };
    static const std::vector<double> neighbour_steps{ 0.5, 0.35, 0.2, -0.3, -0.2 };
    const double e = 0.5 * (length_2d(minus_2d(old, m_xy[a])) + length_2d(minus_2d(m_xy[c], old)));
    const Point_2d d = right_bisector(m_xy[a], old, m_xy[c]);
    const double clear = 0.25 * m_size[b];
    double best_f = 0;
    for(double f : notch ? notch_steps : corner ? corner_steps : neighbour_steps) {
      const Point_2d p{old.x + f * e * d.x, old.y + f * e * d.y};
      m_xy[b] = p;
      bool ok = worst(p) < best - angle_tolerance;
      for(auto q = quads_at[b].begin(); ok && q != quads_at[b].end(); ++q) {
        std::array<Point_2d, 4> P;
        for(int k = 0; k < 4; ++k) P[k] = m_xy[m_mesh.quads[*q][k]];
        ok = quad_badness(P) <= 45.0 + angle_tolerance;
      }
      if(ok && m_locator->segment_distance(m_xy[a], p, clear) > clear
         && m_locator->segment_distance(p, m_xy[c], clear) > clear) {
        best = worst(p);
        best_f = f;
      }
    }
    if(best_f == 0) {
      m_xy[b] = old;
      return false;
    }
    m_xy[b] = Point_2d{old.x + best_f * e * d.x, old.y + best_f * e * d.y};
    m_mesh.points[b] = m_traits.construct_point_2_object()(FT(m_xy[b].x), FT(m_xy[b].y));
    ++(best_f > 0 ? m_report.moved_notches : m_report.cut_corners);
    return true;
  }

  // How far the buffer-side angles at a, b and c (consecutive on a core cycle between a2 and
  // c2) lie outside [112.5, 225] widened by half the angle tolerance (what is within the
  // tolerance counts as in), in one number, so that a search lowering it by more than rounding
  // ends: how many are out first if `count_first` (a step of b that lets a neighbour out for a
  // smaller worst one leaves more out), then the worst, then a tenth of their sum.
  double buffer_angle_excesses(const Point_2d& a2, const Point_2d& a, const Point_2d& b,
                               const Point_2d& c, const Point_2d& c2, bool count_first = true) const
  {
    const std::array<double, 3> betas{ right_side_angle(a2, a, b), right_side_angle(a, b, c), right_side_angle(b, c, c2) };
    return excess_score(betas, count_first);
  }

  // buffer_angle_excesses() of any number of buffer-side angles
  template <class Betas>
  static double excess_score(const Betas& betas, bool count_first)
  {
    double out = 0, worst = 0, sum = 0;
    for(double beta : betas) {
      const double x = (std::max)(0.0, beta - (225.0 + angle_tolerance / 2))
                       + (std::max)(0.0, (112.5 - angle_tolerance / 2) - beta);
      out += x > 0 ? 1 : 0;
      worst = (std::max)(worst, x);
      sum += x;
    }
    return (count_first ? 1000.0 * out : 0.0) + worst + 0.1 * sum;
  }

  // true if core boundary vertex b (between a and c) may lie at p: every quad at it within
  // [45, 135], none of its edges shorter than half what it was in the core the clearance left
  // (angles alone let an edge shrink to nothing: naca0012's (0.872, 0.024) met its neighbour),
  // its boundary edges h(b)/4 from the boundary
  // (with `angles` false, all but the angles: the interior may still give way)
  bool admissible_boundary_position(std::size_t a, std::size_t b, std::size_t c, const Point_2d& p,
                                    const Vertex_quads& quads_at, bool angles = true)
  {
    const Point_2d old = m_xy[b];
    m_xy[b] = p;
    bool ok = true;
    for(auto q = quads_at[b].begin(); ok && q != quads_at[b].end(); ++q) {
      const Quad& Q = m_mesh.quads[*q];
      if(angles) {
        std::array<Point_2d, 4> P;
        for(int k = 0; k < 4; ++k) P[k] = m_xy[Q[k]];
        ok = quad_badness(P) <= 45.0 + core_slack;
      }
      const int k = corner_of(Q, b);
      for(int side : { 1, 3 }) {
        const std::size_t w = Q[(k + side) % 4];
        ok = ok && keeps_half_length(b, w, p);
      }
    }
    m_xy[b] = old;
    const double clear = 0.25 * m_size[b];
    return ok && m_locator->segment_distance(m_xy[a], p, clear) > clear
           && m_locator->segment_distance(p, m_xy[c], clear) > clear;
  }

  // A core boundary vertex b still out of [112.5, 225] after the bisector steps (a2, a, b, c,
  // c2 consecutive on its cycle): on adaptive cores its quads are not the lattice's, and the
  // step its buffer-side angle needs is neither along the bisector nor one of the lattice's.
  // The best admissible point of a ring around b (12 directions, 6 distances), then a pattern
  // search from it (16 directions, halving the step), lowers the excesses at a, b and c.
  // If b's own angle is still out, the core around it may give way: b goes to a point of the
  // ring that would bring it in, and the interior core vertices within two quads of it move to
  // keep their quads within [45, 135] (relax_interior()); the first point where they can is
  // kept, and searched from again. (A transition template's 45-degree corner at b, which b
  // alone cannot open, opens as its diagonal's other end moves.)
  bool search_boundary_vertex(std::size_t a2, std::size_t a, std::size_t b, std::size_t c, std::size_t c2,
                              const Vertex_quads& quads_at)
  {
    const Point_2d old = m_xy[b];
    auto excess = [&](const Point_2d& p) { return buffer_angle_excesses(m_xy[a2], m_xy[a], p, m_xy[c], m_xy[c2]); };
    double best = excess(old);
    if(best == 0 || buffer_angle_excess(right_side_angle(m_xy[a], old, m_xy[c])) <= angle_tolerance
       || near_input_corner(b))
      return false;
    const double e = 0.5 * (length_2d(minus_2d(old, m_xy[a])) + length_2d(minus_2d(m_xy[c], old)));
    auto ring = [&](double r, int k) {
      return Point_2d{ old.x + r * e * std::cos(k * pi / 6), old.y + r * e * std::sin(k * pi / 6) };
    };
    Point_2d best_p = old;
    auto consider = [&](const Point_2d& p) {
      const double x = excess(p);
      if(!(x < best - angle_tolerance / 10) || !admissible_boundary_position(a, b, c, p, quads_at)) return false;
      best = x;
      best_p = p;
      return true;
    };
    for(double r : { 0.05, 0.1, 0.2, 0.3, 0.45, 0.6 })
      for(int k = 0; k < 12; ++k)
        consider(ring(r, k));
    pattern_search(best_p, e, consider);
    bool reshaped = false;
    if(buffer_angle_excess(right_side_angle(m_xy[a], best_p, m_xy[c])) > angle_tolerance) {
      std::vector<std::pair<double, Point_2d>> targets; // in order of distance
      for(double r : { 0.1, 0.2, 0.3, 0.45 })
        for(int k = 0; k < 12; ++k) {
          const Point_2d p = ring(r, k);
          const double x = excess(p);
          if(x < best - angle_tolerance / 10
             && buffer_angle_excess(right_side_angle(m_xy[a], p, m_xy[c])) <= angle_tolerance)
            targets.emplace_back(x, p);
        }
      std::stable_sort(targets.begin(), targets.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      const std::vector<std::size_t> around = interior_around(b, quads_at);
      for(std::size_t t = 0; t < targets.size() && t < 6 && !reshaped; ++t) {
        m_xy[b] = targets[t].second;
        reshaped = admissible_boundary_position(a, b, c, targets[t].second, quads_at, false)
                   && relax_interior(around, b, quads_at);
        if(reshaped) {
          best = targets[t].first;
          best_p = targets[t].second;
          pattern_search(best_p, e, consider);
        }
        m_xy[b] = old;
      }
    }
    if(best_p.x == old.x && best_p.y == old.y) return false;
    m_xy[b] = best_p;
    m_mesh.points[b] = m_traits.construct_point_2_object()(FT(best_p.x), FT(best_p.y));
    ++m_report.searched_vertices;
    return true;
  }

  // A pattern search in the plane about `at`, the best point so far, which `consider(p)`
  // replaces by p if p is better (and then returns true): 16 directions at a step from a
  // twentieth of `scale` down to 1e-10 of it, doubled after a move and halved after none. At
  // most 400 tries of the 16: along a ridge of the angles' maximum the moves can be tiny and
  // many.
  template <class Consider>
  static void pattern_search(const Point_2d& at, double scale, const Consider& consider)
  {
    double step = 0.05 * scale;
    for(int i = 0; i < 400 && step > 1e-10 * scale; ++i) {
      const Point_2d from = at;
      bool moved = false;
      for(int k = 0; k < 16; ++k)
        moved = consider(Point_2d{ from.x + step * std::cos(k * pi / 8), from.y + step * std::sin(k * pi / 8) }) || moved;
      step = moved ? (std::min)(2 * step, 0.05 * scale) : step / 2;
    }
  }

  // true if an input corner (a loop vertex turning by the feature angle or more) at an end of
  // the boundary edge nearest core vertex b lies within 2 h(b) of it: its buffer is the
  // corner's (§5), not Lemma 2's (bird_mx's 1.13, -6.79 moved off the lattice beside the tip
  // left a first-layer quad inverted)
  bool near_input_corner(std::size_t b) const
  {
    const Loop_locator::Hit h = m_locator->closest(m_xy[b], 2 * m_size[b]);
    if(!(h.dist < 2 * m_size[b])) return false;
    const std::size_t nv = m_locator->loop(h.loop).size();
    for(std::size_t k : { h.edge, (h.edge + 1) % nv })
      if(is_feature(h.loop, k) && length_2d(minus_2d(m_locator->loop(h.loop)[k], m_xy[b])) < 2 * m_size[b])
        return true;
    return false;
  }

  // search_boundary_vertex() on every core boundary vertex, in rounds while one moves
  void search_boundary_vertices(const Vertex_quads& quads_at)
  {
    for(int round = 0; round < 3; ++round) {
      bool changed = false;
      for(const auto& cyc : m_cycles) {
        const std::size_t n = cyc.size();
        for(std::size_t i = 0; i < n; ++i)
          if(search_boundary_vertex(cyc[(i + n - 2) % n], cyc[(i + n - 1) % n], cyc[i],
                                    cyc[(i + 1) % n], cyc[(i + 2) % n], quads_at))
            changed = true;
      }
      if(!changed) break;
    }
    for(const auto& cyc : m_cycles)
      for(std::size_t i = 0; i < cyc.size(); ++i)
        search_window(cyc, i, quads_at);
  }

  // A vertex still out whose quad's other corners are at the range's ends (a transition
  // template's corner at 45 and 135 degrees, a tongue's tip) cannot move alone: its
  // neighbours on the cycle, two each side, move in turn (each as search_boundary_vertex()
  // moves one) while that lowers the excesses of the seven buffer-side angles from three
  // before to three after it; kept if fewer are out, or as many but less far.
  bool search_window(const std::vector<std::size_t>& cyc, std::size_t i, const Vertex_quads& quads_at)
  {
    const std::size_t n = cyc.size();
    if(n < 8) return false;
    auto node = [&](int d) { return cyc[(i + 2 * n + d) % n]; };
    auto beta_at = [&](int d) { return right_side_angle(m_xy[node(d - 1)], m_xy[node(d)], m_xy[node(d + 1)]); };
    if(buffer_angle_excess(beta_at(0)) <= angle_tolerance || near_input_corner(cyc[i])) return false;
    auto objective = [&](bool count_first) {
      std::array<double, 7> betas;
      for(int d = -3; d <= 3; ++d) betas[std::size_t(d + 3)] = beta_at(d);
      return excess_score(betas, count_first);
    };
    const double start = objective(true);
    std::vector<std::size_t> movers;
    std::vector<Point_2d> before;
    for(int d = -2; d <= 2; ++d) {
      const std::size_t v = node(d);
      if(m_fixed[v] || near_input_corner(v)) continue;
      movers.push_back(v);
      before.push_back(m_xy[v]);
    }
    for(int sweep = 0; sweep < 6; ++sweep) {
      bool moved = false;
      for(int d = -2; d <= 2; ++d) {
        const std::size_t v = node(d);
        if(std::find(movers.begin(), movers.end(), v) == movers.end()) continue;
        const std::size_t a = node(d - 1), c = node(d + 1);
        const Point_2d old = m_xy[v];
        const double e = 0.5 * (length_2d(minus_2d(old, m_xy[a])) + length_2d(minus_2d(m_xy[c], old)));
        double best = objective(false);
        Point_2d best_p = old;
        auto consider = [&](const Point_2d& p) {
          m_xy[v] = p;
          const double x = objective(false);
          m_xy[v] = old;
          if(!(x < best - angle_tolerance / 10) || !admissible_boundary_position(a, v, c, p, quads_at)) return false;
          best = x;
          best_p = p;
          return true;
        };
        for(double r : { 0.05, 0.1, 0.2 })
          for(int k = 0; k < 12; ++k)
            consider(Point_2d{ old.x + r * e * std::cos(k * pi / 6), old.y + r * e * std::sin(k * pi / 6) });
        pattern_search(best_p, e, consider);
        m_xy[v] = best_p;
        moved = moved || best_p.x != old.x || best_p.y != old.y;
      }
      if(!moved) break;
    }
    const bool kept = objective(true) < start - angle_tolerance;
    for(std::size_t k = 0; k < movers.size(); ++k) {
      const std::size_t v = movers[k];
      if(m_xy[v].x == before[k].x && m_xy[v].y == before[k].y) continue;
      if(kept)
        m_mesh.points[v] = m_traits.construct_point_2_object()(FT(m_xy[v].x), FT(m_xy[v].y));
      else
        m_xy[v] = before[k];
    }
    if(kept) ++m_report.searched_vertices;
    return kept;
  }

  // the interior core vertices (not on a cycle, not the domain's isolated points) of the quads
  // at b and of the quads at those
  std::vector<std::size_t> interior_around(std::size_t b, const Vertex_quads& quads_at) const
  {
    std::vector<std::size_t> near{ b }, out;
    for(int ring = 0; ring < 2; ++ring) {
      std::vector<std::size_t> next;
      for(std::size_t u : near)
        for(std::size_t q : quads_at[u])
          for(std::size_t w : m_mesh.quads[q])
            if(!on_cycle(w) && !m_fixed[w]) next.push_back(w);
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      out.insert(out.end(), next.begin(), next.end());
      near = std::move(next);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // the largest deviation from 90 degrees of the quads at v
  // whether edge v-w, v at p, keeps half the length it had after the clearance at least
  bool keeps_half_length(std::size_t v, std::size_t w, const Point_2d& p) const
  {
    return length_2d(minus_2d(m_xy[w], p)) >= 0.5 * length_2d(minus_2d(m_cleared_xy[w], m_cleared_xy[v]));
  }

  double worst_badness_at(std::size_t v, const Vertex_quads& quads_at) const
  {
    double worst = 0;
    for(std::size_t q : quads_at[v]) {
      std::array<Point_2d, 4> P;
      for(int k = 0; k < 4; ++k) P[k] = m_xy[m_mesh.quads[q][k]];
      worst = (std::max)(worst, quad_badness(P));
    }
    return worst;
  }

  // With core boundary vertex b moved, the interior vertices `around` it move one at a time,
  // those with a quad outside [45, 135], each to the target (as in optimize()) that most lowers
  // the worst deviation from 90 degrees of its quads, none of its edges shorter than half what
  // it was. True, and the moves kept (exactly in the kernel), if then every quad at b and at
  // them is within [45, 135]; otherwise they are undone.
  bool relax_interior(const std::vector<std::size_t>& around, std::size_t b, const Vertex_quads& quads_at)
  {
    std::vector<Point_2d> before(around.size());
    for(std::size_t k = 0; k < around.size(); ++k) before[k] = m_xy[around[k]];
    auto short_edge = [&](std::size_t v) {
      for(std::size_t q : quads_at[v]) {
        const Quad& Q = m_mesh.quads[q];
        const int c = corner_of(Q, v);
        for(int side : { 1, 3 }) {
          const std::size_t w = Q[(c + side) % 4];
          if(!keeps_half_length(v, w, m_xy[v]))
            return true;
        }
      }
      return false;
    };
    std::vector<Point_2d> targets;
    for(int pass = 0; pass < 8; ++pass) {
      bool moved = false;
      for(std::size_t v : around) {
        const double current = worst_badness_at(v, quads_at);
        if(current <= 45.0) continue;
        const Point_2d old = m_xy[v];
        const Point_2d lap = parallelogram_targets(v, quads_at, targets);
        Point_2d mean{ 0, 0 };
        for(const Point_2d& t : targets) { mean.x += t.x; mean.y += t.y; }
        const double nq = double(targets.size());
        targets.push_back(Point_2d{ mean.x / nq, mean.y / nq });
        targets.push_back(lap);
        double best = current;
        Point_2d best_p = old;
        for(const Point_2d& t : targets)
          for(double step : { 1.0, 0.5, 0.25, 0.1 }) {
            m_xy[v] = Point_2d{ old.x + step * (t.x - old.x), old.y + step * (t.y - old.y) };
            const double w = worst_badness_at(v, quads_at);
            if(w < best - angle_tolerance && !short_edge(v)) {
              best = w;
              best_p = m_xy[v];
            }
          }
        m_xy[v] = best_p;
        moved = moved || best < current;
      }
      if(!moved) break;
    }
    bool ok = worst_badness_at(b, quads_at) <= 45.0 + core_slack;
    for(std::size_t v : around) ok = ok && worst_badness_at(v, quads_at) <= 45.0 + core_slack;
    for(std::size_t k = 0; k < around.size(); ++k) {
      const std::size_t v = around[k];
      if(m_xy[v].x == before[k].x && m_xy[v].y == before[k].y) continue;
      if(ok) {
        m_mesh.points[v] = m_traits.construct_point_2_object()(FT(m_xy[v].x), FT(m_xy[v].y));
        m_report.shaped_interior += m_shaped[v] == 0 ? 1 : 0;
        m_shaped[v] = 1;
      } else {
        m_xy[v] = before[k];
      }
    }
    return ok;
  }

  // Triangles of the strip, in order around the loop: an F edge with its apex on G, or a G
  // edge with its apex an F point. Vertices are mesh ids, counter-clockwise.
  typedef std::array<std::size_t, 3> Triangle;

  // the quad made of two triangles sharing an edge (none if they share none)
  static Quad merge(const Triangle& A, const Triangle& B)
  {
    for(int k = 0; k < 3; ++k) {
      const std::size_t x = A[k], y = A[(k + 1) % 3];
      for(int j = 0; j < 3; ++j)
        if(B[j] == y && B[(j + 1) % 3] == x)
          return Quad{ x, B[(j + 2) % 3], y, A[(k + 2) % 3] };
    }
    return Quad{ none, none, none, none };
  }

  double cost(const Quad& q) const
  {
    if(q[0] == none) return 2000.0;
    if(m_cache_costs) {
      auto it = m_cost_cache.find(q);
      if(it != m_cost_cache.end()) return it->second;
      const double b = uncached_cost(q);
      m_cost_cache.emplace(q, b);
      return b;
    }
    return uncached_cost(q);
  }

  double uncached_cost(const Quad& q) const
  {
    std::array<Point_2d, 4> P;
    for(int k = 0; k < 4; ++k) P[k] = m_xy[q[k]];
    double b = quad_badness(P);
    // an angle an input corner alpha forces is not the strip's fault: the quad is judged by its
    // other three, which fit in [45, 135] (they sum to 360 - alpha; with [alpha, 180 - alpha]
    // costing what [45, 135] costs elsewhere, as the paper allows, bird's 11.5-degree tip kept
    // 138.8). Beyond 45 their deviation counts in full from a 6-degree corner up (there they
    // fit: the mirrored bird's tip kept 137.4 while it counted less) and less below, as it
    // did: on a needle's tip they cannot all fit.
    if(b < 1000.0)
      for(int k = 0; k < 4; ++k)
        if(input_corner_angle(q[k]) < 45.0 // cheap test first: the cost runs in inner loops
           && forced_angle(q[k], corner_angle_degrees(P[(k + 3) % 4], P[k], P[(k + 1) % 4]))) {
          const double scale = input_corner_angle(q[k]) >= 6.0 ? 1.0 : 45.0 / (90.0 - input_corner_angle(q[k]));
          b = 0;
          for(int j = 0; j < 4; ++j)
            if(j != k) {
              const double d = std::abs(corner_angle_degrees(P[(j + 3) % 4], P[j], P[(j + 1) % 4]) - 90.0);
              b = (std::max)(b, d <= 45.0 ? d : 45.0 + scale * (d - 45.0));
            }
          break;
        }
    return b;
  }

  // A quad's cost in the strip's pairing: an angle out of [45, 135] at a boundary node between
  // two others (the middle of a fan of boundary edges) is the boundary's own angle there,
  // which no later move changes (an input vertex stays; a point on an input edge only slides
  // along it), unlike a quad sheared by its F points, which the optimizer straightens: it
  // costs as much as a hundred degrees more (lake_superior_jigsaw kept a 135.9-degree corner
  // whole, one quad spanning it, rather than shear a row; the mirrored guitar kept a chord
  // node at 174.5 degrees beside a left-out vertex). So does a quad over 135 degrees on a side
  // of a corner over 270 degrees (wide_side_of_reflex_fan()).
  double strip_cost(const Quad& q) const
  {
    const double b = cost(q);
    if(b <= 45.0 + angle_tolerance || b >= 1000.0) return b;
    return fixed_angle_out_of_range(q) >= 0 || wide_side_of_reflex_fan(q) >= 0 ? b + 100.0 : b;
  }

  // the corner (0 to 3) of q at a boundary node between two others whose angle is out of
  // [45, 135] and not forced, or -1
  int fixed_angle_out_of_range(const Quad& q) const
  {
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = q[k], u = q[(k + 3) % 4], w = q[(k + 1) % 4];
      if(!on_boundary_chain(v) || !on_boundary_chain(u) || !on_boundary_chain(w)) continue;
      const double angle = corner_angle_degrees(m_xy[u], m_xy[v], m_xy[w]);
      if(std::abs(angle - 90.0) > 45.0 + angle_tolerance && !forced_angle(v, angle)) return k;
    }
    return -1;
  }

  // the corner (0 to 3) of q with over 135 degrees at an input corner of 270 degrees or more
  // (270 to rounding: a grid of square holes kept fans of 134.8 + 135.2 at theirs), between a
  // boundary node and an F point, or -1: a side of a fan of two there, or of a fan of three
  // with an F point off to one side. A fan of two at such a corner keeps over 135 degrees in one of its quads
  // however its F point moves (the pairing took two quads of about 147 degrees at a 294-degree
  // island tip over a fan of three whose middle F point, flat for now, the optimizer moves).
  int wide_side_of_reflex_fan(const Quad& q) const
  {
    for(int k = 0; k < 4; ++k) {
      const std::size_t v = q[k], u = q[(k + 3) % 4], w = q[(k + 1) % 4];
      if(!(input_corner_angle(v) > 270.0 - angle_tolerance) || on_boundary_chain(u) == on_boundary_chain(w)) continue;
      if(corner_angle_degrees(m_xy[u], m_xy[v], m_xy[w]) > 135.0 + angle_tolerance) return k;
    }
    return -1;
  }

  // an input vertex, a point on an input edge, or a gap's candidate extra node (an id past the
  // mesh's points while the strip is paired)
  bool on_boundary_chain(std::size_t v) const
  {
    return is_input_vertex(v) || m_slide.count(v) != 0 || v >= m_mesh.points.size();
  }

  // The strip's cost: the sum over its quads of the squared deviation from 90 degrees, plus a
  // heavy penalty beyond 45 (outside [45, 135]) and a prohibitive one for invalid quads. A sum,
  // not the worst quad: one poor quad at a corner beats a whole row of sheared ones.
  struct Cost
  {
    double worst = HUGE_VAL, sum = HUGE_VAL;
    bool operator<(const Cost& o) const { return sum < o.sum || (sum == o.sum && worst < o.worst); }
    void add(double b)
    {
      worst = (std::max)(worst, b);
      const double excess = (std::max)(0.0, b - 45.0);
      sum += b >= 1000.0 ? 1e12 : b * b + 100.0 * excess * excess;
    }
  };

  // the strip of loop cycle c: see the file comment
  void build_strip(std::size_t c)
  {
    const auto& cyc = m_cycles[c];
    const std::size_t n = cyc.size(), l = m_cycle_loop[c];
    const auto& F = m_first[c];
    const auto& loop_xy = m_locator->loop(l);
    const std::size_t nv = loop_xy.size();
    const double L = m_locator->length(l);
    auto cyclic = [&](double d) { d = std::fmod(d, L); if(d > L / 2) d -= L; if(d < -L / 2) d += L; return d; };

    // projections of the first buffer points; those within a third of the layer's thickness
    // of a loop vertex (along the loop) snap to it
    std::vector<Loop_locator::Hit> hit(n);
    std::vector<double> raw(n);
    std::vector<std::size_t> snap(n, none);
    for(std::size_t i = 0; i < n; ++i) {
      hit[i] = m_locator->closest(F[i], 2 * m_size[cyc[i]], l);
      raw[i] = m_locator->param(hit[i]);
      const double reach = 0.35 * hit[i].dist;
      double best = reach;
      for(std::size_t k : { hit[i].edge, (hit[i].edge + 1) % nv }) {
        const double d = std::abs(cyclic(m_locator->arc(l, k) - raw[i]));
        if(d <= best) { best = d; snap[i] = k; }
      }
    }
    // A corner wider than 135 degrees (obtuse or reflex) takes the node of the projection
    // nearest to it: a fan of boundary edges around an F point there would be flat or
    // concave at the corner (paper §5: such corners get a first buffer point of their own).
    {
      std::vector<std::size_t> by_param(n);
      for(std::size_t i = 0; i < n; ++i) by_param[i] = i;
      std::sort(by_param.begin(), by_param.end(), [&](std::size_t x, std::size_t y) { return raw[x] < raw[y]; });
      std::vector<bool> vertex_taken(nv, false);
      for(std::size_t i = 0; i < n; ++i) if(snap[i] != none) vertex_taken[snap[i]] = true;
      for(std::size_t k = 0; k < nv; ++k) {
        if(vertex_taken[k] || !is_feature(l, k)) continue;
        if(domain_angle(l, k) <= 135.0) continue;
        const double a = m_locator->arc(l, k);
        auto it = std::lower_bound(by_param.begin(), by_param.end(), a,
                                   [&](std::size_t x, double v) { return raw[x] < v; });
        std::size_t best = none;
        double bd = HUGE_VAL;
        for(int side = 0; side < 2; ++side) {
          const std::size_t pos = std::size_t(((it - by_param.begin()) - side + std::ptrdiff_t(n)) % std::ptrdiff_t(n));
          const std::size_t i = by_param[pos];
          const double d = std::abs(cyclic(raw[i] - a));
          if(snap[i] == none && d < bd) { bd = d; best = i; }
        }
        if(best != none) { snap[best] = k; vertex_taken[k] = true; }
      }
    }
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t k = snap[i];
      if(k != none && is_feature(l, k) && domain_angle(l, k) > 135.0 && !needs_fan_of_three(l, k)
         && snap[(i + n - 1) % n] != k && snap[(i + 1) % n] != k)
        turn_to_bisector(c, i, k);
    }
    std::size_t s0 = 0;
    while(s0 < n && snap[s0] != none) ++s0;
    if(s0 == n) { s0 = 0; snap[0] = none; }
    auto rot = [&](std::size_t r) { return (s0 + r) % n; };

    // unwrapped positions along the loop from O, the first projection; a step backwards would
    // fold the strip, so such a point shares its predecessor's node instead
    const double O = raw[s0];
    std::vector<double> P(n), W(n);
    std::vector<std::size_t> share(n, none);
    W[0] = P[0] = O;
    for(std::size_t r = 1; r < n; ++r) {
      const std::size_t i = rot(r);
      W[r] = W[r - 1] + cyclic(raw[i] - raw[rot(r - 1)]);
      P[r] = snap[i] != none ? W[r] + cyclic(m_locator->arc(l, snap[i]) - raw[i]) : W[r];
      if(P[r] <= P[r - 1]) {
        P[r] = P[r - 1];
        share[r] = share[r - 1] == none ? r - 1 : share[r - 1];
      }
    }
    const double winding = (W[n - 1] + cyclic(raw[s0] - raw[rot(n - 1)]) - O) / L;
    if(std::abs(winding - 1) > 1e-6) {
      request_all(c);
      m_report.failure = "the first buffer points do not project once around their loop";
      return;
    }
    // Points sharing a node (they project onto one reflex corner, or fold back) are spread
    // along the loop around it, one node each, at about their own spacing: the strip stays a
    // ladder and the pairing is left free to fan where it pays.
    for(std::size_t r = 0; r < n; ++r) P[r] = (std::min)(P[r], O + L);
    // The strip's pairing, with four F points on the node of each corner marked in `four_at`
    // (see may_take_four_fan_points()) and three on the others' (copies: a second plan starts
    // afresh).
    struct Strip_plan { bool ok = false; Strip_result best; std::vector<std::size_t> gid; };
    auto plan_with = [&, P_start = P, snap_start = snap, hit_start = hit, share_start = share](
                         const std::vector<bool>& four_at) {
      std::vector<double> P = P_start;
      std::vector<std::size_t> snap = snap_start, share = share_start;
      std::vector<Loop_locator::Hit> hit = hit_start;
      std::vector<bool> spread(n, false); // the points spread around a shared node: a corner's fan
      // A corner wider than 225 degrees needs three F points on its node for a fan of three
      // quads (see needs_fan_of_three), four where `four_at` asks it: where fewer project onto
      // it, the nearest neighbours (free, on their own nodes) join them.
      for(std::size_t a = 1; a + 1 < n; ++a) {
        const std::size_t k = snap[rot(a)];
        if(k == none || P[a - 1] == P[a] || !needs_fan_of_three(l, k)) continue;
        std::size_t lo = a, hi = a;
        while(hi + 1 < n && P[hi + 1] == P[a]) ++hi;
        const Point_2d corner = loop_xy[k];
        auto free_point = [&](std::size_t r) {
          return r > 0 && r + 1 < n && snap[rot(r)] == none && P[r - 1] != P[r] && P[r + 1] != P[r];
        };
        while(hi - lo + 1 < (four_at[k] ? 4u : 3u)) {
          const bool before = free_point(lo - 1), after = hi + 2 < n && free_point(hi + 1);
          if(!before && !after) break;
          const double db = before ? length_2d(minus_2d(F[rot(lo - 1)], corner)) : HUGE_VAL;
          const double da = after ? length_2d(minus_2d(F[rot(hi + 1)], corner)) : HUGE_VAL;
          const std::size_t r = db <= da ? --lo : ++hi;
          P[r] = P[a];
          snap[rot(r)] = k;
        }
        a = hi;
      }
      for(std::size_t a = 0; a < n;) {
        std::size_t b = a;
        while(b + 1 < n && P[b + 1] == P[a]) ++b;
        const bool at_end = P[a] >= O + L;
        if(b == a && !at_end) { ++a; continue; }
        const double p0 = P[a];
        const double before = a == 0 ? p0 : P[a - 1];
        const double after = b + 1 < n ? P[b + 1] : O + L;
        // the anchor keeps the node; at the start it must stay first, at the end nothing may
        // reach the start again
        std::size_t anchor = a == 0 ? 0 : (at_end ? n : (a + b) / 2);
        // Around a corner wider than 225 degrees three of them (or four: `four_at`) stay on
        // the corner's node. The pairing can make a node the apex of one F triangle per gap it
        // bounds: two spread nodes leave the corner two quads, over 112.5 degrees each; three F
        // points on it make a fan of three (paper Fig. 8(d)).
        std::size_t last_kept = anchor;
        if(!at_end && snap[rot(a)] != none && needs_fan_of_three(l, snap[rot(a)])) {
          const std::size_t k = snap[rot(a)], kept = four_at[k] ? 4 : 3;
          std::size_t first_kept = a == 0 ? 0 : (std::max)(a, anchor - 1);
          // a needle's F points wrap around its tip, so neither the bisector nor the fan's
          // parallelogram below means much there (the 6-degree spike test: 168 degrees with them)
          const bool needle = domain_angle(l, k) > 340.0;
          // of more, those whose middle lies nearest the corner's bisector
          if(a != 0 && b - a + 1 > kept && !needle) {
            const Point_2d C = loop_xy[k];
            const Point_2d bis = right_bisector(loop_xy[(k + nv - 1) % nv], C, loop_xy[(k + 1) % nv]);
            double best = HUGE_VAL;
            for(std::size_t s = a; s + kept - 1 <= b; ++s) {
              Point_2d mid = normalized_2d(minus_2d(F[rot(s + 1)], C));
              if(kept == 4) {
                const Point_2d other = normalized_2d(minus_2d(F[rot(s + 2)], C));
                mid = normalized_2d(Point_2d{ mid.x + other.x, mid.y + other.y });
              }
              const double d = dot_2d(mid, bis); // -1 on the bisector
              if(d < best) { best = d; first_kept = s; }
            }
          }
          last_kept = (std::min)(b, first_kept + kept - 1);
          anchor = first_kept;
          if(last_kept == first_kept + 2 && !needle)
            open_fan(c, rot(first_kept), rot(first_kept + 1), rot(last_kept), loop_xy[k],
                     loop_xy[(k + nv - 1) % nv], loop_xy[(k + 1) % nv]);
        }
        auto spacing = [&](std::size_t r1, std::size_t r2) {
          return length_2d(minus_2d(F[rot(r1)], F[rot(r2)]));
        };
        if(anchor > a) { // a .. anchor-1 go before p0
          const std::size_t cnt = (anchor == n ? b + 1 : anchor) - a;
          const double room = (p0 - before) / double(cnt + 1);
          double s = p0;
          for(std::size_t r = (anchor == n ? b + 1 : anchor); r-- > a;) {
            s -= (std::min)(room, spacing(r, r + 1 < n ? r + 1 : r));
            P[r] = s;
            snap[rot(r)] = none;
            hit[rot(r)] = locate_param(l, s);
          }
        }
        if(anchor < n && b > last_kept) { // last_kept+1 .. b go after p0
          const double room = (after - p0) / double(b - last_kept + 1);
          double s = p0;
          for(std::size_t r = last_kept + 1; r <= b; ++r) {
            s += (std::min)(room, spacing(r, r - 1));
            P[r] = s;
            snap[rot(r)] = none;
            hit[rot(r)] = locate_param(l, s);
          }
        }
        for(std::size_t r = a; r <= b; ++r) {
          share[r] = r > anchor && r <= last_kept ? anchor : none;
          spread[r] = true;
        }
        a = b + 1;
      }

      // candidate nodes, by parameter from O: loop vertices and the F points' own projections
      struct Node { double param; std::size_t vertex; std::size_t owner; Point_2d xy; bool keep; };
      std::vector<Node> nodes;
      std::vector<bool> snapped(nv, false);
      for(std::size_t r = 0; r < n; ++r)
        if(share[r] == none && snap[rot(r)] != none) snapped[snap[rot(r)]] = true;
      for(std::size_t k = 0; k < nv; ++k) {
        double s = std::fmod(m_locator->arc(l, k) - O, L);
        if(s < 0) s += L;
        nodes.push_back(Node{ O + s, k, none, loop_xy[k], snapped[k] || is_feature(l, k) });
      }
      for(std::size_t r = 0; r < n; ++r)
        if(share[r] == none && snap[rot(r)] == none && P[r] < O + L * (1 - 1e-12))
          nodes.push_back(Node{ P[r], none, r, hit[rot(r)].point, true });
      std::stable_sort(nodes.begin(), nodes.end(), [](const Node& x, const Node& y) {
        return x.param < y.param || (x.param == y.param && x.vertex != none && y.vertex == none);
      });
      // a projection on a vertex (to rounding) is that vertex; a second one shares it
      std::vector<std::size_t> alias_vertex(n, none);
      {
        const double tol = (std::max)(1e-9 * L, 1e-8 * m_locator->diagonal()); // verify_mesh merges at 1e-9 of the diagonal
        std::vector<Node> merged;
        for(const Node& nd : nodes) {
          if(!merged.empty() && nd.param - merged.back().param <= tol
             && (nd.vertex == none) != (merged.back().vertex == none)) {
            const bool back_is_vertex = merged.back().vertex != none;
            Node vertex_node = back_is_vertex ? merged.back() : nd;
            const std::size_t owner = back_is_vertex ? nd.owner : merged.back().owner;
            if(vertex_node.owner == none) vertex_node.owner = owner;
            else alias_vertex[owner] = vertex_node.vertex;
            vertex_node.keep = true;
            merged.back() = vertex_node;
            continue;
          }
          merged.push_back(nd);
        }
        nodes = std::move(merged);
      }
      // Loop vertices that are no corners (they turn the boundary by less than the feature
      // angle) and hold no node may be left out where the chord between the kept nodes around
      // them stays within the tolerance (Douglas-Peucker): that keeps the strip a ladder.
      {
        const std::size_t N = nodes.size();
        std::vector<std::size_t> kept_at;
        for(std::size_t k = 0; k < N; ++k) if(nodes[k].keep) kept_at.push_back(k);
        if(kept_at.empty()) { nodes[0].keep = true; kept_at.push_back(0); }
        std::vector<std::pair<std::size_t, std::size_t>> runs; // (a, b) kept, b after a cyclically
        for(std::size_t j = 0; j < kept_at.size(); ++j)
          runs.emplace_back(kept_at[j], kept_at[(j + 1) % kept_at.size()]);
        while(!runs.empty()) {
          auto [a, b] = runs.back();
          runs.pop_back();
          const std::size_t len = (b + N - a) % N == 0 ? N : (b + N - a) % N;
          const Point_2d A = nodes[a].xy, B = nodes[b].xy;
          const double chord = length_2d(minus_2d(B, A));
          const double tol = m_chord_tolerance;
          double worst = -1;
          std::size_t at = none;
          for(std::size_t j = 1; j < len; ++j) {
            const std::size_t k = (a + j) % N;
            const double d = point_segment_distance(nodes[k].xy, A, B);
            if(d > worst) { worst = d; at = k; }
          }
          if(at == none) continue;
          if(worst > tol || chord == 0) {
            nodes[at].keep = true;
            runs.emplace_back(a, at);
            runs.emplace_back(at, b);
          }
        }
      }
      // A kept loop vertex wider than 135 degrees that no F point projects onto may become the
      // middle of a fan of boundary edges, a quad with the vertex's own angle: a coarse polygon's
      // vertices, kept for the chord tolerance and turning by less than the feature angle, are
      // about as many as the F points (a 24-gon of radius 1 had 8 quads at 165 degrees). Such a
      // vertex (of those marked in `at`) takes over the node of the nearer projection beside it
      // in the chain; the first node stays the first F point's, and those spread around a corner
      // stay its fan's. The chord that then spans the projection's place must keep the nodes
      // under it within the tolerance.
      auto take_over_projection_nodes = [&](std::vector<Node>& candidates, std::vector<std::size_t>& alias,
                                            const std::vector<bool>& at) {
        const std::size_t N = candidates.size();
        std::vector<std::size_t> kept;
        for(std::size_t k = 0; k < N; ++k)
          if(candidates[k].keep) kept.push_back(k);
        const std::size_t nk = kept.size();
        // the nearest node kept before (step N - 1) or after (step 1) candidate k
        auto kept_beside = [&](std::size_t k, std::size_t step) {
          do k = (k + step) % N; while(!candidates[k].keep);
          return k;
        };
        auto chord_within_tolerance_without = [&](std::size_t k) {
          const std::size_t a = kept_beside(k, N - 1), b = kept_beside(k, 1);
          for(std::size_t i = (a + 1) % N; i != b; i = (i + 1) % N)
            if(point_segment_distance(candidates[i].xy, candidates[a].xy, candidates[b].xy) > m_chord_tolerance)
              return false;
          return true;
        };
        for(std::size_t j = 0; j < nk; ++j) {
          Node& v = candidates[kept[j]];
          if(v.vertex == none || !at[v.vertex] || v.owner != none || domain_angle(l, v.vertex) <= 135.0) continue;
          std::size_t take = none;
          double nearest = HUGE_VAL;
          for(std::size_t side : { (j + nk - 1) % nk, (j + 1) % nk }) {
            const Node& p = candidates[kept[side]];
            if(!p.keep || p.vertex != none || p.owner == none || p.owner == 0 || spread[p.owner]) continue;
            const double d = std::abs(cyclic(p.param - v.param));
            if(d < nearest && chord_within_tolerance_without(kept[side])) { nearest = d; take = kept[side]; }
          }
          if(take == none) continue;
          v.owner = candidates[take].owner;
          alias[v.owner] = v.vertex;
          candidates[take].keep = false;
        }
      };
      // The pairing of the strip, from the candidate nodes (copies: a second plan starts afresh).
      auto plan_strip = [&](std::vector<Node> nodes, std::vector<std::size_t> alias_vertex,
                            const std::vector<bool>& take_over_at) {
        Strip_plan plan;
        take_over_projection_nodes(nodes, alias_vertex, take_over_at);
        std::vector<Node> chain;
        std::vector<std::size_t> chain_of_node(nodes.size(), none);
        for(std::size_t k = 0; k < nodes.size(); ++k)
          if(nodes[k].keep) { chain_of_node[k] = chain.size(); chain.push_back(nodes[k]); }
        const std::size_t M0 = chain.size();
        std::vector<std::size_t> gid(M0);
        for(std::size_t k = 0; k < M0; ++k)
          gid[k] = chain[k].vertex != none ? input_vertex_point(l, chain[k].vertex)
                                           : point_on_edge(l, hit[rot(chain[k].owner)].edge, hit[rot(chain[k].owner)].t);
        std::vector<std::size_t> node_of_vertex(nv, none), node_of_owner(n, none);
        for(std::size_t k = 0; k < M0; ++k) {
          if(chain[k].vertex != none) node_of_vertex[chain[k].vertex] = k;
          if(chain[k].owner != none) node_of_owner[chain[k].owner] = k;
        }
        std::vector<std::size_t> g(n);
        for(std::size_t r = 0; r < n; ++r) {
          if(share[r] != none) { g[r] = g[share[r]]; continue; }
          if(P[r] >= O + L * (1 - 1e-12)) { g[r] = M0; continue; } // projects past the start
          g[r] = snap[rot(r)] != none ? node_of_vertex[snap[rot(r)]]
                 : alias_vertex[r] != none ? node_of_vertex[alias_vertex[r]] : node_of_owner[r];
          if(g[r] == none) g[r] = r > 0 ? g[r - 1] : 0;
          if(r > 0 && g[r] < g[r - 1]) g[r] = g[r - 1];
        }
        if(g[0] != 0)
          return plan; // not ok: the chain is out of order

        const std::size_t fbase = m_first_base[c];
        std::vector<std::size_t> fid(n);
        for(std::size_t r = 0; r < n; ++r) fid[r] = fbase + rot(r);

        std::vector<double> gparam(gid.size());
        for(std::size_t k = 0; k < gid.size(); ++k) gparam[k] = chain[k].param;
        // n F edges and M G edges make n + M triangles, paired into quads. Every gap may take one
        // more chain node, in the middle of its longest edge (on the loop there, or on a left-out
        // loop vertex near it): the pairing decides where. It switches a ladder of quads between
        // its two phases, and makes an odd triangle count even, where that costs least.
        auto solve = [&]() {
          const std::size_t M0 = gid.size();
          std::vector<Extra_node> extra(n);
          struct Site { std::size_t vertex; double param; };
          std::vector<Site> sites(n);
          const std::size_t first_candidate = m_xy.size();
          for(std::size_t r = 0; r < n; ++r) {
            const std::size_t g0 = g[r], k = (r + 1 < n ? g[r + 1] : M0) - g0;
            if(g0 >= M0 || k == 0) continue;
            std::size_t e = 0;
            double longest = -1;
            for(std::size_t j = 0; j < k; ++j) {
              const double len = length_2d(minus_2d(m_xy[gid[(g0 + j + 1) % M0]], m_xy[gid[g0 + j]]));
              if(len > longest) { longest = len; e = j; }
            }
            const double a = gparam[g0 + e], b = g0 + e + 1 < M0 ? gparam[g0 + e + 1] : gparam[0] + L;
            const double mid = 0.5 * (a + b);
            const Loop_locator::Hit h = locate_param(l, mid);
            // a left-out loop vertex near the middle keeps the input's own point
            Site site{ none, mid };
            Point_2d xy = h.point;
            double nearest = 0.25 * (b - a);
            for(std::size_t v : { h.edge, (h.edge + 1) % nv }) {
              const double sv = mid + cyclic(m_locator->arc(l, v) - mid);
              if(std::abs(sv - mid) < nearest) {
                nearest = std::abs(sv - mid);
                site = Site{ v, sv };
                xy = loop_xy[v];
              }
            }
            sites[r] = site;
            extra[r] = Extra_node{ e, m_xy.size() };
            if(site.vertex != none) { // the pairing costs its angle as the input vertex it is
              m_corner_angle.resize(m_xy.size() + 1, std::numeric_limits<double>::quiet_NaN());
              m_corner_angle[m_xy.size()] = domain_angle(l, site.vertex);
            }
            m_xy.push_back(xy);
          }
          Strip_result res = pair_strip(fid, gid, g, extra);
          // the candidates had ids of their own past the mesh's points (the cost cache knows quads
          // by their ids); the chosen ones become mesh points
          m_xy.resize(first_candidate);
          m_corner_angle.resize((std::min)(m_corner_angle.size(), first_candidate));
          for(auto it = m_cost_cache.begin(); it != m_cost_cache.end();) {
            bool candidate = false;
            for(std::size_t v : it->first) candidate = candidate || v >= first_candidate;
            it = candidate ? m_cost_cache.erase(it) : std::next(it);
          }
          std::vector<std::size_t> real_id(n, none); // by candidate id - first_candidate
          for(std::size_t r = n; r-- > 0;) { // from the back: earlier chain positions stay valid
            if(!res.inserted[r]) continue;
            std::size_t id;
            if(sites[r].vertex != none) {
              id = input_vertex_point(l, sites[r].vertex);
            } else {
              const Loop_locator::Hit h = locate_param(l, sites[r].param);
              id = point_on_edge(l, h.edge, h.t);
            }
            real_id[extra[r].id - first_candidate] = id;
            const std::size_t after = g[r] + extra[r].edge;
            gid.insert(gid.begin() + std::ptrdiff_t(after + 1), id);
            gparam.insert(gparam.begin() + std::ptrdiff_t(after + 1), sites[r].param);
            for(auto& x : g) if(x > after) ++x;
          }
          for(Quad& q : res.quads)
            for(std::size_t& v : q)
              if(v >= first_candidate && v - first_candidate < real_id.size()) v = real_id[v - first_candidate];
          return res;
        };
        m_cache_costs = true;
        Strip_result best = solve();
        // A fan of boundary edges that is flat (its middle node is no input vertex and lies on a
        // straight piece of the boundary) cannot be made a quad: such a node is taken out and the
        // strip paired again.
        for(int attempt = 0; attempt < 8 && best.cost.sum >= 1e12; ++attempt) {
          // a chain node that may be left out: not the first, not an input vertex
          auto removable = [&](std::size_t k) { return k != 0 && !is_input_vertex(gid[k]); };
          std::vector<std::size_t> removed;
          for(const Quad& q : best.quads) {
            std::size_t remove = none;
            if(cost(q) < 1000.0) continue;
            std::vector<std::size_t> pos;
            for(std::size_t v : q) {
              auto it = std::find(gid.begin(), gid.end(), v);
              if(it != gid.end()) pos.push_back(std::size_t(it - gid.begin()));
            }
            if(pos.size() != 3) continue;
            const std::size_t M0 = gid.size();
            // the middle node if it may go, else an end of the fan: with one node fewer nearby the
            // pairing can put the fan elsewhere
            for(std::size_t mid : pos) {
              const bool has_prev = std::find(pos.begin(), pos.end(), (mid + M0 - 1) % M0) != pos.end();
              const bool has_next = std::find(pos.begin(), pos.end(), (mid + 1) % M0) != pos.end();
              if(!has_prev || !has_next) continue;
              for(std::size_t k : { mid, (mid + M0 - 1) % M0, (mid + 1) % M0 })
                if(remove == none && removable(k) && chord_within_tolerance(l, gid, gparam, k)) remove = k;
            }
            if(remove != none) removed.push_back(remove);
          }
          if(removed.empty()) break;
          std::sort(removed.rbegin(), removed.rend());
          removed.erase(std::unique(removed.begin(), removed.end()), removed.end());
          auto erase_node = [&](std::size_t remove) {
            gid.erase(gid.begin() + std::ptrdiff_t(remove));
            gparam.erase(gparam.begin() + std::ptrdiff_t(remove));
            for(auto& x : g) if(x >= remove) --x;
          };
          for(std::size_t remove : removed) // from the back: earlier positions stay valid
            erase_node(remove);
          // An odd triangle count would make the pairing put a node back, likely in the same
          // gap and with it the flat fan: a neighbour of a removed node goes too, if it may.
          if((n + gid.size()) % 2 != 0) {
            const std::size_t M1 = gid.size();
            std::size_t extra = none;
            for(std::size_t j = 0; j < removed.size() && extra == none; ++j) {
              // the removed node's successor now sits where it was (positions before it shifted)
              const std::size_t at = (removed[j] - (removed.size() - 1 - j)) % M1;
              for(std::size_t k : { at, (at + M1 - 1) % M1 })
                if(extra == none && removable(k) && chord_within_tolerance(l, gid, gparam, k)) extra = k;
            }
            if(extra != none) erase_node(extra);
          }
          best = solve();
        }
        plan.ok = true;
        plan.best = std::move(best);
        plan.gid = std::move(gid);
        return plan;
      };
      // The vertices take over only where the pairing leaves a quad out of range, and the strip
      // is paired again only if that lowers its cost: elsewhere the pairing may do better by
      // switching phase at a vertex. First at the vertices a pairing leaves the middle of a fan
      // out of range (the new pairing may leave one at another vertex: a few rounds); if fans
      // remain, at every vertex at once (a coarse polygon's fans move round by round).
      std::vector<bool> take_over_at(nv, false);
      Strip_plan plan = plan_strip(nodes, alias_vertex, take_over_at);
      if(plan.ok && plan.best.cost.worst > 45.0 + angle_tolerance) {
        // the loop vertices at such fans in a pairing (a pairing may add input vertices to the mesh)
        auto fan_vertices = [&](const Strip_plan& p) {
          std::unordered_map<std::size_t, std::size_t> loop_vertex_of_point;
          for(std::size_t k = 0; k < nv; ++k) {
            auto it = m_input_vertex.find(m_loops.loops[l].vertices[k]);
            if(it != m_input_vertex.end()) loop_vertex_of_point[it->second] = k;
          }
          std::vector<std::size_t> fans;
          for(const Quad& q : p.best.quads) {
            const int k = fixed_angle_out_of_range(q);
            auto it = k < 0 ? loop_vertex_of_point.end() : loop_vertex_of_point.find(q[std::size_t(k)]);
            if(it != loop_vertex_of_point.end()) fans.push_back(it->second);
          }
          return fans;
        };
        Strip_plan latest = plan;
        for(int round = 0; round < 4; ++round) {
          bool more = false;
          for(std::size_t k : fan_vertices(latest))
            if(!take_over_at[k]) more = take_over_at[k] = true;
          if(!more) break;
          latest = plan_strip(nodes, alias_vertex, take_over_at);
          if(!latest.ok) break;
          if(latest.best.cost < plan.best.cost) plan = latest;
        }
        if(!fan_vertices(plan).empty()) {
          Strip_plan everywhere = plan_strip(nodes, alias_vertex, std::vector<bool>(nv, true));
          if(everywhere.ok && everywhere.best.cost < plan.best.cost) plan = std::move(everywhere);
        }
      }
      return plan;
    };
    // The mesh points of the strip's F points, which the fans move (open_fan()): a second plan
    // starts from them as they were, and the chosen plan's stay.
    const std::size_t fbase = m_first_base[c];
    auto f_points = [&]() { return std::vector<Point_2>(m_mesh.points.begin() + std::ptrdiff_t(fbase),
                                                       m_mesh.points.begin() + std::ptrdiff_t(fbase + n)); };
    auto restore_f_points = [&](const std::vector<Point_2>& saved) {
      for(std::size_t i = 0; i < n; ++i) {
        m_mesh.points[fbase + i] = saved[i];
        m_first[c][i] = m_xy[fbase + i] = to_point_2d(saved[i]);
      }
      m_cost_cache.clear(); // it knows quads by their points' ids
    };
    const std::vector<Point_2> f_start = f_points();
    Strip_plan plan = plan_with(std::vector<bool>(nv, false));
    // A corner over 270 degrees that kept a fan of two (its ladder's phase, see
    // may_take_four_fan_points()) gets four F points, if that pairs the strip better.
    if(plan.ok) {
      std::unordered_map<std::size_t, std::size_t> loop_vertex_of_point;
      for(std::size_t k = 0; k < nv; ++k) {
        auto it = m_input_vertex.find(m_loops.loops[l].vertices[k]);
        if(it != m_input_vertex.end()) loop_vertex_of_point[it->second] = k;
      }
      std::vector<bool> four_at(nv, false);
      bool any = false;
      for(const Quad& q : plan.best.quads) {
        const int k = wide_side_of_reflex_fan(q);
        auto it = k < 0 ? loop_vertex_of_point.end() : loop_vertex_of_point.find(q[std::size_t(k)]);
        if(it != loop_vertex_of_point.end() && may_take_four_fan_points(l, it->second))
          any = four_at[it->second] = true;
      }
      if(any) {
        const std::vector<Point_2> f_three = f_points();
        restore_f_points(f_start);
        Strip_plan four = plan_with(four_at);
        if(four.ok && four.best.cost < plan.best.cost) plan = std::move(four);
        else restore_f_points(f_three);
      }
    }
    m_cache_costs = false;
    m_cost_cache.clear();
    if(!plan.ok) {
      request_all(c);
      m_report.failure = "the boundary chain of a buffer strip is out of order";
      return;
    }
    const Strip_result& best = plan.best;
    const std::vector<std::size_t>& gid = plan.gid;
    if(best.cost.worst == HUGE_VAL) {
      request_all(c);
      m_report.failure = "no pairing of a buffer strip into quads";
      return;
    }
    const std::size_t M = gid.size();
    for(std::size_t k = 0; k < M; ++k)
      if(m_slide.count(gid[k]))
        m_slide[gid[k]].neighbors = { gid[(k + M - 1) % M], gid[(k + 1) % M] };
    for(const Quad& q : best.quads) {
      add_quad(q);
      ++m_report.second_layer_quads;
    }
  }

  // The F points of a corner's fan of three come from the core's notch around it and may
  // bunch on one side: the middle one then lies near the chord of the other two and the fan's
  // middle quad is flat (greenland's 300-degree corner at (255, 350.5): 25 degrees). The
  // middle F point moves towards the far corner of the parallelogram on the corner and the
  // other two while that lowers the worst of that quad and its two first-layer quads.
  //
  // The fan's outer F points come from the core too and may leave the middle quad too much of
  // the corner (a 320-degree trailing edge split 103, 144 and 73 degrees). Each then turns
  // about the corner, at its distance from it, while that lowers the worst of the middle quad,
  // the first-layer quads at it and the angles at the corner between it and the boundary (its
  // side quad's), then the middle point moves again.
  void open_fan(std::size_t c, std::size_t a, std::size_t m, std::size_t b, const Point_2d& corner,
                const Point_2d& before, const Point_2d& after)
  {
    const auto& cyc = m_cycles[c];
    auto& F = m_first[c];
    const std::size_t n = cyc.size();
    const std::size_t a0 = (a + n - 1) % n, b1 = (b + 1) % n;
    auto side_badness = [&](const Point_2d& f) { // at the corner, between f and the nearer side
      const Point_2d u = minus_2d(f, corner);
      double to_side = 180;
      for(const Point_2d& s : { before, after }) {
        const Point_2d v = minus_2d(s, corner);
        to_side = (std::min)(to_side, angle_degrees(std::abs(cross_2d(u, v)), dot_2d(u, v)));
      }
      return std::abs(to_side - 90);
    };
    auto worst = [&]() {
      return (std::max)({ quad_badness({ corner, F[b], F[m], F[a] }),
                          quad_badness({ m_xy[cyc[a]], F[a], F[m], m_xy[cyc[m]] }),
                          quad_badness({ m_xy[cyc[m]], F[m], F[b], m_xy[cyc[b]] }),
                          quad_badness({ m_xy[cyc[a0]], F[a0], F[a], m_xy[cyc[a]] }),
                          quad_badness({ m_xy[cyc[b]], F[b], F[b1], m_xy[cyc[b1]] }),
                          side_badness(F[a]), side_badness(F[b]) });
    };
    const std::array<std::size_t, 3> fan{ { a, m, b } };
    const std::array<Point_2d, 3> before_move{ { F[a], F[m], F[b] } };
    double best = worst();
    if(best <= 45.0) return;
    auto move_middle = [&]() {
      const Point_2d from = F[m];
      const Point_2d target{ F[a].x + F[b].x - corner.x, F[a].y + F[b].y - corner.y };
      Point_2d best_f = from;
      for(double t : { 1.0, 0.75, 0.5, 0.25 }) {
        F[m] = along_2d(from, target, t);
        const double w = worst();
        if(w < best) { best = w; best_f = F[m]; }
      }
      F[m] = best_f;
    };
    auto turn = [&](std::size_t i) {
      const Point_2d from = F[i];
      Point_2d best_f = from;
      for(double degrees : { -30.0, -20.0, -12.0, -6.0, -3.0, 3.0, 6.0, 12.0, 20.0, 30.0 }) {
        F[i] = turned_about_2d(from, corner, degrees * pi / 180);
        const double w = worst();
        if(w < best) { best = w; best_f = F[i]; }
      }
      F[i] = best_f;
    };
    move_middle();
    for(int pass = 0; pass < 3 && best > 45.0; ++pass) {
      turn(a);
      turn(b);
      move_middle();
    }
    for(std::size_t k = 0; k < 3; ++k) {
      const std::size_t i = fan[k];
      if(F[i].x == before_move[k].x && F[i].y == before_move[k].y) continue;
      const std::size_t id = m_first_base[c] + i;
      m_xy[id] = F[i];
      m_mesh.points[id] = m_traits.construct_point_2_object()(FT(F[i].x), FT(F[i].y));
    }
  }

  // An obtuse corner (135 to 225 degrees) whose node took one first buffer point F is split
  // by the edge from it to F (paper Fig. 8(c): that point lies on the corner's bisector). F
  // comes from a core vertex that need not face the corner, and an uneven split leaves the
  // pairing one quad over the whole corner (a 136-degree sector whose core came to a point
  // before it: 39 + 97 degrees, then one quad of 136). F moves towards the bisector, at its
  // distance from the corner, while that lowers the worst of the two halves' and its two
  // first-layer quads' deviation from 90 degrees.
  void turn_to_bisector(std::size_t c, std::size_t m, std::size_t k)
  {
    const auto& cyc = m_cycles[c];
    auto& F = m_first[c];
    const std::size_t n = cyc.size(), a = (m + n - 1) % n, b = (m + 1) % n;
    const auto& xy = m_locator->loop(m_cycle_loop[c]);
    const std::size_t nv = xy.size();
    const Point_2d& prev = xy[(k + nv - 1) % nv];
    const Point_2d& corner = xy[k];
    const Point_2d& next = xy[(k + 1) % nv];
    const double alpha = domain_angle(m_cycle_loop[c], k);
    auto worst = [&](const Point_2d& f) {
      const double half = 360.0 - right_side_angle(prev, corner, f); // the domain on the left
      return (std::max)({ std::abs(90.0 - half), std::abs(90.0 - (alpha - half)),
                          quad_badness({ m_xy[cyc[a]], F[a], f, m_xy[cyc[m]] }),
                          quad_badness({ m_xy[cyc[m]], f, F[b], m_xy[cyc[b]] }) });
    };
    double best = worst(F[m]);
    if(best <= 45.0) return;
    const Point_2d bis = right_bisector(prev, corner, next); // out of the domain
    const double r = length_2d(minus_2d(F[m], corner));
    const Point_2d target{ corner.x - r * bis.x, corner.y - r * bis.y };
    Point_2d best_f = F[m];
    for(double t : { 1.0, 0.75, 0.5, 0.25 }) {
      const Point_2d f = along_2d(F[m], target, t);
      const double w = worst(f);
      if(w < best - angle_tolerance) { best = w; best_f = f; }
    }
    if(best_f.x == F[m].x && best_f.y == F[m].y) return;
    const std::size_t id = m_first_base[c] + m;
    F[m] = m_xy[id] = best_f;
    m_mesh.points[id] = m_traits.construct_point_2_object()(FT(best_f.x), FT(best_f.y));
  }

  struct Strip_result
  {
    Cost cost;
    std::vector<Quad> quads;
    std::vector<bool> inserted; // per gap: whether it took its extra node
  };

  // the extra chain node a gap may take: after its `edge`-th chain edge, mesh id `id`
  struct Extra_node
  {
    std::size_t edge = none, id = none;
  };

  // Dynamic programming over the gaps of a strip. Gap r lies between F points r, r+1 (mesh
  // ids fid) and chain nodes g[r] .. g[r+1] (g[n] = M wraps to 0), plus its extra node if it
  // takes it; `mid` of its G triangles (apex F_r) come before its F triangle, the rest (apex
  // F_{r+1}) after. State: 0 = no triangle pending; 1 = the gap's F triangle is pending (it
  // came last); 2 = its last G triangle is; 3 = the same, that triangle's first node being
  // the gap's extra node.
  Strip_result pair_strip(const std::vector<std::size_t>& fid, const std::vector<std::size_t>& gid,
                          const std::vector<std::size_t>& g, const std::vector<Extra_node>& extra) const
  {
    const std::size_t n = fid.size(), M = gid.size();
    std::vector<std::size_t> k_of(n);
    for(std::size_t r = 0; r + 1 < n; ++r) k_of[r] = g[r + 1] - g[r];
    k_of[n - 1] = M - g[n - 1];
    auto F = [&](std::size_t r) { return fid[r % n]; };
    auto G = [&](std::size_t k) { return gid[k % M]; };
    auto node = [&](std::size_t r, bool ins, std::size_t e) { // the e-th node of gap r
      if(!ins || e <= extra[r].edge) return G(g[r] + e);
      return e == extra[r].edge + 1 ? extra[r].id : G(g[r] + e - 1);
    };
    auto triangles = [&](std::size_t r, bool ins, std::size_t mid) {
      std::vector<Triangle> t;
      const std::size_t k = k_of[r] + (ins ? 1 : 0);
      for(std::size_t e = 0; e < mid; ++e) t.push_back({ node(r, ins, e), node(r, ins, e + 1), F(r) });
      t.push_back({ F(r), node(r, ins, mid), F(r + 1) });
      for(std::size_t e = mid; e < k; ++e) t.push_back({ node(r, ins, e), node(r, ins, e + 1), F(r + 1) });
      return t;
    };
    auto last_edge_extra = [&](std::size_t r) { return extra[r].edge != none && extra[r].edge + 1 == k_of[r]; };
    auto pending = [&](std::size_t r, int state) {
      const std::size_t end = g[r] + k_of[r];
      if(state == 1) return Triangle{ F(r), G(end), F(r + 1) };
      return Triangle{ state == 3 ? extra[r].id : G(end + M - 1), G(end), F(r + 1) };
    };
    struct Step { std::size_t mid; int state; bool ins; };
    // A gap's ways to triangulate (with or without its extra node, the fan's middle) cost the
    // same whatever state the cycle starts in: each is costed once, when first reached, and
    // the runs from the four start states only add up.
    struct Option
    {
      Option(std::size_t m, bool i, std::vector<Triangle> tr) : mid(m), ins(i), t(std::move(tr)) {}
      std::size_t mid;
      bool ins;
      std::vector<Triangle> t;
      bool paired[2] = { false, false }; // by whether a pending triangle comes in
      std::vector<double> pair_costs[2];
      int out[2] = { 0, 0 };
      std::array<double, 4> with_pending = { { -1, -1, -1, -1 } }; // by incoming state
    };
    std::vector<std::vector<Option>> options(n);
    for(std::size_t r = 0; r < n; ++r)
      for(bool ins : { false, true }) {
        if(ins && extra[r].edge == none) continue;
        const std::size_t k = k_of[r] + (ins ? 1 : 0);
        for(std::size_t mid = 0; mid <= k; ++mid) options[r].emplace_back(mid, ins, triangles(r, ins, mid));
      }
    Strip_result result;
    std::vector<Step> best_steps;
    int best_start = 0;
    for(int start = 0; start < 4; ++start) {
      if(start == 2 && k_of[n - 1] == 0) continue;
      if(start == 3 && !last_edge_extra(n - 1)) continue;
      std::vector<std::array<Cost, 4>> best(n + 1);
      std::vector<std::array<Step, 4>> back(n + 1);
      best[0][start] = Cost{ 0, 0 };
      for(std::size_t r = 0; r < n; ++r)
        for(int s = 0; s < 4; ++s) {
          if(best[r][s].worst == HUGE_VAL) continue;
          const int p = s != 0 ? 1 : 0;
          for(Option& o : options[r]) {
            const auto& t = o.t;
            if(!o.paired[p]) {
              std::size_t pos = std::size_t(p);
              for(; pos + 1 < t.size(); pos += 2) o.pair_costs[p].push_back(strip_cost(merge(t[pos], t[pos + 1])));
              const std::size_t k = k_of[r] + (o.ins ? 1 : 0);
              o.out[p] = pos == t.size() ? 0 : o.mid == k ? 1 : (o.ins && last_edge_extra(r)) ? 3 : 2;
              o.paired[p] = true;
            }
            Cost cst = best[r][s];
            if(s != 0) {
              if(o.with_pending[s] < 0) o.with_pending[s] = strip_cost(merge(pending(r == 0 ? n - 1 : r - 1, s), t[0]));
              cst.add(o.with_pending[s]);
            }
            for(double c : o.pair_costs[p]) cst.add(c);
            const int out = o.out[p];
            if(cst < best[r + 1][out]) { best[r + 1][out] = cst; back[r + 1][out] = Step{ o.mid, s, o.ins }; }
          }
        }
      if(best[n][start] < result.cost) {
        result.cost = best[n][start];
        best_start = start;
        best_steps.assign(n, Step{});
        int s = start;
        for(std::size_t r = n; r > 0; --r) { best_steps[r - 1] = back[r][s]; s = back[r][s].state; }
      }
    }
    if(result.cost.worst == HUGE_VAL) return result;
    result.inserted.assign(n, false);
    Triangle in = best_start == 0 ? Triangle{} : pending(n - 1, best_start);
    bool has_in = best_start != 0;
    for(std::size_t r = 0; r < n; ++r) {
      result.inserted[r] = best_steps[r].ins;
      const auto t = triangles(r, best_steps[r].ins, best_steps[r].mid);
      std::size_t pos = 0;
      if(has_in) { result.quads.push_back(merge(in, t[0])); pos = 1; }
      for(; pos + 1 < t.size(); pos += 2) result.quads.push_back(merge(t[pos], t[pos + 1]));
      has_in = pos < t.size();
      if(has_in) in = t.back();
    }
    return result;
  }

  // the point of loop l at arclength s from its vertex 0
  Loop_locator::Hit locate_param(std::size_t l, double s) const
  {
    const double L = m_locator->length(l);
    s = std::fmod(s, L);
    if(s < 0) s += L;
    const auto& v = m_locator->loop(l);
    std::size_t lo = 0, hi = v.size();
    while(hi - lo > 1) {
      const std::size_t mid = (lo + hi) / 2;
      if(m_locator->arc(l, mid) <= s) lo = mid; else hi = mid;
    }
    const double len = m_locator->arc(l, lo + 1) - m_locator->arc(l, lo);
    Loop_locator::Hit h;
    h.loop = l;
    h.edge = lo;
    h.t = len > 0 ? (std::min)(1.0, (std::max)(0.0, (s - m_locator->arc(l, lo)) / len)) : 0.0;
    const Point_2d& a = v[lo];
    const Point_2d& b = v[(lo + 1) % v.size()];
    h.point = along_2d(a, b, h.t);
    h.dist = 0;
    return h;
  }

  // whether the chord between the chain neighbours of node k stays within the tolerance of
  // the loop between them (taking node k out must not pull the boundary away)
  bool chord_within_tolerance(std::size_t l, const std::vector<std::size_t>& gid,
                              const std::vector<double>& param, std::size_t k) const
  {
    const std::size_t M = gid.size();
    const std::size_t a = (k + M - 1) % M, b = (k + 1) % M;
    const Point_2d A = m_xy[gid[a]], B = m_xy[gid[b]];
    const double L = m_locator->length(l);
    double s0 = param[a], s1 = b > a ? param[b] : param[b] + L;
    const auto& v = m_locator->loop(l);
    for(std::size_t j = 0; j < v.size(); ++j) {
      double s = m_locator->arc(l, j);
      while(s < s0) s += L;
      if(s < s1 && point_segment_distance(v[j], A, B) > m_chord_tolerance) return false;
    }
    return point_segment_distance(m_xy[gid[k]], A, B) <= m_chord_tolerance;
  }

  // the angle of loop l at its vertex k on the domain's side (the loops have it on their left)
  double domain_angle(std::size_t l, std::size_t k) const
  {
    const auto& xy = m_locator->loop(l);
    const std::size_t nv = xy.size();
    return 360.0 - right_side_angle(xy[(k + nv - 1) % nv], xy[k], xy[(k + 1) % nv]);
  }

  // A corner wider than 225 degrees gets a fan of three quads. Over 270 two quads would each
  // have over 135 degrees; from 225 they would each have at least 112.5 and three quads fit
  // better (75 degrees or more each): near 270 the two quads' split is never even (the guitar's
  // 270-degree notch gave 110 + 160).
  bool needs_fan_of_three(std::size_t l, std::size_t k) const { return domain_angle(l, k) > 225.0; }

  // Whether a fan-of-three corner may keep four F points on its node. Of its triangles around
  // the node (one per F point, and one more), the pairing joins pairs: with three F points,
  // four triangles make three quads in one phase of the ladder beside the corner and two in
  // the other, and the ladder's run along the boundary sets the phase (on a straight coast it
  // cannot switch: a node added there would make a flat fan). Four F points make five
  // triangles, hence a fan of three in either phase (bahamas_islands' 281-degree corner at
  // (-77.94317, 24.33101) kept a fan of two, 146 degrees, round after round). Spaced alpha/5
  // apart, they give the corner alpha/5, 2 alpha/5 and 2 alpha/5 either way: within 135
  // degrees up to a corner of 337.5; below 270 a fan of two fits (at 270 only as 135 + 135
  // exactly, so 270 to rounding is taken too).
  bool may_take_four_fan_points(std::size_t l, std::size_t k) const
  {
    const double alpha = domain_angle(l, k);
    return alpha > 270.0 - angle_tolerance && alpha <= 337.5;
  }

  // a loop vertex the mesh must keep: it turns the boundary by the feature angle or more
  bool is_feature(std::size_t l, std::size_t k) const
  {
    const auto& v = m_locator->loop(l);
    const std::size_t nv = v.size();
    const double beta = right_side_angle(v[(k + nv - 1) % nv], v[k], v[(k + 1) % nv]);
    return std::abs(180.0 - beta) >= m_feature_angle;
  }

  // the mesh vertex of a chain node (an input vertex is added once, at its exact position)
  std::size_t input_vertex_point(std::size_t l, std::size_t k)
  {
    const std::size_t input = m_loops.loops[l].vertices[k];
    auto it = m_input_vertex.find(input);
    if(it != m_input_vertex.end()) return it->second;
    m_mesh.points.push_back(m_domain.points[input]);
    m_xy.push_back(to_point_2d(m_domain.points[input]));
    const std::size_t id = m_mesh.points.size() - 1;
    m_input_vertex[input] = id;
    const auto& lv = m_loops.loops[l].vertices;
    const std::size_t nv = lv.size();
    m_corner_angle.resize(id + 1, std::numeric_limits<double>::quiet_NaN());
    m_corner_angle[id] = 360.0 - right_side_angle(to_point_2d(m_domain.points[lv[(k + nv - 1) % nv]]),
                                                  to_point_2d(m_domain.points[input]),
                                                  to_point_2d(m_domain.points[lv[(k + 1) % nv]]));
    return id;
  }

  std::size_t point_on_edge(std::size_t l, std::size_t edge, double t)
  {
    const auto& lv = m_loops.loops[l].vertices;
    const Point_2& a = m_domain.points[lv[edge]];
    const Point_2& b = m_domain.points[lv[(edge + 1) % lv.size()]];
    m_mesh.points.push_back(point_between(a, b, t));
    m_xy.push_back(to_point_2d(m_mesh.points.back()));
    m_slide[m_mesh.points.size() - 1] = Slide{ l, edge, { none, none } };
    return m_mesh.points.size() - 1;
  }

  // a + t (b - a), on the line through a and b exactly under exact constructions
  Point_2 point_between(const Point_2& a, const Point_2& b, double t) const
  {
    auto x = m_traits.compute_x_2_object();
    auto y = m_traits.compute_y_2_object();
    const FT ft(t);
    return m_traits.construct_point_2_object()(x(a) + ft * (x(b) - x(a)), y(a) + ft * (y(b) - y(a)));
  }

  // a new boundary point: it may slide along its input edge between its chain neighbours
  struct Slide
  {
    std::size_t loop, edge;
    std::array<std::size_t, 2> neighbors;
  };

  Mesh& m_mesh;
  std::vector<double> m_size;
  const Domain_2<K>& m_domain;
  const Domain_loops_2<K>& m_loops;
  K m_traits;
  std::unique_ptr<Loop_locator> m_locator;
  // the quads at each vertex from match_loops() to apply_boundary_templates(), which add none
  std::unique_ptr<Vertex_quads> m_quads_at;
  std::vector<Point_2d> m_xy;
  std::vector<Point_2d> m_cleared_xy; // m_xy before apply_boundary_templates(), until apply_connectivity_templates()
  std::vector<std::vector<std::size_t>> m_cycles;
  std::vector<std::size_t> m_cycle_loop;
  std::vector<std::vector<Point_2d>> m_first;
  std::vector<std::size_t> m_first_base;
  std::vector<std::size_t> m_f_core; // core vertex of each first buffer point
  std::unordered_map<std::size_t, std::size_t> m_input_vertex;
  std::vector<double> m_corner_angle; // per mesh point: its input corner's angle, or NaN
  std::unordered_map<std::size_t, Slide> m_slide;
  std::vector<char> m_on_cycle; // per core point
  std::vector<char> m_repaired; // per point
  std::vector<char> m_fixed;    // per core point: a domain's isolated point, which never moves
  std::vector<char> m_shaped;   // per core point: an interior one the templates moved
  struct Quad_hash
  {
    std::size_t operator()(const Quad& q) const
    {
      std::size_t h = 0;
      for(std::size_t v : q) h = h * 0x9E3779B97F4A7C15ull + v;
      return h ^ (h >> 29);
    }
  };
  // quad costs while a strip is paired (its points do not move meanwhile)
  mutable std::unordered_map<Quad, double, Quad_hash> m_cost_cache;
  bool m_cache_costs = false;
  bool m_first_built = false;
  std::size_t m_core_points = 0;
  // the first quad of the first buffer layer and of the second (the core's come before)
  std::array<std::size_t, 2> m_layer_begin{ { std::size_t(-1), std::size_t(-1) } };
  double m_feature_angle = 20.0;  // turning (degrees) that makes a loop vertex a corner
  double m_chord_tolerance = 0;   // how far the mesh boundary may leave the input's
  Buffer_report m_report;
  Refinement_requests m_requests;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_LAYERS_H
