// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The regions of a whole domain's mesh (`Quad_mesh_2::regions`): the faces of the domain,
// those of one regional attribute merged, each with its output tag, and the region of every
// quad. Faces meet only along interfaces, so each piece of the mesh its quads make across the
// edges on no interface lies in one face, which any of its boundary edges tells by the loop
// it lies on (found with its marker: mark_boundary_and_regions()), or any of its interface
// edges by the side it lies on.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_MESH_REGIONS_H
#define CGAL_QUAD_MESHER_2_INTERNAL_MESH_REGIONS_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/boundary_markers.h>
#include <CGAL/Quad_mesher_2/internal/loop_locator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Which side of an interface a mesh edge lies on: the loops on either side of the half-edge
/// a -> b (of an edge and its twin, see `Boundary_loop_2::edge_twins`), found at the edge's
/// midpoint.
template <class K>
class Interface_sides
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  Interface_sides(const Quad_mesh_2<typename K::Point_2>& mesh, const Domain_2<K>& domain, const Domain_loops_2<K>& loops)
    : m_mesh(mesh),
      m_has_interfaces(has_interfaces(loops))
  {
    if(!m_has_interfaces) return;
    m_locator = make_loop_locator(domain, loops);
    m_on = 1e-10 * m_locator->diagonal();
  }

  /// the interface loops that have half-edge a -> b on their left and on their right, or
  /// none if the edge lies on no interface
  std::array<std::size_t, 2> loops_beside(std::size_t a, std::size_t b) const
  {
    if(!m_has_interfaces) return { none, none };
    const Point_2d pa = to_point_2d(m_mesh.points[a]), pb = to_point_2d(m_mesh.points[b]);
    const Loop_locator::Hit h = m_locator->closest(CGAL::midpoint(pa, pb), m_on);
    if(h.dist > m_on) return { none, none };
    const std::size_t twin = m_locator->edge_twin(h.loop, h.edge)[0];
    if(twin == none) return { none, none };
    const auto& loop = m_locator->loop(h.loop);
    const Vector_2d along = loop[(h.edge + 1) % loop.size()] - loop[h.edge];
    if(along * (pb - pa) > 0) return { h.loop, twin };
    return { twin, h.loop };
  }

private:
  const Quad_mesh_2<typename K::Point_2>& m_mesh;
  const bool m_has_interfaces;
  std::unique_ptr<Loop_locator> m_locator;
  double m_on = 0;
};

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
/// lies on (`edge_loops`, in the order of the quads and their corners). The quads are joined
/// into pieces across the edges they share but those on an interface; a piece takes the
/// region of the loop of a boundary edge it has, or of the interface loop it lies on the left of.
template <class K>
void assign_regions(Quad_mesh_2<typename K::Point_2>& mesh, const Domain_2<K>& domain, const Domain_loops_2<K>& loops,
                    const std::vector<std::size_t>& edge_loops)
{
  const std::size_t none = std::size_t(-1);
  mesh.regions.clear();
  const std::vector<std::size_t> output_region = domain_regions(domain, loops, mesh.regions);
  const Interface_sides<K> interfaces(mesh, domain, loops);
  // half-edges by their ends, lower first: (lower, higher, quad, corner)
  std::vector<std::array<std::size_t, 4>> half_edges;
  half_edges.reserve(4 * mesh.quads.size());
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(std::size_t c = 0; c < 4; ++c) {
      const std::size_t a = mesh.quads[q][c], b = mesh.quads[q][(c + 1) % 4];
      half_edges.push_back({ (std::min)(a, b), (std::max)(a, b), q, c });
    }
  std::sort(half_edges.begin(), half_edges.end());
  std::vector<std::size_t> piece(mesh.quads.size());
  std::iota(piece.begin(), piece.end(), std::size_t(0));
  auto find = [&](std::size_t q) {
    while(piece[q] != q) q = piece[q] = piece[piece[q]];
    return q;
  };
  std::vector<std::size_t> region_of_quad(mesh.quads.size(), none);
  // a half-edge is inner where another quad has it the other way round (as
  // marked_boundary_edges() has it): its two quads join, or face each other across an interface
  std::vector<char> on_boundary(4 * mesh.quads.size(), 1); // by 4 quad + corner
  auto source = [&](const std::array<std::size_t, 4>& e) { return mesh.quads[e[2]][e[3]]; };
  for(std::size_t i = 0, j = 0; i < half_edges.size(); i = j) {
    while(j < half_edges.size() && half_edges[j][0] == half_edges[i][0] && half_edges[j][1] == half_edges[i][1]) ++j;
    for(std::size_t x = i; x < j; ++x)
      for(std::size_t y = x + 1; y < j; ++y) {
        const auto& e = half_edges[x];
        const auto& f = half_edges[y];
        if(source(e) == source(f) || e[2] == f[2]) continue;
        on_boundary[4 * e[2] + e[3]] = on_boundary[4 * f[2] + f[3]] = 0;
        const std::array<std::size_t, 2> beside = interfaces.loops_beside(source(e), source(f));
        if(beside[0] == none) {
          piece[find(e[2])] = find(f[2]);
          continue;
        }
        region_of_quad[e[2]] = output_region[loops.loops[beside[0]].region];
        region_of_quad[f[2]] = output_region[loops.loops[beside[1]].region];
      }
  }
  std::size_t boundary_edge = 0;
  for(std::size_t k = 0; k < on_boundary.size() && boundary_edge < edge_loops.size(); ++k)
    if(on_boundary[k]) region_of_quad[k / 4] = output_region[loops.loops[edge_loops[boundary_edge++]].region];
  std::vector<std::size_t> region_of_piece(mesh.quads.size(), none);
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    if(region_of_quad[q] != none) region_of_piece[find(q)] = region_of_quad[q];
  mesh.quad_regions.resize(mesh.quads.size());
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    mesh.quad_regions[q] = region_of_piece[find(q)];
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
