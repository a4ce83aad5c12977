// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_CELL_KEY_H
#define CGAL_QUAD_MESHER_2_CELL_KEY_H

#include <cstdint>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// An unsigned integer of 128 bits (a GCC and Clang extension): the codes of cells and
/// lattice vertices use its low 96 bits.
__extension__ typedef unsigned __int128 Key_code;

/// \ingroup PkgQuadMesher2Ref
/// The integer address of a quadtree cell: at `level` the root grid of `nx` by `ny` square
/// cells is divided into `nx*2^level` by `ny*2^level` cells, and (`i`, `j`) counts them from
/// the lower-left corner. All cell geometry is derived from the key.
///
/// The members are bit-fields, so that a key takes 16 bytes: copy them, do not bind
/// references to them.
struct Cell_key
{
  std::uint64_t i : 56;
  int level : 8;
  std::uint64_t j;

  /// the deepest level a code can hold (6 bits; all ones are left to mark empty map slots)
  static constexpr int max_level = 62;
  /// coordinates use at most this many bits
  static constexpr int coordinate_bits = 45;

  Cell_key() : i(0), level(0), j(0) {}
  Cell_key(int level_, std::uint64_t i_, std::uint64_t j_) : i(i_), level(level_), j(j_) {}

  /// a code of 96 bits, unique per key: `level << 90 | i << 45 | j`; its bits 64 to 95 are
  /// never all ones
  Key_code code() const
  {
    // in 64-bit halves: shifts of 128-bit integers cost several instructions each
    const std::uint64_t lo = (std::uint64_t(i) << coordinate_bits) | j;
    const std::uint64_t hi = (std::uint64_t(i) >> (64 - coordinate_bits))
                             | (std::uint64_t(level) << (2 * coordinate_bits - 64));
    return (Key_code(hi) << 64) | lo;
  }

  static Cell_key from_code(Key_code c)
  {
    const std::uint64_t mask = (std::uint64_t(1) << coordinate_bits) - 1;
    return Cell_key(int(c >> (2 * coordinate_bits)), std::uint64_t(c >> coordinate_bits) & mask,
                    std::uint64_t(c) & mask);
  }

  Cell_key parent() const { return Cell_key(level - 1, i >> 1, j >> 1); }
  Cell_key child(int dx, int dy) const
  {
    return Cell_key(level + 1, 2 * std::uint64_t(i) + dx, 2 * j + dy);
  }

  friend bool operator==(const Cell_key& a, const Cell_key& b)
  {
    return a.level == b.level && a.i == b.i && a.j == b.j;
  }
  friend bool operator!=(const Cell_key& a, const Cell_key& b) { return !(a == b); }
  friend bool operator<(const Cell_key& a, const Cell_key& b)
  {
    if(a.level != b.level)
      return a.level < b.level;
    if(a.i != b.i)
      return a.i < b.i;
    return a.j < b.j;
  }
};

static_assert(6 + 2 * Cell_key::coordinate_bits <= 96, "cell codes must fit in 96 bits");

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_CELL_KEY_H
