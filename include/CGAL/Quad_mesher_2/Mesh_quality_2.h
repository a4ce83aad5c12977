// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_MESH_QUALITY_2_H
#define CGAL_QUAD_MESHER_2_MESH_QUALITY_2_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/Box_tree.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// Shape and validity statistics of a `Quad_mesh_2`, as returned by `compute_quality()`.
///
/// All measures are computed in `double` (coordinates through `CGAL::to_double`). Angles are
/// in degrees. Quads are expected counter-clockwise; the interior angle at a corner is the
/// angle swept counter-clockwise from the next edge to the previous edge, so reflex corners
/// (and every corner of a clockwise quad) measure more than 180 degrees.
/// A quad with an index out of range of `points` is counted as degenerate and otherwise
/// ignored. On an empty mesh every statistic is 0.
struct Mesh_quality_2
{
  /// Number of quads of the mesh.
  std::size_t number_of_quads = 0;
  /// Number of entries of `points` (used or not).
  std::size_t number_of_vertices = 0;

  /// Smallest interior corner angle (degrees). Angle statistics range over the corners
  /// whose two incident edges have non-zero length.
  double min_angle = 0;
  /// Largest interior corner angle (degrees); more than 180 for a reflex or inverted corner.
  double max_angle = 0;
  /// Mean interior corner angle (degrees); 90 for a mesh of simple counter-clockwise quads.
  double mean_angle = 0;
  /// Corner-angle histogram: bin `i` counts the angles in [5i, 5i+5) degrees. A slack of
  /// 1e-7 degrees is added before binning, so that an angle computed as 89.99999999999999
  /// lands in the bin of 90.
  std::array<std::size_t, 72> angle_histogram{};
  /// Fraction of the corner angles in [45, 135] degrees (with 1e-7 degree slack).
  double share_in_45_135 = 0;
  /// Fraction of the corner angles in [60, 120] degrees (with 1e-7 degree slack).
  double share_in_60_120 = 0;

  /// Smallest aspect ratio (longest over shortest edge of a quad), over the quads with no
  /// zero-length edge.
  double min_aspect_ratio = 0;
  /// Largest aspect ratio, over the quads with no zero-length edge.
  double max_aspect_ratio = 0;
  /// Mean aspect ratio, over the quads with no zero-length edge.
  double mean_aspect_ratio = 0;
  /// The aspect ratios below which lie 50%, 95% and 99% of those quads (nearest rank).
  std::array<double, 3> aspect_ratio_percentiles{};
  /// The shortest edge of a quad over the diagonal of the used vertices' bounding box (0 if
  /// an edge has zero length).
  double min_edge_over_diagonal = 0;

  /// Smallest scaled Jacobian of a quad. The scaled Jacobian of a corner is
  /// cross(e_next, e_prev) / (|e_next| |e_prev|) (the sine of its angle, 0 if an edge has zero
  /// length); that of a quad is the minimum over its corners: 1 for a rectangle, negative
  /// for an inverted or non-convex quad.
  double min_scaled_jacobian = 0;
  /// Mean (over quads) of the per-quad scaled Jacobian.
  double mean_scaled_jacobian = 0;

