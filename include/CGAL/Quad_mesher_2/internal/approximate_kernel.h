// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The kernel of the library's double-precision work: the buffer stages' searches and working
// positions, the size fields, the curve decomposition and the quality measures, whatever the
// user's kernel. Its constructions round to doubles; its predicates are exact on those doubles
// (Epick), so a decision taken on a working position (a fold, a side of a line) is the one
// the mesh's point, made from those doubles, gets.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_APPROXIMATE_KERNEL_H
#define CGAL_QUAD_MESHER_2_INTERNAL_APPROXIMATE_KERNEL_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/number_utils.h>

#include <cmath>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Approximate_kernel;
typedef Approximate_kernel::Point_2 Point_2d;
typedef Approximate_kernel::Vector_2 Vector_2d;
typedef Approximate_kernel::Segment_2 Segment_2d;

/// The nearest double point to `p`, a point of the user's traits. The traits concept asks for
/// coordinates with `to_double()`, not for a kernel, so this is not a `Cartesian_converter`.
template <class Point_2>
inline Point_2d to_point_2d(const Point_2& p)
{
  return Point_2d(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
}

/// The length of `v`.
inline double length_2d(const Vector_2d& v) { return std::sqrt(v.squared_length()); }

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_APPROXIMATE_KERNEL_H
