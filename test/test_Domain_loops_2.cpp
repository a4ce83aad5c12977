// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests of CGAL/Quad_mesher_2/Domain_loops_2.h: loops, orientation, nesting, hole semantics,
// isolated points, area, and every validation error with the place it names.

#include "qm2_test_kernel.h"
#include "qm2_time_bounds.h"

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <random>
#include <set>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace qm2_test_loops {

using K = qm2_test::K;
using Point_2 = K::Point_2;
using Domain = CGAL::Quad_mesher_2::Domain_2<K>;
using Loops = CGAL::Quad_mesher_2::Domain_loops_2<K>;
using CGAL::Quad_mesher_2::Meshing_error;
using CGAL::Quad_mesher_2::extract_loops;
namespace fs = std::filesystem;

inline Domain load(const std::string& file)
{
  Domain d;
  std::string err;
  EXPECT_TRUE(CGAL::Quad_mesher_2::IO::read_poly(file, d, &err)) << file << ": " << err;
  return d;
}

/// Adds a closed loop through the given coordinates (in the given order) to `d`.
inline void add_loop(Domain& d, std::initializer_list<std::pair<double, double> > xy)
{
  const std::size_t first = d.points.size();
  for(const auto& p : xy) d.points.push_back(Point_2(p.first, p.second));
  const std::size_t n = xy.size();
  for(std::size_t i = 0; i < n; ++i) d.segments.push_back({first + i, first + (i + 1) % n});
}

inline void add_square(Domain& d, double x0, double y0, double x1, double y1, bool ccw = true)
{
  if(ccw) add_loop(d, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}});
  else add_loop(d, {{x0, y0}, {x0, y1}, {x1, y1}, {x1, y0}});
}

/// The message of the Meshing_error that `extract_loops(d)` throws ("" if none).
inline std::string error_of(const Domain& d)
{
  try {
    extract_loops(d);
  } catch(const Meshing_error& e) {
    return e.what();
  }
  return "";
}

#define QM2_EXPECT_ERROR(d, ...)                                                                   \
  do {                                                                                             \
    const std::string qm2_msg = qm2_test_loops::error_of(d);                                       \
    EXPECT_FALSE(qm2_msg.empty()) << "no Meshing_error";                                           \
    for(const char* qm2_part : {__VA_ARGS__})                                                      \
      EXPECT_NE(qm2_msg.find(qm2_part), std::string::npos) << "message: " << qm2_msg << "\nlacks: " << qm2_part; \
  } while(false)

/// Expects `extract_loops(d)` to throw a message holding every part of `parts`.
inline void expect_error(const Domain& d, const std::vector<std::string>& parts)
{
  const std::string msg = error_of(d);
  EXPECT_FALSE(msg.empty()) << "no Meshing_error";
  for(const std::string& part : parts)
    EXPECT_NE(msg.find(part), std::string::npos) << "message: " << msg << "\nlacks: " << part;
}

/// Every edge twin is the same segment the other way round, and twins are mutual.
inline void expect_edge_twins_consistent(const Loops& loops)
{
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& v = loops.loops[l].vertices;
    ASSERT_EQ(loops.loops[l].edge_twins.size(), v.size());
    for(std::size_t k = 0; k < v.size(); ++k) {
      const auto t = loops.loops[l].edge_twins[k];
      if(t[0] == std::size_t(-1)) continue;
      ASSERT_LT(t[0], loops.loops.size());
      const auto& w = loops.loops[t[0]].vertices;
      ASSERT_LT(t[1], w.size());
      EXPECT_EQ(w[t[1]], v[(k + 1) % v.size()]) << "loop " << l << " edge " << k;
      EXPECT_EQ(w[(t[1] + 1) % w.size()], v[k]) << "loop " << l << " edge " << k;
      EXPECT_EQ(loops.loops[t[0]].edge_twins[t[1]], (std::array<std::size_t, 2>{ l, k }));
    }
  }
}

/// the number of loop edges with a twin
inline std::size_t twinned_edges(const Loops& loops)
{
  std::size_t n = 0;
  for(const auto& loop : loops.loops)
    for(const auto& t : loop.edge_twins) n += t[0] != std::size_t(-1);
  return n;
}

/// Independent check: the domain is on the left of each loop, i.e. its polygon is
/// counterclockwise iff the loop is outer; the first vertex is kept; depths are consistent.
inline void expect_domain_on_left(const Domain& d, const Loops& loops)
{
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& loop = loops.loops[l];
    const CGAL::Polygon_2<K> poly = CGAL::Quad_mesher_2::loop_polygon_2(d, loop);
    ASSERT_EQ(poly.size(), loop.vertices.size());
    EXPECT_TRUE(poly.is_simple()) << "loop " << l;
    EXPECT_EQ(poly.orientation(), loop.is_outer ? CGAL::COUNTERCLOCKWISE : CGAL::CLOCKWISE) << "loop " << l;
    if(l > 0) {
      EXPECT_LE(loops.loops[l - 1].depth, loop.depth) << "loops must be sorted outermost first";
    }
  }
}

inline double area_of(const Domain& d, const Loops& loops)
{
  return CGAL::to_double(CGAL::Quad_mesher_2::domain_area(d, loops));
}

// ---- the shared data --------------------------------------------------------------------

struct Check_values
{
  long loops = -1;
  double area = -1;
};

inline Check_values read_check(const fs::path& file)
{
  Check_values c;
  std::ifstream in(file);
  std::string line;
  while(std::getline(in, line)) {
    if(line.rfind("closed loops:", 0) == 0) c.loops = std::stol(line.substr(13));
    const std::size_t a = line.find("; area ");
    if(line.rfind("domain:", 0) == 0 && a != std::string::npos) c.area = std::stod(line.substr(a + 7));
  }
  return c;
}

