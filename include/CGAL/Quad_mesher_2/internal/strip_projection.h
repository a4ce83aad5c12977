// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.6, where the second buffer layer's strip meets the boundary: the first buffer
// points F of a core cycle projected onto its loop, snapped to the loop's vertices near them,
// unwrapped along the loop from a start, and spread where several share a node, but for the
// F points a corner's fan keeps on it (§5).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PROJECTION_H
#define CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PROJECTION_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/sharp_corner_fans.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The first buffer points' projections onto their loop, by F point (`snap`: the loop vertex
/// it snapped to, `hit`: the point) and by position r from the strip's start (`P`: its
/// unwrapped arclength, `share`: the earlier point whose node it shares, `spread`: it was
/// spread around a shared node).
struct Strip_positions
{
  std::vector<double> P;
  std::vector<std::size_t> snap, share;
  std::vector<Loop_locator::Hit> hit;
  std::vector<bool> spread;
};

/// The projections of the first buffer points of core cycle `c` onto its loop (see the file
/// comment).
template <class K>
class Strip_projection : Buffer_tolerances
{
public:
  Strip_projection(Buffer_zone<K>& zone, std::size_t cycle)
    : m_zone(zone), m_fans(zone), c(cycle), l(zone.cycle_loop[cycle]), n(zone.cycles[cycle].size()),
      nv(zone.locator->loop(l).size()), L(zone.locator->length(l)), cyc(zone.cycles[cycle]),
      F(zone.first_points[cycle]), loop_xy(zone.locator->loop(l))
  {}

  /// Projects the F points, gives the wide corners a projection each, splits the obtuse ones
  /// and unwraps the projections; false (a failure in the zone's report) if they do not wind
  /// once around the loop.
  bool project()
  {
    project_first_points();
    give_wide_corners_a_projection();
    split_obtuse_corners();
    return unwrap_along_loop();
  }

  /// The unwrapped projections with every fan's F points gathered on its corner (four at the
  /// corners `four_at` marks, three at the others) and the other shared nodes spread: each
  /// plan of the strip starts afresh from project()'s.
  Strip_positions spread(const std::vector<bool>& four_at)
  {
    Strip_positions proj = m_start;
    proj.spread.assign(n, false);
    gather_fan_points(proj, four_at);
    spread_shared_nodes(proj, four_at);
    return proj;
  }

  /// the F point at position r from the strip's start
  std::size_t rot(std::size_t r) const { return (m_s0 + r) % n; }
  /// the arclength of the strip's start ("O")
  double origin() const { return m_origin; }
  /// an arclength difference taken into (-L/2, L/2], L the loop's length
  double cyclic(double d) const
  {
    d = std::fmod(d, L);
    if(d > L / 2) d -= L;
    if(d < -L / 2) d += L;
    return d;
  }

private:
  // Strip_positionss of the first buffer points; those within a third of the layer's thickness
  // of a loop vertex (along the loop) snap to it.
  void project_first_points()
  {
    std::vector<Loop_locator::Hit>& hit = m_start.hit;
    std::vector<double>& raw = m_raw;
    std::vector<std::size_t>& snap = m_start.snap;
    hit.resize(n);
    raw.resize(n);
    snap.assign(n, none);
    for(std::size_t i = 0; i < n; ++i) {
      hit[i] = m_zone.locator->closest(F[i], 2 * m_zone.local_size[cyc[i]], l);
      raw[i] = m_zone.locator->param(hit[i]);
      const double reach = 0.35 * hit[i].dist;
      double best = reach;
      for(std::size_t k : { hit[i].edge, (hit[i].edge + 1) % nv }) {
        const double d = std::abs(cyclic(m_zone.locator->arc(l, k) - raw[i]));
        if(d <= best) { best = d; snap[i] = k; }
      }
    }
  }

