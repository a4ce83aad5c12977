// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Input points as mesh vertices (paper §3, Lemma 1): every point a vertex, every angle in
// [45°, 135°], aspect ratio at most 1.5 for the quads at each point.

#include "qm2_mesh_checks.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>
#include <CGAL/Quad_mesher_2/internal/insert_points.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>

namespace qm2_test_points {

using qm2_test::K;
namespace QM = CGAL::Quad_mesher_2;
using Domain = QM::Domain_2<K>;
using Mesher = QM::Quadtree_mesher_2<K>;
using Mesh = QM::Quad_mesh_2<K::Point_2>;

double aspect(const Mesh& m, std::size_t q)
{
  double lo = HUGE_VAL, hi = 0;
  for(int c = 0; c < 4; ++c) {
    const auto &a = m.points[m.quads[q][c]], &b = m.points[m.quads[q][(c + 1) % 4]];
    double l = std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
    lo = (std::min)(lo, l);
    hi = (std::max)(hi, l);
  }
  return hi / lo;
}

// Lemma 1 on a mesh: each point is a vertex (exactly), all angles in [45, 135], the quads at
// each point have aspect ratio <= 1.5, and the mesh tiles its rectangle.
::testing::AssertionResult lemma_1(const Mesher& mesher, const Mesh& mesh, const std::vector<K::Point_2>& points)
{
  std::map<std::pair<double, double>, std::vector<std::size_t>> exact; // by coordinates
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    exact[{ CGAL::to_double(mesh.points[v].x()), CGAL::to_double(mesh.points[v].y()) }].push_back(v);
  std::vector<std::vector<std::size_t>> quads_at(mesh.points.size());
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(int c = 0; c < 4; ++c)
      quads_at[mesh.quads[q][c]].push_back(q);
  for(std::size_t i = 0; i < points.size(); ++i) {
    auto it = exact.find({ CGAL::to_double(points[i].x()), CGAL::to_double(points[i].y()) });
    if(it == exact.end())
      return ::testing::AssertionFailure() << "input point " << i << " is not a mesh vertex";
    bool found = false;
    for(std::size_t v : it->second)
      if(mesh.points[v] == points[i]) { // exact under Epeck
        found = true;
        for(std::size_t q : quads_at[v])
          if(aspect(mesh, q) > 1.5)
            return ::testing::AssertionFailure() << "quad at point " << i << " has aspect " << aspect(mesh, q);
      }
    if(!found)
      return ::testing::AssertionFailure() << "input point " << i << " is only approximately a vertex";
  }
  auto range = qm2_checks::angle_range(mesh);
  if(range.min < 45 - 1e-9 || range.max > 135 + 1e-9)
    return ::testing::AssertionFailure() << "angles [" << range.min << ", " << range.max << "]";
  const CGAL::Bbox_2 r = mesher.mesh_region();
  return qm2_checks::tiles_rectangle(mesh, r.xmin(), r.ymin(), r.xmax(), r.ymax());
}

// the bounding box of the mesh's vertices
CGAL::Bbox_2 vertex_box(const Mesh& mesh)
{
  CGAL::Bbox_2 box = mesh.points.front().bbox();
  for(const K::Point_2& p : mesh.points)
    box += p.bbox();
  return box;
}

// The tents alone, on a uniform tree: for d sampled over its whole range, the bounds the
// construction claims (insert_points.h).
TEST(Insert_points, tent_bounds_hold_over_every_displacement)
{
  using Tree = QM::Balanced_quadtree_2<K>;
  for(int radius : { 1, 3 }) {
    Tree tree(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1, 1)), 6);
    tree.refine([](const QM::Cell_key& k) { return k.level < 4; }); // g = 1/8 on [0,2]^2
    tree.balance();
    std::vector<QM::Key_code> keys;
    const Mesh base = QM::internal::templated_mesh(tree, nullptr, &keys);
    const double g = 0.125, reach = radius == 1 ? 3 * g / 16 : g / 2;
    double lo = 180, hi = 0, worst_aspect = 0;
    const int steps = 16;
    for(int sx = -steps; sx <= steps; ++sx)
      for(int sy = -steps; sy <= steps; ++sy) {
        std::vector<K::Point_2> p = { K::Point_2(1 + reach * sx / steps, 1 + reach * sy / steps) };
        QM::Point_anchor a{ 0, 4, radius, 8, 8 }; // W = (1, 1)
        Mesh mesh = base;
        QM::internal::move_anchors(tree, mesh, keys, { a }, p);
        auto r = qm2_checks::angle_range(mesh);
        lo = (std::min)(lo, r.min);
        hi = (std::max)(hi, r.max);
        for(std::size_t q = 0; q < mesh.quads.size(); ++q)
          for(int c = 0; c < 4; ++c)
            if(mesh.points[mesh.quads[q][c]] == p[0])
              worst_aspect = (std::max)(worst_aspect, aspect(mesh, q));
      }
    if(radius == 1) {
      EXPECT_NEAR(lo, 72.05, 0.01);
      EXPECT_NEAR(hi, 115.99, 0.01);
      EXPECT_LE(worst_aspect, 1.442);
    } else {
      EXPECT_NEAR(lo, 72.05, 0.01);
      EXPECT_NEAR(hi, 115.99, 0.01);
      EXPECT_LE(worst_aspect, 1.282);
    }
  }
}

