// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The boundary-layer stacks (paper §5, Fig. 9), extruded between each wall and its offset
// (boundary_layer_offset.h) from the nodes the mesh of the rest of the domain put on the
// offset. Each such node stands on the wall at its foot: the wall point its offset segment
// maps it to (the same fraction along the wall edge), or the wall vertex its arc turns
// about. The ray from the foot to the node carries a node at each layer's height, a fixed
// fraction of the ray, so every layer is a band of quads between two rays with the angles of
// the band's outer edge (Fig. 9(b)); where two rays share a wall vertex (a fan around a
// corner) the first layer pairs their triangles into kites (Fig. 9(a)), and an odd fan
// gives its first ray a foot of its own on the wall edge before the corner.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_EXTRUSION_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_EXTRUSION_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/approximate_kernel.h>
#include <CGAL/Quad_mesher_2/internal/boundary_layer_offset.h>
#include <CGAL/Quad_mesher_2/internal/loop_locator.h>

#include <array>
#include <cstddef>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// One band of stacked quads between two rays whose feet differ: along wall edge `edge` of
/// wall `wall`, the nodes of its two rays from the wall (0) to the offset (last).
struct Layer_band
{
  std::size_t wall = 0, edge = 0;
  std::vector<std::size_t> left, right;
  bool regular = true; // both rays rise from their own feet along the offset's own map
};

/// the mesh with its stacks, and what the report needs of them
template <class Point_2>
struct Layer_extrusion_result
{
  Quad_mesh_2<Point_2> mesh;
  std::size_t first_layer_quad = 0; // the stacks' quads follow the outer mesh's
  std::vector<Layer_band> bands;
  std::vector<std::size_t> fans;    // by wall: fans of rays around a wall vertex
};

template <class K>
class Layer_extrusion
{
public:
  typedef typename K::Point_2 Point_2;
  typedef typename K::FT FT;
  typedef Quad_mesh_2<Point_2> Mesh;

  /// `fractions`: each layer's lower height over the stack's thickness, 0 first, 1 last
  Layer_extrusion(const Domain_2<K>& domain, const std::vector<Wall_offset>& walls, std::vector<double> fractions)
    : m_domain(domain), m_walls(walls), m_f(std::move(fractions))
  {}

  /// the outer mesh (the domain bounded by the offsets, with its boundary edges) with the
  /// stacks added
  Layer_extrusion_result<Point_2> run(Mesh outer)
  {
    Layer_extrusion_result<Point_2> r;
    r.mesh = std::move(outer);
    r.first_layer_quad = r.mesh.quads.size();
    r.fans.assign(m_walls.size(), 0);
    m_wall_node.assign(m_walls.size(), {});
    for(std::size_t i = 0; i < m_walls.size(); ++i) m_wall_node[i].assign(m_walls[i].size(), none);
    const std::vector<std::vector<Ray>> cycles = offset_cycles(r.mesh);
    for(std::size_t i = 0; i < m_walls.size(); ++i) {
      std::vector<Ray> rays = cycles[i];
      give_every_vertex_a_ray(i, rays);
      r.fans[i] = pair_fans(i, rays);
      extrude(i, rays, r);
    }
    return r;
  }

private:
  static constexpr std::size_t none = std::size_t(-1);

  // a node of the outer mesh on wall i's offset, where it stands on the wall: on edge k at
  // fraction s (s = 0: vertex k)
  struct Ray
  {
    std::size_t node;
    std::size_t k;
    double s;
    bool own = true; // the offset's own map gave the foot (not moved to close a fan or a gap)
    bool at_vertex() const { return s == 0; }
  };

