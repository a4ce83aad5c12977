// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_MESHER_2_H
#define CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_MESHER_2_H

#include <CGAL/Quad_mesher_2/Boundary_layer_criteria_2.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>
#include <CGAL/Quad_mesher_2/internal/boundary_layer_extrusion.h>
#include <CGAL/Quad_mesher_2/internal/boundary_layer_offset.h>
#include <CGAL/Quad_mesher_2/internal/boundary_layer_smoothing.h>
#include <CGAL/Quad_mesher_2/internal/mesh_regions.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// What `Boundary_layer_mesher_2::run()` made of the stacks, by wall marker. Heights are
/// measured as the verifier would: the distance of each layer's nodes on a band's two rays
/// from the line of the band's wall edge.
struct Boundary_layer_report
{
  struct Wall
  {
    int marker = 0;
    std::size_t bands = 0;          ///< bands of stacked quads, one per wall edge piece
    std::size_t thinned_bands = 0;  ///< of those, thinner than the full stack (narrow places)
    std::size_t fans = 0;           ///< fans of rays about a wall vertex (sharp outward corners)
    /// over the bands that are neither thinned nor beside a fan: the first layer's height,
    /// each layer's height over the one below, and the stack's thickness
    double first_height_min = 0, first_height_median = 0, first_height_max = 0;
    double growth_min = 0, growth_max = 0;
    double thickness_min = 0, thickness_max = 0;
    /// the thinnest band's thickness over the full stack's, and where (a wall point)
    double thinnest_ratio = 1;
    std::array<double, 2> thinnest_at{ { 0, 0 } };
  };
  std::vector<Wall> walls;
  int layers = 0;
  std::size_t layer_quads = 0;
  /// the angle ranges inside the stacks and in the rest of the mesh, degrees
  double layer_min_angle = 0, layer_max_angle = 0;
  double outer_min_angle = 0, outer_max_angle = 0;
};

/// \ingroup PkgQuadMesher2Ref
/// Meshes a domain with boundary layers on its walls (paper §5): each wall loop is offset into
/// the domain by the stack's thickness (thinned where the boundary faces it closer than three
/// stacks), the domain bounded by the offsets is meshed by `Quadtree_mesher_2` with its
/// guarantee, and the stacks are extruded between each wall and its offset from the nodes
/// that mesh put on the offset: `layers()` quads on every wall edge, their heights growing by
/// `growth()` from `first_height()`, conforming with the rest. Around a corner turning the
/// wall outward by more than 45° (a trailing edge, a reflex corner of the domain) the stack
/// fans around the corner in kites and bands whose angles stay within [45°, 135°] where the
/// rest of the mesh does not crowd the fan; every angle of the stacks stays within
/// [22.5°, 157.5°] but where an input angle under 45° forces less.
///
/// \tparam GeomTraits a model of `QuadMesherTraits_2`
template <class GeomTraits>
class Boundary_layer_mesher_2
{
public:
  typedef typename GeomTraits::Point_2 Point_2;
  typedef Quad_mesh_2<Point_2> Mesh;
  typedef Quadtree_mesher_2<GeomTraits> Outer_mesher;

  /// Keeps a reference to `domain`, which must outlive the mesher.
  Boundary_layer_mesher_2(const Domain_2<GeomTraits>& domain, const Mesh_criteria_2<GeomTraits>& criteria,
                          const Boundary_layer_criteria_2& layers, const GeomTraits& traits = GeomTraits())
    : m_domain(domain), m_criteria(criteria), m_layers(layers), m_traits(traits)
  {}
  Boundary_layer_mesher_2(Domain_2<GeomTraits>&& domain, const Mesh_criteria_2<GeomTraits>& criteria,
                          const Boundary_layer_criteria_2& layers, const GeomTraits& traits = GeomTraits()) = delete;

