// Cracks: a 4 x 2 plate with a bolt hole (a disc of 64 segments, radius 0.5) and two cracks,
// open polylines inside the plate: a straight one beside the hole and one kinked twice. Each
// crack is kept as a chain of mesh edges with a quad on either side, the two sides sharing
// its nodes; its ends are corners of 360 degrees. Written as cracks.vtu and cracks.svg.
//
// Prints the mesh's size and angles, and returns non-zero if the mesh is invalid, an angle is
// outside [45, 135], or a crack segment is not a chain of inner mesh edges.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <set>
#include <utility>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

const std::vector<std::vector<K::Point_2>> cracks = {
  { { 2.6, 1.0 }, { 3.2, 1.0 } },
  { { 0.4, 0.5 }, { 0.8, 0.8 }, { 1.1, 0.7 }, { 1.2, 1.2 } }, // kinks of 125 and 83 degrees
};

// appends a chain of points to the domain, closed into a loop or open (a crack)
void add_chain(QM::Domain_2<K>& domain, const std::vector<K::Point_2>& chain, bool closed)
{
  const std::size_t first = domain.points.size();
  domain.points.insert(domain.points.end(), chain.begin(), chain.end());
  for(std::size_t k = 0; k + (closed ? 0 : 1) < chain.size(); ++k)
    domain.segments.push_back({ first + k, first + (k + 1) % chain.size() });
}

QM::Domain_2<K> plate_with_cracks()
{
  QM::Domain_2<K> domain;
  add_chain(domain, { { 0, 0 }, { 4, 0 }, { 4, 2 }, { 0, 2 } }, true);
  std::vector<K::Point_2> hole;
  for(int k = 0; k < 64; ++k) hole.emplace_back(2 + 0.5 * std::cos(CGAL_PI * k / 32), 1 + 0.5 * std::sin(CGAL_PI * k / 32));
  add_chain(domain, hole, true);
  for(const auto& crack : cracks) add_chain(domain, crack, false);
  return domain;
}

// whether every segment of every crack is a chain of mesh edges, each with a quad on either side
bool cracks_are_edge_chains(const QM::Quad_mesh_2<K::Point_2>& mesh)
{
  std::set<std::pair<std::size_t, std::size_t>> directed_edges;
  for(const auto& q : mesh.quads)
    for(int c = 0; c < 4; ++c) directed_edges.insert({ q[c], q[(c + 1) % 4] });
  for(const auto& crack : cracks)
    for(std::size_t k = 0; k + 1 < crack.size(); ++k) {
      const K::Segment_2 segment(crack[k], crack[k + 1]);
      std::vector<std::pair<double, std::size_t>> on; // the mesh vertices on it, along it
      for(std::size_t v = 0; v < mesh.points.size(); ++v)
        if(CGAL::squared_distance(segment, mesh.points[v]) < 1e-24)
          on.emplace_back(CGAL::squared_distance(segment.source(), mesh.points[v]), v);
      std::sort(on.begin(), on.end());
      if(on.size() < 2 || mesh.points[on.front().second] != segment.source() || mesh.points[on.back().second] != segment.target())
        return false;
      for(std::size_t j = 0; j + 1 < on.size(); ++j)
        if(!directed_edges.count({ on[j].second, on[j + 1].second }) || !directed_edges.count({ on[j + 1].second, on[j].second }))
          return false;
    }
  return true;
}

// Meshes, writes, prints and checks; a Meshing_error is main's to report.
int mesh_cracks()
{
  const QM::Quad_mesh_2<K::Point_2> mesh = QM::make_quad_mesh_2(plate_with_cracks());
  if(!QM::IO::write_quad_mesh("cracks.vtu", mesh) || !QM::IO::write_quad_mesh("cracks.svg", mesh))
    return 1;
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  std::cout << mesh.quads.size() << " quads, angles [" << quality.min_angle << ", " << quality.max_angle << "] degrees"
            << std::endl;
  std::cout << "wrote cracks.vtu and cracks.svg" << std::endl;
  if(!quality.is_valid() || quality.min_angle < 45 - 1e-7 || quality.max_angle > 135 + 1e-7 || !cracks_are_edge_chains(mesh)) {
    std::cerr << "wrong mesh" << std::endl;
    return 3;
  }
  return 0;
}

int main()
{
  try {
    return mesh_cracks();
  } catch(const QM::Meshing_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 2;
  }
}
