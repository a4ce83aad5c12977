// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The kernel a test binary is built for: each test source is compiled once per kernel.

#ifndef QM2_TEST_KERNEL_H
#define QM2_TEST_KERNEL_H

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace qm2_test {
#if defined(QM2_TEST_KERNEL_EPECK)
using K = CGAL::Exact_predicates_exact_constructions_kernel;
inline constexpr bool exact_constructions = true;
#else
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
inline constexpr bool exact_constructions = false;
#endif
using FT = K::FT;
using Point_2 = K::Point_2;
} // namespace qm2_test

#endif // QM2_TEST_KERNEL_H
