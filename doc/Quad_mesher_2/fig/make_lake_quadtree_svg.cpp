// Draws the quadtree stage of Lake Superior sized by point spacing alone, without the
// refinement that makes the input points vertices (Mesh_criteria_2::set_points_as_vertices(false),
// which the command-line tool does not offer). From the repository root:
//   g++ -std=c++17 -O2 -I include doc/Quad_mesher_2/fig/make_lake_quadtree_svg.cpp -lgmp -lmpfr -o /tmp/make_lake_quadtree_svg
//   /tmp/make_lake_quadtree_svg examples/data/lake_superior/lake_superior.poly doc/Quad_mesher_2/fig/lake_superior_quadtree.svg
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <iostream>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

int main(int argc, char** argv)
{
  if(argc != 3) {
    std::cerr << "usage: make_lake_quadtree_svg INPUT.poly OUTPUT.svg\n";
    return 2;
  }
  QM::Domain_2<K> domain;
  std::string error;
  if(!QM::IO::read_poly(argv[1], domain, &error)) {
    std::cerr << error << std::endl;
    return 1;
  }
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_points_as_vertices(false);
  QM::Quadtree_mesher_2<K> mesher(domain, criteria);
  QM::Quad_mesh_2<K::Point_2> mesh = mesher.run(QM::Stage::QUADTREE);
  std::vector<std::pair<K::Point_2, K::Point_2>> segments;
  for(const auto& s : domain.segments)
    segments.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  QM::Mesh_quality_2 q = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads, " << mesh.number_of_vertices()
            << " vertices, angles [" << q.min_angle << ", " << q.max_angle << "] deg, quadtree depth "
            << mesher.quadtree().depth() << std::endl;
  return QM::IO::write_SVG(std::string(argv[2]), mesh, segments) && q.is_valid() ? 0 : 1;
}
