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
#include <ostream>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

namespace internal {

/// `<Cells>`: the quads (`VTK_QUAD`, 9), then the boundary edges (`VTK_LINE`, 3).
template <class Point_2>
void write_vtu_cells(std::ostream& out, const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t m = mesh.quads.size(), cells = m + mesh.boundary_edges.size();
  Quad_mesher_2::internal::Text_buffer text(out);
  out << "      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const auto& q : mesh.quads)
    text << q[0] << ' ' << q[1] << ' ' << q[2] << ' ' << q[3] << '\n';
  for(const auto& e : mesh.boundary_edges)
    text << e.v0 << ' ' << e.v1 << '\n';
  text.flush();
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for(std::size_t i = 1; i <= cells; ++i)
    text << (i <= m ? 4 * i : 4 * m + 2 * (i - m)) << (i % 16 == 0 || i == cells ? '\n' : ' ');
  text.flush();
  out << "        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t i = 1; i <= cells; ++i)
    text << (i <= m ? 9 : 3) << (i % 32 == 0 || i == cells ? '\n' : ' ');
  text.flush();
  out << "        </DataArray>\n"
         "      </Cells>\n";
}

/// the cell fields `region` (each quad's region tag, 0 on the lines) and `attribute` (its
/// regional attribute, 0 where none and on the lines)
template <class Point_2>
void write_vtu_regions(std::ostream& out, const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t lines = mesh.boundary_edges.size();
  Quad_mesher_2::internal::Text_buffer text(out);
  out << "        <DataArray type=\"Int32\" Name=\"region\" format=\"ascii\">\n";
  for(std::size_t r : mesh.quad_regions)
    text << mesh.regions[r].tag << '\n';
  for(std::size_t i = 0; i < lines; ++i)
    text << "0\n";
  text.flush();
  out << "        </DataArray>\n"
         "        <DataArray type=\"Float64\" Name=\"attribute\" format=\"ascii\">\n";
  for(std::size_t r : mesh.quad_regions)
    text << mesh.regions[r].attribute << '\n';
  for(std::size_t i = 0; i < lines; ++i)
    text << "0\n";
  text.flush();
  out << "        </DataArray>\n";
}

/// `<CellData>`: the quads' quality fields, neutral values on the lines (1 and 0: a filter
/// for bad quads never picks one), and every cell's `marker`, 0 on the quads.
template <class Point_2>
void write_vtu_cell_data(std::ostream& out, const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t lines = mesh.boundary_edges.size();
  auto corners = [&](const std::array<std::size_t, 4>& q) {
    std::array<Quad_mesher_2::internal::Point_2d, 4> g;
    for(int k = 0; k < 4; ++k)
      g[k] = Quad_mesher_2::internal::to_point_2d(mesh.points[q[k]]);
    return g;
  };
  // 6 significant digits are plenty for colouring
  Quad_mesher_2::internal::Text_buffer text(out, 6);
  out << "      <CellData Scalars=\"max_angle_deviation\">\n"
         "        <DataArray type=\"Float64\" Name=\"scaled_jacobian\" format=\"ascii\">\n";
  for(const auto& q : mesh.quads)
    text << Quad_mesher_2::internal::quad_scaled_jacobian(corners(q)) << '\n';
  for(std::size_t i = 0; i < lines; ++i)
    text << "1\n";
  text.flush();
  out << "        </DataArray>\n"
         "        <DataArray type=\"Float64\" Name=\"max_angle_deviation\" format=\"ascii\">\n";
  for(const auto& q : mesh.quads)
    text << Quad_mesher_2::internal::quad_max_angle_deviation(corners(q)) << '\n';
  for(std::size_t i = 0; i < lines; ++i)
    text << "0\n";
  text.flush();
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int32\" Name=\"marker\" format=\"ascii\">\n";
  for(std::size_t i = 0; i < mesh.quads.size(); ++i)
    text << "0\n";
  for(const auto& e : mesh.boundary_edges)
    text << e.marker << '\n';
  text.flush();
  out << "        </DataArray>\n";
  if(Quad_mesher_2::internal::has_named_regions(mesh))
    write_vtu_regions(out, mesh);
  out << "      </CellData>\n";
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as a VTK XML unstructured grid (`.vtu`, ASCII), readable by ParaView: the
/// points (z = 0, `Float64`, the shortest decimals that read back as the same doubles); the
/// cells, with `Int64` connectivity and offsets: the quads first, as `VTK_QUAD` (9) in the
/// order of `mesh.quads`, so that cell i is quad i as before lines were written, then
/// `mesh.boundary_edges` as `VTK_LINE` (3); and three or five cell fields:
/// `scaled_jacobian` (minimum over the corners) and `max_angle_deviation` (largest
/// |angle - 90| over the corners, in degrees), both computed in double, for colouring (1 and
/// 0 on the lines), and `marker`, `Int32`, the boundary marker of each line (0 on the quads);
/// for a mesh of several regions, or of one with a regional attribute (`mesh.regions`), two
/// more: `region`, `Int32`, each quad's region tag, and
/// `attribute`, `Float64`, its regional attribute (0 where none; both 0 on the lines).
/// Returns `false`, without throwing, if the stream fails or an index is out of range.
/// The stream's precision and format flags are restored.
template <class Point_2>
bool write_VTU(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::mesh_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\""
        << mesh.quads.size() + mesh.boundary_edges.size() << "\">\n";

    out << "      <Points>\n"
           "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" format=\"ascii\">\n";
    Quad_mesher_2::internal::Text_buffer text(out);
    for(const Point_2& p : mesh.points)
      text << CGAL::to_double(p.x()) << ' ' << CGAL::to_double(p.y()) << " 0\n";
    text.flush();
    out << "        </DataArray>\n"
           "      </Points>\n";
    internal::write_vtu_cells(out, mesh);
    internal::write_vtu_cell_data(out, mesh);
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
