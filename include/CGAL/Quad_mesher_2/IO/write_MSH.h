// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_MSH_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_MSH_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
namespace internal {

using Quad_mesher_2::internal::Marker_group;

/// The bounding box `xmin ymin 0 xmax ymax 0` of the points `index(0)`, ..., `index(n - 1)` of
/// `mesh`, as an `$Entities` line gives it (zeros if `n` is 0).
template <class Point_2, class Index>
void write_msh_box(std::ostream& out, const Quad_mesh_2<Point_2>& mesh, std::size_t n, Index index)
{
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const Point_2& p = mesh.points[index(i)];
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    xmin = i == 0 ? x : (std::min)(xmin, x);
    xmax = i == 0 ? x : (std::max)(xmax, x);
    ymin = i == 0 ? y : (std::min)(ymin, y);
    ymax = i == 0 ? y : (std::max)(ymax, y);
  }
  out << xmin << ' ' << ymin << " 0 " << xmax << ' ' << ymax << " 0";
}

/// The physical tag of each marker group: the marker itself if every marker is positive (as
/// Gmsh's own tags are, and solvers take them for boundary ids), else 1, 2, ... in order.
inline std::vector<int> msh_physical_tags(const std::vector<Marker_group>& groups)
{
  const bool positive = groups.empty() || groups.front().marker > 0; // markers increase
  std::vector<int> tags;
  for(std::size_t g = 0; g < groups.size(); ++g)
    tags.push_back(positive ? groups[g].marker : int(g + 1));
  return tags;
}

/// The surfaces: one per region where the mesh names its regions (`has_named_regions()`),
/// else one, "domain" (tag 1). Surface s + 1 holds `quads[s]`, bounded by the curves with
/// edges on it (`curves[s]`: marker groups).
struct Msh_surfaces
{
  std::vector<std::vector<std::size_t>> quads;
  std::vector<int> tags;
  std::vector<std::string> names;
  std::vector<std::vector<std::size_t>> curves;
};

template <class Point_2>
Msh_surfaces msh_surfaces(const Quad_mesh_2<Point_2>& mesh, const std::vector<Marker_group>& groups)
{
  Msh_surfaces s;
  if(Quad_mesher_2::internal::has_named_regions(mesh)) {
    s.quads = Quad_mesher_2::internal::region_quads(mesh);
    for(const auto& r : mesh.regions) {
      s.tags.push_back(r.tag);
      s.names.push_back(Quad_mesher_2::internal::region_name(r.tag));
    }
  } else {
    s.quads.emplace_back(mesh.quads.size());
    for(std::size_t q = 0; q < mesh.quads.size(); ++q) s.quads[0][q] = q;
    s.tags.push_back(1);
    s.names.push_back("domain");
  }
  // a boundary vertex lies in one surface: regions share no vertex
  std::vector<std::size_t> surface_of(mesh.points.size(), 0);
  for(std::size_t k = 0; k < s.quads.size(); ++k)
    for(std::size_t q : s.quads[k])
      for(std::size_t v : mesh.quads[q]) surface_of[v] = k;
  s.curves.resize(s.quads.size());
  for(std::size_t g = 0; g < groups.size(); ++g)
    for(std::size_t e : groups[g].edges) {
      std::vector<std::size_t>& curves = s.curves[surface_of[mesh.boundary_edges[e].v0]];
      if(curves.empty() || curves.back() != g) curves.push_back(g);
    }
  return s;
}

/// `$PhysicalNames` (a group per marker, then one per surface) and `$Entities`: curve g + 1
/// holds marker group g, surface s + 1 the quads of `surfaces.quads[s]`.
template <class Point_2>
void write_msh_entities(std::ostream& out, const Quad_mesh_2<Point_2>& mesh, const std::vector<Marker_group>& groups,
                        const std::vector<int>& tags, const Msh_surfaces& surfaces)
{
  const std::size_t ns = surfaces.quads.size();
  if(!groups.empty() || ns > 1) {
    out << "$PhysicalNames\n" << groups.size() + ns << '\n';
    for(std::size_t g = 0; g < groups.size(); ++g)
      out << "1 " << tags[g] << " \"" << Quad_mesher_2::internal::marker_name(groups[g].marker) << "\"\n";
    for(std::size_t k = 0; k < ns; ++k)
      out << "2 " << surfaces.tags[k] << " \"" << surfaces.names[k] << "\"\n";
    out << "$EndPhysicalNames\n";
  }
  // numPoints numCurves numSurfaces numVolumes; then each entity: tag, bounding box,
  // numPhysicalTags and tags, numBoundingPoints or numBoundingCurves and tags.
  out << "$Entities\n0 " << groups.size() << ' ' << ns << " 0\n";
  for(std::size_t g = 0; g < groups.size(); ++g) {
    const std::vector<std::size_t>& edges = groups[g].edges;
    out << g + 1 << ' ';
    write_msh_box(out, mesh, 2 * edges.size(), [&](std::size_t i) {
      const auto& e = mesh.boundary_edges[edges[i / 2]];
      return i % 2 == 0 ? e.v0 : e.v1;
    });
    out << " 1 " << tags[g] << " 0\n";
  }
  for(std::size_t k = 0; k < ns; ++k) {
    const std::vector<std::size_t>& quads = surfaces.quads[k];
    out << k + 1 << ' ';
    if(ns == 1)
      write_msh_box(out, mesh, mesh.points.size(), [](std::size_t i) { return i; });
    else
      write_msh_box(out, mesh, 4 * quads.size(), [&](std::size_t i) { return mesh.quads[quads[i / 4]][i % 4]; });
    if(groups.empty() && ns == 1) {
      out << " 0 0\n";
      continue;
    }
    out << " 1 " << surfaces.tags[k] << ' ' << surfaces.curves[k].size();
    for(std::size_t g : surfaces.curves[k])
      out << ' ' << g + 1;
    out << '\n';
  }
  out << "$EndEntities\n";
}

