// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The strongly balanced quadtree and its 2-refinement templates.

#include "qm2_mesh_checks.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Balanced_quadtree_2.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/internal/Key_map.h>
#include <CGAL/Quad_mesher_2/internal/apply_templates.h>
#include <CGAL/Quad_mesher_2/internal/radix_sort.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace qm2_test_quadtree {

using qm2_test::K;
using Tree = CGAL::Quad_mesher_2::Balanced_quadtree_2<K>;
using CGAL::Quad_mesher_2::Cell_key;
using CGAL::Quad_mesher_2::internal::Template_choice;

Tree unit_tree(int max_depth = 8)
{
  // [0,1]^2 gets a root square of side 2 anchored at the origin.
  return Tree(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1, 1)), max_depth);
}

// a tree of depth max_depth refined at `points` random points of [0, 2]^2, each to a random
// level, then balanced
Tree random_balanced_tree(std::mt19937& rng, int max_depth, int points)
{
  Tree t = unit_tree(max_depth);
  std::uniform_real_distribution<double> u(0, 2);
  std::uniform_int_distribution<int> lv(1, max_depth);
  for(int p = 0; p < points; ++p)
    t.refine_at(K::Point_2(u(rng), u(rng)), lv(rng));
  t.balance();
  return t;
}

void refine_uniformly(Tree& t, int level)
{
  t.refine([&](const Cell_key& k) { return k.level < level; });
}

// Brute force: every pair of leaves that share an edge or a corner differ by <= 1 level.
::testing::AssertionResult brute_force_balanced(const Tree& t)
{
  std::vector<Cell_key> leaves = t.leaves();
  const int top = t.max_depth();
  for(std::size_t a = 0; a < leaves.size(); ++a)
    for(std::size_t b = a + 1; b < leaves.size(); ++b) {
      const Cell_key &p = leaves[a], &q = leaves[b];
      // integer boxes on the finest lattice
      long long px0 = (long long)p.i << (top - p.level), px1 = (long long)(p.i + 1) << (top - p.level);
      long long py0 = (long long)p.j << (top - p.level), py1 = (long long)(p.j + 1) << (top - p.level);
      long long qx0 = (long long)q.i << (top - q.level), qx1 = (long long)(q.i + 1) << (top - q.level);
      long long qy0 = (long long)q.j << (top - q.level), qy1 = (long long)(q.j + 1) << (top - q.level);
      bool touch = px0 <= qx1 && qx0 <= px1 && py0 <= qy1 && qy0 <= py1;
      if(touch && std::abs(p.level - q.level) > 1)
        return ::testing::AssertionFailure() << "leaves at levels " << p.level << " and " << q.level << " touch";
    }
  return ::testing::AssertionSuccess();
}

TEST(Balanced_quadtree_2, root_grid_is_dyadic_and_covers_input)
{
  Tree t(K::Iso_rectangle_2(K::Point_2(0.3, -0.7), K::Point_2(0.9, -0.3)), 10);
  EXPECT_EQ(t.root_side(), 0.5); // the smallest power of two >= 0.4, the shorter side
  EXPECT_LE(t.origin_x(), 0.3);
  EXPECT_LE(t.origin_y(), -0.7);
  EXPECT_GT(t.origin_x() + t.root_cells_x() * t.root_side(), 0.9);
  EXPECT_GT(t.origin_y() + t.root_cells_y() * t.root_side(), -0.3);
  double finest = std::ldexp(t.root_side(), -11);
  EXPECT_EQ(std::fmod(t.origin_x(), finest), 0.0);
  EXPECT_EQ(t.number_of_leaves(), std::size_t(t.root_cells_x() * t.root_cells_y()));
}

TEST(Balanced_quadtree_2, thin_input_gets_a_row_of_square_cells)
{
  Tree t(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(100, 1)), 10);
  EXPECT_GE(t.root_cells_x(), 7u);
  EXPECT_EQ(t.root_cells_y(), 1u);
  EXPECT_GE(t.root_side() * t.root_cells_x(), 100.0);
}

