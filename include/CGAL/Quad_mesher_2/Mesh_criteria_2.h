// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_MESH_CRITERIA_2_H
#define CGAL_QUAD_MESHER_2_MESH_CRITERIA_2_H

#include <CGAL/Quad_mesher_2/Balanced_quadtree_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>

#include <CGAL/number_utils.h>

#include <cmath>
#include <functional>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The size criteria of the quadtree (paper §4.2). A cell is split while it is
/// - larger than `max_size()` (if set, i.e. > 0), or
/// - larger than the spacing `s_i = min_j d_ij` of an input point `i` it contains
///   (if `use_point_spacing()`); for a domain bounded by segments, than `2 s_i` at a loop
///   vertex turning the boundary by less than 20 degrees, which the mesh may leave out; or
/// - larger than the user's sizing field at its centre or one of its corners (if set);
///
/// for a domain bounded by segments, the first and the last only in cells meeting the
/// bounding box of its points (beyond it every cell is cleared away, see `Stage::CLEARANCE`);
/// but never below `min_size()` (if set) nor deeper than `max_depth()`. A sizing that asks
/// for cells deeper than `max_depth()` without a `min_size()` to stop it is an error
/// (`Meshing_error`), not a silently coarser mesh. `max_size()` wins over `min_size()` where
/// the power-of-two cell sides cannot meet both.
///
/// With `points_as_vertices()` (the default) every input point becomes a mesh vertex (paper
/// §3, Lemma 1): the tree is refined further around each point, see `Stage::POINTS`.
///
/// \tparam GeomTraits a model of `QuadMesherTraits_2`
template <class GeomTraits>
class Mesh_criteria_2
{
public:
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  /// a target cell side at a point; must be positive
  typedef std::function<FT(const Point_2&)> Sizing_field;

  /// the deepest quadtree level `max_depth()` accepts: 40, cells of side `root_side/2^40`
  /// (input points about 10^-10 of the extent apart still become vertices); the tree may
  /// stop earlier where doubles cannot hold its lattice exactly (far from the origin)
  static constexpr int max_supported_depth = Balanced_quadtree_2<GeomTraits>::max_supported_depth;
  static constexpr int default_max_depth = max_supported_depth;

  /// `max_size` and `min_size` of 0 mean "no bound".
  explicit Mesh_criteria_2(double max_size = 0, double min_size = 0,
                           int max_depth = default_max_depth)
  {
    set_max_size(max_size);
    set_min_size(min_size);
    set_max_depth(max_depth);
  }

  double max_size() const { return m_max_size; }
  double min_size() const { return m_min_size; }
  int max_depth() const { return m_max_depth; }
  bool use_point_spacing() const { return m_use_point_spacing; }
  bool points_as_vertices() const { return m_points_as_vertices; }
  /// With segments in the input: refine so that every narrow region (two parts of the
  /// boundary facing each other across a gap w) has cells of side <= w/4 across it (paper
  /// §4.2: more than two cells in every direction, so no loop merges or vanishes).
  bool resolve_narrow_regions() const { return m_resolve_narrow_regions; }
  void set_resolve_narrow_regions(bool b) { m_resolve_narrow_regions = b; }
  /// the most quadtree leaves a mesher may make before it stops with `Meshing_error`: a guard
  /// against exhausting memory (about 120 bytes per leaf with Epick at the peak; the default,
  /// 2^23, is about 1 GB and is reached within seconds, while the largest shared domain needs
  /// under 10^6 leaves)
  std::size_t max_cells() const { return m_max_cells; }
  void set_max_cells(std::size_t n) { m_max_cells = n; }
  /// With segments in the input: how far from a loop vertex that turns the boundary by less
  /// than 20° the mesh's boundary may pass where it leaves the vertex out, as a fraction of
  /// the domain's diagonal (default 1e-3); 0 keeps every loop vertex a mesh vertex but those
  /// exactly on the line between the mesh vertices beside them.
  double chord_tolerance() const { return m_chord_tolerance; }
  void set_chord_tolerance(double t)
  {
    if(!(std::isfinite(t) && t >= 0))
      throw Meshing_error("the chord tolerance must be a finite number >= 0, got " + std::to_string(t));
    m_chord_tolerance = t;
  }
  const Sizing_field& sizing_field() const { return m_sizing_field; }

  void set_max_size(double s) { check_size(s, "maximum size"); m_max_size = s; check_order(); }
  void set_min_size(double s) { check_size(s, "minimum size"); m_min_size = s; check_order(); }
  void set_max_depth(int d)
  {
    if(d < 0 || d > max_supported_depth)
      throw Meshing_error("maximum depth " + std::to_string(d) + " is outside [0, "
                          + std::to_string(max_supported_depth) + "]");
    m_max_depth = d;
  }
  void set_use_point_spacing(bool b) { m_use_point_spacing = b; }
  void set_points_as_vertices(bool b) { m_points_as_vertices = b; }
  void set_sizing_field(Sizing_field f) { m_sizing_field = std::move(f); }

private:
  static void check_size(double s, const char* what)
  {
    if(!(std::isfinite(s) && s >= 0))
      throw Meshing_error(std::string(what) + " must be a finite number >= 0 (0 = unbounded), got "
                          + std::to_string(s));
  }
  void check_order() const
  {
    if(m_max_size > 0 && m_min_size > 0 && m_min_size > m_max_size)
      throw Meshing_error("minimum size " + std::to_string(m_min_size)
                          + " exceeds maximum size " + std::to_string(m_max_size));
  }

  double m_max_size = 0;
  double m_min_size = 0;
  int m_max_depth = default_max_depth;
  bool m_use_point_spacing = true;
  bool m_points_as_vertices = true;
  bool m_resolve_narrow_regions = true;
  std::size_t m_max_cells = std::size_t(1) << 23;
  double m_chord_tolerance = 1e-3;
  Sizing_field m_sizing_field;
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_MESH_CRITERIA_2_H
