// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Narrow regions (paper §4.2): more than two quadtree cells across every gap between two
// parts of the boundary; sharp corners are not narrow regions.

#include "qm2_mesh_checks.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace qm2_test_narrow {

using qm2_test::K;
namespace QM = CGAL::Quad_mesher_2;

void close_loop(QM::Domain_2<K>& d, std::size_t first)
{
  for(std::size_t v = first; v + 1 < d.points.size(); ++v)
    d.segments.push_back({ v, v + 1 });
  d.segments.push_back({ d.points.size() - 1, first });
}

// Two unit discs centred at (-2, 0) and (2, 0), joined by a channel of width 2h whose walls
// are single long segments (so that point spacing alone would not refine the channel), CCW.
QM::Domain_2<K> dumbbell(double h, int n = 64)
{
  QM::Domain_2<K> d;
  const double t = std::asin(h);
  for(int k = 0; k <= n; ++k) { // left disc, from the channel's top round to its bottom
    const double a = t + (2 * M_PI - 2 * t) * k / n;
    d.points.emplace_back(-2 + std::cos(a), std::sin(a));
  }
  for(int k = 0; k <= n; ++k) { // right disc
    const double a = M_PI + t + (2 * M_PI - 2 * t) * k / n;
    d.points.emplace_back(2 + std::cos(a), std::sin(a));
  }
  close_loop(d, 0);
  return d;
}

QM::Mesh_criteria_2<K> quadtree_only()
{
  QM::Mesh_criteria_2<K> c;
  c.set_points_as_vertices(false);
  return c;
}

TEST(Narrow_regions, more_than_two_cells_across_a_channel)
{
  for(double h : { 0.01, 0.001 }) {
    QM::Domain_2<K> d = dumbbell(h);
    QM::Quadtree_mesher_2<K> mesher(d, quadtree_only());
    auto mesh = mesher.run(QM::Stage::QUADTREE);
    const auto& tree = mesher.quadtree();
    double worst = 0;
    for(int k = 0; k <= 200; ++k) // along the channel's axis, and along both walls
      for(double y : { 0.0, 0.99 * h, -0.99 * h }) {
        K::Point_2 p(-0.9 + 1.8 * k / 200, y);
        worst = (std::max)(worst, tree.cell_side(tree.locate(p).level));
      }
    EXPECT_LT(worst, 2 * h / 2) << "h = " << h; // strictly more than two cells across 2h
    EXPECT_TRUE(qm2_checks::is_conforming(mesh));
    // without the narrow-region rule the channel would get far larger cells
    QM::Mesh_criteria_2<K> off = quadtree_only();
    off.set_resolve_narrow_regions(false);
    QM::Quadtree_mesher_2<K> coarse(d, off);
    coarse.run(QM::Stage::QUADTREE);
    EXPECT_GT(coarse.quadtree().cell_side(coarse.quadtree().locate(K::Point_2(0, 0)).level), 2 * h);
  }
}

// A needle's sides face each other across a narrowing channel: more than two cells across it
// beyond the corner zone (an eighth of its sides), but no refinement into the tip itself,
// which no cell size resolves. A 45-degree corner is no needle.
TEST(Narrow_regions, a_needle_is_narrow_beyond_its_corner_zone)
{
  const double half = 2.5 * M_PI / 180;
  QM::Domain_2<K> d; // a 5-degree needle
  d.points = { K::Point_2(0, 0), K::Point_2(1, std::tan(half)), K::Point_2(1, -std::tan(half)) };
  d.segments = { { 0, 2 }, { 2, 1 }, { 1, 0 } };
  QM::Quadtree_mesher_2<K> mesher(d, quadtree_only());
  mesher.run(QM::Stage::QUADTREE);
  EXPECT_LE(mesher.quadtree().depth(), 10);
  for(double x : { 0.25, 0.5, 0.9 }) {
    const double width = 2 * x * std::tan(half);
    EXPECT_LT(mesher.quadtree().cell_side(mesher.quadtree().locate(K::Point_2(x, 0)).level), width / 2) << x;
  }

  QM::Domain_2<K> wedge; // 45 degrees: a corner, not a needle
  wedge.points = { K::Point_2(0, 0), K::Point_2(1, std::tan(M_PI / 8)), K::Point_2(1, -std::tan(M_PI / 8)) };
  wedge.segments = d.segments;
  QM::Quadtree_mesher_2<K> corner(wedge, quadtree_only());
  corner.run(QM::Stage::QUADTREE);
  EXPECT_LE(corner.quadtree().depth(), 8);
}

