// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.5, the first buffer layer: B's first buffer point F lies halfway (in distance to the
// boundary) between B and the boundary, along the mean of the bisector of beta and the
// direction to the nearest boundary point, turned back towards the bisector where B's two
// first-layer angles would leave [45°, 135°]; each F then moves alone to improve its two
// first-layer quads and its two projection quads (smooth_first_points). Quads
// B_i F_i F_{i+1} B_{i+1}.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_FIRST_BUFFER_LAYER_H
#define CGAL_QUAD_MESHER_2_INTERNAL_FIRST_BUFFER_LAYER_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// The first buffer points of cycle c, moved one at a time to improve the two layers they
// will bound: their quads B_i F_i F_{i+1} B_{i+1} and the projection quads
// F_i G_i G_{i+1} F_{i+1}, G the nearest boundary point (Lemmas 3 and 4 ask that the F chain
// run nearly parallel to the boundary, so that the projections make right angles). A move is
// kept if it lowers (invalid quads, quads outside [45, 135], worst deviation from 90 degrees,
// sum of squared deviations) of the four quads at F_i; F_i stays within half its distance
// from B_i of where it started, so it cannot wander across the buffer, and does not move
// within twice the local size of a loop corner.
template <class K>
class First_point_smoothing : Buffer_tolerances
{
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
      else if(deviation_out_of_range(b)) ++out;
      worst = (std::max)(worst, b);
      sum += b * b;
    }
  };

public:
  First_point_smoothing(Buffer_zone<K>& zone, std::size_t c)
    : m_zone(zone), cyc(zone.cycles[c]), n(cyc.size()), l(zone.cycle_loop[c]), F(zone.first_points[c]),
      start(F), reach(n), G(n)
  {
    for(int k = 0; k < 8; ++k) {
      const double a = k * pi / 4;
      direction[k] = Vector_2d(std::cos(a), std::sin(a));
    }
  }

  // Up to eight passes over the F points. A try at F_i reads F and G at i and its two
  // neighbours only: it is made again only once one of them has moved (same moves, far fewer
  // tries).
  void smooth()
  {
    if(n < 3) return;
    for(std::size_t i = 0; i < n; ++i) find_reach(i);
    std::vector<char> dirty(n, 1);
    for(int pass = 0; pass < 8; ++pass) {
      bool moved = false;
      for(std::size_t i = 0; i < n; ++i) {
        if(reach[i] == 0 || !dirty[i]) continue;
        dirty[i] = 0;
        if(try_move(i)) {
          moved = true;
          dirty[(i + n - 1) % n] = dirty[i] = dirty[(i + 1) % n] = 1;
        }
      }
      if(!moved) break;
    }
  }