  // the outer mesh's boundary nodes on each wall's offset, in the offset's order (the outer
  // mesh's boundary edges run with the domain on their left, as the walls do)
  std::vector<std::vector<Ray>> offset_cycles(const Mesh& mesh) const
  {
    std::vector<std::vector<Point_2d>> polylines(m_walls.size());
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> owner(m_walls.size()); // (k, arc point)
    for(std::size_t i = 0; i < m_walls.size(); ++i)
      for(std::size_t k = 0; k < m_walls[i].size(); ++k)
        for(std::size_t a = 0; a < m_walls[i].offset[k].size(); ++a) {
          polylines[i].push_back(m_walls[i].offset[k][a]);
          owner[i].emplace_back(k, a);
        }
    const Loop_locator locator(polylines);
    const double tolerance = 1e-9 * locator.diagonal();
    std::vector<std::size_t> wall_of(mesh.points.size(), none - 1); // none - 1: not located yet
    std::vector<Ray> foot(mesh.points.size());
    auto locate = [&](std::size_t v) {
      if(wall_of[v] != none - 1) return wall_of[v];
      const Loop_locator::Hit h = locator.closest(to_point_2d(mesh.points[v]), tolerance);
      wall_of[v] = h.dist <= tolerance ? h.loop : none;
      if(wall_of[v] != none) foot[v] = foot_of(h, owner[h.loop], v);
      return wall_of[v];
    };
    std::vector<std::size_t> next(mesh.points.size(), none);
    std::vector<std::size_t> start(m_walls.size(), none);
    for(const auto& e : mesh.boundary_edges) {
      const std::size_t i = locate(e.v0);
      if(i == none || locate(e.v1) != i) continue;
      next[e.v0] = e.v1;
      if(start[i] == none || foot[e.v0].at_vertex()) start[i] = e.v0;
    }
    std::vector<std::vector<Ray>> cycles(m_walls.size());
    for(std::size_t i = 0; i < m_walls.size(); ++i) {
      if(start[i] == none) throw Meshing_error(unmeshed_offset(i));
      std::size_t v = start[i];
      do {
        cycles[i].push_back(foot[v]);
        v = next[v];
        if(v == none || cycles[i].size() > mesh.points.size()) throw Meshing_error(unmeshed_offset(i));
      } while(v != start[i]);
    }
    return cycles;
  }

  // the foot of node v, which lies on polyline edge h.edge of its wall's offset
  Ray foot_of(const Loop_locator::Hit& h, const std::vector<std::pair<std::size_t, std::size_t>>& owner,
              std::size_t v) const
  {
    const Wall_offset& w = m_walls[h.loop];
    const auto [k, a] = owner[h.edge];
    if(a + 1 < w.offset[k].size()) // on the arc about vertex k
      return { v, k, 0.0 };
    const double snap = 1e-12;
    if(h.t <= snap) return { v, k, 0.0 };
    if(h.t >= 1 - snap) return { v, w.next(k), 0.0 };
    return { v, k, h.t };
  }

  std::string unmeshed_offset(std::size_t i) const
  {
    std::ostringstream msg;
    msg << "boundary layers: the mesh of the domain outside the stacks does not follow the offset of the wall "
        << "through input point " << m_domain.point_label(m_walls[i].vertices.front());
    return msg.str();
  }

  // A wall vertex whose offset point the outer mesh left out (within its chord tolerance)
  // takes the nearer of the two rays about it whose feet are not vertices.
  void give_every_vertex_a_ray(std::size_t i, std::vector<Ray>& rays) const
  {
    const Wall_offset& w = m_walls[i];
    std::vector<char> has(w.size(), 0);
    for(const Ray& r : rays)
      if(r.at_vertex()) has[r.k] = 1;
    for(std::size_t k = 0; k < w.size(); ++k) {
      if(has[k] != 0) continue;
      // the rays before and after vertex k: the last on edge prev(k) and the first on edge k
      std::size_t before = none, after = none;
      for(std::size_t j = 0; j < rays.size(); ++j) {
        const Ray& r = rays[j];
        if(r.k == w.prev(k) && !r.at_vertex()) before = j;
        if(r.k == k && !r.at_vertex() && after == none) after = j;
      }
      const double d_before = before == none ? HUGE_VAL : (1 - rays[before].s) * edge_length(w, w.prev(k));
      const double d_after = after == none ? HUGE_VAL : rays[after].s * edge_length(w, k);
      const std::size_t take = d_before <= d_after ? before : after;
      if(take == none) {
        std::ostringstream msg;
        msg << "boundary layers: no node of the outer mesh is left to carry the stack of input point "
            << m_domain.point_label(w.vertices[k]);
        throw Meshing_error(msg.str());
      }
      rays[take] = { rays[take].node, k, 0.0, false };
      has[k] = 1;
    }
  }

  static double edge_length(const Wall_offset& w, std::size_t k) { return length_2d(w.wall[w.next(k)] - w.wall[k]); }

  // Fans: runs of rays from one wall vertex. A run of an odd number of edges gives its first
  // ray a foot on the edge before the vertex, so that the run's triangles pair into kites.
  std::size_t pair_fans(std::size_t i, std::vector<Ray>& rays) const
  {
    const Wall_offset& w = m_walls[i];
    const std::size_t n = rays.size();
    std::size_t fans = 0;
    for(std::size_t j = 0; j < n; ++j) {
      const Ray& prev = rays[(j + n - 1) % n];
      if(!rays[j].at_vertex() || (prev.at_vertex() && prev.k == rays[j].k)) continue; // not a run's first
      std::size_t m = 0;
      while(m + 1 < n && rays[(j + m + 1) % n].at_vertex() && rays[(j + m + 1) % n].k == rays[j].k) ++m;
      if(m == 0) continue;
      ++fans;
      if(m % 2 == 0) continue;
      const std::size_t k = rays[j].k, e = w.prev(k);
      const double len = edge_length(w, e);
      const double room = prev.k == e ? (1 - prev.s) * len : len; // from the previous foot to vertex k
      const double delta = (std::min)(m_f[1] * w.thickness[k], room / 2);
      rays[j] = { rays[j].node, e, 1 - delta / len, false };
    }
    return fans;
  }

