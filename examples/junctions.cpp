// Junctions: a 6 x 2 laminate of three layers whose middle one is two materials, and a crack
// from the bottom edge into the lowest layer. The layers' interfaces meet the plate's sides,
// and the segment between the two middle materials meets the interfaces, at junctions
// (vertices of three segments): every face is a region, the regions sharing the nodes on the
// segments between them. Regional attributes give the materials: 1 for the outer layers, 2
// and 3 in the middle. Written as junctions.vtu (cell data "region") and junctions.svg.
//
// Prints each material's quads and the mesh's angles, and returns non-zero if the mesh is
// invalid, an angle is outside [45, 135], or a quad is not in the material its centre lies in.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <iostream>
#include <map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

QM::Domain_2<K> laminate()
{
  QM::Domain_2<K> domain;
  domain.points = { { 0, 0 },   { 1.5, 0 }, { 6, 0 }, { 6, 0.6 }, { 6, 1.4 }, { 6, 2 },    // 0 .. 5
                    { 3, 2 },   { 0, 2 },   { 0, 1.4 }, { 0, 0.6 },                      // 6 .. 9
                    { 3, 0.6 }, { 3, 1.4 }, { 1.5, 0.4 } };                             // 10 .. 12
  domain.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 4 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 8 }, { 8, 9 }, { 9, 0 },
                      { 9, 10 }, { 10, 3 }, { 8, 11 }, { 11, 4 }, // the layers' interfaces
                      { 10, 11 },                                // between the middle materials
                      { 1, 12 } };                               // the crack from the bottom edge
  domain.region_attributes = { { { 3, 0.3 }, 1, 0 }, { { 3, 1.7 }, 1, 0 }, { { 1, 1 }, 2, 0 }, { { 5, 1 }, 3, 0 } };
  return domain;
}

// the material whose part of the laminate holds p
int material_at(const K::Point_2& p)
{
  if(p.y() < 0.6 || p.y() > 1.4) return 1;
  return p.x() < 3 ? 2 : 3;
}

// Meshes, writes, prints and checks; a Meshing_error is main's to report.
int mesh_laminate()
{
  const QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(laminate());
  if(!QM::IO::write_quad_mesh("junctions.vtu", mesh) || !QM::IO::write_quad_mesh("junctions.svg", mesh))
    return 1;
  std::map<int, std::size_t> quads_of;
  bool in_place = mesh.quad_regions.size() == mesh.quads.size();
  for(std::size_t q = 0; q < mesh.quads.size() && in_place; ++q) {
    const auto& v = mesh.quads[q];
    const int tag = mesh.regions[mesh.quad_regions[q]].tag;
    ++quads_of[tag];
    in_place = tag == material_at(CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]));
  }
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  for(const auto& [tag, quads] : quads_of) std::cout << "material " << tag << ": " << quads << " quads" << std::endl;
  std::cout << mesh.quads.size() << " quads, angles [" << quality.min_angle << ", " << quality.max_angle << "] degrees"
            << std::endl;
  std::cout << "wrote junctions.vtu and junctions.svg" << std::endl;
  if(!quality.is_valid() || quality.min_angle < 45 - 1e-7 || quality.max_angle > 135 + 1e-7 || !in_place) {
    std::cerr << "wrong mesh" << std::endl;
    return 3;
  }
  return 0;
}

int main()
{
  try {
    return mesh_laminate();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 2;
  }
}
