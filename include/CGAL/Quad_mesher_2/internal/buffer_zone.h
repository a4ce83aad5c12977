// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The state the buffer stages (paper §4.4-§5) share: the mesh being built and its points in
// doubles, the core's boundary cycles matched one to one with the domain's loops, and what each
// point is (on a cycle, moved by a stage, an input vertex, sliding along an input edge), with
// the queries every stage asks of them. Each stage is a class of its own header working on one
// `Buffer_zone`; `Buffer_layers` (buffer_layers.h) runs them in order.

#ifndef CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_H
#define CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_H

#include <CGAL/Quad_mesher_2/Buffer_report.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/buffer_tolerances.h>
#include <CGAL/Quad_mesher_2/internal/loop_locator.h>
#include <CGAL/Quad_mesher_2/internal/mesh_adjacency.h>
#include <CGAL/Quad_mesher_2/internal/move_memo.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace internal {

/// where the quadtree should be finer: points with the local size there
struct Refinement_requests
{
  /// where a finer quadtree would make the buffer valid
  std::vector<std::pair<Point_2d, double>> for_validity;
  /// where it would bring angles into [45, 135]
  std::vector<std::pair<Point_2d, double>> for_angles;
};

/// whether vertex k of `loop` is the tip of a crack (its neighbours are one input point: the
/// loop runs along the crack and back), a corner of 360 degrees
template <class K>
bool is_crack_tip(const Boundary_loop_2<K>& loop, std::size_t k)
{
  const std::vector<std::size_t>& lv = loop.vertices;
  const std::size_t nv = lv.size();
  return lv[(k + nv - 1) % nv] == lv[(k + 1) % nv];
}

/// the angle of the domain at vertex k of `loop` (the domain on its left), degrees
template <class K>
double loop_corner_angle(const Domain_2<K>& domain, const Boundary_loop_2<K>& loop, std::size_t k)
{
  const std::vector<std::size_t>& lv = loop.vertices;
  const std::size_t nv = lv.size();
  if(is_crack_tip(loop, k)) return 360.0;
  return 360.0 - right_side_angle(to_point_2d(domain.points[lv[(k + nv - 1) % nv]]), to_point_2d(domain.points[lv[k]]),
                                  to_point_2d(domain.points[lv[(k + 1) % nv]]));
}

/// The buffer stages' shared state on one core mesh (see the file comment).
template <class K>
class Buffer_zone : public Buffer_tolerances
{
public:
  typedef typename K::FT FT;
  typedef typename K::Point_2 Point_2;
  typedef Quad_mesh_2<Point_2> Mesh;
  typedef Quad_vertices Quad;

  // a loop, and how many vertices of a core cycle it is nearest
  typedef std::pair<std::size_t, std::size_t> Vote;

  // a new boundary point: it may slide along its input edge between its chain neighbours
  struct Slide
  {
    std::size_t loop, edge;
    std::array<std::size_t, 2> neighbors;
  };

  Buffer_zone(Mesh& core, const std::vector<double>& core_size, const Domain_2<K>& input, const Domain_loops_2<K>& input_loops,
              const K& kernel)
    : mesh(core), local_size(core_size), domain(input), loops(input_loops), traits(kernel)
  {
    locator = make_loop_locator(domain, loops);
    find_interface_corners();
    xy.reserve(mesh.points.capacity()); // the room the clearance left for the layers' points
    xy.resize(mesh.points.size());
    for(std::size_t v = 0; v < mesh.points.size(); ++v)
      xy[v] = to_point_2d(mesh.points[v]);
    core_points = mesh.points.size();
  }

