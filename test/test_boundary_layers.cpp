// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Boundary layers (paper §5, Fig. 9): N quads stacked on every wall edge, heights H, HR,
// HR^2, ..., conforming with the rest of the mesh, which keeps its [45°, 135°] bound; fans
// around sharp outward corners; stacks thinned where walls face each other closely.

#include "qm2_mesh_checks.h"
#include "qm2_test_domains.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Boundary_layer_mesher_2.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace qm2_test_boundary_layers {

using qm2_test::K;
using qm2_test::Point_2;
namespace QM = CGAL::Quad_mesher_2;
typedef QM::Quad_mesh_2<Point_2> Mesh;

struct Layered
{
  Mesh mesh;
  QM::Boundary_layer_report report;
};

Layered mesh_with_layers(const QM::Domain_2<K>& d, int n, double h, double r, std::vector<int> walls = {})
{
  QM::Boundary_layer_mesher_2<K> mesher(d, QM::Mesh_criteria_2<K>(), QM::Boundary_layer_criteria_2(n, h, r, walls));
  Layered l;
  l.mesh = mesher.run();
  l.report = mesher.report();
  return l;
}

// The first layer's height over each wall edge, measured on the mesh alone: the distance of
// the other two corners of the edge's quad from the edge's line, as the verifier would.
std::vector<double> first_heights(const Mesh& m, const std::vector<int>& wall_markers)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> quad_of;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) quad_of[{ m.quads[q][c], m.quads[q][(c + 1) % 4] }] = q;
  std::vector<double> heights;
  for(const auto& e : m.boundary_edges) {
    if(std::find(wall_markers.begin(), wall_markers.end(), e.marker) == wall_markers.end()) continue;
    const auto& quad = m.quads[quad_of.at({ e.v0, e.v1 })];
    const double ax = CGAL::to_double(m.points[e.v0].x()), ay = CGAL::to_double(m.points[e.v0].y());
    const double bx = CGAL::to_double(m.points[e.v1].x()), by = CGAL::to_double(m.points[e.v1].y());
    const double len = std::hypot(bx - ax, by - ay);
    for(std::size_t v : quad) {
      if(v == e.v0 || v == e.v1) continue;
      const double px = CGAL::to_double(m.points[v].x()), py = CGAL::to_double(m.points[v].y());
      heights.push_back(((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / len);
    }
  }
  return heights;
}

// the mesh is conforming and valid, its layers' angles within [low, 180° - low] and the
// rest's within [45°, 135°]
void expect_valid_with_angles(const Layered& l, double low, const std::string& where = "")
{
  EXPECT_TRUE(qm2_checks::is_conforming(l.mesh)) << where;
  EXPECT_TRUE(QM::compute_quality(l.mesh).is_valid()) << where;
  EXPECT_GE(l.report.layer_min_angle, low) << where;
  EXPECT_LE(l.report.layer_max_angle, 180 - low) << where;
  EXPECT_GE(l.report.outer_min_angle, 45 - 1e-6) << where;
  EXPECT_LE(l.report.outer_max_angle, 135 + 1e-6) << where;
}

// the share of `values` within `tolerance` (relative) of `target`
double share_near(const std::vector<double>& values, double target, double tolerance)
{
  std::size_t near = 0;
  for(double v : values) near += std::abs(v - target) <= tolerance * target ? 1 : 0;
  return values.empty() ? 0.0 : double(near) / values.size();
}

TEST(Boundary_layers, a_flat_wall_gets_every_layer_at_its_height)
{
  // a plate whose outer loop is the wall (no holes): 90° corners, mitred
  const QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 4, 1) });
  const double H = 0.005, R = 1.2;
  const Layered l = mesh_with_layers(d, 8, H, R);
  expect_valid_with_angles(l, 45 - 1e-6); // the mitres at the corners: 45° and 135°
  const std::vector<double> h = first_heights(l.mesh, { 1 });
  ASSERT_FALSE(h.empty());
  EXPECT_EQ(share_near(h, H, 0.01), 1.0); // every wall edge, the corners' too
  ASSERT_EQ(l.report.walls.size(), 1u);
  const auto& w = l.report.walls[0];
  EXPECT_NEAR(w.first_height_min, H, 0.01 * H);
  EXPECT_NEAR(w.first_height_max, H, 0.01 * H);
  EXPECT_NEAR(w.growth_min, R, 0.02 * R);
  EXPECT_NEAR(w.growth_max, R, 0.02 * R);
  EXPECT_NEAR(w.thickness_min, QM::Boundary_layer_criteria_2(8, H, R).thickness(), 1e-9);
  EXPECT_EQ(w.thinned_bands, 0u);
  EXPECT_EQ(l.report.layer_quads, 8 * w.bands);
}

