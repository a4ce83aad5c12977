// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_OFF_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_OFF_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <iomanip>
#include <limits>
#include <ostream>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as an ASCII OFF file: header `OFF`, counts, one `x y 0` line per point
/// (converted with `CGAL::to_double`, written as the shortest decimals that read back as the
/// same doubles), then one `4 a b c d` line per quad (0-based indices).
/// CGAL's own `CGAL::IO::write_OFF` needs 3D points and does not compile with EPECK
/// polygon soups; this writer works for any 2D kernel point.
/// Returns `false`, without throwing, if the stream fails or a quad index is out of range.
/// The stream's precision and format flags are restored.
template <class Point_2>
bool write_OFF(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::quad_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "OFF\n" << mesh.points.size() << ' ' << mesh.quads.size() << " 0\n";
    Quad_mesher_2::internal::Text_buffer text(out);
    for(const Point_2& p : mesh.points)
      text << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << " 0\n";
    for(const auto& q : mesh.quads)
      text << "4 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
    text.flush();
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to the file `filename` in OFF format (see the stream overload).
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_OFF(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return write_OFF(os, mesh); });
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_OFF_H
