// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_DOMAIN_2_H
#define CGAL_QUAD_MESHER_2_DOMAIN_2_H

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// A planar input in the sense of Triangle's `.poly` files: points, segments between them and
/// hole seed points.
///
/// - `segments`: each is two 0-based indices into `points`; they may meet only at their end
///   points. They form boundary <em>loops</em> (closed chains), open polylines inside the
///   domain (cracks) and, where three or more meet at a point (a junction), faces of an
///   arrangement: regions meshed together, sharing the nodes of the segments between them.
///   The outer loop and the hole loops are given alike, in either orientation (the mesher
///   orients them, see `extract_loops()`).
/// - `holes`: a hole is marked by a seed point strictly inside it (not on a segment), which
///   makes the region it lies in outside the domain; with seed points, every hole needs one.
///   With none at all, nesting decides: inside an outermost loop is domain, inside a loop
///   nested in it a hole, inside the next domain again, and so on; unless
///   `every_hole_marked` says that there is no hole.
/// - `every_hole_marked`: `true` if `holes` marks every hole even when it is empty, so that
///   every bounded region without a hole point is in the domain whatever its nesting, as in
///   any domain with hole points. The WKT reader sets it: its holes are inner rings, each
///   with a seed unless other polygons fill it.
/// - <em>Isolated points</em> are the points on no segment; each must lie strictly inside the
///   domain, and the points stage (`Mesh_criteria_2::points_as_vertices()`, the default) makes
///   each one a mesh vertex.
/// - `region_attributes`: optional, Triangle's regional attributes: a point strictly inside
///   the domain gives the region it lies in (the face bounded by the loop around it and the
///   loops just within) its attribute; every quad of that region carries it
///   (`Quad_mesh_2::regions`). At most one attribute per region; a region without one is a
///   region of its own all the same.
/// - `segment_markers`: optional, one boundary marker per segment (a `.poly` file's segment
///   markers); the mesh's boundary edges carry them (`Quad_mesh_2::boundary_edges`). Empty if
///   the input has none: each loop's edges then carry the loop's number instead.
/// - A <em>point cloud</em> is a `Domain_2` without segments (`is_point_cloud()`): every
///   point becomes a mesh vertex.
template <class GeomTraits>
struct Domain_2
{
  typedef typename GeomTraits::Point_2 Point_2;
  typedef std::array<std::size_t, 2> Segment;
  /// a regional attribute: `attribute` for the region holding `point`; `max_area`, Triangle's
  /// area bound (0: none), bounds the side of the quadtree cells meeting that region by its
  /// square root: the core's quads keep within it, the buffer's beside corners may not (up to
  /// a few times it), unlike Triangle's triangles
  struct Region_attribute
  {
    Point_2 point;
    double attribute = 0;
    double max_area = 0;
  };

  std::vector<Point_2> points;
  std::vector<Segment> segments;
  std::vector<Point_2> holes;
  bool every_hole_marked = false;
  std::vector<int> segment_markers; // empty, or one per segment
  std::vector<Region_attribute> region_attributes;
  /// Optional, for error messages: how the user knows point `i`, segment `s`, hole `h`, regional
  /// attribute `r`. The readers
  /// give the file's own numbering and line (`"5 (line 7)"` in a 1-based `.poly`); where
  /// these are empty, messages give the 0-based index.
  std::vector<std::string> point_labels;
  std::vector<std::string> segment_labels;
  std::vector<std::string> hole_labels;
  std::vector<std::string> region_attribute_labels;

  bool is_point_cloud() const { return segments.empty(); }
  /// `point_labels[i]`, or `i` (0-based) if there is none
  std::string point_label(std::size_t i) const
  {
    return i < point_labels.size() ? point_labels[i] : std::to_string(i);
  }
  /// `segment_labels[s]`, or `s` (0-based) if there is none
  std::string segment_label(std::size_t s) const
  {
    return s < segment_labels.size() ? segment_labels[s] : std::to_string(s);
  }
  /// `hole_labels[h]`, or `h` (0-based) if there is none
  std::string hole_label(std::size_t h) const
  {
    return h < hole_labels.size() ? hole_labels[h] : std::to_string(h);
  }
  /// `region_attribute_labels[r]`, or `r` (0-based) if there is none
  std::string region_attribute_label(std::size_t r) const
  {
    return r < region_attribute_labels.size() ? region_attribute_labels[r] : std::to_string(r);
  }
};

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_DOMAIN_2_H