  // A corner wider than 135 degrees (obtuse or reflex) takes the node of the projection
  // nearest to it: a fan of boundary edges around an F point there would be flat or
  // concave at the corner (paper §5: such corners get a first buffer point of their own).
  void give_wide_corners_a_projection()
  {
    const std::vector<double>& raw = m_raw;
    std::vector<std::size_t>& snap = m_start.snap;
    std::vector<std::size_t> by_param(n);
    for(std::size_t i = 0; i < n; ++i) by_param[i] = i;
    std::sort(by_param.begin(), by_param.end(), [&](std::size_t x, std::size_t y) { return raw[x] < raw[y]; });
    std::vector<bool> vertex_taken(nv, false);
    for(std::size_t i = 0; i < n; ++i) if(snap[i] != none) vertex_taken[snap[i]] = true;
    for(std::size_t k = 0; k < nv; ++k) {
      if(vertex_taken[k] || !m_zone.is_feature(l, k)) continue;
      if(m_zone.domain_angle(l, k) <= 135.0) continue;
      const double a = m_zone.locator->arc(l, k);
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

  // An obtuse corner whose node took one projection alone is split by the edge to its F point
  // (sharp_corner_fans.h).
  void split_obtuse_corners()
  {
    const std::vector<std::size_t>& snap = m_start.snap;
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t k = snap[i];
      if(k != none && m_zone.is_feature(l, k) && m_zone.domain_angle(l, k) > 135.0 && !m_fans.needs_fan_of_three(l, k)
         && snap[(i + n - 1) % n] != k && snap[(i + 1) % n] != k)
        m_fans.turn_to_bisector(c, i, k);
    }
  }

  // The strip starts at the first projection on no loop vertex, F point rot(0) at arclength
  // m_origin ("O"). Unwrapped positions along the loop from there; a step backwards would fold
  // the strip, so such a point shares its predecessor's node instead. False (a failure) if
  // they do not wind once around the loop.
  bool unwrap_along_loop()
  {
    const std::vector<double>& raw = m_raw;
    std::vector<std::size_t>& snap = m_start.snap;
    std::size_t& s0 = m_s0;
    s0 = 0;
    while(s0 < n && snap[s0] != none) ++s0;
    if(s0 == n) { s0 = 0; snap[0] = none; }
    const double O = m_origin = raw[s0];
    std::vector<double>& P = m_start.P;
    std::vector<std::size_t>& share = m_start.share;
    std::vector<double> W(n);
    P.resize(n);
    share.assign(n, none);
    W[0] = P[0] = O;
    for(std::size_t r = 1; r < n; ++r) {
      const std::size_t i = rot(r);
      W[r] = W[r - 1] + cyclic(raw[i] - raw[rot(r - 1)]);
      P[r] = snap[i] != none ? W[r] + cyclic(m_zone.locator->arc(l, snap[i]) - raw[i]) : W[r];
      if(P[r] <= P[r - 1]) {
        P[r] = P[r - 1];
        share[r] = share[r - 1] == none ? r - 1 : share[r - 1];
      }
    }
    const double winding = (W[n - 1] + cyclic(raw[s0] - raw[rot(n - 1)]) - O) / L;
    if(std::abs(winding - 1) > 1e-6) {
      m_zone.request_all(c);
      m_zone.report.failure = "the first buffer points do not project once around their loop";
      return false;
    }
    // no position past one turn of the loop (the start again)
    for(std::size_t r = 0; r < n; ++r) P[r] = (std::min)(P[r], O + L);
    return true;
  }

  // A corner wider than 225 degrees needs three F points on its node for a fan of three
  // quads (see needs_fan_of_three()), four where `four_at` asks it: where fewer project onto
  // it, the nearest neighbours (free, on their own nodes) join them.
  void gather_fan_points(Strip_positions& proj, const std::vector<bool>& four_at)
  {
    std::vector<double>& P = proj.P;
    std::vector<std::size_t>& snap = proj.snap;
    for(std::size_t a = 1; a + 1 < n; ++a) {
      const std::size_t k = snap[rot(a)];
      if(k == none || P[a - 1] == P[a] || !m_fans.needs_fan_of_three(l, k)) continue;
      std::size_t lo = a, hi = a;
      while(hi + 1 < n && P[hi + 1] == P[a]) ++hi;
      const Point_2d corner = loop_xy[k];
      auto free_point = [&](std::size_t r) {
        return r > 0 && r + 1 < n && snap[rot(r)] == none && P[r - 1] != P[r] && P[r + 1] != P[r];
      };
      while(hi - lo + 1 < (four_at[k] ? 4u : 3u)) {
        const bool before = free_point(lo - 1), after = hi + 2 < n && free_point(hi + 1);
        if(!before && !after) break;
        const double db = before ? length_2d(F[rot(lo - 1)] - corner) : HUGE_VAL;
        const double da = after ? length_2d(F[rot(hi + 1)] - corner) : HUGE_VAL;
        const std::size_t r = db <= da ? --lo : ++hi;
        P[r] = P[a];
        snap[rot(r)] = k;
      }
      a = hi;
    }
  }

  // Points sharing a node (they project onto one reflex corner, or fold back) are spread
  // along the loop around it, one node each, at about their own spacing, but for a fan's F
  // points (keep_fan_points()), which stay on their corner's: the strip stays a ladder and the
  // pairing is left free to fan where it pays.
  void spread_shared_nodes(Strip_positions& proj, const std::vector<bool>& four_at)
  {
    std::vector<double>& P = proj.P;
    std::vector<std::size_t>& snap = proj.snap;
    std::vector<std::size_t>& share = proj.share;
    std::vector<Loop_locator::Hit>& hit = proj.hit;
    std::vector<bool>& spread = proj.spread;
    const double O = m_origin;
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
        // the corner's node: a fan of three (paper Fig. 8(d)).
        std::size_t last_kept = anchor;
        if(!at_end && snap[rot(a)] != none && m_fans.needs_fan_of_three(l, snap[rot(a)]))
          keep_fan_points(proj, a, b, four_at, anchor, last_kept);
      auto spacing = [&](std::size_t r1, std::size_t r2) {
        return length_2d(F[rot(r1)] - F[rot(r2)]);
      };
      if(anchor > a) { // a .. anchor-1 go before p0
        const std::size_t cnt = (anchor == n ? b + 1 : anchor) - a;
        const double room = (p0 - before) / double(cnt + 1);
        double s = p0;
        for(std::size_t r = (anchor == n ? b + 1 : anchor); r-- > a;) {
          s -= (std::min)(room, spacing(r, r + 1 < n ? r + 1 : r));
          P[r] = s;
          snap[rot(r)] = none;
          hit[rot(r)] = m_zone.locator->point_at_arclength(l, s);
        }
      }
      if(anchor < n && b > last_kept) { // last_kept+1 .. b go after p0
        const double room = (after - p0) / double(b - last_kept + 1);
        double s = p0;
        for(std::size_t r = last_kept + 1; r <= b; ++r) {
          s += (std::min)(room, spacing(r, r - 1));
          P[r] = s;
          snap[rot(r)] = none;
          hit[rot(r)] = m_zone.locator->point_at_arclength(l, s);
        }
      }
      for(std::size_t r = a; r <= b; ++r) {
        share[r] = r > anchor && r <= last_kept ? anchor : none;
        spread[r] = true;
      }
      a = b + 1;
    }
  }

