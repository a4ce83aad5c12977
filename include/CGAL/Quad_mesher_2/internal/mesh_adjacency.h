// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Adjacency of a quad mesh: the quads at each vertex, a quad's corner at a vertex, and the
// oriented boundary loops of a mesh whose boundary vertices have two boundary edges each.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_MESH_ADJACENCY_H
#define CGAL_QUAD_MESHER_2_INTERNAL_MESH_ADJACENCY_H

#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// a quad's four vertex indices, counter-clockwise (`Quad_mesh_2::Quad`)
typedef std::array<std::size_t, 4> Quad_vertices;

/// The quads at each vertex of a quad mesh, in increasing order: compressed rows (two arrays
/// for the whole mesh, not a vector per vertex, which cost more than the buffer's own work on
/// large cores), of 32-bit indices, which halve the arrays' memory and its page faults.
class Vertex_quads
{
public:
  struct Range
  {
    const std::uint32_t* first;
    const std::uint32_t* last;
    const std::uint32_t* begin() const { return first; }
    const std::uint32_t* end() const { return last; }
    std::size_t size() const { return std::size_t(last - first); }
  };

  Vertex_quads(const std::vector<std::array<std::size_t, 4>>& quads, std::size_t n_points)
    : m_offsets(n_points + 1, 0), m_quads(4 * quads.size())
  {
    CGAL_precondition(4 * quads.size() <= (std::numeric_limits<std::uint32_t>::max)());
    for(const auto& q : quads)
      for(std::size_t v : q) ++m_offsets[v + 1];
    for(std::size_t v = 0; v < n_points; ++v) m_offsets[v + 1] += m_offsets[v];
    Array fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t q = 0; q < quads.size(); ++q)
      for(std::size_t v : quads[q]) m_quads[fill[v]++] = std::uint32_t(q);
  }

  Range operator[](std::size_t v) const
  {
    return Range{ m_quads.data() + m_offsets[v], m_quads.data() + m_offsets[v + 1] };
  }

private:
  // an entry per vertex or corner of a million-quad mesh, built twice a run: 2 MB pages
  typedef std::vector<std::uint32_t, Huge_page_allocator<std::uint32_t>> Array;
  Array m_offsets;
  Array m_quads;
};

/// the corner (0 to 3) of quad `Q` that is vertex `v` (a corner of it)
inline int corner_of(const Quad_vertices& Q, std::size_t v)
{
  int c = 0;
  while(Q[c] != v) ++c;
  return c;
}

/// calls `f(a, b)` for every boundary edge a -> b of a quad mesh (the only one of a -> b and
/// b -> a: the mesh is on its left), by increasing a (`quads_at`: the quads at each vertex)
template <class F>
void for_each_boundary_edge(const std::vector<std::array<std::size_t, 4>>& quads, const Vertex_quads& quads_at,
                            std::size_t n_points, F&& f)
{
  // both a -> b and b -> a are edges of quads at a
  std::vector<std::array<std::size_t, 2>> around; // a's next and previous vertex in each quad at a
  for(std::size_t a = 0; a < n_points; ++a) {
    around.clear();
    for(std::size_t q : quads_at[a]) {
      const int c = corner_of(quads[q], a);
      around.push_back({ quads[q][(c + 1) % 4], quads[q][(c + 3) % 4] });
    }
    for(const auto& e : around) {
      const std::size_t b = e[0];
      std::size_t uses = 0;
      for(const auto& g : around) uses += (g[0] == b ? 1 : 0) + (g[1] == b ? 1 : 0);
      if(uses == 1) f(a, b);
    }
  }
}

/// the oriented boundary loops of a quad mesh whose boundary vertices all have two boundary
/// edges (the core after the clearance): each loop has the mesh on its left
/// (`quads_at`: the quads at each vertex)
inline std::vector<std::vector<std::size_t>>
mesh_boundary_cycles(const std::vector<std::array<std::size_t, 4>>& quads, const Vertex_quads& quads_at,
                     std::size_t n_points)
{
  // Where several boundary edges leave one vertex, the largest target wins (they cannot: see
  // the precondition).
  std::vector<std::size_t> next(n_points, std::size_t(-1));
  for_each_boundary_edge(quads, quads_at, n_points, [&](std::size_t a, std::size_t b) {
    if(next[a] == std::size_t(-1) || b > next[a]) next[a] = b;
  });
  std::vector<std::vector<std::size_t>> cycles;
  std::vector<bool> seen(n_points, false);
  for(std::size_t v = 0; v < n_points; ++v) {
    if(next[v] == std::size_t(-1) || seen[v]) continue;
    std::vector<std::size_t> c;
    for(std::size_t u = v; !seen[u]; u = next[u]) {
      seen[u] = true;
      c.push_back(u);
      if(next[u] == std::size_t(-1)) break;
    }
    cycles.push_back(std::move(c));
  }
  return cycles;
}

inline std::vector<std::vector<std::size_t>>
mesh_boundary_cycles(const std::vector<std::array<std::size_t, 4>>& quads, std::size_t n_points)
{
  return mesh_boundary_cycles(quads, Vertex_quads(quads, n_points), n_points);
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_MESH_ADJACENCY_H
