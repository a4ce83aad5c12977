// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The tests' wall-clock bounds are the optimised build's. A build instrumented by
// AddressSanitizer (QM2_SANITIZE, with UndefinedBehaviorSanitizer) runs several times slower
// and checks memory and behaviour, not speed: its bounds are ten times looser.

#ifndef QM2_TIME_BOUNDS_H
#define QM2_TIME_BOUNDS_H

namespace qm2_test {

// GCC says so with __SANITIZE_ADDRESS__, clang with __has_feature
#if defined(__SANITIZE_ADDRESS__)
#define QM2_TEST_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define QM2_TEST_ADDRESS_SANITIZER 1
#endif
#endif

#ifdef QM2_TEST_ADDRESS_SANITIZER
inline constexpr double time_scale = 10;
#else
inline constexpr double time_scale = 1;
#endif

// `seconds`, the bound of the optimised build, for this build
inline constexpr double time_bound(double seconds) { return seconds * time_scale; }

} // namespace qm2_test

#endif // QM2_TIME_BOUNDS_H