TEST(Boundary_layers, a_cylinder_in_a_far_field_keeps_its_angles)
{
  const QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-5, -5, 5, 5), qm2_test::disc(0, 0, 0.5, 64) },
                                               { Point_2(0, 0) });
  for(int n : { 1, 5, 40 }) {
    const double H = 0.002 / n, R = 1.15;
    const Layered l = mesh_with_layers(d, n, H, R); // walls: the hole's loop, by default
    expect_valid_with_angles(l, 80, std::to_string(n)); // near rectangles
    EXPECT_EQ(share_near(first_heights(l.mesh, { 2 }), H, 0.01), 1.0) << n;
    ASSERT_EQ(l.report.walls.size(), 1u);
    EXPECT_EQ(l.report.walls[0].marker, 2);
    EXPECT_EQ(l.report.walls[0].fans, 0u); // turns of 5.6°: no corner
    EXPECT_EQ(l.report.layer_quads, std::size_t(n) * l.report.walls[0].bands) << n;
    if(n > 1) {
      EXPECT_NEAR(l.report.walls[0].growth_min, R, 0.02 * R) << n;
      EXPECT_NEAR(l.report.walls[0].growth_max, R, 0.02 * R) << n;
    }
  }
}

TEST(Boundary_layers, a_growth_of_one_gives_equal_layers)
{
  const QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-5, -5, 5, 5), qm2_test::disc(0, 0, 0.5, 48) },
                                               { Point_2(0, 0) });
  const Layered l = mesh_with_layers(d, 6, 0.003, 1.0);
  EXPECT_TRUE(QM::compute_quality(l.mesh).is_valid());
  EXPECT_NEAR(l.report.walls[0].growth_min, 1.0, 0.02);
  EXPECT_NEAR(l.report.walls[0].growth_max, 1.0, 0.02);
  EXPECT_NEAR(l.report.walls[0].thickness_max, 0.018, 0.018 * 0.01);
}

TEST(Boundary_layers, reflex_corners_of_the_domain_get_fans)
{
  // a square body in a far field: four 270° corners of the domain, each a fan of kites
  const QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-5, -5, 5, 5), qm2_test::rectangle(0, 0, 1, 1) },
                                               { Point_2(0.5, 0.5) });
  const Layered l = mesh_with_layers(d, 5, 0.01, 1.2);
  expect_valid_with_angles(l, 22.5);
  EXPECT_EQ(l.report.walls[0].fans, 4u);
  // off the corners, every wall edge has its first height
  EXPECT_NEAR(l.report.walls[0].first_height_min, 0.01, 1e-4);
  EXPECT_NEAR(l.report.walls[0].first_height_max, 0.01, 1e-4);
}