Domain make(std::vector<K::Point_2> pts)
{
  Domain d;
  d.points = std::move(pts);
  return d;
}

void check(const std::vector<K::Point_2>& pts, const char* what)
{
  SCOPED_TRACE(what);
  Domain d = make(pts);
  Mesher mesher(d);
  Mesh mesh = mesher.run();
  EXPECT_TRUE(lemma_1(mesher, mesh, mesher.points()));
  EXPECT_EQ(mesher.anchors().size(), mesher.points().size());
}

TEST(Insert_points, random_points)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Point_2> pts;
  for(int i = 0; i < 300; ++i)
    pts.emplace_back(u(rng), u(rng));
  check(pts, "uniform");
}

TEST(Insert_points, clusters_next_to_isolated_points)
{
  std::mt19937 rng(12);
  std::normal_distribution<double> n(0, 1e-3);
  std::vector<K::Point_2> pts = { K::Point_2(0.9, 0.9), K::Point_2(0.1, 0.8), K::Point_2(0.95, 0.05) };
  for(int c = 0; c < 3; ++c)
    for(int i = 0; i < 60; ++i)
      pts.emplace_back(0.2 + 0.3 * c + n(rng), 0.3 + n(rng));
  check(pts, "clusters");
}

TEST(Insert_points, degenerate_sets)
{
  check({ K::Point_2(0.3, 0.7) }, "one point");
  check({ K::Point_2(0, 0), K::Point_2(1, 0) }, "two points");
  std::vector<K::Point_2> line, diagonal, grid;
  for(int i = 0; i < 40; ++i) {
    line.emplace_back(0.1 * i, 2.0);
    diagonal.emplace_back(i / 3.0, i / 3.0); // thirds never sit on a lattice
  }
  for(int i = 0; i < 10; ++i)
    for(int j = 0; j < 10; ++j)
      grid.emplace_back(i, j);
  check(line, "collinear, horizontal");
  check(diagonal, "collinear, diagonal, thirds");
  check(grid, "integer grid");
}

TEST(Insert_points, far_from_the_origin_and_tiny_extents)
{
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Point_2> offset, tiny, close;
  for(int i = 0; i < 50; ++i) {
    offset.emplace_back(1e6 + u(rng), -1e6 + u(rng));
    tiny.emplace_back(1e-6 * u(rng), 1e-6 * u(rng));
  }
  check(offset, "1e6 offset");
  check(tiny, "1e-6 extent");
  close = { K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5 + 1e-5, 0.5) };
  check(close, "1e-5 of the extent apart");
}

// A point cloud is meshed over its points' bounding box with a margin, at every stage, not
// over the root grid, whose power-of-two side is 2 for points in [0,1]^2 (the mesh reached
// 1.875 there): 1/8 of the larger side below and left, 1/10 to 3/20 above and right.
void check_extent(const std::vector<K::Point_2>& pts, const CGAL::Bbox_2& points_box, const char* what)
{
  SCOPED_TRACE(what);
  const double extent = (std::max)(points_box.xmax() - points_box.xmin(), points_box.ymax() - points_box.ymin());
  for(QM::Stage last : { QM::Stage::QUADTREE, QM::Stage::POINTS }) {
    SCOPED_TRACE(QM::stage_name(last));
    const Domain d = make(pts);
    Mesher mesher(d);
    const Mesh mesh = mesher.run(last);
    const CGAL::Bbox_2 box = vertex_box(mesh);
    EXPECT_TRUE(qm2_checks::tiles_rectangle(mesh, box.xmin(), box.ymin(), box.xmax(), box.ymax()));
    EXPECT_EQ(box, mesher.mesh_region());
    const double lower = extent / 8, upper_min = extent / 10, upper_max = extent * 3 / 20;
    EXPECT_LE(box.xmin(), points_box.xmin() - lower);
    EXPECT_GE(box.xmin(), points_box.xmin() - lower * (1 + 1e-6));
    EXPECT_LE(box.ymin(), points_box.ymin() - lower);
    EXPECT_GE(box.ymin(), points_box.ymin() - lower * (1 + 1e-6));
    EXPECT_GE(box.xmax(), points_box.xmax() + upper_min);
    EXPECT_LE(box.xmax(), points_box.xmax() + upper_max);
    EXPECT_GE(box.ymax(), points_box.ymax() + upper_min);
    EXPECT_LE(box.ymax(), points_box.ymax() + upper_max);
    auto range = qm2_checks::angle_range(mesh);
    EXPECT_GE(range.min, 45 - 1e-9);
    EXPECT_LE(range.max, 135 + 1e-9);
    if(last == QM::Stage::POINTS) {
      EXPECT_TRUE(lemma_1(mesher, mesh, mesher.points()));
    }
  }
}

