// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Paper §4.6, the pairing of the second buffer layer's strip: the strip between the first
// buffer points F and the boundary chain G is cut into triangles, each with one F edge or one G
// edge, and consecutive triangles are paired into quads by dynamic programming around the loop,
// minimising a sum of the quads' costs. Each gap between two F points may also take one extra
// chain node where the pairing wants it (an odd triangle count made even, a ladder of quads
// switched between its two phases).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PAIRING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PAIRING_H

#include <CGAL/Quad_mesher_2/internal/buffer_tolerances.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Triangles of the strip, in order around the loop: an F edge with its apex on G, or a G
// edge with its apex an F point. Vertices are mesh ids, counter-clockwise.
typedef std::array<std::size_t, 3> Triangle;

// the quad made of two triangles sharing an edge (Buffer_tolerances::none if they share Buffer_tolerances::none)
inline Quad_vertices merge(const Triangle& A, const Triangle& B)
{
  for(int k = 0; k < 3; ++k) {
    const std::size_t x = A[k], y = A[(k + 1) % 3];
    for(int j = 0; j < 3; ++j)
      if(B[j] == y && B[(j + 1) % 3] == x)
        return Quad_vertices{ x, B[(j + 2) % 3], y, A[(k + 2) % 3] };
  }
  return Quad_vertices{ Buffer_tolerances::none, Buffer_tolerances::none, Buffer_tolerances::none, Buffer_tolerances::none };
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
  // adds the quads costed in `o`
  void add(const Cost& o)
  {
    worst = (std::max)(worst, o.worst);
    sum += o.sum;
  }
};

struct Strip_result
{
  Cost cost;
  std::vector<Quad_vertices> quads;
  std::vector<bool> inserted; // per gap: whether it took its extra node
};

// the extra chain node a gap may take: after its `edge`-th chain edge, mesh id `id`
struct Extra_node
{
  std::size_t edge = Buffer_tolerances::none, id = Buffer_tolerances::none;
};

// Dynamic programming over the gaps of a strip. Gap r lies between F points r, r+1 (mesh
// ids fid) and chain nodes g[r] .. g[r+1] (g[n] = M wraps to 0), plus its extra node if it
// takes it; `mid` of its G triangles (apex F_r) come before its F triangle, the rest (apex
// F_{r+1}) after. State: 0 = no triangle pending; 1 = the gap's F triangle is pending (it
// came last); 2 = its last G triangle is; 3 = the same, that triangle's first node being
// the gap's extra node. `strip_cost(quad)` is a quad's cost in the pairing.
template <class Strip_cost>
class Strip_pairing
{
  static constexpr std::size_t none = Buffer_tolerances::none;
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
    Cost own[2];                       // its own quads' cost, by the same
    int out[2] = { 0, 0 };
    std::array<double, 4> with_pending = { { -1, -1, -1, -1 } }; // by incoming state
  };

public:
  Strip_pairing(const std::vector<std::size_t>& fid, const std::vector<std::size_t>& gid,
                const std::vector<std::size_t>& g, const std::vector<Extra_node>& extra, const Strip_cost& strip_cost)
    : m_fid(fid), m_gid(gid), m_g(g), m_extra(extra), m_strip_cost(strip_cost), n(fid.size()), M(gid.size()),
      m_k(n), m_options(n)
  {
    for(std::size_t r = 0; r + 1 < n; ++r) m_k[r] = g[r + 1] - g[r];
    m_k[n - 1] = M - g[n - 1];
    for(std::size_t r = 0; r < n; ++r)
      for(bool ins : { false, true }) {
        if(ins && extra[r].edge == none) continue;
        const std::size_t k = m_k[r] + (ins ? 1 : 0);
        for(std::size_t mid = 0; mid <= k; ++mid) m_options[r].emplace_back(mid, ins, triangles(r, ins, mid));
      }
  }

  // the cheapest pairing over the four states the cycle may start (and end) in
  Strip_result pair()
  {
    Strip_result result;
    std::vector<Step> best_steps;
    int best_start = 0;
    for(int start = 0; start < 4; ++start) {
      if(start == 2 && m_k[n - 1] == 0) continue;
      if(start == 3 && !last_edge_extra(n - 1)) continue;
      std::vector<Step> steps;
      const Cost cost = run_from(start, steps);
      if(cost < result.cost) {
        result.cost = cost;
        best_start = start;
        best_steps = std::move(steps);
      }
    }
    if(result.cost.worst == HUGE_VAL) return result;
    add_quads(best_start, best_steps, result);
    return result;
  }

