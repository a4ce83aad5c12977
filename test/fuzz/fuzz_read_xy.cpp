// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// libFuzzer target: read_xy() on arbitrary bytes keeps its promises (fuzz_reader.h).

#include "fuzz_reader.h"

#include <CGAL/Quad_mesher_2/IO/read_xy.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  qm2_fuzz::check_reader(data, size, qm2_fuzz::Point_reader(&CGAL::Quad_mesher_2::IO::read_xy<qm2_fuzz::K>));
  return 0;
}
