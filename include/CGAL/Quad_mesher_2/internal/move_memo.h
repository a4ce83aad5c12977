// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Where a local move of the buffer stages took a vertex, by the state it started from, kept
// from one refinement round to the next. A round rebuilds every stage, but it refines the
// quadtree only around its requests: elsewhere its moves start from the states of the round
// before and end where they did. A move whose whole starting state (every position, flag and
// shared vertex its result depends on) hashes to one seen before takes the result seen then:
// the same mesh, at the cost of a hash where the state is unchanged.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_MOVE_MEMO_H
#define CGAL_QUAD_MESHER_2_INTERNAL_MOVE_MEMO_H

#include <CGAL/Quad_mesher_2/internal/state_hash.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// The results of the moves of this round and the last, by their State_hash (see the file
/// comment). `next_round()` forgets the older round; a result looked up from the last round
/// is kept for the next.
class Move_memo
{
public:
  /// true, with the result in `to`, if a move from this state was recorded in this round or
  /// the last
  bool find(const State_hash& h, Point_2d& to)
  {
    if(m_current.find(h, to)) return true;
    if(!m_last.find(h, to)) return false;
    m_current.insert(h, to);
    return true;
  }
  /// records that a move from the state `h` ended at `to`
  void insert(const State_hash& h, const Point_2d& to) { m_current.insert(h, to); }
  /// to be called as a round starts
  void next_round()
  {
    std::swap(m_last, m_current);
    m_current.clear();
  }

private:
  // open addressing with linear probing, at most half full
  class Table
  {
  public:
    bool find(const State_hash& h, Point_2d& to) const
    {
      if(m_slots.empty()) return false;
      for(std::size_t i = index(h);; i = (i + 1) & mask()) {
        const Slot& s = m_slots[i];
        if(s.first == 0) return false;
        if(s.first == h.first() && s.second == h.second()) {
          to = Point_2d(s.x, s.y);
          return true;
        }
      }
    }
    void insert(const State_hash& h, const Point_2d& to)
    {
      if(2 * (m_size + 1) > m_slots.size()) grow();
      place(Slot{ h.first(), h.second(), to.x(), to.y() });
    }
    void clear()
    {
      std::fill(m_slots.begin(), m_slots.end(), Slot{});
      m_size = 0;
    }

  private:
    struct Slot
    {
      std::uint64_t first = 0, second = 0;
      double x = 0, y = 0;
    };
    std::size_t mask() const { return m_slots.size() - 1; }
    std::size_t index(const State_hash& h) const { return std::size_t(h.second()) & mask(); }
    void place(const Slot& s)
    {
      std::size_t i = std::size_t(s.second) & mask();
      while(m_slots[i].first != 0 && !(m_slots[i].first == s.first && m_slots[i].second == s.second))
        i = (i + 1) & mask();
      if(m_slots[i].first == 0) ++m_size;
      m_slots[i] = s;
    }
    void grow()
    {
      std::vector<Slot> old(m_slots.empty() ? 1024 : 2 * m_slots.size());
      old.swap(m_slots);
      m_size = 0;
      for(const Slot& s : old)
        if(s.first != 0) place(s);
    }

    std::vector<Slot> m_slots; // a power of two of them
    std::size_t m_size = 0;
  };

  Table m_current, m_last;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_MOVE_MEMO_H
