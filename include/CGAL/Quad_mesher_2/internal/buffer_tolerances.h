// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The tolerances the buffer stages decide with: how near an angle must be to a bound to
// count as on it, and how far the final check and the templates' searches let angles leave
// [45, 135].

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_TOLERANCES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_TOLERANCES_H

#include <cstddef>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// Shared by the buffer stages' classes (they derive from it) and their free functions.
struct Buffer_tolerances
{
  static constexpr std::size_t none = std::size_t(-1);
  static constexpr double pi = 3.14159265358979323846;
  // Angles within this many degrees of a bound count as on it, and closer ones as equal:
  // doubles hold an angle only to about 1e-8 degrees where the coordinates are 2^20 cell
  // sides, and a choice made by rounding differs on a scaled or moved domain (a cut corner's
  // core angle is exactly 135 degrees): power-of-two scalings and dyadic moves must give the
  // same mesh
  static constexpr double angle_tolerance = 1e-6;
  // The final check of the buffer quads is no looser than verify_mesh.py's range slack: a
  // quad passed here is one it passes.
  static constexpr double verifier_slack = 1e-7;
  // How far the templates' searches let a core angle leave [45, 135]: rounding only, well
  // below verifier_slack (nothing later need mend it).
  static constexpr double core_slack = 1e-9;

  // out of [45, 135] as the final check (and the verifier) counts it: an angle...
  static bool angle_out_of_range(double degrees)
  {
    return degrees < 45.0 - verifier_slack || degrees > 135.0 + verifier_slack;
  }
  // ... and a quad whose worst angle it may move lies `deviation` degrees from 90 (a quad's
  // cost, Buffer_zone::quad_cost()): what the optimiser and the first-layer smoothing lower
  static bool deviation_out_of_range(double deviation) { return deviation > 45.0 + verifier_slack; }
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_TOLERANCES_H
