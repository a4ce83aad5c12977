// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_TABLE_H
#define CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_TABLE_H

#include <array>
#include <cstddef>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// The 2-refinement templates (paper Fig. 1(a-c)) on the local lattice of a cell: coordinates
// count half cell sides, so the cell is [0,2]x[0,2] and every vertex a template adds lies on
// the lattice one level finer, where neighbouring cells' vertices meet with equal keys.
// Quads are counter-clockwise. Corner c of a cell is (0,0), (2,0), (2,2), (0,2) for
// c = 0, 1, 2, 3.
struct Local_vertex { unsigned char x, y; };
typedef std::array<Local_vertex, 4> Local_quad;

struct Quad_template
{
  std::size_t size;
  std::array<Local_quad, 4> quads;
};

// A cell with no active corner stays one quad.
inline const Quad_template& plain_template()
{
  static const Quad_template t = { 1, {{ {{ {0,0}, {2,0}, {2,2}, {0,2} }} }} };
  return t;
}

// One active corner: its quarter becomes a square and the rest two kites with angles
// 90, 90, 45, 135; both edges at the active corner are split, the other two are not.
inline const Quad_template& transition_template(int corner)
{
  static const std::array<Quad_template, 4> table = [] {
    const Quad_template base = { 3, {{
      {{ {0,0}, {1,0}, {1,1}, {0,1} }},
      {{ {1,0}, {2,0}, {2,2}, {1,1} }},
      {{ {1,1}, {2,2}, {0,2}, {0,1} }} }} };
    std::array<Quad_template, 4> result;
    result[0] = base;
    for(int c = 1; c < 4; ++c) {
      result[c] = result[c - 1];
      // a quarter turn about the cell centre maps corner c-1 to corner c
      for(Local_quad& q : result[c].quads)
        for(Local_vertex& v : q)
          v = Local_vertex{ static_cast<unsigned char>(2 - v.y), v.x };
    }
    return result;
  }();
  return table[corner];
}

// Two active corners (always diagonal, see apply_templates.h): four squares.
inline const Quad_template& refinement_template()
{
  static const Quad_template t = { 4, {{
    {{ {0,0}, {1,0}, {1,1}, {0,1} }},
    {{ {1,0}, {2,0}, {2,1}, {1,1} }},
    {{ {1,1}, {2,1}, {2,2}, {1,2} }},
    {{ {0,1}, {1,1}, {1,2}, {0,2} }} }} };
  return t;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_TEMPLATE_TABLE_H
