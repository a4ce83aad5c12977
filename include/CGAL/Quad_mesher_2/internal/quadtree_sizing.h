// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_QUADTREE_SIZING_H
#define CGAL_QUAD_MESHER_2_INTERNAL_QUADTREE_SIZING_H

#include <CGAL/Quad_mesher_2/Balanced_quadtree_2.h>
#include <CGAL/Quad_mesher_2/Cell_key.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone_clearance.h>
#include <CGAL/Quad_mesher_2/internal/narrow_regions.h>
#include <CGAL/Quad_mesher_2/internal/nearest_neighbor_distances.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <new>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

// Paper §4.2: the sizes the quadtree is refined to, before it is balanced. Every bound asks
// for a level at a place; a level beyond the tree's depth is an error naming the place, not a
// silently coarser mesh.

// the level whose cells have side <= s
template <class Quadtree>
int level_for_size(const Quadtree& tree, double s)
{
  return (std::max)(0, int(std::ceil(std::log2(tree.root_side() / s))));
}

// the deepest level whose cells are not below the criteria's minimum size
template <class Quadtree, class Criteria>
int min_size_level(const Quadtree& tree, const Criteria& criteria)
{
  if(criteria.min_size() <= 0)
    return tree.max_depth();
  int l = int(std::floor(std::log2(tree.root_side() / criteria.min_size())));
  return (std::min)((std::max)(l, 0), tree.max_depth());
}

// How much a closed polyline turns near a point of it: the arc length at each vertex and
// the running sum of the absolute turns (degrees) at the vertices, for sums over a stretch.
class Loop_turning
{
public:
  explicit Loop_turning(const std::vector<Point_2d>& loop) : m_arc(loop.size() + 1, 0.0), m_turn(loop.size() + 1, 0.0)
  {
    const std::size_t n = loop.size();
    for(std::size_t k = 0; k < n; ++k) {
      const Point_2d &a = loop[k], &b = loop[(k + 1) % n], &c = loop[(k + 2) % n];
      m_arc[k + 1] = m_arc[k] + length_2d(b - a);
      m_turn[k + 1] = m_turn[k] + turn_degrees(a, b, c); // at vertex k + 1
    }
  }

  /// the arc length from vertex 0 to vertex k
  double arc(std::size_t k) const { return m_arc[k]; }

  /// the turns at the vertices within arc length r of the point at arc length s
  double within(double s, double r) const
  {
    const double length = m_arc.back();
    if(2 * r >= length) return m_turn.back();
    double lo = s - r, hi = s + r, sum = 0;
    if(lo < 0) { sum += between(lo + length, length); lo = 0; }
    if(hi > length) { sum += between(0, hi - length); hi = length; }
    return sum + between(lo, hi);
  }

private:
  // the turns at the vertices k >= 1 with arc(k) in [lo, hi] (vertex n is vertex 0)
  double between(double lo, double hi) const
  {
    const std::size_t first = std::size_t(std::lower_bound(m_arc.begin() + 1, m_arc.end(), lo) - m_arc.begin());
    const std::size_t end = std::size_t(std::upper_bound(m_arc.begin() + 1, m_arc.end(), hi) - m_arc.begin());
    return end > first ? m_turn[end - 1] - m_turn[first - 1] : 0.0;
  }

  std::vector<double> m_arc, m_turn;
};

// A point where a round of the buffer stages asked for finer cells, and the local size there.
typedef std::pair<Point_2d, double> Refinement_request;

// The requests of every round so far. Each round builds its quadtree anew and refines it at
// all of them, a round's requests after those of the rounds before: one level finer than it
// is there, at least, and cells of half the local size. "There" is the tree before the
// requests of that round: two poor quads sharing a core vertex, or two requests in one leaf,
// ask for one level more together, not one level each.
class Refinement_queue
{
public:
  void clear()
  {
    m_requests.clear();
    m_round_begin.clear();
    m_applied = 0;
  }

  // Queues the requests of one round, but not those that ask for cells below the quadtree's
  // depth; returns how many it queued.
  template <class Quadtree>
  std::size_t add(const Quadtree& tree, const std::vector<Refinement_request>& requests)
  {
    const std::size_t begin = m_requests.size();
    for(const auto& r : requests) {
      const double size = r.second > 0 ? r.second / 2 : 0;
      if(size > 0 && level_for_size(tree, size) > tree.max_depth()) continue;
      m_requests.push_back(r);
    }
    if(m_requests.size() > begin) m_round_begin.push_back(begin);
    return m_requests.size() - begin;
  }

