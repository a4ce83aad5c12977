// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_APPLY_TEMPLATES_H
#define CGAL_QUAD_MESHER_2_INTERNAL_APPLY_TEMPLATES_H

#include <CGAL/Quad_mesher_2/Cell_key.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>
#include <CGAL/Quad_mesher_2/internal/Key_map.h>
#include <CGAL/Quad_mesher_2/internal/lattice_region.h>
#include <CGAL/Quad_mesher_2/internal/template_table.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Which 2-refinement template a leaf takes.
//
// The paper (§3) walks each boundary {V1..V2k} of the region of split cells at a level and
// makes every other vertex active. We take the alternation from the lattice instead: a
// vertex (X, Y) of the level-L lattice is active if X+Y is even and it touches a split
// level-L cell. Consecutive boundary vertices differ by one lattice step, so this alternates
// along every boundary loop, agrees at pinch points and needs no loop tracing. Every edge then
// has exactly one even end, and the even corners of a cell are diagonal, so:
//  - no active corner: the leaf stays one quad;
//  - one active corner: the transition template, which splits the two edges at that corner;
//  - two active corners: the refinement template, which splits all four edges.
// An edge is split exactly when its even end is active, which both cells sharing it see, so
// the mesh is conforming; strong balance guarantees that the split cells a leaf touches are
// its own level's (a leaf never touches a cell two levels finer).
struct Template_choice
{
  enum Kind : unsigned char { PLAIN, TRANSITION, REFINEMENT };
  Kind kind;
  int corner; // the active corner of a transition (0..3 as in template_table.h)
};

// `true` if the level-L lattice vertex (X, Y), a corner of leaf `k`, is active.
template <class Tree>
bool is_active_vertex(const Tree& tree, const Cell_key& k, std::int64_t X, std::int64_t Y)
{
  if(((X + Y) & 1) != 0)
    return false;
  for(std::int64_t j = Y - 1; j <= Y; ++j)
    for(std::int64_t i = X - 1; i <= X; ++i)
      if((i != std::int64_t(k.i) || j != std::int64_t(k.j)) && tree.in_grid(k.level, i, j)
         && tree.is_split(Cell_key(k.level, std::uint64_t(i), std::uint64_t(j))))
        return true;
  return false;
}

// `siblings_are_leaves`: the caller knows that k's three siblings are leaves, so the corner
// they share, their parent's centre (an even vertex), is not active, and is not looked up.
template <class Tree>
Template_choice choose_template(const Tree& tree, const Cell_key& k, bool siblings_are_leaves = false)
{
  static const int corner_dx[4] = { 0, 1, 1, 0 };
  static const int corner_dy[4] = { 0, 0, 1, 1 };
  const int centre_dx = 1 - int(k.i & 1), centre_dy = 1 - int(k.j & 1);
  int count = 0, last = -1;
  for(int c = 0; c < 4; ++c)
    if(!(siblings_are_leaves && corner_dx[c] == centre_dx && corner_dy[c] == centre_dy)
       && is_active_vertex(tree, k, std::int64_t(k.i) + corner_dx[c], std::int64_t(k.j) + corner_dy[c])) {
      ++count;
      last = c;
    }
  if(count == 0)
    return { Template_choice::PLAIN, -1 };
  if(count == 1)
    return { Template_choice::TRANSITION, last };
  return { Template_choice::REFINEMENT, -1 };
}

inline const Quad_template& template_of(const Template_choice& t)
{
  switch(t.kind) {
  case Template_choice::PLAIN: return plain_template();
  case Template_choice::TRANSITION: return transition_template(t.corner);
  default: return refinement_template();
  }
}

// The leaves in Morton (Z) order: neighbours are visited close together in time, so the
// hash-map slots of the vertices they share are still in cache.
template <class Tree>
std::vector<Cell_key> leaves_in_morton_order(const Tree& tree)
{
  typename Tree::Morton_coded_cells coded;
  coded.reserve(tree.number_of_leaves());
  tree.for_each_leaf([&](const Cell_key& k) { coded.emplace_back(tree.morton_code(k), k); });
  tree.sort_by_morton_code(coded);
  std::vector<Cell_key> result;
  result.reserve(coded.size());
  for(const auto& c : coded)
    result.push_back(c.second);
  return result;
}

