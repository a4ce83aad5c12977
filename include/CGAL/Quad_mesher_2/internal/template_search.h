// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.4 on adaptive cores: the templates' search for where a core boundary vertex still
// out of Lemma 2's range should go. On cores that are not one uniform lattice the bisector and
// the lattice's steps leave about 1% of the vertices out (quads that are not squares, transition
// templates' 45° corners): each then searches the plane around it (a ring of points, then a
// pattern search) for where the three buffer-side angles at it and its neighbours come nearest
// [112.5°, 225°]; if its own stays out, the interior core within two quads of it may give way
// (they move to keep their quads within [45°, 135°]); still out, it moves with its two
// neighbours each side (search_window()). Not near an input corner: its buffer is §5's.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_SEARCH_H
#define CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_SEARCH_H

#include <CGAL/Quad_mesher_2/internal/buffer_side_angles.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>

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

// the unit vectors at angles 2 pi k / N, k = 0 to N - 1 (computed once: the searches below
// step along them in their inner loops)
template <int N>
const std::array<Vector_2d, N>& unit_directions()
{
  static const std::array<Vector_2d, N> directions = [] {
    std::array<Vector_2d, N> d;
    for(int k = 0; k < N; ++k)
      d[std::size_t(k)] = Vector_2d(std::cos(k * Buffer_tolerances::pi / (N / 2)), std::sin(k * Buffer_tolerances::pi / (N / 2)));
    return d;
  }();
  return directions;
}

// The largest step under which every point `step` or less from p rounds to p itself: half
// the spacing of doubles below each coordinate's magnitude, the smaller.
inline double rounding_step(const Point_2d& p)
{
  auto spacing_below = [](double v) { v = std::abs(v); return v - std::nextafter(v, 0.0); };
  return 0.5 * (std::min)(spacing_below(p.x()), spacing_below(p.y()));
}

// A pattern search in the plane about `at`, the best point so far, which `consider(p)`
// replaces by p if p is better (and then returns true): 16 directions at a step from a
// twentieth of `scale` down to 1e-10 of it, doubled after a move and halved after none. At
// most 400 tries of the 16: along a ridge of the angles' maximum the moves can be tiny and
// many. It ends once `best`, the excess consider() lowers, is 0: no point can beat that; and
// once a step would round back to `at` (far from the origin, well before 1e-10 of `scale`).
template <class Consider>
void pattern_search(const Point_2d& at, double scale, const double& best, const Consider& consider)
{
  double step = 0.05 * scale;
  for(int i = 0; i < 400 && step > 1e-10 * scale && step >= rounding_step(at); ++i) {
    const Point_2d from = at;
    bool moved = false;
    for(const Vector_2d& d : unit_directions<16>()) {
      moved = consider(from + step * d) || moved;
      if(best == 0) return;
    }
    step = moved ? (std::min)(2 * step, 0.05 * scale) : step / 2;
  }
}

/// The plane search of the boundary templates on one buffer zone (see the file comment).
template <class K>
class Template_search : Buffer_tolerances
{
  typedef typename K::FT FT;
  typedef Quad_vertices Quad;

public:
  explicit Template_search(Buffer_zone<K>& zone) : m_zone(zone) {}