  // Refines `tree` at every request, round by round; true if those queued since the last call
  // split a cell. Every leaf touching the point is refined, not only the one `locate` picks:
  // most requests are at core vertices, lattice points with four cells around them, and the
  // poor buffer quads may lie in any of them.
  template <class Quadtree>
  bool refine(Quadtree& tree)
  {
    std::size_t leaves_before_new = 0;
    for(std::size_t k = 0; k < m_round_begin.size(); ++k) {
      const std::size_t begin = m_round_begin[k];
      const std::size_t end = k + 1 < m_round_begin.size() ? m_round_begin[k + 1] : m_requests.size();
      if(begin == m_applied)
        leaves_before_new = tree.number_of_leaves();
      refine_round(tree, begin, end);
    }
    const bool refined = m_applied < m_requests.size() && tree.number_of_leaves() > leaves_before_new;
    m_applied = m_requests.size();
    return refined;
  }

private:
  // the requests begin .. end - 1 of one round: every level is read before any cell is split
  template <class Quadtree>
  void refine_round(Quadtree& tree, std::size_t begin, std::size_t end) const
  {
    std::vector<Points_around<typename Quadtree::Point_2>> around;
    std::vector<int> level;
    around.reserve(end - begin);
    level.reserve(end - begin);
    for(std::size_t i = begin; i < end; ++i) {
      around.push_back(points_around(tree, m_requests[i].first));
      const double size = m_requests[i].second;
      int l = size > 0 ? level_for_size(tree, size / 2) : 0;
      for(std::size_t k = 0; k < around.back().n; ++k) l = (std::max)(l, tree.locate(around.back().p[k]).level + 1);
      level.push_back(l);
    }
    for(std::size_t r = 0; r < around.size(); ++r) {
      if(level[r] > tree.max_depth()) continue;
      for(std::size_t k = 0; k < around[r].n; ++k) tree.refine_at(around[r].p[k], level[r]);
    }
  }

  // the points of the tree half a finest cell diagonally off a request's point, one in each
  // leaf touching it (`n` of them)
  template <class Point_2>
  struct Points_around
  {
    std::array<Point_2, 4> p;
    std::size_t n = 0;
  };

  template <class Quadtree>
  static Points_around<typename Quadtree::Point_2> points_around(const Quadtree& tree, const Point_2d& p)
  {
    auto make_point = tree.geom_traits().construct_point_2_object();
    const double delta = tree.cell_side(tree.max_depth()) / 2;
    Points_around<typename Quadtree::Point_2> around;
    for(int c = 0; c < 4; ++c) {
      const auto q = make_point(p.x() + ((c & 1) ? delta : -delta), p.y() + ((c & 2) ? delta : -delta));
      if(tree.contains(q)) around.p[around.n++] = q;
    }
    return around;
  }

  std::vector<Refinement_request> m_requests;
  std::vector<std::size_t> m_round_begin; // the first of m_requests that each round queued
  std::size_t m_applied = 0; // of m_requests, by the last refine()
};

// The sizing of one quadtree by the criteria and the input: each refine_to_...() applies one
// bound of §4.2. `points` are the input points without duplicates; `box` their bounding box.
template <class GeomTraits>
class Quadtree_sizing
{
public:
  typedef Balanced_quadtree_2<GeomTraits> Quadtree;
  typedef typename GeomTraits::Point_2 Point_2;
  // how messages name points[i]
  typedef std::function<std::string(std::size_t)> Point_name;

  Quadtree_sizing(Quadtree& tree, const Domain_2<GeomTraits>& domain, const Domain_loops_2<GeomTraits>& loops,
                  const Mesh_criteria_2<GeomTraits>& criteria, const std::vector<Point_2>& points,
                  const Bbox_2& box, Point_name name, const GeomTraits& traits)
    : m_tree(tree), m_domain(domain), m_loops(loops), m_criteria(criteria), m_points(points), m_box(box),
      m_name(std::move(name)), m_traits(traits)
  {
    compute_point_spacing();
  }

