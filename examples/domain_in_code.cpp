// A domain built in code, not read from a file: a 4 x 4 square with a 1 x 1 square hole in its
// middle, meshed through every stage and written as a Gmsh file, domain_in_code.msh.
//
// Prints the quad count and the worst angles, and returns non-zero if meshing fails or the mesh
// is not what it must be: valid, covering the domain (area 16 - 1 = 15), with two boundary loops
// and every angle in [45, 135] degrees (no input corner is under 45 degrees, so none is excused).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <cmath>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

// Builds, meshes, writes and checks the domain; a Meshing_error is main's to report.
int mesh_square_with_hole()
{
  QM::Domain_2<K> domain;
  domain.points = { { 0, 0 }, { 4, 0 }, { 4, 4 }, { 0, 4 },                  // outer loop: 0-3
                    { 1.5, 1.5 }, { 2.5, 1.5 }, { 2.5, 2.5 }, { 1.5, 2.5 } }; // hole loop: 4-7
  domain.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 },   // 0-based indices into points,
                      { 4, 5 }, { 5, 6 }, { 6, 7 }, { 7, 4 } }; // loops in either orientation
  domain.holes = { { 2, 2 } };                                  // a seed strictly inside the hole

  QM::Mesh_criteria_2<K> criteria; // cells sized by the point spacing and the gaps
  QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(domain, criteria); // every stage
  if(!QM::IO::write_quad_mesh("domain_in_code.msh", mesh)) // format from the extension
    return 1;

  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads, angles [" << quality.min_angle << ", "
            << quality.max_angle << "], wrote domain_in_code.msh" << std::endl;

  // A valid mesh has no overlapping quads, so its quads lie in the domain exactly when their
  // areas add up to the domain's, 15 (up to rounding).
  double area = 0;
  for(const auto& q : mesh.quads)
    for(int c = 0; c < 4; ++c) {
      const K::Point_2& a = mesh.points[q[c]];
      const K::Point_2& b = mesh.points[q[(c + 1) % 4]];
      area += 0.5 * (a.x() * b.y() - b.x() * a.y());
    }
  const bool area_ok = std::abs(area - 15) <= 1e-9 * 15;
  const bool angles_ok = quality.min_angle >= 45 - 1e-6 && quality.max_angle <= 135 + 1e-6;
  if(mesh.quads.empty() || !quality.is_valid() || quality.number_of_boundary_loops != 2 || !area_ok ||
     !angles_ok) {
    std::cerr << "wrong mesh: area " << area << " (15 expected), " << (quality.is_valid() ? "valid" : "invalid")
              << ", " << quality.number_of_boundary_loops << " boundary loops (2 expected), angles ["
              << quality.min_angle << ", " << quality.max_angle << "] ([45, 135] expected)" << std::endl;
    return 3;
  }
  return 0;
}

int main()
{
  try {
    return mesh_square_with_hole();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }
}