TEST(Balanced_quadtree_2, locate_is_exact_on_lattice_lines)
{
  Tree t = unit_tree(6);
  refine_uniformly(t, 3); // side 2 / 8 = 0.25
  // A point on a vertical lattice line belongs to the cell on its right (half-open cells).
  Cell_key k = t.locate(K::Point_2(0.25, 0.1));
  EXPECT_EQ(k, Cell_key(3, 1, 0));
  k = t.locate(K::Point_2(std::nextafter(0.25, 0.0), 0.1));
  EXPECT_EQ(k, Cell_key(3, 0, 0));
  k = t.locate(K::Point_2(0.5, 0.75));
  EXPECT_EQ(k, Cell_key(3, 2, 3));
}

TEST(Balanced_quadtree_2, refine_at_reaches_requested_level)
{
  Tree t = unit_tree(12);
  K::Point_2 p(0.123456789, 0.987654321);
  t.refine_at(p, 9);
  Cell_key k = t.locate(p);
  EXPECT_EQ(k.level, 9);
  K::Iso_rectangle_2 r = t.cell_rectangle(k);
  EXPECT_NE(r.bounded_side(p), CGAL::ON_UNBOUNDED_SIDE);
}

TEST(Balanced_quadtree_2, the_cell_containing_a_point_is_a_node_down_to_its_leaf)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 2.0);
  for(int trial = 0; trial < 10; ++trial) {
    const Tree t = random_balanced_tree(rng, 9, 1 + trial % 6);
    for(int n = 0; n < 200; ++n) {
      const K::Point_2 p(u(rng), u(rng));
      const Cell_key leaf = t.locate(p);
      for(int level = 0; level <= t.max_depth(); ++level) {
        const Cell_key k = t.cell_containing(p, level);
        ASSERT_EQ(t.is_node(k), level <= leaf.level) << "trial " << trial << " level " << level;
        if(level == leaf.level) {
          ASSERT_EQ(k, leaf);
        }
      }
    }
  }
}

TEST(Balanced_quadtree_2, depth_guard_raises_a_clear_error)
{
  Tree t = unit_tree(5);
  try {
    t.refine_at(K::Point_2(0.5, 0.5), 6);
    FAIL() << "no error";
  } catch(const CGAL::Quad_mesher_2::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("maximum depth 5"), std::string::npos) << e.what();
  }
  EXPECT_THROW(t.refine([](const Cell_key&) { return true; }), CGAL::Quad_mesher_2::Meshing_error);
  EXPECT_THROW(Tree(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1, 1)), 99),
               CGAL::Quad_mesher_2::Meshing_error);
}

TEST(Balanced_quadtree_2, precision_lowers_the_depth_with_a_reason)
{
  // 1e-4 across at 1e5 from the origin: 24 levels cannot be represented exactly in doubles
  K::Iso_rectangle_2 box(K::Point_2(1e5, 1e5), K::Point_2(1e5 + 1e-4, 1e5 + 1e-4));
  Tree t(box, 24);
  EXPECT_LT(t.max_depth(), 24);
  EXPECT_GE(t.max_depth(), 12);
  EXPECT_NE(t.depth_limit().find("exactly this far from the origin"), std::string::npos) << t.depth_limit();
  try {
    t.refine([](const Cell_key&) { return true; });
    FAIL() << "no error";
  } catch(const CGAL::Quad_mesher_2::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("far from the origin"), std::string::npos) << e.what();
  }
  // a vanishing extent cannot be meshed at all
  EXPECT_THROW(Tree(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1e-300, 1e-300)), 24),
               CGAL::Quad_mesher_2::Meshing_error);
  Tree tiny(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1e-135, 1e-135)), 24);
  EXPECT_LT(tiny.max_depth(), 24);
  EXPECT_NE(tiny.depth_limit().find("too small to measure"), std::string::npos) << tiny.depth_limit();
}