// A slit of the outside 0.01 wide between two prongs 1 wide: its walls face each other
// across no domain, so the cells beside it need only be no wider than the slit (none spans
// it), not a quarter of it as across a channel of the domain; and the whole pipeline meshes
// it within the bound. Sizing by a quarter of the slit made the bird's toes twice as fine.
TEST(Narrow_regions, a_slit_of_the_outside_needs_cells_as_wide_as_it)
{
  const double slit = 0.01;
  QM::Domain_2<K> d;
  d.points = { K::Point_2(0, 0),        K::Point_2(2 + slit, 0), K::Point_2(2 + slit, 5), K::Point_2(1 + slit, 5),
               K::Point_2(1 + slit, 1), K::Point_2(1, 1),        K::Point_2(1, 5),        K::Point_2(0, 5) };
  close_loop(d, 0);
  QM::Quadtree_mesher_2<K> tree_only(d, quadtree_only());
  tree_only.run(QM::Stage::QUADTREE);
  const auto& tree = tree_only.quadtree();
  for(int k = 0; k <= 20; ++k) { // beside the slit, away from its ends' corners
    const double y = 2.5 + k * 0.05;
    for(double x : { 1 - slit / 4, 1 + slit + slit / 4 }) {
      const double side = tree.cell_side(tree.locate(K::Point_2(x, y)).level);
      EXPECT_LE(side, slit) << "at (" << x << ", " << y << ")";
      EXPECT_GT(side, slit / 2) << "at (" << x << ", " << y << ")";
    }
  }
  QM::Quadtree_mesher_2<K> mesher(d);
  auto mesh = mesher.run(QM::Stage::SMOOTHING);
  EXPECT_TRUE(qm2_checks::is_conforming(mesh));
  const auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-7);
  EXPECT_LE(range.max, 135 + 1e-7);
}

// A thin rectangle whose long sides are single segments: seen from its corners, the far side
// is the near side's neighbour along the loop, so a walk that gave up after its first sample
// never found the gap. Both long sides' whole length needs more than two cells across, and
// the full mesh follows (the buffer layers failed on 1 x 0.1 when the channel was not found).
// Two prongs whose tops are collinear, turned: the other prong's top, beside this one's line
// to rounding, lies across the slit's mouth, outside, as it does unturned. Read as a gap of
// the domain (the sign of a rounded determinant), it left a blob of cells a tenth of the
// slit's width at one top corner of every prong of a turned comb.
TEST(Narrow_regions, a_collinear_neighbour_across_a_slit_is_outside_turned_or_not)
{
  const double slit = 0.3;
  const double xs[] = { 0, 2 + slit, 2 + slit, 1 + slit, 1 + slit, 1, 1, 0 };
  const double ys[] = { 0, 0, 5, 5, 1, 1, 5, 5 };
  for(double degrees : { 0.0, 33.0, 61.0 }) {
    SCOPED_TRACE(degrees);
    const double c = std::cos(degrees * CGAL_PI / 180), s = std::sin(degrees * CGAL_PI / 180);
    auto turned = [&](double x, double y) { return K::Point_2(c * x - s * y, s * x + c * y); };
    QM::Domain_2<K> d;
    for(int k = 0; k < 8; ++k) d.points.push_back(turned(xs[k], ys[k]));
    close_loop(d, 0);
    QM::Quadtree_mesher_2<K> tree_only(d, quadtree_only());
    tree_only.run(QM::Stage::QUADTREE);
    const auto& tree = tree_only.quadtree();
    // within the prongs' tops, a fifth of the slit from the corners beside it
    for(const auto& [x, y] : { std::pair<double, double>(1 - slit / 5, 5 - slit / 5), { 1 + 1.2 * slit, 5 - slit / 5 } })
      EXPECT_GT(tree.cell_side(tree.locate(turned(x, y)).level), slit / 4) << "at (" << x << ", " << y << ") unturned";
  }
}