  // The level whose cells have side <= spacing/divisor at point i; an error if that is beyond
  // the maximum depth and no minimum size caps it.
  int point_level(std::size_t i, double divisor) const
  {
    if(!std::isfinite(m_spacing[i]))
      return 0; // a single point
    int level = level_for_size(m_tree, m_spacing[i] / divisor);
    if(level <= min_size_level(m_tree, m_criteria))
      return level;
    if(m_criteria.min_size() > 0 && !m_criteria.points_as_vertices())
      return min_size_level(m_tree, m_criteria);
    std::ostringstream msg;
    msg.precision(17);
    msg << "input points " << m_name(i) << " (" << m_xy[i][0] << ", " << m_xy[i][1]
        << ") and " << m_name(m_nearest[i]) << " (" << m_xy[m_nearest[i]][0] << ", "
        << m_xy[m_nearest[i]][1] << ") are " << m_spacing[i] << " apart: separating them needs quadtree depth " << level
        << ", beyond " << m_tree.depth_limit();
    if(m_criteria.min_size() > 0)
      msg << " or the minimum size " << m_criteria.min_size();
    throw Meshing_error(msg.str());
  }

  // No cell meeting the domain's box larger than the maximum size. The cells it asks for are
  // counted before any is made: a budget error now, not after minutes and gigabytes.
  void refine_to_max_size()
  {
    if(m_criteria.max_size() <= 0)
      return;
    const int level = level_for_size(m_tree, m_criteria.max_size());
    if(level > m_tree.max_depth()) {
      std::ostringstream msg;
      msg << "the maximum size " << m_criteria.max_size() << " needs quadtree depth " << level
          << ", beyond " << m_tree.depth_limit();
      throw Meshing_error(msg.str());
    }
    const double side = m_tree.cell_side(level);
    auto cells_across = [&](double lo, double hi, double origin, std::uint64_t all) {
      if(m_domain.is_point_cloud())
        return double(all);
      return std::floor((hi - origin) / side) - std::floor((lo - origin) / side) + 1;
    };
    const double cells = cells_across(m_box.xmin(), m_box.xmax(), m_tree.lattice_x(0, 0), m_tree.cells_x(level))
                         * cells_across(m_box.ymin(), m_box.ymax(), m_tree.lattice_y(0, 0), m_tree.cells_y(level));
    if(cells > double(m_criteria.max_cells())) {
      std::ostringstream msg;
      msg << "the maximum size " << m_criteria.max_size() << " needs about " << cells
          << " quadtree cells over the domain, more than the cell budget of " << m_criteria.max_cells()
          << "; coarsen it or raise the cell budget";
      throw Meshing_error(msg.str());
    }
    if(m_domain.is_point_cloud()) {
      reserve_cells(cells, level);
      m_tree.refine([&](const Cell_key& k) { return k.level < level; });
      return;
    }
    split_inside_domain(level, side);
  }

  // Makes room at once for `cells` cells of `level`, which refining to the maximum size makes
  // at the least. Memory that cannot hold them would run out later anyway, after minutes:
  // within the cell budget, it is the budget that is too large for this machine.
  void reserve_cells(double cells, int level)
  {
    try {
      m_tree.reserve(cells < double(m_criteria.max_cells()) ? std::size_t(cells) : m_criteria.max_cells());
    } catch(const std::bad_alloc&) {
      std::ostringstream msg;
      msg << "the maximum size " << m_criteria.max_size() << " needs at least " << cells << " quadtree cells of side "
          << m_tree.cell_side(level) << ", more than memory holds, though within the cell budget of "
          << m_criteria.max_cells() << "; coarsen it or lower the cell budget to what memory holds";
      throw Meshing_error(msg.str());
    }
  }

  // Paper §4.2: the cell holding input point i is no larger than s_i = min_j d_ij; at a
  // domain's loop vertex that is no feature (is_loop_feature()), no larger than
  // `domain_spacing_factor` times that. The buffer layers place the boundary's nodes by
  // projection and the chord tolerance may leave such a vertex out: it needs no cell of its
  // own. A feature, which the mesh keeps, does (in a coarser cell a projection came to lie
  // next to it: slivers of aspect ratio 1200 along a saw-toothed side), and so do a point
  // cloud's points and a domain's isolated points: Lemma 1 puts each alone in its cell.
  void refine_to_point_spacing()
  {
    const std::vector<Point_2d> own = points_in_own_cells();
    for(std::size_t i = 0; i < m_points.size(); ++i) {
      const bool own_cell = m_domain.is_point_cloud()
                            || std::binary_search(own.begin(), own.end(), Point_2d(m_xy[i][0], m_xy[i][1]));
      const int level = point_level(i, own_cell ? 1.0 : 1.0 / domain_spacing_factor);
      if(level > 0)
        m_tree.refine_at(m_points[i], level);
    }
  }
  // one quadtree level coarser than s_i: half the cells along smooth stretches of boundary
  static constexpr double domain_spacing_factor = 2;