TEST(Balanced_quadtree_2, leaf_budget_stops_refinement)
{
  Tree t = unit_tree(12);
  t.set_max_leaves(1000);
  EXPECT_THROW(t.refine([](const Cell_key& k) { return k.level < 10; }), CGAL::Quad_mesher_2::Meshing_error);
  EXPECT_LE(t.number_of_leaves(), 1000u);
}

TEST(Balanced_quadtree_2, balance_random_trees)
{
  std::mt19937 rng(7);
  for(int trial = 0; trial < 30; ++trial) {
    const Tree t = random_balanced_tree(rng, 9, 1 + trial % 6);
    ASSERT_TRUE(t.is_strongly_balanced());
    if(t.number_of_leaves() < 2500) {
      ASSERT_TRUE(brute_force_balanced(t));
    }
    auto mesh = CGAL::Quad_mesher_2::internal::templated_mesh(t);
    ASSERT_TRUE(qm2_checks::tiles_rectangle(mesh, 0, 0, 2, 2));
    auto range = qm2_checks::angle_range(mesh);
    EXPECT_GE(range.min, 45 - 1e-9);
    EXPECT_LE(range.max, 135 + 1e-9);
  }
}

// templated_mesh() skips the lookups of four sibling leaves at their parent's centre: each
// leaf must still get the template choose_template() gives it alone (as many quads).
TEST(Balanced_quadtree_2, templated_mesh_takes_each_leafs_own_template)
{
  std::mt19937 rng(11);
  for(int trial = 0; trial < 20; ++trial) {
    const Tree t = random_balanced_tree(rng, 8, 1 + trial % 5);
    std::vector<Cell_key> cells;
    const auto mesh = CGAL::Quad_mesher_2::internal::templated_mesh(t, &cells);
    ASSERT_EQ(cells.size(), mesh.quads.size());
    for(std::size_t q = 0; q < cells.size();) {
      const Cell_key k = cells[q];
      std::size_t n = 0;
      while(q < cells.size() && cells[q] == k) ++q, ++n;
      const auto& expected = CGAL::Quad_mesher_2::internal::template_of(CGAL::Quad_mesher_2::internal::choose_template(t, k));
      ASSERT_EQ(n, expected.size) << "leaf (" << k.level << ", " << k.i << ", " << k.j << ")";
    }
  }
}

