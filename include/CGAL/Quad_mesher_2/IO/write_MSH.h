// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_MSH_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_MSH_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as a Gmsh MSH 4.1 ASCII file: `$MeshFormat` (4.1 0 8), `$Entities` with a
/// single surface (tag 1) whose bounding box is that of the points, `$Nodes` (one block on
/// that surface, node tags 1..n in the order of `mesh.points`, z = 0) and `$Elements` (one
/// block of type 3, the 4-node quadrangle, element tags 1..m in the order of `mesh.quads`).
/// Coordinates are converted with `CGAL::to_double`; the node coordinates are written as the
/// shortest decimals that read back as the same doubles, the bounding box with `max_digits10`
/// digits.
/// Returns `false`, without throwing, if the stream fails or a quad index is out of range.
/// The stream's precision and format flags are restored.
template <class Point_2>
bool write_MSH(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::quad_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    const std::size_t n = mesh.points.size(), m = mesh.quads.size();
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

    double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
    for(std::size_t i = 0; i < n; ++i) {
      const double x = CGAL::to_double(mesh.points[i].x()), y = CGAL::to_double(mesh.points[i].y());
      if(i == 0) {
        xmin = xmax = x;
        ymin = ymax = y;
      } else {
        xmin = (std::min)(xmin, x);
        xmax = (std::max)(xmax, x);
        ymin = (std::min)(ymin, y);
        ymax = (std::max)(ymax, y);
      }
    }
    // numPoints numCurves numSurfaces numVolumes; then the surface: tag, bounding box,
    // numPhysicalTags, numBoundingCurves.
    out << "$Entities\n0 0 1 0\n1 " << xmin << ' ' << ymin << " 0 " << xmax << ' ' << ymax
        << " 0 0 0\n$EndEntities\n";

    out << "$Nodes\n";
    if(n == 0) {
      out << "0 0 0 0\n";
    } else {
      out << "1 " << n << " 1 " << n << '\n'; // numEntityBlocks numNodes minNodeTag maxNodeTag
      out << "2 1 0 " << n << '\n';           // entityDim entityTag parametric numNodesInBlock
      Quad_mesher_2::internal::Text_buffer text(out);
      for(std::size_t i = 1; i <= n; ++i)
        text << i << '\n';
      for(const Point_2& p : mesh.points)
        text << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << " 0\n";
      text.flush();
    }
    out << "$EndNodes\n";

    out << "$Elements\n";
    if(m == 0) {
      out << "0 0 0 0\n";
    } else {
      out << "1 " << m << " 1 " << m << '\n'; // numEntityBlocks numElements minTag maxTag
      out << "2 1 3 " << m << '\n';           // entityDim entityTag elementType numElements
      Quad_mesher_2::internal::Text_buffer text(out);
      std::size_t tag = 1;
      for(const auto& q : mesh.quads)
        text << tag++ << ' ' << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << ' ' << q[3] + 1 << '\n';
      text.flush();
    }
    out << "$EndElements\n";
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to the file `filename` in MSH 4.1 ASCII format (see the stream overload).
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_MSH(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return write_MSH(os, mesh); });
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_MSH_H