/// Every .poly in the shared data, with its CHECK file.
inline std::vector<std::pair<fs::path, fs::path> > shared_cases()
{
  std::vector<std::pair<fs::path, fs::path> > out;
  for(const auto& dir : fs::directory_iterator(QM2_SHARED_DATA_DIR)) {
    if(!dir.is_directory()) continue;
    for(const auto& f : fs::directory_iterator(dir.path())) {
      if(f.path().extension() != ".poly") continue;
      const std::string stem = f.path().stem().string();
      const fs::path check = dir.path() / (stem == dir.path().filename().string() ? "CHECK.txt" : "CHECK_" + stem + ".txt");
      out.emplace_back(f.path(), check);
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(Domain_loops_2, SharedDataLoopsOrientationAndArea)
{
  const auto cases = shared_cases();
  std::size_t tested = 0;
  for(const auto& c : cases) {
    const std::string name = c.first.stem().string();
    if(name == "cgal_butterfly" || name == "face") continue;
    SCOPED_TRACE(name);
    const Domain d = load(c.first.string());
    const Check_values check = read_check(c.second);
    ASSERT_GT(check.loops, 0) << c.second;
    ASSERT_GT(check.area, 0) << c.second;
    const Loops loops = extract_loops(d);
    ASSERT_EQ(static_cast<long>(loops.loops.size()), check.loops);
    EXPECT_TRUE(loops.isolated_points.empty());
    // The normalised files list each loop with the domain on its left: every edge of every
    // extracted loop must be a file segment in the same direction.
    std::set<std::pair<std::size_t, std::size_t> > directed;
    for(const auto& s : d.segments) directed.insert({s[0], s[1]});
    std::size_t edges = 0;
    for(const auto& loop : loops.loops)
      for(std::size_t i = 0; i < loop.vertices.size(); ++i, ++edges)
        ASSERT_TRUE(directed.count({loop.vertices[i], loop.vertices[(i + 1) % loop.vertices.size()]}))
            << "edge " << loop.vertices[i] << " -> " << loop.vertices[(i + 1) % loop.vertices.size()];
    EXPECT_EQ(edges, d.segments.size());
    // Outer first: one outer loop then holes (all shared cases are a boundary with holes).
    EXPECT_TRUE(loops.loops[0].is_outer);
    EXPECT_EQ(loops.loops[0].depth, 0);
    for(std::size_t l = 1; l < loops.loops.size(); ++l) {
      EXPECT_FALSE(loops.loops[l].is_outer);
      EXPECT_EQ(loops.loops[l].depth, 1);
    }
    expect_domain_on_left(d, loops);
    EXPECT_NEAR(area_of(d, loops), check.area, 1e-9 * check.area);
    ++tested;
  }
  EXPECT_GE(tested, 13u) << "shared data not found in " << QM2_SHARED_DATA_DIR;
}

TEST(Domain_loops_2, SharedDataWithoutHolePointsUsesNestingParity)
{
  // Dropping the hole points of lake_superior keeps the same loops and area (parity rule).
  Domain d = load(std::string(QM2_SHARED_DATA_DIR) + "/lake_superior/lake_superior.poly");
  const Loops with = extract_loops(d);
  d.holes.clear();
  const Loops without = extract_loops(d);
  ASSERT_EQ(with.loops.size(), without.loops.size());
  for(std::size_t l = 0; l < with.loops.size(); ++l) {
    EXPECT_EQ(with.loops[l].vertices, without.loops[l].vertices);
    EXPECT_EQ(with.loops[l].is_outer, without.loops[l].is_outer);
  }
  EXPECT_NEAR(area_of(d, without), 0.1523024229, 1e-9);
}

TEST(Domain_loops_2, ExampleLakeSuperior)
{
  const Domain d = load(std::string(QM2_DATA_DIR) + "/lake_superior/lake_superior.poly");
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 7u);
  EXPECT_TRUE(loops.loops[0].is_outer);
  expect_domain_on_left(d, loops);
  EXPECT_GT(area_of(d, loops), 0);
}

TEST(Domain_loops_2, the_shared_butterfly_is_six_faces_at_a_junction_and_the_faces_cracks_are_loops)
{
  const std::string base = QM2_SHARED_DATA_DIR;
  // butterfly: 8 segments meet at the origin (vertex 0); the wings and the body are 6 faces
  const Domain butterfly = load(base + "/cgal_butterfly/cgal_butterfly.poly");
  const Loops wings = extract_loops(butterfly);
  ASSERT_EQ(wings.loops.size(), 6u);
  expect_domain_on_left(butterfly, wings);
  expect_edge_twins_consistent(wings);
  for(std::size_t l = 0; l < wings.loops.size(); ++l) {
    EXPECT_TRUE(wings.loops[l].is_outer);
    EXPECT_EQ(wings.loops[l].region, l);
    EXPECT_NE(std::find(wings.loops[l].vertices.begin(), wings.loops[l].vertices.end(), 0u), wings.loops[l].vertices.end());
  }
  EXPECT_EQ(twinned_edges(wings), 2u * 4u); // the body meets each wing along one segment
  // face: an outer loop, three holes and two cracks (single segments), two isolated points
  const Domain face = load(base + "/face/face.poly");
  const Loops loops = extract_loops(face);
  ASSERT_EQ(loops.loops.size(), 6u);
  std::size_t cracks = 0;
  for(std::size_t l = 0; l < loops.loops.size(); ++l)
    if(loops.loops[l].twin == l) {
      ++cracks;
      EXPECT_EQ(loops.loops[l].vertices.size(), 2u);
      EXPECT_FALSE(loops.loops[l].is_outer);
    }
  EXPECT_EQ(cracks, 2u);
  EXPECT_EQ(loops.isolated_points, (std::vector<std::size_t>{ 24, 25 }));
}

// A polyline with free ends is a crack: the hole loop along it and back, enclosing nothing,
// its own twin; it adds no area and leaves the other loops' nesting as it was.
TEST(Domain_loops_2, a_polyline_with_free_ends_is_a_crack_its_own_twin)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  d.points.insert(d.points.end(), { Point_2(2, 2), Point_2(5, 5), Point_2(8, 4), Point_2(7, 8) }); // 4 .. 7
  d.segments.insert(d.segments.end(), { { 5, 6 }, { 4, 5 }, { 7, 6 } }); // in no order
  d.points.insert(d.points.end(), { Point_2(1, 8), Point_2(3, 9) }); // 8, 9: one segment
  d.segments.push_back({ 9, 8 });
  add_square(d, 4, 0.5, 6, 2.5); // a hole below the polyline, with a hole point
  d.holes.push_back(Point_2(5, 1));
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  EXPECT_EQ(loops.loops[0].twin, std::size_t(-1));
  // along the polyline from an end (found from its lowest segment) and back
  EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{ 4, 5, 6, 7, 6, 5 }));
  EXPECT_EQ(loops.loops[2].vertices, (std::vector<std::size_t>{ 9, 8 }));
  for(std::size_t l : { 1u, 2u }) {
    EXPECT_EQ(loops.loops[l].twin, l);
    EXPECT_FALSE(loops.loops[l].is_outer);
    EXPECT_EQ(loops.loops[l].region, 0u);
    EXPECT_EQ(loops.loops[l].depth, 1);
  }
  EXPECT_FALSE(loops.loops[3].is_outer);
  EXPECT_EQ(loops.loops[3].twin, std::size_t(-1));
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 100 - 4);
  // a crack's edges take their segments' markers, one number for the loop by default
  const std::vector<std::vector<int>> markers = CGAL::Quad_mesher_2::internal::loop_edge_markers(d, loops);
  EXPECT_EQ(markers[1], std::vector<int>(6, 2));
  EXPECT_EQ(markers[2], std::vector<int>(2, 3));
  EXPECT_EQ(markers[3], std::vector<int>(4, 4));
}

