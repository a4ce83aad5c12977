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
#include <CGAL/Quad_mesher_2/internal/state_hash.h>

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

// The choice a gap's pairing makes: where its F triangle lies among its G triangles (`mid` of
// them before it) and whether it takes its extra node.
struct Gap_choice
{
  std::uint32_t mid = 0;
  bool ins = false;
};

// A min-plus transfer over one gap or a run of them: from the state the gap before leaves
// (row) to the state the run's last gap leaves (column), the cheapest cost.
typedef std::array<std::array<Cost, 4>, 4> Transfer;

/// Dynamic programming over the gaps of a strip, kept from one pairing to the next. Gap r lies
/// between F points r, r+1 (mesh ids fid) and chain nodes g[r] .. g[r+1] (g[n] = M wraps to 0),
/// plus its extra node if it takes it; `mid` of its G triangles (apex F_r) come before its F
/// triangle, the rest (apex F_{r+1}) after. State: 0 = no triangle pending; 1 = the gap's F
/// triangle is pending (it came last); 2 = its last G triangle is; 3 = the same, that
/// triangle's first node being the gap's extra node.
///
/// Each gap is summed up as a Transfer; the strip's cheapest pairing from start state s back to
/// s is entry (s, s) of their ordered min-plus product, kept in a segment tree. A strip paired
/// again (another plan, a node taken out) differs from the last in a few gaps: only the gaps
/// whose inputs (every node's position and kind the costs read: `Costs::describe()`) hash
/// differently are costed again, and only their paths to the root multiplied again.
/// `Costs::strip_cost(quad)` is a quad's cost in the pairing.
template <class Costs>
class Strip_pairing
{
  static constexpr std::size_t none = Buffer_tolerances::none;
  struct Leaf
  {
    Transfer cost;
    std::array<std::array<Gap_choice, 4>, 4> choice;
    std::uint64_t hash[2] = { 0, 0 };
  };
  struct Node
  {
    Transfer cost;
    std::array<std::array<std::uint8_t, 4>, 4> via; // the state between the two halves
  };

public:
  explicit Strip_pairing(const Costs& costs) : m_costs(costs) {}

  /// The cheapest pairing of the strip over the four states its cycle may start (and end) in.
  Strip_result pair(const std::vector<std::size_t>& fid, const std::vector<std::size_t>& gid,
                    const std::vector<std::size_t>& g, const std::vector<Extra_node>& extra)
  {
    const bool new_strip = set_strip(fid, gid, g, extra);
    const std::vector<std::size_t> changed = cost_changed_gaps();
    if(new_strip) multiply_all();
    else update_tree(changed);
    Strip_result result;
    int best_start = 0;
    const Transfer& all = root();
    for(int start = 0; start < 4; ++start)
      if(all[start][start] < result.cost) { result.cost = all[start][start]; best_start = start; }
    if(result.cost.worst == HUGE_VAL) return result;
    std::vector<Gap_choice> steps(n);
    trace(1, 0, m_size, best_start, best_start, steps);
    add_quads(best_start, steps, result);
    return result;
  }

  /// how many gaps were costed, over every pairing so far
  std::size_t gaps_costed() const { return m_gaps_costed; }

private:
  // true if the strip has another number of gaps than the last: nothing is kept
  bool set_strip(const std::vector<std::size_t>& fid, const std::vector<std::size_t>& gid,
                 const std::vector<std::size_t>& g, const std::vector<Extra_node>& extra)
  {
    m_fid = &fid;
    m_gid = &gid;
    m_g = &g;
    m_extra = &extra;
    M = gid.size();
    const bool new_strip = fid.size() != n;
    if(new_strip) {
      n = fid.size();
      m_leaves.assign(n, Leaf{});
      for(m_size = 1; m_size < n; m_size *= 2) {}
      m_nodes.assign(m_size, Node{});
    }
    m_k.resize(n);
    for(std::size_t r = 0; r + 1 < n; ++r) m_k[r] = g[r + 1] - g[r];
    m_k[n - 1] = M - g[n - 1];
    return new_strip;
  }

