// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_INP_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_INP_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as an Abaqus / CalculiX input file (`.inp`, the mesh part of a model):
/// `*NODE` with one line `n, x, y` per point (node numbers from 1 in the order of
/// `mesh.points`); `*ELEMENT, TYPE=CPS4, ELSET=domain` with one line `e, a, b, c, d` per quad
/// (4-node plane-stress elements numbered from 1, nodes counter-clockwise; the set `domain`
/// holds them all); and per boundary marker of `mesh.boundary_edges`, by increasing marker,
/// `*NSET, NSET=marker_3` (`marker_m3` for -3) with the nodes of its edges, increasing, 16 a
/// line (Abaqus's limit). Coordinates are converted with `CGAL::to_double` and written as the
/// shortest decimals that read back as the same doubles.
/// Returns `false`, without throwing, if the stream fails or an index is out of range.
template <class Point_2>
bool write_INP(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::mesh_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    Quad_mesher_2::internal::Text_buffer text(out);
    text << "*HEADING\nQuad_mesher_2: " << mesh.quads.size() << " quads, a node set per boundary marker\n*NODE\n";
    std::size_t i = 1;
    for(const Point_2& p : mesh.points)
      text << i++ << ", " << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << '\n';
    text << "*ELEMENT, TYPE=CPS4, ELSET=domain\n";
    i = 1;
    for(const auto& q : mesh.quads)
      text << i++ << ", " << q[0] + 1 << ", " << q[1] + 1 << ", " << q[2] + 1 << ", " << q[3] + 1 << '\n';
    std::vector<std::size_t> nodes;
    for(const auto& g : Quad_mesher_2::internal::marker_groups(mesh)) {
      nodes.clear();
      for(std::size_t e : g.edges)
        nodes.insert(nodes.end(), { mesh.boundary_edges[e].v0 + 1, mesh.boundary_edges[e].v1 + 1 });
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      text << "*NSET, NSET=" << Quad_mesher_2::internal::marker_name(g.marker).c_str() << '\n';
      for(std::size_t k = 0; k < nodes.size(); ++k)
        text << nodes[k] << (k + 1 == nodes.size() || k % 16 == 15 ? "\n" : ", ");
    }
    text.flush();
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` to the file `filename` in Abaqus / CalculiX format (see the stream overload).
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_INP(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return write_INP(os, mesh); });
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_INP_H
