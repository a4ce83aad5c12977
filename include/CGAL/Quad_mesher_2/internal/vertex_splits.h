// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The vertex splits of the smoothing stage (not in the paper): the angles at an interior
// vertex of k quads sum to 360 degrees, so where six or more quads meet some angle is at most
// 60 degrees and where three meet some angle is at least 120, wherever the vertices move.
// Splitting such a vertex v into two, v1 and v2, with a new quad (a, v1, b, v2) between two of
// its edge neighbours a and b, gives v1 and v2 each a part of v's quads and a and b one quad
// more: a vertex of six quads beside one of three becomes four vertices of four quads and one
// of five. Only splits that lower the count of such vertices are made, and only where the
// quads they change keep the bound of the smoothing.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_VERTEX_SPLITS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_VERTEX_SPLITS_H

#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/mesh_smoothing.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/wedge_winding.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The vertex splits of a whole quad mesh (see the file comment). After a split, v1, v2 and
/// v's free interior edge neighbours relax; the split is kept only if every quad at them is
/// then strictly convex, with every angle in [45, 135] and aspect ratio at most 5
/// (`Smoothing_quad_shape::within_bound()`), their edges no shorter than `min_edge`, no
/// interior vertex of theirs folded, and their energy (`Smoothing_quad_shape::energy()`) no
/// higher than that of the same vertices' quads before.
class Vertex_splits
{
public:
  typedef Quad_vertices Quad;

  /// `pinned`: the vertices that may not move (input vertices, isolated points)
  Vertex_splits(std::vector<Point_2d>& xy, std::vector<Quad>& quads, const std::vector<char>& pinned, double min_edge)
    : m_xy(xy), m_quads(quads), m_pinned(pinned), m_quads_at(xy.size()), m_min_edge2(min_edge * min_edge)
  {
    for(std::size_t q = 0; q < quads.size(); ++q)
      for(std::size_t v : quads[q]) m_quads_at[v].push_back(q);
    m_on_boundary.assign(xy.size(), 0);
    for_each_boundary_edge(quads, Vertex_quads(quads, xy.size()), xy.size(), [&](std::size_t a, std::size_t b) {
      m_on_boundary[a] = m_on_boundary[b] = 1;
    });
  }

  /// Splits vertices, in sweeps over them, while a sweep splits any (each split lowers the
  /// sum of `valence_cost()`, so they end); new vertices are appended to `xy` and new quads
  /// to `quads`. Returns how many splits were made. A sweep tries a vertex again only if a
  /// split came near it since its last try: elsewhere the try would fail again.
  std::size_t split_all()
  {
    std::size_t splits = 0;
    std::vector<char> to_try(m_xy.size(), 1);
    for(bool again = true; again;) {
      again = false;
      for(std::size_t v = 0; v < m_xy.size(); ++v) {
        if(to_try[v] == 0) continue;
        to_try[v] = 0;
        if(try_split(v)) {
          ++splits;
          again = true;
          mark_near_split(v, to_try);
        }
      }
    }
    return splits;
  }

private:
  // try_split(w) reads the positions and quads within three rings of w (the ring of its
  // neighbours' quads and the folds at their corners); a split at v moves v and its
  // neighbours and changes the quads at v and at the new vertex, the last one: the outcome
  // may change within four rings of those two
  void mark_near_split(std::size_t v, std::vector<char>& to_try)
  {
    to_try.resize(m_xy.size(), 1);
    m_seen.resize(m_xy.size(), 0);
    ++m_stamp;
    std::vector<std::size_t> ring{ v, m_xy.size() - 1 }, next;
    for(std::size_t w : ring) m_seen[w] = m_stamp;
    for(int step = 0; step < 4; ++step) {
      next.clear();
      for(std::size_t w : ring)
        for(std::size_t q : m_quads_at[w])
          for(std::size_t u : m_quads[q])
            if(m_seen[u] != m_stamp) {
              m_seen[u] = m_stamp;
              next.push_back(u);
            }
      for(std::size_t w : ring) to_try[w] = 1;
      ring.swap(next);
    }
    for(std::size_t w : ring) to_try[w] = 1;
  }

  // The angles outside [60, 120] at an interior vertex of k quads after smoothing, on average
  // over the shared cases: the sum over vertices is what a split must lower.
  static double valence_cost(std::size_t k)
  {
    switch(k) {
    case 3: return 1.4;
    case 4: return 0;
    case 5: return 0.6;
    case 6: return 3.6;
    default: return k < 3 ? 4.0 : 3.6 + 2.6 * double(k - 6);
    }
  }

  // v's edge neighbours counter-clockwise, and its quads: quads[i] = (v, n_i, x_i, n_i+1)
  struct Ring
  {
    std::vector<std::size_t> neighbours, quads;
  };

