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
/// is kept for the next. A move takes one point (`Point_2d`), or several (`Moves`: a search
/// that makes room around its vertex).
class Move_memo
{
public:
  /// the points a move took and where, each by its index in the list of vertices its state
  /// names (the hash is of their places and connections, not of the mesh's numbering)
  typedef std::vector<std::pair<std::uint32_t, Point_2d>> Moves;

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

  /// as find(), for a move of several points
  bool find(const State_hash& h, Moves& moves)
  {
    std::uint32_t k;
    if(m_current_several.find(h, k)) {
      moves = m_current_moves[k];
      return true;
    }
    if(!m_last_several.find(h, k)) return false;
    moves = m_last_moves[k];
    insert(h, moves);
    return true;
  }
  /// as insert(), for a move of several points
  void insert(const State_hash& h, const Moves& moves)
  {
    m_current_several.insert(h, std::uint32_t(m_current_moves.size()));
    m_current_moves.push_back(moves);
  }

  /// to be called as a round starts
  void next_round()
  {
    std::swap(m_last, m_current);
    m_current.clear();
    std::swap(m_last_several, m_current_several);
    m_current_several.clear();
    std::swap(m_last_moves, m_current_moves);
    m_current_moves.clear();
  }

private:
  // open addressing with linear probing, at most half full
  template <class Value>
  class Table
  {
  public:
    bool find(const State_hash& h, Value& to) const
    {
      if(m_slots.empty()) return false;
      for(std::size_t i = index(h);; i = (i + 1) & mask()) {
        const Slot& s = m_slots[i];
        if(s.first == 0) return false;
        if(s.first == h.first() && s.second == h.second()) {
          to = s.value;
          return true;
        }
      }
    }
    void insert(const State_hash& h, const Value& to)
    {
      if(2 * (m_size + 1) > m_slots.size()) grow();
      place(Slot{ h.first(), h.second(), to });
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
      Value value{};
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

  Table<Point_2d> m_current, m_last;
  Table<std::uint32_t> m_current_several, m_last_several; // indices into the moves below
  std::vector<Moves> m_current_moves, m_last_moves;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_MOVE_MEMO_H