// The radix sort behind the Morton order is a stable sort by key, whatever bits the keys use.
TEST(Balanced_quadtree_2, radix_sort_is_a_stable_sort_by_key)
{
  std::mt19937_64 rng(5);
  for(int low_zero_bits : { 0, 3, 20, 40 })
    for(std::size_t n : { 0, 1, 2, 7, 1000, 20000 }) {
      std::vector<std::pair<std::uint64_t, std::size_t>> v(n);
      for(std::size_t i = 0; i < n; ++i)
        v[i] = { ((rng() % (n / 3 + 1)) << low_zero_bits) | (low_zero_bits == 0 ? rng() % 2 : 0), i };
      if(n == 20000) v[7].first = ~std::uint64_t(0) << low_zero_bits; // the top bits too
      auto expected = v;
      std::stable_sort(expected.begin(), expected.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      CGAL::Quad_mesher_2::internal::radix_sort_by_key(v);
      ASSERT_EQ(v, expected) << low_zero_bits << " " << n;
    }
}

TEST(Balanced_quadtree_2, balance_splits_corner_neighbours)
{
  // CGAL's Orthtree::grade() only looks across faces; a deep leaf touching a coarse leaf at a
  // corner only must be balanced too.
  Tree t = unit_tree(6);
  refine_uniformly(t, 1);
  t.refine_at(K::Point_2(0.999, 0.999), 4); // deep in the lower-left root quarter's corner
  EXPECT_FALSE(t.is_strongly_balanced());
  t.balance();
  EXPECT_TRUE(t.is_strongly_balanced());
  EXPECT_TRUE(brute_force_balanced(t));
  // the diagonal neighbour (upper-right quarter) had to be split
  EXPECT_TRUE(t.is_split(Cell_key(1, 1, 1)));
}

TEST(Balanced_quadtree_2, balance_does_not_change_a_balanced_tree)
{
  Tree t = unit_tree(6);
  refine_uniformly(t, 3);
  t.refine_at(K::Point_2(1, 1), 4);
  ASSERT_TRUE(t.is_strongly_balanced());
  std::size_t before = t.number_of_leaves();
  t.balance();
  EXPECT_EQ(t.number_of_leaves(), before);
}

// Every neighbour configuration of a leaf C at level 3: each of its 8 neighbours is a coarser
// leaf (level 2), a leaf of its level, or split (level 4), for C in each of the 4 child
// positions of its parent (which also covers both lattice parities). Admissible configurations
// are those that are already strongly balanced; for each one the templated mesh must be
// conforming with angles in {45, 90, 135} and C must take the template the parity rule names.
TEST(Balanced_quadtree_2, templates_exhaustive_neighbour_configurations)
{
  const int dirs[8][2] = { { -1, -1 }, { 0, -1 }, { 1, -1 }, { -1, 0 }, { 1, 0 }, { -1, 1 }, { 0, 1 }, { 1, 1 } };
  std::set<std::pair<int, int>> templates_seen; // (kind, corner)
  int admissible = 0, total = 0;
  for(int pos = 0; pos < 4; ++pos) {
    const std::uint32_t ci = 3 + (pos & 1), cj = 3 + (pos >> 1);
    for(int code = 0; code < 6561; ++code) {
      int state[8];
      for(int d = 0, c = code; d < 8; ++d, c /= 3)
        state[d] = c % 3 - 1;
      ++total;
      // level-2 cells that must stay leaves (hold a coarse neighbour) or be split
      std::map<std::pair<std::uint32_t, std::uint32_t>, int> parent_state;
      bool consistent = true;
      auto want = [&](std::uint32_t i, std::uint32_t j, int s) {
        auto key = std::make_pair(i >> 1, j >> 1);
        int need = s < 0 ? -1 : 1;
        auto it = parent_state.find(key);
        if(it == parent_state.end())
          parent_state[key] = need;
        else if(it->second != need)
          consistent = false;
      };
      want(ci, cj, 0);
      for(int d = 0; d < 8; ++d)
        want(ci + dirs[d][0], cj + dirs[d][1], state[d]);
      if(!consistent)
        continue;
      Tree t = unit_tree(6);
      refine_uniformly(t, 2);
      for(std::uint32_t j = 0; j < 4; ++j)
        for(std::uint32_t i = 0; i < 4; ++i) {
          auto it = parent_state.find({ i, j });
          if(it == parent_state.end() || it->second > 0)
            t.split(Cell_key(2, i, j));
        }
      for(int d = 0; d < 8; ++d)
        if(state[d] > 0)
          t.split(Cell_key(3, ci + dirs[d][0], cj + dirs[d][1]));
      if(!t.is_strongly_balanced())
        continue;
      ++admissible;
      Template_choice choice = CGAL::Quad_mesher_2::internal::choose_template(t, Cell_key(3, ci, cj));
      // expected by the parity rule: C's even corners touching a split level-3 neighbour
      int expected_active = 0, expected_corner = -1;
      const int cdx[4] = { 0, 1, 1, 0 }, cdy[4] = { 0, 0, 1, 1 };
      for(int c = 0; c < 4; ++c) {
        if(((ci + cdx[c] + cj + cdy[c]) & 1) != 0)
          continue;
        bool touches = false;
        for(int d = 0; d < 8; ++d) {
          int ni = int(ci) + dirs[d][0], nj = int(cj) + dirs[d][1];
          int vx = int(ci) + cdx[c], vy = int(cj) + cdy[c];
          if(state[d] > 0 && vx >= ni && vx <= ni + 1 && vy >= nj && vy <= nj + 1)
            touches = true;
        }
        if(touches) {
          ++expected_active;
          expected_corner = c;
        }
      }
      ASSERT_EQ(int(choice.kind), expected_active) << "pos " << pos << " code " << code;
      if(expected_active == 1) {
        ASSERT_EQ(choice.corner, expected_corner);
      }
      templates_seen.insert({ int(choice.kind), choice.corner });
      auto mesh = CGAL::Quad_mesher_2::internal::templated_mesh(t);
      ASSERT_TRUE(qm2_checks::tiles_rectangle(mesh, 0, 0, 2, 2)) << "pos " << pos << " code " << code;
      auto range = qm2_checks::angle_range(mesh);
      ASSERT_GE(range.min, 45 - 1e-9);
      ASSERT_LE(range.max, 135 + 1e-9);
    }
  }
  EXPECT_GT(admissible, 100);
  EXPECT_LT(admissible, total);
  // plain, the four transitions and refinement all occur
  EXPECT_EQ(templates_seen.size(), 6u);
}

// Subsets of the 16 level-2 cells split (every 7th of the 2^16, which visits every cell
// split and unsplit in all parities), then balanced: the templated mesh tiles the root square
// without hanging nodes.
TEST(Balanced_quadtree_2, templates_split_patterns_of_a_4x4_grid)
{
  const int stride = qm2_test::exact_constructions ? 31 : 7;
  for(int mask = 0; mask < (1 << 16); mask += stride) {
    Tree t = unit_tree(6);
    refine_uniformly(t, 2);
    for(int b = 0; b < 16; ++b)
      if(mask & (1 << b))
        t.split(Cell_key(2, b % 4, b / 4));
    // one deeper cell, so that transitions also occur at level 3
    if(mask & 1)
      t.split(Cell_key(3, 1, 1));
    t.balance();
    ASSERT_TRUE(t.is_strongly_balanced());
    auto mesh = CGAL::Quad_mesher_2::internal::templated_mesh(t);
    ASSERT_TRUE(qm2_checks::tiles_rectangle(mesh, 0, 0, 2, 2)) << "mask " << mask;
    auto range = qm2_checks::angle_range(mesh);
    ASSERT_GE(range.min, 45 - 1e-9);
    ASSERT_LE(range.max, 135 + 1e-9);
  }
}

TEST(Balanced_quadtree_2, uniform_tree_gives_a_grid)
{
  Tree t = unit_tree(6);
  refine_uniformly(t, 3);
  t.balance();
  auto mesh = CGAL::Quad_mesher_2::internal::templated_mesh(t);
  EXPECT_EQ(mesh.quads.size(), 64u);
  EXPECT_EQ(mesh.points.size(), 81u);
  auto range = qm2_checks::angle_range(mesh);
  EXPECT_NEAR(range.min, 90, 1e-9);
  EXPECT_NEAR(range.max, 90, 1e-9);
}

TEST(Balanced_quadtree_2, scaling_by_powers_of_two_keeps_the_topology)
{
  auto build = [](double scale, double shift) {
    Tree t(K::Iso_rectangle_2(K::Point_2(shift, shift), K::Point_2(shift + scale, shift + 0.5 * scale)), 10);
    t.refine_at(K::Point_2(shift + 0.3 * scale, shift + 0.2 * scale), 7);
    t.balance();
    return t.leaves();
  };
  auto reference = build(1, 0);
  EXPECT_EQ(build(std::ldexp(1, 20), 0), reference);
  EXPECT_EQ(build(std::ldexp(1, -20), 0), reference);
}

} // namespace qm2_test_quadtree

