// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// A 128-bit hash of the state a computation reads, for results kept while that state is
// unchanged: the moves of the buffer stages (move_memo.h), the gaps of a strip's pairing
// (strip_pairing.h).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_STATE_HASH_H
#define CGAL_QUAD_MESHER_2_INTERNAL_STATE_HASH_H

#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>

#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// A 128-bit hash of a computation's inputs, fed word by word: two lanes with different
/// seeds and mixers, so that two states of one run agree by chance with odds of about 2^-128
/// per pair.
/// Two lanes of 64 bits, each taking a word in an xxHash64 round (a multiply, a rotation, a
/// multiply: one-to-one in the lane for a given word, and in the word for a given lane), each
/// read out through splitmix64's finaliser. The lanes differ in their start and their
/// multipliers.
class State_hash
{
public:
  void add(std::uint64_t w)
  {
    m_a = rotl(m_a + w * 0xC2B2AE3D27D4EB4Full, 31) * 0x9E3779B185EBCA87ull;
    m_b = rotl(m_b ^ (w * 0x165667B19E3779F9ull), 27) * 0xD6E8FEB86659FD93ull;
  }
  void add(double x)
  {
    std::uint64_t w;
    std::memcpy(&w, &x, sizeof w);
    add(w);
  }
  void add(const Point_2d& p)
  {
    add(p.x());
    add(p.y());
  }
  std::uint64_t first() const { return mix(m_a) | 1; } // never 0: 0 marks an empty slot
  std::uint64_t second() const { return mix(m_b); }

private:
  static std::uint64_t rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }
  // splitmix64's finaliser
  static std::uint64_t mix(std::uint64_t z)
  {
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  std::uint64_t m_a = 0x243F6A8885A308D3ull, m_b = 0x13198A2E03707344ull;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_STATE_HASH_H