// With one layer a fan has only its kites, and the outer mesh put 6 to 10 nodes on the arc of
// a 270° corner: kites with tips of 15° to 30° (angles 14.6° to 168.8° for a square body). One
// layer mitres outward turns up to 135° instead: 45° and 135° at a right angle.
TEST(Boundary_layers, one_layer_mitres_right_angles_instead_of_fanning_them)
{
  const QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-10, -10, 10, 10), qm2_test::rectangle(0, 0, 1, 1) },
                                               { Point_2(0.5, 0.5) });
  for(double h : { 1e-2, 1e-3, 1e-5 }) {
    const Layered l = mesh_with_layers(d, 1, h, 1.2);
    expect_valid_with_angles(l, 45 - 1e-6, std::to_string(h));
    EXPECT_EQ(l.report.walls[0].fans, 0u) << h;
    EXPECT_NEAR(l.report.walls[0].first_height_min, h, 0.01 * h) << h;
    EXPECT_NEAR(l.report.walls[0].first_height_max, h, 0.01 * h) << h;
  }
}

TEST(Boundary_layers, a_sharp_trailing_edge_gets_a_valid_fan)
{
  // a wedge whose tip turns the domain's boundary by 169° (a 349° corner of the domain)
  const QM::Domain_2<K> d =
    qm2_test::polygons({ qm2_test::rectangle(-10, -10, 10, 10),
                         { Point_2(0, 0.05), Point_2(0, -0.05), Point_2(1, 0), Point_2(0.5, 0.025) } },
                       { Point_2(0.2, 0) });
  const Layered l = mesh_with_layers(d, 10, 1e-4, 1.2);
  EXPECT_TRUE(qm2_checks::is_conforming(l.mesh));
  EXPECT_TRUE(QM::compute_quality(l.mesh).is_valid());
  EXPECT_GE(l.report.walls[0].fans, 1u);
  EXPECT_GE(l.report.outer_min_angle, 45 - 1e-6);
  EXPECT_LE(l.report.outer_max_angle, 135 + 1e-6);
}

TEST(Boundary_layers, a_slot_narrower_than_two_stacks_is_thinned_not_overlapped)
{
  // two bodies 0.01 apart; a stack of 0.026 on either side would overlap
  const QM::Domain_2<K> d = qm2_test::polygons(
    { qm2_test::rectangle(-5, -5, 5, 5), qm2_test::rectangle(0, 0, 1, 1), qm2_test::rectangle(0, 1.01, 1, 2) },
    { Point_2(0.5, 0.5), Point_2(0.5, 1.5) });
  const QM::Boundary_layer_criteria_2 layers(10, 0.001, 1.2);
  ASSERT_GT(2 * layers.thickness(), 0.01);
  const Layered l = mesh_with_layers(d, 10, 0.001, 1.2);
  EXPECT_TRUE(qm2_checks::is_conforming(l.mesh));
  EXPECT_TRUE(QM::compute_quality(l.mesh).is_valid());
  std::size_t thinned = 0;
  double thinnest = 1;
  for(const auto& w : l.report.walls) {
    thinned += w.thinned_bands;
    thinnest = (std::min)(thinnest, w.thinnest_ratio);
  }
  EXPECT_GT(thinned, 0u);
  EXPECT_LE(thinnest * layers.thickness(), 0.01 / 3 + 1e-9); // a third of the gap at most
  EXPECT_GE(l.report.outer_min_angle, 45 - 1e-6);
  EXPECT_LE(l.report.outer_max_angle, 135 + 1e-6);
}

