// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// quad-mesher: the command-line tool. The only place that parses arguments, names files or
// prints; everything else is in the library.

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <CGAL/Quad_mesher_2/Boundary_layer_mesher_2.h>
#include <CGAL/Quad_mesher_2/Curve_decomposition_2.h>
#include <CGAL/Quad_mesher_2/IO/read_domain.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Mesh_quality_2.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <vector>
#include <unistd.h>

namespace QM = CGAL::Quad_mesher_2;

namespace {

// 2^40 cells: about 120 TB of quadtree, far beyond any machine, well within 64 bits
constexpr unsigned long long max_cell_budget = 1ULL << 40;

struct Options
{
  std::string input;
  std::vector<std::string> outputs;
  std::string report;
  std::string kernel = "epick";
  std::string stop_after; // empty: every stage the input has
  double max_size = 0;
  double min_size = 0;
  int max_depth = QM::Mesh_criteria_2<CGAL::Epick>::default_max_depth;
  std::size_t max_cells = QM::Mesh_criteria_2<CGAL::Epick>().max_cells();
  std::string curves = "polygon";
  bool merge_duplicates = false;
  double max_turning_angle = 5;
  double chord_error = 0;
  int boundary_layers = 0; // 0: none
  double first_height = 0;
  double growth = 1.2;
  std::vector<int> wall_markers;
  bool verbose = false;
};

const std::vector<std::string> output_extensions = { ".msh", ".vtu", ".su2", ".inp", ".off", ".svg" };

// The outputs are written beside their targets under hidden names (the same extension, which
// picks the format) and renamed into place together once all are written: a run that fails
// to write one leaves none, and the files that were there before untouched.
class Staged_outputs
{
public:
  // the name to write `target` under for now (a symbolic link's file, not the link, is
  // replaced)
  std::string add(const std::string& target)
  {
    std::error_code ec;
    const std::filesystem::path t = std::filesystem::is_symlink(target, ec) ? std::filesystem::weakly_canonical(target, ec)
                                                                             : std::filesystem::path(target);
    const std::filesystem::path part = t.parent_path() / ("." + t.filename().string() + ".partial-"
                                                           + std::to_string(::getpid())
                                                           + std::filesystem::path(target).extension().string());
    m_files.emplace_back(part.string(), t.string());
    return m_files.back().first;
  }
  // renames every file into place; on failure the name of the target that failed
  std::string commit()
  {
    for(auto& [part, target] : m_files) {
      std::error_code ec;
      std::filesystem::rename(part, target, ec);
      if(ec) return target; // as resolved: the name the user gave may be a link to it
      part.clear();
    }
    return {};
  }
  ~Staged_outputs()
  {
    for(const auto& f : m_files)
      if(!f.first.empty()) std::remove(f.first.c_str());
  }

private:
  std::vector<std::pair<std::string, std::string>> m_files; // (written now, target)
};
const QM::Stage all_stages[] = { QM::Stage::QUADTREE, QM::Stage::POINTS, QM::Stage::CLEARANCE,
                                 QM::Stage::TEMPLATES, QM::Stage::BUFFER1, QM::Stage::BUFFER2,
                                 QM::Stage::SMOOTHING };

std::vector<std::string> stage_names()
{
  std::vector<std::string> names;
  for(QM::Stage s : all_stages)
    names.push_back(QM::stage_name(s));
  return names;
}

bool same_file(const std::string& a, const std::string& b)
{
  std::error_code ec;
  if(std::filesystem::exists(a, ec) && std::filesystem::exists(b, ec))
    return std::filesystem::equivalent(a, b, ec);
  return std::filesystem::weakly_canonical(std::filesystem::absolute(a, ec), ec)
         == std::filesystem::weakly_canonical(std::filesystem::absolute(b, ec), ec);
}

double seconds_since(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// a count per buffer layer: the core's quads the templates changed, the first layer, the second
nlohmann::json by_layer(const std::array<std::size_t, 3>& n)
{
  return { { "core", n[0] }, { "first_layer", n[1] }, { "second_layer", n[2] } };
}

// why the refinement rounds ended: the report's name for it, and the warning's words
template <class Mesher>
std::pair<std::string, std::string> rounds_end_text(const Mesher& mesher)
{
  typedef typename Mesher::Rounds_end End;
  switch(mesher.rounds_end()) {
  case End::STALLED:
    return { "stalled", std::to_string(Mesher::max_stalled_angle_rounds)
                          + " refinement rounds did not lower their count (see -v)" };
  case End::ROUND_BUDGET:
    return { "round budget", "the refinement rounds reached their budget of "
                               + std::to_string(Mesher::max_refinement_rounds) };
  case End::FINEST_CELLS:
    return { "finest cells", "refining there needs cells finer than the quadtree may make ("
                               + mesher.quadtree().depth_limit() + ")" };
  default:
    return { "none", "" };
  }
}

// one refinement round as -v prints it, when it ends
template <class Figures>
void print_round(std::ostream& out, const Figures& f)
{
  out << "round " << f.round << ": " << f.quads << " quads, " << (f.valid ? "valid" : "invalid") << ", "
      << f.invalid_quads << " buffer quads not convex, " << f.bad_angle_quads << " with an unforced angle out ("
      << f.bad_angle_quads_by_layer[0] << " core, " << f.bad_angle_quads_by_layer[1] << " first layer, "
      << f.bad_angle_quads_by_layer[2] << " second layer), " << f.refinement_requests << " refinement requests, "
      << f.seconds << " s" << std::endl;
}

// Reads the input (and, with --curves spline, decomposes its loops): false after printing why.
template <class K>
bool read_input(const Options& opt, QM::Domain_2<K>& domain, nlohmann::ordered_json& seconds)
{
  using Clock = std::chrono::steady_clock;
  std::string error;
  auto t = Clock::now();
  if(!QM::IO::read_domain(opt.input, domain, &error,
                          opt.merge_duplicates ? QM::IO::Duplicate_points::KEEP
                                               : QM::IO::Duplicate_points::REJECT)) {
    std::cerr << "quad-mesher: " << error << "\n";
    return false;
  }
  seconds["read"] = seconds_since(t);
  if(opt.verbose)
    std::cerr << "read " << opt.input << ": " << domain.points.size() << " points, "
              << domain.segments.size() << " segments, " << domain.holes.size() << " holes in "
              << seconds["read"].get<double>() << " s\n";

  if(opt.curves == "spline") {
    // paper §4.1: each loop is a closed cubic spline through its points
    t = Clock::now();
    QM::Curve_decomposition_options curve_options;
    curve_options.max_turning_angle_deg = opt.max_turning_angle;
    curve_options.max_chord_error = opt.chord_error;
    const std::size_t before = domain.points.size();
    domain = QM::decompose_domain_curves(domain, curve_options);
    seconds["curves"] = seconds_since(t);
    if(opt.verbose)
      std::cerr << "curves: " << before << " spline points -> " << domain.points.size()
                << " polygon vertices in " << seconds["curves"].get<double>() << " s\n";
  }
  return true;
}

// the stage --stop-after names, or the last the domain has
template <class K>
QM::Stage stop_after_stage(const Options& opt, const QM::Domain_2<K>& domain)
{
  QM::Stage last = QM::last_stage(domain);
  for(QM::Stage s : all_stages)
    if(opt.stop_after == QM::stage_name(s))
      last = s;
  return last;
}

template <class K>
QM::Mesh_criteria_2<K> criteria_of(const Options& opt, QM::Stage last)
{
  QM::Mesh_criteria_2<K> criteria(opt.max_size, opt.min_size, opt.max_depth);
  criteria.set_max_cells(opt.max_cells);
  // the quadtree stage alone does not refine for point insertion
  criteria.set_points_as_vertices(last != QM::Stage::QUADTREE);
  return criteria;
}

// adds the mesher's stage times to `seconds` (one entry per stage and refinement round)
template <class Mesher>
void add_stage_times(const Options& opt, const Mesher& mesher, nlohmann::ordered_json& seconds)
{
  for(const auto& stage : mesher.timings()) {
    seconds[stage.first] = seconds.value(stage.first, 0.0) + stage.second;
    if(opt.verbose)
      std::cerr << "stage " << stage.first << ": " << stage.second << " s\n";
  }
}

// Writes every output under its staged name: false after printing which failed.
template <class K>
bool write_outputs(const Options& opt, const QM::Domain_2<K>& domain,
                   const QM::Quad_mesh_2<typename K::Point_2>& mesh, Staged_outputs& staged)
{
  // the picture shows the input's segments over the mesh
  std::vector<std::pair<typename K::Point_2, typename K::Point_2>> segments;
  for(const auto& s : domain.segments)
    segments.emplace_back(domain.points[s[0]], domain.points[s[1]]);
  for(const std::string& out : opt.outputs) {
    const std::string part = staged.add(out);
    const bool written = QM::IO::file_extension(out) == ".svg" ? QM::IO::write_SVG(part, mesh, segments)
                                                     : QM::IO::write_quad_mesh(part, mesh);
    if(!written) {
      std::cerr << "quad-mesher: cannot write " << out << "\n";
      return false;
    }
  }
  return true;
}

// the report's counts, angles, shape and validity of the mesh
void add_quality(const QM::Mesh_quality_2& quality, nlohmann::ordered_json& report)
{
  report["quads"] = quality.number_of_quads;
  report["vertices"] = quality.number_of_vertices;
  report["min_angle"] = quality.min_angle;
  report["max_angle"] = quality.max_angle;
  report["mean_angle"] = quality.mean_angle;
  report["angle_histogram_5deg"] = quality.angle_histogram;
  report["share_in_45_135"] = quality.share_in_45_135;
  report["share_in_60_120"] = quality.share_in_60_120;
  report["aspect_ratio"] = { { "min", quality.min_aspect_ratio },
                             { "max", quality.max_aspect_ratio },
                             { "mean", quality.mean_aspect_ratio },
                             { "p50", quality.aspect_ratio_percentiles[0] },
                             { "p95", quality.aspect_ratio_percentiles[1] },
                             { "p99", quality.aspect_ratio_percentiles[2] } };
  report["min_edge_over_diagonal"] = quality.min_edge_over_diagonal;
  report["scaled_jacobian"] = { { "min", quality.min_scaled_jacobian },
                                { "mean", quality.mean_scaled_jacobian } };
  report["validity"] = { { "valid", quality.is_valid() },
                         { "inverted_quads", quality.number_of_inverted_quads },
                         { "degenerate_quads", quality.number_of_degenerate_quads },
                         { "non_manifold_edges", quality.number_of_non_manifold_edges },
                         { "hanging_nodes", quality.number_of_hanging_nodes },
                         { "duplicate_vertices", quality.number_of_duplicate_vertices },
                         { "near_duplicate_vertices", quality.number_of_near_duplicate_vertices },
                         { "boundary_loops", quality.number_of_boundary_loops } };
}

// the report's account of the buffer stages and the refinement rounds; warns about quads
// with an unforced angle out
template <class Mesher>
void add_buffer(const Options& opt, const Mesher& mesher, nlohmann::ordered_json& report)
{
  const auto& b = mesher.buffer_report();
  report["buffer"] = { { "refinement_rounds", mesher.rounds() - 1 },
                       { "dropped_core_pieces", b.dropped_core_pieces },
                       { "notches_moved", b.moved_notches },
                       { "corners_cut", b.cut_corners },
                       { "notches_filled", b.filled_notches },
                       { "corners_split", b.split_corners },
                       { "fans_that_may_take_four", b.fans_that_may_take_four },
                       { "fans_of_four", b.fans_of_four },
                       { "buffer_angles_out", b.buffer_angles_out },
                       { "buffer_angles_out_away_from_corners", b.buffer_angles_out_away_from_corners },
                       { "vertices_searched", b.searched_vertices },
                       { "moves_searched", b.moves_searched },
                       { "moves_recalled", b.moves_recalled },
                       { "interior_vertices_moved", b.shaped_interior },
                       { "first_layer_quads", b.first_layer_quads },
                       { "second_layer_quads", b.second_layer_quads },
                       { "quads_outside_45_135_not_forced", b.bad_angle_quads },
                       { "quads_outside_45_135_not_forced_by_layer", by_layer(b.bad_angle_quads_by_layer) } };
  // every round: the first is the stages' own result, before any refinement for angles
  nlohmann::json rounds = nlohmann::json::array();
  for(const auto& f : mesher.round_figures())
    rounds.push_back({ { "round", f.round },
                       { "quads", f.quads },
                       { "valid", f.valid },
                       { "buffer_quads_not_convex", f.invalid_quads },
                       { "quads_outside_45_135_not_forced", f.bad_angle_quads },
                       { "quads_outside_45_135_not_forced_by_layer", by_layer(f.bad_angle_quads_by_layer) },
                       { "refinement_requests", f.refinement_requests },
                       { "seconds", f.seconds } });
  report["rounds"] = rounds;
  const auto [rounds_end, why] = rounds_end_text(mesher);
  report["buffer"]["rounds_end"] = rounds_end;
  if(b.bad_angle_quads > 0)
    std::cerr << "quad-mesher: " << opt.input << ": warning: " << b.bad_angle_quads
              << " buffer quads have an angle outside [45, 135] that no input corner forces: " << why
              << mesher.sharp_interface_corner_note() << "\n";
}

// the mesh's regions: tag, attribute (null where none) and quads of each
template <class Point_2>
void add_regions(const QM::Quad_mesh_2<Point_2>& mesh, nlohmann::ordered_json& report)
{
  if(mesh.regions.empty())
    return;
  std::vector<std::size_t> quads(mesh.regions.size(), 0);
  for(std::size_t r : mesh.quad_regions) ++quads[r];
  nlohmann::json regions = nlohmann::json::array();
  for(std::size_t r = 0; r < mesh.regions.size(); ++r)
    regions.push_back({ { "tag", mesh.regions[r].tag },
                        { "attribute", mesh.regions[r].has_attribute ? nlohmann::json(mesh.regions[r].attribute) : nlohmann::json() },
                        { "quads", quads[r] } });
  report["regions"] = regions;
}

// the whole report but its seconds
template <class K, class Mesher>
void fill_report(const Options& opt, const QM::Domain_2<K>& domain, QM::Stage last, const Mesher& mesher,
                 const QM::Quad_mesh_2<typename K::Point_2>& mesh, const QM::Mesh_quality_2& quality,
                 nlohmann::ordered_json& report)
{
  const auto& tree = mesher.quadtree();
  report["input"] = { { "file", opt.input },
                      { "points", domain.points.size() },
                      { "segments", domain.segments.size() },
                      { "holes", domain.holes.size() },
                      { "regional_attributes", domain.region_attributes.size() } };
  report["input"]["merged_duplicate_points"] = mesher.number_of_merged_points();
  report["kernel"] = opt.kernel;
  report["curves"] = opt.curves;
  report["stop_after"] = QM::stage_name(last);
  add_quality(quality, report);
  if(last >= QM::Stage::CLEARANCE) {
    const auto& removed = mesher.removed_by_clearance();
    report["clearance_removed"] = { { "outside", removed[0] },
                                    { "crossing_boundary", removed[1] },
                                    { "near_boundary", removed[2] },
                                    { "single_or_pinched", removed[3] } };
  }
  if(last >= QM::Stage::TEMPLATES)
    add_buffer(opt, mesher, report);
  if(last >= QM::Stage::SMOOTHING)
    report["smoothing"] = { { "moves", mesher.smoothing_moves() }, { "vertex_splits", mesher.vertex_splits() } };
  add_regions(mesh, report);
  report["points_as_vertices"] = mesher.point_vertices().size();
  report["max_aspect_ratio_at_points"] = QM::max_aspect_ratio_around(mesh, mesher.point_vertices());
  report["quadtree_depth"] = tree.depth();
  report["quadtree_leaves"] = tree.number_of_leaves();
  report["quadtree_root"] = { { "cells_x", tree.root_cells_x() },
                              { "cells_y", tree.root_cells_y() },
                              { "side", tree.root_side() },
                              { "origin", { tree.origin_x(), tree.origin_y() } } };
}

QM::Boundary_layer_criteria_2 layer_criteria_of(const Options& opt)
{
  return QM::Boundary_layer_criteria_2(opt.boundary_layers, opt.first_height, opt.growth, opt.wall_markers);
}

// the report's account of the boundary layers; warns where stacks were thinned
void add_boundary_layers(const Options& opt, const QM::Boundary_layer_report& r, nlohmann::ordered_json& report)
{
  nlohmann::json walls = nlohmann::json::array();
  for(const auto& w : r.walls) {
    walls.push_back({ { "marker", w.marker },
                      { "bands", w.bands },
                      { "fans", w.fans },
                      { "thinned_bands", w.thinned_bands },
                      { "thinnest_ratio", w.thinnest_ratio },
                      { "thinnest_at", w.thinnest_at },
                      { "first_height", { { "min", w.first_height_min },
                                          { "median", w.first_height_median },
                                          { "max", w.first_height_max } } },
                      { "growth", { { "min", w.growth_min }, { "max", w.growth_max } } },
                      { "thickness", { { "min", w.thickness_min }, { "max", w.thickness_max } } } });
    if(w.thinned_bands > 0)
      std::cerr << "quad-mesher: " << opt.input << ": warning: wall marker " << w.marker << ": " << w.thinned_bands
                << " boundary-layer bands thinned where the boundary faces the wall closely, down to "
                << w.thinnest_ratio << " of the stack at (" << w.thinnest_at[0] << ", " << w.thinnest_at[1] << ")\n";
  }
  report["boundary_layers"] = { { "layers", r.layers },
                                { "first_height", opt.first_height },
                                { "growth", opt.growth },
                                { "layer_quads", r.layer_quads },
                                { "angles_in_layers", { r.layer_min_angle, r.layer_max_angle } },
                                { "angles_outside_layers", { r.outer_min_angle, r.outer_max_angle } },
                                { "walls", walls } };
}

// Writes the report under its staged name, if one is asked for: false after printing why not.
bool write_report(const Options& opt, const nlohmann::ordered_json& report, Staged_outputs& staged)
{
  if(opt.report.empty())
    return true;
  std::ofstream out(staged.add(opt.report));
  out << report.dump(2) << "\n";
  out.close();
  if(!out) {
    std::cerr << "quad-mesher: cannot write " << opt.report << "\n";
    return false;
  }
  return true;
}

template <class K>
int run(const Options& opt)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  nlohmann::ordered_json report;
  nlohmann::ordered_json seconds;

  QM::Domain_2<K> domain;
  if(!read_input(opt, domain, seconds))
    return 1;

  const QM::Stage last = stop_after_stage(opt, domain);
  std::unique_ptr<QM::Quadtree_mesher_2<K>> plain;
  std::unique_ptr<QM::Boundary_layer_mesher_2<K>> layered;
  QM::Quad_mesh_2<typename K::Point_2> mesh;
  if(opt.boundary_layers > 0) {
    layered = std::make_unique<QM::Boundary_layer_mesher_2<K>>(domain, criteria_of<K>(opt, last),
                                                               layer_criteria_of(opt));
    if(opt.verbose)
      layered->set_round_observer([](const auto& f) { print_round(std::cerr, f); });
    mesh = layered->run();
  } else {
    plain = std::make_unique<QM::Quadtree_mesher_2<K>>(domain, criteria_of<K>(opt, last));
    if(opt.verbose) // as they end: a hard input can take minutes a round
      plain->set_round_observer([](const auto& f) { print_round(std::cerr, f); });
    mesh = plain->run(last);
  }
  // with boundary layers, the mesher of the domain outside the stacks
  const QM::Quadtree_mesher_2<K>& mesher = layered ? layered->outer_mesher() : *plain;
  if(mesher.number_of_merged_points() > 0)
    std::cerr << "quad-mesher: " << opt.input << ": merged " << mesher.number_of_merged_points()
              << " duplicate input point(s)\n";
  add_stage_times(opt, mesher, seconds);
  if(layered)
    for(const auto& stage : layered->timings()) seconds[stage.first] = stage.second;

  // runs past the clearance checked the whole mesh already (stage "check"), but for the stacks
  auto t = Clock::now();
  const QM::Mesh_quality_2 quality = mesher.quality() && !layered ? *mesher.quality() : QM::compute_quality(mesh);
  seconds["quality"] = seconds_since(t);

  t = Clock::now();
  Staged_outputs staged;
  if(!write_outputs(opt, domain, mesh, staged))
    return 1;
  seconds["write"] = seconds_since(t);
  seconds["total"] = seconds_since(start);

  fill_report(opt, domain, last, mesher, mesh, quality, report);
  if(layered)
    add_boundary_layers(opt, layered->report(), report);
  report["seconds"] = seconds;
  if(!write_report(opt, report, staged))
    return 1;
  if(const std::string failed = staged.commit(); !failed.empty()) {
    std::cerr << "quad-mesher: cannot write " << failed << "\n";
    return 1;
  }
  if(opt.verbose)
    for(const std::string& out : opt.outputs) std::cerr << "wrote " << out << "\n";
  std::cout << quality.number_of_quads << " quads, " << quality.number_of_vertices
            << " vertices, angles [" << quality.min_angle << ", " << quality.max_angle
            << "] deg, quadtree depth " << mesher.quadtree().depth() << ", " << seconds["total"].get<double>()
            << " s\n";
  if(!quality.is_valid()) {
    std::cerr << "quad-mesher: the mesh failed its validity check (see the report)\n";
    return 3;
  }
  if(last >= QM::Stage::BUFFER2 && mesher.buffer_report().bad_angle_quads > 0)
    return 4; // add_buffer() warned with the count and why the rounds ended
  return 0;
}

// sizes: finite and not negative (CLI's own check lets NaN through and prints inf in full)
CLI::Validator finite_size()
{
  return CLI::Validator(
    [](std::string& text) -> std::string {
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if(end == text.c_str() || *end != '\0' || !std::isfinite(v) || v < 0)
        return "must be a finite number, 0 or more, not '" + text + "'";
      return std::string();
    },
    "FINITE NONNEGATIVE");
}

// a whole number of cells (CLI's own check prints 0 in full and takes 1e20, beyond 64 bits)
CLI::Validator cell_budget()
{
  return CLI::Validator(
    [](std::string& text) -> std::string {
      errno = 0;
      char* end = nullptr;
      const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
      if(end == text.c_str() || *end != '\0' || text.find('-') != std::string::npos || errno == ERANGE || v < 1
         || v > max_cell_budget)
        return "must be a whole number from 1 to " + std::to_string(max_cell_budget) + ", not '" + text + "'";
      return std::string();
    },
    "1.." + std::to_string(max_cell_budget));
}

// the command line's options into `opt`; `spline_only` gets the options that apply only with
// --curves spline
void add_options(CLI::App& app, Options& opt, std::array<CLI::Option*, 2>& spline_only)
{
  app.add_option("input", opt.input,
                 "input: Triangle .poly or .node, a plain 'x y' point file (.xy .txt .pts .dat), "
                 "or WKT (.wkt); a point cloud (no segments) is meshed over its points' bounding "
                 "box with a margin of 1/8 of its larger side (1/10 to 3/20 above and right)")->required();
  app.add_option("-o,--output", opt.outputs,
                 "output file, format from the extension: .msh (Gmsh 4.1), .vtu (ParaView), .su2 "
                 "(SU2), .inp (Abaqus/CalculiX), .off, .svg (picture, quads coloured by their worst "
                 "angle); all but .off and .svg carry the boundary edges with their markers (the "
                 ".poly segment markers, else the loop numbers, outer loop 1); repeatable")
    ->required();
  app.add_option("--report", opt.report,
                 "write a JSON report: counts, angles, shape, validity, quadtree depth, seconds "
                 "per stage");
  app.add_option("--kernel", opt.kernel,
                 "CGAL kernel: epick (exact predicates, inexact constructions) or epeck (exact "
                 "constructions)")
    ->check(CLI::IsMember({ "epick", "epeck" }));
  app.add_option("--stop-after", opt.stop_after,
                 "last pipeline stage to run: 'quadtree' writes the strongly balanced, templated "
                 "quadtree mesh of the input's bounding grid, or of a point cloud's box with its "
                 "margin (paper Fig. 3(b)); 'points' (the "
                 "default for point clouds) also moves a vertex onto every point of a point cloud, or every "
                 "isolated point of a domain (paper §3, Lemma 1); 'clearance' (domains only) "
                 "keeps the core mesh clear of the boundary (paper §4.3, Fig. 3(c)); 'templates' opens the "
                 "core's notches and cuts its corners (§4.4); 'buffer1' adds the first buffer layer (§4.5); 'buffer2' "
                 "the second, reaching the boundary (§4.6); 'smoothing' (the default for domains) moves "
                 "vertices to bring angles nearer 90 degrees and splits interior vertices of 3 or 6 quads, "
                 "keeping every angle in [45, 135] in it")
    ->check(CLI::IsMember(stage_names()));
  app.add_flag("--merge-duplicates", opt.merge_duplicates,
               "in a point file (.node, x y), merge points given twice and report how many, "
               "instead of stopping at the first with its line numbers");
  app.add_option("--curves", opt.curves,
                 "how the input's loops are read: 'polygon' (as given) or 'spline' (closed cubic "
                 "splines through their points, decomposed into segments, paper §4.1)")
    ->check(CLI::IsMember({ "polygon", "spline" }));
  spline_only[0] = app.add_option("--max-turning-angle", opt.max_turning_angle,
                 "with --curves spline: largest turn between neighbouring segments, degrees")
    ->check(CLI::Range(0.1, 90.0)); // finer gives millions of boundary vertices on a circle
  spline_only[1] = app.add_option("--chord-error", opt.chord_error,
                 "with --curves spline: largest distance between a segment and its curve (0: 1e-3 "
                 "of the bounding-box diagonal)")
    ->check(finite_size());
  app.add_option("--max-size", opt.max_size,
                 "largest cell side (0: no bound); for a domain, of the cells meeting the bounding "
                 "box of its points")
    ->check(finite_size());
  app.add_option("--min-size", opt.min_size,
                 "smallest cell side (0: no bound); with --stop-after quadtree input points "
                 "closer than this may share a cell, with the points stage they are an error")
    ->check(finite_size());
  app.add_option("--max-depth", opt.max_depth,
                 "deepest quadtree level; a sizing that needs more is an error")
    ->check(CLI::Range(0, QM::Mesh_criteria_2<CGAL::Epick>::max_supported_depth));
  app.add_option("--max-cells", opt.max_cells,
                 "the cell budget: most quadtree cells to make before stopping with an error (a memory guard: "
                 "the quadtree takes about 110 bytes a cell)")
    ->check(cell_budget());
  app.add_option("--boundary-layers", opt.boundary_layers,
                 "boundary layers for CFD: this many quads stacked on every wall edge (with "
                 "--first-height and --growth); the walls are the holes' loops (the bodies in a far "
                 "field), or the outer loop of a domain without holes, or those of --wall-markers")
    ->check(CLI::Range(1, QM::Boundary_layer_criteria_2::max_layers));
  app.add_option("--first-height", opt.first_height,
                 "with --boundary-layers: the first layer's height (> 0)");
  app.add_option("--growth", opt.growth,
                 "with --boundary-layers: each layer's height over the one below (>= 1; default 1.2)");
  app.add_option("--wall-markers", opt.wall_markers,
                 "with --boundary-layers: the boundary markers of the walls' segments (whole loops), "
                 "comma-separated")
    ->delimiter(',');
  app.add_flag("-v,--verbose", opt.verbose, "print what each stage did and its time");
}

// The layer options need --boundary-layers, which needs a first height and the whole pipeline.
bool layer_options_are_consistent(const Options& opt, const CLI::App& app)
{
  if(opt.boundary_layers == 0) {
    for(const char* name : { "--first-height", "--growth", "--wall-markers" })
      if(app.count(name) > 0) {
        std::cerr << "quad-mesher: " << name << " applies only with --boundary-layers\n";
        return false;
      }
    return true;
  }
  if(app.count("--first-height") == 0) {
    std::cerr << "quad-mesher: --boundary-layers needs --first-height\n";
    return false;
  }
  try {
    layer_criteria_of(opt);
  } catch(const QM::Meshing_error& e) {
    std::cerr << "quad-mesher: " << e.what() << "\n";
    return false;
  }
  if(!opt.stop_after.empty() && opt.stop_after != "smoothing") {
    std::cerr << "quad-mesher: --boundary-layers needs the whole pipeline, not --stop-after " << opt.stop_after << "\n";
    return false;
  }
  return true;
}

// The spline options do nothing without splines: taking them silently would hide that.
bool spline_options_have_splines(const Options& opt, const std::array<CLI::Option*, 2>& spline_only)
{
  for(const CLI::Option* option : spline_only)
    if(option->count() > 0 && opt.curves != "spline") {
      std::cerr << "quad-mesher: " << option->get_name() << " applies only with --curves spline\n";
      return false;
    }
  return true;
}

// Never write over the input, and never write one file twice; every output's format known.
bool outputs_are_usable(const Options& opt)
{
  std::vector<std::string> targets = opt.outputs;
  if(!opt.report.empty())
    targets.push_back(opt.report);
  for(std::size_t a = 0; a < targets.size(); ++a) {
    if(same_file(targets[a], opt.input)) {
      std::cerr << "quad-mesher: output '" << targets[a] << "' is the input file\n";
      return false;
    }
    for(std::size_t b = 0; b < a; ++b)
      if(same_file(targets[a], targets[b])) {
        std::cerr << "quad-mesher: '" << targets[a] << "' is named twice as an output\n";
        return false;
      }
  }
  for(const std::string& out : opt.outputs) {
    const std::string ext = QM::IO::file_extension(out);
    if(std::find(output_extensions.begin(), output_extensions.end(), ext)
       == output_extensions.end()) {
      std::cerr << "quad-mesher: output '" << out
                << "': unknown format (use .msh, .vtu, .su2, .inp, .off or .svg)\n";
      return false;
    }
  }
  return true;
}

} // namespace

int main(int argc, char** argv)
{
  Options opt;
  CLI::App app{ "quad-mesher: all-quadrilateral meshes with guaranteed angles "
                "(quadtree method of Liang, Ebeida and Zhang, IMR 2009)" };
  std::array<CLI::Option*, 2> spline_only{};
  add_options(app, opt, spline_only);
  try {
    app.parse(argc, argv);
  } catch(const CLI::ParseError& e) {
    // CLI11 prints the message; its own codes (105, 106, ...) become the documented 2
    return app.exit(e) == 0 ? 0 : 2;
  }

  if(!spline_options_have_splines(opt, spline_only) || !outputs_are_usable(opt)
     || !layer_options_are_consistent(opt, app))
    return 2;
  try {
    if(opt.kernel == "epeck")
      return run<CGAL::Epeck>(opt);
    return run<CGAL::Epick>(opt);
  } catch(const QM::Meshing_error& e) {
    std::cerr << "quad-mesher: " << opt.input << ": " << e.what() << "\n";
    return 1;
  } catch(const std::bad_alloc&) {
    std::cerr << "quad-mesher: out of memory (try a larger --min-size or a smaller --max-depth)\n";
    return 1;
  }
}