  /// Matches the core's boundary loops with the domain's, after dropping the small pieces
  /// of core that would not match (drop_small_unmatched_pieces(): none holds one of
  /// `fixed_points`); false (with `report.failure` and `requests`) if they do not match one
  /// to one.
  bool match_loops(const std::vector<std::size_t>& fixed_points = {})
  {
    find_cycles();
    std::vector<Vote> votes = cycle_votes();
    if(drop_small_unmatched_pieces(votes, fixed_points)) {
      find_cycles();
      votes = cycle_votes();
    }
    // The layers add a few quads and points per core boundary vertex (about two each on a
    // disc): room for four each now (the clearance's core has it already), or the first one
    // added copies the whole core's arrays into fresh memory.
    std::size_t boundary_vertices = 0;
    for(const auto& cyc : cycles)
      boundary_vertices += cyc.size();
    mesh.quads.reserve(mesh.quads.size() + 4 * boundary_vertices);
    mesh.points.reserve(mesh.points.size() + 4 * boundary_vertices);
    xy.reserve(xy.size() + 4 * boundary_vertices);
    cycle_loop.assign(cycles.size(), none);
    on_cycle_mark.assign(mesh.points.size(), 0);
    std::vector<std::size_t> owner(loops.loops.size(), none);
    bool ok = true;
    for(std::size_t c = 0; c < cycles.size(); ++c) {
      const std::size_t l = votes[c].first;
      if(owner[l] != none || !follows(c, votes[c])) {
        ok = false;
        // the smaller of two cycles following one loop is a piece of core cut off by a
        // narrow passage: refine along it, and across the passage (refining along the
        // piece alone grew it, round after round, while the passage stayed closed)
        std::size_t cut = c;
        if(owner[l] != none && cycles[owner[l]].size() < cycles[c].size()) std::swap(cut, owner[l]);
        request_all(cut);
        if(owner[l] != none) request_passage(cut, owner[l]);
        report.failure = "the core mesh's boundary does not follow the domain's loops one to one";
        continue;
      }
      owner[l] = c;
      cycle_loop[c] = l;
      for(std::size_t v : cycles[c]) on_cycle_mark[v] = 1;
    }
    for(std::size_t l = 0; l < owner.size(); ++l)
      if(owner[l] == none) {
        ok = false;
        report.failure = "no core mesh is left near loop " + std::to_string(l)
                           + " of the domain: its cells are too coarse";
        // cells a quarter of its gap to the other loops, on it and halfway across the gap
        for(const Point_2d& p : locator->loop(l)) {
          const Loop_locator::Hit h = locator->closest(p, 1e-6 * locator->diagonal(), l, true);
          const double size = std::isfinite(h.dist) ? 0.25 * h.dist : 0.0;
          requests.for_validity.emplace_back(p, 2 * size);
          if(size > 0)
            requests.for_validity.emplace_back(CGAL::midpoint(p, h.point), 2 * size);
        }
      }
    return ok;
  }

  bool on_cycle(std::size_t v) const { return v < on_cycle_mark.size() && on_cycle_mark[v] != 0; }

  // a core vertex the repair moves of optimize() moved
  bool repaired(std::size_t v) const { return v < repaired_mark.size() && repaired_mark[v] != 0; }

  // an interior core vertex the templates moved (relax_interior())
  bool shaped(std::size_t v) const { return v < shaped_mark.size() && shaped_mark[v] != 0; }

  // a quad the buffer stages made or changed: a vertex new, on the core boundary or moved by
  // the templates or the repair (the other core quads keep their lattice angles, in [45, 135])
  bool made_or_changed(const Quad& Q) const
  {
    for(std::size_t v : Q)
      if(v >= core_points || on_cycle(v) || repaired(v) || shaped(v)) return true;
    return false;
  }

  bool is_core_boundary(std::size_t v) const
  {
    return v < core_points && on_cycle(v) && !first_built;
  }

  void find_cycles()
  {
    quads_at = std::make_unique<Vertex_quads>(mesh.quads, mesh.points.size());
    cycles = mesh_boundary_cycles(mesh.quads, *quads_at, mesh.points.size());
  }

