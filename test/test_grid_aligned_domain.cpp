// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Grid-aligned domains (internal/grid_aligned_domain.h, the paper's Fig. 4(b) exception for a
// whole boundary): an axis-parallel domain whose corners are lattice points is meshed by the
// cells inside it, with no buffer: squares wherever the cells are uniform. Other domains,
// axis-parallel or not, go through the buffer stages as before.

#include "qm2_mesh_checks.h"
#include "qm2_test_domains.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace qm2_test_grid_aligned_domain {

using qm2_test::K;
using qm2_test::Point_2;
namespace QM = CGAL::Quad_mesher_2;
typedef QM::Quad_mesh_2<Point_2> Mesh;

double mesh_area(const Mesh& m)
{
  double area = 0;
  for(std::size_t q = 0; q < m.quads.size(); ++q) area += qm2_checks::signed_area(m, q);
  return area;
}

// every corner of every quad a right angle, to rounding
void expect_all_right_angles(const Mesh& m, const std::string& name)
{
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) ASSERT_NEAR(qm2_checks::corner_angle(m, q, c), 90.0, 1e-9) << name << ": quad " << q;
}

struct Meshed
{
  Mesh mesh;
  std::size_t buffer_quads = 0;
};

Meshed mesh_of(const QM::Domain_2<K>& d, double max_size = 0)
{
  QM::Mesh_criteria_2<K> criteria;
  if(max_size > 0) criteria.set_max_size(max_size);
  QM::Quadtree_mesher_2<K> mesher(d, criteria);
  Meshed r;
  r.mesh = mesher.run();
  r.buffer_quads = mesher.buffer_report().first_layer_quads + mesher.buffer_report().second_layer_quads;
  EXPECT_TRUE(qm2_checks::is_conforming(r.mesh));
  EXPECT_TRUE(QM::compute_quality(r.mesh).is_valid());
  return r;
}

TEST(Grid_aligned_domain, a_unit_square_is_squares)
{
  const auto d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 1, 1) });
  for(double max_size : { 0.0, 0.3, 0.1 }) {
    const Meshed m = mesh_of(d, max_size);
    const std::string name = "unit square, max size " + std::to_string(max_size);
    expect_all_right_angles(m.mesh, name);
    EXPECT_EQ(m.buffer_quads, 0u) << name;
    EXPECT_DOUBLE_EQ(mesh_area(m.mesh), 1.0) << name;
    if(max_size > 0) {
      EXPECT_GE(m.mesh.quads.size(), std::size_t(std::ceil(1 / max_size) * std::ceil(1 / max_size))) << name;
    }
  }
}

TEST(Grid_aligned_domain, an_L_shape_and_a_thin_dyadic_rectangle_are_squares)
{
  const std::vector<Point_2> L{ Point_2(0, 0), Point_2(2, 0), Point_2(2, 1), Point_2(1, 1), Point_2(1, 2), Point_2(0, 2) };
  const Meshed l = mesh_of(qm2_test::polygons({ L }));
  expect_all_right_angles(l.mesh, "L");
  EXPECT_DOUBLE_EQ(mesh_area(l.mesh), 3.0);
  const Meshed thin = mesh_of(qm2_test::polygons({ qm2_test::rectangle(0, 0, 1, 1.0 / 64) }));
  expect_all_right_angles(thin.mesh, "1 x 1/64");
  EXPECT_DOUBLE_EQ(mesh_area(thin.mesh), 1.0 / 64);
  EXPECT_LE(QM::compute_quality(thin.mesh).max_aspect_ratio, 1.0 + 1e-12);
}

// A hole on the lattice: no buffer either; where the cells grade, the transitions keep the
// bound.
TEST(Grid_aligned_domain, a_square_with_a_rectangular_hole_needs_no_buffer)
{
  const auto d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 4, 4), qm2_test::rectangle(1, 1, 2, 3) }, { Point_2(1.5, 2) });
  const Meshed m = mesh_of(d);
  EXPECT_EQ(m.buffer_quads, 0u);
  EXPECT_DOUBLE_EQ(mesh_area(m.mesh), 14.0);
  const qm2_checks::Angle_range r = qm2_checks::angle_range(m.mesh);
  EXPECT_GE(r.min, 45.0 - 1e-7);
  EXPECT_LE(r.max, 135.0 + 1e-7);
}

// Axis-parallel but off the lattice (corners at 0.3, or 0.01 apart), or not axis-parallel:
// the buffer stages mesh them, within the bound.
TEST(Grid_aligned_domain, other_domains_get_a_buffer)
{
  const std::vector<std::pair<std::string, QM::Domain_2<K>>> cases{
    { "square off the lattice", qm2_test::polygons({ qm2_test::rectangle(0.3, 0.3, 1.3, 1.3) }) },
    { "1 x 0.01", qm2_test::polygons({ qm2_test::rectangle(0, 0, 1, 0.01) }) },
    { "diamond", qm2_test::polygons({ { Point_2(1, 0), Point_2(2, 1), Point_2(1, 2), Point_2(0, 1) } }) }
  };
  for(const auto& [name, d] : cases) {
    const Meshed m = mesh_of(d);
    EXPECT_GT(m.buffer_quads, 0u) << name;
    const qm2_checks::Angle_range r = qm2_checks::angle_range(m.mesh);
    EXPECT_GE(r.min, 45.0 - 1e-7) << name;
    EXPECT_LE(r.max, 135.0 + 1e-7) << name;
  }
}

} // namespace qm2_test_grid_aligned_domain
