// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The mesher's first stage: sizing (paper §4.2), balance, templates, output.

#include "qm2_mesh_checks.h"
#include "qm2_test_domains.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace qm2_test_mesher {

using qm2_test::K;
namespace QM = CGAL::Quad_mesher_2;
using Domain = QM::Domain_2<K>;
using Criteria = QM::Mesh_criteria_2<K>;
using Mesher = QM::Quadtree_mesher_2<K>;

Domain random_domain(std::size_t n, unsigned seed, double scale = 1, double shift = 0)
{
  Domain d;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for(std::size_t i = 0; i < n; ++i)
    d.points.emplace_back(shift + scale * u(rng), shift + scale * u(rng));
  return d;
}

// a point cloud's mesh tiles its rectangle (the points' box with a margin)
::testing::AssertionResult tiles_its_region(const QM::Quad_mesh_2<K::Point_2>& mesh, const Mesher& mesher)
{
  const CGAL::Bbox_2 r = mesher.mesh_region();
  return qm2_checks::tiles_rectangle(mesh, r.xmin(), r.ymin(), r.xmax(), r.ymax());
}

TEST(Quadtree_mesher_2, cell_of_each_point_is_no_larger_than_its_spacing)
{
  Domain d = random_domain(300, 1);
  Mesher mesher(d);
  auto mesh = mesher.run();
  const auto& tree = mesher.quadtree();
  for(std::size_t i = 0; i < d.points.size(); ++i) {
    double s = std::numeric_limits<double>::infinity();
    for(std::size_t j = 0; j < d.points.size(); ++j)
      if(j != i)
        s = (std::min)(s, std::sqrt(CGAL::to_double(CGAL::squared_distance(d.points[i], d.points[j]))));
    auto k = tree.locate(d.points[i]);
    EXPECT_LE(tree.cell_side(k.level), s) << "point " << i;
  }
  EXPECT_TRUE(tiles_its_region(mesh, mesher));
  auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
  EXPECT_TRUE(tree.is_strongly_balanced());
}

TEST(Quadtree_mesher_2, max_size_bounds_every_cell)
{
  Domain d;
  d.points = { K::Point_2(0, 0), K::Point_2(3, 1) };
  Mesher mesher(d, Criteria(0.1));
  auto mesh = mesher.run();
  mesher.quadtree().for_each_leaf([&](const QM::Cell_key& k) { EXPECT_LE(mesher.quadtree().cell_side(k.level), 0.1); });
  EXPECT_GT(mesh.quads.size(), 300u);
}

// The size bound applies to the cells that meet the domain: those wholly outside it are
// cleared anyway and stay coarser (balance grades them). A unit disc's power-of-two root
// square has side 4 (16384 cells of side 1/32 in all), its box 4096 of them, the disc 3217.
TEST(Quadtree_mesher_2, max_size_bounds_the_cells_meeting_the_domain_only)
{
  Domain d;
  for(int i = 0; i < 64; ++i) {
    const double t = 2 * 3.14159265358979323846 * i / 64;
    d.points.emplace_back(std::cos(t), std::sin(t));
    d.segments.push_back({ std::size_t(i), std::size_t((i + 1) % 64) });
  }
  const double max_size = 1.0 / 32;
  Mesher mesher(d, Criteria(max_size));
  const auto mesh = mesher.run(QM::Stage::QUADTREE);
  const auto& tree = mesher.quadtree();
  std::size_t in_box = 0, in_disc = 0;
  tree.for_each_leaf([&](const QM::Cell_key& k) {
    const double x0 = tree.lattice_x(k.level, std::int64_t(k.i)), x1 = tree.lattice_x(k.level, std::int64_t(k.i) + 1);
    const double y0 = tree.lattice_y(k.level, std::int64_t(k.j)), y1 = tree.lattice_y(k.level, std::int64_t(k.j) + 1);
    if(x1 < -1 || x0 > 1 || y1 < -1 || y0 > 1) return;
    ++in_box;
    // the cell's nearest point to the centre; the 64-gon lies within the unit circle
    const double nx = (std::max)(x0, (std::min)(0.0, x1)), ny = (std::max)(y0, (std::min)(0.0, y1));
    if(nx * nx + ny * ny >= 1) return;
    ++in_disc;
    EXPECT_LE(tree.cell_side(k.level), max_size);
  });
  EXPECT_GE(double(in_disc), 3.1 / (max_size * max_size));
  EXPECT_LT(double(in_box), 4 / (max_size * max_size)) << "cells outside the disc were refined to the bound";
  std::printf("[quadtree] disc at max size 1/32: %zu leaves, %zu meeting its box, %zu meeting the disc\n",
              tree.number_of_leaves(), in_box, in_disc);
  EXPECT_TRUE(tree.is_strongly_balanced());
  EXPECT_GT(mesh.quads.size(), 3000u);
}

// A domain's loop vertices that are no features (a 64-gon's turn by 5.6 degrees) ask for
// cells of twice their spacing s_i, one level coarser than a point cloud's points, which
// Lemma 1 needs alone in their cells.
TEST(Quadtree_mesher_2, loop_vertices_get_cells_one_level_coarser_than_their_spacing)
{
  Domain domain, cloud;
  for(int i = 0; i < 64; ++i) {
    const double t = 2 * CGAL_PI * i / 64;
    domain.points.emplace_back(std::cos(t), std::sin(t));
    domain.segments.push_back({ std::size_t(i), std::size_t((i + 1) % 64) });
  }
  cloud.points = domain.points;
  const double spacing = 2 * std::sin(CGAL_PI / 64);
  Mesher on_loops(domain), on_points(cloud);
  on_loops.run(QM::Stage::QUADTREE);
  on_points.run(QM::Stage::QUADTREE);
  for(const K::Point_2& p : domain.points) {
    const auto& tree = on_loops.quadtree();
    EXPECT_EQ(tree.locate(p).level, QM::internal::level_for_size(tree, 2 * spacing));
    EXPECT_LT(tree.locate(p).level, QM::internal::level_for_size(tree, spacing));
    EXPECT_GE(on_points.quadtree().locate(p).level, QM::internal::level_for_size(on_points.quadtree(), spacing));
  }
  const QM::Mesh_quality_2 q = QM::compute_quality(on_loops.run());
  EXPECT_TRUE(q.is_valid());
  EXPECT_GE(q.min_angle, 45.0 - 1e-7);
  EXPECT_LE(q.max_angle, 135.0 + 1e-7);
}

// A saw-toothed side (100 teeth 0.004 high along a unit square's bottom, each apex turning
// it by 45 degrees): in cells of twice their spacing, a projection of the second buffer layer
// came to lie 1e-5 from a tooth's vertex, a sliver of aspect ratio 1204 that no sliver round
// mended. Features, which the mesh keeps, keep cells of their own spacing.
TEST(Quadtree_mesher_2, the_teeth_of_a_saw_keep_cells_of_their_own_spacing)
{
  Domain d;
  d.points.emplace_back(0, 0);
  for(int k = 0; k <= 100; ++k) d.points.emplace_back(0.02 + 0.96 * k / 100, k % 2 ? 0.004 : 0.0);
  d.points.emplace_back(1, 0);
  d.points.emplace_back(1, 1);
  d.points.emplace_back(0, 1);
  for(std::size_t i = 0; i < d.points.size(); ++i) d.segments.push_back({ i, (i + 1) % d.points.size() });
  const double spacing = std::hypot(0.0096, 0.004);
  Mesher mesher(d);
  mesher.run(QM::Stage::QUADTREE);
  for(std::size_t i = 2; i + 5 < d.points.size(); ++i) // the teeth but the first and the last
    EXPECT_GE(mesher.quadtree().locate(d.points[i]).level, QM::internal::level_for_size(mesher.quadtree(), spacing));
  const QM::Mesh_quality_2 q = QM::compute_quality(mesher.run());
  EXPECT_TRUE(q.is_valid());
  EXPECT_GE(q.min_angle, 45.0 - 1e-7);
  EXPECT_LE(q.max_angle, 135.0 + 1e-7);
  EXPECT_LE(q.max_aspect_ratio, 10.0);
}