  // per cycle: the loop nearest the most of its vertices, and how many; of an interface's
  // twins (the locator finds the first), the one turning as the cycle does
  std::vector<Vote> cycle_votes() const
  {
    std::vector<Vote> result;
    std::vector<std::size_t> votes(loops.loops.size());
    for(std::size_t c = 0; c < cycles.size(); ++c) {
      std::fill(votes.begin(), votes.end(), 0);
      for(std::size_t v : cycles[c])
        ++votes[locator->closest(xy[v], 2 * local_size[v]).loop];
      std::size_t l = std::size_t(std::max_element(votes.begin(), votes.end()) - votes.begin());
      const std::size_t count = votes[l];
      if(loops.loops[l].twin != none && (cycle_area(c) > 0) != loops.loops[l].is_outer) l = loops.loops[l].twin;
      result.emplace_back(l, count);
    }
    return result;
  }

  // whether cycle c follows the loop of its vote (cycle_votes()): nearest most of its
  // vertices, and turning the same way (the outer side of a piece of core along an outer
  // loop, a hole in the core around a hole)
  bool follows(std::size_t c, const Vote& vote) const
  {
    const bool same_turn = (cycle_area(c) > 0) == loops.loops[vote.first].is_outer;
    return same_turn && 2 * vote.second > cycles[c].size();
  }

  // Drops each piece of core at most two of its largest cells across (its area at most
  // 4 h^2) that follows no loop, or an outer loop a larger piece follows too: a few cells
  // left beyond a narrow passage or along a tapering channel, where refining leaves new such
  // pieces farther along as often as it joins them. The buffer of the other pieces fills
  // their place; where it cannot, the final check asks for finer cells there. A piece
  // holding one of `fixed_points` stays. True if any was dropped.
  bool drop_small_unmatched_pieces(const std::vector<Vote>& votes, const std::vector<std::size_t>& fixed_points)
  {
    std::vector<std::size_t> followed(cycles.size(), none), largest(loops.loops.size(), none);
    for(std::size_t c = 0; c < cycles.size(); ++c) {
      if(!follows(c, votes[c])) continue;
      followed[c] = votes[c].first;
      std::size_t& big = largest[votes[c].first];
      if(big == none || cycles[big].size() < cycles[c].size()) big = c;
    }
    std::vector<std::size_t> candidates;
    for(std::size_t c = 0; c < cycles.size(); ++c)
      if((followed[c] == none || largest[followed[c]] != c) && cycle_area(c) > 0 && is_small_piece(c))
        candidates.push_back(c);
    if(candidates.empty()) return false; // the common case: no pass over the whole mesh
    std::vector<char> fixed(mesh.points.size(), 0), seen(mesh.points.size(), 0);
    for(std::size_t v : fixed_points)
      if(v < fixed.size()) fixed[v] = 1;
    std::vector<char> drop(mesh.quads.size(), 0);
    for(std::size_t c : candidates)
      if(mark_piece(c, fixed, seen, drop)) ++report.dropped_core_pieces;
    std::size_t kept = 0;
    for(std::size_t q = 0; q < mesh.quads.size(); ++q)
      if(!drop[q]) mesh.quads[kept++] = mesh.quads[q];
    const bool dropped = kept < mesh.quads.size();
    mesh.quads.resize(kept);
    return dropped;
  }

  bool is_small_piece(std::size_t c) const
  {
    double h = 0;
    for(std::size_t v : cycles[c]) h = (std::max)(h, local_size[v]);
    return cycle_area(c) <= 4 * h * h * (1 + 1e-9);
  }

  // marks in `drop` the quads of the piece of core that cycle c bounds (it has no hole: it is
  // small), unless it holds a point marked in `fixed`; true if it marked them. `seen` marks
  // the vertices reached, shared by all pieces: they have none in common.
  bool mark_piece(std::size_t c, const std::vector<char>& fixed, std::vector<char>& seen, std::vector<char>& drop) const
  {
    std::vector<std::size_t> piece, stack = cycles[c];
    for(std::size_t v : stack) seen[v] = 1;
    while(!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      if(fixed[v]) return false;
      for(std::size_t q : (*quads_at)[v]) {
        piece.push_back(q);
        for(std::size_t w : mesh.quads[q])
          if(!seen[w]) { seen[w] = 1; stack.push_back(w); }
      }
    }
    for(std::size_t q : piece) drop[q] = 1;
    return true;
  }

