// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The buffer's local min-max angle optimisation, run after the second buffer layer. It is not
// in the paper, whose layers place their points once: here buffer vertices move (boundary ones
// slide along their input edge) while that lowers the invalid, out-of-range and worst quads
// around them, and no move makes a quad invalid.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_OPTIMIZER_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_OPTIMIZER_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/wedge_winding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The optimisation of one buffer zone (see the file comment).
template <class K>
class Buffer_optimizer : Buffer_tolerances
{
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Quad_vertices Quad;
  typedef std::pair<std::size_t, std::size_t> Wedge; // a corner at a vertex: (from, to) vertices

public:
  explicit Buffer_optimizer(Buffer_zone<K>& zone)
    : m_zone(zone), m_quads_at(zone.mesh.quads, zone.mesh.points.size()),
      m_min_edge2(square(min_edge_length(zone))), m_dirty(zone.mesh.points.size(), 1),
      m_dirty_next(zone.mesh.points.size(), 0)
  {}

  /// Local min-max angle optimisation of the buffer: the first buffer points move freely, the
  /// new boundary points slide along their input edge, the core's boundary vertices move too;
  /// a move is kept only if it lowers the largest deviation from 90° of the quads around the
  /// vertex and keeps them convex and unfolded. Then, around each quad still outside
  /// [45°, 135°], a move that keeps that deviation may lower the excess of the angles out,
  /// and the core vertices within two quads of it may move too. Input vertices and
  /// `fixed_points` (a domain's isolated points) never move.
  void optimize(const std::vector<std::size_t>& fixed_points, int passes = 12)
  {
    const std::vector<std::size_t> movable = movable_vertices();
    // Two courses: moves lowering the excess from the start, and the min-max moves first,
    // then those lowering the excess around the quads still out; the second is kept if it is
    // better. Where the moves lock each other the order decides, and each course mends quads
    // the other leaves out. Elsewhere the second would repeat the first's moves: it starts
    // afresh only within three quads of those the first left out or invalid.
    const std::vector<Point_2d> start = m_zone.xy;
    m_by_excess = true;
    run_passes(movable, passes);
    const std::vector<std::size_t> redo = ring(ring(ring(vertices_of_quads_out(true))));
    if(!redo.empty()) {
      const Local excess_first = outcome();
      const std::vector<Point_2d> excess_first_xy = m_zone.xy;
      restart(redo, start);
      m_by_excess = false;
      run_passes(movable, passes);
      m_by_excess = true;
      for(std::size_t v : ring(vertices_of_quads_out(false))) m_dirty[v] = 1;
      run_passes(movable, passes);
      if(!(outcome() < excess_first)) { // where its passes ended: no vertex is to be tried
        m_zone.xy = excess_first_xy;
        std::fill(m_dirty.begin(), m_dirty.end(), 0);
      }
    }
    const std::vector<std::size_t> repair = repair_vertices(fixed_points);
    std::vector<Point_2d> before(repair.size());
    for(std::size_t k = 0; k < repair.size(); ++k) before[k] = m_zone.xy[repair[k]];
    if(!repair.empty()) {
      std::vector<std::size_t> all = repair;
      all.insert(all.end(), movable.begin(), movable.end());
      // the first passes left every clean vertex where a try would leave it again: only the
      // repair's own vertices join the dirty ones (same moves, far fewer tries)
      for(std::size_t v : repair) m_dirty[v] = 1;
      run_passes(all, passes);
    }
    write_back(movable);
    keep_repair_if_valid(repair, before);
  }

private:
  // (invalid quads around v, quads outside [45, 135] around it, the worst deviation from
  // 90 degrees, the excess of their angles out), compared in this order: no move may make a
  // quad invalid. A move must lower the worst by more than rounding (1e-9 degrees is within it
  // on small cells far from the origin): the same moves on a translated domain. With
  // `by_excess`, one that leaves the worst as it is may lower the excess: where a quad has two
  // corners out, each vertex's move mends one and leaves the worst to the other's.
  struct Local
  {
    int invalid = 0, out = 0;
    Deviation worst;
    double excess = 0;
    bool by_excess = false;
    bool operator<(const Local& o) const
    {
      if(invalid != o.invalid) return invalid < o.invalid;
      if(out != o.out) return out < o.out;
      if(worst.below(o.worst, angle_tolerance)) return true;
      if(worst.above(o.worst, angle_tolerance) || !by_excess) return false;
      return excess < o.excess - angle_tolerance;
    }
    // counts quad q (its cost b) in
    void add(const Deviation& b, const Buffer_zone<K>& zone, const Quad& q)
    {
      worst = Deviation::larger(worst, b);
      if(b.is_penalty()) {
        ++invalid;
      } else if(out_of_range(b)) {
        ++out;
        excess += zone.quad_excess(q);
      }
    }
  };

