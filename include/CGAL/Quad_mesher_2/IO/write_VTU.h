// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_VTU_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_VTU_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as a VTK XML unstructured grid (`.vtu`, ASCII), readable by ParaView: the
/// points (z = 0, `Float64`, the shortest decimals that read back as the same doubles), the
/// quads as cells of type `VTK_QUAD` (9) with `Int64` connectivity and offsets, and two cell
/// fields for colouring:
/// `scaled_jacobian` (minimum over the corners) and `max_angle_deviation` (largest
/// |angle - 90| over the corners, in degrees), both computed in double.
/// Returns `false`, without throwing, if the stream fails or a quad index is out of range.
/// The stream's precision and format flags are restored.
template <class Point_2>
bool write_VTU(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::quad_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    const std::size_t n = mesh.points.size(), m = mesh.quads.size();
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << m << "\">\n";

    out << "      <Points>\n"
           "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    Quad_mesher_2::internal::Text_buffer text(out);
    for(const Point_2& p : mesh.points)
      text << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << " 0\n";
    text.flush();
    out << "        </DataArray>\n"
           "      </Points>\n";

    out << "      <Cells>\n"
           "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
    for(const auto& q : mesh.quads)
      text << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
    text.flush();
    out << "        </DataArray>\n"
           "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
    for(std::size_t i = 1; i <= m; ++i)
      out << 4 * i << (i % 16 == 0 || i == m ? '\n' : ' ');
    out << "        </DataArray>\n"
           "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
    for(std::size_t i = 1; i <= m; ++i)
      out << 9 << (i % 32 == 0 || i == m ? '\n' : ' ');
    out << "        </DataArray>\n"
           "      </Cells>\n";

    // Cell quality fields; 6 significant digits are plenty for colouring.
    out << std::setprecision(6);
    out << "      <CellData Scalars=\"max_angle_deviation\">\n"
           "        <DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n";
    auto corners = [&](const std::array<std::size_t, 4>& q) {
      std::array<Quad_mesher_2::internal::Point_2d, 4> g;
      for(int k = 0; k < 4; ++k)
        g[k] = Quad_mesher_2::internal::to_point_2d(mesh.points[q[k]]);
      return g;
    };
    for(const auto& q : mesh.quads)
      out << Quad_mesher_2::internal::quad_scaled_jacobian(corners(q)) << '\n';
    out << "        </DataArray>\n"
           "        <DataArray type=\"Float64\" Name=\"max_angle_deviation\" format=\"ascii\">\n";
    for(const auto& q : mesh.quads)
      out << Quad_mesher_2::internal::quad_max_angle_deviation(corners(q)) << '\n';
    out << "        </DataArray>\n"
           "      </CellData>\n";

    out << "    </Piece>\n"
           "  </UnstructuredGrid>\n"
           "</VTKFile>\n";
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to the file `filename` in VTU format (see the stream overload).
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_VTU(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return write_VTU(os, mesh); });
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_VTU_H
