// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.6, the second buffer layer: F_i is projected onto its boundary loop; the projections,
// together with the loop's vertices (those turning by less than 20 degrees may be left out
// within the chord tolerance), form the boundary chain G. The strip between the F loop and
// G is cut into triangles, each with one F edge or one G edge, and consecutive triangles
// are paired into quads: F/G pairs are the paper's projection quads, G/G pairs fan around
// an F point (the paper's corner quad P-N-M-L of Fig. 8(b)), F/F pairs around a reflex
// corner fan at the corner (Fig. 8(d)); a corner over 225 degrees keeps three F points on
// its node, so that its fan has three quads (four over 270 degrees where three left it a
// fan of two: see may_take_four_fan_points()). Where the F edges meet the G edges and how the
// triangles pair is chosen by dynamic programming around each loop, minimising the sum of
// the quads' squared deviations from 90 degrees, with a heavy penalty outside [45, 135] and
// a prohibitive one for invalid quads. Each gap may also take one more chain node (the
// middle of its longest edge): the pairing decides where, which is how an odd triangle
// count is made even and how a long ladder switches between its two phases (a ladder can
// only switch at a gap with an even number of G edges; without one it shears end to end).
// A segment with the domain on both sides (an interface, a crack, two faces at a junction)
// keeps every vertex and is paired from the side built first; the strip on the other side
// takes those nodes as they are, so that both sides share them: an interface's second twin
// takes the whole chain of its first, a crack's way back mirrors its way out, a face at a
// junction takes the nodes of the faces built before it on the segments it shares with them.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_SECOND_BUFFER_LAYER_H
#define CGAL_QUAD_MESHER_2_INTERNAL_SECOND_BUFFER_LAYER_H

#include <CGAL/Quad_mesher_2/internal/buffer_zone.h>
#include <CGAL/Quad_mesher_2/internal/sharp_corner_fans.h>
#include <CGAL/Quad_mesher_2/internal/strip_costs.h>
#include <CGAL/Quad_mesher_2/internal/strip_pairing.h>
#include <CGAL/Quad_mesher_2/internal/strip_projection.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The second buffer layer's strip of one core cycle c: from its first buffer points F to the
/// boundary chain G on its loop (see the file comment).
template <class K>
class Buffer_strip : Buffer_tolerances
{
  typedef typename K::Point_2 Point_2;
  typedef Quad_vertices Quad;

  // a candidate node of the boundary chain: a loop vertex or an F point's projection (its owner)
  struct Node { double param; std::size_t vertex; std::size_t owner; Point_2d xy; bool keep; };
  // the strip as the pairing sees it: F points' mesh ids, the chain's mesh ids and arclengths,
  // and the first chain node of each gap
  struct Strip_nodes
  {
    std::vector<std::size_t> fid, gid, g;
    std::vector<double> gparam;
  };
  struct Strip_plan { bool ok = false; Strip_result best; std::vector<std::size_t> gid; };
  // where a gap's extra node lies: a loop vertex, or none, and its arclength
  struct Site { std::size_t vertex; double param; };

public:
  Buffer_strip(Buffer_zone<K>& zone, std::size_t cycle)
    : m_zone(zone), m_fans(zone), m_projection(zone, cycle), m_costs(zone), m_pairing(m_costs), c(cycle), l(zone.cycle_loop[cycle]),
      n(zone.cycles[cycle].size()), nv(zone.locator->loop(l).size()), L(zone.locator->length(l)),
      loop_xy(zone.locator->loop(l))
  {}

  // the strip of the cycle: see the file comment
  void build()
  {
    if(!m_projection.project()) return;
    add_plan(shares_edges() ? plan_on_shared_edges() : best_plan());
  }

private:
  // whether an edge of the cycle's loop has the domain on both sides (an interface, a crack,
  // a face at a junction): the strips on either side must share its nodes
  bool shares_edges() const
  {
    for(std::size_t k = 0; k < nv; ++k)
      if(has_edge_twin(m_zone.loops.loops[l], k)) return true;
    return false;
  }

  // whether edge k takes its nodes from its twin: the edge of a loop built before (listed
  // before it) or, of an edge and its reverse on this loop, the later
  bool takes_twins_nodes(std::size_t k) const
  {
    const auto& twin = m_zone.loops.loops[l].edge_twins[k];
    return twin[0] != none && (twin[0] < l || (twin[0] == l && twin[1] < k));
  }