  // deviation_out_of_range() of a Deviation: cosines this far either side of sin(45 degrees),
  // 0.70710678, are over 6e-6 degrees from 45, far beyond verifier_slack, and decide alone
  static bool out_of_range(const Deviation& d)
  {
    if(d.is_cos && d.value < 0.7071067) return false;
    if(d.is_cos && d.value > 0.7071069) return true;
    return deviation_out_of_range(d.in_degrees());
  }

  static double square(double x) { return x * x; }

  // The shortest edge a move may leave: above the whole-mesh check's merge distance (1e-9 of
  // the diagonal), and well below the edges of the finest cells, so that a domain's smallest
  // features keep room to move.
  static double min_edge_length(const Buffer_zone<K>& zone)
  {
    double finest = HUGE_VAL;
    for(double h : zone.local_size)
      if(h > 0) finest = (std::min)(finest, h);
    return (std::max)(2e-9 * zone.locator->diagonal(), (std::min)(1e-8 * zone.locator->diagonal(), finest / 4));
  }

  // the core's boundary vertices and the buffer's points but the input vertices and those in
  // no quad (boundary nodes of the strip plans not taken)
  std::vector<std::size_t> movable_vertices() const
  {
    std::vector<std::size_t> movable;
    for(const auto& cyc : m_zone.cycles)
      movable.insert(movable.end(), cyc.begin(), cyc.end());
    for(std::size_t v = m_zone.core_points; v < m_zone.mesh.points.size(); ++v)
      if(!m_zone.is_input_vertex(v) && m_quads_at[v].size() != 0)
        movable.push_back(v);
    return movable;
  }