  /// Quads with some corner of negative signed area with respect to counter-clockwise
  /// orientation (scaled Jacobian < -1e-12): flipped (clockwise), bow-tie and non-convex quads.
  std::size_t number_of_inverted_quads = 0;
  /// Quads with a repeated or out-of-range vertex index, a zero-length edge, or a corner
  /// with |sine| <= 1e-12 (collinear consecutive edges).
  std::size_t number_of_degenerate_quads = 0;
  /// Undirected edges used by more than two quads, or by two quads in the same direction
  /// (an orientation conflict).
  std::size_t number_of_non_manifold_edges = 0;
  /// Used vertices that lie in the interior of an edge of a quad they do not belong to
  /// (T-junctions), within 1e-9 times the bounding-box diagonal of the used vertices. Only
  /// edges used by exactly one quad are tested: a T-junction always leaves its long edge
  /// (and the two short edges) used once.
  std::size_t number_of_hanging_nodes = 0;
  /// Vertices whose coordinates equal (in double) those of a vertex of smaller index.
  std::size_t number_of_duplicate_vertices = 0;
  /// Pairs of used vertices closer than 1e-9 times the bounding-box diagonal of the used
  /// vertices in both coordinates, exact duplicates included: a reader merging at that
  /// tolerance sees a degenerate quad. Not part of `is_valid()`: a point cloud's input points
  /// may be that close and must stay apart.
  std::size_t number_of_near_duplicate_vertices = 0;
  /// Entries of `points` referenced by no quad.
  std::size_t number_of_unused_vertices = 0;
  /// Number of closed boundary loops: the edges used by exactly one quad, chained head to
  /// tail (at a vertex where several loops meet, the loops are separated by turning around
  /// the vertex through the quads). An open chain, possible only in an invalid mesh,
  /// counts as one loop.
  std::size_t number_of_boundary_loops = 0;

  /// `true` if the mesh has no inverted, degenerate or duplicate-vertex element, no
  /// non-manifold edge and no hanging node. Unused vertices are allowed.
  bool is_valid() const
  {
    return number_of_inverted_quads == 0 && number_of_degenerate_quads == 0 &&
           number_of_non_manifold_edges == 0 && number_of_hanging_nodes == 0 &&
           number_of_duplicate_vertices == 0;
  }
};

namespace internal {

/// The undirected edges of a quad soup, bucketed by their smaller endpoint (a CSR layout
/// filled by counting sort, then each short bucket sorted by the larger endpoint).
/// Halfedge `h` is edge (quads[h/4][h%4], quads[h/4][(h%4+1)%4]). An entry is a code,
/// 2 * halfedge + (1 if the quad walks it from smaller to larger index); its larger endpoint
/// is read from the quads, not stored: a million quads' table is 32 MB less fresh memory,
/// left uninitialised until filled.
class Quality_edge_table
{
public:
  Quality_edge_table(const std::vector<std::array<std::size_t, 4>>& quads,
                     const std::vector<char>& skip_quad,
                     std::size_t number_of_points)
    : m_quads(quads), m_offsets(number_of_points + 1, 0)
  {
    for(std::size_t q = 0; q < quads.size(); ++q) {
      if(skip_quad[q])
        continue;
      for(int k = 0; k < 4; ++k) {
        const std::size_t a = quads[q][k], b = quads[q][(k + 1) % 4];
        if(a != b)
          ++m_offsets[(std::min)(a, b) + 1];
      }
    }
    for(std::size_t i = 0; i < number_of_points; ++i)
      m_offsets[i + 1] += m_offsets[i];
    m_codes.reset(new std::size_t[m_offsets[number_of_points]]);
    std::vector<std::size_t> fill(m_offsets.begin(), m_offsets.end() - 1);
    for(std::size_t q = 0; q < quads.size(); ++q) {
      if(skip_quad[q])
        continue;
      for(std::size_t k = 0; k < 4; ++k) {
        const std::size_t a = quads[q][k], b = quads[q][(k + 1) % 4];
        if(a == b)
          continue;
        m_codes[fill[(std::min)(a, b)]++] = 2 * (4 * q + k) + (a < b ? 1 : 0);
      }
    }
    for(std::size_t i = 0; i < number_of_points; ++i) {
      std::size_t* first = m_codes.get() + m_offsets[i];
      std::size_t* last = m_codes.get() + m_offsets[i + 1];
      if(last - first > 1)
        std::sort(first, last, [&](std::size_t x, std::size_t y) {
          const std::size_t lx = larger_endpoint(x), ly = larger_endpoint(y);
          return lx < ly || (lx == ly && x < y);
        });
    }
  }

  std::size_t number_of_points() const { return m_offsets.size() - 1; }
  std::size_t bucket_begin(std::size_t v) const { return m_offsets[v]; }
  std::size_t bucket_end(std::size_t v) const { return m_offsets[v + 1]; }
  /// the code of entry `i`
  std::size_t code(std::size_t i) const { return m_codes[i]; }
  /// the larger endpoint of entry `i`
  std::size_t other(std::size_t i) const { return larger_endpoint(m_codes[i]); }

