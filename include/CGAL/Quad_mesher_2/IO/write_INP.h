// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_INP_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_INP_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// per boundary edge of `mesh`, 4 q + k for the side k (from corner k to corner k + 1) of quad
// q it is, in either direction, or std::size_t(-1) if it is no side of a quad
template <class Point_2>
std::vector<std::size_t> boundary_edge_faces(const Quad_mesh_2<Point_2>& mesh)
{
  const Vertex_quads quads_at(mesh.quads, mesh.points.size());
  std::vector<std::size_t> faces;
  faces.reserve(mesh.boundary_edges.size());
  for(const auto& e : mesh.boundary_edges) {
    std::size_t face = std::size_t(-1);
    for(std::size_t q : quads_at[e.v0]) {
      const std::size_t c = std::size_t(corner_of(mesh.quads[q], e.v0));
      if(mesh.quads[q][(c + 1) % 4] == e.v1) face = 4 * q + c;
      else if(mesh.quads[q][(c + 3) % 4] == e.v1) face = 4 * q + (c + 3) % 4;
    }
    faces.push_back(face);
  }
  return faces;
}

// increasing numbers, 16 a line (Abaqus's limit)
inline void write_inp_numbers(Text_buffer& text, const std::vector<std::size_t>& numbers)
{
  for(std::size_t k = 0; k < numbers.size(); ++k)
    text << numbers[k] << (k + 1 == numbers.size() || k % 16 == 15 ? "\n" : ", ");
}

} // namespace internal

namespace IO {

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as an Abaqus / CalculiX input file (`.inp`, the mesh part of a model):
/// `*NODE` with one line `n, x, y` per point (node numbers from 1 in the order of
/// `mesh.points`); `*ELEMENT, TYPE=CPS4, ELSET=domain` with one line `e, a, b, c, d` per quad
/// (4-node plane-stress elements numbered from 1, nodes counter-clockwise; the set `domain`
/// holds them all); for a mesh of several regions, or of one with a regional attribute
/// (`Quad_mesh_2::regions`), `*ELSET, ELSET=region_3` with the elements of the region of tag
/// 3, for a `*SOLID SECTION` each; and per boundary marker of `mesh.boundary_edges`, by
/// increasing marker, `*NSET, NSET=marker_3` (`marker_m3` for -3) with the nodes of its edges, and the element
/// surface `*SURFACE, NAME=marker_3, TYPE=ELEMENT` of the element faces on its edges (face
/// `Sk` of an element runs from its node k to its next node), made of the element sets
/// `marker_3_S1` to `marker_3_S4` it names: what `*DSLOAD`, `*DLOAD` with `Pk`, `*FILM` or a
/// contact pair takes. Numbers increase, 16 a line (Abaqus's limit). Coordinates are converted
/// with `CGAL::to_double` and written as the shortest decimals that read back as the same
/// doubles.
/// Returns `false`, without throwing, if the stream fails, an index is out of range or a
/// boundary edge is no side of a quad.
template <class Point_2>
bool write_INP(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::mesh_indices_in_range(mesh))
    return false;
  const std::vector<std::size_t> faces = Quad_mesher_2::internal::boundary_edge_faces(mesh);
  if(std::find(faces.begin(), faces.end(), std::size_t(-1)) != faces.end())
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    Quad_mesher_2::internal::Text_buffer text(out);
    text << "*HEADING\nQuad_mesher_2: " << mesh.quads.size() << " quads, a node set and an element surface per boundary marker\n*NODE\n";
    std::size_t i = 1;
    for(const Point_2& p : mesh.points)
      text << i++ << ", " << CGAL::to_double(p.x()) << ", " << CGAL::to_double(p.y()) << '\n';
    text << "*ELEMENT, TYPE=CPS4, ELSET=domain\n";
    i = 1;
    for(const auto& q : mesh.quads)
      text << i++ << ", " << q[0] + 1 << ", " << q[1] + 1 << ", " << q[2] + 1 << ", " << q[3] + 1 << '\n';
    if(Quad_mesher_2::internal::has_named_regions(mesh)) {
      const std::vector<std::vector<std::size_t>> quads = Quad_mesher_2::internal::region_quads(mesh);
      std::vector<std::size_t> elements;
      for(std::size_t r = 0; r < quads.size(); ++r) {
        elements.clear();
        for(std::size_t q : quads[r]) elements.push_back(q + 1);
        text << "*ELSET, ELSET=" << Quad_mesher_2::internal::region_name(mesh.regions[r].tag).c_str() << '\n';
        Quad_mesher_2::internal::write_inp_numbers(text, elements);
      }
    }
    std::vector<std::size_t> nodes;
    for(const auto& g : Quad_mesher_2::internal::marker_groups(mesh)) {
      nodes.clear();
      for(std::size_t e : g.edges)
        nodes.insert(nodes.end(), { mesh.boundary_edges[e].v0 + 1, mesh.boundary_edges[e].v1 + 1 });
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      const std::string name = Quad_mesher_2::internal::marker_name(g.marker);
      text << "*NSET, NSET=" << name.c_str() << '\n';
      Quad_mesher_2::internal::write_inp_numbers(text, nodes);
      std::array<std::vector<std::size_t>, 4> elements_by_face;
      for(std::size_t e : g.edges)
        elements_by_face[faces[e] % 4].push_back(faces[e] / 4 + 1);
      for(int k = 0; k < 4; ++k) {
        std::vector<std::size_t>& elements = elements_by_face[std::size_t(k)];
        std::sort(elements.begin(), elements.end());
        if(!elements.empty()) {
          text << "*ELSET, ELSET=" << name.c_str() << "_S" << k + 1 << '\n';
          Quad_mesher_2::internal::write_inp_numbers(text, elements);
        }
      }
      text << "*SURFACE, NAME=" << name.c_str() << ", TYPE=ELEMENT\n";
      for(int k = 0; k < 4; ++k)
        if(!elements_by_face[std::size_t(k)].empty())
          text << name.c_str() << "_S" << k + 1 << ", S" << k + 1 << '\n';
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
