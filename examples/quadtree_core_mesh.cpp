// The first stage of the pipeline on the paper's own case: the strongly balanced quadtree of
// Lake Superior's 518 boundary vertices, sized by their spacing (paper §4.2), turned into a
// conforming all-quad mesh by the 2-refinement templates (paper Fig. 3(b)).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

int main(int argc, char** argv)
{
  const std::string file = argc > 1 ? argv[1] : QM2_DATA_DIR "/lake_superior/lake_superior.poly";
  QM::Domain_2<K> domain;
  std::string error;
  if(!QM::IO::read_poly(file, domain, &error)) {
    std::cerr << error << std::endl;
    return 1;
  }
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_points_as_vertices(false); // stage 1 alone: no refinement around the points
  QM::Quadtree_mesher_2<K> mesher(domain, criteria);
  mesher.build_quadtree();
  QM::Quad_mesh_2<K::Point_2> mesh = mesher.core_mesh();
  std::cout << domain.points.size() << " input points -> " << mesher.quadtree().number_of_leaves()
            << " leaves, depth " << mesher.quadtree().depth() << " -> " << mesh.number_of_quads()
            << " quads, " << mesh.number_of_vertices() << " vertices" << std::endl;
  return mesh.number_of_quads() > 0 ? 0 : 1;
}
