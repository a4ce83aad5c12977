// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// A broken promise in a fuzz target: says which, and aborts, which libFuzzer reports as a
// crash with the input that caused it.

#ifndef QM2_FUZZ_REQUIRE_H
#define QM2_FUZZ_REQUIRE_H

#include <cstdio>
#include <cstdlib>
#include <string>

namespace qm2_fuzz {

inline void require(bool holds, const std::string& promise)
{
  if(holds)
    return;
  std::fprintf(stderr, "broken promise: %s\n", promise.c_str());
  std::abort();
}

} // namespace qm2_fuzz

#endif // QM2_FUZZ_REQUIRE_H
