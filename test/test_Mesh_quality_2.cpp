// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests for CGAL/Quad_mesher_2/Mesh_quality_2.h on small hand-built meshes.

#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include "qm2_test_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace qm2_test_quality {

using Point = qm2_test::Point_2;
using Mesh = CGAL::Quad_mesher_2::Quad_mesh_2<Point>;
using CGAL::Quad_mesher_2::compute_quality;
using CGAL::Quad_mesher_2::Mesh_quality_2;

inline Mesh make_mesh(const std::vector<std::pair<double, double>>& xy,
                      const std::vector<std::array<std::size_t, 4>>& quads)
{
  Mesh m;
  for(const auto& p : xy)
    m.points.push_back(Point(p.first, p.second));
  m.quads = quads;
  return m;
}

/// An nx-by-ny grid of unit squares, with optionally the cells listed in `holes` removed
/// (unused vertices are kept).
inline Mesh make_grid(std::size_t nx, std::size_t ny,
                      const std::vector<std::pair<std::size_t, std::size_t>>& holes = {})
{
  Mesh m;
  for(std::size_t j = 0; j <= ny; ++j)
    for(std::size_t i = 0; i <= nx; ++i)
      m.points.push_back(Point(double(i), double(j)));
  auto id = [nx](std::size_t i, std::size_t j) { return j * (nx + 1) + i; };
  for(std::size_t j = 0; j < ny; ++j)
    for(std::size_t i = 0; i < nx; ++i) {
      bool hole = false;
      for(const auto& h : holes)
        hole = hole || (h.first == i && h.second == j);
      if(!hole)
        m.quads.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

inline std::size_t histogram_sum(const Mesh_quality_2& q)
{
  return std::accumulate(q.angle_histogram.begin(), q.angle_histogram.end(), std::size_t(0));
}

} // namespace qm2_test_quality

TEST(MeshQuality2, UnitSquareIsPerfect)
{
  using namespace qm2_test_quality;
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_quads, 1u);
  EXPECT_EQ(q.number_of_vertices, 4u);
  EXPECT_NEAR(q.min_angle, 90.0, 1e-9);
  EXPECT_NEAR(q.max_angle, 90.0, 1e-9);
  EXPECT_NEAR(q.mean_angle, 90.0, 1e-9);
  EXPECT_EQ(q.angle_histogram[18], 4u);
  EXPECT_EQ(histogram_sum(q), 4u);
  EXPECT_DOUBLE_EQ(q.share_in_45_135, 1.0);
  EXPECT_DOUBLE_EQ(q.share_in_60_120, 1.0);
  EXPECT_DOUBLE_EQ(q.min_aspect_ratio, 1.0);
  EXPECT_DOUBLE_EQ(q.max_aspect_ratio, 1.0);
  EXPECT_DOUBLE_EQ(q.mean_aspect_ratio, 1.0);
  EXPECT_NEAR(q.min_scaled_jacobian, 1.0, 1e-12);
  EXPECT_NEAR(q.mean_scaled_jacobian, 1.0, 1e-12);
  EXPECT_EQ(q.number_of_inverted_quads, 0u);
  EXPECT_EQ(q.number_of_degenerate_quads, 0u);
  EXPECT_EQ(q.number_of_non_manifold_edges, 0u);
  EXPECT_EQ(q.number_of_hanging_nodes, 0u);
  EXPECT_EQ(q.number_of_duplicate_vertices, 0u);
  EXPECT_EQ(q.number_of_near_duplicate_vertices, 0u);
  EXPECT_EQ(q.number_of_unused_vertices, 0u);
  EXPECT_EQ(q.number_of_boundary_loops, 1u);
  EXPECT_TRUE(q.is_valid());
}