  // search_boundary_vertex() on every core boundary vertex, in rounds while one moves. A
  // search depends on the points within three quads of its vertex only (its neighbours on
  // the cycle, its quads, the interior that may give way and their quads): after the first
  // round, a vertex none of them moved since its last search would end where it did. A move
  // marks the vertices within three quads of it (the relation is symmetric) to search again.
  void search_boundary_vertices(const Vertex_quads& quads_at)
  {
    m_search_again.assign(m_zone.mesh.points.size(), 1);
    for(int round = 0; round < 3; ++round) {
      bool changed = false;
      for(const auto& cyc : m_zone.cycles) {
        const std::size_t n = cyc.size();
        for(std::size_t i = 0; i < n; ++i) {
          const std::size_t b = cyc[i];
          if(!m_search_again[b]) continue;
          m_search_again[b] = 0;
          if(search_boundary_vertex(cyc[(i + n - 2) % n], cyc[(i + n - 1) % n], b, cyc[(i + 1) % n],
                                    cyc[(i + 2) % n], quads_at))
            changed = true;
        }
      }
      if(!changed) break;
    }
    for(const auto& cyc : m_zone.cycles)
      for(std::size_t i = 0; i < cyc.size(); ++i)
        search_window(cyc, i, quads_at);
  }

private:
  // marks every vertex within three quads of moved point v to be searched again
  void moved(std::size_t v, const Vertex_quads& quads_at)
  {
    std::vector<std::size_t> near{ v };
    for(int ring = 0; ring < 3; ++ring) {
      const std::size_t reached = near.size();
      for(std::size_t k = 0; k < reached; ++k)
        for(std::size_t q : quads_at[near[k]])
          near.insert(near.end(), m_zone.mesh.quads[q].begin(), m_zone.mesh.quads[q].end());
      std::sort(near.begin(), near.end());
      near.erase(std::unique(near.begin(), near.end()), near.end());
    }
    for(std::size_t w : near) m_search_again[w] = 1;
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
    const Point_2d old = m_zone.xy[b];
    auto excess = [&](const Point_2d& p) { return buffer_angle_excesses(m_zone.xy[a2], m_zone.xy[a], p, m_zone.xy[c], m_zone.xy[c2]); };
    double best = excess(old);
    if(best == 0 || !out_of_lemma_2_range(m_zone.xy[a], old, m_zone.xy[c]) || m_zone.near_input_corner(b))
      return false;
    const std::vector<std::size_t> around = interior_around(b, quads_at);
    std::vector<std::size_t>& named = m_state_vertices;
    State_hash state;
    Move_memo::Moves moves;
    if(m_zone.recall_move(state, [&] { return search_state({ a2, a, b, c, c2 }, around, quads_at, named); }, moves))
      return replay(moves, b, quads_at);
    std::vector<Point_2d>& named_before = m_state_positions;
    named_before.clear();
    for(std::size_t w : named) named_before.push_back(m_zone.xy[w]);
    const double least_gain = least_search_gain(m_zone.xy[a2], m_zone.xy[a], old, m_zone.xy[c], m_zone.xy[c2]);
    const double e = 0.5 * (length_2d(old - m_zone.xy[a]) + length_2d(m_zone.xy[c] - old));
    auto ring = [&](double r, int k) { return old + (r * e) * unit_directions<12>()[std::size_t(k)]; };
    Point_2d best_p = old;
    auto consider = [&](const Point_2d& p) {
      const double x = excess(p);
      if(!(x < best - least_gain) || !admissible_boundary_position(a, b, c, p, quads_at)) return false;
      best = x;
      best_p = p;
      return true;
    };
    for(double r : { 0.05, 0.1, 0.2, 0.3, 0.45, 0.6 })
      for(int k = 0; k < 12 && best > 0; ++k)
        consider(ring(r, k));
    pattern_search(best_p, e, best, consider);
    bool reshaped = false;
    if(out_of_lemma_2_range(m_zone.xy[a], best_p, m_zone.xy[c])) {
      std::vector<std::pair<double, Point_2d>> targets; // in order of distance
      for(double r : { 0.1, 0.2, 0.3, 0.45 })
        for(int k = 0; k < 12; ++k) {
          const Point_2d p = ring(r, k);
          const double x = excess(p);
          if(x < best - least_gain && !out_of_lemma_2_range(m_zone.xy[a], p, m_zone.xy[c]))
            targets.emplace_back(x, p);
        }
      std::stable_sort(targets.begin(), targets.end(),
                       [](const auto& x, const auto& y) { return x.first < y.first; });
      for(std::size_t t = 0; t < targets.size() && t < 6 && !reshaped; ++t) {
        m_zone.xy[b] = targets[t].second;
        reshaped = admissible_boundary_position(a, b, c, targets[t].second, quads_at, false)
                   && relax_interior(around, b, quads_at);
        if(reshaped) {
          best = targets[t].first;
          best_p = targets[t].second;
          pattern_search(best_p, e, best, consider);
        }
        m_zone.xy[b] = old;
      }
    }
    if(best_p != old) {
      m_zone.xy[b] = best_p;
      m_zone.mesh.points[b] = m_zone.mesh_point(best_p);
      moved(b, quads_at);
      ++m_zone.report.searched_vertices;
    }
    for(std::size_t k = 0; k < named.size(); ++k)
      if(m_zone.xy[named[k]] != named_before[k]) moves.emplace_back(std::uint32_t(k), m_zone.xy[named[k]]);
    m_zone.record_move(state, moves);
    return best_p != old;
  }

