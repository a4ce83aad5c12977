// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H
#define CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H

#include <CGAL/Quad_mesher_2/Balanced_quadtree_2.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/apply_templates.h>
#include <CGAL/Quad_mesher_2/internal/nearest_neighbor_distances.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The stages of the pipeline, in order; a mesher can stop after any of them.
enum class Stage
{
  QUADTREE ///< strongly balanced adaptive quadtree with 2-refinement templates (paper Fig. 3(b))
};

/// the name of a stage as the command-line tool spells it
inline const char* stage_name(Stage s)
{
  switch(s) {
  case Stage::QUADTREE: return "quadtree";
  }
  return "?";
}

/// \ingroup PkgQuadMesher2Ref
/// The mesher, stage by stage (the role `Delaunay_mesher_2` plays in Mesh_2). Each stage
/// records its wall-clock time in `timings()`.
///
/// \tparam GeomTraits a model of `QuadMesherTraits_2`
template <class GeomTraits>
class Quadtree_mesher_2
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  typedef Balanced_quadtree_2<GeomTraits> Quadtree;
  typedef Quad_mesh_2<Point_2> Mesh;
  typedef std::vector<std::pair<std::string, double>> Timings;

  /// Keeps a reference to `domain`, which must outlive the mesher.
  Quadtree_mesher_2(const Domain_2<GeomTraits>& domain,
                    const Mesh_criteria_2<GeomTraits>& criteria = Mesh_criteria_2<GeomTraits>(),
                    const GeomTraits& traits = GeomTraits())
    : m_domain(domain), m_criteria(criteria), m_traits(traits)
  {}

  /// Stage 1: refines the quadtree by the criteria, then strongly balances it.
  void build_quadtree()
  {
    auto start = std::chrono::steady_clock::now();
    if(m_domain.points.empty())
      throw Meshing_error("the input has no points");
    check_finite();
    m_tree = std::make_unique<Quadtree>(bounding_box(), m_criteria.max_depth(), m_traits);
    refine_to_max_size();
    if(m_criteria.use_point_spacing())
      refine_to_point_spacing();
    if(m_criteria.sizing_field())
      refine_to_sizing_field();
    record("refine", start);
    start = std::chrono::steady_clock::now();
    m_tree->balance();
    record("balance", start);
  }

  /// The conforming all-quad mesh of the whole balanced tree: every leaf replaced by its
  /// 2-refinement template. Every angle is 45, 90 or 135 degrees.
  Mesh core_mesh()
  {
    CGAL_precondition(m_tree != nullptr);
    auto start = std::chrono::steady_clock::now();
    Mesh mesh = internal::templated_mesh(*m_tree);
    record("templates", start);
    return mesh;
  }

  /// Runs the stages up to `last` and returns the mesh.
  Mesh run(Stage last = Stage::QUADTREE)
  {
    build_quadtree();
    CGAL_USE(last);
    return core_mesh();
  }

  const Quadtree& quadtree() const
  {
    CGAL_precondition(m_tree != nullptr);
    return *m_tree;
  }
  const Timings& timings() const { return m_timings; }
  const Mesh_criteria_2<GeomTraits>& criteria() const { return m_criteria; }