TEST(MeshQuality2, RectangleAspectRatio)
{
  using namespace qm2_test_quality;
  const Mesh m = make_mesh({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_DOUBLE_EQ(q.max_aspect_ratio, 2.0);
  EXPECT_NEAR(q.min_scaled_jacobian, 1.0, 1e-12);
  EXPECT_TRUE(q.is_valid());
}

TEST(MeshQuality2, Kite45And135)
{
  using namespace qm2_test_quality;
  const double c = std::sqrt(0.5);
  // A rhombus (a kite with equal sides): 45, 135, 45, 135 degrees.
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1 + c, c}, {c, c}}, {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_NEAR(q.min_angle, 45.0, 1e-9);
  EXPECT_NEAR(q.max_angle, 135.0, 1e-9);
  EXPECT_NEAR(q.mean_angle, 90.0, 1e-9);
  EXPECT_EQ(q.angle_histogram[9], 2u);  // [45, 50)
  EXPECT_EQ(q.angle_histogram[27], 2u); // [135, 140)
  EXPECT_EQ(histogram_sum(q), 4u);
  EXPECT_DOUBLE_EQ(q.share_in_45_135, 1.0);
  EXPECT_DOUBLE_EQ(q.share_in_60_120, 0.0);
  EXPECT_NEAR(q.min_scaled_jacobian, c, 1e-9);
  EXPECT_EQ(q.number_of_inverted_quads, 0u);
  EXPECT_TRUE(q.is_valid());
}

TEST(MeshQuality2, NonConvexQuadIsInverted)
{
  using namespace qm2_test_quality;
  // A dart: reflex corner of 270 degrees at (1,1).
  const Mesh m = make_mesh({{0, 0}, {2, 1}, {0, 2}, {1, 1}}, {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_NEAR(q.max_angle, 270.0, 1e-9);
  EXPECT_NEAR(q.mean_angle, 90.0, 1e-9);
  EXPECT_EQ(q.angle_histogram[54], 1u); // [270, 275)
  EXPECT_LT(q.min_scaled_jacobian, 0.0);
  EXPECT_EQ(q.number_of_inverted_quads, 1u);
  EXPECT_EQ(q.number_of_degenerate_quads, 0u);
  EXPECT_DOUBLE_EQ(q.share_in_45_135, 0.25); // 18.4, 53.1, 18.4, 270
  EXPECT_FALSE(q.is_valid());
}

TEST(MeshQuality2, FlippedQuadIsInverted)
{
  using namespace qm2_test_quality;
  const Mesh m = make_mesh({{0, 0}, {0, 1}, {1, 1}, {1, 0}}, {{0, 1, 2, 3}}); // clockwise
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_inverted_quads, 1u);
  EXPECT_NEAR(q.min_angle, 270.0, 1e-9);
  EXPECT_NEAR(q.min_scaled_jacobian, -1.0, 1e-12);
  EXPECT_FALSE(q.is_valid());
}

TEST(MeshQuality2, BowTieIsInverted)
{
  using namespace qm2_test_quality;
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {0, 1}, {1, 1}}, {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_inverted_quads, 1u);
  EXPECT_EQ(q.number_of_degenerate_quads, 0u);
  EXPECT_NEAR(q.min_angle, 45.0, 1e-9);
  EXPECT_NEAR(q.max_angle, 315.0, 1e-9);
  EXPECT_FALSE(q.is_valid());
}

TEST(MeshQuality2, DegenerateQuads)
{
  using namespace qm2_test_quality;
  // Repeated index; zero-length edge (two distinct but equal points); collinear corner.
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 1}, {2, 0}, {3, 0}, {3, 1}},
                           {{0, 1, 2, 2}, {1, 5, 2, 4}, {1, 5, 6, 7}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_degenerate_quads, 3u);
  EXPECT_GE(q.number_of_duplicate_vertices, 1u);
  EXPECT_FALSE(q.is_valid());
  // An out-of-range index is reported as degenerate, not a crash.
  const Mesh bad = make_mesh({{0, 0}, {1, 0}, {1, 1}}, {{0, 1, 2, 7}});
  EXPECT_EQ(compute_quality(bad).number_of_degenerate_quads, 1u);
}