  double cycle_area(std::size_t c) const
  {
    double a = 0;
    const auto& cyc = cycles[c];
    const Point_2d& o = xy[cyc[0]]; // relative to a vertex: far from the origin, absolute
                                       // coordinates would cancel
    for(std::size_t i = 0; i < cyc.size(); ++i)
      a += CGAL::determinant(xy[cyc[i]] - o, (xy[cyc[(i + 1) % cyc.size()]] - o));
    return a / 2;
  }

  void request_all(std::size_t c)
  {
    for(std::size_t v : cycles[c])
      requests.for_validity.emplace_back(xy[v], local_size[v]);
  }

  // Along the shortest segment between cycle `piece`, core cut off by a narrow passage, and
  // cycle `rest` on the same loop: cells half the distance to the boundary there (the
  // passage's half width), or a quarter of the gap if that is less, at least a level finer.
  void request_passage(std::size_t piece, std::size_t rest)
  {
    const std::pair<Point_2d, Point_2d> ends = nearest_approach(cycles[piece], cycles[rest]);
    const double gap = length_2d(ends.second - ends.first);
    for(double t : { 0.0, 0.25, 0.5, 0.75, 1.0 }) {
      const Point_2d p = along_2d(ends.first, ends.second, t);
      requests.for_validity.emplace_back(p, (std::min)(gap / 2, locator->closest(p, gap).dist));
    }
  }

  // the nearest pair of a vertex of `from` and one of `to`: a sweep over `to` in x order
  std::pair<Point_2d, Point_2d> nearest_approach(const std::vector<std::size_t>& from,
                                                 const std::vector<std::size_t>& to) const
  {
    std::vector<Point_2d> by_x;
    by_x.reserve(to.size());
    for(std::size_t v : to) by_x.push_back(xy[v]);
    std::sort(by_x.begin(), by_x.end(), [](const Point_2d& a, const Point_2d& b) { return a.x() < b.x(); });
    double best = std::numeric_limits<double>::infinity();
    std::pair<Point_2d, Point_2d> ends(xy[from.front()], by_x.front());
    for(std::size_t v : from) {
      const Point_2d& p = xy[v];
      const auto start = std::lower_bound(by_x.begin(), by_x.end(), p.x(),
                                          [](const Point_2d& a, double x) { return a.x() < x; });
      auto consider = [&](const Point_2d& q) {
        const double dx = q.x() - p.x();
        if(dx * dx >= best) return false; // and every point farther along in x
        const double d2 = (q - p).squared_length();
        if(d2 < best) { best = d2; ends = { p, q }; }
        return true;
      };
      for(auto it = start; it != by_x.end() && consider(*it); ++it) {}
      for(auto it = start; it != by_x.begin() && consider(*std::prev(it)); --it) {}
    }
    return ends;
  }

  // Whether a local move from `state` was made in this round or the last (see move_memo.h):
  // then true, with where it ended in `to` (a Point_2d, or Move_memo::Moves for a move of
  // several points). The state is hashed only where the rounds keep moves (`memo`):
  // `state_of()` gives it then.
  template <class State_of, class Result>
  bool recall_move(State_hash& state, const State_of& state_of, Result& to)
  {
    if(memo == nullptr) return false;
    state = state_of();
    if(!memo->find(state, to)) return false;
    ++report.moves_recalled;
    return true;
  }
  // records that the move searched from `state` (given by recall_move()) ended at `to`
  template <class Result>
  void record_move(const State_hash& state, const Result& to)
  {
    ++report.moves_searched;
    if(memo != nullptr) memo->insert(state, to);
  }

  // the traits' point at working position p: exactly p, whatever the kernel
  Point_2 mesh_point(const Point_2d& p) const
  {
    return traits.construct_point_2_object()(FT(p.x()), FT(p.y()));
  }

