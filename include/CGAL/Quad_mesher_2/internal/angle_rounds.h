// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_ANGLE_ROUNDS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_ANGLE_ROUNDS_H

#include <cstddef>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Which valid round `Quadtree_mesher_2::run()` keeps, and whether it may refine again for
/// angles. Each round refines only where quads were out, so a domain with many small features
/// needs many rounds: the angle rounds go on while they lower the count of quads with an
/// unforced angle out, and for at most `max_stalled` valid rounds that do not (the next, finer
/// strip may be paired better: a 25-gon kept a fan at 165.6 degrees for two rounds).
/// Invalid rounds are refined for validity and count for neither.
class Angle_rounds
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  explicit Angle_rounds(int max_stalled) : m_max_stalled(max_stalled) {}

  /// records a round (`valid`: the whole mesh passed its check; `bad`: its quads with an
  /// unforced angle out); true if it is the best valid round so far
  bool record(bool valid, std::size_t bad)
  {
    if(!valid) return false;
    if(bad < m_best) {
      m_best = bad;
      return true;
    }
    ++m_stalled;
    return false;
  }
  /// whether another round may follow the rounds recorded so far
  bool go_on() const { return m_stalled <= m_max_stalled; }
  /// the fewest quads with an unforced angle out of a valid round, `none` before one
  std::size_t best() const { return m_best; }
  bool has_valid_round() const { return m_best != none; }

private:
  int m_max_stalled;
  int m_stalled = 0;
  std::size_t m_best = none;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_ANGLE_ROUNDS_H
