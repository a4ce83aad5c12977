// Every input point becomes a mesh vertex (paper §3, Lemma 1): all angles stay in
// [45°, 135°] and the quads at each point have aspect ratio at most 1.5. Duplicate points are
// merged and counted.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <iostream>
#include <random>

typedef CGAL::Exact_predicates_exact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;

int main()
{
  QM::Domain_2<K> cloud;
  std::mt19937 rng(1);
  std::normal_distribution<double> cluster(0.0, 0.02);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for(int i = 0; i < 100; ++i)
    cloud.points.emplace_back(cluster(rng), cluster(rng)); // a dense cluster
  for(int i = 0; i < 20; ++i)
    cloud.points.emplace_back(uniform(rng), uniform(rng)); // and isolated points
  cloud.points.push_back(cloud.points.front());             // a duplicate

  QM::Quadtree_mesher_2<K> mesher(cloud);
  QM::Quad_mesh_2<K::Point_2> mesh = mesher.run(); // Stage::POINTS

  // Under Epeck the vertices are the input points exactly.
  std::size_t exact = 0;
  for(std::size_t i = 0; i < mesher.points().size(); ++i)
    exact += (mesh.points[mesher.point_vertices()[i]] == mesher.points()[i]);

  QM::Mesh_quality_2 q = QM::compute_quality(mesh);
  std::cout << mesh.number_of_quads() << " quads; " << exact << " of " << mesher.points().size()
            << " points are vertices (" << mesher.number_of_merged_points()
            << " duplicate merged); angles [" << q.min_angle << ", " << q.max_angle
            << "]; aspect at the points <= "
            << QM::max_aspect_ratio_around(mesh, mesher.point_vertices()) << std::endl;
  const bool ok = exact == mesher.points().size() && q.min_angle >= 45 && q.max_angle <= 135 && q.is_valid();
  return ok ? 0 : 1;
}
