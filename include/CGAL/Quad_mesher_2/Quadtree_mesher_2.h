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
#include <CGAL/Quad_mesher_2/internal/apply_templates.h>
#include <CGAL/Quad_mesher_2/internal/buffer_layers.h>
#include <CGAL/Quad_mesher_2/internal/buffer_zone_clearance.h>
#include <CGAL/Quad_mesher_2/internal/grid_aligned_domain.h>
#include <CGAL/Quad_mesher_2/internal/insert_points.h>
#include <CGAL/Quad_mesher_2/internal/lattice_region.h>
#include <CGAL/Quad_mesher_2/internal/mesh_regions.h>
#include <CGAL/Quad_mesher_2/internal/mesh_smoothing.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/quadtree_sizing.h>
#include <CGAL/Quad_mesher_2/internal/refinement_rounds.h>
#include <CGAL/Quad_mesher_2/internal/vertex_splits.h>

#include <CGAL/Bbox_2.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
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
  BUFFER2,   ///< domains only: the second buffer layer, reaching the boundary; the whole domain
             ///< is meshed and every boundary vertex is a mesh vertex (paper §4.6)
  SMOOTHING  ///< domains only: vertices moved to bring angles nearer 90°, under the bound that
             ///< keeps every angle in [45°, 135°] in it (not in the paper)
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
  case Stage::SMOOTHING: return "smoothing";
  }
  return "?";
}

