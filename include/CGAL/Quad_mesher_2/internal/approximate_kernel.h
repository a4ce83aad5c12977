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

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Approximate_kernel;

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_APPROXIMATE_KERNEL_H