  std::size_t source(std::size_t h) const { return m_quads[h / 4][h % 4]; }
  std::size_t target(std::size_t h) const { return m_quads[h / 4][(h % 4 + 1) % 4]; }

private:
  std::size_t larger_endpoint(std::size_t code) const { return (std::max)(source(code / 2), target(code / 2)); }

  const std::vector<std::array<std::size_t, 4>>& m_quads;
  std::vector<std::size_t> m_offsets;
  std::unique_ptr<std::size_t[]> m_codes;
};

/// Counts the pairs of used vertices within `tol` of each other in x and in y. The points are
/// sorted by columns `tol` wide, then by y: a pair lies in one column or in two neighbouring
/// ones (a quadtree's vertices share their x by the thousand, so a sweep along x alone would
/// compare each with its whole column). With `exact`, also counts into it the used vertices
/// equal to another (each group of equal ones counts its size less one): the sort puts them
/// side by side. With `where`, appends one point of each pair to it.
inline std::size_t count_near_duplicate_pairs(const std::vector<Point_2d>& pts, const std::vector<char>& used,
                                              const Point_2d& lo, double tol, std::size_t* exact = nullptr,
                                              std::vector<Point_2d>* where = nullptr)
{
  struct Entry
  {
    std::int64_t column;
    double x, y;
    bool operator<(const Entry& o) const
    {
      return column < o.column || (column == o.column && (y < o.y || (y == o.y && x < o.x)));
    }
  };
  std::vector<Entry> sorted;
  sorted.reserve(pts.size()); // all are used in a mesher's output: no copies on growth
  for(std::size_t v = 0; v < pts.size(); ++v)
    if(used[v])
      sorted.push_back(Entry{ tol > 0 ? std::int64_t(std::floor((pts[v].x() - lo.x()) / tol)) : 0, pts[v].x(), pts[v].y() });
  std::sort(sorted.begin(), sorted.end());
  if(exact != nullptr)
    for(std::size_t i = 1; i < sorted.size(); ++i)
      *exact += sorted[i].x == sorted[i - 1].x && sorted[i].y == sorted[i - 1].y ? 1 : 0;
  auto near = [&](const Entry& a, const Entry& b) {
    const bool is_near = std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol;
    if(is_near && where != nullptr) where->push_back(Point_2d(a.x, a.y));
    return is_near;
  };
  std::size_t count = 0;
  for(std::size_t first = 0; first < sorted.size();) { // one column [first, last) at a time
    std::size_t last = first;
    while(last < sorted.size() && sorted[last].column == sorted[first].column) ++last;
    // the entries of the next two columns (two: the division may round across one), seldom any
    const auto near_begin = sorted.begin() + std::ptrdiff_t(last);
    auto near_end = near_begin;
    while(near_end != sorted.end() && near_end->column <= sorted[first].column + 2) ++near_end;
    for(std::size_t i = first; i < last; ++i) {
      const Entry& p = sorted[i];
      for(std::size_t j = i + 1; j < last && sorted[j].y - p.y <= tol; ++j)
        count += near(p, sorted[j]) ? 1 : 0;
      for(std::int64_t dc = 1; dc <= 2 && near_begin != near_end; ++dc)
        for(auto k = std::lower_bound(near_begin, near_end,
                                      Entry{ p.column + dc, -std::numeric_limits<double>::infinity(), p.y - tol });
            k != near_end && k->column == p.column + dc && k->y - p.y <= tol; ++k)
          count += near(p, *k) ? 1 : 0;
    }
    first = last;
  }
  return count;
}

/// Counts the used vertices lying strictly inside (farther than `tol` from both ends, within
/// `tol` of the line) one of the `edges` (halfedge ids) of a quad they do not belong to.
/// Candidates are the vertices in the edges' boxes grown by `tol`, from a box tree over those
/// (a uniform grid put every vertex of a graded mesh around a tiny island in one cell with
/// every edge there: minutes, on 600k quads). The vertices ask in blocks of consecutive
/// indices, one query per block: a mesh numbers its vertices mostly in spatial order, and the
/// edges (used once, the boundary) are few, so most blocks meet none and cost that one query.
/// With `where`, appends each such vertex's point to it.
template <class Quads>
std::size_t count_hanging_nodes(const std::vector<Point_2d>& pts,
                                const std::vector<char>& used,
                                const Quads& quads,
                                const std::vector<std::size_t>& edges,
                                double tol, std::vector<Point_2d>* where = nullptr)
{
  if(edges.empty() || !(tol > 0))
    return 0;
  auto src = [&](std::size_t e) { return quads[e / 4][e % 4]; };
  auto tgt = [&](std::size_t e) { return quads[e / 4][(e % 4 + 1) % 4]; };
  std::vector<Bbox_2> edge_boxes;
  edge_boxes.reserve(edges.size());
  for(std::size_t e : edges) {
    const Point_2d& a = pts[src(e)];
    const Point_2d& b = pts[tgt(e)];
    edge_boxes.emplace_back((std::min)(a.x(), b.x()) - tol, (std::min)(a.y(), b.y()) - tol,
                            (std::max)(a.x(), b.x()) + tol, (std::max)(a.y(), b.y()) + tol);
  }
  const Box_tree tree(edge_boxes);
  std::vector<char> hanging(pts.size(), 0);
  auto test = [&](std::size_t v, std::size_t i) {
    const std::size_t e = edges[i];
    if(hanging[v])
      return;
    const auto& q = quads[e / 4];
    if(q[0] == v || q[1] == v || q[2] == v || q[3] == v)
      return;
    const Point_2d& a = pts[src(e)];
    const Vector_2d d = pts[tgt(e)] - a;
    const Vector_2d ap = pts[v] - a;
    const double len2 = d.squared_length();
    const double cr = CGAL::determinant(d, ap);
    if(cr * cr > tol * tol * len2) // farther than tol from the line: the common case
      return;
    const double len = std::sqrt(len2);
    const double along = CGAL::scalar_product(ap, d) / len;
    if(len > 2 * tol && along > tol && along < len - tol)
      hanging[v] = 1;
  };
  auto point_box = [&](std::size_t v) { return Bbox_2(pts[v].x(), pts[v].y(), pts[v].x(), pts[v].y()); };
  constexpr std::size_t block = 64;
  std::vector<std::size_t> candidates;
  for(std::size_t v0 = 0; v0 < pts.size(); v0 += block) {
    const std::size_t v1 = (std::min)(v0 + block, pts.size());
    Bbox_2 all;
    for(std::size_t v = v0; v < v1; ++v)
      if(used[v])
        all += point_box(v);
    candidates.clear();
    tree.query(all, [&](std::size_t i) { candidates.push_back(i); });
    if(candidates.size() > block) { // a scattered block: one query per vertex
      for(std::size_t v = v0; v < v1; ++v)
        if(used[v])
          tree.query(point_box(v), [&](std::size_t i) { test(v, i); });
      continue;
    }
    for(std::size_t v = v0; v < v1; ++v)
      if(used[v])
        for(std::size_t i : candidates)
          if(CGAL::do_overlap(point_box(v), edge_boxes[i]))
            test(v, i);
  }
  const std::size_t count = std::size_t(std::count(hanging.begin(), hanging.end(), char(1)));
  if(where != nullptr && count > 0)
    for(std::size_t v = 0; v < pts.size(); ++v)
      if(hanging[v]) where->push_back(pts[v]);
  return count;
}

/// A corner's angle is a function of its edges' cross and dot products, and a quadtree's mesh
/// repeats a few such pairs (its squares and kites at each size) by the hundred thousand: a
/// small cache before atan2, keyed by the pairs' bits (so +0 and -0 differ, as atan2's results
/// do), gives the same angles at a fraction of the cost.
class Corner_angle_cache
{
public:
  /// the interior angle (degrees) at `p` between the edges to `next` and to `prev`
  double operator()(const Point_2d& prev, const Point_2d& p, const Point_2d& next)
  {
    const Vector_2d e_next = next - p;
    const Vector_2d e_prev = prev - p;
    const double cross = CGAL::determinant(e_next, e_prev), dot = CGAL::scalar_product(e_next, e_prev);
    std::uint64_t c, d;
    std::memcpy(&c, &cross, sizeof c);
    std::memcpy(&d, &dot, sizeof d);
    Entry& e = m_entries[((c ^ (d * 0x9e3779b97f4a7c15ULL)) * 0xbf58476d1ce4e5b9ULL) >> 54];
    if(e.angle < 0 || e.cross != c || e.dot != d)
      e = Entry{ c, d, angle_degrees(cross, dot) };
    return e.angle;
  }

private:
  struct Entry
  {
    std::uint64_t cross, dot;
    double angle;
  };
  std::vector<Entry> m_entries = std::vector<Entry>(1024, Entry{ 0, 0, -1 }); // angle -1: empty
};

/// The per-quad shape measures of `compute_quality()`: each quad is added in turn, marking its
/// vertices used; `finish()` writes the statistics. Quads with an index out of range are
/// counted degenerate and marked in `skip`, for the edge table.
class Quad_shape_statistics
{
public:
  Quad_shape_statistics(const std::vector<Point_2d>& pts, Mesh_quality_2& r)
    : m_pts(pts), m_r(r), m_used(pts.size(), 0)
  {}