TEST(Domain_loops_2, a_crack_outside_the_domain_is_an_error_naming_it)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 2, 2, 8, 8);
  d.holes.push_back(Point_2(3, 3));
  d.points.insert(d.points.end(), { Point_2(4, 4), Point_2(6, 5) });
  d.segments.push_back({ 8, 9 });
  QM2_EXPECT_ERROR(d, "the open polyline of 1 segment from vertex 8 (4, 4) to vertex 9 (6, 5) (segment 8) lies inside",
                   "which bounds a hole there: a polyline with free ends is a crack, which must lie in the domain");
  Domain crossing;
  add_square(crossing, 0, 0, 10, 10);
  crossing.points.insert(crossing.points.end(), { Point_2(5, 5), Point_2(12, 5) });
  crossing.segments.push_back({ 4, 5 });
  QM2_EXPECT_ERROR(crossing, "cross");
}

TEST(Domain_loops_2, BahamasTiming)
{
  const Domain d = load(std::string(QM2_SHARED_DATA_DIR) + "/bahamas_islands/bahamas_islands.poly");
  const auto t0 = std::chrono::steady_clock::now();
  const Loops loops = extract_loops(d);
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(loops.loops.size(), 277u);
  std::cout << "[ timing   ] extract_loops on bahamas_islands (" << d.points.size() << " vertices): " << ms << " ms"
            << std::endl;
}

TEST(Domain_loops_2, ManySegmentsIsNotQuadratic)
{
  // A box with 200 x 200 square holes: 160004 segments. Testing all pairs (1.3e10) would take
  // far longer than the limit; the bounding-box hierarchy takes about a second.
  Domain d;
  const int n = 200;
  add_square(d, 0, 0, 3 * n + 1, 3 * n + 1);
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) {
      add_square(d, 3 * i + 1, 3 * j + 1, 3 * i + 3, 3 * j + 3, false);
      d.holes.push_back(Point_2(3 * i + 2, 3 * j + 2));
    }
  const auto t0 = std::chrono::steady_clock::now();
  const Loops loops = extract_loops(d);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(loops.loops.size(), static_cast<std::size_t>(n * n + 1));
  EXPECT_DOUBLE_EQ(area_of(d, loops), (3.0 * n + 1) * (3.0 * n + 1) - 4.0 * n * n);
  EXPECT_LT(s, qm2_test::time_bound(8.0));
  std::cout << "[ timing   ] extract_loops on " << d.segments.size() << " segments: " << s << " s" << std::endl;
}

// ---- hand-made cases ----------------------------------------------------------------------

TEST(Domain_loops_2, SquareWithSquareHoleWithoutHolePoint)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  add_square(d, 1, 1, 3, 3);  // CCW in the input: must come out CW
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  EXPECT_TRUE(loops.loops[0].is_outer);
  EXPECT_EQ(loops.loops[0].depth, 0);
  EXPECT_EQ(loops.loops[0].vertices, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_FALSE(loops.loops[1].is_outer);
  EXPECT_EQ(loops.loops[1].depth, 1);
  EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{4, 7, 6, 5}));
  expect_domain_on_left(d, loops);
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 12);
}

TEST(Domain_loops_2, SquareWithSquareHoleWithHolePoint)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  add_square(d, 1, 1, 3, 3);
  d.holes.push_back(Point_2(2, 2));
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  EXPECT_TRUE(loops.loops[0].is_outer);
  EXPECT_FALSE(loops.loops[1].is_outer);
  EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{4, 7, 6, 5}));
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 12);
}

