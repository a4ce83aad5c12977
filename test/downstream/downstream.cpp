// A user's program against the installed package: a square with a square hole meshed, and
// the mesh copied into CGAL's usual surface mesh (of 3D points). Exits 0 if the surface mesh
// is a valid quad mesh with every quad.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

int main()
{
  QM::Domain_2<K> domain;
  domain.points = { K::Point_2(0, 0), K::Point_2(4, 0), K::Point_2(4, 4), K::Point_2(0, 4),
                    K::Point_2(1, 1), K::Point_2(2, 1), K::Point_2(2, 2), K::Point_2(1, 2) };
  domain.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } };
  domain.holes = { K::Point_2(1.5, 1.5) };
  const QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(domain);

  CGAL::Surface_mesh<K::Point_3> surface;
  const bool copied = QM::copy_to_face_graph(mesh, surface);
  const bool ok = copied && num_faces(surface) == mesh.quads.size() && CGAL::is_quad_mesh(surface)
                  && surface.is_valid(false);
  std::cout << mesh.quads.size() << " quads, " << num_vertices(surface) << " vertices in a Surface_mesh<Point_3>: "
            << (ok ? "ok" : "FAILED") << "\n";
  return ok ? 0 : 1;
}