TEST(MeshQuality2, TJunctionHangingNode)
{
  using namespace qm2_test_quality;
  // A 1x2 quad on the left, two unit quads on the right: (1,1) hangs on edge (1,0)-(1,2).
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 2}, {0, 2}, {2, 0}, {2, 1}, {1, 1}, {2, 2}},
                           {{0, 1, 2, 3}, {1, 4, 5, 6}, {6, 5, 7, 2}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_hanging_nodes, 1u);
  EXPECT_EQ(q.number_of_non_manifold_edges, 0u);
  EXPECT_EQ(q.number_of_inverted_quads, 0u);
  EXPECT_FALSE(q.is_valid());

  // The same region, conforming (the left quad split too): no hanging node.
  const Mesh ok = make_mesh({{0, 0}, {1, 0}, {1, 2}, {0, 2}, {2, 0}, {2, 1}, {1, 1}, {2, 2}, {0, 1}},
                            {{0, 1, 6, 8}, {8, 6, 2, 3}, {1, 4, 5, 6}, {6, 5, 7, 2}});
  const Mesh_quality_2 q_ok = compute_quality(ok);
  EXPECT_EQ(q_ok.number_of_hanging_nodes, 0u);
  EXPECT_EQ(q_ok.number_of_boundary_loops, 1u);
  EXPECT_TRUE(q_ok.is_valid());
}

// The search bins edges in a grid sized by the mean edge length: a graded mesh (here a fine
// 60x60 block of cells 1e-4 wide beside the T-junction) makes the grid fine and the
// T-junction's edges cross many of its cells. At every slope, steep or not, either way round,
// the hanging node is found, and the conforming version has none.
TEST(MeshQuality2, TJunctionHangingNodeAtEverySlopeBesideFineCells)
{
  using namespace qm2_test_quality;
  const std::vector<std::pair<double, double>> t_xy = {{0, 0}, {1, 0}, {1, 2}, {0, 2}, {2, 0}, {2, 1}, {1, 1}, {2, 2}};
  const std::vector<std::array<std::size_t, 4>> t_quads = {{0, 1, 2, 3}, {1, 4, 5, 6}, {6, 5, 7, 2}};
  const std::vector<std::pair<double, double>> ok_xy = {{0, 0}, {1, 0}, {1, 2}, {0, 2}, {2, 0}, {2, 1}, {1, 1}, {2, 2}, {0, 1}};
  const std::vector<std::array<std::size_t, 4>> ok_quads = {{0, 1, 6, 8}, {8, 6, 2, 3}, {1, 4, 5, 6}, {6, 5, 7, 2}};
  auto with_fine_block = [](std::vector<std::pair<double, double>> xy, std::vector<std::array<std::size_t, 4>> quads, double degrees) {
    const double a = degrees * 3.14159265358979323846 / 180, c = std::cos(a), s = std::sin(a);
    for(auto& p : xy) p = { c * p.first - s * p.second, s * p.first + c * p.second };
    const std::size_t n = 60, base = xy.size();
    for(std::size_t j = 0; j <= n; ++j)
      for(std::size_t i = 0; i <= n; ++i)
        xy.push_back({ 5 + 1e-4 * double(i), 5 + 1e-4 * double(j) });
    for(std::size_t j = 0; j < n; ++j)
      for(std::size_t i = 0; i < n; ++i) {
        const std::size_t v = base + j * (n + 1) + i;
        quads.push_back({ v, v + 1, v + n + 2, v + n + 1 });
      }
    return make_mesh(xy, quads);
  };
  for(double degrees = 0; degrees < 360; degrees += 7.5) {
    SCOPED_TRACE(degrees);
    EXPECT_EQ(compute_quality(with_fine_block(t_xy, t_quads, degrees)).number_of_hanging_nodes, 1u);
    EXPECT_EQ(compute_quality(with_fine_block(ok_xy, ok_quads, degrees)).number_of_hanging_nodes, 0u);
  }
}

TEST(MeshQuality2, DuplicateVertices)
{
  using namespace qm2_test_quality;
  // Two unit squares side by side that do not share their common vertices.
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, 0}, {2, 0}, {2, 1}, {1, 1}},
                           {{0, 1, 2, 3}, {4, 5, 6, 7}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_duplicate_vertices, 2u);
  EXPECT_EQ(q.number_of_hanging_nodes, 0u);
  EXPECT_EQ(q.number_of_boundary_loops, 2u);
  EXPECT_FALSE(q.is_valid());
}

