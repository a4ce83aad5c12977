// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H
#define CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H

#include <CGAL/Quad_mesher_2/Cell_key.h>
#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Lattice vertices (X, Y), 0 <= X, Y < 2^47, as 96-bit keys: X << 48 | Y.
constexpr int lattice_key_bits = 47;
inline Key_code lattice_key(std::uint64_t X, std::uint64_t Y)
{
  CGAL_assertion(X >> lattice_key_bits == 0 && Y >> lattice_key_bits == 0);
  return (Key_code(X >> 16) << 64) | ((X << 48) | Y); // in 64-bit halves: cheaper
}
inline std::int64_t lattice_key_x(Key_code key) { return std::int64_t(key >> 48); }
inline std::int64_t lattice_key_y(Key_code key)
{
  return std::int64_t(std::uint64_t(key) & ((std::uint64_t(1) << 48) - 1));
}

// Open-addressing hash map from 96-bit integer keys (cell codes, lattice keys; bits 64 to 95
// never all ones) to 32-bit values. Cell and vertex keys are looked up millions of times per
// mesh; std::unordered_map's node allocations would dominate both time and memory there.
class Key_map
{
public:
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

  const std::uint32_t* find(Key_code key) const
  {
    const std::uint64_t lo = std::uint64_t(key);
    const std::uint32_t hi = std::uint32_t(key >> 64);
    for(std::size_t slot = hash(lo, hi) & m_mask;; slot = (slot + 1) & m_mask) {
      const Slot& s = m_slots[slot];
      if(s.lo == lo && s.hi == hi)
        return &s.value;
      if(s.hi == empty_hi)
        return nullptr;
    }
  }

  // Starts loading the slot where the probe for `key` begins, so that a find or insert of it
  // a little later does not wait for memory: a mesh's vertex map is far larger than the
  // cache. A hint only.
  void prefetch(Key_code key) const
  {
    __builtin_prefetch(&m_slots[hash(std::uint64_t(key), std::uint32_t(key >> 64)) & m_mask]);
  }

  std::uint32_t* find(Key_code key)
  {
    return const_cast<std::uint32_t*>(static_cast<const Key_map&>(*this).find(key));
  }

  // Inserts (key, value) unless key is present; returns the stored value and whether it
  // was inserted.
  std::pair<std::uint32_t*, bool> insert(Key_code key, std::uint32_t value)
  {
    CGAL_precondition((key >> 96) == 0 && std::uint32_t(key >> 64) != empty_hi);
    if(2 * (m_size + 1) > m_slots.size())
      rehash(2 * m_slots.size());
    const std::uint64_t lo = std::uint64_t(key);
    const std::uint32_t hi = std::uint32_t(key >> 64);
    for(std::size_t slot = hash(lo, hi) & m_mask;; slot = (slot + 1) & m_mask) {
      Slot& s = m_slots[slot];
      if(s.lo == lo && s.hi == hi)
        return { &s.value, false };
      if(s.hi == empty_hi) {
        s.lo = lo;
        s.hi = hi;
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
      if(s.hi != empty_hi)
        f((Key_code(s.hi) << 64) | Key_code(s.lo), s.value);
  }


private:
  static constexpr std::uint32_t empty_hi = ~std::uint32_t(0);

  static std::size_t hash(std::uint64_t lo, std::uint32_t hi)
  {
    // splitmix64 finaliser: keys differ in low bits only, so they need mixing.
    std::uint64_t x = lo ^ (std::uint64_t(hi) * 0x9e3779b97f4a7c15ULL);
    x ^= x >> 30; x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27; x *= 0x94d049bb133111ebULL;
    x ^= x >> 31;
    return static_cast<std::size_t>(x);
  }

  // the key's 96 bits and the value side by side in 16 bytes: one cache miss per probe
  struct Slot
  {
    std::uint64_t lo;
    std::uint32_t hi;
    std::uint32_t value;
  };
  static_assert(sizeof(Slot) == 16, "a slot takes 16 bytes");
  // probed at random: with 4 kB pages nearly every probe of a large map also misses the TLB
  typedef std::vector<Slot, Huge_page_allocator<Slot>> Slots;

  void rehash(std::size_t capacity)
  {
    Slots slots(capacity, Slot{ 0, empty_hi, 0 });
    std::size_t mask = capacity - 1;
    for(const Slot& old : m_slots) {
      if(old.hi == empty_hi)
        continue;
      std::size_t s = hash(old.lo, old.hi) & mask;
      while(slots[s].hi != empty_hi)
        s = (s + 1) & mask;
      slots[s] = old;
    }
    m_slots.swap(slots);
    m_mask = mask;
  }

  Slots m_slots;
  std::size_t m_size = 0;
  std::size_t m_mask = 0;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_KEY_MAP_H
