// A domain bounded by smooth curves (paper §4.1): each loop of control points is read as a
// closed cubic spline through them and decomposed into a polygon whose segments turn by at
// most 5 degrees and stay within a chord error of the curve; then the domain is meshed
// through every stage. Here an outer curve through 8 points and a hole through 4.
//
//   spline_domain [OUTPUT.svg]
//
// Prints how many segments replace the curves and the mesh's figures, writes an SVG picture
// (the decomposed curves in blue), and returns non-zero if decomposing or meshing fails or
// the mesh is invalid.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Curve_decomposition_2.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
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

// appends a closed loop through `points` (in either orientation) to the domain
void add_loop(QM::Domain_2<K>& domain, const std::vector<Point_2>& points)
{
  const std::size_t first = domain.points.size(), n = points.size();
  for(std::size_t i = 0; i < n; ++i) {
    domain.points.push_back(points[i]);
    domain.segments.push_back({first + i, first + (i + 1) % n});
  }
}

int main(int argc, char** argv)
{
  const std::string svg = argc > 1 ? argv[1] : "spline_domain.svg";

  // The control points: the curves pass through them, in order; the loops close by themselves.
  QM::Domain_2<K> controls;
  add_loop(controls, { Point_2(0, 0), Point_2(2, -0.5), Point_2(4, 0), Point_2(4.5, 1.5),
                       Point_2(3, 2.5), Point_2(1.5, 2), Point_2(0, 2.5), Point_2(-0.5, 1.2) });
  add_loop(controls, { Point_2(1, 0.8), Point_2(1.6, 0.5), Point_2(2.4, 0.9), Point_2(1.6, 1.3) });
  controls.holes.emplace_back(1.6, 0.9);  // the inner curve bounds a hole

  QM::Curve_decomposition_options options;
  options.max_turning_angle_deg = 5;  // the paper's criterion 1 (the default)
  options.max_chord_error = 0.002;    // criterion 2 (default 0: 1e-3 of the bounding-box diagonal)

  QM::Quad_mesh_2<Point_2> mesh;
  QM::Domain_2<K> domain;
  int rounds = 0;
  try {
    domain = QM::decompose_domain_curves(controls, options);  // keeps the control points as vertices
    QM::Quadtree_mesher_2<K> mesher(domain);
    mesh = mesher.run(); // every stage, through the smoothing
    rounds = mesher.rounds();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "failed: " << e.what() << std::endl;
    return 1;
  }
  std::cout << controls.points.size() << " control points -> " << domain.segments.size() << " segments" << std::endl;

  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads, " << mesh.number_of_vertices() << " vertices, "
            << quality.number_of_boundary_loops << " boundary loops, " << rounds << " round(s), angles ["
            << quality.min_angle << ", " << quality.max_angle << "], " << 100 * quality.share_in_45_135
            << "% in [45, 135]" << std::endl;

  std::vector<std::pair<Point_2, Point_2>> boundary;
  for(const auto& s : domain.segments)
    boundary.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  if(!QM::IO::write_SVG(svg, mesh, boundary)) {
    std::cerr << "cannot write " << svg << std::endl;
    return 1;
  }
  std::cout << "wrote " << svg << std::endl;

  if(mesh.quads.empty() || !quality.is_valid() || quality.number_of_boundary_loops != 2) {
    std::cerr << "invalid mesh: " << quality.number_of_inverted_quads << " inverted, "
              << quality.number_of_degenerate_quads << " degenerate, " << quality.number_of_hanging_nodes
              << " hanging nodes, " << quality.number_of_boundary_loops << " boundary loops" << std::endl;
    return 3;
  }
  return 0;
}
