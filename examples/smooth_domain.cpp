// The whole pipeline on a smooth domain (paper §4): the quadtree, the clearance of the buffer
// zone, the boundary templates and the two buffer layers, which reach the boundary. By default
// a disc with a circular hole; or any domain file given on the command line (`.poly`, WKT...).
//
//   smooth_domain [INPUT] [OUTPUT.svg]
//
// Prints the quad and vertex counts and the angle range, writes an SVG picture, and returns
// non-zero if the mesh is invalid (a quad not strictly convex and counter-clockwise, checked
// with exact predicates, or the library's quality check fails) or meshing fails.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_domain.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point_2;
namespace QM = CGAL::Quad_mesher_2;

// a closed polygon of n points on the circle (cx, cy, r), counter-clockwise or not: the
// library orients the loops itself
void add_circle(QM::Domain_2<K>& domain, double cx, double cy, double r, int n)
{
  const std::size_t first = domain.points.size();
  for(int i = 0; i < n; ++i) {
    const double t = 2 * 3.14159265358979323846 * i / n;
    domain.points.emplace_back(cx + r * std::cos(t), cy + r * std::sin(t));
    domain.segments.push_back({first + i, first + (i + 1) % n});
  }
}

int main(int argc, char** argv)
{
  QM::Domain_2<K> domain;
  if(argc > 1) {
    std::string error;
    if(!QM::IO::read_domain(argv[1], domain, &error)) {
      std::cerr << error << std::endl;
      return 1;
    }
  } else {
    add_circle(domain, 0, 0, 1, 64);      // the outer boundary
    add_circle(domain, 0.1, 0, 0.5, 64);  // a hole...
    domain.holes.emplace_back(0.1, 0);    // ...marked by a seed point inside it
  }
  const std::string svg = argc > 2 ? argv[2] : "smooth_domain.svg";

  QM::Quadtree_mesher_2<K> mesher(domain);
  QM::Quad_mesh_2<Point_2> mesh;
  try {
    mesh = mesher.run(); // every stage, through the smoothing
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }

  // every quad strictly convex and counter-clockwise (exact predicates)
  std::size_t bad = 0;
  const auto orientation = K().orientation_2_object();
  for(const auto& q : mesh.quads)
    for(int c = 0; c < 4; ++c)
      if(orientation(mesh.points[q[c]], mesh.points[q[(c + 1) % 4]], mesh.points[q[(c + 2) % 4]]) != CGAL::LEFT_TURN) {
        ++bad;
        break;
      }
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);

  std::cout << mesh.number_of_quads() << " quads, " << mesh.number_of_vertices() << " vertices, angles ["
            << quality.min_angle << ", " << quality.max_angle << "], " << 100 * quality.share_in_45_135
            << "% in [45, 135], " << quality.number_of_boundary_loops << " boundary loops, "
            << mesher.rounds() << " round(s)" << std::endl;

  std::vector<std::pair<Point_2, Point_2>> segments;
  for(const auto& s : domain.segments)
    segments.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  if(!QM::IO::write_SVG(svg, mesh, segments)) {
    std::cerr << "cannot write " << svg << std::endl;
    return 1;
  }
  std::cout << "wrote " << svg << std::endl;

  if(bad > 0 || !quality.is_valid() || quality.number_of_unused_vertices > 0 || mesh.quads.empty()) {
    std::cerr << "invalid mesh: " << bad << " quads not strictly convex, " << quality.number_of_inverted_quads
              << " inverted, " << quality.number_of_degenerate_quads << " degenerate, "
              << quality.number_of_hanging_nodes << " hanging nodes, " << quality.number_of_unused_vertices
              << " unused vertices" << std::endl;
    return 3;
  }
  return 0;
}
