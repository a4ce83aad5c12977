// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H
#define CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H

#include <CGAL/Quad_mesher_2/Balanced_quadtree_2.h>
#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/Mesh_criteria_2.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Point_anchor.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/angle_rounds.h>
#include <CGAL/Quad_mesher_2/internal/apply_templates.h>
#include <CGAL/Quad_mesher_2/internal/boundary_sizing.h>
#include <CGAL/Quad_mesher_2/internal/buffer_layers.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone_clearance.h>
#include <CGAL/Quad_mesher_2/internal/insert_points.h>
#include <CGAL/Quad_mesher_2/internal/nearest_neighbor_distances.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {

/// \ingroup PkgQuadMesher2Ref
/// The stages of the pipeline, in order; a mesher can stop after any of them.
enum class Stage
{
  QUADTREE, ///< strongly balanced adaptive quadtree with 2-refinement templates (paper Fig. 3(b))
  POINTS,   ///< every input point of a point cloud, or isolated point of a domain, moved onto a
            ///< mesh vertex (paper §3, Lemma 1)
  CLEARANCE, ///< domains only: quads outside, crossing or too near the boundary removed, leaving
             ///< the core mesh and an empty buffer zone (paper §4.3, Fig. 3(c))
  TEMPLATES, ///< domains only: notches of the core boundary opened (moved, or covered by a new
             ///< quad) and its convex corners cut so that every boundary angle is in
             ///< [112.5°, 225°] where the core allows (paper §4.4)
  BUFFER1,   ///< domains only: the first buffer layer, on angle bisectors (paper §4.5)
  BUFFER2    ///< domains only: the second buffer layer, reaching the boundary; the whole domain
             ///< is meshed and every boundary vertex is a mesh vertex (paper §4.6)
};

/// \ingroup PkgQuadMesher2Ref
/// the name of a stage as the command-line tool spells it
inline const char* stage_name(Stage s)
{
  switch(s) {
  case Stage::QUADTREE: return "quadtree";
  case Stage::POINTS: return "points";
  case Stage::CLEARANCE: return "clearance";
  case Stage::TEMPLATES: return "templates";
  case Stage::BUFFER1: return "buffer1";
  case Stage::BUFFER2: return "buffer2";
  }
  return "?";
}

/// \ingroup PkgQuadMesher2Ref
/// the last stage `domain` has, which `make_quad_mesh_2()` and `Quadtree_mesher_2::run()` run
/// to by default, as the command-line tool does: `Stage::POINTS` for a point cloud,
/// `Stage::BUFFER2` (the whole domain meshed) for a domain bounded by segments
template <class GeomTraits>
Stage last_stage(const Domain_2<GeomTraits>& domain)
{
  return domain.is_point_cloud() ? Stage::POINTS : Stage::BUFFER2;
}

/// \ingroup PkgQuadMesher2Ref
/// The mesher, stage by stage (the role `Delaunay_mesher_2` plays in Mesh_2). Each stage
/// records its wall-clock time in `timings()`.
///
/// \tparam GeomTraits a model of `QuadMesherTraits_2`
template <class GeomTraits>
class Quadtree_mesher_2
{
public:
  typedef GeomTraits Geom_traits;
  typedef typename GeomTraits::FT FT;
  typedef typename GeomTraits::Point_2 Point_2;
  typedef Balanced_quadtree_2<GeomTraits> Quadtree;
  typedef Quad_mesh_2<Point_2> Mesh;
  typedef std::vector<std::pair<std::string, double>> Timings;

  /// Keeps a reference to `domain`, which must outlive the mesher.
  Quadtree_mesher_2(const Domain_2<GeomTraits>& domain,
                    const Mesh_criteria_2<GeomTraits>& criteria = Mesh_criteria_2<GeomTraits>(),
                    const GeomTraits& traits = GeomTraits())
    : m_domain(domain), m_criteria(criteria), m_traits(traits)
  {}
  /// A temporary domain would not outlive the mesher.
  Quadtree_mesher_2(Domain_2<GeomTraits>&& domain,
                    const Mesh_criteria_2<GeomTraits>& criteria = Mesh_criteria_2<GeomTraits>(),
                    const GeomTraits& traits = GeomTraits()) = delete;