/// \ingroup PkgQuadMesher2Ref
/// the last stage `domain` has, which `make_quad_mesh_2()` and `Quadtree_mesher_2::run()` run
/// to by default, as the command-line tool does: `Stage::POINTS` for a point cloud,
/// `Stage::SMOOTHING` (the whole domain meshed, then smoothed) for a domain bounded by segments
template <class GeomTraits>
Stage last_stage(const Domain_2<GeomTraits>& domain)
{
  return domain.is_point_cloud() ? Stage::POINTS : Stage::SMOOTHING;
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
  /// `points_as_vertices()`, around every input point), then strongly balances it. The mesh
  /// covers `mesh_region()` of its root grid.
  void build_quadtree()
  {
    auto start = std::chrono::steady_clock::now();
    make_tree(prepare_input());
    internal::Quadtree_sizing<GeomTraits> sizing(*m_tree, m_domain, m_loops, m_criteria, m_points, m_box,
                                                 [&](std::size_t i) { return input_point_name(m_input_index[i]); },
                                                 m_traits);
    refine(sizing);
    internal::split_along_region(*m_tree, m_region);
    record("refine", start);
    start = std::chrono::steady_clock::now();
    if(m_criteria.points_as_vertices())
      anchor_points(sizing);
    else
      m_tree->balance();
    record("balance", start);
  }

  /// The conforming all-quad mesh of the balanced tree over `mesh_region()`: every leaf there
  /// replaced by its 2-refinement template. Every angle is 45, 90 or 135 degrees.
  Mesh core_mesh()
  {
    CGAL_precondition(m_tree != nullptr);
    auto start = std::chrono::steady_clock::now();
    Mesh mesh = internal::templated_mesh(*m_tree, &m_quad_cells, &m_vertex_keys, &m_region);
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
    internal::Buffer_layers<GeomTraits> layers(mesh, m_core_vertex_size, m_domain, m_loops, m_traits, &m_move_memo,
                                               m_criteria.chord_tolerance());
    bool ok = layers.match_loops(m_point_vertices);
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

  /// Stage 7 (domains only, not in the paper) on `mesh`, a valid result of the buffer stages:
  /// its vertices move towards places that bring its angles nearer 90°, each move kept only
  /// under the bound of `internal::Mesh_smoothing`; input vertices and isolated points stay,
  /// and boundary vertices move only along the input segment they lie on, keeping the loop
  /// vertices the boundary leaves out within the chord tolerance. Then interior
  /// vertices of three or six quads split where that keeps the bound (`internal::Vertex_splits`:
  /// new vertices and quads are appended), and the mesh is smoothed again.
  /// The whole-mesh check runs again on the result, and `mesh` is left as it was if that
  /// would fail it.
  void smooth_mesh(Mesh& mesh)
  {
    const auto start = std::chrono::steady_clock::now();
    std::vector<internal::Point_2d> xy;
    xy.reserve(mesh.points.size());
    for(const Point_2& p : mesh.points) xy.push_back(internal::to_point_2d(p));
    const std::vector<internal::Point_2d> before = xy;
    const auto locator = internal::make_loop_locator(m_domain, m_loops);
    std::vector<char> pinned = pinned_vertices(xy, *locator);
    // ten times the distance under which vertices are near duplicates (the whole-mesh check's and
    // the verifier's 1e-8 of the diagonal), below the finest cells of deep trees (30P30N's,
    // depth 22: about 1.7e-7 of the diagonal), which a larger floor would freeze
    const double min_edge = 1e-7 * box_diagonal();
    const internal::Boundary_slides slides(xy, mesh.quads, *locator, m_criteria.chord_tolerance() * locator->diagonal());
    Mesh unsmoothed = mesh;
    m_smoothing_moves = internal::Mesh_smoothing(xy, mesh.quads, pinned, min_edge, &slides).smooth(max_smoothing_passes);
    m_vertex_splits = internal::Vertex_splits(xy, mesh.quads, pinned, min_edge).split_all();
    pinned.resize(xy.size(), 0);
    // the splits change interior vertices only: the boundary, and so the slides, stay
    m_smoothing_moves += internal::Mesh_smoothing(xy, mesh.quads, pinned, min_edge, &slides).smooth(max_smoothing_passes);
    mesh.points.resize(xy.size(), Point_2(0, 0));
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(v >= before.size() || xy[v] != before[v]) mesh.points[v] = Point_2(xy[v].x(), xy[v].y());
    record("smoothing", start); // the checks record their own time
    if(!check_whole_mesh(mesh)) {
      mesh = std::move(unsmoothed);
      check_whole_mesh(mesh);
    }
  }
  /// how many vertex moves the last `smooth_mesh()` kept
  std::size_t smoothing_moves() const { return m_smoothing_moves; }
  /// how many vertex splits (`internal::Vertex_splits`) the last `smooth_mesh()` made
  std::size_t vertex_splits() const { return m_vertex_splits; }
  static constexpr int max_smoothing_passes = 4;

  /// Runs every stage the input has (up to `last_stage(domain)`: the whole domain, or a point
  /// cloud's points made vertices) and returns the mesh; see `run(Stage)`.
  Mesh run() { return run(last_stage(m_domain)); }

  /// Runs the stages up to `last` and returns the mesh. Beyond the clearance, where the buffer
  /// layers would have invalid quads the quadtree is refined there and the stages run again,
  /// at most `max_refinement_rounds` times in all; a mesh with invalid quads is never
  /// returned. Where a valid buffer has angles outside [45°, 135°] that no input corner
  /// forces, the quadtree is refined there, round after round while their count falls and in
  /// at most `max_stalled_angle_rounds` valid rounds that do not lower it; an invalid round
  /// is refined both where it is invalid and where its angles are out, away from its invalid
  /// quads. The valid round with the fewest such quads is the one returned (kept from its
  /// round if a later one was worse). The rounds end too once the refinement a round asked
  /// for splits no cell (finer cells are refused there): the next round would repeat it.
  /// A mesh of the whole domain (`last` is `Stage::BUFFER2`) comes with its `boundary_edges`
  /// and their markers, and its `regions`; with `Stage::SMOOTHING` it is smoothed first
  /// (`smooth_mesh()`), and where the smoothed mesh keeps a sliver, a quad more than
  /// `max_sliver_ratio` times longer than wide that no input forces, the stages run again
  /// with the quadtree refined at each sliver; the new mesh is kept if it has fewer slivers,
  /// no more quads with an unforced angle out and no quad with an aspect ratio above the first
  /// mesh's largest (by `sliver_try_length_slack`), and if not, they run once more refined at
  /// the longest sliver alone (`sliver_tries`, each of `sliver_round_budget` rounds).
  Mesh run(Stage last)
  {
    Mesh mesh = run_rounds(last);
    if(last >= Stage::SMOOTHING) {
      smooth_mesh(mesh);
      mesh = refine_slivers(std::move(mesh), last);
    }
    if(last >= Stage::BUFFER2)
      internal::mark_boundary_and_regions(mesh, m_domain, m_loops);
    return mesh;
  }

  /// the whole-mesh check of the mesh the last `run()` returned (its `compute_quality()`),
  /// made there for runs past the clearance; empty after shorter runs
  const std::optional<Mesh_quality_2>& quality() const { return m_quality; }
  /// how many times `run()` built the quadtree (1 + refinement rounds for the buffer layers)
  int rounds() const { return m_earlier_rounds + m_rounds.round(); }
  /// why the refinement rounds of the last `run()` ended, if they left quads with an angle
  /// outside [45°, 135°] that no input corner forces (or gave up on an invalid round)
  enum class Rounds_end
  {
    NONE,         ///< they did not end that way: no such quad, or a run stopped before `BUFFER2`
    STALLED,      ///< `max_stalled_angle_rounds` valid rounds did not lower the count of such quads
    ROUND_BUDGET, ///< the quadtree was built `max_refinement_rounds` times
    FINEST_CELLS  ///< the cells asked for are finer than the quadtree may make (its depth)
  };
  Rounds_end rounds_end() const { return m_rounds.end(); }
  /// where angles stay out after the rounds on a domain with interfaces, a note naming its
  /// sharpest interface corner under 45 degrees on either side, which the rounds cannot
  /// mend (\ref QM2Interfaces), starting "; "; empty if it has none
  std::string sharp_interface_corner_note() const
  {
    const auto corners = sharp_interface_corners();
    const auto sharpest = std::min_element(corners.begin(), corners.end(),
                                           [](const auto& a, const auto& b) { return a.second < b.second; });
    return sharpest == corners.end() ? std::string() : interface_corner_note(*sharpest);
  }
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
    std::size_t refinement_requests = 0; ///< places it asked to be finer (for angles, and for validity if invalid)
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
  /// the aspect ratio (longest over shortest edge) above which a quad of the smoothed mesh is
  /// a sliver that `run()` refines (see there)
  static constexpr double max_sliver_ratio = 5.0;
  /// the rounds `run()` runs again for slivers in each try: three, each next one refined
  /// where the one before put an angle out or left an invalid quad, as long as the rounds'
  /// rule goes on (the try's mesh must not add angles out)
  static constexpr int sliver_round_budget = 3;
  /// the tries `run()` makes for slivers: at every sliver, then at the longest alone
  static constexpr int sliver_tries = 2;
  /// how much longer than the first mesh's longest quad a sliver try's may come out, relative
  static constexpr double sliver_try_length_slack = 0.01;
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
  /// The rectangle `core_mesh()` tiles (after `build_quadtree()`), whose sides are quadtree
  /// cell sides: for a domain the whole root grid, which the clearance then cuts to the
  /// domain; for a point cloud the points' bounding box widened by 1/8 of its larger side on
  /// the lower and left sides, and by 1/10 to 3/20 on the upper and right sides (to a coarse
  /// cell side), not the root grid, whose power-of-two side can reach twice the cloud's extent.
  /// The points stage moves no vertex of its sides.
  CGAL::Bbox_2 mesh_region() const
  {
    CGAL_precondition(m_tree != nullptr);
    return CGAL::Bbox_2(m_tree->origin_x(), m_tree->origin_y(),
                        m_tree->lattice_x(m_region.level, std::int64_t(m_region.nx)),
                        m_tree->lattice_y(m_region.level, std::int64_t(m_region.ny)));
  }
  const Timings& timings() const { return m_timings; }
  const Mesh_criteria_2<GeomTraits>& criteria() const { return m_criteria; }

private:
  // run(last) but for the boundary edges; `again`: the rounds of refine_slivers(), which keep
  // the requests and figures of the first, and recall its moves as any next round does
  Mesh run_rounds(Stage last, bool again = false)
  {
    if(!again) {
      m_refinement_queue.clear();
      m_round_figures.clear();
      m_earlier_rounds = 0;
      m_move_memo = internal::Move_memo();
    }
    m_quality.reset();
    m_rounds = Rounds(again ? sliver_round_budget : max_refinement_rounds, max_stalled_angle_rounds);
    // the best valid round's mesh and state, kept while later rounds try for better angles:
    // building it again would cost a whole round
    Round_state best;
    for(;;) {
      const auto round_start = std::chrono::steady_clock::now();
      m_rounds.start_round();
      m_move_memo.next_round();
      build_quadtree();
      if(m_rounds.repeats_a_failure(m_requests_refined)) {
        if(m_rounds.has_valid_round())
          return restore_round(std::move(best));
        throw Meshing_error(m_rounds.repeat_error());
      }
      Mesh mesh = core_mesh();
      if(last >= Stage::POINTS && m_criteria.points_as_vertices())
        insert_points(mesh);
      if(last >= Stage::CLEARANCE && m_grid_aligned_candidate && keep_grid_aligned_cells(mesh)) {
        record_round(mesh, true, 0, round_start);
        return mesh;
      }
      if(last >= Stage::CLEARANCE)
        clear_buffer_zone(mesh);
      if(!m_lost_points.empty()) {
        const std::vector<internal::Refinement_request> requests = lost_point_requests();
        const std::size_t added = m_refinement_queue.add(*m_tree, requests);
        if(m_rounds.refine_for_lost_points(added, lost_point_error(requests)))
          continue;
        if(m_rounds.has_valid_round())
          return restore_round(std::move(best));
        throw Meshing_error(lost_point_error(requests));
      }
      if(last <= Stage::CLEARANCE)
        return mesh;
      fill_buffer_zone(mesh, last);
      const bool valid = check_whole_mesh(mesh);
      // An invalid round is refined at its angles out too (refining for validity alone, then
      // for angles, costs a whole round more); the buffer asks for none beside its invalid
      // quads. A stage on its way is not refined for angles: they are the finished buffer's.
      std::vector<internal::Refinement_request> requests;
      if(!valid)
        requests = m_buffer_requests.for_validity;
      if(last >= Stage::BUFFER2)
        requests.insert(requests.end(), m_buffer_requests.for_angles.begin(), m_buffer_requests.for_angles.end());
      // Buffer nodes of two loops met across a narrow gap (a node on another's edge, or
      // nearly on another node): the buffer's own checks do not see them. One level finer
      // there, as for a bad quad.
      for(const internal::Point_2d& p : m_flawed)
        requests.emplace_back(p, 0.0);
      record_round(mesh, valid, requests.size(), round_start);
      const std::size_t bad = m_buffer_report.bad_angle_quads;
      if(valid && (bad == 0 || last < Stage::BUFFER2))
        return mesh;
      const std::size_t added = m_refinement_queue.add(*m_tree, requests);
      bool improved = false;
      if(m_rounds.refine_for_buffer(valid, bad, added, improved, [&] { return buffer_error(requests, true); })) {
        if(improved)
          best = save_round(std::move(mesh));
        continue;
      }
      if(valid && m_rounds.is_best(bad))
        return mesh; // angles outside [45, 135] stay; the quality report shows them
      if(m_rounds.has_valid_round())
        return restore_round(std::move(best));
      // not the round budget
      throw Meshing_error(buffer_error(requests, added < requests.size() || m_tree->depth() >= m_tree->max_depth()));
    }
  }

  // Where the boundary lies on cell sides (internal/grid_aligned_domain.h), the cells inside
  // the domain are the whole mesh, with no buffer: true if so, `mesh` then cut to them and
  // checked. Else `mesh` is left as it was.
  bool keep_grid_aligned_cells(Mesh& mesh)
  {
    if(!corners_on_the_lattice()) return false;
    const auto start = std::chrono::steady_clock::now();
    Mesh cells = mesh;
    std::size_t removed = 0;
    if(!internal::Grid_aligned_cells<GeomTraits>(m_domain, m_loops, m_traits).keep_cells_inside(cells, removed))
      return false;
    m_buffer_report = Buffer_report();
    m_buffer_requests = internal::Refinement_requests();
    record("clearance", start); // the check records its own time
    if(!check_whole_mesh(cells)) return false;
    m_removed = { removed, 0, 0, 0 };
    m_core_vertex_size.clear();
    mesh = std::move(cells);
    return true;
  }

  // whether every input vertex is a point of the tree's finest lattice: else no cell has it
  // as a corner, and the cells cannot mesh the domain alone (a cheap test before the cells')
  bool corners_on_the_lattice() const
  {
    const int level = m_tree->vertex_level();
    const double side = m_tree->cell_side(level);
    for(const auto& loop : m_loops.loops)
      for(std::size_t v : loop.vertices) {
        const internal::Point_2d p = internal::to_point_2d(m_domain.points[v]);
        const std::int64_t i = std::llround((p.x() - m_tree->origin_x()) / side);
        const std::int64_t j = std::llround((p.y() - m_tree->origin_y()) / side);
        if(!m_traits.equal_2_object()(m_tree->lattice_point(level, i, j), m_domain.points[v])) return false;
      }
    return true;
  }

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

  // Not in the paper: a smoothed mesh may keep a sliver, a quad over `max_sliver_ratio` times
  // longer than wide that no input forces (none of its corners is an input corner under 45
  // degrees, and its shortest edge does not join two input vertices). The rounds run again
  // with the quadtree refined at each, and the new mesh is kept if it has fewer, no more
  // quads with an unforced angle out, and no quad longer than the first mesh's longest (by
  // `sliver_try_length_slack`): refined cells move a forced quad's nodes too, most often a
  // little, which the slack allows, and sometimes much, lengthening it more than the slivers
  // were long. If it is not kept, they run once more refined at the longest sliver alone:
  // the more places a round refines, the more of the buffer it changes, and the likelier it
  // puts an angle out.
  Mesh refine_slivers(Mesh mesh, Stage last)
  {
    const Sliver_census first = sliver_census(mesh);
    const std::vector<Sliver>& found = first.slivers;
    if(found.empty())
      return mesh;
    const internal::Refinement_queue queue = m_refinement_queue;
    const std::size_t smoothing_moves = m_smoothing_moves, vertex_splits = m_vertex_splits;
    const Rounds rounds = m_rounds;
    Round_state kept = save_round(std::move(mesh));
    int sliver_rounds = 0; // the rounds the tries below ran: the figures count them
    std::size_t queued = 0;
    for(int attempt = 0; attempt < sliver_tries; ++attempt) {
      // a first try that queued one request queued the longest sliver's, or refused it
      if(attempt > 0 && queued <= 1)
        break;
      std::vector<internal::Refinement_request> requests;
      for(std::size_t k = 0; k < (attempt == 0 ? found.size() : 1); ++k) requests.push_back(found[k].request);
      m_refinement_queue = queue;
      queued = m_refinement_queue.add(*kept.tree, requests);
      if(queued == 0)
        break; // finer cells are refused at every sliver, the longest too
      m_earlier_rounds = rounds.round() + sliver_rounds;
      try {
        Mesh again = run_rounds(last, true);
        sliver_rounds += m_rounds.round();
        // more quads with an angle out: not kept, whatever the smoothing would make of it
        if(m_buffer_report.bad_angle_quads > kept.buffer_report.bad_angle_quads)
          continue;
        smooth_mesh(again);
        const Sliver_census after = sliver_census(again);
        if(after.slivers.size() < found.size() && after.longest <= first.longest * (1 + sliver_try_length_slack))
          return again;
      } catch(const Meshing_error&) {
        sliver_rounds += m_rounds.round(); // refined, the rounds found no valid mesh
      }
    }
    // the first mesh and its state; the rounds, their figures and the timings count all
    m_smoothing_moves = smoothing_moves;
    m_vertex_splits = vertex_splits;
    m_earlier_rounds = sliver_rounds;
    m_rounds = rounds;
    m_refinement_queue = queue;
    return restore_round(std::move(kept));
  }

  // a sliver of a mesh (see refine_slivers()) and its refinement request: of its longest
  // edge's size or the side of the leaf at its centre, whichever is smaller, one level finer
  // there at least
  struct Sliver
  {
    double aspect_ratio;
    internal::Refinement_request request;
  };

  // the slivers of a mesh, longest first, and the largest aspect ratio of its quads, forced
  // or not
  struct Sliver_census
  {
    std::vector<Sliver> slivers;
    double longest = 0;
  };

  Sliver_census sliver_census(const Mesh& mesh) const
  {
    Sliver_census census;
    std::vector<std::pair<std::size_t, double>> long_quads; // over the ratio: slivers unless the input forces them
    for(std::size_t q = 0; q < mesh.quads.size(); ++q) {
      const double ratio = internal::quad_aspect_ratio(corners(mesh, q));
      census.longest = (std::max)(census.longest, ratio);
      if(ratio > max_sliver_ratio) long_quads.emplace_back(q, ratio);
    }
    if(long_quads.empty())
      return census;
    std::vector<internal::Point_2d> xy;
    for(const Point_2& p : mesh.points) xy.push_back(internal::to_point_2d(p));
    const std::vector<double> angle = input_corner_angles(xy);
    std::vector<Sliver>& found = census.slivers;
    for(const auto& [q, ratio] : long_quads) {
      const auto& Q = mesh.quads[q];
      const std::array<internal::Point_2d, 4> c = corners(mesh, q);
      const std::array<double, 4> len = internal::quad_edge_lengths(c);
      const int shortest = int(std::min_element(len.begin(), len.end()) - len.begin());
      bool forced = !std::isnan(angle[Q[shortest]]) && !std::isnan(angle[Q[(shortest + 1) % 4]]);
      for(std::size_t v : Q) forced = forced || angle[v] < 45.0;
      if(forced) continue;
      const internal::Point_2d centre = internal::mean_2d(c.begin(), c.end());
      // a sliver spanning a few cells may be no longer than two of them: its own size alone
      // would ask for the cells it came from
      const Point_2 at(centre.x(), centre.y());
      const double cell = m_tree->contains(at) ? m_tree->cell_side(m_tree->locate(at).level) : HUGE_VAL;
      found.push_back({ ratio, { centre, (std::min)(cell, *std::max_element(len.begin(), len.end())) } });
    }
    std::stable_sort(found.begin(), found.end(),
                     [](const Sliver& a, const Sliver& b) { return a.aspect_ratio > b.aspect_ratio; });
    return census;
  }

  static std::array<internal::Point_2d, 4> corners(const Mesh& mesh, std::size_t q)
  {
    std::array<internal::Point_2d, 4> c;
    for(int k = 0; k < 4; ++k) c[k] = internal::to_point_2d(mesh.points[mesh.quads[q][k]]);
    return c;
  }

  // per point of `xy`: the domain's angle at the loop vertex there, or NaN
  std::vector<double> input_corner_angles(const std::vector<internal::Point_2d>& xy) const
  {
    std::vector<std::pair<internal::Point_2d, double>> input;
    for(const auto& loop : m_loops.loops)
      for(std::size_t k = 0; k < loop.vertices.size(); ++k)
        input.emplace_back(internal::to_point_2d(m_domain.points[loop.vertices[k]]),
                           internal::loop_corner_angle(m_domain, loop, k));
    std::sort(input.begin(), input.end());
    std::vector<double> angle(xy.size(), std::numeric_limits<double>::quiet_NaN());
    for(std::size_t v = 0; v < xy.size(); ++v) {
      auto it = std::lower_bound(input.begin(), input.end(), xy[v], [](const auto& e, const internal::Point_2d& x) { return e.first < x; });
      if(it != input.end() && it->first == xy[v]) angle[v] = it->second;
    }
    return angle;
  }

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
  std::string buffer_error(const std::vector<internal::Refinement_request>& requests, bool refused) const
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
      msg << ", near (" << requests.front().first.x() << ", " << requests.front().first.y() << ")";
    msg << ", after " << m_rounds.round() << " refinement rounds";
    if(refused)
      msg << "; finer cells are refused there: " << m_tree->depth_limit();
    // a failure within 32 cells of a sharp interface corner names it: the strip on one side
    // takes the nodes the other side chose (QM2Interfaces), which a wedge's tip and the fan
    // about it cannot share
    if(!requests.empty())
      msg << interface_corner_note(sharp_interface_corner_near(requests.front().first, 32 * requests.front().second));
    return msg.str();
  }

  // the corners sharper than 45 degrees at vertices on an interface: (input point, that angle)
  std::vector<std::pair<std::size_t, double>> sharp_interface_corners() const
  {
    std::vector<std::pair<std::size_t, double>> corners;
    for(const auto& loop : m_loops.loops)
      for(std::size_t k = 0; k < loop.vertices.size(); ++k) {
        const double a = internal::loop_corner_angle(m_domain, loop, k);
        if(a < 45.0 && internal::on_edge_twin(loop, k)) corners.emplace_back(loop.vertices[k], a);
      }
    return corners;
  }

  // of the sharp interface corners, the nearest to `at` within `reach`, or none
  std::pair<std::size_t, double> sharp_interface_corner_near(const internal::Point_2d& at, double reach) const
  {
    std::pair<std::size_t, double> found(std::size_t(-1), 0.0);
    for(const auto& corner : sharp_interface_corners()) {
      const double d = internal::length_2d(internal::to_point_2d(m_domain.points[corner.first]) - at);
      if(d <= reach) { reach = d; found = corner; }
    }
    return found;
  }

  // "; input point N (x, y) is a corner of A degrees on an interface ...", or empty for none
  std::string interface_corner_note(const std::pair<std::size_t, double>& corner) const
  {
    if(corner.first == std::size_t(-1)) return std::string();
    const Point_2& p = m_domain.points[corner.first];
    std::ostringstream note;
    note << "; input point " << m_domain.point_label(corner.first) << " (" << CGAL::to_double(p.x()) << ", "
         << CGAL::to_double(p.y()) << ") is a corner of " << corner.second << " degrees on an interface between two "
         << "regions: interface corners under 45 degrees on either side are not supported yet";
    return note.str();
  }

  // the first isolated point the last round lost (see lost_points()), `requests` the
  // refinement asked around each
  std::string lost_point_error(const std::vector<internal::Refinement_request>& requests) const
  {
    std::ostringstream msg;
    msg << "isolated point " << input_point_name(m_point_names[m_lost_points.front()]) << " (" << requests.front().first.x()
        << ", " << requests.front().first.y() << ") lies " << 2 * requests.front().second
        << " from the boundary: cells small enough to keep it a vertex inside the core are beyond the "
        << "quadtree's depth or its refinement rounds (" << m_rounds.round() << ")";
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

  // the margin around the points' box `m_box`: room around the extreme points for the
  // refined blocks that make them vertices, when they must become vertices, and around a
  // point cloud, whose mesh covers that box with the margin (mesh_region())
  double margin() const
  {
    // an axis-parallel domain keeps its corners on the lattice where they can be
    if((!m_criteria.points_as_vertices() && !m_domain.is_point_cloud()) || m_grid_aligned_candidate)
      return 0;
    const double xmin = m_box.xmin(), xmax = m_box.xmax(), ymin = m_box.ymin(), ymax = m_box.ymax();
    const double margin = (std::max)(xmax - xmin, ymax - ymin) / 8;
    if(margin > 0)
      return margin;
    return (std::max)((std::max)(std::abs(xmin), std::abs(ymin)) * 0x1p-20, 0x1p-20);
  }

  // the root grid's box: `box`, the points' (whose doubles are `m_box`), with the margin
  // around it
  typename GeomTraits::Iso_rectangle_2 bounding_box(const typename GeomTraits::Iso_rectangle_2& box) const
  {
    const double margin = this->margin();
    if(margin == 0)
      return box;
    const double xmin = m_box.xmin(), xmax = m_box.xmax(), ymin = m_box.ymin(), ymax = m_box.ymax();
    auto make_point = m_traits.construct_point_2_object();
    return m_traits.construct_iso_rectangle_2_object()(
      make_point(FT(std::nextafter(xmin - margin, -HUGE_VAL)), FT(std::nextafter(ymin - margin, -HUGE_VAL))),
      make_point(FT(std::nextafter(xmax + margin, HUGE_VAL)), FT(std::nextafter(ymax + margin, HUGE_VAL))));
  }

  // Checks and merges the input points, validates the loops; returns the points' bounding
  // box, whose doubles it keeps in m_box.
  typename GeomTraits::Iso_rectangle_2 prepare_input()
  {
    if(m_domain.points.empty())
      throw Meshing_error("the input has no points");
    check_finite();
    merge_duplicate_points();
    if(!m_domain.is_point_cloud())
      m_loops = extract_loops(m_domain, m_traits); // validates the boundary first
    m_grid_aligned_candidate = !m_domain.is_point_cloud() && m_loops.isolated_points.empty()
                               && internal::is_axis_parallel(m_domain, m_loops, m_traits);
    const auto box = points_box();
    m_box = CGAL::Bbox_2(CGAL::to_double(m_traits.compute_xmin_2_object()(box)),
                         CGAL::to_double(m_traits.compute_ymin_2_object()(box)),
                         CGAL::to_double(m_traits.compute_xmax_2_object()(box)),
                         CGAL::to_double(m_traits.compute_ymax_2_object()(box)));
    // Below this, sizes and steps along the boundary underflow to subnormal doubles or zero
    // (and the narrow-region search loops for ever).
    const double extent = (std::max)(m_box.xmax() - m_box.xmin(), m_box.ymax() - m_box.ymin());
    if(extent > 0 && extent < min_extent) {
      std::ostringstream msg;
      msg << "the input's extent " << extent << " is too small to mesh (under " << min_extent
          << "); scale the input";
      throw Meshing_error(msg.str());
    }
    return box;
  }

  // the unrefined tree over `box`, the points' bounding box
  void make_tree(const typename GeomTraits::Iso_rectangle_2& box)
  {
    // the whole-mesh check counts vertices closer than 1e-9 of the diagonal as duplicates, and
    // the buffer puts vertices a quarter cell apart: finer cells make a mesh that cannot pass
    // (a point cloud has no buffer, and its points are its finest vertices)
    const double finest_side = m_domain.is_point_cloud()
                                 ? 0.0
                                 : 4e-9 * box_diagonal();
    m_tree = std::make_unique<Quadtree>(bounding_box(box), m_criteria.max_depth(), m_traits, finest_side);
    m_tree->set_max_leaves(m_criteria.max_cells());
    // A point cloud's mesh ends past the upper and right sides of its points' box by 4/5 to
    // 6/5 of the margin: the wider the range, the coarser the cells along those sides can
    // be; the narrower margin still holds the points' blocks, or deeper ones.
    const double margin = this->margin();
    m_region = m_domain.is_point_cloud()
                 ? internal::point_cloud_region(*m_tree, m_box.xmax() + margin * 4 / 5, m_box.ymax() + margin * 4 / 5,
                                                margin * 2 / 5)
                 : internal::whole_grid(*m_tree);
  }

  // Paper §4.2: the sizes the criteria and the input ask for, then the places earlier rounds
  // asked to be finer.
  void refine(internal::Quadtree_sizing<GeomTraits>& sizing)
  {
    sizing.refine_to_max_size();
    if(m_criteria.use_point_spacing())
      sizing.refine_to_point_spacing();
    if(m_criteria.sizing_field())
      sizing.refine_to_sizing_field();
    if(!m_domain.is_point_cloud())
      sizing.refine_to_region_areas();
    if(!m_domain.is_point_cloud() && m_criteria.resolve_narrow_regions())
      sizing.refine_narrow_regions();
    m_requests_refined = m_refinement_queue.refine(*m_tree);
    if(!m_domain.is_point_cloud())
      sizing.refine_boundary_band();
  }

  // Paper §3: anchors a point cloud's points, or a domain's isolated points (its boundary
  // vertices are for the buffer layers), and balances the tree around them.
  void anchor_points(const internal::Quadtree_sizing<GeomTraits>& sizing)
  {
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
      levels.push_back(sizing.point_level(i, 1));
      names.push_back(m_input_index[i]);
      m_anchored_points.push_back(m_points[i]);
    }
    m_anchors = internal::anchor_points(*m_tree, m_anchored_points, levels, m_region,
                                        [&](std::size_t i) { return input_point_name(names[i]); });
    m_point_names = std::move(names);
  }

  // Where the lost points (see lost_points()) ask for finer cells: a quarter of their
  // distance to the boundary.
  std::vector<internal::Refinement_request> lost_point_requests() const
  {
    const auto locator = internal::make_loop_locator(m_domain, m_loops);
    std::vector<internal::Refinement_request> requests;
    for(std::size_t i : m_lost_points) {
      const internal::Point_2d p = internal::to_point_2d(m_anchored_points[i]);
      requests.emplace_back(p, locator->closest(p, m_tree->cell_side(m_tree->depth())).dist / 2);
    }
    return requests;
  }

  // The whole mesh is checked too after the buffer stages: a buffer node on another quad's
  // edge would hang. Keeps the places of its flaws (near-duplicate vertices and hanging
  // nodes) in m_flawed; true if the round is valid.
  bool check_whole_mesh(const Mesh& mesh)
  {
    const auto check_start = std::chrono::steady_clock::now();
    m_flawed.clear();
    const Mesh_quality_2& quality = *(m_quality = internal::compute_quality(mesh, &m_flawed));
    record("check", check_start);
    return m_buffer_report.failure.empty() && m_buffer_report.invalid_quads == 0 && quality.is_valid()
           && quality.number_of_near_duplicate_vertices == 0;
  }

  // the vertices the smoothing keeps where they are: the loops' vertices, isolated points and
  // the points on interfaces (the buffer made them on an interface's segments, which stay
  // chains of mesh edges)
  std::vector<char> pinned_vertices(const std::vector<internal::Point_2d>& xy, const internal::Loop_locator& locator) const
  {
    const std::vector<double> angle = input_corner_angles(xy);
    std::vector<char> pinned(xy.size(), 0);
    for(std::size_t v = 0; v < xy.size(); ++v) pinned[v] = !std::isnan(angle[v]);
    for(std::size_t v : m_point_vertices)
      if(v < pinned.size()) pinned[v] = 1;
    if(internal::has_interfaces(m_loops)) {
      const double on = 1e-10 * locator.diagonal();
      for(std::size_t v = 0; v < xy.size(); ++v) {
        const internal::Loop_locator::Hit h = locator.closest(xy[v], on);
        if(h.dist <= on && locator.edge_twin(h.loop, h.edge)[0] != internal::Loop_locator::none) pinned[v] = 1;
      }
    }
    return pinned;
  }

  double box_diagonal() const
  {
    return std::hypot(m_box.xmax() - m_box.xmin(), m_box.ymax() - m_box.ymin());
  }

  // adds the round's figures and shows them to the observer
  void record_round(const Mesh& mesh, bool valid, std::size_t requests, std::chrono::steady_clock::time_point start)
  {
    m_round_figures.push_back({ rounds(), mesh.quads.size(), m_buffer_report.invalid_quads,
                                m_buffer_report.bad_angle_quads, m_buffer_report.bad_angle_quads_by_layer, valid, requests,
                                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() });
    if(m_round_observer)
      m_round_observer(m_round_figures.back());
  }

  static constexpr double min_extent = 1e-100;

  const Domain_2<GeomTraits>& m_domain;
  Mesh_criteria_2<GeomTraits> m_criteria;
  GeomTraits m_traits;
  std::vector<Point_2> m_points;                // input points, duplicates merged
  std::vector<std::size_t> m_input_index;       // of each in m_domain.points
  CGAL::Bbox_2 m_box;                           // their bounding box
  std::unique_ptr<Quadtree> m_tree;
  internal::Lattice_region m_region;            // the part of its grid the mesh covers
  Domain_loops_2<GeomTraits> m_loops;           // of a domain with segments
  std::vector<Point_anchor> m_anchors;
  std::vector<Key_code> m_vertex_keys;          // of the core mesh's vertices
  std::vector<Cell_key> m_quad_cells;           // the leaf of each core-mesh quad
  std::vector<Point_2> m_anchored_points;       // the points insert_points() makes vertices
  std::array<std::size_t, 4> m_removed{ { 0, 0, 0, 0 } };
  std::vector<std::size_t> m_point_vertices;
  std::vector<double> m_core_vertex_size;       // largest cell side at each core vertex
  internal::Refinement_queue m_refinement_queue; // where earlier rounds asked for finer cells
  internal::Move_memo m_move_memo;              // the buffer's moves of this round and the last
  bool m_requests_refined = false; // whether those the last build_quadtree() applied first split a cell
  Buffer_report m_buffer_report;
  internal::Refinement_requests m_buffer_requests; // the last round's
  std::optional<Mesh_quality_2> m_quality;
  std::vector<std::size_t> m_lost_points; // by anchored point: see clear_buffer_zone()
  std::size_t m_smoothing_moves = 0;
  std::size_t m_vertex_splits = 0;
  bool m_grid_aligned_candidate = false; // an axis-parallel domain with no isolated point
  std::vector<std::size_t> m_point_names; // the input index of each anchored point
  typedef internal::Refinement_rounds<Rounds_end> Rounds;
  Rounds m_rounds{ max_refinement_rounds, max_stalled_angle_rounds };
  int m_earlier_rounds = 0; // of a first run_rounds() that refine_slivers() ran again
  std::vector<internal::Point_2d> m_flawed; // the last whole-mesh check's flaws
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