// A notch of 8.2° into a body: the mitre of its tip lies 14 stack thicknesses up the notch.
// Rays slanted from each wall point to the same fraction of the offset made every band along
// the notch's sides a sliver (a random far field's 1.4° notch: 15369 quads under 22.5°);
// with rays square to the walls only the two bands at the tip keep the tip's half angle.
TEST(Boundary_layers, a_sharp_notch_skews_only_the_bands_at_its_tip)
{
  const QM::Domain_2<K> d = qm2_test::polygons(
    { qm2_test::rectangle(-10, -10, 10, 10),
      { Point_2(0, 0), Point_2(0, 1), Point_2(0.45, 1), Point_2(0.5, 0.3), Point_2(0.55, 1), Point_2(1, 1),
        Point_2(1, 0) } },
    { Point_2(0.2, 0.5) });
  for(double h : { 1e-3, 1e-4 }) {
    const Layered l = mesh_with_layers(d, 10, h, 1.2);
    EXPECT_TRUE(qm2_checks::is_conforming(l.mesh)) << h;
    EXPECT_TRUE(QM::compute_quality(l.mesh).is_valid()) << h;
    std::size_t skewed = 0;
    for(std::size_t q = 0; q < l.mesh.quads.size(); ++q) {
      bool out = false;
      for(int c = 0; c < 4; ++c) {
        const double a = qm2_checks::corner_angle(l.mesh, q, c);
        out = out || a < 22.5 || a > 157.5;
      }
      skewed += out ? 1 : 0;
    }
    EXPECT_LE(skewed, 2u * 10 + 2) << h;
    // the offset's own tip keeps the notch's angle
    EXPECT_GE(l.report.outer_min_angle, 2 * std::atan(0.05 / 0.7) * 180 / M_PI - 1e-6) << h;
    EXPECT_LE(l.report.outer_max_angle, 135 + 1e-6) << h;
  }
}

// A needle of 0.34° whose sides are closer than the validity check tells apart (1e-9 of the
// diagonal) within 1e-5 of its tip: feet there made a node on the other side (a hanging node,
// an invalid mesh with a stack 2e-5 thick) or, stood on the tip, fan rays along the sides
// (angles of 2°). The tip's stack now reaches beyond that stretch.
TEST(Boundary_layers, a_needle_tip_thicker_than_its_stack_keeps_the_mesh_valid)
{
  const QM::Domain_2<K> d =
    qm2_test::polygons({ qm2_test::rectangle(-10, -10, 10, 10), { Point_2(0, -0.003), Point_2(1, 0), Point_2(0, 0.003) } },
                       { Point_2(0.2, 0) });
  for(double h : { 1e-5, 1e-6 }) {
    const Layered l = mesh_with_layers(d, 2, h, 1.0);
    expect_valid_with_angles(l, 22.5, std::to_string(h));
    EXPECT_NEAR(l.report.walls[0].first_height_min, h, 0.01 * h) << h; // away from the tip
  }
}

// The cases: 20 layers from 1e-4 at 1.15 on the shared NACA 0012 (a 341° trailing
// edge) and 30P-30N (cusps of 352°, a slot thinner than two stacks). The slat cusp's fan
// runs over rays the outer mesh crowds at one end; before the stacks were smoothed its
// 1-to-3 steps there made angles of 11° and 169°.
TEST(Boundary_layers, the_shared_air_foils_keep_every_layer_angle_within_22_5_and_157_5)
{
  const std::pair<const char*, std::vector<int>> cases[] = { { "/naca0012/naca0012_sharp.poly", { 2 } },
                                                             { "/airfoil_30p30n/airfoil_30p30n.poly", { 2, 3, 4 } } };
  for(const auto& [file, walls] : cases) {
    QM::Domain_2<K> d;
    std::string error;
    ASSERT_TRUE(QM::IO::read_poly(std::string(QM2_SHARED_DATA_DIR) + file, d, &error)) << file << ": " << error;
    const Layered l = mesh_with_layers(d, 20, 1e-4, 1.15, walls);
    expect_valid_with_angles(l, 22.5, file);
    for(const auto& w : l.report.walls) {
      EXPECT_NEAR(w.first_height_min, 1e-4, 1e-6) << file << " marker " << w.marker;
      EXPECT_NEAR(w.first_height_max, 1e-4, 1e-6) << file << " marker " << w.marker;
      EXPECT_NEAR(w.growth_min, 1.15, 0.02 * 1.15) << file << " marker " << w.marker;
      EXPECT_NEAR(w.growth_max, 1.15, 0.02 * 1.15) << file << " marker " << w.marker;
    }
  }
}