TEST(Quadtree_mesher_2, min_size_caps_refinement_instead_of_failing)
{
  Domain d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(0.5, 0.5), K::Point_2(0.5, 0.5 + 1e-12) };
  EXPECT_THROW(Mesher(d).run(), QM::Meshing_error); // 1e-12 apart needs ~40 levels
  Criteria criteria(0, 1e-3);
  EXPECT_THROW(Mesher(d, criteria).run(), QM::Meshing_error); // the points must be vertices
  criteria.set_points_as_vertices(false);
  Mesher capped(d, criteria);
  auto mesh = capped.run();
  capped.quadtree().for_each_leaf([&](const QM::Cell_key& k) { EXPECT_GE(capped.quadtree().cell_side(k.level), 1e-3); });
  EXPECT_GT(mesh.quads.size(), 0u);
}

TEST(Quadtree_mesher_2, errors_name_the_points)
{
  Domain d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 1), K::Point_2(1, 1e-9 + 1) };
  try {
    Mesher(d, Criteria(0, 0, 16)).run();
    FAIL();
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("input points 1 (0-based) (1, 1) and 2 (0-based)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("maximum depth 16"), std::string::npos) << e.what();
  }
  EXPECT_THROW(Mesher(d, Criteria(1e-3, 0, 5)).run(), QM::Meshing_error); // max size too deep
  Domain empty;
  EXPECT_THROW(Mesher(empty).run(), QM::Meshing_error);
  // a square of subnormal size (the smallest double across) looped for ever
  for(double side : { 4.9406564584124654e-324, 1e-323, 1e-101 }) {
    Domain tiny;
    tiny.points = { K::Point_2(0, 0), K::Point_2(side, 0), K::Point_2(side, side), K::Point_2(0, side) };
    tiny.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
    try {
      Mesher(tiny).run();
      ADD_FAILURE() << side;
    } catch(const QM::Meshing_error& e) {
      EXPECT_NE(std::string(e.what()).find("is too small to mesh"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(Criteria(-1), QM::Meshing_error);
  EXPECT_THROW(Criteria(std::nan("")), QM::Meshing_error);
  EXPECT_THROW(Criteria(1, 2), QM::Meshing_error);
  EXPECT_THROW(Criteria(0, 0, 41), QM::Meshing_error); // beyond max_supported_depth (40)
}

// The cell budget is a memory guard: it must stop a sizing that asks too much early, and say
// where. A maximum size is refused before any cell is made (the count is known); a narrow
// region 1e-5 wide is stopped where it ran out, and the message names the place.
TEST(Quadtree_mesher_2, cell_budget_errors_come_early_and_name_the_place)
{
  Domain square;
  square.points = { K::Point_2(0, 0), K::Point_2(10, 0), K::Point_2(10, 10), K::Point_2(0, 10) };
  square.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  Criteria fine(1e-3); // 10^8 cells of side 1e-3
  fine.set_max_cells(1000000);
  Mesher uniform(square, fine);
  try {
    uniform.run(QM::Stage::QUADTREE);
    FAIL();
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("the maximum size 0.001 needs about"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("cell budget of 1000000"), std::string::npos) << e.what();
  }
  EXPECT_LT(uniform.quadtree().number_of_leaves(), 100u) << "cells were made before the refusal";
  EXPECT_EQ(Criteria().max_cells(), std::size_t(1) << 23);

  Domain gap = square; // two square holes 1e-5 apart
  for(double x0 : { 2.0, 4.00001 }) {
    const std::size_t b = gap.points.size();
    gap.points.insert(gap.points.end(), { K::Point_2(x0, 4), K::Point_2(x0 + 2, 4), K::Point_2(x0 + 2, 2), K::Point_2(x0, 2) });
    for(std::size_t k = 0; k < 4; ++k) gap.segments.push_back({ b + k, b + (k + 1) % 4 });
  }
  gap.holes = { K::Point_2(3, 3), K::Point_2(5, 3) };
  Criteria budget;
  budget.set_max_cells(200000);
  try {
    Mesher(gap, budget).run(QM::Stage::QUADTREE);
    FAIL();
  } catch(const QM::Meshing_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("more than 200000 quadtree cells"), std::string::npos) << m;
    const std::size_t at = m.find("near (");
    ASSERT_NE(at, std::string::npos) << m;
    double x = 0, y = 0;
    ASSERT_EQ(std::sscanf(m.c_str() + at, "near (%lf, %lf)", &x, &y), 2) << m;
    EXPECT_NEAR(x, 4, 0.01) << m;
    EXPECT_GE(y, 2 - 0.01) << m;
    EXPECT_LE(y, 4 + 0.01) << m;
  }
}

TEST(Quadtree_mesher_2, user_sizing_field)
{
  Domain d;
  d.points = { K::Point_2(-1, -1), K::Point_2(1, 1) };
  Criteria c;
  c.set_use_point_spacing(false);
  // fine near the origin, coarse away from it
  c.set_sizing_field([](const K::Point_2& p) {
    return K::FT(0.02 + 0.3 * std::sqrt(CGAL::to_double(p.x() * p.x() + p.y() * p.y())));
  });
  Mesher mesher(d, c);
  auto mesh = mesher.run();
  const auto& tree = mesher.quadtree();
  EXPECT_LE(tree.cell_side(tree.locate(K::Point_2(0, 0)).level), 0.02);
  EXPECT_GT(tree.cell_side(tree.locate(K::Point_2(0.95, 0.95)).level), 0.1);
  EXPECT_TRUE(tiles_its_region(mesh, mesher));
  Criteria bad;
  bad.set_sizing_field([](const K::Point_2&) { return K::FT(0); });
  EXPECT_THROW(Mesher(d, bad).run(), QM::Meshing_error);
}

TEST(Quadtree_mesher_2, vertices_are_exact_lattice_points)
{
  Domain d = random_domain(50, 3, 1e-3, 12345.678);
  Mesher mesher(d);
  auto mesh = mesher.run(QM::Stage::QUADTREE);
  const auto& tree = mesher.quadtree();
  const double h = tree.cell_side(tree.vertex_level());
  for(const auto& p : mesh.points) {
    double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    EXPECT_EQ(std::fmod(x - tree.origin_x(), h), 0.0);
    EXPECT_EQ(std::fmod(y - tree.origin_y(), h), 0.0);
    EXPECT_EQ(K::FT(x), p.x()); // the coordinate is the double exactly, under both kernels
  }
  auto range = qm2_checks::angle_range(mesh);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
}

TEST(Quadtree_mesher_2, translation_and_power_of_two_scaling_keep_the_mesh_topology)
{
  auto count = [](double scale, double shift) {
    Domain d = random_domain(100, 5, scale, shift);
    Mesher mesher(d);
    auto mesh = mesher.run();
    return std::make_pair(mesh.quads.size(), mesher.quadtree().depth());
  };
  auto reference = count(1, 0);
  EXPECT_EQ(count(std::ldexp(1.0, 30), 0), reference);
  EXPECT_EQ(count(std::ldexp(1.0, -30), 0), reference);
}

TEST(Quadtree_mesher_2, copies_into_a_surface_mesh)
{
  Domain d = random_domain(40, 9);
  auto mesh = QM::make_quad_mesh_2(d);
  CGAL::Surface_mesh<K::Point_2> sm;
  ASSERT_TRUE(QM::copy_to_face_graph(mesh, sm));
  EXPECT_EQ(num_faces(sm), mesh.quads.size());
  EXPECT_EQ(num_vertices(sm), mesh.points.size());
  EXPECT_TRUE(CGAL::is_quad_mesh(sm));
  EXPECT_TRUE(sm.is_valid(false));
}

// CGAL's usual surface mesh is one of Point_3: the mesh goes in at z = 0.
TEST(Quadtree_mesher_2, copies_into_a_surface_mesh_of_3d_points)
{
  Domain d = random_domain(40, 9);
  auto mesh = QM::make_quad_mesh_2(d);
  CGAL::Surface_mesh<K::Point_3> sm;
  ASSERT_TRUE(QM::copy_to_face_graph(mesh, sm));
  EXPECT_EQ(num_faces(sm), mesh.quads.size());
  EXPECT_TRUE(CGAL::is_quad_mesh(sm));
  EXPECT_TRUE(sm.is_valid(false));
  std::size_t i = 0;
  for(auto v : vertices(sm)) {
    const K::Point_3& p = sm.point(v);
    EXPECT_EQ(p.x(), mesh.points[i].x());
    EXPECT_EQ(p.y(), mesh.points[i].y());
    EXPECT_EQ(p.z(), 0);
    ++i;
  }
}

// The one-call function meshes a domain through every stage, as the tool does by default (it
// stopped after the points stage and returned the bounding grid, of area 64 here).
TEST(Quadtree_mesher_2, make_quad_mesh_2_meshes_a_domain_up_to_its_boundary)
{
  Domain d;
  d.points = { K::Point_2(0, 0),     K::Point_2(4, 0),     K::Point_2(4, 4),     K::Point_2(0, 4),
               K::Point_2(1.5, 1.5), K::Point_2(2.5, 1.5), K::Point_2(2.5, 2.5), K::Point_2(1.5, 2.5) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } };
  d.holes = { K::Point_2(2, 2) };
  EXPECT_EQ(QM::last_stage(d), QM::Stage::SMOOTHING);
  const auto mesh = QM::make_quad_mesh_2(d);
  ASSERT_GT(mesh.quads.size(), 0u);
  // in the closed square, and not strictly inside the hole
  auto in_domain = [](const K::Point_2& p) {
    const bool in_square = p.x() >= 0 && p.x() <= 4 && p.y() >= 0 && p.y() <= 4;
    const bool in_hole = p.x() > 1.5 && p.x() < 2.5 && p.y() > 1.5 && p.y() < 2.5;
    return in_square && !in_hole;
  };
  double area = 0;
  std::size_t outside = 0;
  for(std::size_t q = 0; q < mesh.quads.size(); ++q) {
    area += qm2_checks::signed_area(mesh, q);
    const auto& c = mesh.quads[q];
    const K::Point_2 centroid = CGAL::centroid(mesh.points[c[0]], mesh.points[c[1]], mesh.points[c[2]], mesh.points[c[3]]);
    bool inside = in_domain(centroid);
    for(int k = 0; k < 4; ++k) inside = inside && in_domain(mesh.points[c[k]]);
    outside += inside ? 0 : 1;
  }
  EXPECT_EQ(outside, 0u) << "quads with a corner or the centroid outside the domain";
  EXPECT_NEAR(area, 15, 1e-9 * 15);
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  EXPECT_TRUE(quality.is_valid());
  EXPECT_EQ(quality.number_of_boundary_loops, 2u);
  EXPECT_GE(quality.min_angle, 45 - 1e-6);
  EXPECT_LE(quality.max_angle, 135 + 1e-6);
  // a point cloud's last stage is the points stage
  Domain cloud;
  cloud.points = d.points;
  EXPECT_EQ(QM::last_stage(cloud), QM::Stage::POINTS);
}

// The square with a square hole of make_quad_mesh_2_meshes_a_domain_up_to_its_boundary.
Domain square_with_hole()
{
  Domain d;
  d.points = { K::Point_2(0, 0),     K::Point_2(4, 0),     K::Point_2(4, 4),     K::Point_2(0, 4),
               K::Point_2(1.5, 1.5), K::Point_2(2.5, 1.5), K::Point_2(2.5, 2.5), K::Point_2(1.5, 2.5) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } };
  d.holes = { K::Point_2(2, 2) };
  return d;
}

// the marker each boundary edge of `mesh` should have, by the side of the square or hole it
// lies on (`side_markers`: bottom, right, top, left, hole); -1 if it lies on none
int expected_marker(const QM::Quad_mesh_2<K::Point_2>& mesh, std::size_t a, std::size_t b,
                    const std::array<int, 5>& side_markers)
{
  const K::Point_2 &p = mesh.points[a], &q = mesh.points[b];
  if(p.y() == 0 && q.y() == 0) return side_markers[0];
  if(p.x() == 4 && q.x() == 4) return side_markers[1];
  if(p.y() == 4 && q.y() == 4) return side_markers[2];
  if(p.x() == 0 && q.x() == 0) return side_markers[3];
  const bool on_hole = (p.x() == 1.5 || p.x() == 2.5 || p.y() == 1.5 || p.y() == 2.5)
                       && (q.x() == 1.5 || q.x() == 2.5 || q.y() == 1.5 || q.y() == 2.5);
  return on_hole ? side_markers[4] : -1;
}

TEST(Quadtree_mesher_2, boundary_edges_carry_the_segment_markers)
{
  Domain d = square_with_hole();
  for(const bool marked : { true, false }) {
    SCOPED_TRACE(marked ? "segment markers" : "loop numbers");
    d.segment_markers = marked ? std::vector<int>{ 3, 4, 5, 6, -1, -1, -1, -1 } : std::vector<int>{};
    const std::array<int, 5> side_markers = marked ? std::array<int, 5>{ 3, 4, 5, 6, -1 }
                                                   : std::array<int, 5>{ 1, 1, 1, 1, 2 };
    const auto mesh = QM::make_quad_mesh_2(d);
    std::map<std::pair<std::size_t, std::size_t>, int> uses; // directed quad edges
    for(const auto& q : mesh.quads)
      for(int c = 0; c < 4; ++c) ++uses[{ q[c], q[(c + 1) % 4] }];
    std::map<int, double> length;
    for(const auto& e : mesh.boundary_edges) {
      const std::pair<std::size_t, std::size_t> edge(e.v0, e.v1), reverse(e.v1, e.v0);
      EXPECT_EQ(uses[edge], 1) << "not an edge of a quad as it runs";
      EXPECT_EQ(uses.count(reverse), 0u) << "an inner edge";
      EXPECT_EQ(e.marker, expected_marker(mesh, e.v0, e.v1, side_markers));
      length[e.marker] += std::sqrt(CGAL::to_double(CGAL::squared_distance(mesh.points[e.v0], mesh.points[e.v1])));
    }
    std::size_t boundary = 0;
    for(const auto& [edge, n] : uses) boundary += uses.count({ edge.second, edge.first }) == 0 ? 1 : 0;
    EXPECT_EQ(mesh.boundary_edges.size(), boundary);
    if(marked) {
      for(int m : { 3, 4, 5, 6 }) EXPECT_NEAR(length[m], 4, 1e-12) << "marker " << m;
      EXPECT_NEAR(length[-1], 4, 1e-12);
    } else {
      EXPECT_NEAR(length[1], 16, 1e-12);
      EXPECT_NEAR(length[2], 4, 1e-12);
    }
  }
  // before the boundary is reached there are none
  EXPECT_TRUE(QM::make_quad_mesh_2(d, Criteria(), QM::Stage::BUFFER1).boundary_edges.empty());
  // one marker per segment, or none
  d.segment_markers = { 1, 2 };
  EXPECT_THROW(QM::make_quad_mesh_2(d), QM::Meshing_error);
}

// Land around a lake (a hole) holding an island: two regions. The island's regional
// attribute 2.5 is no integer, so its region takes tag 1; the land's 7 is its own tag.
TEST(Quadtree_mesher_2, every_quad_carries_its_region)
{
  Domain d;
  d.points = { K::Point_2(0, 0),     K::Point_2(4, 0),     K::Point_2(4, 3),     K::Point_2(0, 3),
               K::Point_2(1, 0.7),   K::Point_2(3.2, 0.6), K::Point_2(3.1, 2.3), K::Point_2(0.9, 2.4),
               K::Point_2(1.7, 1.2), K::Point_2(2.5, 1.3), K::Point_2(2.4, 1.8), K::Point_2(1.6, 1.7) };
  for(std::size_t loop = 0; loop < 3; ++loop)
    for(std::size_t k = 0; k < 4; ++k) d.segments.push_back({ 4 * loop + k, 4 * loop + (k + 1) % 4 });
  d.holes = { K::Point_2(1.2, 1.0) };
  const std::vector<K::Point_2> island(d.points.begin() + 8, d.points.end());
  auto region_of = [&](const QM::Quad_mesh_2<K::Point_2>& mesh, std::size_t q) {
    const auto& v = mesh.quads[q];
    const K::Point_2 centre = CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    return CGAL::bounded_side_2(island.begin(), island.end(), centre, K()) == CGAL::ON_BOUNDED_SIDE ? 1 : 0;
  };

  // without attributes: regions 1 and 2 in the order of their outer loops, land first
  QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(d);
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_EQ(mesh.regions[0].tag, 1);
  EXPECT_EQ(mesh.regions[1].tag, 2);
  EXPECT_FALSE(mesh.regions[0].has_attribute || mesh.regions[1].has_attribute);
  ASSERT_EQ(mesh.quad_regions.size(), mesh.quads.size());
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    ASSERT_EQ(mesh.quad_regions[q], std::size_t(region_of(mesh, q))) << "quad " << q;

  // with attributes, the island's with a maximum area
  const double max_area = 0.002;
  d.region_attributes = { { K::Point_2(0.3, 0.3), 7, 0 }, { K::Point_2(2, 1.5), 2.5, max_area } };
  mesh = QM::make_quad_mesh_2(d);
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_EQ(mesh.regions[0].tag, 7);
  EXPECT_EQ(mesh.regions[0].attribute, 7);
  EXPECT_EQ(mesh.regions[1].tag, 1);
  EXPECT_EQ(mesh.regions[1].attribute, 2.5);
  EXPECT_TRUE(mesh.regions[0].has_attribute && mesh.regions[1].has_attribute);
  std::array<double, 2> area{}, largest{};
  std::array<std::size_t, 2> count{};
  for(std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const std::size_t r = std::size_t(region_of(mesh, q));
    ASSERT_EQ(mesh.quad_regions[q], r) << "quad " << q;
    const auto& v = mesh.quads[q];
    const double a = std::abs(CGAL::to_double(CGAL::area(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]])
                                              + CGAL::area(mesh.points[v[0]], mesh.points[v[2]], mesh.points[v[3]])));
    area[r] += a;
    largest[r] = (std::max)(largest[r], a);
    ++count[r];
  }
  EXPECT_LE(largest[1], max_area);
  EXPECT_GT(count[1], std::size_t(0.48 / max_area)); // the island's area is 0.48
  EXPECT_GT(area[0] / double(count[0]), 4 * area[1] / double(count[1])); // the land is not refined

  // a maximum area beyond the cell budget is an error before any cell is made
  d.region_attributes[1].max_area = 1e-10;
  try {
    QM::make_quad_mesh_2(d);
    ADD_FAILURE() << "no Meshing_error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("maximum areas need about 7.04375e+09 quadtree cells"), std::string::npos)
      << e.what();
  }
  // the minimum size caps it, as it caps the sizing field
  Criteria capped;
  capped.set_min_size(0.05);
  EXPECT_NO_THROW(QM::make_quad_mesh_2(d, capped));
}

