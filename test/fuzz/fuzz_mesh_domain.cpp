// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// libFuzzer target: the whole mesher on small domains decoded from the bytes (a polygon of 3
// to 8 vertices, perhaps with a hole and isolated points, or a point cloud of 1 to 16 points,
// on a 1/16 grid with optional 2^-20 offsets, so that collinear, touching and near-touching
// inputs are frequent), with a cell budget that keeps each run to milliseconds. The mesher
// may refuse an input only with Meshing_error; a mesh it returns must be valid, have every
// isolated point or cloud point as a vertex, and angles in [45, 135] but where the library
// says otherwise: at an input corner under 45 degrees, or after refinement rounds that ended
// with angles out (rounds_end()). A cloud's mesh lies in its points' box with the margin
// (Quadtree_mesher_2::mesh_region()); a domain's covers the domain.

#include "fuzz_require.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace {

using qm2_fuzz::require;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
namespace QM = CGAL::Quad_mesher_2;
typedef QM::Domain_2<K> Domain;
typedef QM::Quadtree_mesher_2<K> Mesher;
typedef QM::Quad_mesh_2<K::Point_2> Mesh;

constexpr std::size_t cell_budget = 4096;
constexpr double angle_slack = 1e-7; // degrees, as the library's own checks

class Bytes
{
public:
  Bytes(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
  bool next(std::uint8_t& b)
  {
    if(m_at == m_size)
      return false;
    b = m_data[m_at++];
    return true;
  }
  // a coordinate on the 1/16 grid of [0, 8), 2^-20 more if the high bit is set
  bool coordinate(double& v)
  {
    std::uint8_t b = 0;
    if(!next(b))
      return false;
    v = (b & 0x7f) / 16.0 + ((b & 0x80) != 0 ? 0x1p-20 : 0.0);
    return true;
  }
  bool point(K::Point_2& p, double scale = 1, const K::Point_2& origin = K::Point_2(0, 0))
  {
    double x = 0, y = 0;
    if(!coordinate(x) || !coordinate(y))
      return false;
    p = K::Point_2(origin.x() + scale * x, origin.y() + scale * y);
    return true;
  }

private:
  const std::uint8_t* m_data;
  std::size_t m_size;
  std::size_t m_at = 0;
};

K::Point_2 centroid(const std::vector<K::Point_2>& ring)
{
  double x = 0, y = 0;
  for(const K::Point_2& p : ring) {
    x += p.x();
    y += p.y();
  }
  return K::Point_2(x / ring.size(), y / ring.size());
}

// a ring in the order of its points' directions from their centroid: mostly simple
void star_order(std::vector<K::Point_2>& ring)
{
  const K::Point_2 c = centroid(ring);
  std::sort(ring.begin(), ring.end(), [&](const K::Point_2& a, const K::Point_2& b) {
    return std::atan2(a.y() - c.y(), a.x() - c.x()) < std::atan2(b.y() - c.y(), b.x() - c.x());
  });
}

void add_ring(Domain& d, const std::vector<K::Point_2>& ring)
{
  const std::size_t first = d.points.size();
  for(std::size_t i = 0; i < ring.size(); ++i) {
    d.points.push_back(ring[i]);
    d.segments.push_back({ first + i, first + (i + 1) % ring.size() });
  }
}

// Byte 0: the kind (mod 3: a polygon, a polygon with a hole, a point cloud) and, above it,
// whether the outer ring and the hole are put in star order and how many isolated points
// follow (0 to 3); byte 1: the sizes; then the points.
bool decode(Bytes& bytes, Domain& d)
{
  std::uint8_t kind = 0, sizes = 0;
  if(!bytes.next(kind) || !bytes.next(sizes))
    return false;
  const unsigned flags = kind / 3;
  if(kind % 3 == 2) {
    d.points.resize(1 + sizes % 16);
    for(K::Point_2& p : d.points)
      if(!bytes.point(p))
        return false;
    return true;
  }
  std::vector<K::Point_2> outer(3 + sizes % 6);
  for(K::Point_2& p : outer)
    if(!bytes.point(p))
      return false;
  if((flags & 1) != 0)
    star_order(outer);
  add_ring(d, outer);
  if(kind % 3 == 1) {
    // within half a unit of the outer ring's centroid: often inside it
    std::vector<K::Point_2> hole(3 + (sizes / 6) % 4);
    const K::Point_2 c = centroid(outer);
    for(K::Point_2& p : hole)
      if(!bytes.point(p, 1.0 / 8, K::Point_2(c.x() - 0.5, c.y() - 0.5)))
        return false;
    if((flags & 2) != 0)
      star_order(hole);
    add_ring(d, hole);
  }
  for(unsigned i = 0; i < (flags / 4) % 4; ++i) {
    K::Point_2 p;
    if(!bytes.point(p))
      return false;
    d.points.push_back(p);
  }
  return true;
}

double ccw_angle(const K::Point_2& at, const K::Point_2& from, const K::Point_2& to)
{
  const double ax = from.x() - at.x(), ay = from.y() - at.y(), bx = to.x() - at.x(), by = to.y() - at.y();
  const double a = std::atan2(ax * by - ay * bx, ax * bx + ay * by) * 180 / M_PI;
  return a < 0 ? a + 360 : a;
}

// the interior angle of each loop vertex, by its place
std::map<std::pair<double, double>, double> input_corner_angles(const Domain& d, const Mesher& mesher)
{
  std::map<std::pair<double, double>, double> angles;
  for(const auto& loop : mesher.loops().loops) {
    const std::vector<std::size_t>& v = loop.vertices;
    for(std::size_t i = 0; i < v.size(); ++i) {
      const K::Point_2& p = d.points[v[i]];
      angles[{ p.x(), p.y() }] = ccw_angle(p, d.points[v[(i + 1) % v.size()]], d.points[v[(i + v.size() - 1) % v.size()]]);
    }
  }
  return angles;
}

// every corner angle in [45, 135], or forced: at an input corner of angle alpha under 45
// degrees, and at least alpha (the library's own rule, internal/buffer_zone.h)
void check_angles(const Domain& d, const Mesher& mesher, const Mesh& mesh)
{
  const auto corners = input_corner_angles(d, mesher);
  for(const auto& quad : mesh.quads)
    for(int c = 0; c < 4; ++c) {
      const K::Point_2& p = mesh.points[quad[c]];
      const double a = ccw_angle(p, mesh.points[quad[(c + 1) % 4]], mesh.points[quad[(c + 3) % 4]]);
      if(a >= 45 - angle_slack && a <= 135 + angle_slack)
        continue;
      const auto corner = corners.find({ p.x(), p.y() });
      require(corner != corners.end() && corner->second < 45 && a >= corner->second - 1e-3,
              "an angle outside [45, 135] is at an input corner under 45 degrees");
    }
}

double mesh_area(const Mesh& mesh)
{
  double area = 0;
  for(const auto& quad : mesh.quads)
    for(int c = 0; c < 4; ++c) {
      const K::Point_2 &p = mesh.points[quad[c]], &q = mesh.points[quad[(c + 1) % 4]];
      area += (p.x() * q.y() - q.x() * p.y()) / 2;
    }
  return area;
}

void check_domain_mesh(const Domain& d, const Mesher& mesher, const Mesh& mesh)
{
  const QM::Mesh_quality_2& quality = *mesher.quality();
  require(quality.number_of_near_duplicate_vertices == 0, "a domain's mesh has no near-duplicate vertices");
  if(mesher.rounds_end() == Mesher::Rounds_end::NONE)
    check_angles(d, mesher, mesh);
  // input vertices that are not sharp corners may be left out within 1e-3 of the diagonal
  const CGAL::Bbox_2 box = CGAL::bbox_2(d.points.begin(), d.points.end());
  const double diagonal = std::hypot(box.xmax() - box.xmin(), box.ymax() - box.ymin());
  double perimeter = 0;
  for(const Domain::Segment& s : d.segments)
    perimeter += std::sqrt(CGAL::squared_distance(d.points[s[0]], d.points[s[1]]));
  const double area = QM::domain_area(d, mesher.loops());
  require(std::abs(mesh_area(mesh) - area) <= 1e-3 * diagonal * perimeter + 1e-9 * diagonal * diagonal,
          "a domain's mesh covers the domain");
}

void check_cloud_mesh(const Mesher& mesher, const Mesh& mesh)
{
  const QM::Mesh_quality_2 quality = QM::compute_quality(mesh);
  require(quality.is_valid(), "a cloud's mesh is valid");
  require(quality.min_angle >= 45 - angle_slack && quality.max_angle <= 135 + angle_slack,
          "a cloud's angles are in [45, 135]");
  const CGAL::Bbox_2 points = CGAL::bbox_2(mesher.points().begin(), mesher.points().end());
  const double extent = (std::max)(points.xmax() - points.xmin(), points.ymax() - points.ymin());
  const double reach = extent > 0 ? extent * 3 / 20 : 1;
  const CGAL::Bbox_2 region = mesher.mesh_region();
  require(region.xmin() >= points.xmin() - reach && region.ymin() >= points.ymin() - reach
            && region.xmax() <= points.xmax() + reach && region.ymax() <= points.ymax() + reach,
          "a cloud's mesh lies in its points' box with the margin");
  for(const K::Point_2& p : mesh.points)
    require(region.xmin() <= p.x() && p.x() <= region.xmax() && region.ymin() <= p.y() && p.y() <= region.ymax(),
            "a cloud's mesh lies in its region");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes bytes(data, size);
  Domain domain;
  if(!decode(bytes, domain))
    return 0;
  QM::Mesh_criteria_2<K> criteria;
  criteria.set_max_cells(cell_budget);
  Mesher mesher(domain, criteria);
  Mesh mesh;
  try {
    mesh = mesher.run();
  } catch(const QM::Meshing_error&) {
    return 0; // refused, with the reason
  }
  require(!mesh.quads.empty(), "a mesh has quads");
  for(std::size_t i = 0; i < mesher.point_vertices().size(); ++i)
    require(mesh.points[mesher.point_vertices()[i]] == mesher.anchored_points()[i], "every point is a vertex");
  if(domain.is_point_cloud()) {
    require(mesher.point_vertices().size() == mesher.points().size(), "every cloud point is anchored");
    check_cloud_mesh(mesher, mesh);
  } else {
    require(mesher.quality() && mesher.quality()->is_valid(), "a domain's mesh is valid");
    std::set<std::pair<double, double>> isolated; // exact duplicates are merged
    for(std::size_t v : mesher.loops().isolated_points)
      isolated.insert({ domain.points[v].x(), domain.points[v].y() });
    require(mesher.point_vertices().size() == isolated.size(), "every isolated point is anchored");
    check_domain_mesh(domain, mesher, mesh);
  }
  return 0;
}
