// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_REFINEMENT_ROUNDS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_REFINEMENT_ROUNDS_H

#include <cstddef>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Which valid round `Quadtree_mesher_2::run()` keeps, and whether it may refine again for
/// angles. Each round refines only where quads were out, so a domain with many small features
/// needs many rounds: the angle rounds go on while they lower the count of quads with an
/// unforced angle out, and for at most `max_stalled` valid rounds that do not (the next, finer
/// strip may be paired better). Invalid rounds are refined for validity and angles alike and count for neither.
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

/// The policy of `Quadtree_mesher_2::run()`'s refinement rounds: whether a round that asked
/// for finer cells is followed by another, and why the rounds ended. `End` is the mesher's
/// `Rounds_end`.
///
/// Each round builds the quadtree anew, the same way, with the requests of every round before
/// it: if the last round's requests split no cell (finer cells refused), this round repeats
/// the last, figure for figure, and so would every round after it, to the budget. So the last
/// round's outcome is final: an invalid one ends the rounds with its error (`repeat_error()`);
/// a valid one is run again and kept, or not, as usual.
template <class End>
class Refinement_rounds
{
public:
  Refinement_rounds(int max_rounds, int max_stalled_angle_rounds)
    : m_max_rounds(max_rounds), m_angles(max_stalled_angle_rounds)
  {}

  /// starts the next round
  void start_round() { ++m_round; }
  /// the number of the current round, from 1 (0 before any)
  int round() const { return m_round; }
  /// why the rounds ended (`End::NONE` while they go on, or if they ended well)
  End end() const { return m_end; }

  /// once the round's quadtree is built (`refined`: whether the requests it applied first
  /// split a cell): true if this round repeats the last, an invalid one; then the rounds end,
  /// without it
  bool repeats_a_failure(bool refined)
  {
    m_repeats = m_round > 1 && !refined;
    if(!m_repeats || m_repeat_error.empty())
      return false;
    --m_round;
    m_end = End::FINEST_CELLS;
    return true;
  }
  /// the error of the last invalid round, which a repeat of it ends with
  const std::string& repeat_error() const { return m_repeat_error; }

  /// after a round that lost isolated points: true if it queued `added` requests for them and
  /// the budget allows another round, which fails with `error` if it repeats this one
  bool refine_for_lost_points(std::size_t added, std::string error)
  {
    if(added > 0 && m_round < m_max_rounds) {
      m_repeat_error = std::move(error);
      return true;
    }
    m_end = m_round < m_max_rounds ? End::FINEST_CELLS : End::ROUND_BUDGET;
    return false;
  }

  /// after a round past the buffer stages that asked for finer cells (`valid`: the whole mesh
  /// passed its check; `bad`: its quads with an unforced angle out; `added`: the requests it
  /// queued): true if another round follows, with `improved` whether this one is the best
  /// valid round so far (to be kept). `error()` gives the message a repeat of an invalid round
  /// ends with, asked only then.
  template <class Error>
  bool refine_for_buffer(bool valid, std::size_t bad, std::size_t added, bool& improved, const Error& error)
  {
    improved = m_angles.record(valid, bad);
    if(added > 0 && m_round < m_max_rounds && m_angles.go_on() && !m_repeats) {
      m_repeat_error = valid ? std::string() : error();
      return true;
    }
    m_end = added == 0 || m_repeats      ? End::FINEST_CELLS
            : m_round >= m_max_rounds ? End::ROUND_BUDGET
                                      : End::STALLED;
    return false;
  }

  /// whether a valid round was kept, to return when the rounds end on a worse one
  bool has_valid_round() const { return m_angles.has_valid_round(); }
  /// whether a round with `bad` quads out is as good as the best valid round
  bool is_best(std::size_t bad) const { return bad == m_angles.best(); }

private:
  int m_max_rounds;
  Angle_rounds m_angles;
  int m_round = 0;
  bool m_repeats = false;
  End m_end = End::NONE;
  std::string m_repeat_error;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_REFINEMENT_ROUNDS_H
