// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Plumbing shared by the mesh writers of `IO/`: index checks, the boundary edges grouped by
// marker, stream-state saving and the filename-to-stream wrapper. Nothing here throws but
// `std::bad_alloc`, which the writers catch (guarded_write()).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_WRITE_COMMON_H
#define CGAL_QUAD_MESHER_2_INTERNAL_WRITE_COMMON_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include <algorithm>
#include <charconv>
#include <cstddef>
#include <fstream>
#include <ios>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

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

/// `true` if every quad and boundary-edge index refers to an entry of `mesh.points`, and the
/// quads' regions are none or one per quad, each in `mesh.regions` (the check of the writers
/// that write the boundary edges and regions).
template <class Point_2>
bool mesh_indices_in_range(const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t n = mesh.points.size();
  for(const auto& e : mesh.boundary_edges)
    if(e.v0 >= n || e.v1 >= n)
      return false;
  if(!mesh.quad_regions.empty() && mesh.quad_regions.size() != mesh.quads.size())
    return false;
  for(std::size_t r : mesh.quad_regions)
    if(r >= mesh.regions.size())
      return false;
  return quad_indices_in_range(mesh);
}

/// Whether the writers write the mesh's regions: more than one, or one with an attribute. The
/// mesh of a single region without one keeps the one group `domain`.
template <class Point_2>
bool has_named_regions(const Quad_mesh_2<Point_2>& mesh)
{
  return !mesh.quad_regions.empty() && (mesh.regions.size() > 1 || mesh.regions.front().has_attribute);
}

/// the quads of each region of `mesh`, in order
template <class Point_2>
std::vector<std::vector<std::size_t>> region_quads(const Quad_mesh_2<Point_2>& mesh)
{
  std::vector<std::vector<std::size_t>> quads(mesh.regions.size());
  for(std::size_t q = 0; q < mesh.quad_regions.size(); ++q)
    quads[mesh.quad_regions[q]].push_back(q);
  return quads;
}

/// The name the writers give a region: `region_3` for tag 3.
inline std::string region_name(int tag) { return "region_" + std::to_string(tag); }

/// The boundary edges of one marker: indices into `Quad_mesh_2::boundary_edges`, in order.
struct Marker_group
{
  int marker;
  std::vector<std::size_t> edges;
};

/// The boundary edges of `mesh` grouped by marker, markers increasing: every writer lists the
/// markers in this order.
template <class Point_2>
std::vector<Marker_group> marker_groups(const Quad_mesh_2<Point_2>& mesh)
{
  std::vector<std::size_t> order(mesh.boundary_edges.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return mesh.boundary_edges[a].marker < mesh.boundary_edges[b].marker;
  });
  std::vector<Marker_group> groups;
  for(std::size_t i : order) {
    const int marker = mesh.boundary_edges[i].marker;
    if(groups.empty() || groups.back().marker != marker)
      groups.push_back({ marker, {} });
    groups.back().edges.push_back(i);
  }
  return groups;
}

/// The name the writers give marker `m`'s group: `marker_3`, or `marker_m3` for -3 (a minus
/// sign is not allowed in Abaqus names).
inline std::string marker_name(int m)
{
  return m < 0 ? "marker_m" + std::to_string(-static_cast<long long>(m)) : "marker_" + std::to_string(m);
}

/// Buffered text for the writers' long blocks of numbers: numbers are formatted with
/// `std::to_chars` and handed to the stream in pieces of about 64 KiB. Formatting through the
/// stream cost most of a write (a second per 10^6 quads). A double is written as the shortest
/// text that reads back as the same double or, given `significant_digits`, as `%g` with that
/// precision would. Call `flush()` at the end.
class Text_buffer
{
public:
  explicit Text_buffer(std::ostream& os, int significant_digits = 0)
    : m_os(os), m_digits(significant_digits)
  {
    m_text.reserve(piece + 64);
  }

  Text_buffer& operator<<(double x)
  {
    if(m_digits == 0)
      return put(x);
    char digits[40];
    const std::to_chars_result r =
      std::to_chars(digits, digits + sizeof(digits), x, std::chars_format::general, m_digits);
    m_text.append(digits, r.ptr);
    return spill();
  }
  Text_buffer& operator<<(char c)
  {
    m_text.push_back(c);
    return spill();
  }
  Text_buffer& operator<<(const char* s)
  {
    m_text.append(s);
    return spill();
  }
  template <class Integer, class = std::enable_if_t<std::is_integral<Integer>::value>>
  Text_buffer& operator<<(Integer i)
  {
    return put(i);
  }

  void flush()
  {
    m_os.write(m_text.data(), std::streamsize(m_text.size()));
    m_text.clear();
  }

private:
  static constexpr std::size_t piece = 1 << 16;

  template <class Number>
  Text_buffer& put(Number x)
  {
    char digits[32];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof(digits), x);
    m_text.append(digits, r.ptr);
    return spill();
  }
  Text_buffer& spill()
  {
    if(m_text.size() >= piece)
      flush();
    return *this;
  }

  std::ostream& m_os;
  int m_digits;
  std::string m_text;
};

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
