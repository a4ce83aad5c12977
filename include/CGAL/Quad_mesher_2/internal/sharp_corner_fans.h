// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §5, sharp features: the buffer at input corners. A corner wider than 225° gets a fan of
// three quads (four F points where a fan of three needs them), an obtuse corner one F point on
// its bisector (Fig. 8(c)); the F points there come from the core and are moved to share the
// corner's angle evenly. The second buffer layer (second_buffer_layer.h) asks these where its
// strip reaches a corner.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_SHARP_CORNER_FANS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_SHARP_CORNER_FANS_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The fans and bisector splits at input corners of one buffer zone (see the file comment).
template <class K>
class Sharp_corner_fans : Buffer_tolerances
{
  typedef typename K::FT FT;

public:
  explicit Sharp_corner_fans(Buffer_zone<K>& zone) : m_zone(zone) {}

  // A corner wider than 225 degrees gets a fan of three quads. Over 270 two quads would each
  // have over 135 degrees; from 225 they would each have at least 112.5 and three quads fit
  // better (75 degrees or more each): near 270 the two quads' split is never even.
  bool needs_fan_of_three(std::size_t l, std::size_t k) const { return m_zone.domain_angle(l, k) > 225.0; }

  // Whether a fan-of-three corner may keep four F points on its node. Of its triangles around
  // the node (one per F point, and one more), the pairing joins pairs: with three F points,
  // four triangles make three quads in one phase of the ladder beside the corner and two in
  // the other, and the ladder's run along the boundary sets the phase (on a straight coast it
  // cannot switch: a node added there would make a flat fan).
  // Four F points make five triangles, hence a fan of three in either phase. Spaced alpha/5
  // apart, they give the corner alpha/5, 2 alpha/5 and 2 alpha/5 either way: within 135
  // degrees up to a corner of 337.5; below 270 a fan of two fits (at 270 only as 135 + 135
  // exactly, so 270 to rounding is taken too).
  bool may_take_four_fan_points(std::size_t l, std::size_t k) const
  {
    const double alpha = m_zone.domain_angle(l, k);
    return alpha > 270.0 - angle_tolerance && alpha <= 337.5;
  }

  // The F points of a corner's fan of three come from the core's notch around it and may
  // bunch on one side: the middle one then lies near the chord of the other two and the fan's
  // middle quad is nearly flat. The middle F point moves towards the far corner of the
  // parallelogram on the corner and the other two while that lowers the worst of that quad and
  // its two first-layer quads.
  //
  // The fan's outer F points come from the core too and may leave the middle quad too much of
  // the corner. Each then turns about the corner, at its distance from it, while that lowers
  // the worst of the middle quad, the first-layer quads at it and the angles at the corner
  // between it and the boundary (its side quad's), then the middle point moves again.
  void open_fan(std::size_t c, std::size_t a, std::size_t m, std::size_t b, const Point_2d& corner,
                const Point_2d& before, const Point_2d& after)
  {
    const auto& cyc = m_zone.cycles[c];
    auto& F = m_zone.first_points[c];
    const std::size_t n = cyc.size();
    const std::size_t a0 = (a + n - 1) % n, b1 = (b + 1) % n;
    auto side_badness = [&](const Point_2d& f) { // at the corner, between f and the nearer side
      const Vector_2d u = f - corner;
      double to_side = 180;
      for(const Point_2d& s : { before, after }) {
        const Vector_2d v = s - corner;
        to_side = (std::min)(to_side, angle_degrees(std::abs(CGAL::determinant(u, v)), CGAL::scalar_product(u, v)));
      }
      return std::abs(to_side - 90);
    };
    auto worst = [&]() {
      return (std::max)({ quad_badness({ corner, F[b], F[m], F[a] }),
                          quad_badness({ m_zone.xy[cyc[a]], F[a], F[m], m_zone.xy[cyc[m]] }),
                          quad_badness({ m_zone.xy[cyc[m]], F[m], F[b], m_zone.xy[cyc[b]] }),
                          quad_badness({ m_zone.xy[cyc[a0]], F[a0], F[a], m_zone.xy[cyc[a]] }),
                          quad_badness({ m_zone.xy[cyc[b]], F[b], F[b1], m_zone.xy[cyc[b1]] }),
                          side_badness(F[a]), side_badness(F[b]) });
    };
    const std::array<std::size_t, 3> fan{ { a, m, b } };
    const std::array<Point_2d, 3> before_move{ { F[a], F[m], F[b] } };
    double best = worst();
    if(best <= 45.0) return;
    auto move_middle = [&]() {
      const Point_2d from = F[m];
      const Point_2d target(F[a].x() + F[b].x() - corner.x(), F[a].y() + F[b].y() - corner.y());
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
      if(F[i] == before_move[k]) continue;
      const std::size_t id = m_zone.first_base[c] + i;
      m_zone.xy[id] = F[i];
      m_zone.mesh.points[id] = m_zone.mesh_point(F[i]);
    }
  }

  // An obtuse corner (135 to 225 degrees) whose node took one first buffer point F is split
  // by the edge from it to F (paper Fig. 8(c): that point lies on the corner's bisector). F
  // comes from a core vertex that need not face the corner (the core may come to a point
  // before it), and an uneven split leaves the pairing one quad over the whole corner. F moves
  // towards the bisector, at its distance from the corner, while that lowers the worst of the
  // two halves' and its two first-layer quads' deviation from 90 degrees.
  void turn_to_bisector(std::size_t c, std::size_t m, std::size_t k)
  {
    const auto& cyc = m_zone.cycles[c];
    auto& F = m_zone.first_points[c];
    const std::size_t n = cyc.size(), a = (m + n - 1) % n, b = (m + 1) % n;
    const auto& xy = m_zone.locator->loop(m_zone.cycle_loop[c]);
    const std::size_t nv = xy.size();
    const Point_2d& prev = xy[(k + nv - 1) % nv];
    const Point_2d& corner = xy[k];
    const Point_2d& next = xy[(k + 1) % nv];
    const double alpha = m_zone.domain_angle(m_zone.cycle_loop[c], k);
    auto worst = [&](const Point_2d& f) {
      const double half = 360.0 - right_side_angle(prev, corner, f); // the domain on the left
      return (std::max)({ std::abs(90.0 - half), std::abs(90.0 - (alpha - half)),
                          quad_badness({ m_zone.xy[cyc[a]], F[a], f, m_zone.xy[cyc[m]] }),
                          quad_badness({ m_zone.xy[cyc[m]], f, F[b], m_zone.xy[cyc[b]] }) });
    };
    double best = worst(F[m]);
    if(best <= 45.0) return;
    const Vector_2d bis = right_bisector(prev, corner, next); // out of the domain
    const double r = length_2d(F[m] - corner);
    const Point_2d target = corner - r * bis;
    Point_2d best_f = F[m];
    for(double t : { 1.0, 0.75, 0.5, 0.25 }) {
      const Point_2d f = along_2d(F[m], target, t);
      const double w = worst(f);
      if(w < best - angle_tolerance) { best = w; best_f = f; }
    }
    if(best_f == F[m]) return;
    const std::size_t id = m_zone.first_base[c] + m;
    F[m] = m_zone.xy[id] = best_f;
    m_zone.mesh.points[id] = m_zone.mesh_point(best_f);
  }

private:

  Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_SHARP_CORNER_FANS_H