  // the mesh node of wall vertex k of wall i: the input point itself
  std::size_t wall_vertex_node(std::size_t i, std::size_t k, Mesh& mesh)
  {
    std::size_t& id = m_wall_node[i][k];
    if(id == none) {
      id = mesh.points.size();
      mesh.points.push_back(m_domain.points[m_walls[i].vertices[k]]);
    }
    return id;
  }

  // the nodes of a ray, from its foot (0) to its node on the offset (last); a fan's inner
  // ray starts at ring `low` (the entries below are none)
  std::vector<std::size_t> ray_nodes(std::size_t i, const Ray& r, Mesh& mesh, std::size_t low = 0)
  {
    const Wall_offset& w = m_walls[i];
    std::vector<std::size_t> ids(m_f.size(), none);
    if(low == 0 && r.at_vertex()) {
      ids[0] = wall_vertex_node(i, r.k, mesh);
    } else if(low == 0) {
      const Point_2& a = m_domain.points[w.vertices[r.k]];
      const Point_2& b = m_domain.points[w.vertices[w.next(r.k)]];
      ids[0] = mesh.points.size();
      mesh.points.push_back(a + (b - a) * FT(r.s));
    }
    ids.back() = r.node;
    for(std::size_t j = (std::max)(low, std::size_t(1)); j + 1 < m_f.size(); ++j)
      ids[j] = add_point(along_ray(i, r, mesh, m_f[j]), mesh);
    return ids;
  }

  // the point at fraction f of ray r, from its foot to its node
  Point_2d along_ray(std::size_t i, const Ray& r, const Mesh& mesh, double f) const
  {
    const Wall_offset& w = m_walls[i];
    const Point_2d foot = r.at_vertex() ? w.wall[r.k] : along_2d(w.wall[r.k], w.wall[w.next(r.k)], r.s);
    return along_2d(foot, to_point_2d(mesh.points[r.node]), f);
  }

  static std::size_t add_point(const Point_2d& p, Mesh& mesh)
  {
    mesh.points.push_back(Point_2(p.x(), p.y()));
    return mesh.points.size() - 1;
  }

  static bool strictly_convex(const std::array<Point_2d, 4>& q)
  {
    for(int c = 0; c < 4; ++c)
      if(CGAL::orientation(q[c], q[(c + 1) % 4], q[(c + 2) % 4]) != LEFT_TURN) return false;
    return true;
  }

  // The first layer's kite (v, b, m, a) of a fan: m moves onto the bisector of the kite's
  // tip, at the mean of a's and b's distances from v over the cosine of half the tip (where
  // a and b are as far from v, the kite's sides meet their rays at right angles and its
  // angles are its tip's, 90°, 180° minus its tip's and 90°), unless that would fold one of
  // the quads `around` (those at m: the fan's, from index `first_quad` on).
  static void square_the_kite(const std::array<std::size_t, 4>& kite, std::size_t first_quad, Mesh& mesh)
  {
    auto at = [&](std::size_t v) { return to_point_2d(mesh.points[v]); };
    const Point_2d v = at(kite[0]), pb = at(kite[1]), pa = at(kite[3]);
    const Vector_2d ua = normalized_2d(pa - v), ub = normalized_2d(pb - v);
    const double half_tip = std::atan2(CGAL::determinant(ub, ua), CGAL::scalar_product(ua, ub)) / 2;
    if(!(half_tip > 0 && half_tip < 1.4)) return; // a tip over 160 degrees: no kite to square
    const double radius = (length_2d(pa - v) + length_2d(pb - v)) / 2 / std::cos(half_tip);
    const Point_2d x = v + normalized_2d(ua + ub) * radius;
    const std::size_t m = kite[2];
    for(std::size_t q = first_quad; q < mesh.quads.size(); ++q) {
      std::array<Point_2d, 4> p;
      bool at_m = false;
      for(int c = 0; c < 4; ++c) {
        at_m = at_m || mesh.quads[q][c] == m;
        p[c] = mesh.quads[q][c] == m ? x : at(mesh.quads[q][c]);
      }
      if(at_m && !strictly_convex(p)) return;
    }
    mesh.points[m] = Point_2(x.x(), x.y());
  }