  /// Stage 1: merges duplicate input points, refines the quadtree by the criteria (and, with
  /// `points_as_vertices()`, around every input point), then strongly balances it.
  void build_quadtree()
  {
    auto start = std::chrono::steady_clock::now();
    if(m_domain.points.empty())
      throw Meshing_error("the input has no points");
    check_finite();
    merge_duplicate_points();
    if(!m_domain.is_point_cloud())
      m_loops = extract_loops(m_domain, m_traits); // validates the boundary first
    const auto box = points_box();
    m_box = CGAL::Bbox_2(CGAL::to_double(m_traits.compute_xmin_2_object()(box)),
                         CGAL::to_double(m_traits.compute_ymin_2_object()(box)),
                         CGAL::to_double(m_traits.compute_xmax_2_object()(box)),
                         CGAL::to_double(m_traits.compute_ymax_2_object()(box)));
    // Below this, sizes and steps along the boundary underflow to subnormal doubles or zero
    // (a square 5e-324 across looped for ever in the narrow-region search).
    const double extent = (std::max)(m_box.xmax() - m_box.xmin(), m_box.ymax() - m_box.ymin());
    if(extent > 0 && extent < min_extent) {
      std::ostringstream msg;
      msg << "the input's extent " << extent << " is too small to mesh (under " << min_extent
          << "); scale the input";
      throw Meshing_error(msg.str());
    }
    // the whole-mesh check counts vertices closer than 1e-9 of the diagonal as duplicates, and
    // the buffer puts vertices a quarter cell apart: finer cells make a mesh that cannot pass
    // (a point cloud has no buffer, and its points are its finest vertices)
    const double finest_side = m_domain.is_point_cloud()
                                 ? 0.0
                                 : 4e-9 * std::hypot(m_box.xmax() - m_box.xmin(), m_box.ymax() - m_box.ymin());
    m_tree = std::make_unique<Quadtree>(bounding_box(box), m_criteria.max_depth(), m_traits, finest_side);
    m_tree->set_max_leaves(m_criteria.max_cells());
    compute_point_spacing();
    refine_to_max_size();
    if(m_criteria.use_point_spacing())
      refine_to_point_spacing();
    if(m_criteria.sizing_field())
      refine_to_sizing_field();
    if(!m_domain.is_point_cloud() && m_criteria.resolve_narrow_regions())
      refine_narrow_regions();
    refine_at_requests();
    if(!m_domain.is_point_cloud())
      refine_boundary_band();
    record("refine", start);
    start = std::chrono::steady_clock::now();
    if(m_criteria.points_as_vertices()) {
      // a point cloud's points, or a domain's isolated points: boundary vertices are for the
      // buffer layers
      std::vector<std::size_t> chosen;
      if(m_domain.is_point_cloud()) {
        for(std::size_t i = 0; i < m_points.size(); ++i)
          chosen.push_back(i);
      } else {
        std::vector<std::size_t> unique_of(m_domain.points.size(), std::size_t(-1));
        for(std::size_t i = 0; i < m_points.size(); ++i)
          unique_of[m_input_index[i]] = i;
        for(std::size_t v : m_loops.isolated_points)
          if(unique_of[v] != std::size_t(-1))
            chosen.push_back(unique_of[v]);
      }
      std::vector<int> levels;
      std::vector<std::size_t> names;
      m_anchored_points.clear();
      for(std::size_t i : chosen) {
        levels.push_back(point_level(i, 1));
        names.push_back(m_input_index[i]);
        m_anchored_points.push_back(m_points[i]);
      }
      m_anchors = internal::anchor_points(*m_tree, m_anchored_points, levels,
                                          [&](std::size_t i) { return input_point_name(names[i]); });
      m_point_names = std::move(names);
    } else {
      m_tree->balance();
    }
    record("balance", start);
  }

  /// The conforming all-quad mesh of the whole balanced tree: every leaf replaced by its
  /// 2-refinement template. Every angle is 45, 90 or 135 degrees.
  Mesh core_mesh()
  {
    CGAL_precondition(m_tree != nullptr);
    auto start = std::chrono::steady_clock::now();
    Mesh mesh = internal::templated_mesh(*m_tree, &m_quad_cells, &m_vertex_keys);
    record("refinement_templates", start);
    return mesh;
  }

  /// Stage 2 (needs `points_as_vertices()`): moves a vertex of `mesh`, the result of
  /// `core_mesh()`, onto every input point, and its neighbours so that every angle stays in
  /// [45°, 135°] (in fact [72°, 116°] near the points) and the quads at each point have an
  /// aspect ratio of at most 1.5 (Lemma 1).
  void insert_points(Mesh& mesh)
  {
    CGAL_precondition(m_tree != nullptr && m_criteria.points_as_vertices());
    auto start = std::chrono::steady_clock::now();
    m_point_vertices = internal::move_anchors(*m_tree, mesh, m_vertex_keys, m_anchors, m_anchored_points);
    record("points", start);
  }

  /// Stage 3 (domains only, paper §4.3): removes the quads of `mesh`, the result of
  /// `core_mesh()` (and `insert_points()`), that lie outside the domain, cross its boundary
  /// or have a vertex within half their size of it, then single elements and pinches, so that
  /// the rest, the core mesh, has simple closed boundary loops.
  void clear_buffer_zone(Mesh& mesh)
  {
    CGAL_precondition(m_tree != nullptr);
    if(m_domain.is_point_cloud())
      throw Meshing_error("the clearance stage needs a domain bounded by segments, not a point cloud");
    auto start = std::chrono::steady_clock::now();
    std::vector<double> quad_size(m_quad_cells.size());
    for(std::size_t q = 0; q < quad_size.size(); ++q)
      quad_size[q] = m_tree->cell_side(m_quad_cells[q].level);
    auto result = internal::clear_buffer_zone(std::move(mesh), quad_size, m_domain, m_loops, m_traits);
    m_core_vertex_size.assign(result.core.points.size(), 0.0);
    for(std::size_t q = 0; q < result.core.quads.size(); ++q)
      for(int c = 0; c < 4; ++c) {
        double& s = m_core_vertex_size[result.core.quads[q][c]];
        s = (std::max)(s, quad_size[result.core_to_input_quad[q]]);
      }
    m_removed = { result.removed_outside, result.removed_intersecting, result.removed_near,
                  result.removed_single };
    for(std::size_t& v : m_point_vertices)
      v = result.core_vertex[v];
    mesh = std::move(result.core);
    // An isolated point too near the boundary for its cells loses its quads here, or ends on
    // the core's boundary, which the buffer stages move: run() refines there (lost_points()).
    m_lost_points.clear();
    if(!m_point_vertices.empty()) {
      std::vector<char> on_boundary(mesh.points.size(), 0);
      for(const auto& cycle : internal::mesh_boundary_cycles(mesh.quads, mesh.points.size()))
        for(std::size_t v : cycle) on_boundary[v] = 1;
      for(std::size_t i = 0; i < m_point_vertices.size(); ++i)
        if(m_point_vertices[i] == std::size_t(-1) || on_boundary[m_point_vertices[i]] != 0)
          m_lost_points.push_back(i);
    }
    record("clearance", start);
  }