private:
  std::size_t F(std::size_t r) const { return m_fid[r % n]; }
  std::size_t G(std::size_t k) const { return m_gid[k % M]; }
  // the e-th node of gap r, with (`ins`) or without its extra node
  std::size_t node(std::size_t r, bool ins, std::size_t e) const
  {
    if(!ins || e <= m_extra[r].edge) return G(m_g[r] + e);
    return e == m_extra[r].edge + 1 ? m_extra[r].id : G(m_g[r] + e - 1);
  }
  std::vector<Triangle> triangles(std::size_t r, bool ins, std::size_t mid) const
  {
    std::vector<Triangle> t;
    const std::size_t k = m_k[r] + (ins ? 1 : 0);
    for(std::size_t e = 0; e < mid; ++e) t.push_back({ node(r, ins, e), node(r, ins, e + 1), F(r) });
    t.push_back({ F(r), node(r, ins, mid), F(r + 1) });
    for(std::size_t e = mid; e < k; ++e) t.push_back({ node(r, ins, e), node(r, ins, e + 1), F(r + 1) });
    return t;
  }
  bool last_edge_extra(std::size_t r) const { return m_extra[r].edge != none && m_extra[r].edge + 1 == m_k[r]; }
  // the triangle gap r leaves pending in `state`
  Triangle pending(std::size_t r, int state) const
  {
    const std::size_t end = m_g[r] + m_k[r];
    if(state == 1) return Triangle{ F(r), G(end), F(r + 1) };
    return Triangle{ state == 3 ? m_extra[r].id : G(end + M - 1), G(end), F(r + 1) };
  }

  // The cheapest way around the cycle from state `start` back to it, its steps gap by gap
  // in `steps` (empty if there is none).
  Cost run_from(int start, std::vector<Step>& steps)
  {
    std::vector<std::array<Cost, 4>> best(n + 1);
    std::vector<std::array<Step, 4>> back(n + 1);
    best[0][start] = Cost{ 0, 0 };
    for(std::size_t r = 0; r < n; ++r)
      for(int s = 0; s < 4; ++s) {
        if(best[r][s].worst == HUGE_VAL) continue;
        const int p = s != 0 ? 1 : 0;
        for(Option& o : m_options[r]) {
          const auto& t = o.t;
          if(!o.paired[p]) pair_option(r, p, o);
          Cost cst = best[r][s];
          if(s != 0) {
            if(o.with_pending[s] < 0) o.with_pending[s] = m_strip_cost(merge(pending(r == 0 ? n - 1 : r - 1, s), t[0]));
            cst.add(o.with_pending[s]);
          }
          cst.add(o.own[p]);
          const int out = o.out[p];
          if(cst < best[r + 1][out]) { best[r + 1][out] = cst; back[r + 1][out] = Step{ o.mid, s, o.ins }; }
        }
      }
    if(best[n][start] < Cost()) {
      steps.assign(n, Step{});
      int s = start;
      for(std::size_t r = n; r > 0; --r) { steps[r - 1] = back[r][s]; s = back[r][s].state; }
    }
    return best[n][start];
  }

  // the costs of option o's own quads of gap r, and the state it leaves, with (p = 1) or
  // without a pending triangle coming in
  void pair_option(std::size_t r, int p, Option& o) const
  {
    const auto& t = o.t;
    std::size_t pos = std::size_t(p);
    o.own[p] = Cost{ 0, 0 };
    for(; pos + 1 < t.size(); pos += 2) o.own[p].add(m_strip_cost(merge(t[pos], t[pos + 1])));
    const std::size_t k = m_k[r] + (o.ins ? 1 : 0);
    o.out[p] = pos == t.size() ? 0 : o.mid == k ? 1 : (o.ins && last_edge_extra(r)) ? 3 : 2;
    o.paired[p] = true;
  }

  // the quads of the steps from state `start`
  void add_quads(int start, const std::vector<Step>& steps, Strip_result& result) const
  {
    result.inserted.assign(n, false);
    Triangle in = start == 0 ? Triangle{} : pending(n - 1, start);
    bool has_in = start != 0;
    for(std::size_t r = 0; r < n; ++r) {
      result.inserted[r] = steps[r].ins;
      const auto t = triangles(r, steps[r].ins, steps[r].mid);
      std::size_t pos = 0;
      if(has_in) { result.quads.push_back(merge(in, t[0])); pos = 1; }
      for(; pos + 1 < t.size(); pos += 2) result.quads.push_back(merge(t[pos], t[pos + 1]));
      has_in = pos < t.size();
      if(has_in) in = t.back();
    }
  }

  const std::vector<std::size_t>& m_fid;
  const std::vector<std::size_t>& m_gid;
  const std::vector<std::size_t>& m_g;
  const std::vector<Extra_node>& m_extra;
  const Strip_cost& m_strip_cost;
  const std::size_t n, M; // F points (gaps), chain nodes
  std::vector<std::size_t> m_k; // chain edges per gap
  std::vector<std::vector<Option>> m_options;
};

template <class Strip_cost>
Strip_result pair_strip(const std::vector<std::size_t>& fid, const std::vector<std::size_t>& gid,
                        const std::vector<std::size_t>& g, const std::vector<Extra_node>& extra,
                        const Strip_cost& strip_cost)
{
  return Strip_pairing<Strip_cost>(fid, gid, g, extra, strip_cost).pair();
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PAIRING_H