  // How many edges a fan of `M` edges turning by `turn` radians has at each ring (index 1 to
  // the layers; ring 0 is its tip): all M where the first ring's kites over them have tips of
  // 45° at least; else kites over the first ring with tips near 90°, then towards the offset
  // three rays for one, in as many 1-to-3 steps as fit, on the ring where the cell of each
  // step is about square (the quadtree's template keeps its angles in [45°, 135°] there).
  std::vector<std::size_t> fan_counts(std::size_t M, double turn) const
  {
    const std::size_t layers = m_f.size() - 1;
    std::vector<std::size_t> c(layers + 1, M);
    const double pi = 3.14159265358979323846;
    const std::size_t first = (std::min)(M, (std::max)(std::size_t(2), 2 * std::size_t(std::lround(turn / (pi / 2)))));
    if(M <= 2 * first) // kites with tips of 45° at least without transitions
      return c;
    std::size_t cap = first;
    std::vector<std::size_t> caps(layers + 1, M);
    for(std::size_t j = 1; j <= layers; ++j, cap = cap > M / 3 ? M : cap * 3) caps[j] = (std::min)(cap, M);
    for(std::size_t j = layers - 1; j >= 1; --j) {
      const std::size_t above = c[j + 1];
      const std::size_t most = (std::min)(above / 3, (above - first) / 2);
      // a 1-to-3 step where the cell it makes below (three cells wide) is about square
      const double width_over_height = 3 * turn * m_f[j] / (double(above) * (m_f[j + 1] - m_f[j]));
      std::size_t blocks = width_over_height <= 1.3 ? most : 0;
      if(above > caps[j]) blocks = (std::max)(blocks, (std::min)(above / 3, (above - caps[j] + 1) / 2));
      c[j] = above - 2 * blocks;
    }
    return c;
  }

  // the rays of ring j of a fan (indices into its rays) from those of ring j + 1: `blocks`
  // runs of three edges, spread evenly, lose their two inner rays
  static std::vector<std::size_t> fewer_rays(const std::vector<std::size_t>& above, std::size_t blocks)
  {
    if(blocks == 0) return above;
    const std::size_t edges = above.size() - 1;
    std::vector<char> drop(above.size(), 0);
    const double step = double(edges) / blocks;
    for(std::size_t b = 0; b < blocks; ++b) {
      const std::size_t s = (std::min)(edges - 3, std::size_t(b * step + (step - 3) / 2));
      drop[s + 1] = drop[s + 2] = 1;
    }
    std::vector<std::size_t> kept;
    for(std::size_t i = 0; i < above.size(); ++i)
      if(drop[i] == 0) kept.push_back(above[i]);
    return kept;
  }

  // The stacks of a fan of rays `rays[0..M]` about a wall vertex (counterclockwise from the
  // last; the end rays' nodes made with the bands beside it): kites on the first ring's rays, then ring by ring a quad between two rays that
  // both go on, or the 1-to-3 template of the quadtree (a cell below three, two nodes a
  // third of the way up) where two rays start.
  void extrude_fan(std::size_t i, const std::vector<Ray>& rays, const std::vector<std::size_t>& first,
                   const std::vector<std::size_t>& last, Mesh& mesh)
  {
    const std::size_t v = first[0];
    const std::size_t layers = m_f.size() - 1, M = rays.size() - 1;
    const std::vector<std::size_t> counts = layers >= 2 ? fan_counts(M, -wall_turn(m_walls[i], rays.back().k))
                                                        : std::vector<std::size_t>(layers + 1, M);
    std::vector<std::vector<std::size_t>> ring(layers + 1); // the rays of each ring, in order
    for(std::size_t a = 0; a <= M; ++a) ring[layers].push_back(a);
    for(std::size_t j = layers - 1; j >= 1; --j)
      ring[j] = fewer_rays(ring[j + 1], (counts[j + 1] - counts[j]) / 2);
    ring[0] = ring[1];
    std::vector<std::size_t> low(M + 1, layers);
    for(std::size_t j = layers; j >= 1; --j)
      for(std::size_t a : ring[j]) low[a] = j;
    std::vector<std::vector<std::size_t>> nodes(M + 1);
    nodes[0] = first;
    nodes[M] = last;
    for(std::size_t a = 1; a < M; ++a) nodes[a] = ray_nodes(i, rays[a], mesh, low[a]);
    const std::size_t first_quad = mesh.quads.size();
    for(std::size_t j = 1; j < layers; ++j) fan_ring(i, rays, ring[j], ring[j + 1], j, nodes, mesh);
    const std::vector<std::size_t>& r1 = ring[1];
    for(std::size_t e = 0; e + 2 < r1.size(); e += 2)
      mesh.quads.push_back({ { v, nodes[r1[e + 2]][1], nodes[r1[e + 1]][1], nodes[r1[e]][1] } });
    if(layers >= 2) // the kites' middles are inner nodes
      for(std::size_t q = mesh.quads.size() - (r1.size() - 1) / 2; q < mesh.quads.size(); ++q)
        square_the_kite(mesh.quads[q], first_quad, mesh);
  }

