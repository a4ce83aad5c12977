// Regions: a 4 x 3 land around a lake (a hole) holding an island, built in code with Triangle's
// regional attributes, the land's 7, the island's 2.5 with a maximum area of 0.002. Meshed
// through every stage and written as regions.msh (a physical surface group per region:
// region_7, and region_1 for the island, whose attribute is no integer) and regions.vtu (cell
// fields region and attribute).
//
// Prints each region's tag, attribute, quads and largest quad, and returns non-zero if the mesh
// is invalid, a quad lies in the other region's face, or an island quad is larger than its
// maximum area.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <algorithm>
#include <iostream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

// the land, the lake (a hole) and the island, each a loop of four points
QM::Domain_2<K> land_lake_island()
{
  QM::Domain_2<K> domain;
  domain.points = { { 0, 0 },     { 4, 0 },     { 4, 3 },     { 0, 3 },     // land: 0-3
                    { 1, 0.7 },   { 3.2, 0.6 }, { 3.1, 2.3 }, { 0.9, 2.4 }, // lake: 4-7
                    { 1.7, 1.2 }, { 2.5, 1.3 }, { 2.4, 1.8 }, { 1.6, 1.7 } }; // island: 8-11
  for(std::size_t loop = 0; loop < 3; ++loop)
    for(std::size_t k = 0; k < 4; ++k) domain.segments.push_back({ 4 * loop + k, 4 * loop + (k + 1) % 4 });
  domain.holes = { { 1.2, 1.0 } }; // in the lake, not on the island
  // a point in each region, its attribute, its maximum area (0: none)
  domain.region_attributes = { { K::Point_2(0.3, 0.3), 7, 0 }, { K::Point_2(2, 1.5), 2.5, 0.002 } };
  return domain;
}

// Meshes, writes, prints and checks; a Meshing_error is main's to report.
int mesh_regions()
{
  const QM::Domain_2<K> domain = land_lake_island();
  const QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(domain);
  if(!QM::IO::write_quad_mesh("regions.msh", mesh) || !QM::IO::write_quad_mesh("regions.vtu", mesh))
    return 1;

  // per region of the mesh: its quads, its largest quad, and its quads in the island's face
  const std::vector<K::Point_2> island(domain.points.begin() + 8, domain.points.end());
  std::vector<std::size_t> quads(mesh.regions.size(), 0), on_island(mesh.regions.size(), 0);
  std::vector<double> largest(mesh.regions.size(), 0);
  for(std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto& v = mesh.quads[q];
    const std::size_t r = mesh.quad_regions[q];
    ++quads[r];
    const double area = CGAL::area(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]])
                        + CGAL::area(mesh.points[v[0]], mesh.points[v[2]], mesh.points[v[3]]);
    largest[r] = (std::max)(largest[r], area);
    const K::Point_2 centre = CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    if(CGAL::bounded_side_2(island.begin(), island.end(), centre, K()) == CGAL::ON_BOUNDED_SIDE)
      ++on_island[r];
  }
  for(std::size_t r = 0; r < mesh.regions.size(); ++r)
    std::cout << "region_" << mesh.regions[r].tag << ": attribute " << mesh.regions[r].attribute << ", "
              << quads[r] << " quads, the largest " << largest[r] << std::endl;
  std::cout << "wrote regions.msh and regions.vtu" << std::endl;

  // region 0 is the land's (its outer loop comes first), region 1 the island's
  const bool regions_ok = mesh.regions.size() == 2 && on_island[0] == 0 && on_island[1] == quads[1] && quads[1] > 0;
  if(!QM::compute_quality(mesh).is_valid() || !regions_ok || largest[1] > 0.002) {
    std::cerr << "wrong mesh: " << mesh.regions.size() << " regions (2 expected), the island's largest quad "
              << (mesh.regions.size() > 1 ? largest[1] : 0) << " (0.002 at most)" << std::endl;
    return 3;
  }
  return 0;
}

int main()
{
  try {
    return mesh_regions();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }
}
