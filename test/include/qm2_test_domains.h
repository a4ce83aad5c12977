// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Domains for the tests, in the test binary's kernel: closed polygons given as point lists.

#ifndef QM2_TEST_DOMAINS_H
#define QM2_TEST_DOMAINS_H

#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Domain_2.h>

#include <cmath>
#include <vector>

namespace qm2_test {

// a domain made of closed polygons (orientation free), plus hole seed points
inline CGAL::Quad_mesher_2::Domain_2<K> polygons(const std::vector<std::vector<Point_2>>& polys,
                                                 const std::vector<Point_2>& holes = {})
{
  CGAL::Quad_mesher_2::Domain_2<K> d;
  for(const auto& poly : polys) {
    const std::size_t first = d.points.size();
    for(std::size_t i = 0; i < poly.size(); ++i) {
      d.points.push_back(poly[i]);
      d.segments.push_back({first + i, first + (i + 1) % poly.size()});
    }
  }
  d.holes = holes;
  return d;
}

inline std::vector<Point_2> rectangle(double x0, double y0, double x1, double y1)
{
  return {Point_2(x0, y0), Point_2(x1, y0), Point_2(x1, y1), Point_2(x0, y1)};
}

// the regular n-gon inscribed in the circle (cx, cy, r), counter-clockwise from angle 0
inline std::vector<Point_2> disc(double cx, double cy, double r, int n)
{
  const double pi = 3.14159265358979323846;
  std::vector<Point_2> p;
  for(int i = 0; i < n; ++i)
    p.emplace_back(cx + r * std::cos(2 * pi * i / n), cy + r * std::sin(2 * pi * i / n));
  return p;
}

} // namespace qm2_test

#endif // QM2_TEST_DOMAINS_H