  // the quads between ring j of a fan and ring j + 1
  void fan_ring(std::size_t i, const std::vector<Ray>& rays, const std::vector<std::size_t>& lower,
                const std::vector<std::size_t>& upper, std::size_t j, std::vector<std::vector<std::size_t>>& nodes,
                Mesh& mesh)
  {
    std::size_t u = 0;
    for(std::size_t e = 0; e + 1 < lower.size(); ++e) {
      const std::size_t a = lower[e], c = lower[e + 1];
      while(upper[u] != a) ++u;
      if(upper[u + 1] == c) {
        mesh.quads.push_back({ { nodes[a][j], nodes[c][j], nodes[c][j + 1], nodes[a][j + 1] } });
        continue;
      }
      const std::size_t p = upper[u + 1], q = upper[u + 2];
      const double f = m_f[j] + (m_f[j + 1] - m_f[j]) / 3;
      const std::size_t pm = add_point(along_ray(i, rays[p], mesh, f), mesh);
      const std::size_t qm = add_point(along_ray(i, rays[q], mesh, f), mesh);
      mesh.quads.push_back({ { nodes[a][j], nodes[c][j], qm, pm } });
      mesh.quads.push_back({ { nodes[a][j], pm, nodes[p][j + 1], nodes[a][j + 1] } });
      mesh.quads.push_back({ { pm, qm, nodes[q][j + 1], nodes[p][j + 1] } });
      mesh.quads.push_back({ { qm, nodes[c][j], nodes[c][j + 1], nodes[q][j + 1] } });
    }
  }

  // the quads of wall i's stacks, counterclockwise: a band between each two rays with
  // different feet, and a fan where rays share a wall vertex
  void extrude(std::size_t i, const std::vector<Ray>& rays, Layer_extrusion_result<Point_2>& r)
  {
    Mesh& mesh = r.mesh;
    const std::size_t n = rays.size(), layers = m_f.size() - 1;
    auto same_foot = [&](std::size_t a, std::size_t b) {
      return rays[a].at_vertex() && rays[b].at_vertex() && rays[a].k == rays[b].k;
    };
    std::size_t start = 0; // a ray that begins no fan edge... after one that ends none
    while(start < n && same_foot((start + n - 1) % n, start)) ++start;
    std::vector<std::vector<std::size_t>> nodes(n);
    std::size_t j = start;
    for(std::size_t done = 0; done < n;) {
      std::size_t m = 0; // the fan's edges from ray j
      while(same_foot((j + m) % n, (j + m + 1) % n)) ++m;
      if(m > 0) {
        std::vector<Ray> fan;
        for(std::size_t a = 0; a <= m; ++a) fan.push_back(rays[(j + a) % n]);
        // the fan's end rays are the bands' too: made once, with every ring
        for(std::size_t a : { std::size_t(0), m })
          if(nodes[(j + a) % n].empty()) nodes[(j + a) % n] = ray_nodes(i, rays[(j + a) % n], mesh);
        extrude_fan(i, fan, nodes[j], nodes[(j + m) % n], mesh);
        j = (j + m) % n;
        done += m;
        continue;
      }
      const std::size_t b = (j + 1) % n;
      for(std::size_t a : { j, b })
        if(nodes[a].empty()) nodes[a] = ray_nodes(i, rays[a], mesh);
      for(std::size_t l = 0; l < layers; ++l)
        mesh.quads.push_back({ { nodes[j][l], nodes[b][l], nodes[b][l + 1], nodes[j][l + 1] } });
      Layer_band band;
      band.wall = i;
      band.edge = rays[j].k;
      band.left = nodes[j];
      band.right = nodes[b];
      band.regular = rays[j].own && rays[b].own;
      r.bands.push_back(std::move(band));
      j = b;
      ++done;
    }
  }

  const Domain_2<K>& m_domain;
  const std::vector<Wall_offset>& m_walls;
  std::vector<double> m_f;
  std::vector<std::vector<std::size_t>> m_wall_node; // by wall and vertex: its mesh node
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_EXTRUSION_H
