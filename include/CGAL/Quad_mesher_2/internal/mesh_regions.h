// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The regions of a whole domain's mesh (`Quad_mesh_2::regions`): the faces of the domain,
// those of one regional attribute merged, each with its output tag, and the region of every
// quad. The faces' meshes share no vertex (loops are disjoint), so each connected piece of
// the mesh lies in one face, which any of its boundary edges tells by the loop it lies on
// (found with its marker: mark_boundary_and_regions()).

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_MESH_REGIONS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_MESH_REGIONS_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/boundary_markers.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// the output region of each region of the domain (`Boundary_loop_2::region`), appended to
/// `out`: one per attribute, one per region without
template <class K, class Region>
std::vector<std::size_t> domain_regions(const Domain_2<K>& domain, const Domain_loops_2<K>& loops, std::vector<Region>& out)
{
  const std::size_t none = std::size_t(-1);
  auto integral_tag = [](double a) { return a >= 1 && a <= double((std::numeric_limits<int>::max)()) && a == std::floor(a); };
  std::set<int> taken;
  for(std::size_t attribute : loops.region_attributes)
    if(attribute != none && integral_tag(domain.region_attributes[attribute].attribute))
      taken.insert(int(domain.region_attributes[attribute].attribute));
  int next_tag = 1;
  auto fresh_tag = [&]() {
    while(taken.count(next_tag) > 0) ++next_tag;
    taken.insert(next_tag);
    return next_tag;
  };
  std::map<double, std::size_t> by_attribute;
  std::vector<std::size_t> output_region;
  for(std::size_t attribute : loops.region_attributes) {
    if(attribute == none) {
      output_region.push_back(out.size());
      out.push_back(Region{ fresh_tag(), false, 0 });
      continue;
    }
    const double a = domain.region_attributes[attribute].attribute;
    auto [it, is_new] = by_attribute.emplace(a, out.size());
    if(is_new)
      out.push_back(Region{ integral_tag(a) ? int(a) : fresh_tag(), true, a });
    output_region.push_back(it->second);
  }
  return output_region;
}

/// Fills `mesh.regions` and `mesh.quad_regions`, given the loop each of `mesh.boundary_edges`
/// lies on (`edge_loops`)
template <class K>
void assign_regions(Quad_mesh_2<typename K::Point_2>& mesh, const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                    const std::vector<std::size_t>& edge_loops)
{
  const std::size_t none = std::size_t(-1);
  mesh.regions.clear();
  const std::vector<std::size_t> output_region = domain_regions(domain, loops, mesh.regions);
  // the connected pieces of the mesh, by the vertices their quads share
  std::vector<std::size_t> piece(mesh.points.size());
  std::iota(piece.begin(), piece.end(), std::size_t(0));
  auto find = [&](std::size_t v) {
    while(piece[v] != v) v = piece[v] = piece[piece[v]];
    return v;
  };
  for(const auto& q : mesh.quads)
    for(int k = 1; k < 4; ++k) piece[find(q[k])] = find(q[0]);
  std::vector<std::size_t> region_of_piece(mesh.points.size(), none);
  for(std::size_t e = 0; e < mesh.boundary_edges.size(); ++e) {
    std::size_t& region = region_of_piece[find(mesh.boundary_edges[e].v0)];
    if(region == none) region = output_region[loops.loops[edge_loops[e]].region];
  }
  mesh.quad_regions.resize(mesh.quads.size());
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    mesh.quad_regions[q] = region_of_piece[find(mesh.quads[q][0])];
}

/// Fills what a mesh of a whole domain carries beyond its quads: `mesh.boundary_edges` with
/// their markers (`marked_boundary_edges()`) and the regions.
template <class K>
void mark_boundary_and_regions(Quad_mesh_2<typename K::Point_2>& mesh, const Domain_2<K>& domain,
                               const Domain_loops_2<K>& loops)
{
  std::vector<std::size_t> edge_loops;
  mesh.boundary_edges = marked_boundary_edges(mesh, domain, loops, edge_loops);
  assign_regions(mesh, domain, loops, edge_loops);
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_MESH_REGIONS_H