  // false for a vertex on the boundary (its quads do not close around it)
  bool ring_of(std::size_t v, Ring& r) const
  {
    r.neighbours.clear();
    r.quads.clear();
    const std::vector<std::size_t>& at = m_quads_at[v];
    if(at.size() < 3) return false;
    std::size_t n = next_of(m_quads[at[0]], v);
    for(std::size_t step = 0; step < at.size(); ++step) {
      const auto q = std::find_if(at.begin(), at.end(), [&](std::size_t c) { return next_of(m_quads[c], v) == n; });
      if(q == at.end()) return false;
      r.neighbours.push_back(n);
      r.quads.push_back(*q);
      n = prev_of(m_quads[*q], v);
    }
    return n == r.neighbours.front();
  }

  static std::size_t next_of(const Quad& Q, std::size_t v) { return Q[(corner_of(Q, v) + 1) % 4]; }
  static std::size_t prev_of(const Quad& Q, std::size_t v) { return Q[(corner_of(Q, v) + 3) % 4]; }

  // not on the boundary (splits leave the boundary as it is, and add interior vertices only)
  bool interior(std::size_t v) const { return v >= m_on_boundary.size() || m_on_boundary[v] == 0; }

  struct Split
  {
    double gain;
    std::size_t i, j; // a = n_i and b = n_j
  };