  // What search_boundary_vertex() reads past its first tests, hashed (see move_memo.h): the
  // five cycle vertices about b, b's local size, and the quads at b and at the interior
  // `around` it, in order, with their corners' positions now and after the clearance,
  // whether they are on a cycle or fixed, and which they share. `named` lists the vertices
  // in the order they first appear.
  State_hash search_state(const std::array<std::size_t, 5>& chain, const std::vector<std::size_t>& around,
                          const Vertex_quads& quads_at, std::vector<std::size_t>& named) const
  {
    State_hash h;
    h.add(std::uint64_t(0x5E)); // a template search, not a move of one point
    named.clear();
    // a vertex's index in `named` wherever it appears, then what is known of it where it
    // first does (its index is then the count named before)
    auto name = [&](std::size_t w) {
      const auto it = std::find(named.begin(), named.end(), w);
      h.add(std::uint64_t(it - named.begin()));
      if(it != named.end()) return;
      named.push_back(w);
      h.add(m_zone.xy[w]);
      h.add(m_zone.cleared_xy[w]);
      h.add(std::uint64_t(m_zone.on_cycle(w)) | std::uint64_t(m_zone.fixed_mark[w]) << 1);
    };
    for(std::size_t w : chain) name(w);
    h.add(m_zone.local_size[chain[2]]);
    auto add_quads_at = [&](std::size_t u) {
      name(u);
      h.add(std::uint64_t(quads_at[u].size()));
      for(std::size_t q : quads_at[u])
        for(std::size_t w : m_zone.mesh.quads[q]) name(w);
    };
    add_quads_at(chain[2]);
    for(std::size_t u : around) add_quads_at(u);
    return h;
  }

