// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Independent checkers shared by the test suites (the role CGAL's _test_cls drivers play).
// They do not use the library's quality module, so a bug there cannot hide one here.

#ifndef QM2_MESH_CHECKS_H
#define QM2_MESH_CHECKS_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace qm2_checks {

struct Angle_range { double min = 360, max = 0; };

// Interior angle in degrees at corner c of quad q (reflex corners > 180).
template <class Point_2>
double corner_angle(const CGAL::Quad_mesher_2::Quad_mesh_2<Point_2>& m, std::size_t q, int c)
{
  const auto& quad = m.quads[q];
  auto xy = [&](std::size_t v) {
    return std::make_pair(CGAL::to_double(m.points[v].x()), CGAL::to_double(m.points[v].y()));
  };
  auto p = xy(quad[c]), a = xy(quad[(c + 1) % 4]), b = xy(quad[(c + 3) % 4]);
  double ax = a.first - p.first, ay = a.second - p.second;
  double bx = b.first - p.first, by = b.second - p.second;
  double angle = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180 / M_PI;
  return angle < 0 ? angle + 360 : angle;
}

template <class Point_2>
Angle_range angle_range(const CGAL::Quad_mesher_2::Quad_mesh_2<Point_2>& m)
{
  Angle_range r;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) {
      double a = corner_angle(m, q, c);
      r.min = (std::min)(r.min, a);
      r.max = (std::max)(r.max, a);
    }
  return r;
}

// Shoelace area, relative to the quad's first corner so that far-off coordinates do not
// cancel away the digits.
template <class Point_2>
double signed_area(const CGAL::Quad_mesher_2::Quad_mesh_2<Point_2>& m, std::size_t q)
{
  const Point_2& o = m.points[m.quads[q][0]];
  double a = 0;
  for(int c = 1; c < 3; ++c) {
    const Point_2& p = m.points[m.quads[q][c]];
    const Point_2& r = m.points[m.quads[q][c + 1]];
    double px = CGAL::to_double(p.x() - o.x()), py = CGAL::to_double(p.y() - o.y());
    double rx = CGAL::to_double(r.x() - o.x()), ry = CGAL::to_double(r.y() - o.y());
    a += px * ry - rx * py;
  }
  return a / 2;
}

// Conformity: every undirected edge is used by one or two quads, twice only in opposite
// directions; all quads counter-clockwise and convex (every corner angle < 180); indices valid,
// no vertex unused, no two vertices equal. Returns the boundary edges (used once), directed.
template <class Point_2>
::testing::AssertionResult is_conforming(const CGAL::Quad_mesher_2::Quad_mesh_2<Point_2>& m,
                                         std::vector<std::pair<std::size_t, std::size_t>>* boundary = nullptr)
{
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  std::vector<bool> used(m.points.size(), false);
  for(std::size_t q = 0; q < m.quads.size(); ++q) {
    for(int c = 0; c < 4; ++c) {
      std::size_t a = m.quads[q][c], b = m.quads[q][(c + 1) % 4];
      if(a >= m.points.size() || b >= m.points.size())
        return ::testing::AssertionFailure() << "quad " << q << " has an index out of range";
      if(a == b)
        return ::testing::AssertionFailure() << "quad " << q << " repeats vertex " << a;
      used[a] = true;
      if(++directed[{ a, b }] > 1)
        return ::testing::AssertionFailure() << "edge " << a << "-" << b << " used twice in the same direction";
      if(corner_angle(m, q, c) >= 180)
        return ::testing::AssertionFailure() << "quad " << q << " is not convex and counter-clockwise";
    }
    if(!(signed_area(m, q) > 0))
      return ::testing::AssertionFailure() << "quad " << q << " has non-positive area";
  }
  for(std::size_t v = 0; v < used.size(); ++v)
    if(!used[v])
      return ::testing::AssertionFailure() << "vertex " << v << " is unused";
  std::set<std::pair<double, double>> coords;
  for(const Point_2& p : m.points)
    if(!coords.insert({ CGAL::to_double(p.x()), CGAL::to_double(p.y()) }).second)
      return ::testing::AssertionFailure() << "two vertices at (" << CGAL::to_double(p.x()) << ", "
                                           << CGAL::to_double(p.y()) << ")";
  if(boundary != nullptr) {
    boundary->clear();
    for(const auto& e : directed)
      if(directed.count({ e.first.second, e.first.first }) == 0)
        boundary->push_back(e.first);
  }
  return ::testing::AssertionSuccess();
}

// A conforming mesh of an axis-parallel rectangle [x0,x1]x[y0,y1]: conforming, every boundary
// edge on the rectangle's sides (a hanging node would leave boundary edges inside), and quad
// areas summing to the rectangle's.
template <class Point_2>
::testing::AssertionResult tiles_rectangle(const CGAL::Quad_mesher_2::Quad_mesh_2<Point_2>& m,
                                           double x0, double y0, double x1, double y1)
{
  std::vector<std::pair<std::size_t, std::size_t>> boundary;
  ::testing::AssertionResult ok = is_conforming(m, &boundary);
  if(!ok)
    return ok;
  auto on_side = [&](const Point_2& p, const Point_2& q) {
    double px = CGAL::to_double(p.x()), py = CGAL::to_double(p.y());
    double qx = CGAL::to_double(q.x()), qy = CGAL::to_double(q.y());
    return (px == qx && (px == x0 || px == x1)) || (py == qy && (py == y0 || py == y1));
  };
  for(const auto& e : boundary)
    if(!on_side(m.points[e.first], m.points[e.second]))
      return ::testing::AssertionFailure()
             << "boundary edge inside the rectangle (a hanging node) at ("
             << CGAL::to_double(m.points[e.first].x()) << ", " << CGAL::to_double(m.points[e.first].y()) << ")";
  double area = 0;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    area += signed_area(m, q);
  double expected = (x1 - x0) * (y1 - y0);
  if(std::abs(area - expected) > 1e-12 * expected)
    return ::testing::AssertionFailure() << "area " << area << " != " << expected;
  return ::testing::AssertionSuccess();
}

} // namespace qm2_checks

#endif // QM2_MESH_CHECKS_H