TEST(Insert_points, a_cloud_is_meshed_over_its_own_extent)
{
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Point_2> unit = { K::Point_2(0, 0), K::Point_2(1, 1) }, thin, offset;
  for(int i = 0; i < 100; ++i) {
    unit.emplace_back(u(rng), u(rng));
    thin.emplace_back(3 * u(rng), 0.01 * u(rng));
    offset.emplace_back(-7 + u(rng), 5 + 0.5 * u(rng));
  }
  thin.insert(thin.end(), { K::Point_2(0, 0), K::Point_2(3, 0.01) });
  offset.insert(offset.end(), { K::Point_2(-7, 5), K::Point_2(-6, 5.5) });
  check_extent(unit, CGAL::Bbox_2(0, 0, 1, 1), "unit square: inside [-0.15, 1.15]^2");
  check_extent({ K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1), K::Point_2(0, 1) }, CGAL::Bbox_2(0, 0, 1, 1),
               "the unit square's corners");
  check_extent(thin, CGAL::Bbox_2(0, 0, 3, 0.01), "a thin strip");
  check_extent(offset, CGAL::Bbox_2(-7, 5, -6, 5.5), "off the origin");
}

TEST(Insert_points, duplicates_are_merged_and_counted)
{
  Domain d = make({ K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0, 0), K::Point_2(0.5, 0.25), K::Point_2(1, 1) });
  Mesher mesher(d);
  Mesh mesh = mesher.run();
  EXPECT_EQ(mesher.number_of_merged_points(), 2u);
  EXPECT_EQ(mesher.points().size(), 3u);
  EXPECT_TRUE(lemma_1(mesher, mesh, d.points));
}

TEST(Insert_points, quadtree_stage_leaves_points_off_the_vertices)
{
  Domain d = make({ K::Point_2(0.1, 0.1), K::Point_2(0.7, 0.3), K::Point_2(1.0 / 3, 0.9) });
  Mesher mesher(d);
  Mesh core = mesher.run(QM::Stage::QUADTREE);
  bool third_is_vertex = false;
  for(const auto& p : core.points)
    third_is_vertex = third_is_vertex || p == d.points[2];
  EXPECT_FALSE(third_is_vertex);
  EXPECT_TRUE(qm2_checks::is_conforming(core));
}

} // namespace qm2_test_points

namespace qm2_test_points {

// Points inside a domain: only the isolated points are anchored (the boundary's vertices are
// the buffer layers' business), and they stay vertices through the clearance.
TEST(Insert_points, isolated_points_of_a_domain_survive_the_clearance)
{
  Domain d;
  d.points = { K::Point_2(0, 0), K::Point_2(4, 0), K::Point_2(4, 4), K::Point_2(0, 4),
               K::Point_2(1.3, 1.7), K::Point_2(2.71828, 3.14159), K::Point_2(1.0 / 3, 3.5) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  Mesher mesher(d);
  Mesh mesh = mesher.run(QM::Stage::CLEARANCE);
  ASSERT_EQ(mesher.anchored_points().size(), 3u);
  ASSERT_EQ(mesher.point_vertices().size(), 3u);
  for(std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(mesh.points[mesher.point_vertices()[i]], d.points[4 + i]);
    for(std::size_t q = 0; q < mesh.quads.size(); ++q)
      for(int c = 0; c < 4; ++c)
        if(mesh.quads[q][c] == mesher.point_vertices()[i]) {
          EXPECT_LE(aspect(mesh, q), 1.5);
        }
  }
  EXPECT_TRUE(qm2_checks::is_conforming(mesh));
  auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
}

// An isolated point nearer the boundary than its cells lost its quads in the clearance, and
// the mesh came out without it, silently (a point 0.01 from a unit square's side: the nearest
// vertex 0.05 away). run() now refines around it until it is a vertex inside the core, through
// every stage (or stops with an error: a point 1e-8 from the side still fails in the buffer).
TEST(Insert_points, isolated_points_near_the_boundary_stay_vertices)
{
  for(const double gap : { 0.06, 0.01, 1e-3 }) {
    SCOPED_TRACE(gap);
    Domain d;
    d.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1), K::Point_2(0, 1), K::Point_2(0.5, gap),
                 K::Point_2(1 - gap, 0.3) };
    d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
    for(QM::Stage last : { QM::Stage::CLEARANCE, QM::Stage::BUFFER2 }) {
      Mesher mesher(d);
      const Mesh mesh = mesher.run(last);
      ASSERT_EQ(mesher.point_vertices().size(), 2u);
      EXPECT_TRUE(mesher.lost_points().empty());
      for(std::size_t i = 0; i < 2; ++i) {
        ASSERT_LT(mesher.point_vertices()[i], mesh.points.size());
        EXPECT_EQ(mesh.points[mesher.point_vertices()[i]], d.points[4 + i]);
      }
    }
  }
}

} // namespace qm2_test_points