// A disc in a far field, the field's regional attribute with a maximum area: the cells beyond
// the layers keep to it, every quad is in the field's region; an attribute within the
// layers is an error that says so.
TEST(Boundary_layers, regional_attributes_reach_the_cells_beyond_the_layers)
{
  QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-2, -2, 2, 2), qm2_test::disc(0, 0, 0.5, 32) },
                                         { Point_2(0, 0) });
  const double max_area = 0.01;
  d.region_attributes = { { Point_2(1.5, 1.5), 4, max_area } };
  const Layered l = mesh_with_layers(d, 4, 1e-3, 1.2);
  expect_valid_with_angles(l, 20);
  ASSERT_EQ(l.mesh.regions.size(), 1u);
  EXPECT_EQ(l.mesh.regions[0].tag, 4);
  EXPECT_EQ(l.mesh.quad_regions, std::vector<std::size_t>(l.mesh.quads.size(), 0));
  std::size_t above = 0;
  for(const auto& q : l.mesh.quads) {
    const double a = CGAL::to_double(CGAL::area(l.mesh.points[q[0]], l.mesh.points[q[1]], l.mesh.points[q[2]])
                                     + CGAL::area(l.mesh.points[q[0]], l.mesh.points[q[2]], l.mesh.points[q[3]]));
    above += a > max_area ? 1 : 0;
  }
  EXPECT_EQ(above, 0u); // 16 / 0.01: without the bound the far field's quads are far larger
  d.region_attributes[0].point = Point_2(0.5005, 0);
  d.region_attribute_labels = { "1 (line 70)" };
  try {
    mesh_with_layers(d, 4, 1e-3, 1.2);
    ADD_FAILURE() << "an attribute within the layers was taken";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("regional attribute 1 (line 70) (it must lie beyond the boundary layers)"),
              std::string::npos) << e.what();
  }
}

// An interface has the domain on both sides: the holes that are walls by default leave it
// out, and wall markers on it are refused by name.
TEST(Boundary_layers, an_interface_is_no_wall)
{
  QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-5, -5, 5, 5), qm2_test::disc(0, 0, 0.5, 48),
                                           qm2_test::rectangle(2, 2, 3, 3) },
                                         { Point_2(2.5, 2.5) });
  d.segment_markers.assign(d.segments.size(), 2); // the disc's
  std::fill(d.segment_markers.begin(), d.segment_markers.begin() + 4, 1);
  std::fill(d.segment_markers.end() - 4, d.segment_markers.end(), 3);
  const Layered l = mesh_with_layers(d, 3, 1e-3, 1.2);
  expect_valid_with_angles(l, 45); // fans at the square's corners
  ASSERT_EQ(l.report.walls.size(), 1u);
  EXPECT_EQ(l.report.walls[0].marker, 3);
  ASSERT_EQ(l.mesh.regions.size(), 2u);
  for(std::size_t q = 0; q < l.mesh.quads.size(); ++q) { // the disc's quads are region 1
    const auto& v = l.mesh.quads[q];
    const Point_2 centre = CGAL::centroid(l.mesh.points[v[0]], l.mesh.points[v[1]], l.mesh.points[v[2]], l.mesh.points[v[3]]);
    EXPECT_EQ(l.mesh.quad_regions[q], CGAL::to_double(CGAL::squared_distance(centre, Point_2(0, 0))) < 0.25 ? 1u : 0u) << q;
  }
  try {
    mesh_with_layers(d, 3, 1e-3, 1.2, { 2 });
    ADD_FAILURE() << "an interface was taken for a wall";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("is an interface between two regions, not a wall"), std::string::npos) << e.what();
  }
}