  // No cell larger than the user's sizing field at its centre or a corner.
  void refine_to_sizing_field()
  {
    const auto& field = m_criteria.sizing_field();
    const int cap = min_size_level(m_tree, m_criteria);
    const bool capped = m_criteria.min_size() > 0;
    m_tree.refine([&](const Cell_key& k) {
      if(outside_domain_box(k))
        return false;
      double side = m_tree.cell_side(k.level);
      double target = CGAL::to_double(field(m_tree.cell_center(k)));
      for(int c = 0; c < 4; ++c)
        target = (std::min)(target, CGAL::to_double(field(m_tree.lattice_point(
                                        k.level, k.i + (c & 1), k.j + (c >> 1)))));
      if(!(target > 0))
        throw Meshing_error("the sizing field is not positive near ("
                            + std::to_string(m_tree.lattice_x(k.level, k.i)) + ", "
                            + std::to_string(m_tree.lattice_y(k.level, k.j)) + ")");
      if(side <= target)
        return false;
      return !capped || k.level < cap;
    });
  }

  // Triangle's maximum areas (`Domain_2::Region_attribute::max_area`): no cell meeting a
  // region larger than the square root of the region's, so its core quads keep within it.
  // A cell meets the region if its centre or a corner lies in it, or a segment of the
  // region's loops may cross it (by boxes).
  void refine_to_region_areas()
  {
    const std::size_t none = std::size_t(-1);
    std::vector<double> bound(m_loops.region_attributes.size(), HUGE_VAL);
    double smallest = HUGE_VAL;
    std::size_t smallest_attribute = none;
    for(std::size_t r = 0; r < bound.size(); ++r) {
      const std::size_t a = m_loops.region_attributes[r];
      if(a == none || !(m_domain.region_attributes[a].max_area > 0)) continue;
      bound[r] = std::sqrt(m_domain.region_attributes[a].max_area);
      if(bound[r] < smallest) { smallest = bound[r]; smallest_attribute = a; }
    }
    if(smallest_attribute == none)
      return;
    // as the sizing field: the minimum size caps it, else it must fit in the depth
    const int level = level_for_size(m_tree, smallest), cap = min_size_level(m_tree, m_criteria);
    if(level > cap && !(m_criteria.min_size() > 0)) {
      const auto& a = m_domain.region_attributes[smallest_attribute];
      std::ostringstream msg;
      msg << "the maximum area " << loops_format_double(a.max_area) << " of regional attribute "
          << m_domain.region_attribute_label(smallest_attribute) << " " << loops_format_point(a.point, m_traits)
          << " needs quadtree depth " << level
          << ", beyond " << m_tree.depth_limit();
      throw Meshing_error(msg.str());
    }
    check_region_area_budget(bound, cap);
    const Domain_segments<GeomTraits> boundary(m_domain, m_loops, m_traits);
    auto bound_at = [&](const Point_2& p) {
      const std::size_t r = boundary.region_at(p);
      return r == boundary.outside ? HUGE_VAL : bound[r];
    };
    m_tree.refine([&](const Cell_key& k) {
      const double side = m_tree.cell_side(k.level);
      if(side <= smallest || k.level >= cap || outside_domain_box(k))
        return false;
      bool split = side > bound_at(m_tree.cell_center(k));
      for(int c = 0; c < 4 && !split; ++c)
        split = side > bound_at(m_tree.lattice_point(k.level, k.i + (c & 1), k.j + (c >> 1)));
      if(!split)
        boundary.query(m_tree.cell_rectangle(k).bbox(), [&](std::size_t s) {
          const std::size_t twin = boundary.twin_loop_of(s);
          split = split || side > bound[m_loops.loops[boundary.loop_of(s)].region]
                  || (twin != boundary.outside && side > bound[m_loops.loops[twin].region]);
        });
      return split;
    });
  }