// The mesh vertices on segment ab, ordered from a to b (within 1e-10 of its length: Epick's
// points on it, to rounding); empty unless the first is a and the last b.
std::vector<std::size_t> vertices_along(const QM::Quad_mesh_2<K::Point_2>& mesh, const K::Point_2& a, const K::Point_2& b)
{
  const K::Segment_2 ab(a, b);
  const double tolerance = 1e-20 * CGAL::to_double(ab.squared_length());
  std::vector<std::pair<double, std::size_t>> on; // along a -> b
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(CGAL::to_double(CGAL::squared_distance(ab, mesh.points[v])) <= tolerance)
      on.emplace_back(CGAL::to_double(CGAL::squared_distance(a, mesh.points[v])), v);
  std::sort(on.begin(), on.end());
  std::vector<std::size_t> chain;
  if(on.size() < 2 || mesh.points[on.front().second] != a || mesh.points[on.back().second] != b) return chain;
  for(const auto& vertex : on) chain.push_back(vertex.second);
  return chain;
}

// Every segment of `d` with the domain on both sides (an interface, a crack, faces meeting at
// junctions) is a chain of mesh edges from vertex to vertex of the input, each edge with one
// quad on either side, in the region of that side; and every quad in the region its centroid
// lies in (`region_of`).
template <class Region_of>
::testing::AssertionResult interfaces_are_edge_chains(const QM::Quad_mesh_2<K::Point_2>& mesh, const Domain& d,
                                                      Region_of region_of)
{
  const QM::Domain_loops_2<K> loops = QM::extract_loops(d);
  std::vector<std::pair<std::size_t, std::size_t>> boundary;
  const ::testing::AssertionResult conforming = qm2_checks::is_conforming(mesh, &boundary);
  if(!conforming) return conforming;
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> quad_of_edge; // directed, ccw in its quad
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) quad_of_edge[{ mesh.quads[q][c], mesh.quads[q][(c + 1) % 4] }] = q;
  std::size_t interfaces = 0;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& loop = loops.loops[l];
    const auto& lv = loop.vertices;
    for(std::size_t k = 0; k < lv.size(); ++k) {
      const auto twin = loop.edge_twins[k];
      if(twin[0] == std::size_t(-1) || twin < std::array<std::size_t, 2>{ l, k }) continue; // each segment once
      ++interfaces;
      const std::vector<std::size_t> on = vertices_along(mesh, d.points[lv[k]], d.points[lv[(k + 1) % lv.size()]]);
      if(on.empty())
        return ::testing::AssertionFailure() << "edge " << k << " of interface loop " << l << " does not end at mesh vertices";
      for(std::size_t j = 0; j + 1 < on.size(); ++j) {
        const auto left = quad_of_edge.find({ on[j], on[j + 1] });
        const auto right = quad_of_edge.find({ on[j + 1], on[j] });
        if(left == quad_of_edge.end() || right == quad_of_edge.end())
          return ::testing::AssertionFailure() << "edge " << k << " of interface loop " << l << " is not a chain of inner mesh edges";
        if(mesh.quad_regions[left->second] != region_of(mesh, left->second)
           || mesh.quad_regions[right->second] != region_of(mesh, right->second)
           || (loop.region == loops.loops[twin[0]].region) != (mesh.quad_regions[left->second] == mesh.quad_regions[right->second]))
          return ::testing::AssertionFailure() << "the quads beside edge " << k << " of interface loop " << l
                                               << " are in the wrong regions";
      }
    }
  }
  if(interfaces == 0) return ::testing::AssertionFailure() << "no interface";
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    if(mesh.quad_regions[q] != region_of(mesh, q))
      return ::testing::AssertionFailure() << "quad " << q << " is in region " << mesh.quad_regions[q];
  return ::testing::AssertionSuccess();
}