private:
  void record(const std::string& stage, std::chrono::steady_clock::time_point start)
  {
    std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
    m_timings.emplace_back(stage, d.count());
  }

  void check_finite() const
  {
    for(std::size_t i = 0; i < m_domain.points.size(); ++i) {
      const Point_2& p = m_domain.points[i];
      double x = CGAL::to_double(m_traits.compute_x_2_object()(p));
      double y = CGAL::to_double(m_traits.compute_y_2_object()(p));
      if(!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e150 || std::abs(y) > 1e150) {
        std::ostringstream msg;
        msg << "input point " << i << " (" << x << ", " << y
            << ") is not finite or beyond 1e150 in magnitude";
        throw Meshing_error(msg.str());
      }
    }
  }

  typename GeomTraits::Iso_rectangle_2 bounding_box() const
  {
    auto less_x = m_traits.less_x_2_object();
    auto less_y = m_traits.less_y_2_object();
    auto xs = std::minmax_element(m_domain.points.begin(), m_domain.points.end(), less_x);
    auto ys = std::minmax_element(m_domain.points.begin(), m_domain.points.end(), less_y);
    return m_traits.construct_iso_rectangle_2_object()(*xs.first, *xs.second, *ys.first,
                                                       *ys.second);
  }

  // the level whose cells have side <= s
  int level_for_size(double s) const
  {
    return (std::max)(0, int(std::ceil(std::log2(m_tree->root_side() / s))));
  }
  // the deepest level whose cells are not below the minimum size
  int min_size_level() const
  {
    if(m_criteria.min_size() <= 0)
      return m_criteria.max_depth();
    int l = int(std::floor(std::log2(m_tree->root_side() / m_criteria.min_size())));
    return (std::min)((std::max)(l, 0), m_criteria.max_depth());
  }

  void refine_to_max_size()
  {
    if(m_criteria.max_size() <= 0)
      return;
    const int level = (std::min)(level_for_size(m_criteria.max_size()), min_size_level());
    m_tree->refine([&](const Cell_key& k) { return k.level < level; });
  }

  // Paper §4.2: the cell holding input point i is no larger than s_i = min_j d_ij.
  void refine_to_point_spacing()
  {
    const std::size_t n = m_domain.points.size();
    if(n < 2)
      return;
    std::vector<std::array<double, 2>> xy(n);
    for(std::size_t i = 0; i < n; ++i)
      xy[i] = { CGAL::to_double(m_traits.compute_x_2_object()(m_domain.points[i])),
                CGAL::to_double(m_traits.compute_y_2_object()(m_domain.points[i])) };
    internal::Nearest_neighbor_distances nn(xy);
    const int cap = min_size_level();
    const bool capped = m_criteria.min_size() > 0;
    for(std::size_t i = 0; i < n; ++i) {
      if(nn.distance[i] <= 0 && !capped) {
        std::ostringstream msg;
        msg << "input points " << (std::min)(i, nn.neighbor[i]) << " and "
            << (std::max)(i, nn.neighbor[i]) << " coincide at (" << xy[i][0] << ", " << xy[i][1]
            << ")";
        throw Meshing_error(msg.str());
      }
      int level = nn.distance[i] > 0 ? level_for_size(nn.distance[i]) : cap;
      if(level > cap) {
        if(!capped) {
          std::ostringstream msg;
          msg.precision(17);
          msg << "input points " << i << " (" << xy[i][0] << ", " << xy[i][1] << ") and "
              << nn.neighbor[i] << " are " << nn.distance[i]
              << " apart: separating them needs quadtree depth " << level
              << ", beyond the maximum depth " << m_criteria.max_depth()
              << "; raise the maximum depth or set a minimum size";
          throw Meshing_error(msg.str());
        }
        level = cap;
      }
      if(level > 0)
        m_tree->refine_at(m_domain.points[i], level);
    }
  }

  void refine_to_sizing_field()
  {
    const auto& field = m_criteria.sizing_field();
    const int cap = min_size_level();
    const bool capped = m_criteria.min_size() > 0;
    m_tree->refine([&](const Cell_key& k) {
      double side = m_tree->cell_side(k.level);
      double target = CGAL::to_double(field(m_tree->cell_center(k)));
      for(int c = 0; c < 4; ++c)
        target = (std::min)(target, CGAL::to_double(field(m_tree->lattice_point(
                                        k.level, k.i + (c & 1), k.j + (c >> 1)))));
      if(!(target > 0))
        throw Meshing_error("the sizing field is not positive near ("
                            + std::to_string(m_tree->lattice_x(k.level, k.i)) + ", "
                            + std::to_string(m_tree->lattice_y(k.level, k.j)) + ")");
      if(side <= target)
        return false;
      return !capped || k.level < cap;
    });
  }

  const Domain_2<GeomTraits>& m_domain;
  Mesh_criteria_2<GeomTraits> m_criteria;
  GeomTraits m_traits;
  std::unique_ptr<Quadtree> m_tree;
  Timings m_timings;
};

/// \ingroup PkgQuadMesher2Ref
/// Meshes `domain` with the criteria, stopping after stage `last`, and returns the mesh
/// (the role `refine_Delaunay_mesh_2` plays in Mesh_2).
template <class GeomTraits>
Quad_mesh_2<typename GeomTraits::Point_2>
make_quad_mesh_2(const Domain_2<GeomTraits>& domain,
                 const Mesh_criteria_2<GeomTraits>& criteria = Mesh_criteria_2<GeomTraits>(),
                 Stage last = Stage::QUADTREE)
{
  Quadtree_mesher_2<GeomTraits> mesher(domain, criteria);
  return mesher.run(last);
}

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H