  void add(const std::array<std::size_t, 4>& q, char& skip)
  {
    const std::size_t np = m_pts.size();
    bool out_of_range = false;
    for(int k = 0; k < 4; ++k)
      out_of_range = out_of_range || q[k] >= np;
    if(out_of_range) {
      skip = 1;
      ++m_r.number_of_degenerate_quads;
      for(int k = 0; k < 4; ++k)
        if(q[k] < np)
          m_used[q[k]] = 1;
      return;
    }
    bool degenerate = false;
    for(int k = 0; k < 4; ++k) {
      m_used[q[k]] = 1;
      for(int l = k + 1; l < 4; ++l)
        degenerate = degenerate || q[k] == q[l];
    }
    const std::array<Point_2d, 4> g = { m_pts[q[0]], m_pts[q[1]], m_pts[q[2]], m_pts[q[3]] };
    const std::array<double, 4> len = quad_edge_lengths(g);
    std::array<double, 4> ang;
    for(int k = 0; k < 4; ++k)
      ang[k] = m_angle(g[(k + 3) % 4], g[k], g[(k + 1) % 4]);
    const std::array<double, 4> sj = quad_corner_scaled_jacobians(g, len);

    bool inverted = false;
    double quad_sj = 1;
    for(int k = 0; k < 4; ++k) {
      if(sj[k] < -sin_tol)
        inverted = true;
      else if(sj[k] <= sin_tol)
        degenerate = true;
      quad_sj = (std::min)(quad_sj, sj[k]);
      // Corner k lies between edges k-1 and k.
      if(len[k] > 0 && len[(k + 3) % 4] > 0)
        add_angle(ang[k]);
    }
    degenerate = !add_aspect_ratio(len) || degenerate;
    m_min_sj = (std::min)(m_min_sj, quad_sj);
    m_sum_sj += quad_sj;
    ++m_n_sj;
    if(inverted)
      ++m_r.number_of_inverted_quads;
    if(degenerate)
      ++m_r.number_of_degenerate_quads;
  }