  // A search recalled (search_state()): its moves made again, with their marks and counts, as
  // search_boundary_vertex() and relax_interior() make them; true if b moved
  bool replay(const Move_memo::Moves& moves, std::size_t b, const Vertex_quads& quads_at)
  {
    bool b_moved = false;
    for(const auto& [k, p] : moves) {
      const std::size_t v = m_state_vertices[k];
      m_zone.xy[v] = p;
      m_zone.mesh.points[v] = m_zone.mesh_point(p);
      moved(v, quads_at);
      if(v == b) {
        b_moved = true;
        ++m_zone.report.searched_vertices;
      } else {
        m_zone.report.shaped_interior += m_zone.shaped_mark[v] == 0 ? 1 : 0;
        m_zone.shaped_mark[v] = 1;
      }
    }
    return b_moved;
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
    auto excess_at = [&](int d) { return widened_excess_at(m_zone.xy[node(d - 1)], m_zone.xy[node(d)], m_zone.xy[node(d + 1)]); };
    if(!out_of_lemma_2_range(m_zone.xy[node(-1)], m_zone.xy[cyc[i]], m_zone.xy[node(1)]) || m_zone.near_input_corner(cyc[i]))
      return false;
    auto all_excesses = [&] {
      std::array<double, 7> excesses;
      for(int d = -3; d <= 3; ++d) excesses[std::size_t(d + 3)] = excess_at(d);
      return excesses;
    };
    auto objective = [&](bool count_first) { return score_of_excesses(all_excesses(), count_first); };
    const double start = objective(true);
    std::vector<std::size_t> movers;
    std::vector<Point_2d> before;
    for(int d = -2; d <= 2; ++d) {
      const std::size_t v = node(d);
      if(m_zone.fixed_mark[v] || m_zone.near_input_corner(v)) continue;
      movers.push_back(v);
      before.push_back(m_zone.xy[v]);
    }
    for(int sweep = 0; sweep < 6; ++sweep) {
      bool moved = false;
      for(int d = -2; d <= 2; ++d) {
        const std::size_t v = node(d);
        if(std::find(movers.begin(), movers.end(), v) == movers.end()) continue;
        const std::size_t a = node(d - 1), c = node(d + 1);
        const Point_2d old = m_zone.xy[v];
        const double e = 0.5 * (length_2d(old - m_zone.xy[a]) + length_2d(m_zone.xy[c] - old));
        const double least_gain = least_search_gain(m_zone.xy[node(d - 2)], m_zone.xy[a], old, m_zone.xy[c], m_zone.xy[node(d + 2)]);
        // v's move changes the angles at it and its two neighbours only
        const std::array<double, 7> excesses = all_excesses();
        double best = score_of_excesses(excesses, false);
        Point_2d best_p = old;
        auto consider = [&](const Point_2d& p) {
          m_zone.xy[v] = p;
          std::array<double, 7> tried = excesses;
          for(int j = d - 1; j <= d + 1; ++j) tried[std::size_t(j + 3)] = excess_at(j);
          const double x = score_of_excesses(tried, false);
          m_zone.xy[v] = old;
          if(!(x < best - least_gain) || !admissible_boundary_position(a, v, c, p, quads_at)) return false;
          best = x;
          best_p = p;
          return true;
        };
        for(double r : { 0.05, 0.1, 0.2 })
          for(const Vector_2d& u : unit_directions<12>())
            if(best > 0) consider(old + (r * e) * u);
        pattern_search(best_p, e, best, consider);
        m_zone.xy[v] = best_p;
        moved = moved || best_p != old;
      }
      if(!moved) break;
    }
    const bool kept = objective(true) < start - angle_tolerance;
    for(std::size_t k = 0; k < movers.size(); ++k) {
      const std::size_t v = movers[k];
      if(m_zone.xy[v] == before[k]) continue;
      if(kept)
        m_zone.mesh.points[v] = m_zone.mesh_point(m_zone.xy[v]);
      else
        m_zone.xy[v] = before[k];
    }
    if(kept) ++m_zone.report.searched_vertices;
    return kept;
  }

  // true if core boundary vertex b (between a and c) may lie at p: every quad at it within
  // [45, 135], none of its edges shorter than half what it was in the core the clearance left
  // (angles alone would let an edge shrink to nothing, b meeting its neighbour),
  // its boundary edges h(b)/4 from the boundary
  // (with `angles` false, all but the angles: the interior may still give way)
  bool admissible_boundary_position(std::size_t a, std::size_t b, std::size_t c, const Point_2d& p,
                                    const Vertex_quads& quads_at, bool angles = true)
  {
    const Point_2d old = m_zone.xy[b];
    m_zone.xy[b] = p;
    bool ok = true;
    for(auto q = quads_at[b].begin(); ok && q != quads_at[b].end(); ++q) {
      const Quad& Q = m_zone.mesh.quads[*q];
      if(angles) {
        std::array<Point_2d, 4> P;
        for(int k = 0; k < 4; ++k) P[k] = m_zone.xy[Q[k]];
        ok = quad_badness(P) <= 45.0 + core_slack;
      }
      const int k = corner_of(Q, b);
      for(int side : { 1, 3 }) {
        const std::size_t w = Q[(k + side) % 4];
        ok = ok && keeps_half_length(b, w, p);
      }
    }
    m_zone.xy[b] = old;
    const double clear = 0.25 * m_zone.local_size[b];
    return ok && m_zone.clear_of_boundary(m_zone.xy[a], p, clear)
           && m_zone.clear_of_boundary(p, m_zone.xy[c], clear);
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
          for(std::size_t w : m_zone.mesh.quads[q])
            if(!m_zone.on_cycle(w) && !m_zone.fixed_mark[w]) next.push_back(w);
      std::sort(next.begin(), next.end());
      next.erase(std::unique(next.begin(), next.end()), next.end());
      out.insert(out.end(), next.begin(), next.end());
      near = std::move(next);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
  }