  std::size_t add_point(const Point_2d& p)
  {
    mesh.points.push_back(mesh_point(p));
    xy.push_back(p);
    return mesh.points.size() - 1;
  }

  void add_quad(const Quad& q) { mesh.quads.push_back(q); }

  // a new core point of local size `size` (the templates' new quads: the first buffer points
  // come after every core point)
  std::size_t add_core_point(const Point_2d& p, double size, bool on_boundary)
  {
    const std::size_t v = add_point(p);
    local_size.push_back(size);
    on_cycle_mark.push_back(on_boundary ? 1 : 0);
    fixed_mark.push_back(0);
    shaped_mark.push_back(0);
    cleared_xy.push_back(p);
    return v;
  }

  double input_corner_angle(std::size_t v) const
  {
    return v < corner_angle.size() ? corner_angle[v] : std::numeric_limits<double>::quiet_NaN();
  }

  // every input vertex on the chain has its corner angle
  bool is_input_vertex(std::size_t v) const { return !std::isnan(input_corner_angle(v)); }

  // An input vertex on an interface has a corner in each region about it (a and 360 - a
  // on an interface between two; more at a junction): the sharpest and the widest of them.
  // Elsewhere both are the corner's angle.
  double sharp_corner_angle(std::size_t v) const
  {
    return on_interface(v) ? interface_corners[v]->sharpest : input_corner_angle(v);
  }
  double wide_corner_angle(std::size_t v) const
  {
    return on_interface(v) ? interface_corners[v]->widest : input_corner_angle(v);
  }
  bool on_interface(std::size_t v) const { return v < interface_corners.size() && interface_corners[v] != nullptr; }

  // the corners of the domain about each input point on an interface
  void find_interface_corners()
  {
    for(std::size_t l = 0; l < loops.loops.size(); ++l)
      for(std::size_t k = 0; k < loops.loops[l].vertices.size(); ++k) {
        if(!on_edge_twin(loops.loops[l], k)) continue;
        const double a = loop_corner_angle(domain, loops.loops[l], k);
        auto [it, is_new] = corners_at_input.emplace(loops.loops[l].vertices[k], Interface_corners{ a, a, {} });
        Interface_corners& corners = it->second;
        corners.sharpest = (std::min)(corners.sharpest, a);
        corners.widest = (std::max)(corners.widest, a);
        if(a < 45.0) corners.under_45.push_back(a);
      }
  }

  // true if `angle`, a quad's angle at mesh vertex v, is forced: v is an input corner sharper
  // than 45 degrees and the quad spans all of it (a split corner has less). The quad's other
  // three angles are not. A corner over 270 degrees forces nothing: a fan of three quads
  // splits it within [45, 135]. On an interface, a quad spans one of the corners about v, so
  // its angle is forced only if it is one of the sharp ones.
  bool forced_angle(std::size_t v, double angle) const
  {
    const double alpha = sharp_corner_angle(v);
    if(!(alpha < 45.0)) return false; // false for NaN
    if(!on_interface(v)) return angle >= alpha - 1e-3;
    for(double a : interface_corners[v]->under_45)
      if(std::abs(angle - a) <= 1e-3) return true;
    return false;
  }

  // true if an input corner (a loop vertex turning by the feature angle or more) at an end of
  // the boundary edge nearest core vertex b lies within 2 h(b) of it: its buffer is the
  // corner's (§5), not Lemma 2's: the templates' plane searches, filled notches and split
  // corners leave b alone (moved there, b can fold the buffer quads beside the corner)
  bool near_input_corner(std::size_t b) const
  {
    const Loop_locator::Hit h = locator->closest(xy[b], 2 * local_size[b]);
    if(!(h.dist < 2 * local_size[b])) return false;
    const std::size_t nv = locator->loop(h.loop).size();
    for(std::size_t k : { h.edge, (h.edge + 1) % nv })
      if(is_feature(h.loop, k) && length_2d(locator->loop(h.loop)[k] - xy[b]) < 2 * local_size[b])
        return true;
    return false;
  }