  // The cells the maximum areas ask for at the least (each region's area over its cells',
  // no deeper than `cap`, the minimum size's level), counted before any is made: a budget
  // error now, not after seconds and gigabytes.
  void check_region_area_budget(const std::vector<double>& bound, int cap) const
  {
    double cells = 0;
    for(std::size_t r = 0; r < bound.size(); ++r)
      if(bound[r] < HUGE_VAL) {
        const double side = m_tree.cell_side((std::min)(level_for_size(m_tree, bound[r]), cap));
        cells += CGAL::to_double(region_area(m_domain, m_loops, r, m_traits)) / (side * side);
      }
    if(cells <= double(m_criteria.max_cells()))
      return;
    std::ostringstream msg;
    msg << "the regional attributes' maximum areas need about " << cells
        << " quadtree cells, more than the cell budget of " << m_criteria.max_cells()
        << "; raise the areas or the cell budget";
    throw Meshing_error(msg.str());
  }

  // Paper §4.2: more than two cells across every narrow region (narrow_regions.h).
  void refine_narrow_regions()
  {
    auto make_point = m_traits.construct_point_2_object();
    for(const Size_sample& s : narrow_region_samples(m_domain, m_loops, m_tree.cell_side(m_tree.max_depth()), m_criteria.max_cells(), m_traits)) {
      const int level = level_for_size(m_tree, s.size);
      if(level > m_tree.max_depth()) {
        std::ostringstream msg;
        msg << "a narrow region of width " << 4 * s.size << " near (" << s.point.x() << ", "
            << s.point.y() << ") needs quadtree depth " << level << ", beyond "
            << m_tree.depth_limit();
        throw Meshing_error(msg.str());
      }
      const Point_2 p = make_point(s.point.x(), s.point.y());
      if(level > 0 && m_tree.contains(p))
        m_tree.refine_at(p, level);
    }
  }

  // Cells near the boundary are made as small as the leaf at the nearest boundary point, so
  // the clearance leaves a core boundary of one cell size: the uniform grid of §4.4 (boundary
  // angles 90°, 180° and 270° only) and a buffer zone of even width. The levels are read
  // before any band is refined, so fine cells do not spread along the whole boundary, one
  // band after another.
  void refine_boundary_band()
  {
    auto make_point = m_traits.construct_point_2_object();
    struct Band { Point_2d centre; int level, cells; };
    std::vector<Band> bands;
    for(std::size_t l = 0; l < m_loops.loops.size(); ++l) {
      const auto& loop = m_loops.loops[l];
      std::vector<Point_2d> xy;
      for(std::size_t v : loop.vertices) xy.push_back(to_point_2d(m_domain.points[v]));
      const Loop_turning turning(xy);
      for(std::size_t k = 0; k < xy.size(); ++k) {
        if(is_second_side(m_loops, l, k)) continue; // a segment once
        const Vector_2d d = xy[(k + 1) % xy.size()] - xy[k];
        const double length = length_2d(d);
        for(double t = 0; t < 1;) {
          const Point_2d q = xy[k] + t * d;
          const int level = m_tree.locate(make_point(q.x(), q.y())).level;
          const double h = m_tree.cell_side(level);
          bands.push_back({ q, level, band_cells(turning, turning.arc(k) + t * length, h) });
          t += h / (2 * length);
        }
      }
    }
    for(const Band& band : bands) {
      const double h = m_tree.cell_side(band.level);
      for(int i = -band.cells; i <= band.cells; ++i)
        for(int j = -band.cells; j <= band.cells; ++j) {
          const Point_2 p = make_point(band.centre.x() + i * h, band.centre.y() + j * h);
          if(m_tree.contains(p) && !m_tree.is_node(m_tree.cell_containing(p, band.level)))
            m_tree.refine_at(p, band.level);
        }
    }
  }

  // How many cells of side h the band reaches from the boundary point at arc length s of a
  // loop: along a straight stretch `straight_band` suffice (balance grades the rest; each
  // band cell more costs a row of quads along the whole boundary); where the loop turns by
  // more than `band_turn_limit` degrees within `turning_band` cells, the wedge beside the
  // turn needs its cells that far too.
  static int band_cells(const Loop_turning& turning, double s, double h)
  {
    return turning.within(s, turning_band * h) > band_turn_limit ? turning_band : straight_band;
  }
  static constexpr int straight_band = 1, turning_band = 3;
  static constexpr double band_turn_limit = 50;

private:
  // a domain's features and isolated points, sorted (as m_xy holds them)
  std::vector<Point_2d> points_in_own_cells() const
  {
    std::vector<Point_2d> own;
    for(const auto& loop : m_loops.loops) {
      const std::size_t n = loop.vertices.size();
      for(std::size_t k = 0; k < n; ++k) {
        const Point_2d p = to_point_2d(m_domain.points[loop.vertices[k]]);
        if(on_edge_twin(loop, k) // an interface keeps every vertex
           || is_loop_feature(to_point_2d(m_domain.points[loop.vertices[(k + n - 1) % n]]), p,
                              to_point_2d(m_domain.points[loop.vertices[(k + 1) % n]])))
          own.push_back(p);
      }
    }
    for(std::size_t v : m_loops.isolated_points) own.push_back(to_point_2d(m_domain.points[v]));
    std::sort(own.begin(), own.end());
    return own;
  }