// the region of quad q: 1 if its centroid lies inside `inner`, else 0
struct Inside_polygon
{
  std::vector<K::Point_2> inner;
  std::size_t operator()(const QM::Quad_mesh_2<K::Point_2>& mesh, std::size_t q) const
  {
    const auto& v = mesh.quads[q];
    const K::Point_2 centre = CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    return CGAL::bounded_side_2(inner.begin(), inner.end(), centre, K()) == CGAL::ON_BOUNDED_SIDE ? 1 : 0;
  }
};

void expect_angles_within_45_135(const QM::Quad_mesh_2<K::Point_2>& mesh)
{
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  EXPECT_TRUE(quality.is_valid());
  EXPECT_GE(quality.min_angle, 45.0 - 1e-7);
  EXPECT_LE(quality.max_angle, 135.0 + 1e-7);
}

// The regions of a mesh with a non-manifold edge (three quads on one edge, as a broken mesh
// given to the marking could have) come from the same boundary edges as the markers: no
// read past them (the sanitizers' build runs this).
TEST(Quadtree_mesher_2, regions_of_a_non_manifold_mesh_read_only_its_boundary_edges)
{
  const Domain d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 2, 1) });
  const QM::Domain_loops_2<K> loops = QM::extract_loops(d);
  QM::Quad_mesh_2<K::Point_2> mesh;
  mesh.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1), K::Point_2(0, 1), K::Point_2(2, 0),
                  K::Point_2(2, 1), K::Point_2(1.5, 0.5), K::Point_2(1.5, 0.7) };
  mesh.quads = { { 0, 1, 2, 3 }, { 1, 4, 5, 2 }, { 1, 6, 7, 2 } }; // edge 1-2 in all three
  QM::internal::mark_boundary_and_regions(mesh, d, loops);
  ASSERT_EQ(mesh.quad_regions.size(), 3u);
  for(std::size_t r : mesh.quad_regions) EXPECT_EQ(r, 0u);
}