  // A loop with shared edges: the pairing chooses the nodes on the edges of its own (free, or
  // shared with a loop built later), as best_plan() does; the edges shared with a loop built
  // before take that loop's nodes (an interface's second side takes its whole chain), and
  // those along an edge's reverse on this loop (a crack's way back) the nodes of the edge. Then
  // the strip is paired onto that chain, with extra nodes only where no node is settled
  // (on_settled_edge()). Every vertex of a shared edge is a node.
  Strip_plan plan_on_shared_edges()
  {
    bool any_own = false;
    for(std::size_t k = 0; k < nv; ++k) any_own = any_own || !takes_twins_nodes(k);
    Strip_plan own;
    if(any_own) {
      own = best_plan();
      if(!own.ok) return own;
    }
    std::vector<std::size_t> chosen = own.gid;
    std::sort(chosen.begin(), chosen.end());
    auto was_chosen = [&](std::size_t id) { return std::binary_search(chosen.begin(), chosen.end(), id); };
    const Loop_locator& at = *m_zone.locator;
    const Boundary_loop_2<K>& loop = m_zone.loops.loops[l];
    std::vector<std::pair<double, std::size_t>> by_param; // arclength, mesh id
    std::vector<std::size_t> fixed;                        // the nodes of loops built before
    for(std::size_t k = 0; k < nv; ++k)
      if(on_edge_twin(loop, k) || was_chosen(m_zone.point_of_input(loop.vertices[k])))
        by_param.emplace_back(at.arc(l, k), m_zone.input_vertex_point(l, k));
    for(std::size_t id : own.gid)
      if(const auto* slide = m_zone.slide(id); slide != nullptr && slide->loop == l && !takes_twins_nodes(slide->edge))
        by_param.emplace_back(at.arc(l, slide->edge) + length_2d(m_zone.xy[id] - loop_xy[slide->edge]), id);
    for(std::size_t k = 0; k < nv; ++k) {
      if(!takes_twins_nodes(k)) continue;
      const auto& twin = loop.edge_twins[k];
      const std::vector<std::size_t>& source = twin[0] == l ? own.gid : m_zone.loop_chain[twin[0]];
      if(source.empty()) return Strip_plan(); // not ok: the twin's strip failed
      const double length = at.arc(l, k + 1) - at.arc(l, k);
      for(std::size_t id : source)
        if(const auto* slide = m_zone.slide(id); slide != nullptr && slide->loop == twin[0] && slide->edge == twin[1]) {
          by_param.emplace_back(at.arc(l, k) + length - length_2d(m_zone.xy[id] - at.loop(twin[0])[twin[1]]), id);
          if(twin[0] != l) fixed.push_back(id);
        }
    }
    return plan_without_invalid_fans(std::move(by_param), fixed);
  }

  // The pairing onto a shared chain (plan_on_chain()); where a side's F point must fan over
  // three chain nodes in a row into an invalid quad, or one with the boundary's angle out of
  // range (the other side, a reflex corner's, took more nodes there), the middle node leaves
  // both sides if it is no input vertex, else its two neighbours that are none, and the strip
  // is paired again, while that lowers its cost. The nodes in `fixed` (a strip built before
  // has them) stay.
  Strip_plan plan_without_invalid_fans(std::vector<std::pair<double, std::size_t>> by_param,
                                       const std::vector<std::size_t>& fixed)
  {
    Strip_plan plan = plan_on_chain(by_param);
    for(int attempt = 0; attempt < 8 && plan.best.cost.sum >= 1e12; ++attempt) {
      std::vector<std::size_t> leave_out = nodes_about_invalid_fans(plan);
      leave_out.erase(std::remove_if(leave_out.begin(), leave_out.end(),
                                     [&](std::size_t id) { return std::find(fixed.begin(), fixed.end(), id) != fixed.end(); }),
                      leave_out.end());
      if(leave_out.empty()) break;
      std::vector<std::pair<double, std::size_t>> fewer;
      for(const auto& node : by_param)
        if(std::find(leave_out.begin(), leave_out.end(), node.second) == leave_out.end()) fewer.push_back(node);
      Strip_plan again = plan_on_chain(fewer);
      if(!(again.best.cost < plan.best.cost)) break;
      plan = std::move(again);
      by_param = std::move(fewer);
    }
    return plan;
  }

  // The chain nodes to leave out about the invalid fans of boundary edges in `plan` (three
  // chain nodes in a row in one quad, see Strip_quad_costs::cost()): the middle one if it is
  // no input vertex, else those of its neighbours that are none. A crack keeps every vertex,
  // so such a node lies on a segment between two others: leaving it out keeps the crack.
  std::vector<std::size_t> nodes_about_invalid_fans(const Strip_plan& plan) const
  {
    std::vector<std::size_t> nodes;
    const std::size_t M = plan.gid.size();
    for(const Quad& q : plan.best.quads) {
      if(m_costs.cost(q) < 1000.0) continue;
      auto in_q = [&](std::size_t v) { return std::find(q.begin(), q.end(), v) != q.end(); };
      for(std::size_t k = 0; k < M; ++k) {
        const std::size_t before = plan.gid[(k + M - 1) % M], middle = plan.gid[k], after = plan.gid[(k + 1) % M];
        if(!in_q(before) || !in_q(middle) || !in_q(after)) continue;
        if(!m_zone.is_input_vertex(middle)) nodes.push_back(middle);
        else
          for(std::size_t v : { before, after })
            if(!m_zone.is_input_vertex(v)) nodes.push_back(v);
      }
    }
    return nodes;
  }