private:
  // F_i's boundary point G_i, and how far F_i may move: half its distance from B_i, none near
  // a loop corner (the strip fans there and its nodes are not the projections)
  void find_reach(std::size_t i)
  {
    const auto& loop_xy = m_zone.locator->loop(l);
    const std::size_t nv = loop_xy.size();
    const Loop_locator::Hit hit = m_zone.locator->closest(F[i], 2 * m_zone.local_size[cyc[i]], l);
    G[i] = hit.point;
    reach[i] = 0.5 * length_2d(F[i] - m_zone.xy[cyc[i]]);
    const double near = 2 * m_zone.local_size[cyc[i]];
    for(std::size_t step : { nv - 1, std::size_t(1) }) // backwards from the edge's start, forwards from its end
      for(std::size_t k = step == 1 ? (hit.edge + 1) % nv : hit.edge, walked = 0;
          reach[i] > 0 && walked < nv && length_2d(loop_xy[k] - hit.point) <= near;
          k = (k + step) % nv, ++walked)
        if(m_zone.is_feature(l, k)) reach[i] = 0;
  }

  // The four quads at F_i with F_i at f, its boundary point from g_at(f) (asked only when
  // needed). With `bound`, stops once the result cannot be below it: each quad only adds.
  template <class Boundary_point>
  Local local(std::size_t i, const Point_2d& f, const Boundary_point& g_at, const Local* bound) const
  {
    const std::size_t p = (i + n - 1) % n, q = (i + 1) % n;
    Local r;
    auto add = [&](const std::array<Point_2d, 4>& quad) {
      r.add(quad_badness(quad));
      return bound == nullptr || r < *bound;
    };
    if(!add({ m_zone.xy[cyc[p]], F[p], f, m_zone.xy[cyc[i]] }) || !add({ m_zone.xy[cyc[i]], f, F[q], m_zone.xy[cyc[q]] }))
      return r;
    const Point_2d g = g_at(f);
    if(add({ F[p], G[p], g, f }))
      add({ f, g, G[q], F[q] });
    return r;
  }

  // Whether the four quads at F_i are strictly convex with each angle in [70.01, 109.99]
  // degrees: then local() finds them within [70, 110] (quad_well_within())
  bool quads_well_within_70_110(std::size_t i) const
  {
    const std::size_t p = (i + n - 1) % n, q = (i + 1) % n;
    const Point_2d &b = m_zone.xy[cyc[i]], &f = F[i], &g = G[i];
    const double max_cos2 = 0.1169; // sin(20 degrees) squared is 0.11698
    return quad_well_within({ m_zone.xy[cyc[p]], F[p], f, b }, max_cos2)
           && quad_well_within({ b, f, F[q], m_zone.xy[cyc[q]] }, max_cos2)
           && quad_well_within({ F[p], G[p], g, f }, max_cos2) && quad_well_within({ f, g, G[q], F[q] }, max_cos2);
  }

  // Moves F_i, unless its quads are valid and within [70, 110], to the best of the tries:
  // towards the middle of its neighbours, and a few steps in eight directions. True if it
  // moved.
  bool try_move(std::size_t i)
  {
    if(quads_well_within_70_110(i)) return false; // the test below, without a sine or a root
    // a recorded move failed the test below from the same state: recalled before its costs
    const double h = m_zone.local_size[cyc[i]];
    State_hash state;
    Point_2d to;
    if(m_zone.recall_move(state, [&] { return move_state(i); }, to)) {
      if(to == F[i]) return false;
      F[i] = to;
      G[i] = m_zone.locator->closest(to, 2 * h, l).point;
      return true;
    }
    Local best = local(i, F[i], [&](const Point_2d&) { return G[i]; }, nullptr);
    if(best.invalid == 0 && best.out == 0 && best.worst <= 20.0) return false;
    Point_2d best_f = F[i], best_g = G[i];
    const Point_2d mid = CGAL::midpoint(F[(i + n - 1) % n], F[(i + 1) % n]);
    tries.clear();
    for(double s : { 1.0, 0.5, 0.25 })
      tries.push_back(along_2d(F[i], mid, s));
    for(double s : { 0.2, 0.1, 0.05 })
      for(const Vector_2d& d : direction)
        tries.push_back(F[i] + (s * h) * d);
    for(const Point_2d& f : tries) {
      if(length_2d(f - start[i]) > reach[i]) continue;
      Point_2d g = ORIGIN;
      auto boundary_point = [&](const Point_2d& at) { return g = m_zone.locator->closest(at, 2 * h, l).point; };
      const Local r = local(i, f, boundary_point, &best);
      if(r < best) { best = r; best_f = f; best_g = g; }
    }
    m_zone.record_move(state, best_f);
    if(best_f == F[i]) return false;
    F[i] = best_f;
    G[i] = best_g;
    return true;
  }

  // What try_move(i) depends on past its first test, hashed (see move_memo.h): B, F and G at
  // i and its two neighbours, where F_i started and how far it may go, the cell size and the
  // loop its boundary points are on. (A moved F_i's boundary point is the loop's point
  // nearest to it, as the tries found it.)
  State_hash move_state(std::size_t i) const
  {
    State_hash h;
    h.add(std::uint64_t(0xF1)); // a first point's move, not the optimiser's
    for(std::size_t j : { (i + n - 1) % n, i, (i + 1) % n }) {
      h.add(m_zone.xy[cyc[j]]);
      h.add(F[j]);
      h.add(G[j]);
    }
    h.add(start[i]);
    h.add(reach[i]);
    h.add(m_zone.local_size[cyc[i]]);
    h.add(std::uint64_t(l));
    return h;
  }

  Buffer_zone<K>& m_zone;
  const std::vector<std::size_t>& cyc;
  const std::size_t n, l;
  std::vector<Point_2d>& F;
  const std::vector<Point_2d> start; // F as first placed
  std::vector<double> reach;
  std::vector<Point_2d> G;
  std::array<Vector_2d, 8> direction; // the eight directions the tries step in
  std::vector<Point_2d> tries;       // try_move()'s, kept for their memory
};