// Triangle's rule: with hole points, a loop with no hole point inside is an interface between
// the region inside and the one around; both are meshed, sharing the nodes on it.
TEST(Quadtree_mesher_2, an_inclusion_is_meshed_on_both_sides_sharing_its_nodes)
{
  for(const std::vector<K::Point_2>& inclusion :
      { qm2_test::disc(5, 5, 3, 48), std::vector<K::Point_2>{ K::Point_2(3, 3), K::Point_2(7, 3.5), K::Point_2(4.5, 7) },
        qm2_test::rectangle(4, 4, 6, 6) }) {
    SCOPED_TRACE(inclusion.size());
    const Domain d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10), inclusion, qm2_test::rectangle(0.5, 0.5, 1.5, 1.5) },
                                        { K::Point_2(1, 1) });
    Mesher mesher(d);
    const QM::Quad_mesh_2<K::Point_2> mesh = mesher.run();
    ASSERT_EQ(mesh.regions.size(), 2u);
    EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, Inside_polygon{ inclusion }));
    expect_angles_within_45_135(mesh);
    // the mesh's boundary is the square's and the hole's: 2 loops
    EXPECT_EQ(QM::compute_quality(mesh).number_of_boundary_loops, 2u);
  }
  // the regions' attributes (materials) reach their quads
  Domain d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10), qm2_test::disc(5, 5, 3, 48),
                                  qm2_test::rectangle(0.5, 0.5, 1.5, 1.5) },
                                { K::Point_2(1, 1) });
  d.region_attributes = { { K::Point_2(9, 9), 5, 0 }, { K::Point_2(5, 5), 7, 0 } };
  const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_EQ(mesh.regions[0].tag, 5);
  EXPECT_EQ(mesh.regions[1].tag, 7);
  EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, Inside_polygon{ qm2_test::disc(5, 5, 3, 48) }));
}

// The paper's future work: an air foil's inside and its far field, in one mesh.
TEST(Quadtree_mesher_2, an_air_foil_is_meshed_inside_and_out)
{
  Domain d;
  std::string error;
  ASSERT_TRUE(QM::IO::read_poly(std::string(QM2_DATA_DIR) + "/naca0012/naca0012.poly", d, &error)) << error;
  // its hole point goes; a small hole elsewhere keeps Triangle's rule (with hole points)
  const std::vector<K::Point_2> foil(d.points.begin() + 4, d.points.end());
  const std::vector<K::Point_2> hole = qm2_test::rectangle(-15, -15, -14.5, -14.5);
  d.holes = { K::Point_2(-14.75, -14.75) };
  const std::size_t base = d.points.size();
  d.points.insert(d.points.end(), hole.begin(), hole.end());
  for(std::size_t k = 0; k < 4; ++k) {
    d.segments.push_back({ base + k, base + (k + 1) % 4 });
    d.segment_markers.push_back(3);
  }
  Mesher mesher(d);
  const QM::Quad_mesh_2<K::Point_2> mesh = mesher.run();
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, Inside_polygon{ foil }));
  expect_angles_within_45_135(mesh);
}

// A corner under 45 degrees on either side of an interface is not supported yet: the strip
// on the wedge's side cannot take the nodes the fan on the other side needs. Where angles
// stay out, the mesher names the corner.
Domain square_holding_a_wedge(double degrees) // a wedge of `degrees` at (6, 5), 3 long
{
  const double half_width = 3 * std::tan(degrees / 2 * CGAL_PI / 180);
  return qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10),
                              { K::Point_2(3, 5 - half_width), K::Point_2(6, 5), K::Point_2(3, 5 + half_width) },
                              qm2_test::rectangle(0.5, 0.5, 1.5, 1.5) },
                            { K::Point_2(1, 1) });
}

TEST(Quadtree_mesher_2, a_sharp_interface_corner_is_named_where_angles_stay_out)
{
  const Domain d = square_holding_a_wedge(40);
  Mesher mesher(d);
  const QM::Quad_mesh_2<K::Point_2> mesh = mesher.run();
  EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, Inside_polygon{ std::vector<K::Point_2>(d.points.begin() + 4, d.points.begin() + 7) }));
  EXPECT_GT(mesher.buffer_report().bad_angle_quads, 0u);
  const std::string note = mesher.sharp_interface_corner_note();
  EXPECT_NE(note.find("input point 5 (6, 5) is a corner of 40"), std::string::npos) << note;
  // none on a mild interface
  const Domain mild = qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10), qm2_test::rectangle(4, 4, 6, 6),
                                           qm2_test::rectangle(0.5, 0.5, 1.5, 1.5) },
                                         { K::Point_2(1, 1) });
  EXPECT_EQ(Mesher(mild).sharp_interface_corner_note(), "");
  // where the buffer cannot be built at all, the error names it
  const Domain needle = square_holding_a_wedge(15);
  try {
    Mesher(needle).run();
    ADD_FAILURE() << "no Meshing_error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("input point 5 (6, 5) is a corner of 15 degrees on an interface"), std::string::npos)
      << e.what();
  }
}