  // Whether segment (a, b) keeps more than `clear` from every boundary segment, decided by
  // the kernel's exact Compare_squared_distance_2 on a and b as kernel points (the templates'
  // clearance of the core from the boundary). The locator's boxes, of the loops' vertices in
  // doubles, find the candidates: the query box is widened past their rounding.
  bool clear_of_boundary(const Point_2d& a, const Point_2d& b, double clear) const
  {
    const typename K::Segment_2 ab = traits.construct_segment_2_object()(mesh_point(a), mesh_point(b));
    const FT clear2 = FT(clear) * FT(clear);
    const auto compare = traits.compare_squared_distance_2_object();
    const auto segment = traits.construct_segment_2_object();
    // the boxes within `clear` of the segment's, widened past the rounding of its corners
    const double r = clear * (1 + 1e-6) + 4 * coordinate_rounding_2d(a, b);
    const Bbox_2 box((std::min)(a.x(), b.x()) - r, (std::min)(a.y(), b.y()) - r, (std::max)(a.x(), b.x()) + r, (std::max)(a.y(), b.y()) + r);
    bool clear_of = true;
    locator->edges_meeting(box, [&](std::size_t l, std::size_t k) {
      const auto& lv = loops.loops[l].vertices;
      if(clear_of && compare(ab, segment(domain.points[lv[k]], domain.points[lv[(k + 1) % lv.size()]]), clear2) != LARGER)
        clear_of = false;
    });
    return clear_of;
  }

  // the angle of loop l at its vertex k on the domain's side (the loops have it on their left)
  double domain_angle(std::size_t l, std::size_t k) const
  {
    const auto& loop_xy = locator->loop(l);
    const std::size_t nv = loop_xy.size();
    if(is_crack_tip(loops.loops[l], k)) return 360.0;
    return 360.0 - right_side_angle(loop_xy[(k + nv - 1) % nv], loop_xy[k], loop_xy[(k + 1) % nv]);
  }

  // the mesh point of input point `input`, or none if it has none yet
  std::size_t point_of_input(std::size_t input) const { return input < input_vertex.size() ? input_vertex[input] : none; }

  // the Slide of point v, or null if it does not slide on an input edge
  const Slide* slide(std::size_t v) const { return v < slide_of.size() && slide_of[v].loop != none ? &slide_of[v] : nullptr; }
  Slide* slide(std::size_t v) { return v < slide_of.size() && slide_of[v].loop != none ? &slide_of[v] : nullptr; }

  // a loop vertex the mesh must keep: it turns the boundary by the feature angle or more
  bool is_feature(std::size_t l, std::size_t k) const
  {
    const auto& v = locator->loop(l);
    const std::size_t nv = v.size();
    const double beta = right_side_angle(v[(k + nv - 1) % nv], v[k], v[(k + 1) % nv]);
    return std::abs(180.0 - beta) >= feature_angle;
  }

  // the mesh vertex of a chain node (an input vertex is added once, at its exact position)
  std::size_t input_vertex_point(std::size_t l, std::size_t k)
  {
    const std::size_t input = loops.loops[l].vertices[k];
    const std::size_t known = point_of_input(input);
    if(known != none) return known;
    mesh.points.push_back(domain.points[input]);
    xy.push_back(to_point_2d(domain.points[input]));
    const std::size_t id = mesh.points.size() - 1;
    input_vertex.resize((std::max)(input_vertex.size(), input + 1), none);
    input_vertex[input] = id;
    corner_angle.resize(id + 1, std::numeric_limits<double>::quiet_NaN());
    corner_angle[id] = loop_corner_angle(domain, loops.loops[l], k);
    if(const auto it = corners_at_input.find(input); it != corners_at_input.end()) {
      interface_corners.resize(id + 1, nullptr);
      interface_corners[id] = &it->second;
    }
    return id;
  }

