// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H
#define CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Open-addressing hash map from 64-bit integer keys to 32-bit values. Cell and vertex keys
// are looked up millions of times per mesh; std::unordered_map's node allocations would
// dominate both time and memory there.
class Key_map
{
public:
  static constexpr std::uint64_t empty_key = ~std::uint64_t(0);

  explicit Key_map(std::size_t expected = 16) { reserve(expected); }

  void reserve(std::size_t expected)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * expected + 2)
      capacity *= 2;
    if(capacity > m_slots.size())
      rehash(capacity);
  }

  std::size_t size() const { return m_size; }

  const std::uint32_t* find(std::uint64_t key) const
  {
    for(std::size_t slot = hash(key) & m_mask;; slot = (slot + 1) & m_mask) {
      if(m_slots[slot].key == key)
        return &m_slots[slot].value;
      if(m_slots[slot].key == empty_key)
        return nullptr;
    }
  }

  std::uint32_t* find(std::uint64_t key)
  {
    return const_cast<std::uint32_t*>(static_cast<const Key_map&>(*this).find(key));
  }

  // Inserts (key, value) unless key is present; returns the stored value and whether it
  // was inserted.
  std::pair<std::uint32_t*, bool> insert(std::uint64_t key, std::uint32_t value)
  {
    if(2 * (m_size + 1) > m_slots.size())
      rehash(2 * m_slots.size());
    for(std::size_t slot = hash(key) & m_mask;; slot = (slot + 1) & m_mask) {
      Slot& s = m_slots[slot];
      if(s.key == key)
        return { &s.value, false };
      if(s.key == empty_key) {
        s.key = key;
        s.value = value;
        ++m_size;
        return { &s.value, true };
      }
    }
  }

  template <class Function>
  void for_each(Function f) const
  {
    for(const Slot& s : m_slots)
      if(s.key != empty_key)
        f(s.key, s.value);
  }


private:
  static std::size_t hash(std::uint64_t x)
  {
    // splitmix64 finaliser: keys differ in low bits only, so they need mixing.
    x ^= x >> 30; x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27; x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return static_cast<std::size_t>(x);
  }

  // key and value side by side: one cache miss per probe, not two
  struct Slot
  {
    std::uint64_t key;
    std::uint32_t value;
  };

  void rehash(std::size_t capacity)
  {
    std::vector<Slot> slots(capacity, Slot{ empty_key, 0 });
    std::size_t mask = capacity - 1;
    for(const Slot& old : m_slots) {
      if(old.key == empty_key)
        continue;
      std::size_t s = hash(old.key) & mask;
      while(slots[s].key != empty_key)
        s = (s + 1) & mask;
      slots[s] = old;
    }
    m_slots.swap(slots);
    m_mask = mask;
  }

  std::vector<Slot> m_slots;
  std::size_t m_size = 0;
  std::size_t m_mask = 0;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H