// A crack has the domain on both sides too: the hole is the wall, the crack keeps its
// segments (the offset domain takes them once, along the crack), and wall markers on it are
// refused by name.
TEST(Boundary_layers, a_crack_is_no_wall)
{
  QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(0, 0, 10, 10), qm2_test::rectangle(4, 4, 6, 6) },
                                         { Point_2(5, 5) });
  d.points.insert(d.points.end(), { Point_2(1, 1), Point_2(3, 1.5), Point_2(2.5, 3) });
  d.segments.push_back({ 8, 9 });
  d.segments.push_back({ 9, 10 });
  d.segment_markers = { 1, 1, 1, 1, 2, 2, 2, 2, 3, 3 };
  const Layered l = mesh_with_layers(d, 3, 1e-2, 1.2, { 2 });
  expect_valid_with_angles(l, 45);
  ASSERT_EQ(l.report.walls.size(), 1u);
  EXPECT_EQ(l.report.walls[0].marker, 2);
  try {
    mesh_with_layers(d, 3, 1e-2, 1.2, { 3 });
    ADD_FAILURE() << "a crack was taken for a wall";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("is a crack, not a wall"), std::string::npos) << e.what();
  }
}

// Junctions are not taken yet: the error names the vertex.
TEST(Boundary_layers, a_junction_is_named_as_not_taken_yet)
{
  QM::Domain_2<K> d = qm2_test::polygons({ { Point_2(0, 0), Point_2(5, 0), Point_2(10, 0), Point_2(10, 10), Point_2(5, 10),
                                             Point_2(0, 10) },
                                           qm2_test::rectangle(2, 4, 3, 6) });
  d.segments.push_back({ 1, 4 });
  d.holes = { Point_2(2.5, 5) };
  d.segment_markers.assign(d.segments.size(), 1);
  for(std::size_t s = 6; s < 10; ++s) d.segment_markers[s] = 2;
  try {
    mesh_with_layers(d, 3, 1e-2, 1.2, { 2 });
    ADD_FAILURE() << "no Meshing_error";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("vertex 1 (5, 0) joins 3 segments: boundary layers do not take junctions"),
              std::string::npos)
      << e.what();
  }
}

TEST(Boundary_layers, bad_values_are_clear_errors)
{
  EXPECT_THROW(QM::Boundary_layer_criteria_2(0, 1e-3, 1.2), QM::Meshing_error);
  EXPECT_THROW(QM::Boundary_layer_criteria_2(5, 0, 1.2), QM::Meshing_error);
  EXPECT_THROW(QM::Boundary_layer_criteria_2(5, -1e-3, 1.2), QM::Meshing_error);
  EXPECT_THROW(QM::Boundary_layer_criteria_2(5, 1e-3, 0.9), QM::Meshing_error);
  EXPECT_THROW(QM::Boundary_layer_criteria_2(5, std::nan(""), 1.2), QM::Meshing_error);
  EXPECT_THROW(QM::Boundary_layer_criteria_2(1000, 1, 3), QM::Meshing_error); // 3^1000: too thick
  QM::Domain_2<K> d = qm2_test::polygons({ qm2_test::rectangle(-5, -5, 5, 5), qm2_test::disc(0, 0, 0.5, 32) },
                                         { Point_2(0, 0) });
  EXPECT_THROW(mesh_with_layers(d, 5, 1e-3, 1.2, { 7 }), QM::Meshing_error); // no segment has 7
  d.segment_markers.assign(d.segments.size(), 3);
  d.segment_markers[5] = 4;
  try {
    mesh_with_layers(d, 5, 1e-3, 1.2, { 4 }); // one segment of the disc's loop
    ADD_FAILURE() << "a loop only partly a wall was taken";
  } catch(const QM::Meshing_error& e) {
    EXPECT_NE(std::string(e.what()).find("only partly a wall"), std::string::npos) << e.what();
  }
  QM::Domain_2<K> cloud;
  cloud.points = { Point_2(0, 0), Point_2(1, 1) };
  EXPECT_THROW(mesh_with_layers(cloud, 5, 1e-3, 1.2), QM::Meshing_error);
}

} // namespace qm2_test_boundary_layers