  std::size_t point_on_edge(std::size_t l, std::size_t edge, double t)
  {
    const auto& lv = loops.loops[l].vertices;
    const Point_2& a = domain.points[lv[edge]];
    const Point_2& b = domain.points[lv[(edge + 1) % lv.size()]];
    mesh.points.push_back(point_between(a, b, t));
    xy.push_back(to_point_2d(mesh.points.back()));
    slide_of.resize(mesh.points.size(), Slide{ none, none, { none, none } });
    slide_of.back() = Slide{ l, edge, { none, none } };
    return mesh.points.size() - 1;
  }

  // a + t (b - a), on the line through a and b exactly under exact constructions
  Point_2 point_between(const Point_2& a, const Point_2& b, double t) const
  {
    auto x = traits.compute_x_2_object();
    auto y = traits.compute_y_2_object();
    const FT ft(t);
    return traits.construct_point_2_object()(x(a) + ft * (x(b) - x(a)), y(a) + ft * (y(b) - y(a)));
  }

  // a quad's cost, its largest deviation from 90 degrees (quad_badness()), judged without the
  // angle an input corner forces
  double quad_cost(const Quad& q) const { return quad_deviation(q).in_degrees(); }

  // quad_cost() with its arcsine deferred (the optimiser's inner loop compares costs)
  Deviation quad_deviation(const Quad& q) const
  {
    std::array<Point_2d, 4> P;
    for(int k = 0; k < 4; ++k) P[k] = xy[q[k]];
    const double c = quad_worst_cos(P);
    if(c >= 1000.0)
      return Deviation::degrees(c);
    // an angle an input corner alpha forces is not the strip's fault: the quad is judged by its
    // other three against [45, 135], not the paper's looser [alpha, 180 - alpha]. They fit
    // there for any alpha (they sum to 360 - alpha: 120 each, say).
    for(int k = 0; k < 4; ++k)
      if(sharp_corner_angle(q[k]) < 45.0 // cheap test first: the cost runs in inner loops
         && forced_angle(q[k], corner_angle_degrees(P[(k + 3) % 4], P[k], P[(k + 1) % 4]))) {
        double b = 0;
        for(int j = 0; j < 4; ++j)
          if(j != k) b = (std::max)(b, std::abs(corner_angle_degrees(P[(j + 3) % 4], P[j], P[(j + 1) % 4]) - 90.0));
        return Deviation::degrees(b);
      }
    return Deviation::of_cos(c);
  }

  // the sum over a quad's corners outside [45, 135] of the square of their excess, but for
  // an angle an input corner forces: it tells apart moves that leave the worst angle as it is
  double quad_excess(const Quad& q) const
  {
    double sum = 0;
    for(int k = 0; k < 4; ++k) {
      const double a = corner_angle_degrees(xy[q[(k + 3) % 4]], xy[q[k]], xy[q[(k + 1) % 4]]);
      const double excess = std::abs(a - 90.0) - 45.0;
      if(excess > 0 && !forced_angle(q[k], a)) sum += excess * excess;
    }
    return sum;
  }

  // strictly convex and counter-clockwise by the kernel's predicate, and no corner nearly flat
  // (the quality check rejects those)
  bool is_valid_quad(const Quad& Q) const
  {
    auto orient = traits.orientation_2_object();
    for(int c = 0; c < 4; ++c)
      if(orient(mesh.points[Q[c]], mesh.points[Q[(c + 1) % 4]], mesh.points[Q[(c + 2) % 4]]) != CGAL::LEFT_TURN)
        return false;
    for(int c = 0; c < 4; ++c)
      if(!(corner_scaled_jacobian(xy[Q[(c + 3) % 4]], xy[Q[c]], xy[Q[(c + 1) % 4]]) > 1e-9))
        return false;
    return true;
  }

  /// Drops the points no quad uses (boundary nodes the pairing took out again); returns the
  /// new index of every old point (`none` for a dropped one).
  std::vector<std::size_t> remove_unused_points()
  {
    std::vector<std::size_t> index(mesh.points.size(), none);
    for(const Quad& q : mesh.quads)
      for(std::size_t v : q) index[v] = 0;
    std::size_t next = 0;
    for(std::size_t v = 0; v < index.size(); ++v)
      if(index[v] == 0) {
        mesh.points[next] = mesh.points[v];
        index[v] = next++;
      }
    mesh.points.resize(next);
    for(Quad& q : mesh.quads)
      for(std::size_t& v : q) v = index[v];
    return index;
  }