  /// Stages 4 to 6 (domains only, paper §4.4-§4.6) on `mesh`, the result of
  /// `clear_buffer_zone()`, up to `last`: opens the core's notches and cuts its corners, then
  /// adds the first buffer layer and the second, which reaches the boundary. Returns `false`
  /// if the quadtree should be finer somewhere (see `refinement_requests()`): a buffer quad
  /// would be invalid, or have an angle outside [45°, 135°] that no input corner forces.
  bool fill_buffer_zone(Mesh& mesh, Stage last = Stage::BUFFER2)
  {
    CGAL_precondition(m_tree != nullptr && !m_domain.is_point_cloud());
    auto start = std::chrono::steady_clock::now();
    internal::Buffer_layers<GeomTraits> layers(mesh, m_core_vertex_size, m_domain, m_loops, m_traits);
    bool ok = layers.match_loops();
    if(ok && last >= Stage::TEMPLATES) {
      layers.apply_boundary_templates(m_point_vertices);
      layers.apply_connectivity_templates();
    }
    if(ok && last >= Stage::BUFFER1)
      layers.build_first_layer();
    if(ok && last >= Stage::BUFFER2)
      layers.build_second_layer();
    ok = ok && layers.report().failure.empty();
    if(ok && last >= Stage::BUFFER2)
      layers.optimize(m_point_vertices);
    if(ok)
      layers.check_quads();
    const std::vector<std::size_t> index = layers.remove_unused_points();
    for(std::size_t& v : m_point_vertices)
      v = v < index.size() ? index[v] : v; // a lost point (see lost_points()) stays lost
    m_buffer_report = layers.report();
    m_buffer_requests = layers.requests();
    record("buffer", start);
    return ok && m_buffer_report.invalid_quads == 0 && m_buffer_report.bad_angle_quads == 0;
  }

  /// Runs every stage the input has (up to `last_stage(domain)`: the whole domain, or a point
  /// cloud's points made vertices) and returns the mesh; see `run(Stage)`.
  Mesh run() { return run(last_stage(m_domain)); }

  /// Runs the stages up to `last` and returns the mesh. Beyond the clearance, where the buffer
  /// layers would have invalid quads the quadtree is refined there and the stages run again,
  /// at most `max_refinement_rounds` times in all; a mesh with invalid quads is never
  /// returned. Where a valid buffer has angles outside [45°, 135°] that no input corner
  /// forces, the quadtree is refined there, round after round while their count falls and in
  /// at most `max_stalled_angle_rounds` valid rounds that do not lower it; a round the angle refinement made invalid is
  /// refined for validity first. The valid round with the fewest such quads is the one
  /// returned (kept from its round if a later one was worse). The rounds end too once the
  /// refinement a round asked for splits no cell (finer cells are refused there): the next
  /// round would repeat it.
  Mesh run(Stage last)
  {
    m_extra_refinement.clear();
    m_requests_applied = 0;
    m_round_figures.clear();
    m_quality.reset();
    m_rounds_end = Rounds_end::NONE;
    internal::Angle_rounds angle_rounds(max_stalled_angle_rounds);
    // the best valid round's mesh and state, kept while later rounds try for better angles:
    // building it again would cost a whole round
    Round_state best;
    // the error that ends the rounds if the next one repeats the last, an invalid one
    std::string repeat_error;
    for(m_rounds = 1;; ++m_rounds) {
      const auto round_start = std::chrono::steady_clock::now();
      build_quadtree();
      // Each round builds the quadtree anew, the same way, with the requests of every round
      // before it: if the last round's requests split no cell (finer cells refused), this
      // round repeats the last, figure for figure, and so would every round after it, to the
      // budget (a 128-gon hole 1e-7 from the side of a square repeated its seventh round nine
      // times, 27 s each). The last round's outcome is final: an invalid one ends here (its
      // mesh is not kept, nor needed); a valid one is run again and kept, or not, as usual.
      const bool repeats = m_rounds > 1 && !m_requests_refined;
      if(repeats && !repeat_error.empty()) {
        --m_rounds;
        m_rounds_end = Rounds_end::FINEST_CELLS;
        if(angle_rounds.has_valid_round())
          return restore_round(std::move(best));
        throw Meshing_error(repeat_error);
      }
      Mesh mesh = core_mesh();
      if(last >= Stage::POINTS && m_criteria.points_as_vertices())
        insert_points(mesh);
      if(last >= Stage::CLEARANCE)
        clear_buffer_zone(mesh);
      if(!m_lost_points.empty()) { // cells a quarter of the point's distance to the boundary
        const auto locator = internal::make_loop_locator(m_domain, m_loops);
        std::vector<std::pair<internal::Point_2d, double>> requests;
        for(std::size_t i : m_lost_points) {
          const internal::Point_2d p = internal::to_point_2d(m_anchored_points[i]);
          requests.emplace_back(p, locator->closest(p, m_tree->cell_side(m_tree->depth())).dist / 2);
        }
        if(queue_refinement(requests) > 0 && m_rounds < max_refinement_rounds) {
          repeat_error = lost_point_error(requests);
          continue;
        }
        m_rounds_end = m_rounds < max_refinement_rounds ? Rounds_end::FINEST_CELLS : Rounds_end::ROUND_BUDGET;
        if(angle_rounds.has_valid_round())
          return restore_round(std::move(best));
        throw Meshing_error(lost_point_error(requests));
      }
      if(last <= Stage::CLEARANCE)
        return mesh;
      fill_buffer_zone(mesh, last);
      // the whole mesh is checked too: a buffer node on another quad's edge would hang
      const auto check_start = std::chrono::steady_clock::now();
      std::vector<internal::Point_2d> flawed; // near-duplicate vertices and hanging nodes
      const Mesh_quality_2& quality = *(m_quality = internal::compute_quality(mesh, &flawed));
      record("check", check_start);
      const bool valid = m_buffer_report.failure.empty() && m_buffer_report.invalid_quads == 0
                         && quality.is_valid() && quality.number_of_near_duplicate_vertices == 0;
      // refined for validity first; for angles only once a round is valid
      std::vector<std::pair<internal::Point_2d, double>> requests =
        valid ? m_buffer_requests.for_angles : m_buffer_requests.for_validity;
      // Buffer nodes of two loops met across a narrow gap (a node on another's edge, or
      // nearly on another node): the buffer's own checks do not see them, and without a
      // request there the rounds ended, keeping an earlier round's angles out (the 30P30N
      // turned 11 degrees and scaled by 1.37). One level finer there, as for a bad quad.
      for(const internal::Point_2d& p : flawed)
        requests.emplace_back(p, 0.0);
      m_round_figures.push_back({ m_rounds, mesh.quads.size(), m_buffer_report.invalid_quads,
                                  m_buffer_report.bad_angle_quads, m_buffer_report.bad_angle_quads_by_layer, valid, requests.size(),
                                  std::chrono::duration<double>(std::chrono::steady_clock::now() - round_start).count() });
      if(m_round_observer)
        m_round_observer(m_round_figures.back());
      // a stage on its way is not refined for angles: they are the finished buffer's
      if(valid && (m_buffer_report.bad_angle_quads == 0 || last < Stage::BUFFER2))
        return mesh;
      const bool improved = angle_rounds.record(valid, m_buffer_report.bad_angle_quads);
      const std::size_t added = queue_refinement(requests);
      // an angle round that came out invalid is refined for validity, within the round budget
      if(added > 0 && m_rounds < max_refinement_rounds && angle_rounds.go_on() && !repeats) {
        if(improved)
          best = save_round(std::move(mesh));
        // should the next round repeat this one, it fails as this one would fail now
        repeat_error = valid ? std::string() : buffer_error(requests, true);
        continue;
      }
      m_rounds_end = added == 0 || repeats                ? Rounds_end::FINEST_CELLS
                     : m_rounds >= max_refinement_rounds ? Rounds_end::ROUND_BUDGET
                                                         : Rounds_end::STALLED;
      if(valid && m_buffer_report.bad_angle_quads == angle_rounds.best())
        return mesh; // angles outside [45, 135] stay; the quality report shows them
      if(angle_rounds.has_valid_round())
        return restore_round(std::move(best));
      // not the round budget
      throw Meshing_error(buffer_error(requests, added < requests.size() || m_tree->depth() >= m_tree->max_depth()));
    }
  }

