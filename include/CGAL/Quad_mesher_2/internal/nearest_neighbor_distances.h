// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_NEAREST_NEIGHBOR_DISTANCES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_NEAREST_NEIGHBOR_DISTANCES_H

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// For each point, the distance to its nearest other point and that point's index (a size
// field only, so doubles suffice). A balanced k-d tree that splits each node across its
// wider extent, so that points sharing a coordinate (all on one line) still prune.
class Nearest_neighbor_distances
{
public:
  typedef std::array<double, 2> P;

  explicit Nearest_neighbor_distances(const std::vector<P>& points)
    : m_points(points), m_order(points.size()), m_axis(points.size())
  {
    std::iota(m_order.begin(), m_order.end(), std::size_t(0));
    build(0, m_order.size());
    distance.assign(points.size(), std::numeric_limits<double>::infinity());
    neighbor.assign(points.size(), std::size_t(-1));
    for(std::size_t i = 0; i < points.size(); ++i) {
      double best2 = std::numeric_limits<double>::infinity();
      query(0, m_order.size(), i, best2);
      distance[i] = std::sqrt(best2);
    }
  }

  std::vector<double> distance;
  std::vector<std::size_t> neighbor;

private:
  void build(std::size_t b, std::size_t e)
  {
    if(e - b <= 1)
      return;
    std::size_t m = b + (e - b) / 2;
    double lo[2] = { HUGE_VAL, HUGE_VAL }, hi[2] = { -HUGE_VAL, -HUGE_VAL };
    for(std::size_t k = b; k < e; ++k)
      for(int a = 0; a < 2; ++a) {
        lo[a] = (std::min)(lo[a], m_points[m_order[k]][a]);
        hi[a] = (std::max)(hi[a], m_points[m_order[k]][a]);
      }
    const int axis = hi[0] - lo[0] >= hi[1] - lo[1] ? 0 : 1;
    m_axis[m] = static_cast<unsigned char>(axis);
    std::nth_element(m_order.begin() + b, m_order.begin() + m, m_order.begin() + e,
                     [&](std::size_t u, std::size_t v) { return m_points[u][axis] < m_points[v][axis]; });
    build(b, m);
    build(m + 1, e);
  }

  void query(std::size_t b, std::size_t e, std::size_t i, double& best2)
  {
    if(b >= e)
      return;
    std::size_t m = b + (e - b) / 2;
    const int axis = m_axis[m];
    std::size_t c = m_order[m];
    const P& p = m_points[i];
    if(c != i) {
      double dx = m_points[c][0] - p[0], dy = m_points[c][1] - p[1];
      double d2 = dx * dx + dy * dy;
      if(d2 < best2) {
        best2 = d2;
        neighbor[i] = c;
      }
    }
    double delta = p[axis] - m_points[c][axis];
    if(delta < 0) {
      query(b, m, i, best2);
      if(delta * delta < best2)
        query(m + 1, e, i, best2);
    } else {
      query(m + 1, e, i, best2);
      if(delta * delta < best2)
        query(b, m, i, best2);
    }
  }

  const std::vector<P>& m_points;
  std::vector<std::size_t> m_order;
  std::vector<unsigned char> m_axis; // split axis of the node whose median sits at each position
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_NEAREST_NEIGHBOR_DISTANCES_H