/// Stage "buffer1" (paper §4.5) on one buffer zone: see the file comment.
template <class K>
class First_buffer_layer : Buffer_tolerances
{
public:
  explicit First_buffer_layer(Buffer_zone<K>& zone) : m_zone(zone) {}

  /// Stage "buffer1": the first buffer points and the quads B_i F_i F_{i+1} B_{i+1}.
  void build_first_layer()
  {
    m_zone.layer_begin[0] = m_zone.mesh.quads.size();
    m_zone.first_points.assign(m_zone.cycles.size(), {});
    for(std::size_t c = 0; c < m_zone.cycles.size(); ++c) {
      const auto& cyc = m_zone.cycles[c];
      const std::size_t n = cyc.size();
      auto& F = m_zone.first_points[c];
      F.resize(n);
      for(std::size_t i = 0; i < n; ++i)
        F[i] = first_point(c, i);
      First_point_smoothing<K>(m_zone, c).smooth();
      const std::size_t base = m_zone.mesh.points.size();
      for(std::size_t i = 0; i < n; ++i) {
        m_zone.add_point(F[i]);
        m_zone.first_core.push_back(cyc[i]);
      }
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t j = (i + 1) % n;
        m_zone.add_quad({cyc[i], base + i, base + j, cyc[j]});
      }
      m_zone.first_base.push_back(base);
      m_zone.first_built = true;
      m_zone.report.first_layer_quads += n;
    }
  }

private:
  // The first buffer point of core boundary vertex B = cyc[i] of cycle c: halfway (in
  // distance to the boundary) between B and the boundary, along the mean of the bisector of
  // beta and the direction to the nearest boundary point (bisectors alone converge in the
  // core's notches and cross), but no farther from the bisector than leaves B's two
  // first-layer angles, beta / 2 plus and minus the deviation, within [45, 135] with a fifth
  // to spare (Lemma 3). A notch of 90 degrees or less (beside a sharp corner, where Lemma 2
  // failed) has no such room and keeps the mean: on its bisector alone neighbouring F points
  // cross.
  Point_2d first_point(std::size_t c, std::size_t i) const
  {
    const auto& cyc = m_zone.cycles[c];
    const std::size_t n = cyc.size(), l = m_zone.cycle_loop[c];
    const Point_2d& a = m_zone.xy[cyc[(i + n - 1) % n]];
    const Point_2d& b = m_zone.xy[cyc[i]];
    const Point_2d& nb = m_zone.xy[cyc[(i + 1) % n]];
    const Loop_locator::Hit h = m_zone.locator->closest(b, 2 * m_zone.local_size[cyc[i]], l);
    const Vector_2d toward = normalized_2d(h.point - b);
    // nearest a crack's tip: straight towards it, or F could land beside the crack's sides,
    // which lie closer along the mean direction than the tip
    if(at_crack_tip(l, h)) return b + 0.5 * (h.point - b);
    const Vector_2d bis = right_bisector(a, b, nb);
    Vector_2d d = normalized_2d(0.5 * (bis + toward));
    const double beta = right_side_angle(a, b, nb) * pi / 180;
    const double limit = 0.8 * (std::min)(beta / 2 - pi / 4, 3 * pi / 4 - beta / 2);
    const double dev = std::atan2(CGAL::determinant(bis, d), CGAL::scalar_product(bis, d));
    if(limit > 0 && std::abs(dev) > limit) {
      const double t = dev > 0 ? limit : -limit;
      d = turned_2d(bis, t);
    }
    const double c_dn = (std::max)(CGAL::scalar_product(d, toward), 0.5);
    const double lambda = 0.5 * h.dist / c_dn;
    return b + lambda * d;
  }

  // whether `h`, a closest point on loop l, is the tip of a crack (is_crack_tip())
  bool at_crack_tip(std::size_t l, const Loop_locator::Hit& h) const
  {
    if(h.t > 0 && h.t < 1) return false;
    const std::size_t nv = m_zone.loops.loops[l].vertices.size();
    return is_crack_tip(m_zone.loops.loops[l], h.t == 0 ? h.edge : (h.edge + 1) % nv);
  }

  Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_FIRST_BUFFER_LAYER_H