  /// the whole-mesh check of the mesh the last `run()` returned (its `compute_quality()`),
  /// made there for runs past the clearance; empty after shorter runs
  const std::optional<Mesh_quality_2>& quality() const { return m_quality; }
  /// how many times `run()` built the quadtree (1 + refinement rounds for the buffer layers)
  int rounds() const { return m_rounds; }
  /// why the refinement rounds of the last `run()` ended, if they left quads with an angle
  /// outside [45°, 135°] that no input corner forces (or gave up on an invalid round)
  enum class Rounds_end
  {
    NONE,         ///< they did not end that way: no such quad, or a run stopped before `BUFFER2`
    STALLED,      ///< `max_stalled_angle_rounds` valid rounds did not lower the count of such quads
    ROUND_BUDGET, ///< the quadtree was built `max_refinement_rounds` times
    FINEST_CELLS  ///< the cells asked for are finer than the quadtree may make (its depth)
  };
  Rounds_end rounds_end() const { return m_rounds_end; }
  /// what one round of `run()` past the clearance found: how it went decides the next
  struct Round_figures
  {
    int round = 0;                    ///< its number among the rounds of `run()` (see `rounds()`)
    std::size_t quads = 0;
    std::size_t invalid_quads = 0;    ///< buffer quads not strictly convex
    std::size_t bad_angle_quads = 0;  ///< buffer quads with an angle out that no input corner forces
    /// of those, the core's (changed by the templates), the first layer's and the second's
    std::array<std::size_t, 3> bad_angle_quads_by_layer{ { 0, 0, 0 } };
    bool valid = false;               ///< the whole mesh passed its check
    std::size_t refinement_requests = 0; ///< places it asked to be finer (for validity, or angles once valid)
    double seconds = 0;               ///< its wall-clock time, from the quadtree to the whole-mesh check
  };
  /// the rounds of the last `run()` past the clearance, in order (the one returned may be an
  /// earlier one than the last: see `run()`)
  const std::vector<Round_figures>& round_figures() const { return m_round_figures; }
  /// called by `run()` as each round past the clearance ends, with its figures (the entry it
  /// has just added to `round_figures()`), before it decides whether to refine again
  typedef std::function<void(const Round_figures&)> Round_observer;
  /// sets the round observer (an empty one, the default, is not called): rounds can take
  /// minutes each on a hard input, and `round_figures()` is read only after `run()` returns
  void set_round_observer(Round_observer observer) { m_round_observer = std::move(observer); }
  /// what the buffer stages did in the last round
  const Buffer_report& buffer_report() const { return m_buffer_report; }
  static constexpr int max_refinement_rounds = 16;
  /// valid rounds refined for angles that did not lower their count, at most
  static constexpr int max_stalled_angle_rounds = 3;

  /// quads removed by the clearance: outside, crossing the boundary, near it, single
  const std::array<std::size_t, 4>& removed_by_clearance() const { return m_removed; }
  /// after `clear_buffer_zone()`: the isolated points (indices into `anchored_points()`) whose
  /// vertex the clearance removed or left on the core's boundary; `run()` refines around them
  const std::vector<std::size_t>& lost_points() const { return m_lost_points; }
  /// the points made vertices: a point cloud's, or a domain's isolated points
  const std::vector<Point_2>& anchored_points() const { return m_anchored_points; }