/// `$Nodes`: one block on surface 1, node tags 1..n in the order of `mesh.points` (as every
/// other writer numbers them; Gmsh takes the nodes of the other surfaces' quads from it).
template <class Point_2>
void write_msh_nodes(std::ostream& out, const Quad_mesh_2<Point_2>& mesh)
{
  const std::size_t n = mesh.points.size();
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
}

/// `$Elements`: the quads first, quad q with tag q + 1, one block per non-empty surface, then
/// one block of lines per marker group on its curve (tags from m + 1).
template <class Point_2>
void write_msh_elements(std::ostream& out, const Quad_mesh_2<Point_2>& mesh, const std::vector<Marker_group>& groups,
                        const Msh_surfaces& surfaces)
{
  const std::size_t m = mesh.quads.size(), total = m + mesh.boundary_edges.size();
  out << "$Elements\n";
  if(total == 0) {
    out << "0 0 0 0\n$EndElements\n";
    return;
  }
  std::size_t blocks = groups.size();
  for(const auto& quads : surfaces.quads) blocks += quads.empty() ? 0 : 1;
  // numEntityBlocks numElements minTag maxTag; each block: entityDim entityTag elementType
  // numElements
  out << blocks << ' ' << total << " 1 " << total << '\n';
  Quad_mesher_2::internal::Text_buffer text(out);
  for(std::size_t k = 0; k < surfaces.quads.size(); ++k) {
    if(surfaces.quads[k].empty()) continue;
    text << "2 " << k + 1 << " 3 " << surfaces.quads[k].size() << '\n';
    for(std::size_t q : surfaces.quads[k]) {
      const auto& v = mesh.quads[q];
      text << q + 1 << ' ' << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << ' ' << v[3] + 1 << '\n';
    }
  }
  std::size_t tag = m + 1;
  for(std::size_t g = 0; g < groups.size(); ++g) {
    text << "1 " << g + 1 << " 1 " << groups[g].edges.size() << '\n';
    for(std::size_t i : groups[g].edges)
      text << tag++ << ' ' << mesh.boundary_edges[i].v0 + 1 << ' ' << mesh.boundary_edges[i].v1 + 1 << '\n';
  }
  text.flush();
  out << "$EndElements\n";
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Writes `mesh` as a Gmsh MSH 4.1 ASCII file: `$MeshFormat` (4.1 0 8), `$Entities`,
/// `$Nodes` (one block, node tags 1..n in the order of `mesh.points`, z = 0)
/// and `$Elements` (a block of type 3, the 4-node quadrangle, per surface; quad q has
/// element tag q + 1).
///
/// The quads are one surface entity (tag 1), but for a mesh of several regions, or of one
/// with a regional attribute (`Quad_mesh_2::regions`): then region k is surface k + 1 with
/// the physical group `region_3` of its tag 3, bounded by the curves of its boundary edges.
///
/// With `mesh.boundary_edges`, each boundary marker gets a curve entity (tags 1, 2, ... by
/// increasing marker) holding its edges as a block of 2-node lines (type 1, tags after the quads') and a named physical
/// group, `marker_3` for marker 3 (`marker_m3` for -3), and a single surface the physical
/// group `domain` (tag 1); `$PhysicalNames` lists them. A marker's physical tag is the marker
/// itself if every marker is positive, else 1, 2, ... by increasing marker (Gmsh's tags are
/// positive). Gmsh lists one physical group per marker; deal.II, for one, takes the physical
/// tags for boundary ids.
///
/// Coordinates are converted with `CGAL::to_double`; the node coordinates are written as the
/// shortest decimals that read back as the same doubles, the bounding boxes with
/// `max_digits10` digits.
/// Returns `false`, without throwing, if the stream fails or an index is out of range.
/// The stream's precision and format flags are restored.
template <class Point_2>
bool write_MSH(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  if(!Quad_mesher_2::internal::mesh_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    const std::vector<internal::Marker_group> groups = Quad_mesher_2::internal::marker_groups(mesh);
    const internal::Msh_surfaces surfaces = internal::msh_surfaces(mesh, groups);
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    internal::write_msh_entities(out, mesh, groups, internal::msh_physical_tags(groups), surfaces);
    internal::write_msh_nodes(out, mesh);
    internal::write_msh_elements(out, mesh, groups, surfaces);
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