TEST(Domain_loops_2, with_hole_points_an_unmarked_inner_loop_is_an_interface_listed_twice)
{
  // Triangle's rule: with hole points, only marked faces are holes. The second inner square
  // has no hole point: it bounds a region of its own, inside the land around it.
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 1, 1, 3, 3);
  add_square(d, 5, 5, 7, 7);
  d.holes.push_back(Point_2(2, 2));
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  const std::size_t none = std::size_t(-1);
  EXPECT_EQ(loops.loops[0].twin, none);
  EXPECT_EQ(loops.loops[1].twin, none); // the hole
  EXPECT_FALSE(loops.loops[1].is_outer);
  // the interface: the outer loop of the inner region, then its twin, a hole of the land
  EXPECT_TRUE(loops.loops[2].is_outer);
  EXPECT_EQ(loops.loops[2].region, 1u);
  EXPECT_EQ(loops.loops[2].vertices, (std::vector<std::size_t>{ 8, 9, 10, 11 }));
  EXPECT_EQ(loops.loops[2].twin, 3u);
  EXPECT_FALSE(loops.loops[3].is_outer);
  EXPECT_EQ(loops.loops[3].region, 0u);
  EXPECT_EQ(loops.loops[3].vertices, (std::vector<std::size_t>{ 8, 11, 10, 9 }));
  EXPECT_EQ(loops.loops[3].twin, 2u);
  EXPECT_EQ(loops.loops[2].depth, loops.loops[3].depth);
  expect_domain_on_left(d, loops);
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 100 - 4);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 0), 100 - 4 - 4);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 1), 4);
}

// every_hole_marked: no hole point means no hole, so the inner square is an interface, not
// the hole depth parity would make it
TEST(Domain_loops_2, with_every_hole_marked_and_no_hole_point_an_inner_loop_is_an_interface)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 1, 1, 3, 3);
  d.every_hole_marked = true;
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 3u);
  EXPECT_TRUE(loops.loops[1].is_outer);
  EXPECT_EQ(loops.loops[1].region, 1u);
  EXPECT_EQ(loops.loops[1].twin, 2u);
  EXPECT_FALSE(loops.loops[2].is_outer);
  EXPECT_EQ(loops.loops[2].region, 0u);
  expect_domain_on_left(d, loops);
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 100);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 1), 4);
}

TEST(Domain_loops_2, IslandInHole)
{
  for(int with_hole_point = 0; with_hole_point < 2; ++with_hole_point) {
    SCOPED_TRACE(with_hole_point);
    Domain d;
    add_square(d, 2, 2, 8, 8, false);   // hole, listed first and CW
    add_square(d, 4, 4, 6, 6, false);   // island, CW in the input
    add_square(d, 0, 0, 10, 10, false); // outer, CW in the input
    if(with_hole_point) d.holes.push_back(Point_2(3, 3));
    d.points.push_back(Point_2(5, 5));  // isolated point on the island
    d.points.push_back(Point_2(1, 9));  // isolated point in the outer ring
    const Loops loops = extract_loops(d);
    ASSERT_EQ(loops.loops.size(), 3u);
    EXPECT_EQ(loops.loops[0].vertices, (std::vector<std::size_t>{8, 11, 10, 9}));
    EXPECT_EQ(loops.loops[0].depth, 0);
    EXPECT_TRUE(loops.loops[0].is_outer);
    EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{0, 1, 2, 3}));
    EXPECT_EQ(loops.loops[1].depth, 1);
    EXPECT_FALSE(loops.loops[1].is_outer);
    EXPECT_EQ(loops.loops[2].vertices, (std::vector<std::size_t>{4, 7, 6, 5}));
    EXPECT_EQ(loops.loops[2].depth, 2);
    EXPECT_TRUE(loops.loops[2].is_outer);
    expect_domain_on_left(d, loops);
    EXPECT_EQ(loops.isolated_points, (std::vector<std::size_t>{12, 13}));
    EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 100 - 36 + 4);
  }
}

TEST(Domain_loops_2, RegionsAndTheirAttributes)
{
  Domain d;
  add_square(d, 2, 2, 8, 8);   // hole
  add_square(d, 4, 4, 6, 6);   // island
  add_square(d, 0, 0, 10, 10); // outer
  add_square(d, 20, 0, 30, 10); // a second outer loop, apart
  d.holes.push_back(Point_2(3, 3));
  // the island's attribute given twice alike, the ring's once; the far square has none
  d.region_attributes = { { Point_2(5, 5), 2.5, 0.1 }, { Point_2(1, 1), 7, 0 }, { Point_2(5.5, 4.5), 2.5, 0.1 } };
  Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  // by depth: the two outer squares (regions 0 and 1), the hole (region 0's), the island
  EXPECT_EQ(loops.loops[0].region, 0u);
  EXPECT_EQ(loops.loops[1].region, 1u);
  EXPECT_EQ(loops.loops[2].region, 0u);
  EXPECT_FALSE(loops.loops[2].is_outer);
  EXPECT_EQ(loops.loops[3].region, 2u);
  EXPECT_EQ(loops.region_attributes, (std::vector<std::size_t>{ 1, std::size_t(-1), 0 }));
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 0), 100 - 36);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 2), 4);

  // errors name the attribute: outside the domain (in the hole), on a segment, two different
  // ones in a region, and not finite
  const std::pair<Point_2, std::string> misplaced[] = { { Point_2(3, 3), "lies outside the domain (inside the loop" },
                                                        { Point_2(10, 5), "lies on segment" },
                                                        { Point_2(15, 5), "outside every boundary loop" } };
  for(const auto& [p, what] : misplaced) {
    Domain bad = d;
    bad.region_attributes.push_back({ p, 1, 0 });
    bad.region_attribute_labels = { "1 (line 20)", "2 (line 21)", "3 (line 22)", "4 (line 23)" };
    expect_error(bad, { "regional attribute 4 (line 23) (" + std::to_string(int(CGAL::to_double(p.x()))), what });
  }
  Domain two = d;
  two.region_attributes[2].attribute = 3;
  expect_error(two, { "regional attribute 2 ", "and regional attribute 0 (5, 5)", "lie in the same region", "differ" });
  Domain area = d;
  area.region_attributes[2].max_area = 0.2;
  expect_error(area, { "lie in the same region" });
  Domain nan = d;
  nan.region_attributes[1].attribute = std::numeric_limits<double>::quiet_NaN();
  expect_error(nan, { "regional attribute 1 (1, 1) has attribute nan", "must be finite" });
  // a point cloud has no regions
  Domain cloud;
  cloud.points = { Point_2(0, 0), Point_2(1, 1) };
  cloud.region_attributes = { { Point_2(0.5, 0.5), 1, 0 } };
  expect_error(cloud, { "regional attribute 0 (0.5, 0.5) lies outside every boundary loop", "no regions" });
}

