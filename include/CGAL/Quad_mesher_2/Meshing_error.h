// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_MESHING_ERROR_H
#define CGAL_QUAD_MESHER_2_MESHING_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// Thrown when an input or a setting makes meshing impossible (a depth limit that a sizing
/// field would exceed, coordinates too far apart for the requested resolution, ...). The
/// message names the cause and, where there is one, the place.
class Meshing_error : public std::runtime_error
{
public:
  explicit Meshing_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_MESHING_ERROR_H
