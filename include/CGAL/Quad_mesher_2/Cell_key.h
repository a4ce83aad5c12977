// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_CELL_KEY_H
#define CGAL_QUAD_MESHER_2_CELL_KEY_H

#include <cstdint>
#include <tuple>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The integer address of a quadtree cell: at `level` the root grid of `nx` by `ny` square
/// cells is divided into `nx*2^level` by `ny*2^level` cells, and (`i`, `j`) counts them from
/// the lower-left corner. All cell geometry is derived from the key.
struct Cell_key
{
  int level = 0;
  std::uint32_t i = 0;
  std::uint32_t j = 0;

  /// the deepest level a key can hold together with its coordinates
  static constexpr int max_level = 31;
  /// coordinates use at most this many bits
  static constexpr int coordinate_bits = 29;

  Cell_key() = default;
  Cell_key(int level_, std::uint32_t i_, std::uint32_t j_) : level(level_), i(i_), j(j_) {}

  /// a 64-bit code, unique per key, never all ones
  std::uint64_t code() const
  {
    return (std::uint64_t(level) << (2 * coordinate_bits)) | (std::uint64_t(i) << coordinate_bits)
           | std::uint64_t(j);
  }

  static Cell_key from_code(std::uint64_t c)
  {
    const std::uint64_t mask = (std::uint64_t(1) << coordinate_bits) - 1;
    return Cell_key(int(c >> (2 * coordinate_bits)), std::uint32_t((c >> coordinate_bits) & mask),
                    std::uint32_t(c & mask));
  }

  Cell_key parent() const { return Cell_key(level - 1, i >> 1, j >> 1); }
  Cell_key child(int dx, int dy) const { return Cell_key(level + 1, 2 * i + dx, 2 * j + dy); }

  friend bool operator==(const Cell_key& a, const Cell_key& b)
  {
    return a.level == b.level && a.i == b.i && a.j == b.j;
  }
  friend bool operator!=(const Cell_key& a, const Cell_key& b) { return !(a == b); }
  friend bool operator<(const Cell_key& a, const Cell_key& b)
  {
    return std::tie(a.level, a.i, a.j) < std::tie(b.level, b.i, b.j);
  }
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_CELL_KEY_H