TEST(Narrow_regions, a_thin_rectangle_is_narrow_all_along)
{
  for(double w : { 0.1, 0.01 }) {
    QM::Domain_2<K> d;
    d.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, w), K::Point_2(0, w) };
    d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
    QM::Quadtree_mesher_2<K> tree_only(d, quadtree_only());
    tree_only.run(QM::Stage::QUADTREE);
    const auto& tree = tree_only.quadtree();
    for(int k = 0; k <= 100; ++k) {
      const double x = 0.005 + 0.99 * k / 100;
      for(double y : { 0.0, w / 2, 0.999 * w })
        EXPECT_LT(tree.cell_side(tree.locate(K::Point_2(x, y)).level), w / 2) << "w = " << w << " at " << x;
    }
    QM::Quadtree_mesher_2<K> mesher(d);
    auto mesh = mesher.run(QM::Stage::BUFFER2);
    EXPECT_TRUE(qm2_checks::is_conforming(mesh)) << "w = " << w;
    const auto range = qm2_checks::angle_range(mesh);
    EXPECT_GE(range.min, 45 - 1e-7) << "w = " << w;
    EXPECT_LE(range.max, 135 + 1e-7) << "w = " << w;
  }
}

// A 128-gon hole of radius 0.3 with one vertex 1e-7 above the bottom of a unit square. The
// walk along the bottom stepped at least 1/65536 of its length (1.5e-5), so it never sampled
// the gap: the buffer layers failed round after round (119 s, then "133 buffer quads not
// convex"). Stepping down to the finest cell, one round meshes it.
TEST(Narrow_regions, a_gap_far_narrower_than_its_sides_is_found)
{
  QM::Domain_2<K> d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1), K::Point_2(0, 1) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  const double gap = 1e-7;
  for(int k = 0; k < 128; ++k) {
    const double a = 2 * M_PI * k / 128;
    d.points.push_back(k == 96 ? K::Point_2(0.5, gap) : K::Point_2(0.5 + 0.3 * std::cos(a), 0.3 + gap + 0.3 * std::sin(a)));
  }
  close_loop(d, 4);
  d.holes = { K::Point_2(0.5, 0.5) };
  QM::Quadtree_mesher_2<K> mesher(d);
  auto mesh = mesher.run(QM::Stage::BUFFER2);
  EXPECT_EQ(mesher.rounds(), 1);
  EXPECT_TRUE(qm2_checks::is_conforming(mesh));
  const auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-7);
  EXPECT_LE(range.max, 135 + 1e-7);
  const auto& tree = mesher.quadtree();
  EXPECT_LT(tree.cell_side(tree.locate(K::Point_2(0.5, gap / 2)).level), gap / 2);
}

// A channel 1e-7 wide along a unit side needs millions of cells: an error naming the narrow
// region as soon as its samples pass the cell budget, not after the quadtree has filled it
// (or the memory).
TEST(Narrow_regions, a_channel_beyond_the_cell_budget_is_an_error_naming_it)
{
  QM::Domain_2<K> d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1e-7), K::Point_2(0, 1e-7) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_max_cells(1 << 16);
  std::string error;
  try {
    QM::Quadtree_mesher_2<K>(d, criteria).run(QM::Stage::QUADTREE);
  } catch(const QM::Meshing_error& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("the narrow regions need more than 65536 quadtree cells (the cell budget): the gap near ("),
            std::string::npos) << error;
  EXPECT_NE(error.find(") is 1e-07 wide"), std::string::npos) << error;
}

// A channel thinner than the finest cell the quadtree makes (1e-8 across a unit square,
// whose cells stop at 7.5e-9) is the depth error at once, naming the width: walking it at the
// finest step reached the cell budget after seconds and 0.8 GB, and said to raise it (a
// reviewer's find).
TEST(Narrow_regions, a_gap_below_the_finest_cell_is_the_depth_error_at_once)
{
  QM::Domain_2<K> d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1e-8), K::Point_2(0, 1e-8) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_max_cells(1 << 16); // the budget error would come first if the walk went on
  std::string error;
  try {
    QM::Quadtree_mesher_2<K>(d, criteria).run(QM::Stage::QUADTREE);
  } catch(const QM::Meshing_error& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("a narrow region of width 1e-08 near ("), std::string::npos) << error;
  EXPECT_NE(error.find("needs quadtree depth"), std::string::npos) << error;
}

TEST(Narrow_regions, invalid_loops_are_reported)
{
  QM::Domain_2<K> d = dumbbell(0.01, 16);
  d.segments.pop_back(); // open the loop
  EXPECT_THROW(QM::Quadtree_mesher_2<K>(d, quadtree_only()).run(QM::Stage::QUADTREE), QM::Meshing_error);
}

} // namespace qm2_test_narrow
