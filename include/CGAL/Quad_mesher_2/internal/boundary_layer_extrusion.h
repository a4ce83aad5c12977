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
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <sstream>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// A node of the mesh with stacks: the outer mesh's or on the wall, on a band's ray, or
/// inside a fan (on its inner rays or a 1-to-3 step's)
enum class Stack_node : char { fixed, band, fan };

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
  std::vector<Stack_node> nodes;    // by node: what it is
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
    m_outer_points = r.mesh.points.size();
    if(m_f.size() == 2) // one layer: the kites' middles are the outer mesh's nodes
      m_outer_quads_at = std::make_unique<Vertex_quads>(r.mesh.quads, m_outer_points);
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
    r.nodes.assign(r.mesh.points.size(), Stack_node::band);
    std::fill(r.nodes.begin(), r.nodes.begin() + std::ptrdiff_t(m_outer_points), Stack_node::fixed);
    for(std::size_t v : m_wall_nodes) r.nodes[v] = Stack_node::fixed;
    for(std::size_t v : m_fan_nodes) r.nodes[v] = Stack_node::fan;
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
    std::vector<std::size_t> wall_of(mesh.points.size(), none); // none: on no offset
    std::vector<char> located(mesh.points.size(), 0);
    std::vector<Ray> foot(mesh.points.size());
    auto locate = [&](std::size_t v) {
      if(located[v] != 0) return wall_of[v];
      located[v] = 1;
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
    const double s = wall_fraction(w, k, h.t), length = edge_length(w, k);
    if(s * length < nearest_foot(w, k)) return { v, k, 0.0 };
    if((1 - s) * length < nearest_foot(w, w.next(k))) return { v, w.next(k), 0.0 };
    return { v, k, s };
  }

  // Where the node at fraction t along the offset segment of wall edge k stands on the edge:
  // the same fraction shifted along the edge as the offset's ends are shifted from the
  // edge's (rays turning smoothly from one end's to the other's), but for an end whose mitre
  // lies ahead along the edge (a concave corner): there the node's own projection, whose ray
  // is square to the wall. A sharp concave corner's mitre lies far ahead (the thickness over
  // the sine of half its angle), and rays slanted to it all along the edge made the whole
  // band a sliver.
  static double wall_fraction(const Wall_offset& w, std::size_t k, double t)
  {
    const std::size_t k1 = w.next(k);
    const Vector_2d edge = w.wall[k1] - w.wall[k];
    const double length = length_2d(edge);
    const Vector_2d e = edge / length;
    const Point_2d& from = w.offset[k].back();
    const Point_2d& to = w.offset[k1].front();
    const double ahead0 = CGAL::scalar_product(from - w.wall[k], e); // > 0: ahead, concave
    const double ahead1 = CGAL::scalar_product(w.wall[k1] - to, e);
    if(ahead0 <= 0 && ahead1 <= 0) return t;
    const double x0 = (std::max)(ahead0, 0.0), x1 = length - (std::max)(ahead1, 0.0);
    if(!(x1 > x0)) return t; // the two mitres pass each other: no room to square the rays
    return (x0 + t * (x1 - x0)) / length;
  }

  std::string unmeshed_offset(std::size_t i) const
  {
    std::ostringstream msg;
    msg << "boundary layers: the mesh of the domain outside the stacks does not follow the offset of the wall "
        << "through input point " << m_domain.point_label(m_walls[i].vertices.front());
    return msg.str();
  }

  // A wall vertex whose offset point the outer mesh left out takes the nearer of the two rays
  // about it whose feet are not vertices, unless it lies on the line of its neighbours (the
  // outer mesh leaves out an offset point exactly on its neighbours' line even with no chord
  // tolerance): the band over it then follows the wall as well.
  void give_every_vertex_a_ray(std::size_t i, std::vector<Ray>& rays) const
  {
    const Wall_offset& w = m_walls[i];
    std::vector<char> has(w.size(), 0);
    for(const Ray& r : rays)
      if(r.at_vertex()) has[r.k] = 1;
    for(std::size_t k = 0; k < w.size(); ++k) {
      if(has[k] != 0 || CGAL::orientation(w.wall[w.prev(k)], w.wall[k], w.wall[w.next(k)]) == COLLINEAR) continue;
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
      const double delta = (std::min)((std::max)(m_f[1] * w.thickness[k], nearest_foot(w, k)), room / 2);
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
      m_wall_nodes.push_back(id);
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
      m_wall_nodes.push_back(ids[0]);
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
  // angles are its tip's, 90°, 180° minus its tip's and 90°), or as far towards there as
  // better_at() allows (with one layer, m is the outer mesh's node, whose quads count too).
  void square_the_kite(const std::array<std::size_t, 4>& kite, std::size_t fan_quads, Mesh& mesh) const
  {
    auto at = [&](std::size_t v) { return to_point_2d(mesh.points[v]); };
    const Point_2d v = at(kite[0]), pb = at(kite[1]), pa = at(kite[3]);
    const Vector_2d ua = normalized_2d(pa - v), ub = normalized_2d(pb - v);
    const double half_tip = std::atan2(CGAL::determinant(ub, ua), CGAL::scalar_product(ua, ub)) / 2;
    if(!(half_tip > 0 && half_tip < 1.4)) return; // a tip over 160 degrees: no kite to square
    const double radius = (length_2d(pa - v) + length_2d(pb - v)) / 2 / std::cos(half_tip);
    const Point_2d x = v + normalized_2d(ua + ub) * radius;
    const std::size_t m = kite[2];
    const Point_2d from = at(m);
    // all the way there, else as far as the outer mesh's quads at m allow
    for(double step = 1; step >= 1.0 / 64; step /= 2) {
      const Point_2d to = along_2d(from, x, step);
      if(better_at(m, to, fan_quads, mesh)) {
        mesh.points[m] = Point_2(to.x(), to.y());
        return;
      }
    }
  }

  // whether node m at `to` keeps the quads at it convex (the fan's, from index `fan_quads`
  // on, and with one layer the outer mesh's), those of the outer mesh within [45°, 135°],
  // and brings the worst nearer to right angles
  bool better_at(std::size_t m, const Point_2d& to, std::size_t fan_quads, const Mesh& mesh) const
  {
    std::vector<std::size_t> at_m;
    if(m_outer_quads_at != nullptr && m < m_outer_points)
      for(std::uint32_t q : (*m_outer_quads_at)[m]) at_m.push_back(q);
    for(std::size_t q = fan_quads; q < mesh.quads.size(); ++q)
      if(std::find(mesh.quads[q].begin(), mesh.quads[q].end(), m) != mesh.quads[q].end()) at_m.push_back(q);
    double before = 0, after = 0; // the worst angle's distance from 90° in the quads at m
    for(std::size_t q : at_m) {
      std::array<Point_2d, 4> p, moved;
      for(int c = 0; c < 4; ++c) {
        p[c] = to_point_2d(mesh.points[mesh.quads[q][c]]);
        moved[c] = mesh.quads[q][c] == m ? to : p[c];
      }
      if(!strictly_convex(moved)) return false;
      if(q < fan_quads && quad_max_angle_deviation(moved) > 45 + 1e-9) return false;
      before = (std::max)(before, quad_max_angle_deviation(p));
      after = (std::max)(after, quad_max_angle_deviation(moved));
    }
    return after < before;
  }

  // A fan's rays `rays[0..M]` about one wall vertex (counterclockwise from the last), their
  // angles from the first, and their nodes by ring, made as they are needed.
  struct Fan
  {
    std::size_t wall, v;
    std::vector<Ray> rays;
    std::vector<double> angle;
    std::vector<std::vector<std::size_t>> nodes;
  };

  std::size_t fan_node(Fan& fan, std::size_t a, std::size_t j, Mesh& mesh)
  {
    std::size_t& id = fan.nodes[a][j];
    if(id == none) {
      id = add_point(along_ray(fan.wall, fan.rays[a], mesh, m_f[j]), mesh);
      m_fan_nodes.push_back(id);
    }
    return id;
  }

  // how many levels of 1-to-3 steps a run of g edges (odd) needs from one edge
  static std::size_t levels(std::size_t g)
  {
    std::size_t n = 0;
    for(std::size_t reach = 1; reach < g; reach *= 3) ++n;
    return n;
  }

  // The ray after `from`, at least one edge and an odd number of them on, nearest to angle
  // `target`, leaving `rest` edges up to `to` that `gaps` odd runs of at most `most` edges
  // each can take.
  static std::size_t odd_step(const Fan& fan, std::size_t from, std::size_t to, double target, std::size_t gaps,
                              std::size_t most)
  {
    std::size_t best = none;
    for(std::size_t p = from + 1; p < to; p += 2) {
      const std::size_t rest = to - p;
      if(rest < gaps || (rest - gaps) % 2 != 0 || rest > gaps * most || p - from > most) continue;
      if(best == none || std::abs(fan.angle[p] - target) < std::abs(fan.angle[best] - target)) best = p;
    }
    CGAL_assertion(best != none); // the callers leave room: an odd run of one edge at least
    return best == none ? from + 1 : best;
  }

  // The quads between rays lo and hi from ring `low` on, whose odd number of edges at the
  // offset the quadtree's 1-to-3 template reaches step by step: one cell up to the ring where
  // it is as wide as tall (or the last that leaves enough rings), there the template (a cell
  // below three, two inner nodes), then each third likewise.
  void fan_gap(Fan& fan, std::size_t lo, std::size_t hi, std::size_t low, Mesh& mesh)
  {
    const std::size_t layers = m_f.size() - 1, g = hi - lo;
    std::size_t split = layers;
    if(g > 1) {
      const std::size_t latest = layers - levels(g);
      const double span = fan.angle[hi] - fan.angle[lo];
      split = latest;
      for(std::size_t j = low; j < latest; ++j)
        if(span * m_f[j] >= m_f[j + 1] - m_f[j]) { split = j; break; }
    }
    for(std::size_t j = low; j < split; ++j)
      mesh.quads.push_back({ { fan_node(fan, lo, j, mesh), fan_node(fan, hi, j, mesh), fan_node(fan, hi, j + 1, mesh),
                               fan_node(fan, lo, j + 1, mesh) } });
    if(g == 1) return;
    const std::size_t most = std::size_t(std::pow(3.0, double(layers - split - 1)) + 0.5);
    const double third = (fan.angle[hi] - fan.angle[lo]) / 3;
    const std::size_t p = odd_step(fan, lo, hi, fan.angle[lo] + third, 2, most);
    const std::size_t q = odd_step(fan, p, hi, fan.angle[hi] - third, 1, most);
    const std::size_t j = split;
    // the two inner nodes a third of the cell's width up (45° at its lower corners), between a
    // third and 0.6 of its height
    const double width_over_height = (fan.angle[hi] - fan.angle[lo]) * m_f[j] / (m_f[j + 1] - m_f[j]);
    const double up = (std::min)(0.6, (std::max)(1.0 / 3, width_over_height / 3));
    const double f = m_f[j] + (m_f[j + 1] - m_f[j]) * up;
    const std::size_t pm = add_point(along_ray(fan.wall, fan.rays[p], mesh, f), mesh);
    const std::size_t qm = add_point(along_ray(fan.wall, fan.rays[q], mesh, f), mesh);
    m_fan_nodes.insert(m_fan_nodes.end(), { pm, qm });
    const std::size_t a = fan_node(fan, lo, j, mesh), c = fan_node(fan, hi, j, mesh);
    mesh.quads.push_back({ { a, c, qm, pm } });
    mesh.quads.push_back({ { a, pm, fan_node(fan, p, j + 1, mesh), fan_node(fan, lo, j + 1, mesh) } });
    mesh.quads.push_back({ { pm, qm, fan_node(fan, q, j + 1, mesh), fan_node(fan, p, j + 1, mesh) } });
    mesh.quads.push_back({ { qm, c, fan_node(fan, hi, j + 1, mesh), fan_node(fan, q, j + 1, mesh) } });
    fan_gap(fan, lo, p, j + 1, mesh);
    fan_gap(fan, p, q, j + 1, mesh);
    fan_gap(fan, q, hi, j + 1, mesh);
  }

  // The stacks of a fan of rays `rays[0..M]` about a wall vertex (counterclockwise from the
  // last; the end rays' nodes made with the bands beside it): kites over every two of the
  // offset's edges where their tips are 45° at least; else on the first ring kites with tips
  // near 90° over rays chosen by angle, each two runs of an odd number of the offset's edges,
  // which 1-to-3 steps reach ring by ring (fan_gap()). With one layer, kites over the
  // offset's own nodes.
  void extrude_fan(std::size_t i, const std::vector<Ray>& rays, const std::vector<std::size_t>& first,
                   const std::vector<std::size_t>& last, Mesh& mesh)
  {
    const std::size_t layers = m_f.size() - 1, M = rays.size() - 1;
    Fan fan{ i, first[0], rays, { 0.0 }, std::vector<std::vector<std::size_t>>(M + 1, std::vector<std::size_t>(layers + 1, none)) };
    for(std::size_t a = 1; a <= M; ++a) {
      const Vector_2d u = to_point_2d(mesh.points[rays[a - 1].node]) - m_walls[i].wall[rays[a].k];
      const Vector_2d w = to_point_2d(mesh.points[rays[a].node]) - m_walls[i].wall[rays[a].k];
      fan.angle.push_back(fan.angle.back() + std::abs(std::atan2(CGAL::determinant(u, w), CGAL::scalar_product(u, w))));
    }
    fan.nodes[0] = first;
    fan.nodes[M] = last;
    for(std::size_t a = 1; a < M; ++a) fan.nodes[a].back() = rays[a].node;
    // the first ring's rays: 2 round(turn / 90°) runs, none longer than the rings can reach
    const double pi = 3.14159265358979323846;
    const std::size_t most = layers == 1 ? 1 : std::size_t(std::pow(3.0, double((std::min)(layers - 1, std::size_t(20)))) + 0.5);
    std::size_t runs = (std::max)(std::size_t(2), 2 * std::size_t(std::lround(fan.angle.back() / (pi / 2))));
    if(double(M) * pi / 8 <= fan.angle.back() + 1e-9) runs = M; // kites over every edge, with tips of 45° at least
    while(runs * most < M) runs += 2;
    runs = (std::min)(runs, M);
    std::vector<std::size_t> ring1{ 0 };
    for(std::size_t r = 1; r < runs; ++r)
      ring1.push_back(odd_step(fan, ring1.back(), M, fan.angle.back() * r / runs, runs - r, most));
    ring1.push_back(M);
    const std::size_t first_quad = mesh.quads.size();
    for(std::size_t r = 0; r + 1 < ring1.size(); ++r)
      fan_gap(fan, ring1[r], ring1[r + 1], 1, mesh);
    for(std::size_t r = 0; r + 2 < ring1.size(); r += 2)
      mesh.quads.push_back({ { fan.v, fan_node(fan, ring1[r + 2], 1, mesh), fan_node(fan, ring1[r + 1], 1, mesh),
                               fan_node(fan, ring1[r], 1, mesh) } });
    for(std::size_t q = mesh.quads.size() - runs / 2; q < mesh.quads.size(); ++q)
      square_the_kite(mesh.quads[q], first_quad, mesh);
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
  std::size_t m_outer_points = 0;                    // the outer mesh's, first in the result
  std::unique_ptr<Vertex_quads> m_outer_quads_at;    // with one layer: its quads at each node
  std::vector<std::size_t> m_wall_nodes;             // the stacks' nodes on the wall
  std::vector<std::size_t> m_fan_nodes;              // and inside fans
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BOUNDARY_LAYER_EXTRUSION_H
