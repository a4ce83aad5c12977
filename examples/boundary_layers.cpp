// Boundary layers for a viscous-flow solver (paper §5): the NACA 0012 with a sharp trailing
// edge in a far field, 20 layers on the air foil from a first height of 1e-4 chords growing
// by 1.15, the rest of the far field meshed with angles in [45°, 135°].
//
//   boundary_layers [INPUT.poly] [OUTPUT_NAME]
//
// Prints what the stacks are (per wall marker: bands, fans, first height, growth, thickness)
// and the angle ranges inside and outside them, writes OUTPUT_NAME.msh (the boundary edges
// with their markers, for the solver's wall and far-field conditions) and two SVG close-ups:
// the leading edge (OUTPUT_NAME_leading_edge.svg) and the trailing edge
// (OUTPUT_NAME_trailing_edge.svg). Returns non-zero if meshing fails, the mesh is invalid or a
// first height is off by more than 1%.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Boundary_layer_mesher_2.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
namespace QM = CGAL::Quad_mesher_2;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : QM2_DATA_DIR "/naca0012/naca0012_sharp.poly";
  const std::string name = argc > 2 ? argv[2] : "boundary_layers";

  QM::Domain_2<K> domain;
  std::string error;
  if(!QM::IO::read_poly(input, domain, &error)) {
    std::cerr << error << std::endl;
    return 1;
  }

  // The walls: the far field's holes (here the air foil, marker 2), by default.
  const double first_height = 1e-4, growth = 1.15;
  const QM::Boundary_layer_criteria_2 layers(20, first_height, growth);
  QM::Boundary_layer_mesher_2<K> mesher(domain, QM::Mesh_criteria_2<K>(), layers);
  QM::Quad_mesh_2<Point_2> mesh;
  try {
    mesh = mesher.run();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  const QM::Boundary_layer_report& report = mesher.report();
  std::cout << mesh.number_of_quads() << " quads, " << report.layer_quads << " in the layers (stack "
            << layers.thickness() << " thick); angles in the layers [" << report.layer_min_angle << ", "
            << report.layer_max_angle << "], outside [" << report.outer_min_angle << ", " << report.outer_max_angle
            << "]" << std::endl;
  bool heights_ok = true;
  for(const auto& w : report.walls) {
    std::cout << "wall marker " << w.marker << ": " << w.bands << " bands, " << w.fans << " fans, "
              << w.thinned_bands << " thinned; first height [" << w.first_height_min << ", " << w.first_height_max
              << "], growth [" << w.growth_min << ", " << w.growth_max << "]" << std::endl;
    heights_ok = heights_ok && std::abs(w.first_height_min - first_height) <= 0.01 * first_height
                 && std::abs(w.first_height_max - first_height) <= 0.01 * first_height;
  }

  // close-ups of the air foil's ends (the chord runs from 0 to 1)
  std::vector<std::pair<Point_2, Point_2>> boundary;
  for(const auto& s : domain.segments)
    boundary.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  if(!QM::IO::write_MSH(name + ".msh", mesh)
     || !QM::IO::write_SVG(name + "_leading_edge.svg", mesh, boundary, CGAL::Bbox_2(-0.01, -0.015, 0.02, 0.015))
     || !QM::IO::write_SVG(name + "_trailing_edge.svg", mesh, boundary, CGAL::Bbox_2(0.985, -0.012, 1.015, 0.012))) {
    std::cerr << "cannot write the outputs" << std::endl;
    return 1;
  }
  if(!quality.is_valid()) {
    std::cerr << "the mesh is invalid" << std::endl;
    return 3;
  }
  return heights_ok ? 0 : 4;
}
