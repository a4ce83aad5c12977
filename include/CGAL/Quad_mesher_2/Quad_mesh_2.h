// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_QUAD_MESH_2_H
#define CGAL_QUAD_MESHER_2_QUAD_MESH_2_H

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dimension.h>
#include <CGAL/Kernel_traits.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// A light indexed all-quadrilateral mesh: the output of every meshing stage.
/// Each quad lists four indices into `points`, counter-clockwise. Vertices are unique:
/// no two entries of `points` are equal and every point is used by some quad.
template <class Point_2_>
struct Quad_mesh_2
{
  typedef Point_2_ Point_2;
  typedef std::array<std::size_t, 4> Quad;
  /// an edge of the mesh's boundary, from `v0` to `v1` (indices into `points`), and the
  /// boundary marker of the input segment it lies on
  struct Boundary_edge
  {
    std::size_t v0, v1;
    int marker;
  };

  std::vector<Point_2> points;
  std::vector<Quad> quads;
  /// For a mesh of a whole domain (`Stage::BUFFER2`, the default for a domain bounded by
  /// segments): every boundary edge (the edge of one quad only), directed as its quad runs
  /// (the domain on its left), in the order of the quads, with the marker of the input
  /// segment it lies on: its `Domain_2::segment_markers` entry, or where the domain has none
  /// its loop's number, from 1, outer loop first (the order of `extract_loops()`). An edge
  /// over an input vertex the mesh leaves out (within the chord tolerance) takes the marker
  /// of the segment nearest its midpoint. Empty after the earlier stages and for a point
  /// cloud, whose boundary is not the input's. The MSH, VTU, SU2 and INP writers write these
  /// edges with the quads; they change neither `points` nor `quads`.
  std::vector<Boundary_edge> boundary_edges;

  /// A region of the mesh: the quads of one face of the domain, or of every face that has
  /// one regional attribute (`Domain_2::region_attributes`: one material). `tag` (> 0) names
  /// it in the outputs: the attribute itself where it is an integer from 1 to 2^31 - 1, else
  /// the next tag no region has, in the order of the domain's regions.
  struct Region
  {
    int tag = 1;
    bool has_attribute = false;
    double attribute = 0; ///< 0 where there is none, as Triangle gives
  };
  /// For a mesh of a whole domain (with `boundary_edges`): its regions, in the order of the
  /// domain's (`Boundary_loop_2::region`), those of one attribute merged at the first; empty
  /// after the earlier stages and for a point cloud.
  std::vector<Region> regions;
  /// the region of each quad, an index into `regions` (empty when `regions` is)
  std::vector<std::size_t> quad_regions;

  std::size_t number_of_vertices() const { return points.size(); }
  std::size_t number_of_quads() const { return quads.size(); }
  void clear()
  {
    points.clear();
    quads.clear();
    boundary_edges.clear();
    regions.clear();
    quad_regions.clear();
  }
};

namespace internal {

// `p` as a point of a face graph: itself where the graph's point type is constructible from
// it, else the 3D point (x, y, 0) (a surface mesh of `Point_3`, the usual one in CGAL)
template <class Graph_point, class Point_2>
Graph_point face_graph_point(const Point_2& p)
{
  if constexpr(std::is_constructible_v<Graph_point, const Point_2&>) {
    return Graph_point(p);
  } else {
    static_assert(Ambient_dimension<Graph_point>::value == 3,
                  "copy_to_face_graph: the graph's points must be made from a Point_2 or be 3D");
    typedef typename Kernel_traits<Graph_point>::Kernel::FT FT;
    return Graph_point(FT(p.x()), FT(p.y()), FT(0));
  }
}

} // namespace internal

/// \ingroup PkgQuadMesher2Ref
/// Appends `mesh` to `graph`, a model of `MutableFaceGraph` whose vertex point type is
/// constructible from `Point_2`, or is a 3D point whose coordinates' type is constructible
/// from those of `Point_2` (then the mesh lies in the plane z = 0). Returns `false` (leaving
/// `graph` partly filled) if a face could not be added, which happens only for a non-manifold
/// input.
template <class Point_2, class FaceGraph>
bool copy_to_face_graph(const Quad_mesh_2<Point_2>& mesh, FaceGraph& graph)
{
  typedef typename boost::graph_traits<FaceGraph>::vertex_descriptor vertex_descriptor;
  auto vpm = get(CGAL::vertex_point, graph);
  typedef typename boost::property_traits<decltype(vpm)>::value_type Graph_point;
  std::vector<vertex_descriptor> vertices;
  vertices.reserve(mesh.points.size());
  for(const Point_2& p : mesh.points) {
    vertex_descriptor v = add_vertex(graph);
    put(vpm, v, internal::face_graph_point<Graph_point>(p));
    vertices.push_back(v);
  }
  std::array<vertex_descriptor, 4> face;
  for(const auto& q : mesh.quads) {
    for(int k = 0; k < 4; ++k)
      face[k] = vertices[q[k]];
    if(CGAL::Euler::add_face(face, graph) == boost::graph_traits<FaceGraph>::null_face())
      return false;
  }
  return true;
}

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_QUAD_MESH_2_H