// Every segment of `polyline` is a chain of mesh edges from vertex to vertex, each edge with a
// quad on either side (the two sides of a crack share its nodes).
::testing::AssertionResult crack_is_an_edge_chain(const QM::Quad_mesh_2<K::Point_2>& mesh,
                                                  const std::vector<K::Point_2>& polyline)
{
  const ::testing::AssertionResult conforming = qm2_checks::is_conforming(mesh);
  if(!conforming) return conforming;
  std::set<std::pair<std::size_t, std::size_t>> directed_edges;
  for(const auto& q : mesh.quads)
    for(int c = 0; c < 4; ++c) directed_edges.insert({ q[c], q[(c + 1) % 4] });
  for(std::size_t k = 0; k + 1 < polyline.size(); ++k) {
    const std::vector<std::size_t> on = vertices_along(mesh, polyline[k], polyline[k + 1]);
    if(on.empty()) return ::testing::AssertionFailure() << "segment " << k << " of the crack does not end at mesh vertices";
    for(std::size_t j = 0; j + 1 < on.size(); ++j)
      if(!directed_edges.count({ on[j], on[j + 1] }) || !directed_edges.count({ on[j + 1], on[j] }))
        return ::testing::AssertionFailure() << "segment " << k << " of the crack is not a chain of inner mesh edges";
  }
  return ::testing::AssertionSuccess();
}

// Triangle's rule: a polyline with free ends inside the domain is a crack, kept as mesh edges
// with quads on either side sharing its nodes; its tips are corners of 360 degrees, so every
// angle stays within [45, 135].
TEST(Quadtree_mesher_2, a_crack_is_a_chain_of_mesh_edges_with_quads_on_either_side)
{
  const std::vector<std::vector<K::Point_2>> cracks = {
    { K::Point_2(3, 4), K::Point_2(7, 6) },
    { K::Point_2(2, 2), K::Point_2(5, 5), K::Point_2(8, 4), K::Point_2(7, 8) }, // kinked at 117 and 57.5 degrees
  };
  for(const auto& crack : cracks) {
    SCOPED_TRACE(crack.size());
    Domain d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10) });
    for(std::size_t k = 0; k < crack.size(); ++k) {
      d.points.push_back(crack[k]);
      if(k > 0) d.segments.push_back({ d.points.size() - 2, d.points.size() - 1 });
    }
    const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
    EXPECT_TRUE(crack_is_an_edge_chain(mesh, crack));
    expect_angles_within_45_135(mesh);
    EXPECT_EQ(QM::compute_quality(mesh).number_of_boundary_loops, 1u); // the square's only
  }
}

// A crack's kink of 155 and 205 degrees in a random convex domain (crack_sweep.py --seed 12,
// domain 23): the narrow side took the wide side's three nodes about the kink and fanned over
// them (154.7 degrees at the kink) until the two beside it could leave both sides.
TEST(Quadtree_mesher_2, a_crack_kink_keeps_no_fan_over_its_narrow_side)
{
  Domain d;
  std::string error;
  ASSERT_TRUE(QM::IO::read_poly(std::string(QM2_TEST_DATA_DIR) + "/crack_kink_fan_12_23.poly", d, &error)) << error;
  const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
  const std::vector<K::Point_2> crack(d.points.end() - 5, d.points.end());
  EXPECT_TRUE(crack_is_an_edge_chain(mesh, crack));
  expect_angles_within_45_135(mesh);
}

// The shared case `face`: three holes, two cracks and two isolated points.
TEST(Quadtree_mesher_2, the_shared_face_keeps_its_cracks_and_isolated_points)
{
  Domain d;
  std::string error;
  ASSERT_TRUE(QM::IO::read_poly(std::string(QM2_SHARED_DATA_DIR) + "/face/face.poly", d, &error)) << error;
  const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
  EXPECT_TRUE(crack_is_an_edge_chain(mesh, { d.points[20], d.points[21] }));
  EXPECT_TRUE(crack_is_an_edge_chain(mesh, { d.points[22], d.points[23] }));
  for(std::size_t v : { 24u, 25u })
    EXPECT_NE(std::find(mesh.points.begin(), mesh.points.end(), d.points[v]), mesh.points.end()) << v;
  expect_angles_within_45_135(mesh);
  EXPECT_EQ(QM::compute_quality(mesh).number_of_boundary_loops, 4u);
}

// the region of quad q: that of the face of `d` (an outer loop, without attributes) that
// holds its centroid
struct Face_holding
{
  QM::Domain_loops_2<K> loops;
  const Domain& d;
  Face_holding(const Domain& domain) : loops(QM::extract_loops(domain)), d(domain) {}
  std::size_t operator()(const QM::Quad_mesh_2<K::Point_2>& mesh, std::size_t q) const
  {
    const auto& v = mesh.quads[q];
    const K::Point_2 centre = CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    for(const auto& loop : loops.loops) {
      if(!loop.is_outer) continue;
      const CGAL::Polygon_2<K> face = QM::loop_polygon_2(d, loop);
      if(face.bounded_side(centre) == CGAL::ON_BOUNDED_SIDE) return loop.region;
    }
    return std::size_t(-1);
  }
};

// a closed polygon's segments and, joining its vertices `spokes`, the segments inside it
Domain polygon_with_spokes(const std::vector<K::Point_2>& polygon, const std::vector<std::array<std::size_t, 2>>& spokes,
                           const std::vector<K::Point_2>& inner_points = {})
{
  Domain d = qm2_test::polygons({ polygon });
  d.points.insert(d.points.end(), inner_points.begin(), inner_points.end());
  for(const auto& s : spokes) d.segments.push_back(s);
  return d;
}

// Faces that meet at junctions (vertices of three segments or more) are regions meshed
// together: every segment between two of them a chain of mesh edges, each region's quads
// on its side, every angle within [45, 135].
TEST(Quadtree_mesher_2, faces_meeting_at_junctions_share_the_nodes_of_their_segments)
{
  typedef K::Point_2 P;
  std::vector<std::pair<std::string, Domain>> cases;
  cases.emplace_back("a square split by a segment",
                     polygon_with_spokes({ P(0, 0), P(1, 0), P(2, 0), P(2, 1.5), P(1, 1.5), P(0, 1.5) }, { { { 1, 4 } } }));
  cases.emplace_back("a T", polygon_with_spokes({ P(0, 0), P(2, 0), P(2, 0.5), P(2, 1), P(1, 1), P(0, 1), P(0, 0.5) },
                                                { { { 6, 7 } }, { { 7, 2 } }, { { 7, 4 } } }, { P(1, 0.5) }));
  cases.emplace_back("a cross", polygon_with_spokes({ P(0, 0), P(1, 0), P(2, 0), P(2, 1), P(2, 2), P(1, 2), P(0, 2), P(0, 1) },
                                                    { { { 8, 1 } }, { { 8, 3 } }, { { 8, 5 } }, { { 8, 7 } } }, { P(1, 1) }));
  cases.emplace_back("three layers", polygon_with_spokes({ P(0, 0), P(4, 0), P(4, 0.3), P(4, 0.6), P(4, 1), P(0, 1), P(0, 0.6),
                                                           P(0, 0.3) },
                                                         { { { 7, 2 } }, { { 6, 3 } } }));
  std::vector<P> disc = qm2_test::disc(0, 0, 1, 20);
  cases.emplace_back("five spokes 72 degrees apart",
                     polygon_with_spokes(disc, { { { 20, 0 } }, { { 20, 4 } }, { { 20, 8 } }, { { 20, 12 } }, { { 20, 16 } } },
                                         { P(0, 0) }));
  for(const auto& [name, d] : cases) {
    SCOPED_TRACE(name);
    const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
    const Face_holding face(d);
    EXPECT_EQ(mesh.regions.size(), face.loops.loops.size());
    EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, face));
    expect_angles_within_45_135(mesh);
    EXPECT_EQ(QM::compute_quality(mesh).number_of_boundary_loops, 1u);
  }
}

