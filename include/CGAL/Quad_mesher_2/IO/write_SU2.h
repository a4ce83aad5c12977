// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_SU2_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_SU2_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` in SU2's native mesh format (`.su2`, ASCII), for the SU2 CFD suite:
/// `NDIME= 2`; `NELEM=` and one line `9 a b c d i` per quad (type 9, the quadrilateral, its
/// 0-based point indices counter-clockwise, then its index i); `NPOIN=` and one line `x y i`
/// per point; `NMARK=` and, per boundary marker of `mesh.boundary_edges` by increasing
/// marker, `MARKER_TAG=` the marker itself (`3`: meshio, for one, reads only numbers there;
/// SU2's configuration names it so) and `MARKER_ELEMS=` with one line `3 a b` (type 3, the
/// line) per boundary edge, directed with the domain on its left. Coordinates are converted
/// with `CGAL::to_double` and written as the shortest decimals that read back as the same
/// doubles. A single-zone SU2 file has no place for `mesh.regions`: they are left out.
/// Returns `false`, without throwing, if the stream fails or an index is out of range.
template <class Point_2>
bool write_SU2(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::mesh_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    const std::vector<Quad_mesher_2::internal::Marker_group> groups = Quad_mesher_2::internal::marker_groups(mesh);
    Quad_mesher_2::internal::Text_buffer text(out);
    text << "NDIME= 2\nNELEM= " << mesh.quads.size() << '\n';
    std::size_t i = 0;
    for(const auto& q : mesh.quads)
      text << "9 " << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << ' ' << i++ << '\n';
    text << "NPOIN= " << mesh.points.size() << '\n';
    i = 0;
    for(const Point_2& p : mesh.points)
      text << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << ' ' << i++ << '\n';
    text << "NMARK= " << groups.size() << '\n';
    for(const auto& g : groups) {
      text << "MARKER_TAG= " << g.marker << "\nMARKER_ELEMS= " << g.edges.size() << '\n';
      for(std::size_t e : g.edges)
        text << "3 " << mesh.boundary_edges[e].v0 << ' ' << mesh.boundary_edges[e].v1 << '\n';
    }
    text.flush();
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to the file `filename` in SU2 format (see the stream overload).
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_SU2(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return write_SU2(os, mesh); });
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_SU2_H