TEST(Domain_loops_2, HoleInIslandInHole)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 1, 1, 9, 9);
  add_square(d, 2, 2, 8, 8);
  add_square(d, 3, 3, 7, 7);
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  for(int l = 0; l < 4; ++l) {
    EXPECT_EQ(loops.loops[l].depth, l);
    EXPECT_EQ(loops.loops[l].is_outer, l % 2 == 0);
  }
  expect_domain_on_left(d, loops);
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 100 - 64 + 36 - 16);
}

TEST(Domain_loops_2, a_hole_point_in_the_island_only_makes_the_loop_around_it_an_interface)
{
  // With a hole point only inside the island, the ring between the hole loop and the island
  // is domain, so the hole loop has the domain on both sides: two regions meet there.
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 2, 2, 8, 8);
  add_square(d, 4, 4, 6, 6);
  d.holes.push_back(Point_2(5, 5));
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  EXPECT_EQ(loops.loops[1].twin, 2u);
  EXPECT_EQ(loops.loops[2].twin, 1u);
  EXPECT_TRUE(loops.loops[1].is_outer);
  EXPECT_FALSE(loops.loops[2].is_outer);
  EXPECT_FALSE(loops.loops[3].is_outer); // the island's loop bounds the hole
  EXPECT_EQ(loops.loops[3].region, loops.loops[1].region);
  EXPECT_EQ(loops.loops[2].region, loops.loops[0].region);
  expect_domain_on_left(d, loops);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, loops.loops[1].region), 36 - 4);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, loops.loops[0].region), 100 - 36);
}

TEST(Domain_loops_2, HolePointsInsideAndAroundALoopIsAnError)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_square(d, 2, 2, 8, 8);
  d.holes.push_back(Point_2(1, 1));
  d.holes.push_back(Point_2(5, 5));
  // The hole point in the domain is the problem, named first (not the loop around it).
  QM2_EXPECT_ERROR(d, "hole point 0 (1, 1) is in no hole: it lies inside the loop of 4 vertices starting at vertex 0 (0, 0)",
                   "and outside the loops within it", "neither side of that loop");
  // In the same place without the hole loop; and in an island, where the hole loop has hole
  // points on both sides (its parent's region is not to blame: nesting puts a hole there).
  Domain plain;
  add_square(plain, 0, 0, 10, 10);
  plain.holes.push_back(Point_2(1, 1));
  QM2_EXPECT_ERROR(plain, "hole point 0 (1, 1) is in no hole: it lies inside the loop of 4 vertices starting at vertex 0 (0, 0) "
                          "(segment 0), in the domain, which would then lie on neither side of that loop");
  Domain island;
  add_square(island, 0, 0, 10, 10);
  add_square(island, 2, 2, 8, 8);
  add_square(island, 4, 4, 6, 6);
  island.holes.push_back(Point_2(3, 3));
  island.holes.push_back(Point_2(5, 5));
  QM2_EXPECT_ERROR(island, "hole point 1 (5, 5) is in no hole: it lies inside the loop of 4 vertices starting at vertex 8 (4, 4)",
                   "neither side of that loop");
  // The hole loop met first (its segments come first): still the hole point in the domain.
  Domain hole_first;
  add_square(hole_first, 2, 2, 8, 8);
  add_square(hole_first, 0, 0, 10, 10);
  hole_first.holes.push_back(Point_2(1, 1));
  hole_first.holes.push_back(Point_2(5, 5));
  QM2_EXPECT_ERROR(hole_first, "hole point 0 (1, 1) is in no hole: it lies inside the loop of 4 vertices starting at vertex 4 (0, 0)",
                   "neither side of the loop of 4 vertices starting at vertex 0 (2, 2)");
}