  // The pairing onto a given chain (arclength along this loop, mesh id): each F point takes
  // the chain node nearest its projection (in order along the loop), with no node left out,
  // and none added but a gap's extra node on an edge whose nodes are not settled
  // (on_settled_edge()).
  Strip_plan plan_on_chain(std::vector<std::pair<double, std::size_t>> by_param)
  {
    Strip_plan plan;
    const Strip_positions proj = m_projection.spread(std::vector<bool>(nv, false));
    Strip_nodes strip = chain_from(std::move(by_param), proj.P[0]);
    give_first_points_their_nearest_nodes(strip, proj.P);
    m_extra_off_settled_edges = true;
    plan.best = pair_strip_nodes(strip);
    m_extra_off_settled_edges = false;
    plan.ok = true;
    plan.gid = std::move(strip.gid);
    return plan;
  }

  // The chain's nodes (arclength, mesh id) by arclength along this loop, from the one nearest
  // arclength `start` (the first F point's projection), which starts the strip.
  Strip_nodes chain_from(std::vector<std::pair<double, std::size_t>> by_param, double start) const
  {
    std::size_t first = 0;
    for(std::size_t k = 1; k < by_param.size(); ++k)
      if(std::abs(cyclic(by_param[k].first - start)) < std::abs(cyclic(by_param[first].first - start))) first = k;
    const double base = by_param[first].first;
    for(auto& node : by_param) node.first = base + arc_after(node.first - base);
    std::sort(by_param.begin(), by_param.end());
    Strip_nodes strip;
    for(const auto& node : by_param) {
      strip.gparam.push_back(node.first);
      strip.gid.push_back(node.second);
    }
    return strip;
  }

  // F point r (at arclength P[r]) takes the chain node nearest its projection, but no node
  // before the previous point's; the first point takes the first node.
  void give_first_points_their_nearest_nodes(Strip_nodes& strip, const std::vector<double>& P) const
  {
    const std::size_t M = strip.gid.size();
    const double base = strip.gparam.front();
    const std::size_t fbase = m_zone.first_base[c];
    strip.g.assign(n, 0);
    strip.fid.resize(n);
    for(std::size_t r = 0; r < n; ++r) {
      strip.fid[r] = fbase + rot(r);
      if(r == 0) continue;
      const double at = base + arc_after(P[r] - base);
      std::size_t k = std::size_t(std::lower_bound(strip.gparam.begin(), strip.gparam.end(), at) - strip.gparam.begin());
      const double after = k < M ? strip.gparam[k] : base + L;
      if(k > 0 && at - strip.gparam[k - 1] < after - at) --k;
      strip.g[r] = (std::max)(strip.g[r - 1], k);
    }
  }

  // an arclength difference taken into [0, L)
  double arc_after(double d) const
  {
    d = std::fmod(d, L);
    return d < 0 ? d + L : d;
  }

  // The strip's pairing, with four F points on the node of each corner marked in `four_at`
  // (see may_take_four_fan_points()) and three on the others' (from the unwrapped
  // projections: a second plan starts afresh).
  Strip_plan plan_with(const std::vector<bool>& four_at)
  {
    const Strip_positions proj = m_projection.spread(four_at);
    std::vector<std::size_t> alias_vertex(n, none);
    std::vector<Node> nodes = candidate_nodes(proj, alias_vertex);
    keep_nodes_for_chord_tolerance(nodes);
    // The vertices take over only where the pairing leaves a quad out of range, and the strip
    // is paired again only if that lowers its cost: elsewhere the pairing may do better by
    // switching phase at a vertex. First at the vertices a pairing leaves the middle of a fan
    // out of range (the new pairing may leave one at another vertex: a few rounds); if fans
    // remain, at every vertex at once (a coarse polygon's fans move round by round).
    std::vector<bool> take_over_at(nv, false);
    Strip_plan plan = plan_strip(proj, nodes, alias_vertex, take_over_at);
    if(plan.ok && plan.best.cost.worst > 45.0 + angle_tolerance) {
      Strip_plan latest = plan;
      for(int round = 0; round < 4; ++round) {
        bool more = false;
        for(std::size_t k : fan_vertices(latest))
          if(!take_over_at[k]) more = take_over_at[k] = true;
        if(!more) break;
        latest = plan_strip(proj, nodes, alias_vertex, take_over_at);
        if(!latest.ok) break;
        if(latest.best.cost < plan.best.cost) plan = latest;
      }
      if(!fan_vertices(plan).empty()) {
        Strip_plan everywhere = plan_strip(proj, nodes, alias_vertex, std::vector<bool>(nv, true));
        if(everywhere.ok && everywhere.best.cost < plan.best.cost) plan = std::move(everywhere);
      }
    }
    return plan;
  }