  void finish()
  {
    if(m_n_angles > 0) {
      m_r.min_angle = m_min_a;
      m_r.max_angle = m_max_a;
      m_r.mean_angle = m_sum_a / double(m_n_angles);
      m_r.share_in_45_135 = double(m_n_45) / double(m_n_angles);
      m_r.share_in_60_120 = double(m_n_60) / double(m_n_angles);
    }
    if(m_n_ar > 0) {
      m_r.min_aspect_ratio = m_min_ar;
      m_r.max_aspect_ratio = m_max_ar;
      m_r.mean_aspect_ratio = m_sum_ar / double(m_n_ar);
      const double shares[3] = { 0.5, 0.95, 0.99 };
      for(int k = 0; k < 3; ++k) {
        const auto rank = m_ratios.begin() + std::ptrdiff_t(std::ceil(shares[k] * double(m_ratios.size())) - 1);
        std::nth_element(m_ratios.begin(), rank, m_ratios.end());
        m_r.aspect_ratio_percentiles[k] = *rank;
      }
    }
    if(m_n_sj > 0) {
      m_r.min_scaled_jacobian = m_min_sj;
      m_r.mean_scaled_jacobian = m_sum_sj / double(m_n_sj);
    }
  }

  /// by vertex: 1 if some quad uses it
  const std::vector<char>& used() const { return m_used; }
  /// the shortest edge of a quad (0 if one has zero length)
  double shortest_edge() const { return m_shortest_edge; }

private:
  static constexpr double slack = 1e-7;
  static constexpr double sin_tol = 1e-12;