  /// the input points without exact duplicates, in input order
  const std::vector<Point_2>& points() const { return m_points; }
  /// the validated, oriented boundary loops (empty for a point cloud)
  const Domain_loops_2<GeomTraits>& loops() const { return m_loops; }
  /// for each point of `points()`, its index in the domain's points
  const std::vector<std::size_t>& input_indices() const { return m_input_index; }
  /// how many input points were exact duplicates of an earlier one (merged)
  std::size_t number_of_merged_points() const { return m_domain.points.size() - m_points.size(); }
  /// for each point of `anchored_points()`, its vertex in the mesh (after `insert_points()`)
  const std::vector<std::size_t>& point_vertices() const { return m_point_vertices; }
  /// for each point of `anchored_points()`, the lattice vertex it moves and its tent (after
  /// `build_quadtree()`)
  const std::vector<Point_anchor>& anchors() const { return m_anchors; }

  const Quadtree& quadtree() const
  {
    CGAL_precondition(m_tree != nullptr);
    return *m_tree;
  }
  const Timings& timings() const { return m_timings; }
  const Mesh_criteria_2<GeomTraits>& criteria() const { return m_criteria; }

private:
  // what run() returns and the accessors show of one round
  struct Round_state
  {
    Mesh mesh;
    std::unique_ptr<Quadtree> tree;
    std::vector<Point_anchor> anchors;
    std::vector<Key_code> vertex_keys;
    std::vector<Cell_key> quad_cells;
    std::vector<Point_2> anchored_points;
    std::array<std::size_t, 4> removed{ { 0, 0, 0, 0 } };
    std::vector<std::size_t> point_vertices;
    std::vector<double> core_vertex_size;
    Buffer_report buffer_report;
    std::optional<Mesh_quality_2> quality;
  };

  // takes the current round's state (the next round builds its own)
  Round_state save_round(Mesh&& mesh)
  {
    Round_state r;
    r.mesh = std::move(mesh);
    r.tree = std::move(m_tree);
    r.anchors = std::move(m_anchors);
    r.vertex_keys = std::move(m_vertex_keys);
    r.quad_cells = std::move(m_quad_cells);
    r.anchored_points = std::move(m_anchored_points);
    r.removed = m_removed;
    r.point_vertices = std::move(m_point_vertices);
    r.core_vertex_size = std::move(m_core_vertex_size);
    r.buffer_report = std::move(m_buffer_report);
    r.quality = std::move(m_quality);
    return r;
  }

  Mesh restore_round(Round_state&& r)
  {
    m_tree = std::move(r.tree);
    m_anchors = std::move(r.anchors);
    m_vertex_keys = std::move(r.vertex_keys);
    m_quad_cells = std::move(r.quad_cells);
    m_anchored_points = std::move(r.anchored_points);
    m_removed = r.removed;
    m_point_vertices = std::move(r.point_vertices);
    m_core_vertex_size = std::move(r.core_vertex_size);
    m_buffer_report = std::move(r.buffer_report);
    m_quality = std::move(r.quality);
    return std::move(r.mesh);
  }

  // why the last round's buffer is invalid, where, and after how many rounds; `refused`: the
  // quadtree refused finer cells there
  std::string buffer_error(const std::vector<std::pair<internal::Point_2d, double>>& requests, bool refused) const
  {
    std::ostringstream msg;
    msg << "the buffer layers could not be built";
    if(!m_buffer_report.failure.empty())
      msg << ": " << m_buffer_report.failure;
    else if(m_buffer_report.invalid_quads > 0)
      msg << ": " << m_buffer_report.invalid_quads << " buffer quads are not convex";
    else
      msg << ": the mesh has a hanging node, a non-manifold edge or two vertices closer than 1e-9 of its diagonal";
    if(!requests.empty())
      msg << ", near (" << requests.front().first.x << ", " << requests.front().first.y << ")";
    msg << ", after " << m_rounds << " refinement rounds";
    if(refused)
      msg << "; finer cells are refused there: " << m_tree->depth_limit();
    return msg.str();
  }

  // the first isolated point the last round lost (see lost_points()), `requests` the
  // refinement asked around each
  std::string lost_point_error(const std::vector<std::pair<internal::Point_2d, double>>& requests) const
  {
    std::ostringstream msg;
    msg << "isolated point " << input_point_name(m_point_names[m_lost_points.front()]) << " (" << requests.front().first.x
        << ", " << requests.front().first.y << ") lies " << 2 * requests.front().second
        << " from the boundary: cells small enough to keep it a vertex inside the core are beyond the "
        << "quadtree's depth or its refinement rounds (" << m_rounds << ")";
    return msg.str();
  }

  void record(const std::string& stage, std::chrono::steady_clock::time_point start)
  {
    std::chrono::duration<double> d = std::chrono::steady_clock::now() - start;
    m_timings.emplace_back(stage, d.count());
  }

  // input point i as messages name it: its label, or its 0-based index marked so
  std::string input_point_name(std::size_t i) const
  {
    return m_domain.point_label(i) + (m_domain.point_labels.empty() ? " (0-based)" : "");
  }

  void check_finite() const
  {
    for(std::size_t i = 0; i < m_domain.points.size(); ++i) {
      const Point_2& p = m_domain.points[i];
      double x = CGAL::to_double(m_traits.compute_x_2_object()(p));
      double y = CGAL::to_double(m_traits.compute_y_2_object()(p));
      if(!std::isfinite(x) || !std::isfinite(y) || std::abs(x) > 1e150 || std::abs(y) > 1e150) {
        std::ostringstream msg;
        msg << "input point " << input_point_name(i) << " (" << x << ", " << y
            << ") is not finite or beyond 1e150 in magnitude";
        throw Meshing_error(msg.str());
      }
    }
  }

