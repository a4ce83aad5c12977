// A user sizing field and the output as a CGAL::Surface_mesh: cells shrink toward a circle,
// the mesh stays conforming with every angle 45, 90 or 135 degrees.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

int main()
{
  QM::Domain_2<K> square; // only its bounding box matters here
  square.points = { K::Point_2(-1, -1), K::Point_2(1, 1) };

  QM::Mesh_criteria_2<K> criteria(/*max_size*/ 0.25);
  criteria.set_use_point_spacing(false);
  criteria.set_sizing_field([](const K::Point_2& p) {
    double r = std::sqrt(p.x() * p.x() + p.y() * p.y());
    return 0.01 + 0.5 * std::abs(r - 0.6); // fine near the circle of radius 0.6
  });

  QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(square, criteria);
  CGAL::Surface_mesh<K::Point_2> sm;
  QM::copy_to_face_graph(mesh, sm);
  std::cout << num_faces(sm) << " quads, " << num_vertices(sm) << " vertices" << std::endl;
  return num_faces(sm) > 0 ? 0 : 1;
}