  // Candidate nodes, by parameter from O: loop vertices and the F points' own projections. A
  // projection on a vertex (to rounding) is that vertex; a second one shares it
  // (`alias_vertex`).
  std::vector<Node> candidate_nodes(const Strip_positions& proj, std::vector<std::size_t>& alias_vertex) const
  {
    const std::vector<double>& P = proj.P;
    const std::vector<std::size_t>& snap = proj.snap;
    const std::vector<std::size_t>& share = proj.share;
    const std::vector<Loop_locator::Hit>& hit = proj.hit;
    const double O = m_projection.origin();
    std::vector<Node> nodes;
    std::vector<bool> snapped(nv, false);
    // an interface keeps every vertex: its segments are the mesh's edges (constraints)
    const Boundary_loop_2<K>& loop = m_zone.loops.loops[l];
    for(std::size_t r = 0; r < n; ++r)
      if(share[r] == none && snap[rot(r)] != none) snapped[snap[rot(r)]] = true;
    for(std::size_t k = 0; k < nv; ++k) {
      double s = std::fmod(m_zone.locator->arc(l, k) - O, L);
      if(s < 0) s += L;
      nodes.push_back(Node{ O + s, k, none, loop_xy[k], snapped[k] || on_edge_twin(loop, k) || m_zone.is_feature(l, k) });
    }
    for(std::size_t r = 0; r < n; ++r)
      if(share[r] == none && snap[rot(r)] == none && P[r] < O + L * (1 - 1e-12))
        nodes.push_back(Node{ P[r], none, r, hit[rot(r)].point, true });
    std::stable_sort(nodes.begin(), nodes.end(), [](const Node& x, const Node& y) {
      return x.param < y.param || (x.param == y.param && x.vertex != none && y.vertex == none);
    });
    {
      const double tol = (std::max)(1e-9 * L, 1e-8 * m_zone.locator->diagonal()); // verify_mesh merges at 1e-9 of the diagonal
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
    return nodes;
  }

  // Loop vertices that are no corners (they turn the boundary by less than the feature
  // angle) and hold no node may be left out where the chord between the kept nodes around
  // them stays within the tolerance (Douglas-Peucker): that keeps the strip a ladder.
  void keep_nodes_for_chord_tolerance(std::vector<Node>& nodes) const
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
      const double chord = length_2d(B - A);
      const double tol = m_zone.chord_tolerance;
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
  // about as many as the F points. Such a vertex (of those marked in `at`) takes over the node
  // of the nearer projection beside it in the chain; the first node stays the first F
  // point's, and those spread around a corner stay its fan's. The chord that then spans the
  // projection's place must keep the nodes under it within the tolerance.
  void take_over_projection_nodes(const Strip_positions& proj, std::vector<Node>& candidates, std::vector<std::size_t>& alias,
                                  const std::vector<bool>& at) const
  {
    const std::vector<bool>& spread = proj.spread;
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
        if(point_segment_distance(candidates[i].xy, candidates[a].xy, candidates[b].xy) > m_zone.chord_tolerance)
          return false;
      return true;
    };
    for(std::size_t j = 0; j < nk; ++j) {
      Node& v = candidates[kept[j]];
      if(v.vertex == none || !at[v.vertex] || v.owner != none || m_zone.domain_angle(l, v.vertex) <= 135.0) continue;
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
  }

  // The pairing of the strip from the candidate nodes (copies: a second plan starts afresh),
  // the vertices marked in `take_over_at` taking over projection nodes.
  Strip_plan plan_strip(const Strip_positions& proj, std::vector<Node> nodes, std::vector<std::size_t> alias_vertex,
                        const std::vector<bool>& take_over_at)
  {
    const std::vector<double>& P = proj.P;
    const std::vector<std::size_t>& snap = proj.snap;
    const std::vector<std::size_t>& share = proj.share;
    const std::vector<Loop_locator::Hit>& hit = proj.hit;
    const double O = m_projection.origin();
    Strip_nodes strip;
    std::vector<std::size_t>& gid = strip.gid;
    std::vector<std::size_t>& g = strip.g;
    std::vector<std::size_t>& fid = strip.fid;
    std::vector<double>& gparam = strip.gparam;
    Strip_plan plan;
    take_over_projection_nodes(proj, nodes, alias_vertex, take_over_at);
    std::vector<Node> chain;
    std::vector<std::size_t> chain_of_node(nodes.size(), none);
    for(std::size_t k = 0; k < nodes.size(); ++k)
      if(nodes[k].keep) { chain_of_node[k] = chain.size(); chain.push_back(nodes[k]); }
    const std::size_t M0 = chain.size();
    gid.resize(M0);
    for(std::size_t k = 0; k < M0; ++k)
      gid[k] = chain[k].vertex != none ? m_zone.input_vertex_point(l, chain[k].vertex)
                                       : m_zone.point_on_edge(l, hit[rot(chain[k].owner)].edge, hit[rot(chain[k].owner)].t);
    std::vector<std::size_t> node_of_vertex(nv, none), node_of_owner(n, none);
    for(std::size_t k = 0; k < M0; ++k) {
      if(chain[k].vertex != none) node_of_vertex[chain[k].vertex] = k;
      if(chain[k].owner != none) node_of_owner[chain[k].owner] = k;
    }
    g.resize(n);
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

    const std::size_t fbase = m_zone.first_base[c];
    fid.resize(n);
    for(std::size_t r = 0; r < n; ++r) fid[r] = fbase + rot(r);

    gparam.resize(gid.size());
    for(std::size_t k = 0; k < gid.size(); ++k) gparam[k] = chain[k].param;
    Strip_result best = pair_strip_nodes(strip);
    take_out_flat_fans(strip, best);
    plan.ok = true;
    plan.best = std::move(best);
    plan.gid = std::move(gid);
    return plan;
  }

    // n F edges and M G edges make n + M triangles, paired into quads. Every gap may take one
    // more chain node, in the middle of its longest edge (on the loop there, or on a left-out
    // loop vertex near it): the pairing decides where. It switches a ladder of quads between
    // its two phases, and makes an odd triangle count even, where that costs least.
  Strip_result pair_strip_nodes(Strip_nodes& strip)
  {
    std::vector<Extra_node> extra(n);
    std::vector<Site> sites(n);
    const std::size_t first_candidate = m_zone.xy.size();
    for(std::size_t r = 0; r < n; ++r)
      add_extra_candidate(strip, r, extra, sites);
    Strip_result res = m_pairing.pair(strip.fid, strip.gid, strip.g, extra);
    forget_candidates(first_candidate);
    insert_chosen_extra_nodes(strip, extra, sites, first_candidate, res);
    return res;
  }

  // Gap r's candidate extra node, in the middle of its longest chain edge, on the loop there
  // or at a left-out loop vertex near it (which keeps the input's own point): `extra[r]`,
  // `sites[r]`, with an id of its own past the mesh's points.
  void add_extra_candidate(const Strip_nodes& strip, std::size_t r, std::vector<Extra_node>& extra, std::vector<Site>& sites)
  {
    const std::vector<std::size_t>& gid = strip.gid;
    const std::vector<std::size_t>& g = strip.g;
    const std::vector<double>& gparam = strip.gparam;
    const std::size_t M0 = gid.size();
    const std::size_t g0 = g[r], k = (r + 1 < n ? g[r + 1] : M0) - g0;
    if(g0 >= M0 || k == 0) return;
    std::size_t e = 0;
    double longest = -1;
    for(std::size_t j = 0; j < k; ++j) {
      const double len = length_2d(m_zone.xy[gid[(g0 + j + 1) % M0]] - (m_zone.xy[gid[g0 + j]]));
      if(len > longest && !(m_extra_off_settled_edges && on_settled_edge(strip, g0 + j))) { longest = len; e = j; }
    }
    if(longest < 0) return; // every edge of the gap is settled
    const double a = gparam[g0 + e], b = g0 + e + 1 < M0 ? gparam[g0 + e + 1] : gparam[0] + L;
    const double mid = 0.5 * (a + b);
    const Loop_locator::Hit h = m_zone.locator->point_at_arclength(l, mid);
    // a left-out loop vertex near the middle keeps the input's own point
    Site site{ none, mid };
    Point_2d xy = h.point;
    double nearest = 0.25 * (b - a);
    for(std::size_t v : { h.edge, (h.edge + 1) % nv }) {
      const double sv = mid + cyclic(m_zone.locator->arc(l, v) - mid);
      if(std::abs(sv - mid) < nearest) {
        nearest = std::abs(sv - mid);
        site = Site{ v, sv };
        xy = loop_xy[v];
      }
    }
    sites[r] = site;
    extra[r] = Extra_node{ e, m_zone.xy.size() };
    if(site.vertex != none) { // the pairing costs its angle as the input vertex it is
      m_zone.corner_angle.resize(m_zone.xy.size() + 1, std::numeric_limits<double>::quiet_NaN());
      m_zone.corner_angle[m_zone.xy.size()] = m_zone.domain_angle(l, site.vertex);
    }
    m_zone.xy.push_back(xy);
  }

  // The candidates had ids of their own past the mesh's points: they go, and the chosen ones
  // become mesh points.
  void forget_candidates(std::size_t first_candidate)
  {
    m_zone.xy.resize(first_candidate);
    m_zone.corner_angle.resize((std::min)(m_zone.corner_angle.size(), first_candidate));
  }

  // the extra nodes the pairing took, made mesh points and put into the chain, and into the
  // pairing's quads in place of their candidate ids
  void insert_chosen_extra_nodes(Strip_nodes& strip, const std::vector<Extra_node>& extra, const std::vector<Site>& sites,
                                 std::size_t first_candidate, Strip_result& res)
  {
    std::vector<std::size_t>& gid = strip.gid;
    std::vector<std::size_t>& g = strip.g;
    std::vector<double>& gparam = strip.gparam;
    if(res.inserted.empty()) return; // no pairing
    std::vector<std::size_t> real_id(n, none); // by candidate id - first_candidate
    for(std::size_t r = n; r-- > 0;) { // from the back: earlier chain positions stay valid
      if(!res.inserted[r]) continue;
      std::size_t id;
      if(sites[r].vertex != none) {
        id = m_zone.input_vertex_point(l, sites[r].vertex);
      } else {
        const Loop_locator::Hit h = m_zone.locator->point_at_arclength(l, sites[r].param);
        id = m_zone.point_on_edge(l, h.edge, h.t);
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
  }

  // A fan of boundary edges that is flat (its middle node is no input vertex and lies on a
  // straight piece of the boundary) cannot be made a quad: such a node is taken out and the
  // strip paired again, while that lowers the strip's cost (the pairing may put the node
  // back as a gap's extra node: the same strip again).
  void take_out_flat_fans(Strip_nodes& strip, Strip_result& best)
  {
    std::vector<std::size_t>& gid = strip.gid;
    std::vector<std::size_t>& g = strip.g;
    std::vector<double>& gparam = strip.gparam;
    for(int attempt = 0; attempt < 8 && best.cost.sum >= 1e12; ++attempt) {
      // a chain node that may be left out: not the first, not an input vertex
      auto removable = [&](std::size_t k) { return k != 0 && !m_zone.is_input_vertex(gid[k]); };
      std::vector<std::size_t> removed;
      for(const Quad& q : best.quads) {
        std::size_t remove = none;
        if(m_costs.cost(q) < 1000.0) continue;
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
      const Strip_nodes before = strip;
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
      Strip_result paired = pair_strip_nodes(strip);
      if(!(paired.cost < best.cost)) {
        strip = before;
        break;
      }
      best = std::move(paired);
    }
  }

  // the loop vertices at fans of boundary edges out of range in a pairing (a pairing may add
  // input vertices to the mesh)
  std::vector<std::size_t> fan_vertices(const Strip_plan& p) const
  {
    const std::unordered_map<std::size_t, std::size_t> loop_vertex_of_point = loop_vertices_by_point();
    std::vector<std::size_t> fans;
    for(const Quad& q : p.best.quads) {
      const int k = m_costs.fixed_angle_out_of_range(q);
      auto it = k < 0 ? loop_vertex_of_point.end() : loop_vertex_of_point.find(q[std::size_t(k)]);
      if(it != loop_vertex_of_point.end()) fans.push_back(it->second);
    }
    return fans;
  }

  // the loop vertex of each input vertex the mesh has, by its mesh point
  std::unordered_map<std::size_t, std::size_t> loop_vertices_by_point() const
  {
    std::unordered_map<std::size_t, std::size_t> loop_vertex_of_point;
    for(std::size_t k = 0; k < nv; ++k) {
      const std::size_t point = m_zone.point_of_input(m_zone.loops.loops[l].vertices[k]);
      if(point != none) loop_vertex_of_point[point] = k;
    }
    return loop_vertex_of_point;
  }

  // The mesh points of the strip's F points, which the fans move (open_fan()): a second plan
  // starts from them as they were, and the chosen plan's stay.
  std::vector<Point_2> f_points() const
  {
    const std::size_t fbase = m_zone.first_base[c];
    return std::vector<Point_2>(m_zone.mesh.points.begin() + std::ptrdiff_t(fbase),
                                m_zone.mesh.points.begin() + std::ptrdiff_t(fbase + n));
  }

  void restore_f_points(const std::vector<Point_2>& saved)
  {
    const std::size_t fbase = m_zone.first_base[c];
    for(std::size_t i = 0; i < n; ++i) {
      m_zone.mesh.points[fbase + i] = saved[i];
      m_zone.first_points[c][i] = m_zone.xy[fbase + i] = to_point_2d(saved[i]);
    }
  }

  // The plan with three F points at each corner's fan, or with four where a corner over 270
  // degrees kept a fan of two (its ladder's phase, see may_take_four_fan_points()) and four
  // pair the strip better there: each such corner is decided by the quads about it, so that
  // a poor quad elsewhere on the loop does not decide every corner at once.
  Strip_plan best_plan()
  {
    const std::vector<Point_2> f_start = f_points();
    Strip_plan three = plan_with(std::vector<bool>(nv, false));
    if(!three.ok) return three;
    std::vector<Corner_choice> corners = corners_that_may_take_four(three);
    if(corners.empty()) return three;
    m_zone.report.fans_that_may_take_four += corners.size();
    const std::vector<Point_2> f_three = f_points();
    cost_about_corners(three, corners, false);
    restore_f_points(f_start);
    Strip_plan four = plan_with(four_at(corners, true));
    if(!four.ok) {
      restore_f_points(f_three);
      return three;
    }
    cost_about_corners(four, corners, true);
    const std::size_t better_with_four = std::size_t(
        std::count_if(corners.begin(), corners.end(), [](const Corner_choice& x) { return x.four < x.three; }));
    if(better_with_four == corners.size()) return take_fans_of_four(std::move(four), corners.size());
    if(better_with_four == 0) {
      restore_f_points(f_three);
      return three;
    }
    // a mixed plan, unless the corners' choices interfere (the ladder's phase between them)
    const std::vector<Point_2> f_four = f_points();
    restore_f_points(f_start);
    Strip_plan mixed = plan_with(four_at(corners, false));
    if(mixed.ok && mixed.best.cost < three.best.cost && mixed.best.cost < four.best.cost)
      return take_fans_of_four(std::move(mixed), better_with_four);
    if(four.best.cost < three.best.cost) {
      restore_f_points(f_four);
      return take_fans_of_four(std::move(four), corners.size());
    }
    restore_f_points(f_three);
    return three;
  }

  Strip_plan take_fans_of_four(Strip_plan&& plan, std::size_t fans)
  {
    m_zone.report.fans_of_four += fans;
    return std::move(plan);
  }

  // a corner that may take four F points: its loop vertex, the F point its fan starts from
  // in the plan with three, and the cost of the strip's quads about it in either plan
  struct Corner_choice { std::size_t vertex, f; Cost three, four; };

  std::vector<Corner_choice> corners_that_may_take_four(const Strip_plan& three) const
  {
    const std::unordered_map<std::size_t, std::size_t> loop_vertex_of_point = loop_vertices_by_point();
    std::vector<Corner_choice> corners;
    std::vector<bool> seen(nv, false);
    for(const Quad& q : three.best.quads) {
      const int k = m_costs.wide_side_of_reflex_fan(q);
      auto it = k < 0 ? loop_vertex_of_point.end() : loop_vertex_of_point.find(q[std::size_t(k)]);
      if(it == loop_vertex_of_point.end() || seen[it->second] || !m_fans.may_take_four_fan_points(l, it->second))
        continue;
      seen[it->second] = true;
      const std::size_t f = f_index(q);
      if(f != none) corners.push_back(Corner_choice{ it->second, f, Cost{ 0, 0 }, Cost{ 0, 0 } });
    }
    return corners;
  }

  // the loop vertices of `corners` (all of them, or those better with four)
  std::vector<bool> four_at(const std::vector<Corner_choice>& corners, bool all) const
  {
    std::vector<bool> at(nv, false);
    for(const Corner_choice& corner : corners)
      if(all || corner.four < corner.three) at[corner.vertex] = true;
    return at;
  }

  // Adds the cost of each quad of `plan` (its F points in place) to the nearest of `corners`
  // by F points along the cycle (the quads of F points: all but a fan of boundary edges)
  void cost_about_corners(const Strip_plan& plan, std::vector<Corner_choice>& corners, bool four) const
  {
    for(const Quad& q : plan.best.quads) {
      const std::size_t f = f_index(q);
      if(f == none) continue;
      Corner_choice* nearest = &corners.front();
      std::size_t distance = n;
      for(Corner_choice& corner : corners) {
        const std::size_t d = (f + n - corner.f) % n, cyclic_d = (std::min)(d, n - d);
        if(cyclic_d < distance) { distance = cyclic_d; nearest = &corner; }
      }
      (four ? nearest->four : nearest->three).add(m_costs.strip_cost(q));
    }
  }

  // the position along the cycle of a first buffer point of `q`, `none` if it has none
  std::size_t f_index(const Quad& q) const
  {
    const std::size_t fbase = m_zone.first_base[c];
    for(std::size_t v : q)
      if(v >= fbase && v < fbase + n) return v - fbase;
    return none;
  }

  // the quads of the chosen plan, or a failure
  void add_plan(const Strip_plan& plan)
  {
    if(!plan.ok) {
      m_zone.request_all(c);
      m_zone.report.failure = "the boundary chain of a buffer strip is out of order";
      return;
    }
    const Strip_result& best = plan.best;
    const std::vector<std::size_t>& gid = plan.gid;
    if(best.cost.worst == HUGE_VAL) {
      m_zone.request_all(c);
      m_zone.report.failure = "no pairing of a buffer strip into quads";
      return;
    }
    const std::size_t M = gid.size();
    for(std::size_t k = 0; k < M; ++k)
      if(auto* slide = m_zone.slide(gid[k]))
        slide->neighbors = { gid[(k + M - 1) % M], gid[(k + 1) % M] };
    m_zone.loop_chain[l] = gid;
    for(const Quad& q : best.quads) {
      m_zone.add_quad(q);
      ++m_zone.report.second_layer_quads;
    }
  }

  // whether chain edge j (from node j to j + 1) lies on an edge whose nodes are settled: it
  // takes its twin's, or its reverse on this loop takes its own (a node added to either side
  // would be on one side only). A loop built later takes what the others have.
  bool on_settled_edge(const Strip_nodes& strip, std::size_t j) const
  {
    const std::size_t M = strip.gid.size();
    const double a = strip.gparam[j], b = j + 1 < M ? strip.gparam[j + 1] : strip.gparam[0] + L;
    const std::size_t k = m_zone.locator->point_at_arclength(l, 0.5 * (a + b)).edge;
    const std::size_t twin = m_zone.loops.loops[l].edge_twins[k][0];
    return twin != none && twin <= l;
  }

  // the F point at position r from the strip's start
  std::size_t rot(std::size_t r) const { return m_projection.rot(r); }
  double cyclic(double d) const { return m_projection.cyclic(d); }

  bool chord_within_tolerance(std::size_t l, const std::vector<std::size_t>& gid,
                              const std::vector<double>& param, std::size_t k) const
  {
    const std::size_t M = gid.size();
    const std::size_t a = (k + M - 1) % M, b = (k + 1) % M;
    const Point_2d A = m_zone.xy[gid[a]], B = m_zone.xy[gid[b]];
    const double L = m_zone.locator->length(l);
    double s0 = param[a], s1 = b > a ? param[b] : param[b] + L;
    const auto& v = m_zone.locator->loop(l);
    for(std::size_t j = 0; j < v.size(); ++j) {
      double s = m_zone.locator->arc(l, j);
      while(s < s0) s += L;
      if(s < s1 && point_segment_distance(v[j], A, B) > m_zone.chord_tolerance) return false;
    }
    return point_segment_distance(m_zone.xy[gid[k]], A, B) <= m_zone.chord_tolerance;
  }

  Buffer_zone<K>& m_zone;
  Sharp_corner_fans<K> m_fans;
  Strip_projection<K> m_projection;
  Strip_quad_costs<K> m_costs;
  Strip_pairing<Strip_quad_costs<K>> m_pairing; // kept from plan to plan: see Strip_pairing
  // the cycle, its loop, the number of F points and of loop vertices, the loop's length
  const std::size_t c, l, n, nv;
  const double L;
  const std::vector<Point_2d>& loop_xy;
  bool m_extra_off_settled_edges = false; // while plan_on_chain() pairs a shared chain
};

/// Stage "buffer2" (paper §4.6) on one buffer zone: the strip of each cycle (Buffer_strip).
template <class K>
class Second_buffer_layer
{
public:
  explicit Second_buffer_layer(Buffer_zone<K>& zone) : m_zone(zone) {}

  // Each cycle after those of the loops listed before it that share an edge with it (an
  // interface's second twin, a face at a junction): it takes their nodes on those edges.
  void build_second_layer()
  {
    m_zone.layer_begin[1] = m_zone.mesh.quads.size();
    m_zone.loop_chain.assign(m_zone.loops.loops.size(), {});
    const std::size_t nc = m_zone.cycles.size();
    std::vector<char> built_loop(m_zone.loops.loops.size(), 0), built_cycle(nc, 0);
    for(std::size_t done = 0; done < nc;) {
      std::vector<std::size_t> ready;
      for(std::size_t c = 0; c < nc; ++c)
        if(!built_cycle[c] && takes_from_built_loops(m_zone.cycle_loop[c], built_loop)) ready.push_back(c);
      CGAL_assertion(!ready.empty()); // a loop waits only for loops listed before it
      for(std::size_t c : ready) {
        Buffer_strip<K>(m_zone, c).build();
        built_cycle[c] = 1;
        ++done;
      }
      for(std::size_t c : ready) built_loop[m_zone.cycle_loop[c]] = 1;
    }
  }

private:
  // whether every loop listed before loop l that shares an edge with it is built
  bool takes_from_built_loops(std::size_t l, const std::vector<char>& built_loop) const
  {
    for(const auto& twin : m_zone.loops.loops[l].edge_twins)
      if(twin[0] != std::size_t(-1) && twin[0] < l && !built_loop[twin[0]]) return false;
    return true;
  }

  Buffer_zone<K>& m_zone;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_SECOND_BUFFER_LAYER_H
