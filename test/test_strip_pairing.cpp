// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The second buffer layer's strip pairing (strip_pairing.h) on synthetic strips with random
// quad costs: the cheapest pairing against an enumeration of every pairing of small strips,
// and a strip paired again after local changes against a fresh pairing, costing only the
// gaps the changes touch.

#include <CGAL/Quad_mesher_2/internal/strip_pairing.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <random>
#include <vector>

namespace qm2_strip_pairing_tests {

namespace QI = CGAL::Quad_mesher_2::internal;
using QI::Triangle;
using Quad = QI::Quad_vertices;
constexpr std::size_t none = QI::Buffer_tolerances::none;

// Quad costs drawn from the quad's vertices and each vertex's version: changing a version
// changes the costs of every quad at that vertex, as moving a point does.
struct Random_costs
{
  std::map<std::size_t, std::uint64_t> version;

  double strip_cost(const Quad& q) const
  {
    if(q[0] == none) return 2000.0;
    QI::State_hash h;
    for(std::size_t v : q) describe(v, h);
    const double u = double(h.second() >> 11) / double(std::uint64_t(1) << 53);
    return u < 0.05 ? 1000.0 + u : 60.0 * u; // a few invalid quads
  }
  void describe(std::size_t v, QI::State_hash& h) const
  {
    h.add(std::uint64_t(v));
    auto it = version.find(v);
    h.add(it == version.end() ? std::uint64_t(0) : it->second);
  }
};

// A strip of n F points (ids 0 ..) and M chain nodes (ids 1000000 ..), gap r holding
// g[r+1] - g[r] chain edges, some gaps with an extra node (ids 2000000 ..).
struct Strip
{
  std::vector<std::size_t> fid, gid, g;
  std::vector<QI::Extra_node> extra;
};

Strip random_strip(std::mt19937& rng, std::size_t n, std::size_t max_edges)
{
  Strip s;
  std::uniform_int_distribution<std::size_t> edges(0, max_edges);
  std::size_t M = 0;
  for(std::size_t r = 0; r < n; ++r) {
    s.fid.push_back(r);
    s.g.push_back(M);
    const std::size_t k = r == 0 ? 1 + edges(rng) % max_edges : edges(rng);
    s.extra.push_back(k > 0 && rng() % 2 ? QI::Extra_node{ rng() % k, 2000000 + r } : QI::Extra_node{});
    M += k;
  }
  for(std::size_t k = 0; k < M; ++k) s.gid.push_back(1000000 + k);
  return s;
}

// Every pairing of the strip, enumerated: each gap's option (extra node or not, F triangle
// after `mid` G triangles) and each start state, kept where the triangle the last gap leaves
// pending is the one the start assumed; the least cost (Cost::sum).
double cheapest_by_enumeration(const Strip& s, const Random_costs& costs)
{
  const std::size_t n = s.fid.size(), M = s.gid.size();
  auto k_of = [&](std::size_t r) { return (r + 1 < n ? s.g[r + 1] : M) - s.g[r]; };
  auto G = [&](std::size_t k) { return s.gid[k % M]; };
  auto F = [&](std::size_t r) { return s.fid[r % n]; };
  auto triangles = [&](std::size_t r, bool ins, std::size_t mid) {
    std::vector<std::size_t> nodes;
    for(std::size_t e = 0; e <= k_of(r); ++e) {
      nodes.push_back(G(s.g[r] + e));
      if(ins && e == s.extra[r].edge) nodes.push_back(s.extra[r].id);
    }
    std::vector<Triangle> t;
    for(std::size_t e = 0; e + 1 < nodes.size(); ++e) {
      if(e == mid) t.push_back({ F(r), nodes[e], F(r + 1) });
      t.push_back({ nodes[e], nodes[e + 1], e < mid ? F(r) : F(r + 1) });
    }
    if(mid + 1 == nodes.size()) t.push_back({ F(r), nodes[mid], F(r + 1) });
    return t;
  };
  double best = HUGE_VAL;
  std::vector<std::pair<bool, std::size_t>> choice(n);
  std::function<void(std::size_t)> choose = [&](std::size_t r) {
    if(r == n) {
      std::vector<Triangle> all;
      for(std::size_t j = 0; j < n; ++j) {
        const auto t = triangles(j, choice[j].first, choice[j].second);
        all.insert(all.end(), t.begin(), t.end());
      }
      if(all.size() % 2 != 0) return;
      // the triangles in cyclic order are paired from an even or an odd start
      for(std::size_t shift : { 0, 1 }) {
        QI::Cost c{ 0, 0 };
        for(std::size_t j = 0; j < all.size(); j += 2)
          c.add(costs.strip_cost(QI::merge(all[(j + shift) % all.size()], all[(j + shift + 1) % all.size()])));
        best = std::min(best, c.sum);
      }
      return;
    }
    for(bool ins : { false, true }) {
      if(ins && s.extra[r].edge == none) continue;
      for(std::size_t mid = 0; mid <= k_of(r) + (ins ? 1 : 0); ++mid) {
        choice[r] = { ins, mid };
        choose(r + 1);
      }
    }
  };
  choose(0);
  return best;
}

double cost_of(const QI::Strip_result& res, const Random_costs& costs)
{
  QI::Cost c{ 0, 0 };
  for(const Quad& q : res.quads) c.add(costs.strip_cost(q));
  return c.sum;
}

TEST(Strip_pairing, finds_the_cheapest_pairing_of_small_strips)
{
  std::mt19937 rng(7);
  for(int trial = 0; trial < 300; ++trial) {
    const Strip s = random_strip(rng, 1 + trial % 5, 3);
    if((s.fid.size() + s.gid.size()) % 2 != 0 && std::none_of(s.extra.begin(), s.extra.end(), [](const QI::Extra_node& x) {
         return x.edge != none;
       }))
      continue; // an odd triangle count without an extra node has no pairing
    Random_costs costs;
    const double expected = cheapest_by_enumeration(s, costs);
    QI::Strip_pairing<Random_costs> pairing(costs);
    const QI::Strip_result res = pairing.pair(s.fid, s.gid, s.g, s.extra);
    ASSERT_NEAR(res.cost.sum, expected, 1e-9 * (1 + expected)) << "trial " << trial;
    EXPECT_NEAR(cost_of(res, costs), res.cost.sum, 1e-9 * (1 + expected)) << "trial " << trial;
    EXPECT_EQ(2 * res.quads.size(), s.fid.size() + s.gid.size()
                                         + std::size_t(std::count(res.inserted.begin(), res.inserted.end(), true)));
  }
}

TEST(Strip_pairing, a_strip_paired_again_costs_only_the_gaps_its_changes_touch)
{
  std::mt19937 rng(11);
  const Strip s = random_strip(rng, 3000, 3);
  Random_costs costs;
  QI::Strip_pairing<Random_costs> kept(costs);
  kept.pair(s.fid, s.gid, s.g, s.extra);
  EXPECT_EQ(kept.gaps_costed(), s.fid.size());
  const std::size_t n = s.fid.size(), M = s.gid.size();
  for(int change = 1; change <= 20; ++change) {
    // a chain node and an F point move: the gaps that may pair a triangle at them change
    const std::size_t moved_g = rng() % M, moved_f = rng() % n;
    costs.version[s.gid[moved_g]] = std::uint64_t(change);
    costs.version[s.fid[moved_f]] = std::uint64_t(change);
    std::size_t touched = 0;
    for(std::size_t r = 0; r < n; ++r) {
      const std::size_t first = s.g[r], last = r + 1 < n ? s.g[r + 1] : M;
      const bool at_g = (moved_g + 1 - first + M) % M <= last - first + 1; // from first - 1 to last
      const bool at_f = (moved_f + 1 - r + n) % n <= 2;                    // from r - 1 to r + 1
      touched += at_g || at_f ? 1 : 0;
    }
    const std::size_t before = kept.gaps_costed();
    const QI::Strip_result again = kept.pair(s.fid, s.gid, s.g, s.extra);
    EXPECT_GT(kept.gaps_costed(), before);
    EXPECT_LE(kept.gaps_costed() - before, touched);
    QI::Strip_pairing<Random_costs> fresh(costs);
    const QI::Strip_result expected = fresh.pair(s.fid, s.gid, s.g, s.extra);
    EXPECT_EQ(again.cost.sum, expected.cost.sum);
    EXPECT_EQ(again.quads, expected.quads);
    EXPECT_EQ(again.inserted, expected.inserted);
  }
}

} // namespace qm2_strip_pairing_tests