  void add_angle(double a)
  {
    m_min_a = (std::min)(m_min_a, a);
    m_max_a = (std::max)(m_max_a, a);
    m_sum_a += a;
    ++m_n_angles;
    std::size_t bin = std::size_t((std::max)(0.0, std::floor((a + slack) / 5.0)));
    ++m_r.angle_histogram[(std::min)(bin, std::size_t(71))];
    if(a >= 45 - slack && a <= 135 + slack)
      ++m_n_45;
    if(a >= 60 - slack && a <= 120 + slack)
      ++m_n_60;
  }

  // false if an edge has zero length (no aspect ratio)
  bool add_aspect_ratio(const std::array<double, 4>& len)
  {
    const double lo = (std::min)((std::min)(len[0], len[1]), (std::min)(len[2], len[3]));
    const double hi = (std::max)((std::max)(len[0], len[1]), (std::max)(len[2], len[3]));
    m_shortest_edge = (std::min)(m_shortest_edge, lo);
    if(!(lo > 0))
      return false;
    const double ar = hi / lo;
    m_ratios.push_back(ar);
    m_min_ar = (std::min)(m_min_ar, ar);
    m_max_ar = (std::max)(m_max_ar, ar);
    m_sum_ar += ar;
    ++m_n_ar;
    return true;
  }