  // Of the F points a .. b on the node of a corner wider than 225 degrees, the three (four
  // where `four_at` asks) that stay there, first_kept (the new `anchor`) to `last_kept`. The
  // pairing can make a node the apex of one F triangle per gap it bounds: two spread nodes
  // leave the corner two quads, over 112.5 degrees each; three F points on it make a fan of
  // three. A fan of three is opened (open_fan()).
  void keep_fan_points(const Strip_positions& proj, std::size_t a, std::size_t b, const std::vector<bool>& four_at,
                       std::size_t& anchor, std::size_t& last_kept)
  {
    const std::vector<std::size_t>& snap = proj.snap;
    const std::size_t k = snap[rot(a)], kept = four_at[k] ? 4 : 3;
    std::size_t first_kept = a == 0 ? 0 : (std::max)(a, anchor - 1);
    // a needle's F points wrap around its tip, so neither the bisector nor the fan's
    // parallelogram below means much there (choosing by them leaves a fan quad far out)
    const bool needle = m_zone.domain_angle(l, k) > 340.0;
    // of more, those whose middle lies nearest the corner's bisector
    if(a != 0 && b - a + 1 > kept && !needle) {
      const Point_2d C = loop_xy[k];
      const Vector_2d bis = right_bisector(loop_xy[(k + nv - 1) % nv], C, loop_xy[(k + 1) % nv]);
      double best = HUGE_VAL;
      for(std::size_t s = a; s + kept - 1 <= b; ++s) {
        Vector_2d mid = normalized_2d(F[rot(s + 1)] - C);
        if(kept == 4) {
          const Vector_2d other = normalized_2d(F[rot(s + 2)] - C);
          mid = normalized_2d(mid + other);
        }
        const double d = CGAL::scalar_product(mid, bis); // -1 on the bisector
        if(d < best) { best = d; first_kept = s; }
      }
    }
    last_kept = (std::min)(b, first_kept + kept - 1);
    anchor = first_kept;
    if(last_kept == first_kept + 2 && !needle)
      m_fans.open_fan(c, rot(first_kept), rot(first_kept + 1), rot(last_kept), loop_xy[k],
               loop_xy[(k + nv - 1) % nv], loop_xy[(k + 1) % nv]);
  }

  Buffer_zone<K>& m_zone;
  Sharp_corner_fans<K> m_fans;
  // the cycle, its loop, the number of F points and of loop vertices, the loop's length
  const std::size_t c, l, n, nv;
  const double L;
  const std::vector<std::size_t>& cyc;
  const std::vector<Point_2d>& F;
  const std::vector<Point_2d>& loop_xy;
  std::vector<double> m_raw;  // each F point's arclength along the loop
  Strip_positions m_start;    // the unwrapped projections every plan starts from
  std::size_t m_s0 = 0;
  double m_origin = 0;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PROJECTION_H
