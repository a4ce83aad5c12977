// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The smoothing stage, after the buffer layers (not in the paper, whose quads keep the places
// its stages give them): vertices move, one at a time, towards places that bring the angles of
// their quads nearer 90 degrees, under the hard bound. Interior vertices move freely; a
// boundary vertex between two boundary neighbours on one line slides along that line, which
// leaves the meshed region as it was; one on a curved stretch slides along the input segment
// it lies on, within the chord tolerance (boundary_slides.h); input vertices and isolated
// points stay.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_MESH_SMOOTHING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_MESH_SMOOTHING_H

#include <CGAL/Quad_mesher_2/internal/boundary_slides.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/wedge_winding.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The shape of one quad as the smoothing judges it, in products only (no root, no arcsine):
/// for each corner the squared cosine of its angle, whether every corner is strictly convex,
/// and the squared ratio of its longest edge to its shortest.
struct Smoothing_quad_shape
{
  std::array<double, 4> cos2{};
  bool convex = false;
  double aspect2 = 0;

  explicit Smoothing_quad_shape(const std::array<Point_2d, 4>& q)
  {
    std::array<Vector_2d, 4> e;
    std::array<double, 4> len2;
    for(int k = 0; k < 4; ++k) {
      e[k] = q[(k + 1) % 4] - q[k];
      len2[k] = e[k].squared_length();
    }
    convex = true;
    for(int c = 0; c < 4; ++c) {
      const Vector_2d& in = e[(c + 3) % 4];
      const Vector_2d& out = e[c];
      const double cross = CGAL::determinant(in, out), dot = CGAL::scalar_product(in, out);
      const double ll = len2[c] * len2[(c + 3) % 4];
      // a sine above 1e-6 is far beyond the rounding of cross: the corner is convex, exactly
      convex = convex && cross > 0 && cross * cross > 1e-12 * ll;
      cos2[c] = ll > 0 ? dot * dot / ll : 1.0;
    }
    const auto [shortest, longest] = std::minmax_element(len2.begin(), len2.end());
    aspect2 = *shortest > 0 ? *longest / *shortest : HUGE_VAL;
  }

  // an angle's squared cosine at 45 or 135 degrees, and the rounding the verifier's slack
  // (1e-7 degrees, about 1.7e-9 in cos^2) forgives many times over
  static constexpr double bound_cos2 = 0.5 + 1e-12;
  static constexpr double max_aspect2 = 25.0;

  /// strictly convex, every angle in [45, 135] and the aspect ratio at most 5
  bool within_bound() const
  {
    return convex && aspect2 <= max_aspect2 && *std::max_element(cos2.begin(), cos2.end()) <= bound_cos2;
  }

  /// an angle outside [60, 120] or an aspect ratio over 3: the quads the smoothing is for. An
  /// angle within 1e-9 of 1/4 in cos^2 (6e-8 degrees, within the verifier's slack) is in: a
  /// vertex at its Fermat point (fermat_point_2d()) has angles of 120 to rounding, on either side.
  bool needs_smoothing() const { return aspect2 > 9.0 || *std::max_element(cos2.begin(), cos2.end()) > range_cos2; }
  static constexpr double range_cos2 = 0.25 + 1e-9;

  /// the smoothing's energy of the quad: over its corners, cos^2 plus three times its excess
  /// over 1/4 (angles outside [60, 120] weigh most), plus 1/2 for an angle outside [60, 120]
  /// (reached within 1e-3 of cos^2 past 1/4, 0.07 degrees, so that differences see it); plus
  /// log(r^2 / 9) for an aspect ratio r over 3, and 20 log(r^2 / 25) more over 5. The step
  /// counts what the stage is measured by: the angles at a vertex of three quads add up to
  /// 360 degrees, and one of them at 121 is then better than all three at 120.3 (all three
  /// at 120 is best: the Fermat point). An aspect ratio over 5 outweighs any angle within the
  /// bound: the quad at a sharp input corner, long and thin with its other angles near 90 or
  /// 120, widens towards 135 at its far end. The excess and the step start at `range_cos2`,
  /// so that an angle of 120 to rounding costs the same on either side.
  double energy() const
  {
    double e = 0;
    for(double c2 : cos2) {
      const double excess = (std::max)(0.0, c2 - range_cos2);
      e += c2 + 3.0 * excess + 0.5 * (std::min)(1.0, excess / 1e-3);
    }
    if(aspect2 > max_aspect2)
      e += 20.0 * std::log(aspect2 / max_aspect2);
    return aspect2 > 9.0 ? e + std::log(aspect2 / 9.0) : e;
  }
};