TEST(Domain_loops_2, ReversedAndShuffledInputIsNormalised)
{
  const Domain orig = load(std::string(QM2_SHARED_DATA_DIR) + "/lake_superior/lake_superior.poly");
  Domain d = orig;
  for(auto& s : d.segments) std::swap(s[0], s[1]);
  std::mt19937 rng(7);
  std::shuffle(d.segments.begin(), d.segments.end(), rng);
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 7u);
  std::set<std::pair<std::size_t, std::size_t> > directed;
  for(const auto& s : orig.segments) directed.insert({s[0], s[1]});
  for(const auto& loop : loops.loops)
    for(std::size_t i = 0; i < loop.vertices.size(); ++i)
      EXPECT_TRUE(directed.count({loop.vertices[i], loop.vertices[(i + 1) % loop.vertices.size()]}));
  expect_domain_on_left(d, loops);
  EXPECT_EQ(d.points.size(), orig.points.size());
  for(std::size_t i = 0; i < d.points.size(); ++i) EXPECT_EQ(d.points[i], orig.points[i]);
  EXPECT_NEAR(area_of(d, loops), 0.1523024229, 1e-9);
  // The first vertex of each loop is the first end of its lowest-index segment.
  std::vector<std::size_t> first_ends;
  for(const auto& loop : loops.loops) first_ends.push_back(loop.vertices[0]);
  EXPECT_NE(std::find(first_ends.begin(), first_ends.end(), d.segments[0][0]), first_ends.end());
}

TEST(Domain_loops_2, PointCloud)
{
  Domain d;
  d.points = {Point_2(0, 0), Point_2(1, 0), Point_2(5, 7)};
  const Loops loops = extract_loops(d);
  EXPECT_TRUE(loops.loops.empty());
  EXPECT_EQ(loops.isolated_points, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 0);
  d.holes.push_back(Point_2(3, 3));
  QM2_EXPECT_ERROR(d, "hole point 0 (3, 3)", "no segments");
}

TEST(Domain_loops_2, IsolatedPoints)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  add_square(d, 1, 1, 3, 3);
  d.points.push_back(Point_2(0.5, 0.5));
  const Loops loops = extract_loops(d);
  EXPECT_EQ(loops.isolated_points, (std::vector<std::size_t>{8}));

  Domain in_hole = d;
  in_hole.points.push_back(Point_2(2, 2.5));
  QM2_EXPECT_ERROR(in_hole, "point 9 (2, 2.5)", "outside the domain", "hole", "vertex 4 (1, 1)");

  Domain outside = d;
  outside.points.push_back(Point_2(-1, 2));
  QM2_EXPECT_ERROR(outside, "point 9 (-1, 2)", "outside the domain", "outside every boundary loop");

  Domain on_segment = d;
  on_segment.points.push_back(Point_2(4, 2));
  QM2_EXPECT_ERROR(on_segment, "point 9 (4, 2)", "lies on segment 1 ");

  Domain on_vertex = d;
  on_vertex.points.push_back(Point_2(3, 3));
  QM2_EXPECT_ERROR(on_vertex, "point 9 (3, 3)", "lies on segment ");
}

// ---- errors -------------------------------------------------------------------------------

TEST(Domain_loops_2, ErrorSegmentIndexOutOfRange)
{
  Domain d;
  add_square(d, 0, 0, 1, 1);
  d.segments[2][1] = 9;
  QM2_EXPECT_ERROR(d, "segment 2 refers to vertex 9", "only 4 points");
}

TEST(Domain_loops_2, ErrorDanglingSegment)
{
  Domain d;
  d.points = {Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(0, 1)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}};
  QM2_EXPECT_ERROR(d, "the open polyline of 3 segments from vertex 0 (0, 0) to vertex 3 (0, 1) (segment 0) lies outside "
                      "every boundary loop: a polyline with free ends is a crack, which must lie in the domain");
}

TEST(Domain_loops_2, ErrorCrossingSegments)
{
  Domain d;  // a bow tie
  add_loop(d, {{0, 0}, {2, 0}, {0, 2}, {2, 2}});
  QM2_EXPECT_ERROR(d, "segments 1 (vertices 1 (2, 0) and 2 (0, 2))", "3 (vertices 3 (2, 2) and 0 (0, 0))", "cross");

  Domain two;  // two squares crossing
  add_square(two, 0, 0, 2, 2);
  add_square(two, 1, 1, 3, 3);
  QM2_EXPECT_ERROR(two, "segments 1 ", "and 4 ", "cross");
}

TEST(Domain_loops_2, ErrorOverlappingSegments)
{
  Domain d;  // two squares sharing part of an edge
  add_square(d, 0, 0, 2, 2);
  add_loop(d, {{2, 1.5}, {2, 1}, {4, 1}, {4, 1.5}});
  QM2_EXPECT_ERROR(d, "segments 1 (vertices 1 (2, 0) and 2 (2, 2)) and 4 (vertices 4 (2, 1.5) and 5 (2, 1)) overlap",
                   ": vertex 4 (2, 1.5) lies on segment 1 (segments may meet only at their ends: split that segment there)");

  Domain back;  // a loop that runs back along its own previous segment
  add_loop(back, {{0, 0}, {2, 0}, {1, 0}, {1, 1}});
  QM2_EXPECT_ERROR(back, "segments 0 ", "and 1 ", "overlap", "vertex 1 (2, 0)");
}

TEST(Domain_loops_2, ErrorTouchingSegments)
{
  Domain d;  // a triangle whose apex lies on the square's edge
  add_square(d, 0, 0, 4, 4);
  add_loop(d, {{1, 1}, {3, 1}, {2, 4}});
  QM2_EXPECT_ERROR(d, "touch", "vertex 6 (2, 4) lies on segment 2");

  Domain dup;  // two loops with a vertex each at the same place
  add_square(dup, 0, 0, 1, 1);
  add_loop(dup, {{1, 1}, {2, 1}, {2, 2}});
  QM2_EXPECT_ERROR(dup, "touch", "(1, 1)");
}

TEST(Domain_loops_2, ErrorZeroLengthSegment)
{
  Domain d;
  add_square(d, 0, 0, 1, 1);
  d.segments.push_back({2, 2});
  QM2_EXPECT_ERROR(d, "zero-length segment 4", "vertex 2 (1, 1)");

  Domain same_place;
  add_loop(same_place, {{0, 0}, {1, 0}, {1, 0}, {1, 1}});
  QM2_EXPECT_ERROR(same_place, "zero-length segment 1 (vertices 1 (1, 0) and 2 (1, 0))");
}