// A 3 x 3 checkerboard of two materials: nine faces, two regions by their attributes.
TEST(Quadtree_mesher_2, a_checkerboard_of_two_materials_is_two_regions)
{
  Domain d;
  const auto at = [](int i, int j) { return std::size_t(4 * j + i); };
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i) d.points.push_back(K::Point_2(i, j));
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 3; ++i) d.segments.push_back({ at(i, j), at(i + 1, j) });
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 4; ++i) d.segments.push_back({ at(i, j), at(i, j + 1) });
  for(int j = 0; j < 3; ++j)
    for(int i = 0; i < 3; ++i) d.region_attributes.push_back({ K::Point_2(i + 0.5, j + 0.5), double(1 + (i + j) % 2), 0 });
  const QM::Quad_mesh_2<K::Point_2> mesh = Mesher(d).run();
  ASSERT_EQ(mesh.regions.size(), 2u);
  EXPECT_EQ(mesh.regions[0].tag, 1);
  EXPECT_EQ(mesh.regions[1].tag, 2);
  auto material = [](const QM::Quad_mesh_2<K::Point_2>& m, std::size_t q) {
    const auto& v = m.quads[q];
    const K::Point_2 c = CGAL::centroid(m.points[v[0]], m.points[v[1]], m.points[v[2]], m.points[v[3]]);
    return std::size_t(int(std::floor(CGAL::to_double(c.x())) + std::floor(CGAL::to_double(c.y()))) % 2);
  };
  EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, material));
  expect_angles_within_45_135(mesh);
}

// Expects every angle of `mesh` within [45, 135] but angles under 45 at `corner`, a sharp
// input corner; returns how many there are.
std::size_t angles_under_45_only_at(const QM::Quad_mesh_2<K::Point_2>& mesh, const K::Point_2& corner)
{
  EXPECT_TRUE(QM::compute_quality(mesh).is_valid());
  std::size_t sharp = 0;
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) {
      const double angle = qm2_checks::corner_angle(mesh, q, c);
      EXPECT_LE(angle, 135.0 + 1e-7);
      if(angle >= 45.0 - 1e-7) continue;
      ++sharp;
      EXPECT_EQ(mesh.points[mesh.quads[q][c]], corner) << angle;
    }
  return sharp;
}

// A crack from a corner of the domain and three cracks meeting inside it: the faces walk
// around them; every crack a chain of inner mesh edges.
TEST(Quadtree_mesher_2, cracks_from_a_corner_and_meeting_at_a_junction_are_edge_chains)
{
  typedef K::Point_2 P;
  const Domain tail = polygon_with_spokes(qm2_test::rectangle(0, 0, 4, 4), { { { 0, 4 } } }, { P(2, 1.5) });
  const QM::Quad_mesh_2<K::Point_2> walked = Mesher(tail).run();
  EXPECT_TRUE(crack_is_an_edge_chain(walked, { P(0, 0), P(2, 1.5) }));
  EXPECT_EQ(angles_under_45_only_at(walked, P(0, 0)), 1u); // the crack leaves the corner at 36.9 degrees
  const Domain y = polygon_with_spokes(qm2_test::rectangle(0, 0, 4, 4), { { { 4, 5 } }, { { 4, 6 } }, { { 4, 7 } } },
                                       { P(2, 2), P(1, 1), P(3, 1.2), P(2.2, 3) });
  const QM::Quad_mesh_2<K::Point_2> branched = Mesher(y).run();
  for(std::size_t end : { 5u, 6u, 7u }) EXPECT_TRUE(crack_is_an_edge_chain(branched, { y.points[4], y.points[end] })) << end;
  expect_angles_within_45_135(branched);
  EXPECT_EQ(QM::compute_quality(branched).number_of_boundary_loops, 1u);
}

// The shared case `cgal_butterfly`: eight segments meet at the origin, six faces in the
// domain with corners of 31.9 and 39.1 degrees there, which only their own quads keep.
TEST(Quadtree_mesher_2, the_shared_butterfly_keeps_its_junction_s_sharp_corners_only)
{
  Domain d;
  std::string error;
  ASSERT_TRUE(QM::IO::read_poly(std::string(QM2_SHARED_DATA_DIR) + "/cgal_butterfly/cgal_butterfly.poly", d, &error)) << error;
  Mesher mesher(d);
  const QM::Quad_mesh_2<K::Point_2> mesh = mesher.run();
  EXPECT_TRUE(interfaces_are_edge_chains(mesh, d, Face_holding(d)));
  EXPECT_TRUE(QM::compute_quality(mesh).is_valid());
  EXPECT_EQ(angles_under_45_only_at(mesh, K::Point_2(0, 0)), 6u); // one quad in each face's corner there
  EXPECT_EQ(mesher.buffer_report().bad_angle_quads, 0u);
}

TEST(Quadtree_mesher_2, stage_timings_are_recorded)
{
  Domain d = random_domain(10, 2);
  Mesher mesher(d);
  mesher.run();
  std::vector<std::string> names;
  for(const auto& t : mesher.timings()) {
    names.push_back(t.first);
    EXPECT_GE(t.second, 0.0);
  }
  EXPECT_EQ(names, (std::vector<std::string>{ "refine", "balance", "refinement_templates", "points" }));
}

TEST(Quadtree_mesher_2, single_point_and_collinear_points)
{
  Domain one;
  one.points = { K::Point_2(3, 4) };
  Criteria plain;
  plain.set_points_as_vertices(false);
  auto mesh = QM::make_quad_mesh_2(one, plain);
  EXPECT_EQ(mesh.quads.size(), 1u);
  Domain line;
  for(int i = 0; i < 20; ++i)
    line.points.emplace_back(0.5, 0.1 * i);
  Mesher mesher(line);
  auto m = mesher.run();
  auto range = qm2_checks::angle_range(m);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
  EXPECT_TRUE(qm2_checks::is_conforming(m));
}