/// The smoothing of a whole quad mesh (see the file comment). A move is kept only if it
/// lowers the energy of the vertex's quads (`Smoothing_quad_shape::energy()`) and:
/// - every quad at the vertex stays strictly convex, and the corners it winds once around it
///   (no fold);
/// - no angle in [45, 135] leaves it, and none outside goes further out;
/// - no quad's aspect ratio rises above 5, or above the worst of the vertex's quads where
///   that was over 5 (the worst of the mesh never rises; a sliver can pass some of its
///   length to a neighbour);
/// - no edge at the vertex becomes shorter than `min_edge`, or than it was where it was.
class Mesh_smoothing
{
public:
  typedef Quad_vertices Quad;

  /// `pinned`: the vertices that may not move (input vertices, isolated points); boundary
  /// vertices not between two boundary neighbours on one line stay too, unless `slides` has
  /// a slide for them (null: none has).
  Mesh_smoothing(std::vector<Point_2d>& xy, const std::vector<Quad>& quads, const std::vector<char>& pinned,
                 double min_edge, const Boundary_slides* slides = nullptr)
    : m_xy(xy), m_quads(quads), m_quads_at(quads, xy.size()), m_slides(slides), m_min_edge2(min_edge * min_edge),
      m_freedom(xy.size(), FREE), m_boundary_prev(xy.size(), none), m_boundary_next(xy.size(), none),
      m_descended(xy.size(), 0)
  {
    find_boundary();
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(pinned[v] != 0 || m_quads_at[v].size() == 0) m_freedom[v] = PINNED;
  }

  /// At most `passes` sweeps over the vertices: the first over those of quads with an angle
  /// outside [60, 120] or an aspect ratio over 3, each next over those whose quads changed
  /// in the sweep before; returns how many moves were kept.
  std::size_t smooth(int passes)
  {
    std::vector<char> active(m_xy.size(), 0), next_active(m_xy.size(), 0);
    // first the vertices of quads the stage is for (most of a mesh is not: one look per quad
    // instead of one per corner)
    for(const Quad& Q : m_quads)
      if(Smoothing_quad_shape(corners(Q)).needs_smoothing())
        for(std::size_t v : Q) active[v] = m_freedom[v] != PINNED;
    std::size_t moves = 0;
    for(int pass = 0; pass < passes; ++pass) {
      std::size_t moved = 0;
      for(std::size_t v = 0; v < m_xy.size(); ++v) {
        if(active[v] == 0 || !try_moves(v)) continue;
        ++moved;
        for(std::size_t q : m_quads_at[v])
          for(std::size_t w : m_quads[q]) next_active[w] = m_freedom[w] != PINNED;
      }
      moves += moved;
      if(moved == 0) break;
      active.swap(next_active);
      std::fill(next_active.begin(), next_active.end(), 0);
    }
    return moves;
  }

private:
  // SLIDING: along the line through its boundary neighbours; ALONG_INPUT: along its slide's
  // input segment
  enum Freedom : unsigned char { PINNED, FREE, SLIDING, ALONG_INPUT };
  static constexpr std::size_t none = std::size_t(-1);
  // an energy gain below this (a few hundredths of a degree on one angle near 60) is not
  // worth a move
  static constexpr double min_gain = 1e-3;
  static constexpr int max_descent_steps = 4;

  // Boundary edges are the quad edges a -> b without b -> a. A vertex with one boundary edge
  // in and one out, on a line with its two boundary neighbours, slides; elsewhere it slides
  // along the input if it has a slide; other boundary vertices (corners, vertices where two
  // loops touch) stay.
  void find_boundary()
  {
    std::vector<int> boundary_edges(m_xy.size(), 0);
    for_each_boundary_edge(m_quads, m_quads_at, m_xy.size(), [&](std::size_t a, std::size_t b) {
      ++boundary_edges[a];
      ++boundary_edges[b];
      m_boundary_next[a] = b;
      m_boundary_prev[b] = a;
    });
    for(std::size_t v = 0; v < m_xy.size(); ++v) {
      if(boundary_edges[v] == 0) continue;
      if(boundary_edges[v] != 2) m_freedom[v] = PINNED;
      else if(on_line_between(v)) m_freedom[v] = SLIDING;
      else m_freedom[v] = m_slides != nullptr && m_slides->slide(v) != nullptr ? ALONG_INPUT : PINNED;
    }
  }

