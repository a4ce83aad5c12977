// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_QUAD_MESH_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_QUAD_MESH_H

#include <CGAL/Quad_mesher_2/IO/file_extension.h>
#include <CGAL/Quad_mesher_2/IO/write_INP.h>
#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
#include <CGAL/Quad_mesher_2/IO/write_OFF.h>
#include <CGAL/Quad_mesher_2/IO/write_SU2.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/IO/write_VTU.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include <cctype>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to `filename` in the format given by its extension (case-insensitive):
/// `.msh` (Gmsh MSH 4.1 ASCII, `write_MSH()`), `.vtu` (VTK XML, `write_VTU()`), `.su2` (SU2,
/// `write_SU2()`), `.inp` (Abaqus / CalculiX, `write_INP()`), `.off` (`write_OFF()`) or
/// `.svg` (a picture, `write_SVG()`). All but OFF and SVG write the boundary edges and their
/// markers too.
/// Returns `false`, without throwing, for any other extension or if the file cannot be
/// written.
template <class Point_2>
bool write_quad_mesh(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  const std::string ext = file_extension(filename);
  if(ext == ".msh")
    return CGAL::Quad_mesher_2::IO::write_MSH(filename, mesh);
  if(ext == ".vtu")
    return CGAL::Quad_mesher_2::IO::write_VTU(filename, mesh);
  if(ext == ".su2")
    return CGAL::Quad_mesher_2::IO::write_SU2(filename, mesh);
  if(ext == ".inp")
    return CGAL::Quad_mesher_2::IO::write_INP(filename, mesh);
  if(ext == ".off")
    return CGAL::Quad_mesher_2::IO::write_OFF(filename, mesh);
  if(ext == ".svg")
    return CGAL::Quad_mesher_2::IO::write_SVG(filename, mesh);
  return false;
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_QUAD_MESH_H
