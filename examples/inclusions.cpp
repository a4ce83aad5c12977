// Inclusions: a composite's cross-section, a 4 x 3 matrix holding three fibres (discs of 48
// segments) and a square hole, built in code. With a hole point (the hole's), Triangle's rule
// puts every face without one in the domain, so each fibre's loop is an interface between the
// matrix and the fibre: both are meshed, sharing the nodes on it. Regional attributes make
// two materials, the matrix 1 and the fibres 2. Written as inclusions.msh (physical surface
// groups region_1 and region_2) and inclusions.vtu.
//
// Prints each material's quads, and returns non-zero if the mesh is invalid, an angle is
// outside [45, 135], a quad lies in the other material, or a fibre's boundary is not a chain
// of mesh edges with a quad of either material on each.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

struct Fibre { double x, y, r; };
const std::vector<Fibre> fibres = { { 1.0, 1.0, 0.6 }, { 2.6, 1.9, 0.75 }, { 1.2, 2.3, 0.45 } };
const int fibre_segments = 48;

// appends a closed loop of points to the domain
void add_loop(QM::Domain_2<K>& domain, const std::vector<K::Point_2>& loop)
{
  const std::size_t first = domain.points.size();
  for(std::size_t k = 0; k < loop.size(); ++k) {
    domain.points.push_back(loop[k]);
    domain.segments.push_back({ first + k, first + (k + 1) % loop.size() });
  }
}

QM::Domain_2<K> matrix_with_fibres()
{
  QM::Domain_2<K> domain;
  add_loop(domain, { { 0, 0 }, { 4, 0 }, { 4, 3 }, { 0, 3 } });
  for(const Fibre& f : fibres) {
    std::vector<K::Point_2> disc;
    for(int k = 0; k < fibre_segments; ++k) {
      const double a = 2 * CGAL_PI * k / fibre_segments;
      disc.emplace_back(f.x + f.r * std::cos(a), f.y + f.r * std::sin(a));
    }
    add_loop(domain, disc);
  }
  add_loop(domain, { { 3.2, 0.3 }, { 3.6, 0.3 }, { 3.6, 0.7 }, { 3.2, 0.7 } });
  domain.holes = { { 3.4, 0.5 } };
  // the matrix's attribute 1, the fibres' 2 (one point in each fibre)
  domain.region_attributes = { { K::Point_2(0.1, 0.1), 1, 0 } };
  for(const Fibre& f : fibres) domain.region_attributes.push_back({ K::Point_2(f.x, f.y), 2, 0 });
  return domain;
}

// the fibre a point lies in, or -1
int fibre_at(const K::Point_2& p)
{
  for(std::size_t i = 0; i < fibres.size(); ++i)
    if(std::hypot(p.x() - fibres[i].x, p.y() - fibres[i].y) < fibres[i].r) return int(i);
  return -1;
}

// whether every segment of every fibre's loop is a chain of mesh edges, each with a matrix
// quad on one side and a fibre quad on the other
bool fibres_are_edge_chains(const QM::Domain_2<K>& domain, const QM::Quad_mesh_2<K::Point_2>& mesh)
{
  std::map<std::pair<std::size_t, std::size_t>, std::size_t> quad_of_edge;
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) quad_of_edge[{ mesh.quads[q][c], mesh.quads[q][(c + 1) % 4] }] = q;
  for(std::size_t s = 4; s < 4 + fibres.size() * fibre_segments; ++s) {
    const K::Segment_2 segment(domain.points[domain.segments[s][0]], domain.points[domain.segments[s][1]]);
    std::vector<std::pair<double, std::size_t>> on; // the mesh vertices on it, along it
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      if(CGAL::squared_distance(segment, mesh.points[v]) < 1e-24)
        on.emplace_back(CGAL::squared_distance(segment.source(), mesh.points[v]), v);
    std::sort(on.begin(), on.end());
    if(on.size() < 2 || mesh.points[on.front().second] != segment.source() || mesh.points[on.back().second] != segment.target())
      return false;
    for(std::size_t j = 0; j + 1 < on.size(); ++j) {
      const auto one = quad_of_edge.find({ on[j].second, on[j + 1].second });
      const auto other = quad_of_edge.find({ on[j + 1].second, on[j].second });
      if(one == quad_of_edge.end() || other == quad_of_edge.end()
         || mesh.regions[mesh.quad_regions[one->second]].attribute == mesh.regions[mesh.quad_regions[other->second]].attribute)
        return false;
    }
  }
  return true;
}

// Meshes, writes, prints and checks; a Meshing_error is main's to report.
int mesh_inclusions()
{
  const QM::Domain_2<K> domain = matrix_with_fibres();
  const QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(domain);
  if(!QM::IO::write_quad_mesh("inclusions.msh", mesh) || !QM::IO::write_quad_mesh("inclusions.vtu", mesh))
    return 1;
  std::map<double, std::size_t> quads; // by attribute
  bool in_place = true;
  for(std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const auto& v = mesh.quads[q];
    const double attribute = mesh.regions[mesh.quad_regions[q]].attribute;
    ++quads[attribute];
    const K::Point_2 centre = CGAL::centroid(mesh.points[v[0]], mesh.points[v[1]], mesh.points[v[2]], mesh.points[v[3]]);
    in_place = in_place && (attribute == 2) == (fibre_at(centre) >= 0);
  }
  for(const auto& [attribute, count] : quads)
    std::cout << "material " << attribute << ": " << count << " quads" << std::endl;
  std::cout << "wrote inclusions.msh and inclusions.vtu" << std::endl;
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << "angles [" << quality.min_angle << ", " << quality.max_angle << "] degrees" << std::endl;
  if(!quality.is_valid() || quality.min_angle < 45 - 1e-7 || quality.max_angle > 135 + 1e-7 || !in_place
     || quads.size() != 2 || !fibres_are_edge_chains(domain, mesh)) {
    std::cerr << "wrong mesh" << std::endl;
    return 3;
  }
  return 0;
}

int main()
{
  try {
    return mesh_inclusions();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 2;
  }
}