// The rounds of bahamas_islands (`quad-mesher -v`): invalid rounds count for nothing; the count
// of quads with an unforced angle out fell 420, 65, 19, 3, 1 over five valid rounds (a fixed
// budget of three angle rounds stopped at 3), then went 2, 1, 2, 2: the fourth valid round in a
// row that does not lower it ends the rounds, and the best is the round with 1.
TEST(Quadtree_mesher_2, angle_rounds_go_on_while_the_count_falls)
{
  QM::internal::Angle_rounds rounds(Mesher::max_stalled_angle_rounds);
  EXPECT_FALSE(rounds.has_valid_round());
  const std::vector<std::pair<bool, std::size_t>> seen = {
    { false, 422 }, { false, 420 }, { true, 420 }, { false, 69 }, { true, 65 }, { false, 21 },
    { true, 19 },   { true, 3 },    { true, 1 },   { true, 2 },   { true, 1 },  { true, 2 }, { true, 2 }
  };
  const std::vector<bool> best = { false, false, true, false, true, false, true, true, true, false, false, false, false };
  for(std::size_t r = 0; r < seen.size(); ++r) {
    EXPECT_EQ(rounds.record(seen[r].first, seen[r].second), best[r]) << "round " << r + 1;
    EXPECT_EQ(rounds.go_on(), r + 1 < seen.size()) << "round " << r + 1;
  }
  EXPECT_EQ(rounds.best(), 1u);
  EXPECT_TRUE(rounds.has_valid_round());
}

// The refinement requests of one round ask for one level finer than the tree is there before
// them, together: two at one point (a poor quad's core vertex, which a neighbouring poor quad or
// its first buffer point asks for again) and one beside them in the same leaf split it once,
// where each had gone one level past the last (levels 5 and 6 here, then 6 for both); the
// next round's go one level further.
TEST(Quadtree_mesher_2, one_round_of_requests_refines_one_level_together)
{
  using Tree = QM::Balanced_quadtree_2<K>;
  using P2d = QM::internal::Point_2d;
  // the unit square's root has side 2 at the origin: (0.3, 0.3) and (0.31, 0.32) share the
  // level-3 leaf [0.25, 0.5]^2 and its level-4 child
  auto tree = [] {
    Tree t(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(1, 1)), 20);
    t.refine_at(K::Point_2(0.3, 0.3), 3);
    return t;
  };
  const P2d p(0.3, 0.3), q(0.31, 0.32);
  QM::internal::Refinement_queue queue;
  Tree first = tree();
  EXPECT_EQ(queue.add(first, { { p, 0.0 }, { p, 0.0 }, { q, 0.0 } }), 3u);
  EXPECT_TRUE(queue.refine(first));
  EXPECT_EQ(first.locate(K::Point_2(0.3, 0.3)).level, 4);
  EXPECT_EQ(first.locate(K::Point_2(0.31, 0.32)).level, 4);
  Tree second = tree();
  EXPECT_EQ(queue.add(second, { { p, 0.0 } }), 1u);
  EXPECT_TRUE(queue.refine(second));
  EXPECT_EQ(second.locate(K::Point_2(0.3, 0.3)).level, 5);
  EXPECT_EQ(second.locate(K::Point_2(0.31, 0.32)).level, 5); // in a child of the leaf split
}

TEST(Quadtree_mesher_2, loop_turning_sums_the_turns_near_a_point)
{
  using P2d = QM::internal::Point_2d;
  const QM::internal::Loop_turning square({ P2d(0, 0), P2d(1, 0), P2d(1, 1), P2d(0, 1) });
  EXPECT_DOUBLE_EQ(square.arc(0), 0.0);
  EXPECT_DOUBLE_EQ(square.arc(3), 3.0);
  EXPECT_DOUBLE_EQ(square.within(0.5, 0.2), 0.0); // mid first side
  EXPECT_DOUBLE_EQ(square.within(1.0, 0.1), 90.0); // at vertex 1
  EXPECT_DOUBLE_EQ(square.within(1.5, 0.6), 180.0); // vertices 1 and 2
  EXPECT_DOUBLE_EQ(square.within(0.05, 0.1), 90.0); // vertex 0, across the loop's start
  EXPECT_DOUBLE_EQ(square.within(3.95, 0.1), 90.0); // and from its end
  EXPECT_DOUBLE_EQ(square.within(2.0, 2.0), 360.0); // the whole loop
  // a turn either way counts: the notch's reflex vertex as much as a convex one
  const QM::internal::Loop_turning notch({ P2d(0, 0), P2d(2, 0), P2d(2, 2), P2d(1, 1), P2d(0, 2) });
  EXPECT_NEAR(notch.within(4.0 + std::sqrt(2.0), 0.1), 90.0, 1e-9);
}

// The quadtree's band along the boundary (refine_boundary_band()): one cell along a
// straight side, three within three cells of a corner or of a curve turning by over 50°.
TEST(Quadtree_mesher_2, boundary_band_is_wider_where_the_boundary_turns)
{
  using P2d = QM::internal::Point_2d;
  using Sizing = QM::internal::Quadtree_sizing<K>;
  EXPECT_LT(Sizing::straight_band, Sizing::turning_band);
  const QM::internal::Loop_turning rectangle({ P2d(0, 0), P2d(4, 0), P2d(4, 1), P2d(0, 1) });
  const double h = 1.0 / 16;
  EXPECT_EQ(Sizing::band_cells(rectangle, 2.0, h), Sizing::straight_band); // mid bottom side
  EXPECT_EQ(Sizing::band_cells(rectangle, 4.0 - 2 * h, h), Sizing::turning_band); // 2 cells from a corner
  EXPECT_EQ(Sizing::band_cells(rectangle, 4.0 - 4 * h, h), Sizing::straight_band); // 4 cells from it
  EXPECT_EQ(Sizing::band_cells(rectangle, 0.5 * h, h), Sizing::turning_band); // past the loop's start
  // a 64-gon (5.625° a vertex, sides of 0.098): gentle within 3 cells of 1/16 and 1/8 (8
  // vertices, 45°: a band of 3 cells there while the limit was 40°), not of 1/4
  std::vector<P2d> circle;
  for(int k = 0; k < 64; ++k) circle.emplace_back(std::cos(k * CGAL_PI / 32), std::sin(k * CGAL_PI / 32));
  const QM::internal::Loop_turning turning(circle);
  EXPECT_EQ(Sizing::band_cells(turning, 1.0, 1.0 / 16), Sizing::straight_band);
  EXPECT_EQ(Sizing::band_cells(turning, 1.0, 1.0 / 8), Sizing::straight_band); // 45° within 3 cells
  EXPECT_EQ(Sizing::band_cells(turning, 1.0, 1.0 / 4), Sizing::turning_band);
}

// The 30P30N turned 135 degrees and scaled by 1.37 (benchmark/transform_sweep.py airfoils): the
// rounds refining its slat cusp, a thin wedge, made cells of 1.4e-8 of the diagonal there while
// each request of a round went a level past the last (mesh vertices 9.2e-9 of the diagonal
// apart); one level a round, 2 rounds instead of 5 and vertices 1.8e-7 of it apart.
TEST(Quadtree_mesher_2, a_thin_wedge_tip_keeps_its_vertices_apart)
{
  Domain d;
  std::string error;
  const std::string file = std::string(QM2_TEST_DATA_DIR) + "/airfoil_30p30n_turned135_x1.37.poly";
  ASSERT_TRUE(QM::IO::read_poly(file, d, &error)) << error;
  Mesher mesher(d);
  const QM::Quad_mesh_2<K::Point_2> m = mesher.run();
  const QM::Mesh_quality_2 q = QM::compute_quality(m);
  EXPECT_TRUE(q.is_valid());
  EXPECT_GE(q.min_edge_over_diagonal, 1e-8);
  EXPECT_LE(q.max_aspect_ratio, 10.0);
  EXPECT_GE(q.min_angle, 45.0 - 1e-7);
  EXPECT_LE(q.max_angle, 135.0 + 1e-7);
  EXPECT_EQ(mesher.buffer_report().bad_angle_quads, 0u);
}

} // namespace qm2_test_mesher