TEST(Domain_loops_2, ErrorRepeatedSegment)
{
  Domain d;
  add_square(d, 0, 0, 1, 1);
  d.segments.push_back({2, 1});
  QM2_EXPECT_ERROR(d, "repeated segment", "segments 1 and 4", "vertex 1 (1, 0)", "vertex 2 (1, 1)");
}

TEST(Domain_loops_2, ErrorLoopWithFewerThanThreeVertices)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  d.points.push_back(Point_2(1, 1));
  d.points.push_back(Point_2(2, 2));
  d.segments.push_back({4, 5});
  d.segments.push_back({5, 4});
  QM2_EXPECT_ERROR(d, "fewer than 3 vertices", "segments 4 and 5", "vertex 4 (1, 1)", "vertex 5 (2, 2)");
}

TEST(Domain_loops_2, ErrorCollinearLoop)
{
  Domain d;
  add_square(d, 0, 0, 10, 10);
  add_loop(d, {{1, 1}, {3, 3}, {2, 2}});
  QM2_EXPECT_ERROR(d, "collinear", "zero area", "vertex 4 (1, 1)");
}

TEST(Domain_loops_2, ErrorHolePointOnSegment)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  add_square(d, 1, 1, 3, 3);
  d.holes.push_back(Point_2(3, 2));
  QM2_EXPECT_ERROR(d, "hole point 0 (3, 2) lies exactly on segment 5 ");

  Domain at_vertex = d;
  at_vertex.holes[0] = Point_2(1, 1);
  QM2_EXPECT_ERROR(at_vertex, "hole point 0 (1, 1) lies exactly on segment ");
}

TEST(Domain_loops_2, ErrorHolePointOutsideEveryLoop)
{
  Domain d;
  add_square(d, 0, 0, 4, 4);
  add_square(d, 1, 1, 3, 3);
  d.holes.push_back(Point_2(2, 2));
  d.holes.push_back(Point_2(5, 1));
  QM2_EXPECT_ERROR(d, "hole point 1 (5, 1) lies outside every boundary loop",
                   "not inside the loop of 4 vertices starting at vertex 0 (0, 0)");

  Domain two;
  add_square(two, 0, 0, 1, 1);
  add_square(two, 2, 0, 3, 1);
  two.holes.push_back(Point_2(1.5, 0.5));
  QM2_EXPECT_ERROR(two, "hole point 0 (1.5, 0.5) lies outside every boundary loop", "none of the 2 outermost loops");
}

// ---- junctions: a vertex on three segments or more; the arrangement is traced face by face --

/// the domain of a `cols` x `rows` grid of unit squares, every grid line a segment
inline Domain grid_domain(int cols, int rows)
{
  Domain d;
  const auto at = [cols](int i, int j) { return std::size_t(j * (cols + 1) + i); };
  for(int j = 0; j <= rows; ++j)
    for(int i = 0; i <= cols; ++i) d.points.push_back(Point_2(i, j));
  for(int j = 0; j <= rows; ++j)
    for(int i = 0; i < cols; ++i) d.segments.push_back({ at(i, j), at(i + 1, j) });
  for(int j = 0; j < rows; ++j)
    for(int i = 0; i <= cols; ++i) d.segments.push_back({ at(i, j), at(i, j + 1) });
  return d;
}

TEST(Domain_loops_2, a_square_split_by_a_segment_is_two_regions_sharing_it_as_twin_edges)
{
  Domain d;
  add_loop(d, { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 0, 1 } });
  d.segments.push_back({ 4, 1 });
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  expect_domain_on_left(d, loops);
  expect_edge_twins_consistent(loops);
  EXPECT_EQ(loops.loops[0].vertices, (std::vector<std::size_t>{ 0, 1, 4, 5 }));
  EXPECT_EQ(loops.loops[1].vertices, (std::vector<std::size_t>{ 1, 2, 3, 4 }));
  EXPECT_EQ(loops.loops[0].edge_twins[1], (std::array<std::size_t, 2>{ 1, 3 }));
  EXPECT_EQ(twinned_edges(loops), 2u);
  for(std::size_t l = 0; l < 2; ++l) {
    EXPECT_TRUE(loops.loops[l].is_outer);
    EXPECT_EQ(loops.loops[l].region, l);
    EXPECT_EQ(loops.loops[l].twin, std::size_t(-1)); // no loop shares all its edges
  }
  EXPECT_EQ(CGAL::to_double(CGAL::Quad_mesher_2::domain_area(d, loops)), 2.0);
}

TEST(Domain_loops_2, a_checkerboard_is_nine_regions_with_its_inner_segments_twinned)
{
  Domain d = grid_domain(3, 3);
  d.region_attributes.push_back({ Point_2(1.5, 1.5), 7, 0 });
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 9u);
  expect_domain_on_left(d, loops);
  expect_edge_twins_consistent(loops);
  EXPECT_EQ(twinned_edges(loops), 2u * 12u);
  std::set<std::size_t> regions;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    regions.insert(loops.loops[l].region);
    EXPECT_NEAR(CGAL::to_double(CGAL::Quad_mesher_2::region_area(d, loops, loops.loops[l].region)), 1.0, 1e-12);
  }
  EXPECT_EQ(regions.size(), 9u);
  ASSERT_EQ(loops.region_attributes.size(), 9u);
  EXPECT_EQ(std::count(loops.region_attributes.begin(), loops.region_attributes.end(), 0u), 1);
  EXPECT_EQ(CGAL::to_double(CGAL::Quad_mesher_2::domain_area(d, loops)), 9.0);
}

