// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
#define CGAL_QUAD_MESHER_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>

#if defined(__linux__)
#include <sys/mman.h> // madvise
#endif

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// The allocator of the large arrays a mesh of millions of quads fills once: blocks of 4 MB
// and more ask the system for 2 MB pages where it offers them on request (Linux's transparent
// huge pages, "madvise" mode included). A fresh block costs a page fault per page first
// touched, 512 times fewer with 2 MB pages (faults were a third of the pipeline's time on a
// million quads), and random probes, as a hash map's, miss the TLB far less often. A hint
// only: the contents are the same either way; elsewhere it is std::allocator.
template <class T>
struct Huge_page_allocator
{
  typedef T value_type;
  Huge_page_allocator() = default;
  template <class U>
  Huge_page_allocator(const Huge_page_allocator<U>&) {}

  T* allocate(std::size_t n)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) {
      void* p = std::aligned_alloc(huge_page, (n * sizeof(T) + huge_page - 1) / huge_page * huge_page);
      if(p == nullptr)
        throw std::bad_alloc();
      ::madvise(p, n * sizeof(T), MADV_HUGEPAGE);
      return static_cast<T*>(p);
    }
#endif
    return std::allocator<T>().allocate(n);
  }
  void deallocate(T* p, std::size_t n)
  {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if(is_large(n)) {
      std::free(p);
      return;
    }
#endif
    std::allocator<T>().deallocate(p, n);
  }
  template <class U>
  bool operator==(const Huge_page_allocator<U>&) const { return true; }
  template <class U>
  bool operator!=(const Huge_page_allocator<U>&) const { return false; }

private:
  static constexpr std::size_t huge_page = std::size_t(1) << 21;
  static bool is_large(std::size_t n) { return n * sizeof(T) >= 2 * huge_page; }
};

// Reserves room for `n` elements in `v`, a vector whose allocator is fixed (a mesh's), and
// asks for 2 MB pages on the whole ones within it, as Huge_page_allocator does: for arrays of
// millions filled after the reserve.
template <class Vector>
void reserve_on_huge_pages(Vector& v, std::size_t n)
{
  v.reserve(n);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t huge_page = std::uintptr_t(1) << 21;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (begin + huge_page - 1) & ~(huge_page - 1);
  const std::uintptr_t last = (begin + n * sizeof(typename Vector::value_type)) & ~(huge_page - 1);
  if(last > first + huge_page) // as Huge_page_allocator: 4 MB and more
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#endif
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_HUGE_PAGE_ALLOCATOR_H
