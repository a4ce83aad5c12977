// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The QuadMesherTraits_2 concept is exactly what the code uses (an archetype providing only
// the documented types and functors must compile and mesh), and header hygiene: every header
// has the include guard that spells its path, closed by a comment repeating it.

#include "qm2_mesh_checks.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <type_traits>

namespace qm2_test_traits {

using qm2_test::K;

// Only what doc/Quad_mesher_2/Concepts/QuadMesherTraits_2.h lists.
struct Archetype_traits
{
  typedef K::FT FT;
  typedef K::Point_2 Point_2;
  typedef K::Iso_rectangle_2 Iso_rectangle_2;
  typedef K::Compute_x_2 Compute_x_2;
  typedef K::Compute_y_2 Compute_y_2;
  typedef K::Compute_xmin_2 Compute_xmin_2;
  typedef K::Compute_ymin_2 Compute_ymin_2;
  typedef K::Compute_xmax_2 Compute_xmax_2;
  typedef K::Compute_ymax_2 Compute_ymax_2;
  typedef K::Less_x_2 Less_x_2;
  typedef K::Less_y_2 Less_y_2;
  typedef K::Less_xy_2 Less_xy_2;
  typedef K::Equal_2 Equal_2;
  // for the boundary loops (Domain_loops_2.h)
  typedef K::Segment_2 Segment_2;
  typedef K::Compare_x_2 Compare_x_2;
  typedef K::Orientation_2 Orientation_2;
  typedef K::Collinear_are_ordered_along_line_2 Collinear_are_ordered_along_line_2;
  typedef K::Compute_area_2 Compute_area_2;
  typedef K::Construct_bbox_2 Construct_bbox_2;
  typedef K::Construct_segment_2 Construct_segment_2;
  typedef K::Do_intersect_2 Do_intersect_2;
  // for the buffer-zone clearance
  typedef K::Compare_squared_distance_2 Compare_squared_distance_2;
  typedef K::Construct_point_2 Construct_point_2;
  typedef K::Construct_iso_rectangle_2 Construct_iso_rectangle_2;

  Compute_x_2 compute_x_2_object() const { return K().compute_x_2_object(); }
  Compute_y_2 compute_y_2_object() const { return K().compute_y_2_object(); }
  Compute_xmin_2 compute_xmin_2_object() const { return K().compute_xmin_2_object(); }
  Compute_ymin_2 compute_ymin_2_object() const { return K().compute_ymin_2_object(); }
  Compute_xmax_2 compute_xmax_2_object() const { return K().compute_xmax_2_object(); }
  Compute_ymax_2 compute_ymax_2_object() const { return K().compute_ymax_2_object(); }
  Less_x_2 less_x_2_object() const { return K().less_x_2_object(); }
  Less_y_2 less_y_2_object() const { return K().less_y_2_object(); }
  Less_xy_2 less_xy_2_object() const { return K().less_xy_2_object(); }
  Equal_2 equal_2_object() const { return K().equal_2_object(); }
  Compare_x_2 compare_x_2_object() const { return K().compare_x_2_object(); }
  Orientation_2 orientation_2_object() const { return K().orientation_2_object(); }
  Collinear_are_ordered_along_line_2 collinear_are_ordered_along_line_2_object() const
  {
    return K().collinear_are_ordered_along_line_2_object();
  }
  Compute_area_2 compute_area_2_object() const { return K().compute_area_2_object(); }
  Construct_bbox_2 construct_bbox_2_object() const { return K().construct_bbox_2_object(); }
  Construct_segment_2 construct_segment_2_object() const { return K().construct_segment_2_object(); }
  Do_intersect_2 do_intersect_2_object() const { return K().do_intersect_2_object(); }
  Compare_squared_distance_2 compare_squared_distance_2_object() const
  {
    return K().compare_squared_distance_2_object();
  }
  Construct_point_2 construct_point_2_object() const { return K().construct_point_2_object(); }
  Construct_iso_rectangle_2 construct_iso_rectangle_2_object() const
  {
    return K().construct_iso_rectangle_2_object();
  }
};

TEST(QuadMesherTraits_2, archetype_is_enough_for_the_mesher)
{
  CGAL::Quad_mesher_2::Domain_2<Archetype_traits> d;
  d.points = { K::Point_2(0, 0), K::Point_2(1, 0.5), K::Point_2(0.3, 0.2), K::Point_2(0.31, 0.2) };
  CGAL::Quad_mesher_2::Mesh_criteria_2<Archetype_traits> criteria(0.2);
  CGAL::Quad_mesher_2::Quadtree_mesher_2<Archetype_traits> mesher(d, criteria);
  auto mesh = mesher.run();
  EXPECT_TRUE(qm2_checks::is_conforming(mesh));
  EXPECT_TRUE(mesher.quadtree().is_strongly_balanced());
  // a domain with a boundary loop, through every stage (narrow-region sizing, loop
  // validation, clearance, the buffer layers)
  CGAL::Quad_mesher_2::Domain_2<Archetype_traits> square;
  square.points = { K::Point_2(0, 0), K::Point_2(1, 0), K::Point_2(1, 1), K::Point_2(0, 1) };
  square.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  CGAL::Quad_mesher_2::Quadtree_mesher_2<Archetype_traits> domain_mesher(square, criteria);
  const auto square_mesh = domain_mesher.run(CGAL::Quad_mesher_2::Stage::BUFFER2);
  EXPECT_TRUE(qm2_checks::is_conforming(square_mesh));
  EXPECT_EQ(domain_mesher.loops().loops.size(), 1u);
  ASSERT_TRUE(domain_mesher.quality().has_value());
  EXPECT_TRUE(domain_mesher.quality()->is_valid());
  EXPECT_GE(domain_mesher.quality()->min_angle, 45.0 - 1e-6);
  EXPECT_LE(domain_mesher.quality()->max_angle, 135.0 + 1e-6);
}

// The mesher keeps a reference to its domain: a temporary one must not compile.
TEST(QuadMesherTraits_2, mesher_refuses_a_temporary_domain)
{
  typedef CGAL::Quad_mesher_2::Quadtree_mesher_2<qm2_test::K> Mesher;
  typedef CGAL::Quad_mesher_2::Domain_2<qm2_test::K> Domain;
  static_assert(std::is_constructible<Mesher, const Domain&>::value, "a named domain is taken");
  static_assert(!std::is_constructible<Mesher, Domain&&>::value, "a temporary domain is refused");
  SUCCEED();
}

TEST(Header_hygiene, include_guards_spell_their_paths)
{
  const std::filesystem::path root = std::filesystem::path(QM2_SOURCE_DIR) / "include";
  std::size_t headers = 0;
  for(const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if(entry.path().extension() != ".h")
      continue;
    ++headers;
    std::string rel = std::filesystem::relative(entry.path(), root).string();
    std::string guard;
    for(char c : rel.substr(0, rel.size() - 2))
      guard += (c == '/' ? '_' : char(std::toupper(static_cast<unsigned char>(c))));
    guard += "_H";
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    const std::string s = text.str();
    EXPECT_NE(s.find("#ifndef " + guard + "\n#define " + guard + "\n"), std::string::npos) << rel << " guard " << guard;
    EXPECT_NE(s.find("#endif // " + guard), std::string::npos) << rel;
    EXPECT_NE(s.find("SPDX-License-Identifier:"), std::string::npos) << rel;
    EXPECT_EQ(s.find("std::cout"), std::string::npos) << rel << " prints (no output in include/)";
  }
  EXPECT_GT(headers, 15u);
}

} // namespace qm2_test_traits