  // the gaps whose inputs changed since the last pairing, costed again, in order
  std::vector<std::size_t> cost_changed_gaps()
  {
    std::vector<std::size_t> changed;
    for(std::size_t r = 0; r < n; ++r) {
      const State_hash h = gap_inputs(r);
      Leaf& leaf = m_leaves[r];
      if(leaf.hash[0] == h.first() && leaf.hash[1] == h.second()) continue;
      leaf.hash[0] = h.first();
      leaf.hash[1] = h.second();
      cost_gap(r, leaf);
      changed.push_back(r);
    }
    m_gaps_costed += changed.size();
    return changed;
  }

  // Everything gap r's transfer reads: its own nodes, its F points and those of the gap before,
  // whose pending triangle it may pair with, and which of these nodes are the same.
  State_hash gap_inputs(std::size_t r) const
  {
    const std::size_t prev = r == 0 ? n - 1 : r - 1;
    std::vector<std::size_t>& nodes = m_gap_nodes;
    nodes.assign({ F(prev), F(r), F(r + 1) });
    for(std::size_t e = 0; e <= m_k[r]; ++e) nodes.push_back(G((*m_g)[r] + e));
    if(has_extra(r)) nodes.push_back((*m_extra)[r].id);
    if(m_k[prev] > 0) nodes.push_back(G((*m_g)[r] + M - 1));
    if(last_edge_extra(prev)) nodes.push_back((*m_extra)[prev].id);
    State_hash h;
    h.add(std::uint64_t(m_k[r]));
    h.add(std::uint64_t(m_k[prev]));
    h.add(std::uint64_t(has_extra(r) ? (*m_extra)[r].edge : none));
    h.add(std::uint64_t(last_edge_extra(prev)));
    for(std::size_t i = 0; i < nodes.size(); ++i) {
      m_costs.describe(nodes[i], h);
      h.add(std::uint64_t(std::find(nodes.begin(), nodes.end(), nodes[i]) - nodes.begin()));
    }
    return h;
  }

  // Gap r's transfer: for each incoming state, each option (without, then with its extra
  // node; its F triangle after 0, 1, ... G triangles), the first cheapest per outgoing state.
  void cost_gap(std::size_t r, Leaf& leaf) const
  {
    leaf.cost = Transfer{};
    const std::size_t prev = r == 0 ? n - 1 : r - 1;
    const std::array<bool, 4> can_come_in = { { true, true, m_k[prev] > 0, last_edge_extra(prev) } };
    for(bool ins : { false, true }) {
      if(ins && !has_extra(r)) continue;
      const std::size_t k = m_k[r] + (ins ? 1 : 0);
      for(std::size_t mid = 0; mid <= k; ++mid) {
        const std::vector<Triangle> t = triangles(r, ins, mid);
        std::array<Cost, 2> own; // by whether a pending triangle comes in
        std::array<int, 2> out;
        for(std::size_t p = 0; p < 2; ++p) {
          std::size_t pos = p;
          own[p] = Cost{ 0, 0 };
          for(; pos + 1 < t.size(); pos += 2) own[p].add(m_costs.strip_cost(merge(t[pos], t[pos + 1])));
          out[p] = pos == t.size() ? 0 : mid == k ? 1 : (ins && last_edge_extra(r)) ? 3 : 2;
        }
        for(int s = 0; s < 4; ++s) {
          if(!can_come_in[s]) continue;
          const std::size_t p = s != 0 ? 1 : 0;
          Cost c{ 0, 0 };
          if(s != 0) c.add(m_costs.strip_cost(merge(pending(prev, s), t[0])));
          c.add(own[p]);
          if(c < leaf.cost[s][out[p]]) {
            leaf.cost[s][out[p]] = c;
            leaf.choice[s][out[p]] = Gap_choice{ std::uint32_t(mid), ins };
          }
        }
      }
    }
  }

  // the products over the tree's nodes above the changed leaves, level by level
  void update_tree(const std::vector<std::size_t>& changed)
  {
    std::vector<std::size_t> level;
    for(std::size_t r : changed) level.push_back((m_size + r) / 2);
    while(!level.empty() && level.front() != 0) {
      level.erase(std::unique(level.begin(), level.end()), level.end());
      for(std::size_t i : level) multiply(i);
      for(std::size_t& i : level) i /= 2;
    }
  }

