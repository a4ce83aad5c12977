// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_BALANCED_QUADTREE_2_H
#define CGAL_QUAD_MESHER_2_BALANCED_QUADTREE_2_H

#include <CGAL/Quad_mesher_2/Cell_key.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/Huge_page_allocator.h>
#include <CGAL/Quad_mesher_2/internal/Key_map.h>
#include <CGAL/Quad_mesher_2/internal/radix_sort.h>

#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// An adaptive quadtree over a row-major grid of `nx` by `ny` square root cells, kept
/// *strongly balanced* on demand: leaves that share an edge or only a corner differ by at
/// most one level.
///
/// The root grid's side is a power of two and its lower-left corner a multiple of the finest
/// lattice spacing, so every cell corner (and every vertex the 2-refinement templates add at
/// half a cell) is an exactly representable `double`: the same code is exact under
/// `Exact_predicates_exact_constructions_kernel` and loses nothing under
/// `Exact_predicates_inexact_constructions_kernel`. A constructor argument that would break
/// this raises `Meshing_error`.
///
/// \tparam GeomTraits a model of `QuadMesherTraits_2`
template <class GeomTraits>
class Balanced_quadtree_2
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  typedef typename GeomTraits::Iso_rectangle_2 Iso_rectangle_2;
  /// cells with their `morton_code()`, as `sort_by_morton_code()` takes them; the lists of a
  /// million cells are fresh memory, in large pages where the system offers them
  typedef std::vector<std::pair<std::uint64_t, Cell_key>,
                      internal::Huge_page_allocator<std::pair<std::uint64_t, Cell_key>>> Morton_coded_cells;

  /// Builds a tree of root cells only, covering `bbox` with a margin, able to refine down to
  /// `max_depth` (cells of side `root_side/2^max_depth`; templates add half of that), at most
  /// `max_supported_depth` (40), or less where doubles cannot hold that lattice exactly (see
  /// `depth_limit()`). Cells of side below `finest_side` are refused too: a mesher passes the
  /// size below which its mesh's vertices could no longer be told apart.
  Balanced_quadtree_2(const Iso_rectangle_2& bbox, int max_depth = 20,
                      const GeomTraits& traits = GeomTraits(), double finest_side = 0)
    : m_traits(traits), m_max_depth(max_depth)
  {
    if(max_depth < 0 || max_depth > max_supported_depth)
      throw Meshing_error("maximum quadtree depth " + std::to_string(max_depth)
                          + " is outside [0, " + std::to_string(max_supported_depth) + "]");
    auto xmin = CGAL::to_interval(m_traits.compute_xmin_2_object()(bbox));
    auto ymin = CGAL::to_interval(m_traits.compute_ymin_2_object()(bbox));
    auto xmax = CGAL::to_interval(m_traits.compute_xmax_2_object()(bbox));
    auto ymax = CGAL::to_interval(m_traits.compute_ymax_2_object()(bbox));
    setup_root(xmin.first, ymin.first, xmax.second, ymax.second, finest_side);
  }

  /// \name Root grid and lattice
  /// @{
  int max_depth() const { return m_max_depth; }
  std::uint32_t root_cells_x() const { return m_nx; }
  std::uint32_t root_cells_y() const { return m_ny; }
  double root_side() const { return m_root_side; }
  double origin_x() const { return m_ox; }
  double origin_y() const { return m_oy; }
  /// side of a cell at `level`
  double cell_side(int level) const
  {
    // from a table: every lattice point and cell asks, and ldexp is a library call
    return unsigned(level) < m_sides.size() ? m_sides[level] : std::ldexp(m_root_side, -level);
  }
  /// the lattice level of the vertices of a templated mesh: one below `max_depth()`
  int vertex_level() const { return m_max_depth + 1; }
  /// the lattice coordinate `x` at `level`, as the exact double it is
  double lattice_x(int level, std::int64_t x) const { return m_ox + double(x) * cell_side(level); }
  double lattice_y(int level, std::int64_t y) const { return m_oy + double(y) * cell_side(level); }
  Point_2 lattice_point(int level, std::int64_t x, std::int64_t y) const
  {
    // From the doubles themselves: a lazy kernel then keeps one node per point, not three.
    return m_traits.construct_point_2_object()(lattice_x(level, x), lattice_y(level, y));
  }
  std::uint64_t cells_x(int level) const { return std::uint64_t(m_nx) << level; }
  std::uint64_t cells_y(int level) const { return std::uint64_t(m_ny) << level; }
  bool in_grid(int level, std::int64_t i, std::int64_t j) const
  {
    return i >= 0 && j >= 0 && i < std::int64_t(cells_x(level)) && j < std::int64_t(cells_y(level));
  }
  /// @}

  /// \name Cells
  /// @{
  bool is_node(const Cell_key& k) const { return m_nodes.find(k.code()) != nullptr; }
  bool is_leaf(const Cell_key& k) const
  {
    const std::uint32_t* v = m_nodes.find(k.code());
    return v != nullptr && *v == LEAF;
  }
  /// `true` if `k` is a node that has children
  bool is_split(const Cell_key& k) const
  {
    const std::uint32_t* v = m_nodes.find(k.code());
    return v != nullptr && *v == SPLIT;
  }
  /// starts loading the node map's slot of `k`, so that a lookup of it a little later does
  /// not wait for memory (a hint only: the map of a large tree is far larger than the cache)
  void prefetch(const Cell_key& k) const { m_nodes.prefetch(k.code()); }
  std::size_t number_of_leaves() const { return m_number_of_leaves; }
  std::size_t number_of_nodes() const { return m_nodes.size(); }
  /// the deepest level of any leaf
  int depth() const { return m_depth; }

  /// calls `f(const Cell_key&)` on every leaf
  template <class Function>
  void for_each_leaf(Function f) const
  {
    m_nodes.for_each([&](Key_code code, std::uint32_t v) {
      if(v == LEAF)
        f(Cell_key::from_code(code));
    });
  }
  std::vector<Cell_key> leaves() const
  {
    std::vector<Cell_key> result;
    result.reserve(m_number_of_leaves);
    for_each_leaf([&](const Cell_key& k) { result.push_back(k); });
    std::sort(result.begin(), result.end());
    return result;
  }

  Iso_rectangle_2 cell_rectangle(const Cell_key& k) const
  {
    return m_traits.construct_iso_rectangle_2_object()(lattice_point(k.level, k.i, k.j),
                                                       lattice_point(k.level, k.i + 1, k.j + 1));
  }
  Point_2 cell_center(const Cell_key& k) const
  {
    return lattice_point(k.level + 1, 2 * std::int64_t(k.i) + 1, 2 * std::int64_t(k.j) + 1);
  }

  /// The leaf that contains `p` (cells are closed below and to the left, open above and to
  /// the right); `p` must lie in the root grid. Decided with exact comparisons.
  Cell_key locate(const Point_2& p) const
  {
    std::uint64_t i = lattice_index(m_traits.compute_x_2_object()(p), m_ox, m_nx, m_max_depth);
    std::uint64_t j = lattice_index(m_traits.compute_y_2_object()(p), m_oy, m_ny, m_max_depth);
    for(int level = 0;; ++level) {
      Cell_key k(level, i >> (m_max_depth - level), j >> (m_max_depth - level));
      if(is_leaf(k))
        return k;
    }
  }
  /// The cell of level `level` (at most `max_depth()`) that contains `p`, a node of the tree
  /// or not: it is one exactly where the leaf `locate(p)` is at that level or finer, which
  /// one lookup tells. `p` must lie in the root grid.
  Cell_key cell_containing(const Point_2& p, int level) const
  {
    CGAL_precondition(level <= m_max_depth);
    const std::uint64_t i = lattice_index(m_traits.compute_x_2_object()(p), m_ox, m_nx, m_max_depth);
    const std::uint64_t j = lattice_index(m_traits.compute_y_2_object()(p), m_oy, m_ny, m_max_depth);
    return Cell_key(level, i >> (m_max_depth - level), j >> (m_max_depth - level));
  }
  /// The vertex of the level-`level` lattice nearest to `p` (ties go up and right), as lattice
  /// coordinates; decided exactly. `p` must lie in the root grid.
  std::pair<std::int64_t, std::int64_t> nearest_vertex(const Point_2& p, int level) const
  {
    CGAL_precondition(level <= m_max_depth);
    // the half-cell interval holding p tells the nearer end of the cell interval
    std::int64_t i = lattice_index(m_traits.compute_x_2_object()(p), m_ox, m_nx, level + 1);
    std::int64_t j = lattice_index(m_traits.compute_y_2_object()(p), m_oy, m_ny, level + 1);
    return { (i + 1) >> 1, (j + 1) >> 1 };
  }

  /// `true` if `p` lies in the half-open root grid
  bool contains(const Point_2& p) const
  {
    const FT x = m_traits.compute_x_2_object()(p), y = m_traits.compute_y_2_object()(p);
    return !(x < FT(m_ox)) && x < FT(lattice_x(0, m_nx)) && !(y < FT(m_oy))
           && y < FT(lattice_y(0, m_ny));
  }
  /// @}

  /// \name Refinement
  /// @{
  /// Splits leaf `k` into its four children.
  void split(const Cell_key& k)
  {
    // the children's slots, far apart in a map far larger than the cache, load together
    for(int c = 0; c < 4; ++c)
      m_nodes.prefetch(k.child(c & 1, c >> 1).code());
    std::uint32_t* v = m_nodes.find(k.code());
    CGAL_precondition(v != nullptr && *v == LEAF);
    if(k.level >= m_max_depth)
      throw Meshing_error(depth_message(k));
    if(m_number_of_leaves + 3 > m_max_leaves) {
      std::ostringstream msg;
      // where it ran out tells the user which feature asks for so many cells
      msg << "the mesh would need more than " << m_max_leaves
          << " quadtree cells (it ran out splitting a cell of side " << cell_side(k.level)
          << " near (" << lattice_x(k.level, k.i) << ", " << lattice_y(k.level, k.j)
          << ")); coarsen the sizing (maximum size, minimum size) or raise the cell budget";
      throw Meshing_error(msg.str());
    }
    *v = SPLIT;
    --m_number_of_leaves;
    for(int dy = 0; dy < 2; ++dy)
      for(int dx = 0; dx < 2; ++dx)
        add_leaf(k.child(dx, dy));
  }

  /// Makes room for about `n` more leaves, and their ancestors, before refining to a size
  /// known in advance: the node map and the list of new leaves then do not grow step by step,
  /// each step a copy into fresh memory (a rehash, one cache miss per node).
  void reserve(std::size_t n)
  {
    m_nodes.reserve(m_nodes.size() + n + n / 3);
    m_unbalanced.reserve(m_unbalanced.size() + n);
  }

  /// Splits leaves, children first, as long as `needs_split(const Cell_key&)` says so.
  /// Throws `Meshing_error` if it asks to split a cell at `max_depth()`.
  template <class SplitPredicate>
  void refine(SplitPredicate needs_split)
  {
    std::vector<Cell_key> stack = leaves();
    while(!stack.empty()) {
      Cell_key k = stack.back();
      stack.pop_back();
      if(!is_leaf(k) || !needs_split(k))
        continue;
      split(k);
      for(int dy = 0; dy < 2; ++dy)
        for(int dx = 0; dx < 2; ++dx)
          stack.push_back(k.child(dx, dy));
    }
  }

  /// Refines until the leaf containing `p` has at least `level`; `p` must lie in the grid.
  void refine_at(const Point_2& p, int level)
  {
    CGAL_precondition(contains(p));
    if(level > m_max_depth)
      throw Meshing_error(depth_message(Cell_key(level, 0, 0), &p));
    std::uint64_t i = lattice_index(m_traits.compute_x_2_object()(p), m_ox, m_nx, m_max_depth);
    std::uint64_t j = lattice_index(m_traits.compute_y_2_object()(p), m_oy, m_ny, m_max_depth);
    for(int l = 0; l < level; ++l) {
      Cell_key k(l, i >> (m_max_depth - l), j >> (m_max_depth - l));
      if(is_leaf(k))
        split(k);
    }
  }

  /// Makes `k` a node (a leaf or split) by splitting the leaf that covers it, and that leaf's
  /// descendants on the way down to `k`.
  void ensure_node(const Cell_key& k)
  {
    if(is_node(k))
      return;
    int level = k.level - 1;
    while(!is_node(Cell_key(level, k.i >> (k.level - level), k.j >> (k.level - level))))
      --level;
    for(; level < k.level; ++level)
      split(Cell_key(level, k.i >> (k.level - level), k.j >> (k.level - level)));
  }

  /// Splits leaves until any two leaves that share an edge or a corner differ by at most one
  /// level. One sweep from the deepest level up suffices: a leaf at level `L` only ever forces
  /// splits that create leaves above `L`, and those are visited later in the sweep.
  void balance()
  {
    // Only leaves made since the last balance can be too fine for a neighbour: the tree was
    // balanced before, and splitting never coarsens anything.
    std::vector<Cell_list> by_level(m_max_depth + 1);
    {
      // each level's list in one allocation: a million leaves would copy themselves on
      // every growth
      std::vector<std::size_t> count(m_max_depth + 1, 0);
      for(const Cell_key& k : m_unbalanced)
        ++count[k.level];
      for(int level = 0; level <= m_max_depth; ++level)
        by_level[level].reserve(count[level]);
    }
    for(const Cell_key& k : m_unbalanced)
      by_level[k.level].push_back(k);
    m_unbalanced.clear();
    m_unbalanced.shrink_to_fit();
    m_new_leaves = &by_level;
    // Cells known to be nodes, in a small direct-mapped cache before the node map: leaves
    // close in Morton order mostly share their neighbours (siblings their parent), and a node
    // stays one, so a hit skips a lookup, a cache miss in a map far larger than the cache.
    std::vector<Key_code> known_nodes(std::size_t(1) << known_bits, ~Key_code(0));
    for(int level = m_depth; level >= 2; --level) {
      // by_level[level] does not grow while this level is processed; Morton order keeps the
      // lookups of neighbouring leaves close together in time (and so in cache).
      Morton_coded_cells ordered;
      ordered.reserve(by_level[level].size());
      for(const Cell_key& k : by_level[level])
        ordered.emplace_back(morton_code(k), k);
      sort_by_morton_code(ordered);
      for(std::size_t n = 0; n < ordered.size(); ++n) {
        // the node map's slot of a leaf a few places on is loaded meanwhile: its lookup here
        // was most of balance()'s time, one cache miss each
        if(n + prefetch_ahead < ordered.size())
          m_nodes.prefetch(ordered[n + prefetch_ahead].second.code());
        const Cell_key& k = ordered[n].second;
        if(!is_leaf(k))
          continue;
        // The 3x3 block of level-L cells around k lies in a 2x2 block of level L-1 cells,
        // one of which is k's parent: at most three cells to make nodes.
        const std::int64_t i0 = k.i & 1 ? k.i : std::int64_t(k.i) - 1;
        const std::int64_t j0 = k.j & 1 ? k.j : std::int64_t(k.j) - 1;
        for(std::int64_t nj = j0; nj <= j0 + 1; ++nj)
          for(std::int64_t ni = i0; ni <= i0 + 1; ++ni)
            if(in_grid(level, ni, nj)) {
              const Key_code code = Cell_key(level - 1, std::uint64_t(ni >> 1), std::uint64_t(nj >> 1)).code();
              Key_code& known = known_nodes[(std::uint64_t(code) * 0x9e3779b97f4a7c15ULL) >> (64 - known_bits)];
              if(known != code) {
                ensure_node(Cell_key::from_code(code));
                known = code;
              }
            }
      }
    }
    m_new_leaves = nullptr;
    CGAL_expensive_postcondition(is_strongly_balanced());
  }

  /// The Morton (Z-order) code of a cell's lower-left corner on the lattice of level
  /// `min(max_depth(), 27)`, whose coordinates fit in 32 bits. Sorting by it follows the Z
  /// curve; cells deeper than level 27 tie with the others in their level-27 cell.
  std::uint64_t morton_code(const Cell_key& k) const
  {
    const int level = (std::min)(m_max_depth, morton_level);
    const std::uint64_t i = level >= k.level ? std::uint64_t(k.i) << (level - k.level)
                                             : std::uint64_t(k.i) >> (k.level - level);
    const std::uint64_t j = level >= k.level ? std::uint64_t(k.j) << (level - k.level)
                                             : std::uint64_t(k.j) >> (k.level - level);
    return spread_bits(i) | (spread_bits(j) << 1);
  }

  /// Sorts `coded`, cells each with its `morton_code()`, by the code.
  void sort_by_morton_code(Morton_coded_cells& coded) const
  {
    // Down to level 27 every cell has its own code and there is one order, which a radix sort
    // finds fastest. Deeper cells tie: they keep the order std::sort gives them, as they did.
    int deepest = 0;
    for(const auto& c : coded) deepest = (std::max)(deepest, int(c.second.level));
    if(deepest <= morton_level)
      internal::radix_sort_by_key(coded);
    else
      std::sort(coded.begin(), coded.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  }

  /// `true` if leaves sharing an edge or a corner never differ by more than one level.
  bool is_strongly_balanced() const
  {
    bool ok = true;
    for_each_leaf([&](const Cell_key& k) {
      for(int dy = -1; dy <= 1 && ok; ++dy)
        for(int dx = -1; dx <= 1 && ok; ++dx) {
          std::int64_t ni = std::int64_t(k.i) + dx, nj = std::int64_t(k.j) + dy;
          if(k.level < 2 || (dx == 0 && dy == 0) || !in_grid(k.level, ni, nj))
            continue;
          if(!is_node(Cell_key(k.level - 1, std::uint64_t(ni >> 1), std::uint64_t(nj >> 1))))
            ok = false;
        }
    });
    return ok;
  }
  /// @}

  const GeomTraits& geom_traits() const { return m_traits; }

  /// Refinement that would make more than `n` leaves raises `Meshing_error` instead of
  /// exhausting memory.
  void set_max_leaves(std::size_t n) { m_max_leaves = n; }
  std::size_t max_leaves() const { return m_max_leaves; }


  /// The deepest `max_depth` the tree accepts: 40 levels, cells of side `root_side/2^40`, about
  /// 10^-12 of the input's extent. Cell and vertex keys hold it (96-bit codes); doubles hold its
  /// lattice exactly for inputs within a few extents of the origin. Farther out the tree lowers
  /// its depth to what doubles hold and says so in `depth_limit()`.
  static constexpr int max_supported_depth = 40;

private:
  typedef std::vector<Cell_key, internal::Huge_page_allocator<Cell_key>> Cell_list;

  static constexpr std::uint32_t LEAF = 1;
  static constexpr std::uint32_t SPLIT = 0;

  static constexpr int morton_level = 27;
  static constexpr int known_bits = 12; // balance()'s cache of known nodes: 4096 cells
  static constexpr std::size_t prefetch_ahead = 8; // balance()'s look-ahead in its leaves
  static constexpr int snap_depth = 24;

  // spreads the low 32 bits of x to the even bits of the result
  static std::uint64_t spread_bits(std::uint64_t x)
  {
    x &= 0xffffffffULL;
    x = (x | (x << 16)) & 0x0000ffff0000ffffULL;
    x = (x | (x << 8)) & 0x00ff00ff00ff00ffULL;
    x = (x | (x << 4)) & 0x0f0f0f0f0f0f0f0fULL;
    x = (x | (x << 2)) & 0x3333333333333333ULL;
    x = (x | (x << 1)) & 0x5555555555555555ULL;
    return x;
  }

  void add_leaf(const Cell_key& k)
  {
    m_nodes.insert(k.code(), LEAF);
    ++m_number_of_leaves;
    m_depth = (std::max)(m_depth, k.level);
    if(m_new_leaves != nullptr)
      (*m_new_leaves)[k.level].push_back(k);
    else
      m_unbalanced.push_back(k);
  }

  void setup_root(double xmin, double ymin, double xmax, double ymax, double finest_side)
  {
    if(!(std::isfinite(xmin) && std::isfinite(ymin) && std::isfinite(xmax) && std::isfinite(ymax))
       || xmin > xmax || ymin > ymax)
      throw Meshing_error("the bounding box of the input is empty or not finite");
    const double w = xmax - xmin, h = ymax - ymin;
    double extent = (std::max)(w, h);
    // Root cells are at least 1/max_aspect of the longer side, so that the grid holds at
    // most max_aspect cells in a row; a thin input gets a row of square cells, not one huge
    // square.
    double side_goal = (std::max)((std::min)(w, h), extent / max_aspect);
    if(side_goal <= 0) // a single point, or all points equal
      side_goal = (std::max)(std::abs(xmin), std::abs(ymin)) > 0
                    ? (std::max)(std::abs(xmin), std::abs(ymin)) * 0x1p-20 : 1.0;
    int e = 0;
    std::frexp(side_goal, &e); // side_goal in [2^(e-1), 2^e)
    m_root_side = std::ldexp(1.0, e);
    for(std::size_t level = 0; level < m_sides.size(); ++level)
      m_sides[level] = std::ldexp(m_root_side, -int(level));
    // The deepest level whose lattice (and the half-cell lattice of its templates) is exact in
    // double this far from the origin, and whose cells are not so small that squared lengths
    // underflow. Deeper cells are refused with the reason, not rounded.
    const double far = (std::max)((std::max)(std::abs(xmin), std::abs(xmax)),
                                  (std::max)(std::abs(ymin), std::abs(ymax)))
                       + max_aspect * 2 * m_root_side;
    int exact_depth = 50 - int(std::ceil(std::log2(far / m_root_side)));
    while(exact_depth >= 0 && std::ldexp(m_root_side, -(exact_depth + 1)) < min_cell_side)
      --exact_depth;
    if(exact_depth < 0) {
      std::ostringstream msg;
      msg << "the input's extent " << extent << (extent < 1e-100 ? " is too small to mesh"
                                                                 : " is too small for its distance from the origin")
          << " (|x| up to " << far << "); translate or scale the input";
      throw Meshing_error(msg.str());
    }
    if(exact_depth < m_max_depth) {
      std::ostringstream msg;
      msg << "cells below " << std::ldexp(m_root_side, -exact_depth)
          << (std::ldexp(m_root_side, -(exact_depth + 1)) < min_cell_side * 2
                ? " are too small to measure in double precision"
                : " cannot be represented exactly this far from the origin")
          << " (quadtree depth " << exact_depth << ")";
      m_depth_limit = msg.str();
      m_max_depth = exact_depth;
    }
    int resolved_depth = m_max_depth;
    while(resolved_depth > 0 && std::ldexp(m_root_side, -resolved_depth) < finest_side)
      --resolved_depth;
    if(resolved_depth < m_max_depth) {
      std::ostringstream msg;
      msg << "cells below " << std::ldexp(m_root_side, -resolved_depth) << " are too small to tell "
          << "their vertices apart in an input " << extent << " across (quadtree depth "
          << resolved_depth << ")";
      m_depth_limit = msg.str();
      m_max_depth = resolved_depth;
    }
    // The origin lies on the vertex lattice of level min(max_depth, 24) + 1, which the deeper
    // lattices contain: the grid of an input that needed at most the 24 levels of earlier
    // versions does not move with the maximum depth, nor does its mesh.
    const double snap = std::ldexp(m_root_side, -((std::min)(m_max_depth, snap_depth) + 1));
    m_ox = std::floor(xmin / snap) * snap;
    m_oy = std::floor(ymin / snap) * snap;
    // Strictly inside: cells are half-open, so the upper bounds need their own cell.
    m_nx = std::uint32_t(std::floor((xmax - m_ox) / m_root_side)) + 1;
    m_ny = std::uint32_t(std::floor((ymax - m_oy) / m_root_side)) + 1;
    CGAL_assertion(m_nx <= max_aspect + 2 && m_ny <= max_aspect + 2);
    m_nodes = internal::Key_map(std::size_t(m_nx) * m_ny * 4);
    m_number_of_leaves = 0;
    m_depth = 0;
    for(std::uint32_t j = 0; j < m_ny; ++j)
      for(std::uint32_t i = 0; i < m_nx; ++i)
        add_leaf(Cell_key(0, i, j));
  }

  // The index of the lattice interval [origin + i h, origin + (i+1) h) containing x, with h
  // the cell side at `level`; exact, and clamped into the grid.
  std::uint64_t lattice_index(const FT& x, double origin, std::uint32_t root_cells, int level) const
  {
    const double h = cell_side(level);
    const std::int64_t n = std::int64_t(root_cells) << level;
    const auto xi = CGAL::to_interval(x);
    double guess = std::floor((0.5 * xi.first + 0.5 * xi.second - origin) / h);
    std::int64_t i = std::int64_t((std::min)((std::max)(guess, 0.0), double(n - 1)));
    while(i > 0 && x < FT(origin + double(i) * h))
      --i;
    while(i + 1 < n && !(x < FT(origin + double(i + 1) * h)))
      ++i;
    return std::uint64_t(i);
  }

public:
  /// Why no cell can be split at `max_depth()`: the requested depth, or the precision limit
  /// that lowered it. For error messages.
  std::string depth_limit() const
  {
    if(!m_depth_limit.empty())
      return m_depth_limit;
    return "the maximum depth " + std::to_string(m_max_depth);
  }

private:
  std::string depth_message(const Cell_key& k, const Point_2* p = nullptr) const
  {
    std::ostringstream msg;
    msg << "the sizing asks for quadtree cells deeper than " << depth_limit() << " (cells of side "
        << cell_side(m_max_depth) << ")";
    if(p != nullptr)
      msg << " near (" << CGAL::to_double(m_traits.compute_x_2_object()(*p)) << ", "
          << CGAL::to_double(m_traits.compute_y_2_object()(*p)) << ")";
    else
      msg << " near (" << lattice_x(k.level, k.i) << ", " << lattice_y(k.level, k.j) << ")";
    msg << "; raise the maximum depth or set a minimum size";
    return msg.str();
  }

  static constexpr double max_aspect = 16;
  // the most root cells in a row (setup_root) times 2^max_supported_depth cells, and twice that
  // many vertices, fit the keys
  static_assert((max_aspect + 2) * double(std::uint64_t(1) << max_supported_depth)
                  < double(std::uint64_t(1) << Cell_key::coordinate_bits)
                && (max_aspect + 2) * double(std::uint64_t(1) << (max_supported_depth + 1))
                     < double(std::uint64_t(1) << internal::lattice_key_bits)
                && max_supported_depth < Cell_key::max_level
                && (max_aspect + 2) * double(std::uint64_t(1) << morton_level)
                     < double(std::uint64_t(1) << 32),
                "keys too short for max_supported_depth");
  // cells smaller than this would have squared lengths near double's underflow
  static constexpr double min_cell_side = 1e-140;

  GeomTraits m_traits;
  int m_max_depth;
  double m_root_side = 1;
  std::array<double, 64> m_sides; // cell_side() of levels 0 to 63
  double m_ox = 0, m_oy = 0;
  std::uint32_t m_nx = 1, m_ny = 1;
  internal::Key_map m_nodes;
  std::size_t m_number_of_leaves = 0;
  int m_depth = 0;
  std::vector<Cell_list>* m_new_leaves = nullptr; // during balance()
  Cell_list m_unbalanced; // leaves made since the last balance()
  std::string m_depth_limit;          // set when precision lowered the maximum depth
  std::size_t m_max_leaves = (std::numeric_limits<std::size_t>::max)();
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_BALANCED_QUADTREE_2_H
