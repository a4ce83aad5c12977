// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_CRITERIA_2_H
#define CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_CRITERIA_2_H

#include <CGAL/Quad_mesher_2/Meshing_error.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The boundary layers of a CFD mesh (paper §5): on every wall edge a stack of
/// `layers()` quads along the wall normal, of heights `first_height()`,
/// `first_height() * growth()`, `first_height() * growth()^2`, and so on, whose thickness is
/// `thickness()`. The walls are the loops whose segments carry one of `wall_markers()`; with
/// none given, the loops of the holes (the bodies in a far field), or the outer loop of a
/// domain without holes. Where facing walls are closer than three stacks, the stacks there
/// are thinned (every height scaled down alike, graded along the wall); see
/// `Boundary_layer_mesher_2`.
class Boundary_layer_criteria_2
{
public:
  /// the most layers a stack may have
  static constexpr int max_layers = 1000;

  Boundary_layer_criteria_2() = default;
  /// Throws `Meshing_error` on a bad value (see the setters).
  Boundary_layer_criteria_2(int layers, double first_height, double growth,
                            std::vector<int> wall_markers = std::vector<int>())
  {
    set_layers(layers);
    set_first_height(first_height);
    set_growth(growth);
    set_wall_markers(std::move(wall_markers));
  }

  int layers() const { return m_layers; }
  double first_height() const { return m_first_height; }
  double growth() const { return m_growth; }
  const std::vector<int>& wall_markers() const { return m_wall_markers; }

  /// the stack's thickness: `first_height() * (growth()^layers() - 1) / (growth() - 1)`, or
  /// `first_height() * layers()` for a growth of 1
  double thickness() const { return height_below(m_layers); }
  /// the height of layer `j`'s lower side above the wall (0 for j = 0, `thickness()` for
  /// j = `layers()`)
  double height_below(int j) const
  {
    if(m_growth == 1)
      return m_first_height * j;
    return m_first_height * (std::pow(m_growth, j) - 1) / (m_growth - 1);
  }

  /// `n` in [1, `max_layers`]
  void set_layers(int n)
  {
    if(n < 1 || n > max_layers)
      throw Meshing_error("the number of boundary layers must be in [1, " + std::to_string(max_layers) + "], got "
                          + std::to_string(n));
    m_layers = n;
    check_thickness();
  }
  /// `h` finite and > 0
  void set_first_height(double h)
  {
    if(!(std::isfinite(h) && h > 0))
      throw Meshing_error("the first boundary-layer height must be a finite number > 0, got " + text(h));
    m_first_height = h;
    check_thickness();
  }
  /// `r` finite and >= 1
  void set_growth(double r)
  {
    if(!(std::isfinite(r) && r >= 1))
      throw Meshing_error("the boundary-layer growth ratio must be a finite number >= 1, got " + text(r));
    m_growth = r;
    check_thickness();
  }
  /// the markers of the wall segments (`Domain_2::segment_markers`, or the loop numbers of a
  /// domain without markers); empty: the default walls
  void set_wall_markers(std::vector<int> markers) { m_wall_markers = std::move(markers); }

private:
  static std::string text(double v)
  {
    std::ostringstream s;
    s << v;
    return s.str();
  }
  void check_thickness() const
  {
    if(!std::isfinite(thickness()))
      throw Meshing_error("the boundary-layer stack is too thick to represent: first height " + text(m_first_height)
                          + ", growth " + text(m_growth) + ", " + std::to_string(m_layers) + " layers");
  }

  int m_layers = 1;
  double m_first_height = 1;
  double m_growth = 1;
  std::vector<int> m_wall_markers;
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_BOUNDARY_LAYER_CRITERIA_2_H