TEST(MeshQuality2, NearDuplicateVertices)
{
  using namespace qm2_test_quality;
  // The same two squares, the second one's left side moved right by 1e-12 (the verifier
  // merges at 1e-9 of the diagonal) and then by 1e-8 (apart for it).
  for(const double gap : { 1e-12, 1e-8 }) {
    const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1 + gap, 0}, {2, 0}, {2, 1}, {1 + gap, 1}},
                             {{0, 1, 2, 3}, {4, 5, 6, 7}});
    const Mesh_quality_2 q = compute_quality(m);
    EXPECT_EQ(q.number_of_duplicate_vertices, 0u) << gap;
    EXPECT_EQ(q.number_of_near_duplicate_vertices, gap < 1e-9 ? 2u : 0u) << gap;
    EXPECT_TRUE(q.is_valid()) << gap; // a point cloud may hold points this close
  }
}

TEST(MeshQuality2, NearDuplicatePairsMatchAllPairs)
{
  using CGAL::Quad_mesher_2::internal::Point_2d;
  // A quadtree-like grid (whole columns share one x) with pairs and triples of points within,
  // at and beyond the tolerance, some straddling the borders of the tolerance-wide columns:
  // the sorted sweep must count exactly the pairs an all-pairs scan finds.
  const double tol = 1e-3;
  std::vector<Point_2d> pts;
  for(int i = 0; i < 30; ++i)
    for(int j = 0; j < 30; ++j)
      pts.push_back(Point_2d{ 0.1 * i, 0.1 * j });
  std::uint64_t state = 12345;
  auto uniform = [&]() {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  };
  for(int k = 0; k < 300; ++k) {
    const Point_2d base = pts[std::size_t(uniform() * 900)]; // a copy: push_back may reallocate pts
    const double dx = (uniform() - 0.5) * 3 * tol, dy = (uniform() - 0.5) * 3 * tol;
    pts.push_back(Point_2d{ base.x() + dx, base.y() + dy });
    if(k % 3 == 0) pts.push_back(Point_2d{ base.x() + dx, base.y() + dy + (k % 2 ? tol : 2 * tol) });
  }
  std::vector<char> used(pts.size(), 1);
  used[7] = 0; // unused points do not count
  std::size_t expected = 0;
  for(std::size_t a = 0; a < pts.size(); ++a)
    for(std::size_t b = a + 1; b < pts.size(); ++b)
      if(used[a] && used[b] && std::abs(pts[a].x() - pts[b].x()) <= tol && std::abs(pts[a].y() - pts[b].y()) <= tol)
        ++expected;
  EXPECT_GT(expected, 100u);
  EXPECT_EQ(CGAL::Quad_mesher_2::internal::count_near_duplicate_pairs(pts, used, Point_2d{ -0.01, -0.01 }, tol),
            expected);
}

TEST(MeshQuality2, NonManifoldEdges)
{
  using namespace qm2_test_quality;
  // Three quads on edge (0,1).
  const Mesh three = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {1, -1}, {0, -1}, {1, 2}, {0, 2}},
                               {{0, 1, 2, 3}, {1, 0, 5, 4}, {0, 1, 6, 7}});
  EXPECT_EQ(compute_quality(three).number_of_non_manifold_edges, 1u);
  EXPECT_FALSE(compute_quality(three).is_valid());

  // Two quads using edge (1,2) in the same direction (one of them clockwise).
  const Mesh same_dir = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}},
                                  {{0, 1, 2, 3}, {1, 2, 5, 4}});
  const Mesh_quality_2 q = compute_quality(same_dir);
  EXPECT_EQ(q.number_of_non_manifold_edges, 1u);
  EXPECT_EQ(q.number_of_inverted_quads, 1u);

  // Correctly oriented neighbours: the shared edge is interior and manifold.
  const Mesh ok = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}},
                            {{0, 1, 2, 3}, {1, 4, 5, 2}});
  EXPECT_EQ(compute_quality(ok).number_of_non_manifold_edges, 0u);
  EXPECT_TRUE(compute_quality(ok).is_valid());
}