  void compute_point_spacing()
  {
    const std::size_t n = m_points.size();
    m_xy.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_xy[i] = { CGAL::to_double(m_traits.compute_x_2_object()(m_points[i])),
                  CGAL::to_double(m_traits.compute_y_2_object()(m_points[i])) };
    Nearest_neighbor_distances nn(m_xy);
    m_spacing = std::move(nn.distance);
    m_nearest = std::move(nn.neighbor);
  }

  // Splits the cells meeting the domain down to `level` (of cell side `side`). A cell wholly
  // outside the domain is cleared anyway: it stays as it is (balance grades it), which saves
  // the quarter of the cells that a disc's box holds outside the disc. A cell that no segment
  // meets lies on one side, which its parent's tells, or its centre.
  void split_inside_domain(int level, double side)
  {
    enum Side : unsigned char { UNKNOWN, INSIDE, OUTSIDE };
    // Room for the cells of that size the domain's area holds: fewer than it gets (the
    // boundary's cells come on top), so never a larger node map than growing would make.
    reserve_cells(std::floor(CGAL::to_double(domain_area(m_domain, m_loops, m_traits)) / (side * side)), level);
    const Domain_segments<GeomTraits> boundary(m_domain, m_loops, m_traits);
    auto meets_boundary = [&](const Cell_key& k) { // by boxes: it may say yes too often
      bool any = false;
      boundary.query(m_tree.cell_rectangle(k).bbox(), [&](std::size_t) { any = true; });
      return any;
    };
    std::vector<std::pair<Cell_key, Side>> stack;
    for(const Cell_key& k : m_tree.leaves()) stack.emplace_back(k, UNKNOWN);
    while(!stack.empty()) {
      auto [k, side_of_k] = stack.back();
      stack.pop_back();
      if(k.level >= level || !m_tree.is_leaf(k) || outside_domain_box(k))
        continue;
      if(side_of_k == UNKNOWN && !meets_boundary(k))
        side_of_k = boundary.in_domain(m_tree.cell_center(k)) ? INSIDE : OUTSIDE;
      if(side_of_k == OUTSIDE)
        continue;
      m_tree.split(k);
      for(int dy = 0; dy < 2; ++dy)
        for(int dx = 0; dx < 2; ++dx) stack.emplace_back(k.child(dx, dy), side_of_k);
    }
  }

  // A domain's mesh lies within the bounding box of its points: cells wholly outside it are
  // cleared anyway, so the size bounds are not applied there (the power-of-two root square
  // can be four times the box's area; balance still grades them). A point cloud's mesh is the
  // whole root square.
  bool outside_domain_box(const Cell_key& k) const
  {
    if(m_domain.is_point_cloud())
      return false;
    const std::int64_t i = std::int64_t(k.i), j = std::int64_t(k.j);
    return m_tree.lattice_x(k.level, i + 1) < m_box.xmin() || m_tree.lattice_x(k.level, i) > m_box.xmax()
           || m_tree.lattice_y(k.level, j + 1) < m_box.ymin() || m_tree.lattice_y(k.level, j) > m_box.ymax();
  }

  Quadtree& m_tree;
  const Domain_2<GeomTraits>& m_domain;
  const Domain_loops_2<GeomTraits>& m_loops;
  const Mesh_criteria_2<GeomTraits>& m_criteria;
  const std::vector<Point_2>& m_points;
  Bbox_2 m_box;
  Point_name m_name;
  const GeomTraits& m_traits;
  std::vector<std::array<double, 2>> m_xy; // the points' coordinates, for sizing only
  std::vector<double> m_spacing;           // s_i = min_j d_ij
  std::vector<std::size_t> m_nearest;      // the j of s_i
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_QUADTREE_SIZING_H