  // whether edge v-w, v at p, keeps half the length it had after the clearance at least
  bool keeps_half_length(std::size_t v, std::size_t w, const Point_2d& p) const
  {
    return length_2d(m_zone.xy[w] - p) >= 0.5 * length_2d(m_zone.cleared_xy[w] - m_zone.cleared_xy[v]);
  }

  // the largest deviation from 90 degrees of the quads at v
  double worst_badness_at(std::size_t v, const Vertex_quads& quads_at) const
  {
    double worst = 0;
    for(std::size_t q : quads_at[v]) {
      std::array<Point_2d, 4> P;
      for(int k = 0; k < 4; ++k) P[k] = m_zone.xy[m_zone.mesh.quads[q][k]];
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
    for(std::size_t k = 0; k < around.size(); ++k) before[k] = m_zone.xy[around[k]];
    auto short_edge = [&](std::size_t v) {
      for(std::size_t q : quads_at[v]) {
        const Quad& Q = m_zone.mesh.quads[q];
        const int c = corner_of(Q, v);
        for(int side : { 1, 3 }) {
          const std::size_t w = Q[(c + side) % 4];
          if(!keeps_half_length(v, w, m_zone.xy[v]))
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
        const Point_2d old = m_zone.xy[v];
        const Point_2d lap = m_zone.parallelogram_targets(v, quads_at, targets);
        targets.push_back(mean_2d(targets.begin(), targets.end()));
        targets.push_back(lap);
        double best = current;
        Point_2d best_p = old;
        for(const Point_2d& t : targets)
          for(double step : { 1.0, 0.5, 0.25, 0.1 }) {
            m_zone.xy[v] = along_2d(old, t, step);
            const double w = worst_badness_at(v, quads_at);
            if(w < best - angle_tolerance && !short_edge(v)) {
              best = w;
              best_p = m_zone.xy[v];
            }
          }
        m_zone.xy[v] = best_p;
        moved = moved || best < current;
      }
      if(!moved) break;
    }
    bool ok = worst_badness_at(b, quads_at) <= 45.0 + core_slack;
    for(std::size_t v : around) ok = ok && worst_badness_at(v, quads_at) <= 45.0 + core_slack;
    for(std::size_t k = 0; k < around.size(); ++k) {
      const std::size_t v = around[k];
      if(m_zone.xy[v] == before[k]) continue;
      if(ok) {
        m_zone.mesh.points[v] = m_zone.mesh_point(m_zone.xy[v]);
        moved(v, quads_at);
        m_zone.report.shaped_interior += m_zone.shaped_mark[v] == 0 ? 1 : 0;
        m_zone.shaped_mark[v] = 1;
      } else {
        m_zone.xy[v] = before[k];
      }
    }
    return ok;
  }

  Buffer_zone<K>& m_zone;
  std::vector<char> m_search_again; // per point: whether search_boundary_vertices() is to search it
  std::vector<std::size_t> m_state_vertices; // search_state()'s, for their memory
  std::vector<Point_2d> m_state_positions;   // their positions before a search
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_SEARCH_H