  // the splits of a vertex of ring r that lower the cost, the best first: a = n_i and b = n_j
  // with i < j and 2 <= j - i <= k - 2 (v1 and v2 have at least three quads)
  std::vector<Split> splits_of(const Ring& r) const
  {
    const std::size_t k = r.neighbours.size();
    std::vector<Split> splits;
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 2; j < k && j + 2 <= i + k; ++j) {
        const std::size_t a = r.neighbours[i], b = r.neighbours[j];
        const std::size_t ka = m_quads_at[a].size(), kb = m_quads_at[b].size();
        if(!interior(a) || !interior(b)) continue;
        const double before = valence_cost(k) + valence_cost(ka) + valence_cost(kb);
        const double after = valence_cost(j - i + 1) + valence_cost(k - (j - i) + 1) + valence_cost(ka + 1)
                             + valence_cost(kb + 1);
        if(before - after > 1e-9) splits.push_back(Split{ before - after, i, j });
      }
    std::stable_sort(splits.begin(), splits.end(), [](const Split& x, const Split& y) { return x.gain > y.gain; });
    return splits;
  }

  bool try_split(std::size_t v)
  {
    if(pinned(v) || m_quads_at[v].size() < 5) return false;
    Ring r;
    if(!interior(v) || !ring_of(v, r)) return false;
    for(const Split& s : splits_of(r))
      if(split(v, r, s.i, s.j)) return true;
    return false;
  }

  double energy_of(const std::vector<std::size_t>& quads) const
  {
    double e = 0;
    for(std::size_t q : quads) e += Smoothing_quad_shape(corners(m_quads[q])).energy();
    return e;
  }

  std::array<Point_2d, 4> corners(const Quad& Q) const
  {
    return { m_xy[Q[0]], m_xy[Q[1]], m_xy[Q[2]], m_xy[Q[3]] };
  }

  // Splits v (see the file comment) with a = n_i, b = n_j: v keeps the quads from n_i to n_j
  // (as v1), a new vertex v2 takes the others, and the quad (a, v1, b, v2) is added. v1, v2
  // and v's free interior edge neighbours then relax to make room for it; the split is undone
  // unless that keeps the bound.
  bool split(std::size_t v, const Ring& r, std::size_t i, std::size_t j)
  {
    std::vector<std::size_t> movable = room_makers(v, r);
    std::vector<std::size_t> region = quads_at_any(movable);
    const double energy_before = energy_of(region);
    std::vector<Point_2d> kept;
    for(std::size_t w : movable) kept.push_back(m_xy[w]);
    const std::size_t v2 = m_xy.size();
    connect(v, v2, r, i, j);
    movable.push_back(v2);
    region.push_back(m_quads.size() - 1);
    // v1 towards n_i+1 .. n_j-1, v2 away: along the normal of a -> b, turned left
    const Point_2d& a = m_xy[r.neighbours[i]];
    const Point_2d& b = m_xy[r.neighbours[j]];
    const Vector_2d side = 0.5 * length_2d(a - b) * normalized_2d((a - b).perpendicular(COUNTERCLOCKWISE));
    for(double offset : { 0.3, 0.5 }) {
      for(std::size_t m = 0; m < kept.size(); ++m) m_xy[movable[m]] = kept[m];
      m_xy[v] = kept[0] + offset * side;
      m_xy[v2] = kept[0] - offset * side;
      relax(movable);
      if(keeps_the_bound(region) && energy_of(region) <= energy_before) return true;
    }
    for(std::size_t m = 0; m < kept.size(); ++m) m_xy[movable[m]] = kept[m];
    disconnect(v, v2, r, r.neighbours[i], r.neighbours[j]);
    return false;
  }

  // v, then the free interior vertices among its edge neighbours
  std::vector<std::size_t> room_makers(std::size_t v, const Ring& r) const
  {
    std::vector<std::size_t> movable{ v };
    for(std::size_t n : r.neighbours)
      if(!pinned(n) && interior(n)) movable.push_back(n);
    return movable;
  }

  bool pinned(std::size_t v) const { return v < m_pinned.size() && m_pinned[v] != 0; }

  // the quads at any of `vertices`, each once
  std::vector<std::size_t> quads_at_any(const std::vector<std::size_t>& vertices) const
  {
    std::vector<std::size_t> quads;
    for(std::size_t w : vertices) quads.insert(quads.end(), m_quads_at[w].begin(), m_quads_at[w].end());
    std::sort(quads.begin(), quads.end());
    quads.erase(std::unique(quads.begin(), quads.end()), quads.end());
    return quads;
  }

  // the split's change of the quads (see split()), v2 at v's place
  void connect(std::size_t v, std::size_t v2, const Ring& r, std::size_t i, std::size_t j)
  {
    const std::size_t k = r.neighbours.size(), new_quad = m_quads.size();
    const std::size_t a = r.neighbours[i], b = r.neighbours[j];
    std::vector<std::size_t> quads_v1, quads_v2;
    for(std::size_t l = 0; l < k; ++l) {
      const bool first_side = (l + k - i) % k < j - i;
      (first_side ? quads_v1 : quads_v2).push_back(r.quads[l]);
    }
    for(std::size_t q : quads_v2) std::replace(m_quads[q].begin(), m_quads[q].end(), v, v2);
    quads_v1.push_back(new_quad);
    quads_v2.push_back(new_quad);
    m_xy.push_back(m_xy[v]);
    m_quads.push_back(Quad{ a, v, b, v2 });
    m_quads_at[v] = quads_v1;
    m_quads_at.push_back(quads_v2);
    m_quads_at[a].push_back(new_quad);
    m_quads_at[b].push_back(new_quad);
  }

  void disconnect(std::size_t v, std::size_t v2, const Ring& r, std::size_t a, std::size_t b)
  {
    m_quads.pop_back();
    m_quads_at[v2].pop_back();
    for(std::size_t q : m_quads_at[v2])
      std::replace(m_quads[q].begin(), m_quads[q].end(), v2, v);
    m_xy.pop_back();
    m_quads_at.pop_back();
    m_quads_at[v] = r.quads;
    m_quads_at[a].pop_back();
    m_quads_at[b].pop_back();
  }

  // twenty steps moving each of `vertices` halfway to the mean of its edge neighbours (the
  // mean, unlike the smoothing's parallelogram target, keeps the squeezed quads of a fresh
  // split from turning inside out)
  void relax(const std::vector<std::size_t>& vertices)
  {
    for(int step = 0; step < 20; ++step)
      for(std::size_t v : vertices) m_xy[v] = along_2d(m_xy[v], laplacian_target(v), 0.5);
  }

  // the mean of v's edge neighbours (each counted in both of its quads at v)
  Point_2d laplacian_target(std::size_t v) const
  {
    Vector_2d sum = NULL_VECTOR;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_quads[q];
      const int c = corner_of(Q, v);
      sum = sum + (m_xy[Q[(c + 1) % 4]] - ORIGIN) + (m_xy[Q[(c + 3) % 4]] - ORIGIN);
    }
    return ORIGIN + sum / double(2 * m_quads_at[v].size());
  }

  // every quad of `region` within the bound, with edges no shorter than the minimum, and no
  // interior vertex of theirs folded (each looked at once)
  bool keeps_the_bound(const std::vector<std::size_t>& region) const
  {
    std::vector<std::size_t> corners_of_region;
    for(std::size_t q : region) {
      const Quad& Q = m_quads[q];
      if(!Smoothing_quad_shape(corners(Q)).within_bound()) return false;
      for(int c = 0; c < 4; ++c)
        if((m_xy[Q[(c + 1) % 4]] - m_xy[Q[c]]).squared_length() < m_min_edge2) return false;
      corners_of_region.insert(corners_of_region.end(), Q.begin(), Q.end());
    }
    std::sort(corners_of_region.begin(), corners_of_region.end());
    corners_of_region.erase(std::unique(corners_of_region.begin(), corners_of_region.end()), corners_of_region.end());
    return std::none_of(corners_of_region.begin(), corners_of_region.end(), [&](std::size_t w) { return folded(w); });
  }

  // whether the corners at an interior vertex w fail to wind once around it (a boundary
  // vertex's quads do not close: the whole-mesh check judges those)
  bool folded(std::size_t w) const
  {
    if(!interior(w)) return false;
    std::vector<std::pair<Point_2d, Point_2d>> wedges;
    for(std::size_t q : m_quads_at[w])
      wedges.emplace_back(m_xy[next_of(m_quads[q], w)], m_xy[prev_of(m_quads[q], w)]);
    return times_wedges_cover(m_xy[w], wedges) != 1;
  }

  std::vector<Point_2d>& m_xy;
  std::vector<Quad>& m_quads;
  const std::vector<char>& m_pinned;
  std::vector<std::vector<std::size_t>> m_quads_at;
  std::vector<char> m_on_boundary; // by vertex, for those of the mesh as it came
  double m_min_edge2;
  std::vector<std::size_t> m_seen; // by vertex, the stamp of the last mark_near_split() that reached it
  std::size_t m_stamp = 0;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_VERTEX_SPLITS_H