TEST(Domain_loops_2, a_hole_point_in_one_face_makes_it_a_hole_its_neighbours_stay)
{
  Domain d;
  add_square(d, -1, -1, 3, 2);                                          // a frame, 0 .. 3
  add_loop(d, { { 0, 0 }, { 1, 0 }, { 2, 0 }, { 2, 1 }, { 1, 1 }, { 0, 1 } }); // 4 .. 9
  d.segments.push_back({ 8, 5 });
  d.holes.push_back(Point_2(1.5, 0.5));
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 3u); // the frame, the outline of the split square, its left face
  expect_edge_twins_consistent(loops);
  EXPECT_TRUE(loops.loops[0].is_outer);
  std::size_t holes = 0, faces = 0;
  for(std::size_t l = 1; l < 3; ++l) (loops.loops[l].is_outer ? faces : holes) += 1;
  EXPECT_EQ(holes, 1u);
  EXPECT_EQ(faces, 1u);
  EXPECT_EQ(twinned_edges(loops), 2u * 3u); // the left face's outer three sides
  EXPECT_EQ(CGAL::to_double(CGAL::Quad_mesher_2::domain_area(d, loops)), 12.0 - 1.0);

  Domain alone = d; // without the frame, the hole's outer sides bound nothing
  alone.points.erase(alone.points.begin(), alone.points.begin() + 4);
  alone.segments.erase(alone.segments.begin(), alone.segments.begin() + 4);
  for(auto& sg : alone.segments) sg = { sg[0] - 4, sg[1] - 4 };
  QM2_EXPECT_ERROR(alone, "segment 1 (vertices 1 (1, 0) and 2 (2, 0)) has the domain on neither side",
                   "which holds hole point 0 (1.5, 0.5)", "outside every boundary loop");

  Domain framed = grid_domain(2, 2); // without hole points, inside a frame nesting makes a hole
  add_square(framed, -1, -1, 3, 3);
  QM2_EXPECT_ERROR(framed, "has the domain on neither side", "which nesting makes a hole");
}

TEST(Domain_loops_2, loops_touching_at_a_vertex_are_two_faces)
{
  Domain d;
  d.points = { Point_2(0, 0), Point_2(1, 0), Point_2(1, 1), Point_2(-1, 0), Point_2(-1, -1) };
  d.segments = { { 0, 1 }, { 1, 2 }, { 2, 0 }, { 0, 3 }, { 3, 4 }, { 4, 0 } };
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  expect_domain_on_left(d, loops);
  EXPECT_EQ(twinned_edges(loops), 0u);
  EXPECT_EQ(loops.loops[0].vertices.front(), 0u);
  EXPECT_EQ(loops.loops[1].vertices.front(), 0u);
  EXPECT_NE(loops.loops[0].region, loops.loops[1].region);
}

TEST(Domain_loops_2, a_crack_from_a_corner_and_a_branched_crack_are_walked_around)
{
  Domain tail;
  add_square(tail, 0, 0, 4, 4);
  tail.points.push_back(Point_2(2, 2));
  tail.segments.push_back({ 0, 4 }); // vertex 0 on three segments, vertex 4 on one
  const Loops walked = extract_loops(tail);
  ASSERT_EQ(walked.loops.size(), 1u);
  expect_edge_twins_consistent(walked);
  EXPECT_EQ(walked.loops[0].vertices, (std::vector<std::size_t>{ 0, 1, 2, 3, 0, 4 }));
  EXPECT_EQ(twinned_edges(walked), 2u);
  EXPECT_EQ(CGAL::to_double(CGAL::Quad_mesher_2::domain_area(tail, walked)), 16.0);

  Domain y; // three cracks meeting at (2, 2), inside a square
  add_square(y, 0, 0, 4, 4);
  y.points.insert(y.points.end(), { Point_2(2, 2), Point_2(1, 1), Point_2(3, 1), Point_2(2, 3) });
  y.segments.insert(y.segments.end(), { { 4, 5 }, { 4, 6 }, { 4, 7 } });
  const Loops branched = extract_loops(y);
  ASSERT_EQ(branched.loops.size(), 2u);
  expect_edge_twins_consistent(branched);
  EXPECT_FALSE(branched.loops[1].is_outer);
  EXPECT_EQ(branched.loops[1].vertices.size(), 6u);
  EXPECT_EQ(twinned_edges(branched), 6u);
  EXPECT_EQ(branched.loops[1].twin, std::size_t(-1)); // no simple crack: its edges are twinned one by one
  EXPECT_EQ(CGAL::to_double(CGAL::Quad_mesher_2::domain_area(y, branched)), 16.0);

  Domain outside = y; // the same branched crack beside the square
  for(std::size_t v = 4; v < 8; ++v) outside.points[v] = Point_2(outside.points[v].x() + 10, outside.points[v].y());
  QM2_EXPECT_ERROR(outside, "has the domain on neither side", "outside every boundary loop");
}

TEST(Domain_loops_2, ExactPredicatesNearlyCollinear)
{
  // A vertex a tiny distance inside the square's edge: a double comparison with a tolerance
  // would call it touching; exact predicates accept it.
  Domain d;
  add_square(d, 0, 0, 1, 1);
  add_loop(d, {{0.25, 0.5}, {0.5, 0.25}, {std::nextafter(1.0, 0.0), 0.5}});
  const Loops loops = extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  expect_domain_on_left(d, loops);

  Domain touching = d;
  touching.points[6] = Point_2(1, 0.5);
  QM2_EXPECT_ERROR(touching, "touch", "vertex 6 (1, 0.5) lies on segment 1");
}

} // namespace qm2_test_loops

#undef QM2_EXPECT_ERROR
