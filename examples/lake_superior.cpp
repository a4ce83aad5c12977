// Lake Superior, the paper's test case (1): the shore and 6 islands, 518 points on 7 loops,
// with narrow channels and a 15-degree corner, meshed through every stage with a size bound.
//
//   lake_superior [INPUT.poly] [OUTPUT.svg] [OUTPUT.msh]
//
// Prints the quad and vertex counts, the angle range and the share of angles in [45, 135],
// writes an SVG picture (quads coloured by their worst angle, the input boundary in blue) and
// the mesh for Gmsh, and returns non-zero if meshing fails or the mesh is invalid.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
namespace QM = CGAL::Quad_mesher_2;

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : QM2_DATA_DIR "/lake_superior/lake_superior.poly";
  const std::string svg = argc > 2 ? argv[2] : "lake_superior.svg";
  const std::string msh = argc > 3 ? argv[3] : "lake_superior.msh";

  QM::Domain_2<K> domain;  // points, segments, and one seed point in each island (a hole)
  std::string error;
  if(!QM::IO::read_poly(input, domain, &error)) {
    std::cerr << error << std::endl;  // "FILE:LINE: problem"
    return 1;
  }

  // The cells are sized by the spacing of the input points and the narrow channels; a size
  // bound also caps them in open water (the lake is 0.8 wide): no cell side above 0.01.
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_max_size(0.01);

  QM::Quadtree_mesher_2<K> mesher(domain, criteria);
  QM::Quad_mesh_2<Point_2> mesh;
  try {
    mesh = mesher.run();  // every stage, through the smoothing
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }

  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads, " << mesh.number_of_vertices() << " vertices, "
            << quality.number_of_boundary_loops << " boundary loops, " << mesher.rounds() << " round(s)\n"
            << "angles [" << quality.min_angle << ", " << quality.max_angle << "], "
            << 100 * quality.share_in_45_135 << "% in [45, 135], " << 100 * quality.share_in_60_120
            << "% in [60, 120]" << std::endl;

  std::vector<std::pair<Point_2, Point_2>> boundary;
  for(const auto& s : domain.segments)
    boundary.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  if(!QM::IO::write_SVG(svg, mesh, boundary) || !QM::IO::write_MSH(msh, mesh)) {
    std::cerr << "cannot write " << svg << " or " << msh << std::endl;
    return 1;
  }
  std::cout << "wrote " << svg << " and " << msh << std::endl;

  // valid: no inverted or degenerate quad, no hanging node, conforming, and one boundary loop
  // per input loop (the shore and the islands)
  if(mesh.quads.empty() || !quality.is_valid() || quality.number_of_boundary_loops != mesher.loops().loops.size()) {
    std::cerr << "invalid mesh: " << quality.number_of_inverted_quads << " inverted, "
              << quality.number_of_degenerate_quads << " degenerate, " << quality.number_of_hanging_nodes
              << " hanging nodes, " << quality.number_of_non_manifold_edges << " non-manifold edges, "
              << quality.number_of_boundary_loops << " boundary loops" << std::endl;
    return 3;
  }
  return 0;
}