// Issue 3: depths beyond the 24 levels that 64-bit keys held, up to 40.
namespace qm2_test_deep_keys {

using qm2_test::K;
namespace QM = CGAL::Quad_mesher_2;
using Tree = QM::Balanced_quadtree_2<K>;
using QM::Cell_key;

TEST(Balanced_quadtree_2, deep_cell_keys_round_trip)
{
  EXPECT_GE(Tree::max_supported_depth, 40);
  EXPECT_EQ(QM::Mesh_criteria_2<K>::max_supported_depth, Tree::max_supported_depth);
  const std::uint64_t top = (std::uint64_t(18) << 40) - 1; // the most cells in a row at level 40
  const std::uint64_t coordinates[] = { 0, 1, 2, (std::uint64_t(1) << 19) - 1, std::uint64_t(1) << 19,
                                        std::uint64_t(1) << 32, (std::uint64_t(1) << 45) - 1, top,
                                        0x0123456789aULL };
  std::set<std::pair<std::uint64_t, std::uint64_t>> codes;
  std::size_t n = 0;
  for(int level : { 0, 1, 24, 25, 31, 32, 39, 40, 41, Cell_key::max_level })
    for(std::uint64_t i : coordinates)
      for(std::uint64_t j : coordinates) {
        const Cell_key k(level, i, j);
        ASSERT_EQ(k.level, level);
        ASSERT_EQ(std::uint64_t(k.i), i);
        ASSERT_EQ(std::uint64_t(k.j), j);
        const QM::Key_code c = k.code();
        ASSERT_EQ(std::uint64_t(c >> 96), 0u);           // 96 bits
        ASSERT_NE(std::uint32_t(c >> 64), ~std::uint32_t(0)); // never the empty-slot mark
        ASSERT_EQ(Cell_key::from_code(c), k);
        codes.insert({ std::uint64_t(c >> 64), std::uint64_t(c) });
        ++n;
        if(level > 0 && level < Cell_key::max_level) {
          ASSERT_EQ(k.child(1, 1).parent(), k);
          ASSERT_EQ(std::uint64_t(k.child(1, 0).i), 2 * i + 1);
        }
      }
  EXPECT_EQ(codes.size(), n); // unique
  EXPECT_LT(Cell_key(40, top, 0), Cell_key(40, top, 1));
  EXPECT_LT(Cell_key(39, top, top), Cell_key(40, 0, 0));
}

TEST(Balanced_quadtree_2, key_map_tells_keys_apart_above_bit_64)
{
  QM::internal::Key_map map;
  std::vector<QM::Key_code> keys;
  for(std::uint64_t hi : { 0u, 1u, 2u, 0x7fffffffu, 0xfffffffeu })
    for(std::uint64_t lo : { std::uint64_t(0), std::uint64_t(1), ~std::uint64_t(0) })
      keys.push_back((QM::Key_code(hi) << 64) | lo);
  for(std::size_t v = 0; v < keys.size(); ++v)
    EXPECT_TRUE(map.insert(keys[v], std::uint32_t(v)).second);
  for(int grow = 0; grow < 1000; ++grow) // rehashes
    map.insert(QM::Key_code(grow + 1000) << 70, 0);
  for(std::size_t v = 0; v < keys.size(); ++v) {
    ASSERT_NE(map.find(keys[v]), nullptr);
    EXPECT_EQ(*map.find(keys[v]), v);
    EXPECT_FALSE(map.insert(keys[v], 99).second);
  }
  EXPECT_EQ(map.find(QM::Key_code(3) << 64), nullptr);
  std::size_t seen = 0;
  map.for_each([&](QM::Key_code key, std::uint32_t v) { seen += v < keys.size() && key == keys[v]; });
  EXPECT_EQ(seen, keys.size());
  EXPECT_EQ(map.size(), keys.size() + 1000);
  // lattice vertex keys of the deepest vertex lattice
  const std::uint64_t big = (std::uint64_t(1) << QM::internal::lattice_key_bits) - 1;
  for(std::uint64_t x : { std::uint64_t(0), std::uint64_t(65535), std::uint64_t(65536), big })
    for(std::uint64_t y : { std::uint64_t(0), std::uint64_t(1) << 40, big }) {
      QM::Key_code key = QM::internal::lattice_key(x, y);
      EXPECT_EQ(QM::internal::lattice_key_x(key), std::int64_t(x));
      EXPECT_EQ(QM::internal::lattice_key_y(key), std::int64_t(y));
      EXPECT_NE(std::uint32_t(key >> 64), ~std::uint32_t(0));
    }
}

// One point refined to level 40, then balanced and templated: a tree 40 levels deep (64-bit
// keys held 24) whose leaves, mesh vertices and Morton order are all consistent.
TEST(Balanced_quadtree_2, refinement_to_depth_40_balances_and_templates)
{
  // [0,1]^2: root side 2 anchored at the origin; the lattice is exact in doubles this close
  Tree t(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1, 1)), 40);
  ASSERT_EQ(t.max_depth(), 40) << t.depth_limit();
  const K::Point_2 p(0.7 + 1e-11, 0.3 - 3e-12), q(0.7 + 2e-11, 0.3 - 3e-12);
  t.refine_at(p, 40);
  t.refine_at(q, 40);
  const Cell_key kp = t.locate(p), kq = t.locate(q);
  EXPECT_EQ(kp.level, 40);
  EXPECT_EQ(kq.level, 40);
  EXPECT_NE(kp, kq);
  EXPECT_NE(t.cell_rectangle(kp).bounded_side(p), CGAL::ON_UNBOUNDED_SIDE);
  EXPECT_NE(t.cell_rectangle(kq).bounded_side(q), CGAL::ON_UNBOUNDED_SIDE);
  EXPECT_EQ(t.cell_rectangle(kp).xmax() - t.cell_rectangle(kp).xmin(), std::ldexp(1.0, -39));
  auto w = t.nearest_vertex(p, 40);
  EXPECT_LE(std::abs(t.lattice_x(40, w.first) - 0.7 - 1e-11), std::ldexp(1.0, -40));
  EXPECT_LE(std::abs(t.lattice_y(40, w.second) - 0.3 + 3e-12), std::ldexp(1.0, -40));
  t.balance();
  EXPECT_EQ(t.depth(), 40);
  EXPECT_TRUE(t.is_strongly_balanced());
  // leaves round-trip through the node map's codes
  std::size_t leaves = 0;
  t.for_each_leaf([&](const Cell_key& k) {
    ++leaves;
    EXPECT_TRUE(t.is_leaf(k));
    EXPECT_FALSE(t.is_leaf(k.parent())) << k.level;
  });
  EXPECT_EQ(leaves, t.number_of_leaves());
  // Morton order: Z order down to level 27, cells below it tie with their level-27 cell
  EXPECT_LT(t.morton_code(Cell_key(27, 0, 0)), t.morton_code(Cell_key(27, 1, 0)));
  EXPECT_LT(t.morton_code(Cell_key(27, 1, 0)), t.morton_code(Cell_key(27, 0, 1)));
  EXPECT_LT(t.morton_code(Cell_key(27, 1, 1)), t.morton_code(Cell_key(26, 1, 0)));
  EXPECT_EQ(t.morton_code(kp), t.morton_code(Cell_key(27, kp.i >> 13, kp.j >> 13)));
  EXPECT_LE(t.morton_code(kp.parent()), t.morton_code(kp));
  EXPECT_LT(t.morton_code(Cell_key(40, 0, 0)), t.morton_code(kp));
  std::vector<QM::Key_code> keys;
  std::vector<Cell_key> cells;
  auto mesh = QM::internal::templated_mesh(t, &cells, &keys);
  ASSERT_EQ(keys.size(), mesh.points.size());
  ASSERT_EQ(cells.size(), mesh.quads.size());
  EXPECT_TRUE(qm2_checks::tiles_rectangle(mesh, 0, 0, 2, 2));
  auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
  // every vertex sits exactly on its key's lattice point, and the finest cells are there
  bool finest = false;
  for(std::size_t v = 0; v < keys.size(); ++v) {
    ASSERT_EQ(CGAL::to_double(mesh.points[v].x()), t.lattice_x(41, QM::internal::lattice_key_x(keys[v])));
    ASSERT_EQ(CGAL::to_double(mesh.points[v].y()), t.lattice_y(41, QM::internal::lattice_key_y(keys[v])));
  }
  for(const Cell_key& c : cells)
    finest = finest || c.level == 40;
  EXPECT_TRUE(finest);
}