// The conforming all-quad mesh of a strongly balanced tree: every leaf replaced by its
// template. Vertices are deduplicated by their integer key on the finest lattice, never by
// comparing coordinates. If `quad_cells` is given, it receives the leaf of each quad; if
// `vertex_keys` is, the key of each vertex on the tree's vertex lattice (`lattice_key(X, Y)`).
// If `region` is given, only its leaves are meshed (no leaf may cross its sides): templates
// are chosen in the whole tree, so the mesh is the part of the whole one inside it.
template <class Tree>
Quad_mesh_2<typename Tree::Point_2>
templated_mesh(const Tree& tree, std::vector<Cell_key>* quad_cells = nullptr,
               std::vector<Key_code>* vertex_keys_out = nullptr, const Lattice_region* region = nullptr)
{
  CGAL_precondition(tree.is_strongly_balanced());
  typedef typename Tree::Point_2 Point_2;
  Quad_mesh_2<Point_2> mesh;
  const int vertex_level = tree.vertex_level();
  const std::size_t expected = tree.number_of_leaves() * 2;
  // about one vertex per leaf (most leaves stay one quad): a map sized for that keeps its
  // load under a half and is half the memory to clear and miss in; more vertices rehash it
  Key_map vertex_index(tree.number_of_leaves());
  std::uint32_t number_of_vertices = 0;
  reserve_on_huge_pages(mesh.quads, expected);
  if(quad_cells != nullptr) {
    quad_cells->clear();
    reserve_on_huge_pages(*quad_cells, expected);
  }

  std::vector<Cell_key> leaves = leaves_in_morton_order(tree);
  if(region != nullptr)
    leaves.erase(std::remove_if(leaves.begin(), leaves.end(),
                                [&](const Cell_key& k) { return !region_contains_cell(*region, k.level, k.i, k.j); }),
                 leaves.end());
  // Four sibling leaves come one after another in Morton order: half of their template
  // lookups (those at their parent's centre) are known without looking (most leaves are so).
  // 2 MB pages: an entry per leaf, millions.
  std::vector<const Quad_template*, Huge_page_allocator<const Quad_template*>> templates(leaves.size());
  // The choice looks up the leaf's neighbours of its level in the node map, far larger than
  // the cache: those of the leaf `ahead` places on are prefetched meanwhile.
  constexpr std::size_t ahead = 8;
  auto prefetch_neighbours = [&tree](const Cell_key& k) {
    for(std::int64_t dj = -1; dj <= 1; ++dj)
      for(std::int64_t di = -1; di <= 1; ++di)
        if((di != 0 || dj != 0) && tree.in_grid(k.level, std::int64_t(k.i) + di, std::int64_t(k.j) + dj))
          tree.prefetch(Cell_key(k.level, std::uint64_t(std::int64_t(k.i) + di), std::uint64_t(std::int64_t(k.j) + dj)));
  };
  for(std::size_t n = 0; n < leaves.size();) {
    const Cell_key& k = leaves[n];
    const bool family = k.level > 0 && (k.i & 1) == 0 && (k.j & 1) == 0 && n + 3 < leaves.size()
                        && leaves[n + 1] == k.parent().child(1, 0) && leaves[n + 2] == k.parent().child(0, 1)
                        && leaves[n + 3] == k.parent().child(1, 1);
    for(const std::size_t end = family ? n + 4 : n + 1; n < end; ++n) {
      if(n + ahead < leaves.size()) prefetch_neighbours(leaves[n + ahead]);
      templates[n] = &template_of(choose_template(tree, leaves[n], family));
    }
  }
  // The quads look up a vertex map far larger than the cache, one miss per lookup: those of
  // the leaf `ahead` places on are prefetched likewise.
  // local half-cell units of leaf k -> its vertex lattice key
  auto vertex_key = [vertex_level](const Cell_key& k, const Local_vertex& v) {
    const int shift = vertex_level - k.level - 1;
    return lattice_key((std::uint64_t(k.i) << (shift + 1)) + (std::uint64_t(v.x) << shift),
                       (std::uint64_t(k.j) << (shift + 1)) + (std::uint64_t(v.y) << shift));
  };
  for(std::size_t n = 0; n < leaves.size(); ++n) {
    if(n + ahead < leaves.size()) {
      const Quad_template& t = *templates[n + ahead];
      for(std::size_t q = 0; q < t.size; ++q)
        for(const Local_vertex& v : t.quads[q])
          vertex_index.prefetch(vertex_key(leaves[n + ahead], v));
    }
    const Cell_key& k = leaves[n];
    const Quad_template& t = *templates[n];
    for(std::size_t q = 0; q < t.size; ++q) {
      typename Quad_mesh_2<Point_2>::Quad quad;
      for(int c = 0; c < 4; ++c) {
        const Key_code key = vertex_key(k, t.quads[q][c]);
        auto inserted = vertex_index.insert(key, number_of_vertices);
        number_of_vertices += inserted.second;
        quad[c] = *inserted.first;
      }
      mesh.quads.push_back(quad);
      if(quad_cells != nullptr)
        quad_cells->push_back(k);
    }
  }

  // The keys in vertex order, taken from the map, which goes before the points come: the
  // map and the points are never held together (peak memory).
  std::vector<Key_code> vertex_keys;
  reserve_on_huge_pages(vertex_keys, number_of_vertices);
  vertex_keys.resize(number_of_vertices);
  vertex_index.for_each([&](Key_code key, std::uint32_t v) { vertex_keys[v] = key; });
  vertex_index = Key_map();
  reserve_on_huge_pages(mesh.points, vertex_keys.size());
  for(Key_code key : vertex_keys)
    mesh.points.push_back(tree.lattice_point(vertex_level, lattice_key_x(key), lattice_key_y(key)));
  if(vertex_keys_out != nullptr)
    vertex_keys_out->swap(vertex_keys);
  return mesh;
}

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_APPLY_TEMPLATES_H
