// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_READ_XY_H
#define CGAL_QUAD_MESHER_2_IO_READ_XY_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>

#include <array>
#include <cstddef>
#include <exception>
#include <istream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
namespace internal {

template <class K>
bool read_xy_impl(std::string&& text, const std::string& source, Domain_2<K>& out, std::string* error,
                  Duplicate_points duplicates)
{
  return guarded_read(source, out, error, [&](std::string& msg) {
    Text_lines r(std::move(text), source);
    Vertex_list v;
    v.source = source;
    v.base = 1;
    v.xy.reserve(r.text().size() / 16 + 1);
    v.lines.reserve(r.text().size() / 16 + 1);
    bool ok = true;
    while(ok && r.next()) {
      double x = 0, y = 0;
      std::string problem;
      if(!read_coordinate(r[0], x, problem, [&]() { return std::string("the x coordinate"); }) ||
         (r.size() >= 2 && !read_coordinate(r[1], y, problem, [&]() { return std::string("the y coordinate"); }))) {
        msg = r.here() + problem;
        ok = false;
      } else if(r.size() < 2) {
        msg = r.here() + "only one coordinate (expected: x y)";
        ok = false;
      } else if(r.size() >= 3) {
        double z;
        if(r.size() > 3) {
          msg = r.here() + "unexpected text " + quote(r[3]) + " after the coordinates (expected: x y, or x y 0)";
          ok = false;
        } else if(!parse_double(r[2], z)) {
          msg = r.here() + "unexpected text " + quote(r[2]) + " after the coordinates (expected: x y, or x y 0)";
          ok = false;
        } else if(z != 0) {
          msg = r.here() + "non-zero third coordinate " + quote(r[2]) +
                ": only 2D input is accepted (a third column must be 0)";
          ok = false;
        }
      }
      if(ok) {
        v.xy.push_back({x, y});
        v.lines.push_back(r.line());
      }
    }
    if(ok && v.xy.empty()) {
      msg = r.where(r.end_line()) + (r.is_empty() ? "empty file" : "no data (the file holds only comments or blank lines)");
      ok = false;
    }
    if(ok && duplicates == Duplicate_points::REJECT) {
      std::size_t a = 0, b = 0;
      if(find_duplicate_point(v.xy, a, b)) {
        msg = r.where(v.lines[b]) + "duplicate point: point " + std::to_string(b + 1) + " (line " + std::to_string(v.lines[b]) +
              ") and point " + std::to_string(a + 1) + " (line " + std::to_string(v.lines[a]) + ") are both at " +
              format_point(v.xy[b][0], v.xy[b][1]);
        ok = false;
      }
    }
    if(ok) {
      append_points<K>(v.xy, out.points);
      out.point_labels = file_labels(v.base, v.lines);
      return true;
    }
    return false;
  });
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Reads a point cloud from plain text into `out` (replacing its content; no segments, no
/// holes): one point `x y` per line, separated by blanks or tabs. Blank lines and `#`
/// comments (to the end of the line) are allowed. A third column is accepted only if it is
/// exactly 0 on that line (a planar export from a 3D tool); a non-zero third column or a
/// fourth column is an error, since silently dropping z would change the geometry.
/// Points are numbered 1, 2, ... in the order of the file in messages.
///
/// Rejected with one message `SOURCE:LINE: problem` in `*error` (and `out` left empty):
/// empty input, non-numeric or trailing text, a missing y, non-finite or too large
/// (|v| > 1e150) coordinates, and duplicate points. Never throws.
template <class K>
bool read_xy(std::istream& in, Domain_2<K>& out, std::string* error = nullptr,
             const std::string& source_name = "<stream>",
             Duplicate_points duplicates = Duplicate_points::REJECT)
{
  std::string text, msg;
  if(!internal::slurp(in, text, source_name, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_xy_impl(std::move(text), source_name, out, error, duplicates);
}

/// \ingroup PkgQuadMesher2IO
/// Reads the point file `filename`; see the stream overload.
template <class K>
bool read_xy(const std::string& filename, Domain_2<K>& out, std::string* error = nullptr,
             Duplicate_points duplicates = Duplicate_points::REJECT)
{
  std::string text, msg;
  if(!internal::slurp_file(filename, text, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_xy_impl(std::move(text), filename, out, error, duplicates);
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_READ_XY_H