  // `targets`: for each quad at v, where v would make it a parallelogram (the corners beside v
  // plus one side); returns the mean of those corners, v's neighbours (a Laplacian step)
  Point_2d parallelogram_targets(std::size_t v, const Vertex_quads& quads_at, std::vector<Point_2d>& targets) const
  {
    targets.clear();
    Vector_2d lap = NULL_VECTOR;
    for(std::size_t q : quads_at[v]) {
      const Quad& Q = mesh.quads[q];
      const int c = corner_of(Q, v);
      const Point_2d& prev = xy[Q[(c + 3) % 4]];
      const Point_2d& next = xy[Q[(c + 1) % 4]];
      const Point_2d& opp = xy[Q[(c + 2) % 4]];
      targets.push_back(Point_2d(prev.x() + next.x() - opp.x(), prev.y() + next.y() - opp.y()));
      lap = lap + ((prev - ORIGIN) + (next - ORIGIN));
    }
    const int corners = 2 * int(quads_at[v].size());
    return ORIGIN + lap / corners;
  }

  Mesh& mesh;
  std::vector<double> local_size; // per core point: the side of its largest quadtree cell
  const Domain_2<K>& domain;
  const Domain_loops_2<K>& loops;
  K traits;
  std::unique_ptr<Loop_locator> locator;
  // the quads at each vertex from match_loops() to apply_boundary_templates(), which add none
  std::unique_ptr<Vertex_quads> quads_at;
  std::vector<Point_2d> xy;
  std::vector<Point_2d> cleared_xy; // xy before apply_boundary_templates(), until apply_connectivity_templates()
  std::vector<std::vector<std::size_t>> cycles;
  std::vector<std::size_t> cycle_loop;
  std::vector<std::vector<Point_2d>> first_points; // per cycle: its first buffer points (buffer1 on)
  std::vector<std::size_t> first_base; // per cycle: the mesh index of its first buffer point
  std::vector<std::vector<std::size_t>> loop_chain; // per loop: its boundary chain's mesh ids (buffer2 on)
  std::vector<std::size_t> first_core; // core vertex of each first buffer point
  std::vector<std::size_t> input_vertex; // per input point: its mesh point, or none
  std::vector<double> corner_angle; // per mesh point: its input corner's angle, or NaN
  // the corners of the domain about an input point on an interface, one in each region
  // about it: the sharpest, the widest, and those under 45 degrees
  struct Interface_corners { double sharpest, widest; std::vector<double> under_45; };
  std::unordered_map<std::size_t, Interface_corners> corners_at_input; // by input point (its nodes stay put)
  std::vector<const Interface_corners*> interface_corners; // per mesh point: its input point's, or null
  std::vector<Slide> slide_of; // per point: its Slide (loop none: it does not slide; see slide())
  std::vector<char> on_cycle_mark; // per core point
  std::vector<char> repaired_mark; // per point
  std::vector<char> fixed_mark;    // per core point: a domain's isolated point, which never moves
  std::vector<char> shaped_mark;   // per core point: an interior one the templates moved
  Move_memo* memo = nullptr; // the moves of this round and the last, if the rounds keep them
  bool first_built = false;
  std::size_t core_points = 0;
  // the first quad of the first buffer layer and of the second (the core's come before)
  std::array<std::size_t, 2> layer_begin{ { std::size_t(-1), std::size_t(-1) } };
  double feature_angle = loop_feature_angle; // turning (degrees) that makes a loop vertex a corner
  double chord_tolerance = 0;   // how far the mesh boundary may leave the input's
  Buffer_report report;
  Refinement_requests requests;
};

} // namespace internal
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_INTERNAL_BUFFER_ZONE_H
