// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_DOMAIN_2_H
#define CGAL_QUAD_MESHER_2_DOMAIN_2_H

#include <array>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// A planar input in the sense of Triangle's `.poly` files: points, segments between them
/// (indices into `points`, 0-based) and hole seed points (each marks the face that contains
/// it as outside the domain). A point cloud is a `Domain_2` without segments.
template <class GeomTraits>
struct Domain_2
{
  typedef typename GeomTraits::Point_2 Point_2;
  typedef std::array<std::size_t, 2> Segment;

  std::vector<Point_2> points;
  std::vector<Segment> segments;
  std::vector<Point_2> holes;

  bool is_point_cloud() const { return segments.empty(); }
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_DOMAIN_2_H