  // whether v lies on the segment between its boundary neighbours, within 1e-12 of its
  // length or the rounding of the coordinates (the larger far from the origin, where map
  // projections put domains): sliding along it then moves the boundary by rounding only
  bool on_line_between(std::size_t v) const
  {
    const Point_2d& a = m_xy[m_boundary_prev[v]];
    const Point_2d& b = m_xy[m_boundary_next[v]];
    const Vector_2d ab = b - a, av = m_xy[v] - a;
    const double cross = CGAL::determinant(ab, av), dot = CGAL::scalar_product(ab, av);
    const double off_line = (std::max)(1e-12 * std::sqrt(ab.squared_length()), 16 * coordinate_rounding_2d(a, b));
    return cross * cross <= off_line * off_line * ab.squared_length() && dot > 0 && dot < ab.squared_length();
  }

  std::array<Point_2d, 4> corners(const Quad& Q) const
  {
    return { m_xy[Q[0]], m_xy[Q[1]], m_xy[Q[2]], m_xy[Q[3]] };
  }

  // the quads at v as they are now, and their energy
  struct Star
  {
    std::vector<Smoothing_quad_shape> shapes;
    std::vector<std::array<double, 2>> edges2; // at v in each quad: to the next and previous corner
    double energy = 0;
    bool wanted = false; // a quad with an angle outside [60, 120] or an aspect ratio over 3
    double worst_aspect2 = 0;
  };

