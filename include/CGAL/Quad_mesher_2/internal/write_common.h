// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Plumbing shared by the mesh writers of `IO/`: index checks, stream-state saving and the
// filename-to-stream wrapper. Nothing here throws.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_WRITE_COMMON_H
#define CGAL_QUAD_MESHER_2_INTERNAL_WRITE_COMMON_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include <cstddef>
#include <fstream>
#include <ios>
#include <ostream>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// `true` if every quad index refers to an entry of `mesh.points`.
template <class Point_2>
bool quad_indices_in_range(const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t n = mesh.points.size();
  for(const auto& q : mesh.quads)
    for(std::size_t v : q)
      if(v >= n)
        return false;
  return true;
}

/// Restores the precision and format flags of a stream on destruction.
class Stream_format_saver
{
public:
  explicit Stream_format_saver(std::ostream& os)
    : m_os(os), m_flags(os.flags()), m_precision(os.precision())
  {}
  ~Stream_format_saver()
  {
    m_os.flags(m_flags);
    m_os.precision(m_precision);
  }
  Stream_format_saver(const Stream_format_saver&) = delete;
  Stream_format_saver& operator=(const Stream_format_saver&) = delete;

private:
  std::ostream& m_os;
  std::ios_base::fmtflags m_flags;
  std::streamsize m_precision;
};

/// Runs `write(stream)` on `stream`, catching every exception (a stream with exceptions
/// enabled, or `std::bad_alloc`): returns `false` on an exception or a failed stream.
template <class Write>
bool guarded_write(std::ostream& os, Write&& write)
{
  if(!os.good())
    return false;
  try {
    Stream_format_saver saver(os);
    if(!write(os))
      return false;
    os.flush();
    return os.good();
  } catch(...) {
    return false;
  }
}

/// Opens `filename` for writing and runs `write(stream)`; `false` if the file cannot be
/// opened, the writer fails, or closing the file fails.
template <class Write>
bool write_to_file(const std::string& filename, Write&& write)
{
  try {
    std::ofstream os(filename, std::ios::out | std::ios::trunc);
    if(!os.is_open())
      return false;
    if(!write(os))
      return false;
    os.close();
    return !os.fail();
  } catch(...) {
    return false;
  }
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_WRITE_COMMON_H