  void multiply_all()
  {
    for(std::size_t i = m_size; i-- > 1;) multiply(i);
  }

  // node i = its left child's transfer, then its right child's
  void multiply(std::size_t i)
  {
    const Transfer& A = transfer(2 * i);
    const Transfer& B = transfer(2 * i + 1);
    Node& node = m_nodes[i];
    for(int s = 0; s < 4; ++s)
      for(int t = 0; t < 4; ++t) {
        Cost best;
        std::uint8_t via = 0;
        for(int m = 0; m < 4; ++m) {
          if(A[s][m].worst == HUGE_VAL || B[m][t].worst == HUGE_VAL) continue;
          Cost c = A[s][m];
          c.add(B[m][t]);
          if(c < best) { best = c; via = std::uint8_t(m); }
        }
        node.cost[s][t] = best;
        node.via[s][t] = via;
      }
  }

  // node i's transfer: a gap's, the identity past the last gap, or a product
  const Transfer& transfer(std::size_t i) const
  {
    if(i < m_size) return m_nodes[i].cost;
    return i - m_size < n ? m_leaves[i - m_size].cost : m_identity;
  }
  const Transfer& root() const { return m_size == 1 ? m_leaves[0].cost : m_nodes[1].cost; }
  // (not a function-local static built by a lambda: GCC 12 gets that one wrong)
  static Transfer identity()
  {
    Transfer t{};
    for(int s = 0; s < 4; ++s) t[s][s] = Cost{ 0, 0 };
    return t;
  }

  // the gaps' choices under node i (gaps lo .. hi - 1), from state s to state t
  void trace(std::size_t i, std::size_t lo, std::size_t hi, int s, int t, std::vector<Gap_choice>& steps) const
  {
    if(lo >= n) return;
    if(i >= m_size) { steps[lo] = m_leaves[lo].choice[s][t]; return; }
    const int m = m_nodes[i].via[s][t];
    const std::size_t half = (lo + hi) / 2;
    trace(2 * i, lo, half, s, m, steps);
    trace(2 * i + 1, half, hi, m, t, steps);
  }

  std::size_t F(std::size_t r) const { return (*m_fid)[r % n]; }
  std::size_t G(std::size_t k) const { return (*m_gid)[k % M]; }
  bool has_extra(std::size_t r) const { return (*m_extra)[r].edge != none; }
  // the e-th node of gap r, with (`ins`) or without its extra node
  std::size_t node(std::size_t r, bool ins, std::size_t e) const
  {
    const Extra_node& x = (*m_extra)[r];
    if(!ins || e <= x.edge) return G((*m_g)[r] + e);
    return e == x.edge + 1 ? x.id : G((*m_g)[r] + e - 1);
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
  bool last_edge_extra(std::size_t r) const { return has_extra(r) && (*m_extra)[r].edge + 1 == m_k[r]; }
  // the triangle gap r leaves pending in `state`
  Triangle pending(std::size_t r, int state) const
  {
    const std::size_t end = (*m_g)[r] + m_k[r];
    if(state == 1) return Triangle{ F(r), G(end), F(r + 1) };
    return Triangle{ state == 3 ? (*m_extra)[r].id : G(end + M - 1), G(end), F(r + 1) };
  }

  // the quads of the gaps' choices from state `start`
  void add_quads(int start, const std::vector<Gap_choice>& steps, Strip_result& result) const
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

  const Costs& m_costs;
  const std::vector<std::size_t>* m_fid = nullptr;
  const std::vector<std::size_t>* m_gid = nullptr;
  const std::vector<std::size_t>* m_g = nullptr;
  const std::vector<Extra_node>* m_extra = nullptr;
  std::size_t n = 0, M = 0;     // F points (gaps), chain nodes
  std::vector<std::size_t> m_k; // chain edges per gap
  mutable std::vector<std::size_t> m_gap_nodes; // gap_inputs()' scratch
  std::vector<Leaf> m_leaves;   // by gap
  std::size_t m_size = 1;       // the tree's leaves: a power of two, at least n
  std::vector<Node> m_nodes;    // the tree's inner nodes, from 1 (the root)
  const Transfer m_identity = identity();
  std::size_t m_gaps_costed = 0;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_STRIP_PAIRING_H