  // fills `s` (its buffers kept: no allocation once they have grown)
  void star(std::size_t v, Star& s) const
  {
    s.shapes.clear();
    s.edges2.clear();
    s.energy = 0;
    s.wanted = false;
    s.worst_aspect2 = 0;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_quads[q];
      s.shapes.emplace_back(corners(Q));
      const Smoothing_quad_shape& shape = s.shapes.back();
      s.energy += shape.energy();
      s.wanted = s.wanted || shape.needs_smoothing();
      s.worst_aspect2 = (std::max)(s.worst_aspect2, shape.aspect2);
      const int c = corner_of(Q, v);
      s.edges2.push_back(
          { (m_xy[Q[(c + 1) % 4]] - m_xy[v]).squared_length(), (m_xy[Q[(c + 3) % 4]] - m_xy[v]).squared_length() });
    }
  }

  // whether the star after a move (`after`) keeps the bound that `before` had
  bool keeps_the_bound(const Star& before, const Star& after) const
  {
    const double aspect2_bound = (std::max)(before.worst_aspect2, Smoothing_quad_shape::max_aspect2);
    for(std::size_t k = 0; k < before.shapes.size(); ++k) {
      const Smoothing_quad_shape& b = before.shapes[k];
      const Smoothing_quad_shape& a = after.shapes[k];
      if(!a.convex) return false;
      for(int c = 0; c < 4; ++c)
        if(a.cos2[c] > (std::max)(b.cos2[c], Smoothing_quad_shape::bound_cos2)) return false;
      if(a.aspect2 > aspect2_bound) return false;
      for(int side = 0; side < 2; ++side)
        if(after.edges2[k][side] < (std::min)(before.edges2[k][side], m_min_edge2)) return false;
    }
    return true;
  }

  // no fold: the corners at v (and, on the boundary, the outside between its boundary
  // neighbours) wind once around it
  bool unfolded(std::size_t v) const
  {
    std::vector<std::pair<Point_2d, Point_2d>> wedges;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_quads[q];
      const int c = corner_of(Q, v);
      wedges.emplace_back(m_xy[Q[(c + 1) % 4]], m_xy[Q[(c + 3) % 4]]);
    }
    if(on_boundary(v)) wedges.emplace_back(m_xy[m_boundary_prev[v]], m_xy[m_boundary_next[v]]);
    return times_wedges_cover(m_xy[v], wedges) == 1;
  }

  // The places try_moves() tries, `count` of them.
  struct Targets
  {
    std::array<Point_2d, 3> places;
    int count = 0;
  };

  // Where v's quads would be parallelograms, on average (for each quad at v, its two
  // neighbours' sum less the opposite corner), the mean of its edge neighbours, and for a
  // sliding vertex the midpoint of its boundary neighbours: the two others leave uneven
  // boundary edges where the quads behind them are long.
  Targets targets(std::size_t v) const
  {
    Vector_2d parallelogram = NULL_VECTOR, neighbours = NULL_VECTOR;
    double n = 0;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_quads[q];
      const int c = corner_of(Q, v);
      const Vector_2d next = m_xy[Q[(c + 1) % 4]] - ORIGIN, prev = m_xy[Q[(c + 3) % 4]] - ORIGIN;
      parallelogram = parallelogram + next + prev - (m_xy[Q[(c + 2) % 4]] - ORIGIN);
      neighbours = neighbours + next + prev;
      ++n;
    }
    Targets t;
    t.places[t.count++] = ORIGIN + parallelogram / n;
    t.places[t.count++] = ORIGIN + neighbours / (2 * n);
    if(on_boundary(v)) t.places[t.count++] = CGAL::midpoint(m_xy[m_boundary_prev[v]], m_xy[m_boundary_next[v]]);
    return t;
  }

  // The corners of three quads at an interior vertex add up to 360 degrees, so one is 120 or
  // more wherever it lies; all three are 120 only at the Fermat point of its edge neighbours:
  // false if v has not three quads or is not free, or that point does not exist.
  bool fermat_target(std::size_t v, Point_2d& p) const
  {
    if(m_freedom[v] != FREE || m_quads_at[v].size() != 3) return false;
    std::array<Point_2d, 3> around;
    std::size_t k = 0;
    for(std::size_t q : m_quads_at[v]) {
      const Quad& Q = m_quads[q];
      around[k++] = m_xy[Q[(corner_of(Q, v) + 1) % 4]];
    }
    return fermat_point_2d(around[0], around[1], around[2], p);
  }

  bool on_boundary(std::size_t v) const { return m_freedom[v] == SLIDING || m_freedom[v] == ALONG_INPUT; }

  // the line a boundary vertex slides along: through its boundary neighbours, or its slide's
  // input segment
  std::array<Point_2d, 2> slide_line(std::size_t v) const
  {
    if(m_freedom[v] == ALONG_INPUT) {
      const Boundary_slide& s = *m_slides->slide(v);
      return { s.a, s.b };
    }
    return { m_xy[m_boundary_prev[v]], m_xy[m_boundary_next[v]] };
  }

  // the point of the line through v's boundary neighbours nearest to p, kept a tenth of the
  // way from each; along the input, the point of the slide's segment nearest to p, kept as
  // far from the neighbours as they project on it
  Point_2d on_boundary_line(std::size_t v, const Point_2d& p) const
  {
    const Point_2d& prev = m_xy[m_boundary_prev[v]];
    const Point_2d& next = m_xy[m_boundary_next[v]];
    if(m_freedom[v] == SLIDING) {
      const Vector_2d ab = next - prev;
      const double t = CGAL::scalar_product(p - prev, ab) / ab.squared_length();
      return along_2d(prev, next, (std::min)(0.9, (std::max)(0.1, t)));
    }
    const Boundary_slide& s = *m_slides->slide(v);
    const Vector_2d ab = s.b - s.a;
    auto param = [&](const Point_2d& x) { return CGAL::scalar_product(x - s.a, ab) / ab.squared_length(); };
    const double t_prev = param(prev), t_next = param(next);
    const double margin = 0.1 * std::abs(t_next - t_prev);
    const double lo = (std::max)(0.0, (std::min)(t_prev, t_next) + margin);
    const double hi = (std::min)(1.0, (std::max)(t_prev, t_next) - margin);
    if(lo > hi) return m_xy[v]; // both neighbours project beyond one end: no room
    return along_2d(s.a, s.b, (std::min)(hi, (std::max)(lo, param(p))));
  }

  // whether v is kept at p: the star's energy is lower than `before`'s, by more than a
  // negligible gain, under the bound
  bool better_at(std::size_t v, const Point_2d& p, const Star& before, Star& after)
  {
    const Point_2d start = m_xy[v];
    m_xy[v] = p;
    star(v, after);
    if(after.energy < before.energy - min_gain && keeps_the_bound(before, after) && unfolded(v)
       && (m_freedom[v] != ALONG_INPUT
           || m_slides->keeps_chords(v, start, p, m_xy[m_boundary_prev[v]], m_xy[m_boundary_next[v]])))
      return true;
    m_xy[v] = start;
    return false;
  }

  // Where a quad at v has an angle outside [60, 120] or an aspect ratio over 3 (elsewhere
  // the bulk is as good as the measure asks): tries v at each target, then halfway and a
  // quarter of the way there, and keeps the first place that lowers the energy under the
  // bound. If that still leaves such a quad, a descent follows, once per vertex (the targets
  // do most moves; a descent that found its local best would repeat itself). True if v moved.
  bool try_moves(std::size_t v)
  {
    const Point_2d start = m_xy[v];
    Star& before = m_before;
    Star& after = m_after;
    star(v, before);
    if(!before.wanted) return false;
    // the Fermat point competes with the first place the targets give: the lower energy wins
    Point_2d fermat(0, 0);
    const bool fermat_better = fermat_target(v, fermat) && fermat != start && better_at(v, fermat, before, m_fermat);
    m_xy[v] = start;
    bool moved = false;
    const Targets t = targets(v);
    for(int k = 0; k < t.count; ++k) {
      const Point_2d& target = t.places[k];
      for(double step : { 1.0, 0.5, 0.25 }) {
        Point_2d p = along_2d(start, target, step);
        if(on_boundary(v)) p = on_boundary_line(v, p);
        if(p != start && better_at(v, p, before, after)) {
          moved = true;
          break;
        }
      }
      if(moved) break;
    }
    if(fermat_better && (!moved || m_fermat.energy < after.energy)) {
      m_xy[v] = fermat;
      std::swap(after, m_fermat);
      moved = true;
    }
    if(moved) std::swap(before, after);
    if(before.wanted && m_descended[v] == 0) {
      m_descended[v] = 1;
      moved = descend(v) || moved;
    }
    return moved;
  }

  // Descent from try_moves()'s star: the energy's gradient by differences (along the line
  // for a sliding vertex), then steps against it of a quarter of v's shortest edge, halved
  // until one is kept, down to a 16th; at most `max_descent_steps` such steps.
  bool descend(std::size_t v)
  {
    Star& before = m_before;
    Star& after = m_after;
    bool moved = false;
    for(int k = 0; k < max_descent_steps; ++k) {
      double shortest2 = HUGE_VAL;
      for(const auto& e : before.edges2) shortest2 = (std::min)(shortest2, (std::min)(e[0], e[1]));
      const double h = 0.25 * std::sqrt(shortest2);
      const Vector_2d down = -energy_gradient(v, before.energy, 1e-3 * h);
      if(down == NULL_VECTOR) break;
      const Vector_2d unit = normalized_2d(down);
      bool better = false;
      for(double step = h; step >= h / 16 && !better; step /= 2) {
        Point_2d p = m_xy[v] + step * unit;
        if(on_boundary(v)) p = on_boundary_line(v, p);
        better = p != m_xy[v] && better_at(v, p, before, after);
      }
      if(!better) break;
      std::swap(before, after);
      moved = true;
    }
    return moved;
  }

  // the gradient of the star's energy at v, by forward differences of step `delta` (along the
  // line it slides along for a boundary vertex)
  Vector_2d energy_gradient(std::size_t v, double energy, double delta)
  {
    const Point_2d start = m_xy[v];
    std::array<Vector_2d, 2> axes = { Vector_2d(1, 0), Vector_2d(0, 1) };
    int n_axes = 2;
    if(on_boundary(v)) {
      const auto [a, b] = slide_line(v);
      axes[0] = normalized_2d(b - a);
      n_axes = 1;
    }
    Vector_2d gradient = NULL_VECTOR;
    for(int a = 0; a < n_axes; ++a) {
      m_xy[v] = start + delta * axes[a];
      star(v, m_probe);
      gradient = gradient + ((m_probe.energy - energy) / delta) * axes[a];
    }
    m_xy[v] = start;
    return gradient;
  }

  Star m_before, m_after, m_fermat, m_probe; // try_moves()'s, kept for their buffers
  std::vector<Point_2d>& m_xy;
  const std::vector<Quad>& m_quads;
  Vertex_quads m_quads_at;
  const Boundary_slides* m_slides;
  double m_min_edge2;
  std::vector<Freedom> m_freedom;
  std::vector<std::size_t> m_boundary_prev, m_boundary_next;
  std::vector<char> m_descended; // by vertex: 1 once it descended
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_MESH_SMOOTHING_H