  // Exact duplicates are merged: keeping both would ask for a zero-size cell.
  void merge_duplicate_points()
  {
    std::vector<std::size_t> order(m_domain.points.size());
    for(std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    auto less_xy = m_traits.less_xy_2_object();
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return less_xy(m_domain.points[a], m_domain.points[b]);
    });
    std::vector<bool> duplicate(order.size(), false);
    auto equal = m_traits.equal_2_object();
    for(std::size_t k = 1; k < order.size(); ++k)
      if(equal(m_domain.points[order[k]], m_domain.points[order[k - 1]]))
        duplicate[order[k]] = true;
    m_points.clear();
    m_input_index.clear();
    for(std::size_t i = 0; i < m_domain.points.size(); ++i)
      if(!duplicate[i]) {
        m_points.push_back(m_domain.points[i]);
        m_input_index.push_back(i);
      }
  }

  // the bounding box of the input points
  typename GeomTraits::Iso_rectangle_2 points_box() const
  {
    auto less_x = m_traits.less_x_2_object();
    auto less_y = m_traits.less_y_2_object();
    auto xs = std::minmax_element(m_points.begin(), m_points.end(), less_x);
    auto ys = std::minmax_element(m_points.begin(), m_points.end(), less_y);
    return m_traits.construct_iso_rectangle_2_object()(*xs.first, *xs.second, *ys.first, *ys.second);
  }

  // the root grid's box: `box`, the points' (whose doubles are `m_box`), with room around it
  // when the points must become vertices
  typename GeomTraits::Iso_rectangle_2 bounding_box(const typename GeomTraits::Iso_rectangle_2& box) const
  {
    if(!m_criteria.points_as_vertices())
      return box;
    // Room around the extreme points for the refined blocks that make them vertices.
    const double xmin = m_box.xmin(), xmax = m_box.xmax(), ymin = m_box.ymin(), ymax = m_box.ymax();
    double margin = (std::max)(xmax - xmin, ymax - ymin) / 8;
    if(!(margin > 0))
      margin = (std::max)((std::max)(std::abs(xmin), std::abs(ymin)) * 0x1p-20, 0x1p-20);
    auto make_point = m_traits.construct_point_2_object();
    return m_traits.construct_iso_rectangle_2_object()(
      make_point(FT(std::nextafter(xmin - margin, -HUGE_VAL)), FT(std::nextafter(ymin - margin, -HUGE_VAL))),
      make_point(FT(std::nextafter(xmax + margin, HUGE_VAL)), FT(std::nextafter(ymax + margin, HUGE_VAL))));
  }

  void compute_point_spacing()
  {
    const std::size_t n = m_points.size();
    m_xy.resize(n);
    for(std::size_t i = 0; i < n; ++i)
      m_xy[i] = { CGAL::to_double(m_traits.compute_x_2_object()(m_points[i])),
                  CGAL::to_double(m_traits.compute_y_2_object()(m_points[i])) };
    internal::Nearest_neighbor_distances nn(m_xy);
    m_spacing = std::move(nn.distance);
    m_nearest = std::move(nn.neighbor);
  }

  // The level whose cells have side <= spacing/divisor at point i; an error if that is beyond
  // the maximum depth and no minimum size caps it.
  int point_level(std::size_t i, double divisor) const
  {
    if(!std::isfinite(m_spacing[i]))
      return 0; // a single point
    int level = level_for_size(m_spacing[i] / divisor);
    if(level <= min_size_level())
      return level;
    if(m_criteria.min_size() > 0 && !m_criteria.points_as_vertices())
      return min_size_level();
    std::ostringstream msg;
    msg.precision(17);
    msg << "input points " << input_point_name(m_input_index[i]) << " (" << m_xy[i][0] << ", " << m_xy[i][1]
        << ") and " << input_point_name(m_input_index[m_nearest[i]]) << " (" << m_xy[m_nearest[i]][0] << ", "
        << m_xy[m_nearest[i]][1] << ") are " << m_spacing[i] << " apart: separating them needs quadtree depth " << level
        << ", beyond " << m_tree->depth_limit();
    if(m_criteria.min_size() > 0)
      msg << " or the minimum size " << m_criteria.min_size();
    throw Meshing_error(msg.str());
  }

  // the level whose cells have side <= s
  int level_for_size(double s) const
  {
    return (std::max)(0, int(std::ceil(std::log2(m_tree->root_side() / s))));
  }
  // the deepest level whose cells are not below the minimum size
  int min_size_level() const
  {
    if(m_criteria.min_size() <= 0)
      return m_tree->max_depth();
    int l = int(std::floor(std::log2(m_tree->root_side() / m_criteria.min_size())));
    return (std::min)((std::max)(l, 0), m_tree->max_depth());
  }

  void refine_to_max_size()
  {
    if(m_criteria.max_size() <= 0)
      return;
    const int level = level_for_size(m_criteria.max_size());
    if(level > m_tree->max_depth()) {
      std::ostringstream msg;
      msg << "the maximum size " << m_criteria.max_size() << " needs quadtree depth " << level
          << ", beyond " << m_tree->depth_limit();
      throw Meshing_error(msg.str());
    }
    // the cells it asks for are known before any is made: a budget error now, not after
    // minutes and gigabytes
    const double side = m_tree->cell_side(level);
    auto cells_across = [&](double lo, double hi, double origin, std::uint64_t all) {
      if(m_domain.is_point_cloud())
        return double(all);
      return std::floor((hi - origin) / side) - std::floor((lo - origin) / side) + 1;
    };
    const double cells = cells_across(m_box.xmin(), m_box.xmax(), m_tree->lattice_x(0, 0), m_tree->cells_x(level))
                         * cells_across(m_box.ymin(), m_box.ymax(), m_tree->lattice_y(0, 0), m_tree->cells_y(level));
    if(cells > double(m_criteria.max_cells())) {
      std::ostringstream msg;
      msg << "the maximum size " << m_criteria.max_size() << " needs about " << cells
          << " quadtree cells over the domain, more than the cell budget of " << m_criteria.max_cells()
          << "; coarsen it or raise the cell budget";
      throw Meshing_error(msg.str());
    }
    if(m_domain.is_point_cloud()) {
      m_tree->refine([&](const Cell_key& k) { return k.level < level; });
      return;
    }
    // A cell wholly outside the domain is cleared anyway: it stays as it is (balance grades
    // it), which saves the quarter of the cells that a disc's box holds outside the disc.
    // A cell that no segment meets lies on one side, which its parent's tells, or its centre.
    enum Side : unsigned char { UNKNOWN, INSIDE, OUTSIDE };
    // Room for the cells of that size the domain's area holds: fewer than it gets (the
    // boundary's cells come on top), so never a larger node map than growing would make.
    const double area = CGAL::to_double(domain_area(m_domain, m_loops, m_traits));
    m_tree->reserve(std::size_t(area / (side * side)));
    const internal::Domain_segments<GeomTraits> boundary(m_domain, m_loops, m_traits);
    auto meets_boundary = [&](const Cell_key& k) { // by boxes: it may say yes too often
      bool any = false;
      boundary.query(m_tree->cell_rectangle(k).bbox(), [&](std::size_t) { any = true; });
      return any;
    };
    std::vector<std::pair<Cell_key, Side>> stack;
    for(const Cell_key& k : m_tree->leaves()) stack.emplace_back(k, UNKNOWN);
    while(!stack.empty()) {
      auto [k, side] = stack.back();
      stack.pop_back();
      if(k.level >= level || !m_tree->is_leaf(k) || outside_domain_box(k))
        continue;
      if(side == UNKNOWN && !meets_boundary(k))
        side = boundary.in_domain(m_tree->cell_center(k)) ? INSIDE : OUTSIDE;
      if(side == OUTSIDE)
        continue;
      m_tree->split(k);
      for(int dy = 0; dy < 2; ++dy)
        for(int dx = 0; dx < 2; ++dx) stack.emplace_back(k.child(dx, dy), side);
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
    return m_tree->lattice_x(k.level, i + 1) < m_box.xmin() || m_tree->lattice_x(k.level, i) > m_box.xmax()
           || m_tree->lattice_y(k.level, j + 1) < m_box.ymin() || m_tree->lattice_y(k.level, j) > m_box.ymax();
  }

  // Paper §4.2: the cell holding input point i is no larger than s_i = min_j d_ij.
  void refine_to_point_spacing()
  {
    for(std::size_t i = 0; i < m_points.size(); ++i) {
      const int level = point_level(i, 1);
      if(level > 0)
        m_tree->refine_at(m_points[i], level);
    }
  }

  // Paper §4.2: more than two cells across every narrow region.
  void refine_narrow_regions()
  {
    auto make_point = m_traits.construct_point_2_object();
    for(const internal::Size_sample& s : internal::narrow_region_samples(m_domain, m_loops, m_tree->cell_side(m_tree->max_depth()), m_criteria.max_cells(), m_traits)) {
      const int level = level_for_size(s.size);
      if(level > m_tree->max_depth()) {
        std::ostringstream msg;
        msg << "a narrow region of width " << 4 * s.size << " near (" << s.point[0] << ", "
            << s.point[1] << ") needs quadtree depth " << level << ", beyond "
            << m_tree->depth_limit();
        throw Meshing_error(msg.str());
      }
      const Point_2 p = make_point(s.point[0], s.point[1]);
      if(level > 0 && m_tree->contains(p))
        m_tree->refine_at(p, level);
    }
  }

  // Cells within `boundary_band` cells of the boundary are made as small as the leaf at the
  // nearest boundary point, so the clearance leaves a core boundary of one cell size: the
  // uniform grid of §4.4 (boundary angles 90°, 180° and 270° only) and a buffer zone of even
  // width. The levels are read before any band is refined, so fine cells do not spread along
  // the whole boundary, one band after another.
  void refine_boundary_band()
  {
    auto make_point = m_traits.construct_point_2_object();
    auto x_of = m_traits.compute_x_2_object();
    auto y_of = m_traits.compute_y_2_object();
    std::vector<std::pair<std::array<double, 2>, int>> targets;
    for(const auto& loop : m_loops.loops) {
      const std::size_t n = loop.vertices.size();
      for(std::size_t k = 0; k < n; ++k) {
        const Point_2& a = m_domain.points[loop.vertices[k]];
        const Point_2& b = m_domain.points[loop.vertices[(k + 1) % n]];
        const double ax = CGAL::to_double(x_of(a)), ay = CGAL::to_double(y_of(a));
        const double dx = CGAL::to_double(x_of(b)) - ax, dy = CGAL::to_double(y_of(b)) - ay;
        const double length = std::hypot(dx, dy);
        for(double t = 0; t < 1;) {
          const std::array<double, 2> q{ { ax + t * dx, ay + t * dy } };
          const int level = m_tree->locate(make_point(q[0], q[1])).level;
          targets.push_back({ q, level });
          t += m_tree->cell_side(level) / (2 * length);
        }
      }
    }
    for(const auto& target : targets) {
      const double h = m_tree->cell_side(target.second);
      for(int i = -boundary_band; i <= boundary_band; ++i)
        for(int j = -boundary_band; j <= boundary_band; ++j) {
          const Point_2 p = make_point(target.first[0] + i * h, target.first[1] + j * h);
          if(m_tree->contains(p) && m_tree->locate(p).level < target.second)
            m_tree->refine_at(p, target.second);
        }
    }
  }
  static constexpr int boundary_band = 3;
  static constexpr double min_extent = 1e-100;

  // where earlier rounds found the buffer layers poor: one level finer than it was there.
  // Every leaf touching the point is refined, not only the one `locate` picks: most requests
  // are at core vertices, lattice points with four cells around them, and the poor buffer
  // quads may lie in any of them (refining only the cell up and right of the point left a
  // buffer quad invalid round after round).
  // Records whether the requests queued since the last build split a cell.
  void refine_at_requests()
  {
    auto make_point = m_traits.construct_point_2_object();
    const double delta = m_tree->cell_side(m_tree->max_depth()) / 2;
    std::size_t leaves_before_new = 0;
    for(std::size_t i = 0; i < m_extra_refinement.size(); ++i) {
      if(i == m_requests_applied)
        leaves_before_new = m_tree->number_of_leaves();
      const auto& r = m_extra_refinement[i];
      std::array<Point_2, 4> around;
      std::size_t n = 0;
      for(int c = 0; c < 4; ++c) {
        const Point_2 q = make_point(r.first.x + ((c & 1) ? delta : -delta),
                                     r.first.y + ((c & 2) ? delta : -delta));
        if(m_tree->contains(q)) around[n++] = q;
      }
      // at least one level finer than it is there now
      int level = r.second > 0 ? level_for_size(r.second / 2) : 0;
      for(std::size_t k = 0; k < n; ++k) level = (std::max)(level, m_tree->locate(around[k]).level + 1);
      if(level > m_tree->max_depth()) continue;
      for(std::size_t k = 0; k < n; ++k) m_tree->refine_at(around[k], level);
    }
    m_requests_refined = m_requests_applied < m_extra_refinement.size()
                         && m_tree->number_of_leaves() > leaves_before_new;
    m_requests_applied = m_extra_refinement.size();
  }

  // Queues refinement at each request (a point and the local size there: cells of half that
  // size, at least one level finer, see refine_at_requests()), but not below the quadtree's
  // depth; returns how many it queued.
  std::size_t queue_refinement(const std::vector<std::pair<internal::Point_2d, double>>& requests)
  {
    std::size_t added = 0;
    for(const auto& r : requests) {
      const double size = r.second > 0 ? r.second / 2 : 0;
      if(size > 0 && level_for_size(size) > m_tree->max_depth()) continue;
      m_extra_refinement.push_back(r);
      ++added;
    }
    return added;
  }

  void refine_to_sizing_field()
  {
    const auto& field = m_criteria.sizing_field();
    const int cap = min_size_level();
    const bool capped = m_criteria.min_size() > 0;
    m_tree->refine([&](const Cell_key& k) {
      if(outside_domain_box(k))
        return false;
      double side = m_tree->cell_side(k.level);
      double target = CGAL::to_double(field(m_tree->cell_center(k)));
      for(int c = 0; c < 4; ++c)
        target = (std::min)(target, CGAL::to_double(field(m_tree->lattice_point(
                                        k.level, k.i + (c & 1), k.j + (c >> 1)))));
      if(!(target > 0))
        throw Meshing_error("the sizing field is not positive near ("
                            + std::to_string(m_tree->lattice_x(k.level, k.i)) + ", "
                            + std::to_string(m_tree->lattice_y(k.level, k.j)) + ")");
      if(side <= target)
        return false;
      return !capped || k.level < cap;
    });
  }

  const Domain_2<GeomTraits>& m_domain;
  Mesh_criteria_2<GeomTraits> m_criteria;
  GeomTraits m_traits;
  std::vector<Point_2> m_points;                // input points, duplicates merged
  std::vector<std::size_t> m_input_index;       // of each in m_domain.points
  std::vector<std::array<double, 2>> m_xy;      // their coordinates, for sizing only
  CGAL::Bbox_2 m_box;                           // their bounding box
  std::vector<double> m_spacing;                // s_i = min_j d_ij
  std::vector<std::size_t> m_nearest;           // the j of s_i
  std::unique_ptr<Quadtree> m_tree;
  Domain_loops_2<GeomTraits> m_loops;           // of a domain with segments
  std::vector<Point_anchor> m_anchors;
  std::vector<Key_code> m_vertex_keys;          // of the core mesh's vertices
  std::vector<Cell_key> m_quad_cells;           // the leaf of each core-mesh quad
  std::vector<Point_2> m_anchored_points;       // the points insert_points() makes vertices
  std::array<std::size_t, 4> m_removed{ { 0, 0, 0, 0 } };
  std::vector<std::size_t> m_point_vertices;
  std::vector<double> m_core_vertex_size;       // largest cell side at each core vertex
  std::vector<std::pair<internal::Point_2d, double>> m_extra_refinement; // (point, local size)
  std::size_t m_requests_applied = 0; // of m_extra_refinement, by the last build_quadtree()
  bool m_requests_refined = false;    // whether those it applied first split a cell
  Buffer_report m_buffer_report;
  internal::Refinement_requests m_buffer_requests; // the last round's
  std::optional<Mesh_quality_2> m_quality;
  std::vector<std::size_t> m_lost_points; // by anchored point: see clear_buffer_zone()
  std::vector<std::size_t> m_point_names; // the input index of each anchored point
  int m_rounds = 0;
  Rounds_end m_rounds_end = Rounds_end::NONE;
  std::vector<Round_figures> m_round_figures;
  Round_observer m_round_observer;
  Timings m_timings;
};

/// \ingroup PkgQuadMesher2Ref
/// Meshes `domain` with the criteria, stopping after stage `last`, and returns the mesh
/// (the role `refine_Delaunay_mesh_2` plays in Mesh_2).
template <class GeomTraits>
Quad_mesh_2<typename GeomTraits::Point_2>
make_quad_mesh_2(const Domain_2<GeomTraits>& domain, const Mesh_criteria_2<GeomTraits>& criteria, Stage last)
{
  Quadtree_mesher_2<GeomTraits> mesher(domain, criteria);
  return mesher.run(last);
}

/// \ingroup PkgQuadMesher2Ref
/// Meshes `domain` with the criteria through every stage it has (`last_stage(domain)`): a
/// domain bounded by segments is meshed up to its boundary, a point cloud's points become
/// vertices.
template <class GeomTraits>
Quad_mesh_2<typename GeomTraits::Point_2>
make_quad_mesh_2(const Domain_2<GeomTraits>& domain,
                 const Mesh_criteria_2<GeomTraits>& criteria = Mesh_criteria_2<GeomTraits>())
{
  return make_quad_mesh_2(domain, criteria, last_stage(domain));
}

} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_QUADTREE_MESHER_2_H