  const std::vector<Point_2d>& m_pts;
  Mesh_quality_2& m_r;
  std::vector<char> m_used;
  Corner_angle_cache m_angle;
  double m_min_a = (std::numeric_limits<double>::max)(), m_max_a = -(std::numeric_limits<double>::max)(), m_sum_a = 0;
  std::size_t m_n_angles = 0, m_n_45 = 0, m_n_60 = 0;
  double m_min_ar = (std::numeric_limits<double>::max)(), m_max_ar = 0, m_sum_ar = 0;
  std::size_t m_n_ar = 0;
  std::vector<double> m_ratios; // every aspect ratio, for the percentiles
  double m_shortest_edge = HUGE_VAL;
  double m_min_sj = (std::numeric_limits<double>::max)(), m_sum_sj = 0;
  std::size_t m_n_sj = 0;
};

/// Counts the unused vertices into `r`; returns the bounding box of the used ones (lo, hi),
/// (0, 0) to (0, 0) if none is.
inline std::pair<Point_2d, Point_2d> count_unused_vertices(const std::vector<Point_2d>& pts,
                                                           const std::vector<char>& used, Mesh_quality_2& r)
{
  Point_2d lo = ORIGIN, hi = ORIGIN;
  bool first = true;
  for(std::size_t v = 0; v < pts.size(); ++v) {
    if(!used[v]) {
      ++r.number_of_unused_vertices;
      continue;
    }
    const Point_2d& p = pts[v];
    if(first) {
      lo = hi = p;
      first = false;
    } else {
      lo = Point_2d((std::min)(lo.x(), p.x()), (std::min)(lo.y(), p.y()));
      hi = Point_2d((std::max)(hi.x(), p.x()), (std::max)(hi.y(), p.y()));
    }
  }
  return { lo, hi };
}

/// Counts the duplicate and near-duplicate vertices into `r`. The near-duplicate sweep's sort
/// counts the duplicates among the used vertices, which are all of them in a mesher's output;
/// otherwise all are sorted by coordinates.
inline void count_duplicate_vertices(const std::vector<Point_2d>& pts, const std::vector<char>& used,
                                     const Point_2d& lo, const Point_2d& hi, Mesh_quality_2& r,
                                     std::vector<Point_2d>* where)
{
  std::size_t used_duplicates = 0;
  r.number_of_near_duplicate_vertices =
    count_near_duplicate_pairs(pts, used, lo, 1e-9 * length_2d(hi - lo), &used_duplicates, where);
  if(r.number_of_unused_vertices == 0) {
    r.number_of_duplicate_vertices = used_duplicates;
    return;
  }
  std::vector<Point_2d> sorted(pts);
  std::sort(sorted.begin(), sorted.end(), [](const Point_2d& a, const Point_2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  for(std::size_t i = 1; i < pts.size(); ++i)
    if(sorted[i].x() == sorted[i - 1].x() && sorted[i].y() == sorted[i - 1].y())
      ++r.number_of_duplicate_vertices;
}

/// Counts the non-manifold edges into `r`; returns the boundary (used-once) halfedges.
inline std::vector<std::size_t> boundary_halfedges(const Quality_edge_table& table, Mesh_quality_2& r)
{
  std::vector<std::size_t> boundary;
  for(std::size_t v = 0; v < table.number_of_points(); ++v) {
    std::size_t i = table.bucket_begin(v);
    const std::size_t end = table.bucket_end(v);
    while(i < end) {
      std::size_t j = i, forward = 0;
      const std::size_t other = table.other(i);
      while(j < end && table.other(j) == other) {
        forward += table.code(j) & 1;
        ++j;
      }
      const std::size_t uses = j - i;
      if(uses == 1) {
        const std::size_t h = table.code(i) / 2;
        boundary.push_back(h);
      } else if(uses > 2 || forward != 1) {
        ++r.number_of_non_manifold_edges;
      }
      i = j;
    }
  }
  return boundary;
}

/// The number of loops the `boundary` halfedges of `nq` quads make, chained head to tail.
inline std::size_t count_boundary_loops(const Quality_edge_table& table, const std::vector<std::size_t>& boundary,
                                        const std::vector<Point_2d>& pts, std::size_t nq)
{
  const std::size_t np = pts.size();
  std::vector<std::size_t> out_offsets(np + 1, 0);
  for(std::size_t h : boundary)
    ++out_offsets[table.source(h) + 1];
  for(std::size_t v = 0; v < np; ++v)
    out_offsets[v + 1] += out_offsets[v];
  std::vector<std::size_t> out(boundary.size());
  {
    std::vector<std::size_t> fill(out_offsets.begin(), out_offsets.end() - 1);
    for(std::size_t h : boundary)
      out[fill[table.source(h)]++] = h;
  }
  std::vector<char> visited(4 * nq, 0);
  const std::size_t npos = (std::numeric_limits<std::size_t>::max)();
  // At a vertex where several boundary loops meet, leave through the outgoing boundary
  // halfedge met first when turning counter-clockwise from the incoming one's reverse:
  // the outside lies on the right of both.
  auto turn = [&](std::size_t h) -> std::size_t {
    const std::size_t v = table.target(h);
    const Vector_2d back = pts[table.source(h)] - pts[v];
    std::size_t best = npos;
    double best_angle = 0;
    for(std::size_t i = out_offsets[v]; i < out_offsets[v + 1]; ++i) {
      const std::size_t o = out[i];
      const Vector_2d d = pts[table.target(o)] - pts[v];
      double a = std::atan2(CGAL::determinant(back, d), CGAL::scalar_product(back, d));
      if(a <= 0)
        a += 2 * 3.14159265358979323846;
      if(best == npos || a < best_angle) {
        best = o;
        best_angle = a;
      }
    }
    return best;
  };
  std::size_t loops = 0;
  for(std::size_t start : boundary) {
    if(visited[start])
      continue;
    ++loops;
    for(std::size_t h = start;;) {
      visited[h] = 1;
      const std::size_t v = table.target(h);
      const std::size_t next = out_offsets[v + 1] - out_offsets[v] == 1 ? out[out_offsets[v]] : turn(h);
      if(next == npos || visited[next])
        break;
      h = next;
    }
  }
  return loops;
}

/// `compute_quality()`, and with `where` the places of its near-duplicate vertices (one of
/// each pair) and hanging nodes, which a mesher can refine
template <class Point_2>
Mesh_quality_2 compute_quality(const Quad_mesh_2<Point_2>& mesh, std::vector<Point_2d>* where);

} // namespace internal

/// \ingroup PkgQuadMesher2Ref
/// Computes the shape and validity statistics of `mesh` (see `Mesh_quality_2`).
/// Runs in roughly linear time: about 0.35 s for 10^6 quads.
template <class Point_2>
Mesh_quality_2 compute_quality(const Quad_mesh_2<Point_2>& mesh)
{
  return internal::compute_quality(mesh, nullptr);
}

template <class Point_2>
Mesh_quality_2 internal::compute_quality(const Quad_mesh_2<Point_2>& mesh, std::vector<Point_2d>* where)
{
  Mesh_quality_2 r;
  r.number_of_quads = mesh.quads.size();
  r.number_of_vertices = mesh.points.size();
  std::vector<Point_2d> pts;
  pts.reserve(mesh.points.size());
  for(const Point_2& p : mesh.points)
    pts.push_back(to_point_2d(p));

  std::vector<char> skip(mesh.quads.size(), 0);
  Quad_shape_statistics shapes(pts, r);
  for(std::size_t q = 0; q < mesh.quads.size(); ++q)
    shapes.add(mesh.quads[q], skip[q]);
  shapes.finish();
  const std::vector<char>& used = shapes.used();

  const auto [lo, hi] = count_unused_vertices(pts, used, r);
  count_duplicate_vertices(pts, used, lo, hi, r, where);

  const Quality_edge_table table(mesh.quads, skip, pts.size());
  const std::vector<std::size_t> boundary = boundary_halfedges(table, r);
  r.number_of_boundary_loops = count_boundary_loops(table, boundary, pts, mesh.quads.size());

  // Hanging nodes: used vertices in the interior of a used-once edge of another quad.
  const double diag = length_2d(hi - lo);
  if(diag > 0 && shapes.shortest_edge() < HUGE_VAL) r.min_edge_over_diagonal = shapes.shortest_edge() / diag;
  r.number_of_hanging_nodes = count_hanging_nodes(pts, used, mesh.quads, boundary, 1e-9 * diag, where);
  return r;
}

/// \ingroup PkgQuadMesher2Ref
/// The largest aspect ratio (longest over shortest edge) of the quads that have one of
/// `vertices` as a corner; 0 if there are none. Lemma 1 bounds it by 1.5 at input points.
template <class Point_2>
double max_aspect_ratio_around(const Quad_mesh_2<Point_2>& mesh, const std::vector<std::size_t>& vertices)
{
  std::vector<char> marked(mesh.points.size(), 0);
  for(std::size_t v : vertices)
    if(v < marked.size())
      marked[v] = 1;
  double worst = 0;
  for(const auto& q : mesh.quads) {
    if(!(marked[q[0]] || marked[q[1]] || marked[q[2]] || marked[q[3]]))
      continue;
    std::array<internal::Point_2d, 4> corners;
    for(int k = 0; k < 4; ++k)
      corners[k] = internal::to_point_2d(mesh.points[q[k]]);
    worst = (std::max)(worst, internal::quad_aspect_ratio(corners));
  }
  return worst;
}

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_MESH_QUALITY_2_H