TEST(MeshQuality2, UnusedVertices)
{
  using namespace qm2_test_quality;
  const Mesh m = make_mesh({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {5, 5}, {0.5, 0}},
                           {{0, 1, 2, 3}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_unused_vertices, 2u);
  // An unused vertex on an edge is not a hanging node.
  EXPECT_EQ(q.number_of_hanging_nodes, 0u);
  EXPECT_TRUE(q.is_valid());
}

TEST(MeshQuality2, GridHistogramAndLoops)
{
  using namespace qm2_test_quality;
  const Mesh m = make_grid(20, 15);
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_quads, 300u);
  EXPECT_EQ(histogram_sum(q), 4 * q.number_of_quads);
  EXPECT_EQ(q.angle_histogram[18], 4 * q.number_of_quads);
  EXPECT_EQ(q.number_of_boundary_loops, 1u);
  EXPECT_TRUE(q.is_valid());
}

TEST(MeshQuality2, HistogramSumsOnMixedMesh)
{
  using namespace qm2_test_quality;
  // Perturbed grid: angles spread over many bins, still one per corner.
  Mesh m = make_grid(6, 6);
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    const double dx = 0.2 * std::sin(double(i) * 1.7), dy = 0.2 * std::cos(double(i) * 2.3);
    m.points[i] = Point(m.points[i].x() + dx, m.points[i].y() + dy);
  }
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(histogram_sum(q), 4 * q.number_of_quads);
  std::size_t nonzero_bins = 0;
  for(std::size_t c : q.angle_histogram)
    nonzero_bins += c > 0 ? 1 : 0;
  EXPECT_GT(nonzero_bins, 3u);
  EXPECT_LT(q.min_angle, 90.0);
  EXPECT_GT(q.max_angle, 90.0);
  EXPECT_NEAR(q.mean_angle, 90.0, 1e-9);
  EXPECT_GT(q.share_in_45_135, q.share_in_60_120 - 1e-15);
}

TEST(MeshQuality2, SquareWithSquareHoleHasTwoBoundaryLoops)
{
  using namespace qm2_test_quality;
  const Mesh m = make_grid(3, 3, {{1, 1}});
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_quads, 8u);
  EXPECT_EQ(q.number_of_boundary_loops, 2u);
  EXPECT_EQ(q.number_of_hanging_nodes, 0u);
  EXPECT_TRUE(q.is_valid());

  // Two holes touching at a corner (a pinch vertex): still two separate inner loops.
  const Mesh pinch = make_grid(4, 4, {{1, 1}, {2, 2}});
  EXPECT_EQ(compute_quality(pinch).number_of_boundary_loops, 3u);
}

TEST(MeshQuality2, EmptyMesh)
{
  using namespace qm2_test_quality;
  const Mesh m;
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_EQ(q.number_of_quads, 0u);
  EXPECT_EQ(q.number_of_boundary_loops, 0u);
  EXPECT_EQ(q.min_angle, 0.0);
  EXPECT_TRUE(q.is_valid());
}

// Aspect-ratio percentiles (nearest rank) and the shortest edge over the diagonal: a row of
// 20 quads, 19 unit squares and one 1 by 0.25 at the end.
TEST(MeshQuality2, AspectRatioPercentilesAndShortestEdge)
{
  using namespace qm2_test_quality;
  Mesh m = make_grid(20, 1);
  for(std::size_t v : { std::size_t(20), std::size_t(41) })
    m.points[v] = Point(19.25, CGAL::to_double(m.points[v].y()));
  const Mesh_quality_2 q = compute_quality(m);
  EXPECT_DOUBLE_EQ(q.max_aspect_ratio, 4.0);
  EXPECT_DOUBLE_EQ(q.aspect_ratio_percentiles[0], 1.0);
  EXPECT_DOUBLE_EQ(q.aspect_ratio_percentiles[1], 1.0);  // 19 of 20 quads
  EXPECT_DOUBLE_EQ(q.aspect_ratio_percentiles[2], 4.0);
  EXPECT_DOUBLE_EQ(q.min_edge_over_diagonal, 0.25 / std::hypot(19.25, 1.0));
}