  // Whether every quad at v is strictly convex with each angle in [60.01, 119.99] degrees:
  // then the worst deviation from 90 of local_cost(v) is under 30 (quad_well_within())
  bool quads_well_within_60_120(std::size_t v) const
  {
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_zone.mesh.quads[q];
      if(!quad_well_within({ m_zone.xy[Q[0]], m_zone.xy[Q[1]], m_zone.xy[Q[2]], m_zone.xy[Q[3]] }, 0.2498)) return false;
    }
    return true;
  }

  // The Local cost of the quads at v. With `bound`, the caller keeps the result only if it is
  // below *bound: every quad only adds to the cost, so the sum stops as soon as it cannot be
  // (same decisions, far fewer quads).
  Local local_cost(std::size_t v, const Local* bound) const
  {
    Local r;
    r.by_excess = m_by_excess;
    bool convex = true;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_zone.mesh.quads[q];
      const Deviation b = m_zone.quad_deviation(Q);
      convex = convex && !b.is_penalty();
      r.add(b, m_zone, Q);
      const int c = corner_of(Q, v);
      // an edge collapsing to a point keeps the angles fine but merges two vertices: the
      // whole-mesh check rejects vertices within 1e-9 of the diagonal
      for(int side : { 1, 3 }) {
        const Vector_2d d = m_zone.xy[Q[(c + side) % 4]] - m_zone.xy[v];
        if(d.squared_length() <= m_min_edge2) ++r.invalid;
      }
      if(bound != nullptr && !(r < *bound)) return r;
    }
    if(folded_at(v, convex)) r.invalid += 1 << 20;
    if(near_next_input_edge(v)) ++r.invalid;
    return r;
  }

  // Whether v slides on an input edge within the shortest edge's length of an input edge
  // meeting it at an end: beside a needle's tip or a slit's, where that edge folds back, a
  // point near the tip is nearly on the other side too, and the whole-mesh check sees a node
  // on the other side's edge.
  bool near_next_input_edge(std::size_t v) const
  {
    const auto* slide = m_zone.slide(v);
    if(slide == nullptr) return false;
    const std::vector<Point_2d>& loop = m_zone.locator->loop(slide->loop);
    const std::size_t n = loop.size(), e = slide->edge;
    auto at = [&](std::size_t k) { return loop[k % n]; };
    const auto distance2 = Approximate_kernel().compute_squared_distance_2_object();
    const Point_2d& p = m_zone.xy[v];
    return distance2(p, Segment_2d(at(e + n - 1), at(e))) < m_min_edge2
           || distance2(p, Segment_2d(at(e + 1), at(e + 2))) < m_min_edge2;
  }

  // Whether the quads at v fold over each other, decided exactly on the working positions:
  // their corners at v must cover the plane around it once (see times_wedges_cover()). A
  // point sliding on the boundary adds the outside's corner and must lie between its two
  // neighbours on the edge (they make an obtuse angle at it: on its edge a straight one); the
  // core's boundary vertices are not checked. A zero-length edge, or corners that make no
  // closed chain, are a fold. With `convex` (every quad at v strictly convex, its corner at v
  // under 180 degrees), a closed chain of at most four such corners, or two and the
  // outside's, sums to under 720 degrees: it winds once, and no angle need be summed.
  bool folded_at(std::size_t v, bool convex) const
  {
    const auto* slide = m_zone.slide(v);
    if(slide == nullptr && m_zone.is_core_boundary(v)) return false;
    const std::vector<Wedge>& chain = corner_chain(v);
    if(chain.empty()) return true;
    const Point_2d& p = m_zone.xy[v];
    if(slide != nullptr) {
      const auto& n = slide->neighbors;
      if(Approximate_kernel().angle_2_object()(m_zone.xy[n[0]], p, m_zone.xy[n[1]]) != OBTUSE) return true;
    }
    if(convex && m_quads_at[v].size() <= (slide == nullptr ? 4u : 2u)) return false;
    std::vector<std::pair<Point_2d, Point_2d>>& corners = m_wedge_points;
    corners.clear();
    for(const Wedge& w : chain) {
      if(m_zone.xy[w.first] == p || m_zone.xy[w.second] == p) return true;
      corners.emplace_back(m_zone.xy[w.first], m_zone.xy[w.second]);
    }
    return times_wedges_cover(p, corners) != 1;
  }

  // The corners at v as (from, to) vertices, each counter-clockwise from the edge to its next
  // vertex to the edge to its previous one, and for a sliding point the outside's corner from
  // the neighbour that ends their chain to the one that starts it; empty if they make no
  // closed chain. The optimiser moves points only: computed once for the vertex being tried.
  const std::vector<Wedge>& corner_chain(std::size_t v) const
  {
    if(m_chain_vertex == v) return m_chain;
    m_chain_vertex = v;
    m_chain.clear();
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_zone.mesh.quads[q];
      const int c = corner_of(Q, v);
      m_chain.emplace_back(Q[(c + 1) % 4], Q[(c + 3) % 4]);
    }
    const auto* slide = m_zone.slide(v);
    if(slide != nullptr && !add_outside_wedge(slide->neighbors, m_chain)) m_chain.clear();
    if(!closed_chain(m_chain)) m_chain.clear();
    return m_chain;
  }

  static std::ptrdiff_t wedges_from(const std::vector<Wedge>& wedges, std::size_t u)
  {
    return std::count_if(wedges.begin(), wedges.end(), [u](const Wedge& w) { return w.first == u; });
  }
  static std::ptrdiff_t wedges_to(const std::vector<Wedge>& wedges, std::size_t u)
  {
    return std::count_if(wedges.begin(), wedges.end(), [u](const Wedge& w) { return w.second == u; });
  }

  // whether each vertex starts as many of the wedges as it ends: they make closed chains
  static bool closed_chain(const std::vector<Wedge>& wedges)
  {
    for(const Wedge& w : wedges)
      if(wedges_from(wedges, w.first) != wedges_to(wedges, w.first)) return false;
    return true;
  }

  // Appends the outside's corner of a sliding point with these boundary neighbours; false if
  // one is missing or its quads' corners do not make one chain from one to the other.
  static bool add_outside_wedge(const std::array<std::size_t, 2>& neighbors, std::vector<Wedge>& wedges)
  {
    for(int k = 0; k < 2; ++k) {
      const std::size_t first = neighbors[k], last = neighbors[1 - k];
      if(first == none || last == none) return false;
      if(wedges_from(wedges, first) == 1 && wedges_to(wedges, first) == 0 && wedges_to(wedges, last) == 1
         && wedges_from(wedges, last) == 0) {
        wedges.emplace_back(last, first);
        return true;
      }
    }
    return false;
  }

  // Up to `passes` passes over `vertices`, each moving every dirty one to its best target. A
  // vertex whose quads have not changed since it was last tried would not move: only vertices
  // sharing a quad with a moved one are tried again (same result, far fewer tries).
  void run_passes(const std::vector<std::size_t>& vertices, int passes)
  {
    for(int pass = 0; pass < passes; ++pass) {
      bool improved = false;
      for(std::size_t v : vertices)
        if(m_dirty[v] && try_move(v)) {
          improved = true;
          for(std::size_t q : m_quads_at[v])
            for(std::size_t w : m_zone.mesh.quads[q])
              m_dirty[w] = m_dirty_next[w] = 1;
        }
      if(!improved) break;
      m_dirty.swap(m_dirty_next);
      std::fill(m_dirty_next.begin(), m_dirty_next.end(), 0);
    }
  }

  // Moves v, if its quads are not all within [60, 120], to the best of the steps towards its
  // targets: where it makes each quad at it a parallelogram, the turns about input corners,
  // its neighbours' mean (a Laplacian step) and the mean of the others. True if it moved.
  bool try_move(std::size_t v)
  {
    if(quads_well_within_60_120(v)) return false; // the test below, without a sine or a root
    // a recorded move passed the test below from the same state: recalled before its costs
    const Point_2d old = m_zone.xy[v];
    State_hash state;
    Point_2d to;
    if(m_zone.recall_move(state, [&] { return move_state(v); }, to)) {
      m_zone.xy[v] = to;
      return to != old;
    }
    const Local current = local_cost(v, nullptr);
    if(current.worst.in_degrees() <= 30.0) return false;
    std::vector<Point_2d>& targets = m_targets;
    targets.push_back(m_zone.parallelogram_targets(v, m_quads_at, targets));
    add_turns_about_corners(v, m_quads_at, targets);
    targets.push_back(mean_2d(targets.begin(), targets.end() - 1));
    Local best = current;
    Point_2d best_p = old;
    for(const Point_2d& t : targets)
      for(double step : { 1.0, 0.5, 0.25, 0.1 }) {
        Point_2d p = along_2d(old, t, step);
        if(!slide_to(v, p)) continue;
        m_zone.xy[v] = p;
        const Local c = local_cost(v, &best);
        m_zone.xy[v] = old;
        if(c < best) {
          best = c;
          best_p = p;
        }
      }
    m_zone.record_move(state, best_p);
    if(best_p == old) return false;
    m_zone.xy[v] = best_p;
    return true;
  }

  // What try_move(v) depends on past its first test, hashed (see move_memo.h): the pass's
  // course (by_excess), the shortest edge a move may leave, whether v is on the core's
  // boundary, its quads in order with their corners' positions and input angles and which
  // of them they share (by first appearance), and the edge v slides on with its neighbours.
  State_hash move_state(std::size_t v) const
  {
    State_hash h;
    h.add(std::uint64_t(0x0B)); // the optimiser's move, not a first point's
    h.add(std::uint64_t(m_by_excess));
    h.add(m_min_edge2);
    h.add(std::uint64_t(m_zone.is_core_boundary(v)));
    h.add(std::uint64_t(m_quads_at[v].size()));
    // a vertex's index in `seen` wherever it appears, then its position and input angle
    // where it first does (its index is then the count seen before)
    std::vector<std::size_t>& seen = m_state_vertices;
    seen.clear();
    auto add_vertex = [&](std::size_t w) {
      const auto it = std::find(seen.begin(), seen.end(), w);
      h.add(std::uint64_t(it - seen.begin()));
      if(it != seen.end()) return;
      seen.push_back(w);
      h.add(m_zone.xy[w]);
      h.add(m_zone.input_corner_angle(w));
    };
    add_vertex(v);
    for(std::size_t q : m_quads_at[v])
      for(std::size_t w : m_zone.mesh.quads[q]) add_vertex(w);
    const auto* slide = m_zone.slide(v);
    if(slide == nullptr) return h;
    h.add(std::uint64_t(slide->loop));
    h.add(std::uint64_t(slide->edge));
    for(std::size_t w : slide->neighbors) {
      if(w == none) h.add(~std::uint64_t(0));
      else add_vertex(w);
    }
    return h;
  }

  // how a course of moves left the quads the buffer stages made or changed, as a Local over
  // them all, compared without the excess
  Local outcome() const
  {
    Local r;
    for(const Quad& q : m_zone.mesh.quads)
      if(m_zone.made_or_changed(q)) r.add(m_zone.quad_deviation(q), m_zone, q);
    return r;
  }

  // `vertices` back at their place in `xy` and to be tried, no other vertex
  void restart(const std::vector<std::size_t>& vertices, const std::vector<Point_2d>& xy)
  {
    std::fill(m_dirty.begin(), m_dirty.end(), 0);
    std::fill(m_dirty_next.begin(), m_dirty_next.end(), 0);
    for(std::size_t v : vertices) {
      m_zone.xy[v] = xy[v];
      m_dirty[v] = 1;
    }
  }

  // the vertices of the quads the buffer stages made or changed that are outside [45, 135],
  // and `with_invalid` or valid
  std::vector<std::size_t> vertices_of_quads_out(bool with_invalid) const
  {
    std::vector<std::size_t> out;
    for(const Quad& q : m_zone.mesh.quads) {
      const double b = m_zone.made_or_changed(q) ? m_zone.quad_cost(q) : 0.0;
      if(deviation_out_of_range(b) && (with_invalid || b < 1000.0)) out.insert(out.end(), q.begin(), q.end());
    }
    return out;
  }

  // the vertices of the quads at `from`
  std::vector<std::size_t> ring(const std::vector<std::size_t>& from) const
  {
    std::vector<std::size_t> out;
    for(std::size_t u : from)
      for(std::size_t q : m_quads_at[u])
        out.insert(out.end(), m_zone.mesh.quads[q].begin(), m_zone.mesh.quads[q].end());
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // A quad still outside [45, 135] (often just: a core quad beside a moved notch) may be
  // mended by moving the core vertices within two quads of it too: the interior core vertices
  // there, but `fixed_points`. The core keeps its connectivity, and no move may put one of its
  // angles out of range.
  std::vector<std::size_t> repair_vertices(const std::vector<std::size_t>& fixed_points) const
  {
    std::vector<std::size_t> near_bad = ring(ring(vertices_of_quads_out(false)));
    std::vector<char> fixed(m_zone.mesh.points.size(), 0);
    for(std::size_t v : fixed_points) if(v < fixed.size()) fixed[v] = 1;
    near_bad.erase(std::remove_if(near_bad.begin(), near_bad.end(), [&](std::size_t x) {
                     return x >= m_zone.core_points || m_zone.on_cycle(x) || m_zone.is_input_vertex(x) || fixed[x];
                   }), near_bad.end());
    return near_bad;
  }

  // The repair's moves into the kernel, where the kernel's predicates have the last word: a
  // core quad they left nearly flat or not strictly convex undoes them all. The quads at the
  // vertices kept moved are checked with the buffer's (repaired_mark).
  void keep_repair_if_valid(const std::vector<std::size_t>& repair, const std::vector<Point_2d>& before)
  {
    std::vector<std::size_t> moved;
    std::vector<Point_2d> moved_from;
    std::vector<Point_2> exact_before; // for undoing: the core's points are not all doubles
    for(std::size_t k = 0; k < repair.size(); ++k)
      if(m_zone.xy[repair[k]] != before[k]) {
        moved.push_back(repair[k]);
        moved_from.push_back(before[k]);
        exact_before.push_back(m_zone.mesh.points[repair[k]]);
      }
    write_back(moved);
    bool valid = true;
    for(std::size_t v : moved)
      for(std::size_t q : m_quads_at[v]) valid = valid && m_zone.is_valid_quad(m_zone.mesh.quads[q]);
    m_zone.repaired_mark.assign(m_zone.mesh.points.size(), 0);
    for(std::size_t k = 0; k < moved.size(); ++k) {
      if(valid) {
        m_zone.repaired_mark[moved[k]] = 1;
      } else {
        m_zone.xy[moved[k]] = moved_from[k];
        m_zone.mesh.points[moved[k]] = exact_before[k];
      }
    }
  }

  // Beside an input corner, v turns about it to share the corner's angle evenly between the
  // two quads it separates there (the paper's rotated bisectors, §5): one target per corner.
  void add_turns_about_corners(std::size_t v, const Vertex_quads& quads_at,
                               std::vector<Point_2d>& targets) const
  {
    const Point_2d old = m_zone.xy[v];
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = m_zone.mesh.quads[q];
      const int c = corner_of(Q, v);
      for(int side : { 1, 3 }) {
        const std::size_t corner = Q[(c + side) % 4];
        if(!m_zone.is_input_vertex(corner)) continue;
        const Point_2d& P = m_zone.xy[corner];
        const Point_2d& w = m_zone.xy[Q[(c + 2 * side) % 4]]; // the corner's other neighbour in q
        double other = -1; // the corner's angle in the other quad at v
        for(std::size_t q2 : quads_at[v]) {
          if(q2 == q) continue;
          const Quad& R = m_zone.mesh.quads[q2];
          for(int j = 0; j < 4; ++j)
            if(R[j] == corner && (R[(j + 1) % 4] == v || R[(j + 3) % 4] == v))
              other = corner_angle_degrees(m_zone.xy[R[(j + 3) % 4]], P, m_zone.xy[R[(j + 1) % 4]]);
        }
        const double here = corner_angle_degrees(w, P, old);
        if(other < 0 || here <= 135.0) continue;
        // turn v towards w by half the difference
        const double turn = (here - other) / 2 * pi / 180;
        const Vector_2d d = (old - P), e = w - P;
        const double sense = CGAL::determinant(d, e) > 0 ? 1.0 : -1.0;
        targets.push_back(turned_about_2d(old, P, sense * turn));
      }
    }
  }

  // the optimised positions back into the kernel: boundary points exactly on their edge
  void write_back(const std::vector<std::size_t>& movable)
  {
    for(std::size_t v : movable) {
      const auto* it = m_zone.slide(v);
      if(it == nullptr) {
        m_zone.mesh.points[v] = m_zone.mesh_point(m_zone.xy[v]);
      } else {
        const auto& lv = m_zone.loops.loops[it->loop].vertices;
        const Point_2& a = m_zone.domain.points[lv[it->edge]];
        const Point_2& b = m_zone.domain.points[lv[(it->edge + 1) % lv.size()]];
        const Point_2d A = to_point_2d(a), B = to_point_2d(b);
        const Vector_2d ab = B - A;
        const double t = CGAL::scalar_product(m_zone.xy[v] - A, ab) / ab.squared_length();
        m_zone.mesh.points[v] = m_zone.point_between(a, b, t);
        m_zone.xy[v] = to_point_2d(m_zone.mesh.points[v]);
      }
    }
  }

  // for a sliding boundary point, moves `p` onto its edge strictly between its neighbours:
  // a thousandth of the way from each and twice the shortest edge a move may leave, at most a
  // tenth (a fixed tenth kept the node beside a needle's long tip edge far from the quads it
  // serves); false if there is no room
  bool slide_to(std::size_t v, Point_2d& p) const
  {
    const auto* it = m_zone.slide(v);
    if(it == nullptr) return true;
    const std::size_t a = it->neighbors[0], b = it->neighbors[1];
    if(a == none || b == none) return false;
    const Point_2d A = m_zone.xy[a], B = m_zone.xy[b];
    const Vector_2d ab = B - A;
    const double len2 = ab.squared_length();
    if(!(len2 > 0)) return false;
    const double margin = (std::min)(0.1, (std::max)(1e-3, 2 * std::sqrt(m_min_edge2 / len2)));
    const double t = (std::min)(1 - margin, (std::max)(margin, CGAL::scalar_product(p - A, ab) / len2));
    // The neighbours must lie on this point's edge (or be its ends) for the chain to stay on
    // it: within 1e-9 of its length, or the rounding of its coordinates (points on a short
    // edge far from the origin are off its line by more than 1e-9 of it).
    const std::vector<Point_2d>& loop = m_zone.locator->loop(it->loop);
    const Point_2d& E0 = loop[it->edge];
    const Point_2d& E1 = loop[(it->edge + 1) % loop.size()];
    const Vector_2d e = E1 - E0;
    const double el = length_2d(e);
    const double off_line = el * (1e-9 * el + 2 * coordinate_rounding_2d(E0, E1));
    if(std::abs(CGAL::determinant(e, A - E0)) > off_line || std::abs(CGAL::determinant(e, B - E0)) > off_line)
      return false;
    p = along_2d(A, B, t);
    return true;
  }

  Buffer_zone<K>& m_zone;
  const Vertex_quads m_quads_at;
  const double m_min_edge2; // the square of min_edge_length()
  bool m_by_excess = false;  // whether moves may lower the excess alone (Local)
  std::vector<char> m_dirty, m_dirty_next; // per point: to try in this pass, in the next
  std::vector<Point_2d> m_targets;         // try_move()'s, kept for their memory
  mutable std::size_t m_chain_vertex = none; // the vertex m_chain is corner_chain() of
  mutable std::vector<Wedge> m_chain;
  mutable std::vector<std::pair<Point_2d, Point_2d>> m_wedge_points; // folded_at()'s, for their memory
  mutable std::vector<std::size_t> m_state_vertices;                 // move_state()'s, for their memory
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_OPTIMIZER_H
