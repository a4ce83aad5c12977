// An air foil in a far field: the NACA 0012 with a sharp trailing edge (153 points) is a hole
// in a square 40 chords wide, an ordinary domain with a hole. The sharp trailing edge, where
// the flow side turns by 341 degrees, must stay a corner of the mesh: it is kept as a vertex,
// and the quads around it share its angle.
//
//   airfoil [INPUT.poly] [OUTPUT_NAME]
//
// Prints the mesh's figures and the angle of every quad at the trailing edge (the air foil's
// rightmost point), writes OUTPUT_NAME.msh and three SVG pictures: the whole far field
// (OUTPUT_NAME.svg), the air foil (OUTPUT_NAME_near.svg) and the trailing edge
// (OUTPUT_NAME_trailing_edge.svg). Returns non-zero if meshing fails, the mesh is invalid or
// the trailing edge is not a mesh vertex.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
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
typedef std::vector<std::pair<Point_2, Point_2>> Segments;
namespace QM = CGAL::Quad_mesher_2;

// the angle (degrees, in [0, 360)) swept counter-clockwise at `v` from the direction to `a` to
// the direction to `b`: the interior angle of a counter-clockwise polygon with `a` after `v` and
// `b` before it
double angle_at(const Point_2& v, const Point_2& a, const Point_2& b)
{
  const double ax = a.x() - v.x(), ay = a.y() - v.y(), bx = b.x() - v.x(), by = b.y() - v.y();
  const double t = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180 / 3.14159265358979323846;
  return t < 0 ? t + 360 : t;
}

int main(int argc, char** argv)
{
  const std::string input = argc > 1 ? argv[1] : QM2_DATA_DIR "/naca0012/naca0012_sharp.poly";
  const std::string name = argc > 2 ? argv[2] : "airfoil";

  QM::Domain_2<K> domain;
  std::string error;
  if(!QM::IO::read_poly(input, domain, &error)) {
    std::cerr << error << std::endl;
    return 1;
  }

  // Default criteria: the cells shrink to the spacing of the air foil's points (0.0018 at the
  // leading edge) and grow, balanced, towards the far field.
  QM::Quadtree_mesher_2<K> mesher(domain);
  QM::Quad_mesh_2<Point_2> mesh;
  try {
    mesh = mesher.run(); // every stage, through the smoothing
  } catch(const QM::Meshing_error& e) {
    std::cerr << "meshing failed: " << e.what() << std::endl;
    return 1;
  }
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads, " << mesh.number_of_vertices() << " vertices, "
            << quality.number_of_boundary_loops << " boundary loops, angles [" << quality.min_angle << ", "
            << quality.max_angle << "], " << 100 * quality.share_in_45_135 << "% in [45, 135]" << std::endl;

  // The trailing edge: the rightmost point of the hole's loop (oriented with the domain, the
  // flow, on its left), and the flow side's angle there.
  std::size_t te = domain.points.size(), prev = 0, next = 0;
  for(const auto& loop : mesher.loops().loops) {
    if(loop.is_outer) continue;
    const std::vector<std::size_t>& v = loop.vertices;
    for(std::size_t k = 0; k < v.size(); ++k)
      if(te == domain.points.size() || domain.points[v[k]].x() > domain.points[te].x()) {
        te = v[k];
        next = v[(k + 1) % v.size()];
        prev = v[(k + v.size() - 1) % v.size()];
      }
  }
  if(te == domain.points.size()) {
    std::cerr << "no air foil: the domain has no hole" << std::endl;
    return 1;
  }
  const Point_2& T = domain.points[te];
  std::cout << "trailing edge " << T << ": domain angle " << angle_at(T, domain.points[next], domain.points[prev])
            << std::endl;

  // It is a mesh vertex, exactly (the mesh keeps the input's sharp corners as they are).
  std::size_t vertex = mesh.points.size();
  for(std::size_t v = 0; v < mesh.points.size(); ++v)
    if(mesh.points[v] == T) vertex = v;
  if(vertex == mesh.points.size()) {
    std::cerr << "the trailing edge is not a mesh vertex" << std::endl;
    return 3;
  }
  // the quads at it, counter-clockwise, and their angles there
  double sum = 0;
  std::cout << "  angles of the quads at it:";
  for(const auto& q : mesh.quads)
    for(int c = 0; c < 4; ++c)
      if(q[c] == vertex) {
        const double a = angle_at(T, mesh.points[q[(c + 1) % 4]], mesh.points[q[(c + 3) % 4]]);
        std::cout << ' ' << a;
        sum += a;
      }
  std::cout << " (sum " << sum << ")" << std::endl;

  Segments boundary;
  for(const auto& s : domain.segments)
    boundary.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  // close-ups (the chord is 1): the air foil, and its trailing edge
  const double x = T.x(), y = T.y();
  const CGAL::Bbox_2 foil_window(x - 1.3, y - 0.5, x + 0.3, y + 0.5);
  const CGAL::Bbox_2 edge_window(x - 0.06, y - 0.03, x + 0.02, y + 0.03);
  if(!QM::IO::write_MSH(name + ".msh", mesh) || !QM::IO::write_SVG(name + ".svg", mesh, boundary) ||
     !QM::IO::write_SVG(name + "_near.svg", mesh, boundary, foil_window) ||
     !QM::IO::write_SVG(name + "_trailing_edge.svg", mesh, boundary, edge_window)) {
    std::cerr << "cannot write " << name << ".msh or its pictures" << std::endl;
    return 1;
  }
  std::cout << "wrote " << name << ".msh, " << name << ".svg, " << name << "_near.svg, " << name
            << "_trailing_edge.svg" << std::endl;

  if(mesh.quads.empty() || !quality.is_valid() || quality.number_of_boundary_loops != mesher.loops().loops.size()) {
    std::cerr << "invalid mesh: " << quality.number_of_inverted_quads << " inverted, "
              << quality.number_of_degenerate_quads << " degenerate, " << quality.number_of_hanging_nodes
              << " hanging nodes, " << quality.number_of_boundary_loops << " boundary loops" << std::endl;
    return 3;
  }
  return 0;
}