  /// The whole mesh, with its boundary edges and their markers. Throws `Meshing_error` for a
  /// point cloud, a wall marker no segment carries, a loop only partly a wall, or a stack
  /// that cannot fit even when thinned.
  Mesh run()
  {
    if(m_domain.is_point_cloud())
      throw Meshing_error("boundary layers need a domain bounded by segments, not a point cloud");
    auto start = std::chrono::steady_clock::now();
    m_loops = extract_loops(m_domain, m_traits);
    internal::reject_junctions(m_domain, "boundary layers");
    m_walls = internal::wall_loops(m_domain, m_loops, m_layers.wall_markers());
    internal::Wall_offsetter<GeomTraits>(m_domain, m_loops, m_walls, m_layers.layers(), m_layers.thickness(),
                                         m_layers.first_height() / m_layers.thickness())
      .run();
    std::vector<std::size_t> offset_first;
    m_outer_domain = std::make_unique<Domain_2<GeomTraits>>(
      internal::offset_domain(m_domain, m_loops, m_walls, offset_first));
    record("boundary_layer_offsets", start);
    // every offset vertex a mesh vertex: the ray of its wall vertex ends there
    Mesh_criteria_2<GeomTraits> outer_criteria = m_criteria;
    outer_criteria.set_chord_tolerance(0);
    m_outer = std::make_unique<Outer_mesher>(*m_outer_domain, outer_criteria, m_traits);
    m_outer->set_round_observer(m_round_observer);
    Mesh outer = m_outer->run();
    start = std::chrono::steady_clock::now();
    std::vector<double> fractions;
    for(int j = 0; j <= m_layers.layers(); ++j) fractions.push_back(m_layers.height_below(j) / m_layers.thickness());
    fractions.back() = 1;
    internal::Layer_extrusion<GeomTraits> extrusion(m_domain, m_walls, fractions);
    internal::Layer_extrusion_result<Point_2> result = extrusion.run(std::move(outer));
    smooth_stacks(result);
    internal::mark_boundary_and_regions(result.mesh, m_domain, m_loops);
    make_report(result);
    record("boundary_layers", start);
    return std::move(result.mesh);
  }

  /// the mesher of the domain bounded by the offsets (after `run()`): its rounds, buffer
  /// report and timings
  const Outer_mesher& outer_mesher() const
  {
    CGAL_precondition(m_outer != nullptr);
    return *m_outer;
  }
  /// the domain bounded by the offsets (after `run()`)
  const Domain_2<GeomTraits>& outer_domain() const
  {
    CGAL_precondition(m_outer_domain != nullptr);
    return *m_outer_domain;
  }
  const Boundary_layer_report& report() const { return m_report; }
  /// passed to the outer mesher (`Quadtree_mesher_2::set_round_observer()`)
  void set_round_observer(typename Outer_mesher::Round_observer observer) { m_round_observer = std::move(observer); }
  /// the offsets' and the stacks' wall-clock times (the outer mesher keeps its own)
  const std::vector<std::pair<std::string, double>>& timings() const { return m_timings; }

private:
  // heights of a ray's nodes above the line of wall edge (a, b)
  static std::vector<double> heights(const Mesh& mesh, const std::vector<std::size_t>& ray, const internal::Point_2d& a,
                                     const internal::Point_2d& b)
  {
    const internal::Vector_2d n = internal::wall_normal(a, b);
    std::vector<double> h;
    for(std::size_t v : ray) h.push_back(CGAL::scalar_product(internal::to_point_2d(mesh.points[v]) - a, n));
    return h;
  }

  // the stack's own thickness over the whole of band's wall edge: neither thinned nor
  // thickened (at a needle's tip)
  bool full_thickness(const internal::Layer_band& band) const
  {
    const internal::Wall_offset& w = m_walls[band.wall];
    const double T = m_layers.thickness();
    for(std::size_t k : { band.edge, w.next(band.edge) })
      if(std::abs(w.thickness[k] - T) > 1e-9 * T) return false;
    return true;
  }

  // smooths the stacks' nodes off the wall, but for the rays of the bands with the stack's
  // own heights (regular and full), which keep them exactly
  void smooth_stacks(internal::Layer_extrusion_result<Point_2>& r) const
  {
    std::vector<internal::Stack_node> nodes = std::move(r.nodes);
    for(const internal::Layer_band& band : r.bands)
      if(band.regular && full_thickness(band))
        for(const auto* ray : { &band.left, &band.right })
          for(std::size_t v : *ray) nodes[v] = internal::Stack_node::fixed;
    internal::Layer_smoothing<Point_2>(r.mesh, r.first_layer_quad, std::move(nodes)).run();
  }