namespace qm2_test_points {

// Issue 3: points 1e-9 or 1e-10 of the extent apart need 32 to 40 quadtree levels, beyond
// the 24 that 64-bit cell and vertex keys held.
void check_deep(const std::vector<K::Point_2>& pts, const char* what, int min_depth)
{
  SCOPED_TRACE(what);
  Domain d = make(pts);
  Mesher mesher(d);
  Mesh mesh = mesher.run();
  EXPECT_TRUE(lemma_1(mesher, mesh, mesher.points()));
  EXPECT_EQ(mesher.points().size(), pts.size());
  EXPECT_EQ(mesher.point_vertices().size(), pts.size());
  EXPECT_GE(mesher.quadtree().depth(), min_depth);
  EXPECT_LE(mesher.quadtree().depth(), 40);
}

std::vector<K::Point_2> close_pairs(double gap, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<K::Point_2> pts = { K::Point_2(0, 0), K::Point_2(1, 1),
                                  K::Point_2(0.5, 0.5), K::Point_2(0.5 + gap, 0.5),       // across
                                  K::Point_2(0.25, 0.75), K::Point_2(0.25 + gap, 0.75 + gap), // diagonal
                                  K::Point_2(1.0 / 3, 0.2), K::Point_2(1.0 / 3, 0.2 + gap),   // off the lattice
                                  K::Point_2(0.8, 0.3), K::Point_2(0.8 + gap, 0.3), K::Point_2(0.8 + 2 * gap, 0.3) };
  for(int i = 0; i < 30; ++i)
    pts.emplace_back(u(rng), u(rng));
  return pts;
}

TEST(Insert_points, points_1e_9_of_the_extent_apart)
{
  check_deep({ K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5 + 1e-9, 0.5) },
             "one pair", 31);
  check_deep(close_pairs(1e-9, 21), "pairs, a triple and random points", 31);
  std::vector<K::Point_2> shifted;
  for(const K::Point_2& p : close_pairs(1e-9, 22))
    shifted.emplace_back(p.x() * 3 - 7, p.y() * 3 + 5); // extent 3, off the origin
  check_deep(shifted, "scaled and shifted", 31);
}

TEST(Insert_points, points_1e_10_of_the_extent_apart)
{
  check_deep({ K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5 + 1e-10, 0.5) },
             "one pair", 35);
  check_deep(close_pairs(1e-10, 23), "pairs, a triple and random points", 35);
}

TEST(Insert_points, too_close_for_depth_40_is_a_clear_error)
{
  for(const double gap : { 1e-12, 1e-13 }) {
    const Domain close = make({ K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5, 0.5 + gap) });
    try {
      Mesher(close).run();
      ADD_FAILURE() << "no error at " << gap;
    } catch(const QM::Meshing_error& e) {
      EXPECT_NE(std::string(e.what()).find("separating them needs quadtree depth"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("beyond the maximum depth 40"), std::string::npos) << e.what();
    }
  }
  // 1e-10 apart: the sizing fits in 35 levels (cells of 2^-34), the blocks that make both
  // points vertices do not (they need 37)
  const Domain d = make({ K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5, 0.5 + 1e-10) });
  try {
    Mesher(d, QM::Mesh_criteria_2<K>(0, 0, 35)).run();
    FAIL() << "no error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("cannot be made a mesh vertex within the maximum depth 35"), std::string::npos) << e.what();
  }
  Mesher deep(d, QM::Mesh_criteria_2<K>(0, 0, 37));
  Mesh mesh = deep.run();
  EXPECT_TRUE(lemma_1(deep, mesh, d.points));
}

} // namespace qm2_test_points