TEST(Balanced_quadtree_2, depth_beyond_the_supported_one_is_a_clear_error)
{
  const K::Iso_rectangle_2 box(K::Point_2(0, 0), K::Point_2(1, 1));
  try {
    Tree t(box, Tree::max_supported_depth + 1);
    FAIL() << "no error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("is outside [0, 40]"), std::string::npos) << e.what();
  }
  EXPECT_THROW(QM::Mesh_criteria_2<K>(0, 0, 41), QM::Meshing_error);
  EXPECT_NO_THROW(QM::Mesh_criteria_2<K>(0, 0, 40));
  Tree t(box, 40);
  try {
    t.refine_at(K::Point_2(0.5, 0.5), 41);
    FAIL() << "no error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("maximum depth 40"), std::string::npos) << e.what();
  }
}

TEST(Balanced_quadtree_2, precision_limits_depth_40_far_from_the_origin)
{
  // near the origin doubles hold 40 levels; at 1e4 extents away they do not, and the tree
  // says so instead of rounding
  Tree near(K::Iso_rectangle_2(K::Point_2(-3, 2), K::Point_2(-2, 3)), 40);
  EXPECT_EQ(near.max_depth(), 40) << near.depth_limit();
  Tree far(K::Iso_rectangle_2(K::Point_2(1e4, 1e4), K::Point_2(1e4 + 1, 1e4 + 1)), 40);
  EXPECT_LT(far.max_depth(), 40);
  EXPECT_GE(far.max_depth(), 30);
  EXPECT_NE(far.depth_limit().find("exactly this far from the origin"), std::string::npos) << far.depth_limit();
  // the deepest vertex lattice it keeps is exact: its last step changes the coordinate
  const int level = far.vertex_level();
  const std::int64_t x = std::int64_t(far.cells_x(level)) - 1;
  EXPECT_NE(far.lattice_x(level, x), far.lattice_x(level, x - 1));
  EXPECT_EQ(far.lattice_x(level, x) - far.lattice_x(level, x - 1), far.cell_side(level));
}

TEST(Balanced_quadtree_2, root_grid_does_not_move_with_the_maximum_depth)
{
  // depths beyond 24 keep the grid (and so the meshes) of the 24 levels earlier versions had
  const K::Iso_rectangle_2 box(K::Point_2(-0.1234567, 0.7654321), K::Point_2(3.3, 2.9));
  const Tree t24(box, 24), t40(box, 40), t10(box, 10);
  EXPECT_EQ(t40.origin_x(), t24.origin_x());
  EXPECT_EQ(t40.origin_y(), t24.origin_y());
  EXPECT_EQ(t40.root_cells_x(), t24.root_cells_x());
  EXPECT_EQ(t40.root_side(), t24.root_side());
  EXPECT_EQ(std::fmod(t10.origin_x(), std::ldexp(t10.root_side(), -11)), 0.0); // its finest lattice
  EXPECT_LE(t24.origin_x() - t10.origin_x(), std::ldexp(t10.root_side(), -11));
}

} // namespace qm2_test_deep_keys