  void make_report(const internal::Layer_extrusion_result<Point_2>& r)
  {
    m_report = Boundary_layer_report();
    m_report.layers = m_layers.layers();
    const double T = m_layers.thickness();
    std::map<int, Boundary_layer_report::Wall> walls;
    std::map<int, std::vector<double>> first;
    for(std::size_t i = 0; i < m_walls.size(); ++i)
      for(int m : m_walls[i].markers) walls[m].marker = m;
    for(std::size_t i = 0; i < m_walls.size(); ++i) walls[m_walls[i].markers.front()].fans += r.fans[i];
    for(const internal::Layer_band& band : r.bands) {
      const internal::Wall_offset& w = m_walls[band.wall];
      Boundary_layer_report::Wall& s = walls[w.markers[band.edge]];
      ++s.bands;
      const internal::Point_2d a = w.wall[band.edge], b = w.wall[w.next(band.edge)];
      const std::vector<double> hl = heights(r.mesh, band.left, a, b), hr = heights(r.mesh, band.right, a, b);
      if(!full_thickness(band)) {
        const double thickness = (std::min)(w.thickness[band.edge], w.thickness[w.next(band.edge)]);
        if(thickness > T * (1 - 1e-9)) continue; // thickened at a needle's tip
        ++s.thinned_bands;
        if(thickness / T < s.thinnest_ratio) {
          s.thinnest_ratio = thickness / T;
          const internal::Point_2d p = internal::to_point_2d(r.mesh.points[band.left.front()]);
          s.thinnest_at = { { p.x(), p.y() } };
        }
        continue;
      }
      if(!band.regular) continue;
      for(const auto* h : { &hl, &hr }) {
        first[s.marker].push_back((*h)[1]);
        for(std::size_t j = 2; j < h->size(); ++j) {
          const double g = ((*h)[j] - (*h)[j - 1]) / ((*h)[j - 1] - (*h)[j - 2]);
          s.growth_min = s.growth_min == 0 ? g : (std::min)(s.growth_min, g);
          s.growth_max = (std::max)(s.growth_max, g);
        }
        s.thickness_min = s.thickness_min == 0 ? h->back() : (std::min)(s.thickness_min, h->back());
        s.thickness_max = (std::max)(s.thickness_max, h->back());
      }
    }
    for(auto& [m, s] : walls) {
      std::vector<double>& f = first[m];
      if(!f.empty()) {
        std::sort(f.begin(), f.end());
        s.first_height_min = f.front();
        s.first_height_max = f.back();
        s.first_height_median = f[f.size() / 2];
      }
      m_report.walls.push_back(s);
    }
    angle_ranges(r);
  }

  void angle_ranges(const internal::Layer_extrusion_result<Point_2>& r)
  {
    m_report.layer_quads = r.mesh.quads.size() - r.first_layer_quad;
    double lo[2] = { 180, 180 }, hi[2] = { 0, 0 };
    for(std::size_t q = 0; q < r.mesh.quads.size(); ++q) {
      std::array<internal::Point_2d, 4> p;
      for(int c = 0; c < 4; ++c) p[c] = internal::to_point_2d(r.mesh.points[r.mesh.quads[q][c]]);
      const int in_layers = q >= r.first_layer_quad ? 1 : 0;
      for(double a : internal::quad_corner_angles(p)) {
        lo[in_layers] = (std::min)(lo[in_layers], a);
        hi[in_layers] = (std::max)(hi[in_layers], a);
      }
    }
    m_report.outer_min_angle = lo[0];
    m_report.outer_max_angle = hi[0];
    m_report.layer_min_angle = lo[1];
    m_report.layer_max_angle = hi[1];
  }

  void record(const char* stage, std::chrono::steady_clock::time_point start)
  {
    m_timings.emplace_back(stage, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }

  const Domain_2<GeomTraits>& m_domain;
  Mesh_criteria_2<GeomTraits> m_criteria;
  Boundary_layer_criteria_2 m_layers;
  GeomTraits m_traits;
  Domain_loops_2<GeomTraits> m_loops;
  std::vector<internal::Wall_offset> m_walls;
  std::unique_ptr<Domain_2<GeomTraits>> m_outer_domain; // the outer mesher refers to it
  std::unique_ptr<Outer_mesher> m_outer;
  Boundary_layer_report m_report;
  typename Outer_mesher::Round_observer m_round_observer;
  std::vector<std::pair<std::string, double>> m_timings;
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_MESHER_2_H
