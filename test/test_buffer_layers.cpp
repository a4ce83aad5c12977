// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Buffer stages (paper §4.4-§4.6: TEMPLATES, BUFFER1, BUFFER2): the whole-domain mesh of
// hand-made and real domains checked independently of the library (exact orientation, own
// conformity and boundary-loop walk, exact on-boundary tests under Epeck), the stage-by-stage
// semantics, determinism, bad input, and the stable internal helpers of buffer_layers.h.

#include "qm2_mesh_checks.h"
#include "qm2_test_domains.h"
#include "qm2_test_kernel.h"

#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/IO/read_domain.h>
#include <CGAL/Quad_mesher_2/Meshing_error.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>
#include <CGAL/Quad_mesher_2/internal/buffer_layers.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Polygon_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace qm2_buffer_tests {

using qm2_test::K;
using Point = K::Point_2;
namespace QM = CGAL::Quad_mesher_2;
using Domain = QM::Domain_2<K>;
using Loops = QM::Domain_loops_2<K>;
using Mesh = QM::Quad_mesh_2<Point>;
using Mesher = QM::Quadtree_mesher_2<K>;
using QM::Stage;
using P2d = QM::internal::Point_2d;
using V2d = QM::internal::Vector_2d;

constexpr double pi = 3.14159265358979323846;

// ---- domains -------------------------------------------------------------------------------

using qm2_test::polygons;
using qm2_test::rectangle;
using qm2_test::disc;

Domain disc_domain() { return polygons({disc(0, 0, 1, 64)}); }

// a disc with a circular hole (hole seed point at its centre)
Domain disc_with_hole(double cx = 0, double r = 0.5, int hole_vertices = 32)
{
  return polygons({disc(0, 0, 1, 64), disc(cx, 0, r, hole_vertices)}, {Point(cx, 0)});
}

// a square with a square island (a hole of the domain: nested loops)
Domain square_with_island(double x0 = 0.2, double x1 = 0.8)
{
  return polygons({rectangle(0, 0, 1, 1), rectangle(x0, x0, x1, x1)}, {Point((x0 + x1) / 2, (x0 + x1) / 2)});
}

// three nested squares: the domain, a hole in it, and a piece of domain in the hole
Domain three_nested_squares(double s = 1)
{
  return polygons({rectangle(0, 0, 3 * s, 3 * s), rectangle(0.5 * s, 0.5 * s, 2.5 * s, 2.5 * s), rectangle(s, s, 2 * s, 2 * s)},
                  {Point(0.7 * s, 0.7 * s)});
}

// Two discs of radius 1 around (-1.5, 0) and (1.5, 0) joined by a channel of the given width
// along y = 0.
Domain two_discs(double width)
{
  std::vector<Point> p;
  const int n = 64;
  const double a = std::asin(width / 2);
  for(int i = 0; i <= n; ++i) {
    const double t = a + (2 * pi - 2 * a) * i / n;
    p.emplace_back(-1.5 + std::cos(t), std::sin(t));
  }
  for(int i = 0; i <= n; ++i) {
    const double t = pi + a + (2 * pi - 2 * a) * i / n;
    p.emplace_back(1.5 + std::cos(t), std::sin(t));
  }
  return polygons({p});
}

// a 32-gon 1e-4 across, 1e5 from the origin
Domain tiny_far_disc() { return polygons({disc(1e5, 1e5, 0.5e-4, 32)}); }

Domain read_or_fail(const std::string& file)
{
  Domain d;
  std::string err;
  EXPECT_TRUE(QM::IO::read_domain(file, d, &err)) << err;
  return d;
}

// a case of ../shared/data
Domain load(const std::string& relative) { return read_or_fail(std::string(QM2_SHARED_DATA_DIR) + "/" + relative); }

// a case of test/data
Domain load_test_data(const std::string& name) { return read_or_fail(std::string(QM2_TEST_DATA_DIR) + "/" + name); }

// ---- independent checks of a whole-domain mesh ---------------------------------------------

struct Figures
{
  std::size_t quads = 0, vertices = 0;
  double min_angle = 360, max_angle = 0;
  double share_45_135 = 0; // of all quad angles
  double area_error = 0;   // relative
  std::size_t boundary_cycles = 0;
  double seconds = 0;
};

double to_d(const K::FT& x) { return CGAL::to_double(x); }

// interior angle (degrees) of loop vertex k of loop l, the domain on the left
double interior_angle(const Domain& d, const Loops& loops, std::size_t l, std::size_t k)
{
  const auto& v = loops.loops[l].vertices;
  const std::size_t n = v.size();
  const Point& a = d.points[v[(k + n - 1) % n]];
  const Point& b = d.points[v[k]];
  const Point& c = d.points[v[(k + 1) % n]];
  const double ux = to_d(a.x()) - to_d(b.x()), uy = to_d(a.y()) - to_d(b.y());
  const double wx = to_d(c.x()) - to_d(b.x()), wy = to_d(c.y()) - to_d(b.y());
  // the angle from (b->c) counter-clockwise to (b->a): the domain's side
  double t = std::atan2(wx * uy - wy * ux, wx * ux + wy * uy) * 180 / pi;
  return t < 0 ? t + 360 : t;
}

// Checks every promise of a BUFFER2 mesh of domain `d`; returns the measured figures.
Figures check_whole_domain(const Domain& d, const Mesh& m, const std::string& name)
{
  SCOPED_TRACE(name);
  Figures f;
  f.quads = m.quads.size();
  f.vertices = m.points.size();
  const Loops loops = QM::extract_loops(d);
  EXPECT_GT(m.quads.size(), 0u);
  if(m.quads.empty()) return f;

  // conforming, every vertex used, no duplicates (double-based convexity inside)
  EXPECT_TRUE(qm2_checks::is_conforming(m));
  // the boundary edges (used once), found here whatever is_conforming says
  std::map<std::pair<std::size_t, std::size_t>, int> directed;
  for(const auto& q : m.quads)
    for(int c = 0; c < 4; ++c) ++directed[{q[c], q[(c + 1) % 4]}];
  std::vector<std::pair<std::size_t, std::size_t>> boundary;
  for(const auto& e : directed)
    if(directed.count({e.first.second, e.first.first}) == 0) boundary.push_back(e.first);
  {
    std::vector<bool> used(m.points.size(), false);
    for(const auto& q : m.quads)
      for(int c = 0; c < 4; ++c) used[q[c]] = true;
    std::size_t unused = 0;
    for(std::size_t v = 0; v < used.size(); ++v)
      if(!used[v] && unused++ < 5)
        ADD_FAILURE() << "vertex " << v << " (" << to_d(m.points[v].x()) << ", " << to_d(m.points[v].y())
                      << ") is in no quad";
    EXPECT_EQ(unused, 0u) << "unused vertices";
  }

  // every quad strictly convex and counter-clockwise: exact orientation of every corner
  const auto orientation = K().orientation_2_object();
  std::size_t not_left = 0;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c)
      if(orientation(m.points[m.quads[q][c]], m.points[m.quads[q][(c + 1) % 4]], m.points[m.quads[q][(c + 2) % 4]]) !=
         CGAL::LEFT_TURN) {
        if(not_left < 5)
          ADD_FAILURE() << "quad " << q << " corner " << (c + 1) % 4 << " at (" << to_d(m.points[m.quads[q][(c + 1) % 4]].x())
                        << ", " << to_d(m.points[m.quads[q][(c + 1) % 4]].y()) << ") is not a strict left turn";
        ++not_left;
      }
  EXPECT_EQ(not_left, 0u) << "corners that are not strict left turns (exact)";

  // bounding box and scale of the input
  double xmin = HUGE_VAL, xmax = -HUGE_VAL, ymin = HUGE_VAL, ymax = -HUGE_VAL;
  for(const Point& p : d.points) {
    xmin = (std::min)(xmin, to_d(p.x())); xmax = (std::max)(xmax, to_d(p.x()));
    ymin = (std::min)(ymin, to_d(p.y())); ymax = (std::max)(ymax, to_d(p.y()));
  }
  const double diag = std::hypot(xmax - xmin, ymax - ymin);
  const double magnitude = (std::max)((std::max)(std::abs(xmin), std::abs(xmax)), (std::max)(std::abs(ymin), std::abs(ymax)));

  // mesh vertices by their double coordinates (for exact look-ups of input points)
  std::multimap<std::pair<double, double>, std::size_t> by_xy;
  for(std::size_t v = 0; v < m.points.size(); ++v)
    by_xy.emplace(std::make_pair(to_d(m.points[v].x()), to_d(m.points[v].y())), v);
  auto is_mesh_vertex = [&](const Point& p) {
    auto range = by_xy.equal_range(std::make_pair(to_d(p.x()), to_d(p.y())));
    for(auto it = range.first; it != range.second; ++it)
      if(m.points[it->second] == p) return true;
    return false;
  };

  // every input corner (interior angle outside [160, 200]) is a mesh vertex, exactly
  std::size_t corners = 0, missing = 0;
  for(std::size_t l = 0; l < loops.loops.size(); ++l)
    for(std::size_t k = 0; k < loops.loops[l].vertices.size(); ++k) {
      const double a = interior_angle(d, loops, l, k);
      if(a >= 160 - 1e-9 && a <= 200 + 1e-9) continue;
      ++corners;
      const Point& p = d.points[loops.loops[l].vertices[k]];
      if(!is_mesh_vertex(p)) {
        if(missing < 5)
          ADD_FAILURE() << "input corner " << loops.loops[l].vertices[k] << " (" << to_d(p.x()) << ", " << to_d(p.y())
                        << "), interior angle " << a << ", is not a mesh vertex";
        ++missing;
      }
    }
  EXPECT_EQ(missing, 0u) << "of " << corners << " input corners";

  // every boundary vertex lies on the input boundary (exactly under Epeck; within 1e-12 of
  // the coordinates' magnitude under Epick), and both ends of a boundary edge on one loop
  std::vector<K::Segment_2> segs;
  std::vector<std::size_t> seg_loop;
  for(std::size_t l = 0; l < loops.loops.size(); ++l) {
    const auto& v = loops.loops[l].vertices;
    for(std::size_t k = 0; k < v.size(); ++k) {
      segs.emplace_back(d.points[v[k]], d.points[v[(k + 1) % v.size()]]);
      seg_loop.push_back(l);
    }
  }
  const double tol = 1e-12 * (diag + magnitude);
  std::map<std::size_t, std::set<std::size_t>> loops_of; // boundary vertex -> loops it lies on
  std::size_t off_boundary = 0;
  auto locate = [&](std::size_t v) {
    if(loops_of.count(v)) return;
    std::set<std::size_t>& on = loops_of[v];
    const Point& p = m.points[v];
    const double px = to_d(p.x()), py = to_d(p.y());
    for(std::size_t s = 0; s < segs.size(); ++s) {
      const double ax = to_d(segs[s].source().x()), ay = to_d(segs[s].source().y());
      const double bx = to_d(segs[s].target().x()), by = to_d(segs[s].target().y());
      if(px < (std::min)(ax, bx) - 1e-6 * diag || px > (std::max)(ax, bx) + 1e-6 * diag ||
         py < (std::min)(ay, by) - 1e-6 * diag || py > (std::max)(ay, by) + 1e-6 * diag)
        continue;
      bool hit;
      if(qm2_test::exact_constructions)
        hit = segs[s].has_on(p); // exact
      else
        hit = std::sqrt(to_d(CGAL::squared_distance(p, segs[s]))) <= tol;
      if(hit) on.insert(seg_loop[s]);
    }
    if(on.empty()) {
      double nearest = HUGE_VAL;
      for(const auto& seg : segs) nearest = (std::min)(nearest, std::sqrt(to_d(CGAL::squared_distance(p, seg))));
      if(off_boundary < 5)
        ADD_FAILURE() << "mesh boundary vertex " << v << " (" << px << ", " << py
                      << ") is not on the input boundary (" << nearest << " from it)";
      ++off_boundary;
    }
  };
  std::size_t split_edges = 0, far_chords = 0;
  for(const auto& e : boundary) {
    locate(e.first);
    locate(e.second);
    const auto& A = loops_of[e.first];
    const auto& B = loops_of[e.second];
    bool common = false;
    for(std::size_t l : A) common = common || B.count(l) != 0;
    if(!A.empty() && !B.empty() && !common) ++split_edges;
    // the edge is a chord of its loop: its midpoint within 1e-3 of the diagonal of it
    const double mx = (to_d(m.points[e.first].x()) + to_d(m.points[e.second].x())) / 2;
    const double my = (to_d(m.points[e.first].y()) + to_d(m.points[e.second].y())) / 2;
    double best = HUGE_VAL;
    for(const auto& s : segs) best = (std::min)(best, std::sqrt(to_d(CGAL::squared_distance(Point(mx, my), s))));
    if(best > 1e-3 * diag * (1 + 1e-9)) ++far_chords;
  }
  EXPECT_EQ(off_boundary, 0u) << "mesh boundary vertices off the input boundary";
  EXPECT_EQ(split_edges, 0u) << "mesh boundary edges joining two different loops";
  EXPECT_EQ(far_chords, 0u) << "mesh boundary edges farther than 1e-3 of the diagonal from the input boundary";

  // the boundary is simple closed loops, as many as the domain's, turning the same way
  std::map<std::size_t, std::size_t> next;
  std::map<std::size_t, int> into;
  std::size_t branching = 0;
  for(const auto& e : boundary) {
    if(next.count(e.first)) ++branching;
    next[e.first] = e.second;
    ++into[e.second];
  }
  for(const auto& x : into) branching += x.second > 1 ? 1 : 0;
  EXPECT_EQ(branching, 0u) << "boundary vertices with more than two boundary edges";
  std::set<std::size_t> seen;
  std::size_t ccw = 0, cw = 0;
  for(const auto& e : boundary) {
    if(seen.count(e.first)) continue;
    double area2 = 0;
    const Point& o = m.points[e.first];
    std::size_t v = e.first, steps = 0;
    while(!seen.count(v) && next.count(v) && steps <= boundary.size()) {
      seen.insert(v);
      const std::size_t w = next[v];
      area2 += to_d((m.points[v].x() - o.x()) * (m.points[w].y() - o.y()) - (m.points[w].x() - o.x()) * (m.points[v].y() - o.y()));
      v = w;
      ++steps;
    }
    ++f.boundary_cycles;
    (area2 > 0 ? ccw : cw) += 1;
  }
  std::size_t outer = 0;
  for(const auto& l : loops.loops) outer += l.is_outer ? 1 : 0;
  EXPECT_EQ(f.boundary_cycles, loops.loops.size()) << "mesh boundary loops vs the domain's";
  EXPECT_EQ(ccw, outer) << "counter-clockwise mesh boundary loops vs the domain's outer loops";
  EXPECT_EQ(cw, loops.loops.size() - outer) << "clockwise mesh boundary loops vs the domain's holes";

  // area: within 2e-3 relative of the domain's (chords may cut off vertices turning < 20°,
  // within the chord tolerance; the two discs' 64-gons lose up to 1.5e-3 of their area with
  // cells of 2 s_i at loop vertices, under 1e-3 with cells of s_i)
  const double domain_area = to_d(QM::domain_area(d, loops));
  double area = 0;
  for(std::size_t q = 0; q < m.quads.size(); ++q) area += qm2_checks::signed_area(m, q);
  f.area_error = std::abs(area - domain_area) / domain_area;
  EXPECT_LE(f.area_error, 2e-3) << "mesh area " << area << " vs domain area " << domain_area;

  // angles
  std::size_t good = 0, all = 0;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) {
      const double a = qm2_checks::corner_angle(m, q, c);
      f.min_angle = (std::min)(f.min_angle, a);
      f.max_angle = (std::max)(f.max_angle, a);
      good += a >= 45 - 1e-9 && a <= 135 + 1e-9 ? 1 : 0;
      ++all;
    }
  f.share_45_135 = double(good) / double(all);
  return f;
}

void print(const std::string& name, const Figures& f, int rounds)
{
  std::printf("[buffer] %-28s %s: %zu quads, %zu vertices, angles [%.2f, %.2f], in [45,135]: %.4f, "
              "area error %.2e, %zu loops, %d round(s), %.3f s\n",
              name.c_str(), qm2_test::exact_constructions ? "epeck" : "epick", f.quads, f.vertices, f.min_angle,
              f.max_angle, f.share_45_135, f.area_error, f.boundary_cycles, rounds, f.seconds);
}

// Meshes `d` to BUFFER2 and checks it; returns the figures (and the mesh, in `out` if given:
// empty after a Meshing_error, which fails the test).
Figures mesh_and_check(const Domain& d, const std::string& name, const QM::Mesh_criteria_2<K>& criteria = QM::Mesh_criteria_2<K>(),
                       Mesh* out = nullptr)
{
  Mesher mesher(d, criteria);
  const auto start = std::chrono::steady_clock::now();
  Mesh m;
  try {
    m = mesher.run(Stage::BUFFER2);
  } catch(const QM::Meshing_error& e) {
    ADD_FAILURE() << name << ": " << e.what();
    return Figures();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Figures f = check_whole_domain(d, m, name);
  f.seconds = seconds;
  print(name, f, mesher.rounds());
  if(out != nullptr) *out = std::move(m);
  return f;
}

// ---- 1. BUFFER2 meshes the whole domain -----------------------------------------------------
//
// Validity, conformity, corners, boundary and area are the product's promise and are checked
// in full on every domain. Angles: only the disc has every angle in [45, 135] today (asserted);
// elsewhere the share of all quad angles in [45, 135] is asserted against the share measured
// with buffer_layers.h of commit 9d349a3 (+ work in progress), minus a margin of about 0.02:
// a regression of the buffer layers' angles fails these.

TEST(Buffer_layers, disc_is_meshed_with_all_angles_in_45_135)
{
  const Figures f = mesh_and_check(disc_domain(), "disc");
  EXPECT_GE(f.min_angle, 45 - 1e-9);
  EXPECT_LE(f.max_angle, 135 + 1e-9);
}

TEST(Buffer_layers, disc_with_a_circular_hole)
{
  // centred and off-centre holes, 32- and 64-gons
  for(const auto& h : std::vector<std::array<double, 3>>{{0, 0.4, 32}, {0.1, 0.3, 64}, {0.1, 0.5, 64}}) {
    const Figures f = mesh_and_check(disc_with_hole(h[0], h[1], int(h[2])),
                                     "disc with hole " + std::to_string(h[0]) + " " + std::to_string(h[1]) + " " +
                                       std::to_string(int(h[2])));
    EXPECT_GE(f.share_45_135, 0.98); // measured 1.0000, 0.9948, 0.9979
  }
}

TEST(Buffer_layers, square_with_a_square_island)
{
  const Figures f = mesh_and_check(square_with_island(), "square with island");
  EXPECT_GE(f.share_45_135, 0.96); // measured 0.9814 (0.9988 at 9d349a3)
}

TEST(Buffer_layers, three_nested_squares)
{
  const Figures f = mesh_and_check(three_nested_squares(), "three nested squares");
  EXPECT_GE(f.share_45_135, 0.94); // measured 0.9650
  // closer loops (at 9d349a3: "1 buffer quads are not convex ... after 8 refinement rounds")
  const Figures g = mesh_and_check(polygons({rectangle(0, 0, 1, 1), rectangle(0.2, 0.2, 0.8, 0.8), rectangle(0.4, 0.4, 0.6, 0.6)},
                                            {Point(0.3, 0.3)}),
                                   "unit square, hole, island");
  EXPECT_GE(g.share_45_135, 0.95); // measured 0.9772
}

TEST(Buffer_layers, two_discs_joined_by_a_thin_channel)
{
  // (0.1 at 9d349a3: "1 buffer quads are not convex ... after 8 refinement rounds")
  for(double width : {0.05, 0.1, 0.3}) {
    const Figures f = mesh_and_check(two_discs(width), "two discs, channel " + std::to_string(width));
    EXPECT_GE(f.share_45_135, 0.98); // measured 0.9999 (0.05), 0.9998 (0.1), 1.0000 (0.3)
  }
}

TEST(Buffer_layers, tiny_domain_far_from_the_origin)
{
  const Figures f = mesh_and_check(tiny_far_disc(), "1e-4 disc at 1e5");
  EXPECT_GE(f.share_45_135, 0.89); // measured 0.9591 (Epick), 0.9440 (Epeck)
}

// Far from the origin a double holds few digits of a small domain's edges: the kites of
// template 1(b), at exactly 225 degrees, came out up to 6e-4 degrees over on a disc 1e-4
// across at 1e5 with a hole, and 29 of them were split as if jammed (72 counted out of
// Lemma 2). What rounding can do to an angle there is not a miss.
TEST(Buffer_layers, rounding_far_from_the_origin_is_no_lemma_2_miss)
{
  const Domain d = polygons({ disc(1e5, 1e5, 5e-5, 120), disc(1e5 + 1e-5, 1e5, 1.5e-5, 40) }, { Point(1e5 + 1e-5, 1e5) });
  Mesher mesher(d);
  mesher.run(Stage::TEMPLATES);
  EXPECT_EQ(mesher.buffer_report().split_corners, 0u);
  EXPECT_EQ(mesher.buffer_report().buffer_angles_out, 0u);
}

// Holes 1e-8 to 1e-7 across in a unit square: before, the buffer's collapse guard (1e-8 of
// the diagonal) forbade every edge this small, refinement rounds grew the mesh to 600k quads
// in 40 s and the 2e-8 and 3e-8 holes failed; the quadtree now also stops at cells whose
// vertices the whole-mesh check could not tell apart (depth_limit() says so).
TEST(Buffer_layers, tiny_holes_in_a_unit_square)
{
  for(double r : { 1e-8, 2e-8, 3e-8, 7e-8 }) {
    const Domain d = polygons({ rectangle(0, 0, 1, 1), disc(0.5, 0.5, r, 8) }, { Point(0.5, 0.5) });
    Mesher mesher(d); // keeps a reference to d
    const std::string name = "hole of radius " + std::to_string(r);
    Mesh m;
    try {
      m = mesher.run(Stage::BUFFER2);
    } catch(const QM::Meshing_error& e) {
      ADD_FAILURE() << name << ": " << e.what();
      continue;
    }
    const Figures f = check_whole_domain(d, m, name);
    EXPECT_LT(f.quads, 5000u) << name; // measured 1483 to 2136
    EXPECT_LE(mesher.rounds(), 3) << name;
    EXPECT_GE(f.share_45_135, 0.999) << name;
    EXPECT_NE(mesher.quadtree().depth_limit().find("too small to tell their vertices apart"), std::string::npos)
      << mesher.quadtree().depth_limit();
  }
}

TEST(Buffer_layers, triangle_A)
{
  const Figures f = mesh_and_check(load("triangle_A/triangle_A.poly"), "triangle A");
  EXPECT_GE(f.share_45_135, 0.98); // measured 0.9979
}

TEST(Buffer_layers, naca0012)
{
  const Figures f = mesh_and_check(load("naca0012/naca0012.poly"), "naca0012");
  EXPECT_GE(f.share_45_135, 0.98); // measured 0.9942
}

// Off-centre holes once left a new boundary point off the input boundary: on a chord across a
// left-out vertex (0.061 from the boundary), then, under Epeck, rounded to doubles (7e-18).
// New boundary points now always lie on an input edge, and a node is taken out of the chain
// only while the chord across it stays within the tolerance.
TEST(Buffer_layers, disc_with_an_off_centre_32_gon_hole)
{
  mesh_and_check(disc_with_hole(0.1, 0.4, 32), "disc with hole 0.1 0.4 32");
}

TEST(Buffer_layers, disc_with_an_off_centre_64_gon_hole)
{
  mesh_and_check(disc_with_hole(0.1, 0.4, 64), "disc with hole 0.1 0.4 64");
}

// ---- the angle guarantee on smooth domains (issue 4's cases) ---------------------------------
// Each needs the boundary band of uniform cells, the first buffer points moved towards
// projection quads and the angle refinement rounds: without any of them some angle leaves
// [45, 135] (measured before them: 96, 295 and 16 angles out).

std::vector<Point> wavy_blob()
{
  std::vector<Point> p;
  for(int i = 0; i < 120; ++i) {
    const double t = 2 * pi * i / 120;
    const double r = 1 + 0.25 * std::sin(3 * t) + 0.1 * std::cos(5 * t);
    p.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return p;
}

// two unit discs 4 apart joined by a straight channel 0.02 wide
std::vector<Point> dumbbell()
{
  const double a = std::asin(0.01);
  std::vector<Point> p;
  for(int i = 0; i <= 128; ++i) {
    const double t = -pi + a + (2 * pi - 2 * a) * i / 128;
    p.emplace_back(2 + std::cos(t), std::sin(t));
  }
  for(int i = 0; i <= 128; ++i) {
    const double t = a + (2 * pi - 2 * a) * i / 128;
    p.emplace_back(-2 + std::cos(t), std::sin(t));
  }
  return p;
}

void expect_angles_45_135(const Figures& f, const std::string& name)
{
  EXPECT_GE(f.min_angle, 45 - 1e-9) << name;
  EXPECT_LE(f.max_angle, 135 + 1e-9) << name;
}

TEST(Buffer_layers, blob_with_two_holes_meets_45_135)
{
  const Domain d = polygons({ wavy_blob(), disc(0.3, 0.2, 0.15, 32), disc(-0.4, -0.3, 0.1, 24) },
                            { Point(0.3, 0.2), Point(-0.4, -0.3) });
  // a fan at a dense run of input vertices reached 168 degrees before the angle rounds
  expect_angles_45_135(mesh_and_check(d, "wavy blob, two holes"), "wavy blob");
}

// Coarse regular polygons: their vertices turn by less than the feature angle but lie too
// far off any chord to be left out, and are about as many as the first buffer points. Each
// must end an F point's edge; as the middle of a fan of boundary edges it gave a quad with
// its own angle (8 quads at 165 degrees on the 24-gon, 1 to 13 on every n from 18 to 48).
TEST(Buffer_layers, coarse_regular_polygons_meet_45_135)
{
  for(int n : { 18, 21, 24, 29, 33, 40, 48 })
    expect_angles_45_135(mesh_and_check(polygons({ disc(0, 0, 1, n) }), std::to_string(n) + "-gon"),
                         std::to_string(n) + "-gon");
  const Domain holed = polygons({ disc(0, 0, 1, 24), disc(0.1, 0, 0.4, 20) }, { Point(0.1, 0) });
  expect_angles_45_135(mesh_and_check(holed, "24-gon with a 20-gon hole"), "24-gon with a 20-gon hole");
}

// A coarse blob: n vertices about the unit circle, each turned by up to 0.3 of the even
// spacing and its radius off by up to `amplitude` (the generator's raw output, not a
// distribution: the same polygons on every library). Their vertices turn by 0 to 40 degrees,
// many kept for the chord tolerance with no F point projecting onto them.
std::vector<Point> coarse_blob(std::mt19937& random, int n, double amplitude)
{
  auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * (double(random()) / 4294967296.0); };
  std::vector<Point> p;
  for(int k = 0; k < n; ++k) {
    const double t = 2 * pi * (k + uniform(-0.3, 0.3)) / n, r = 1 + amplitude * uniform(-1, 1);
    p.emplace_back(r * std::cos(t), r * std::sin(t));
  }
  return p;
}

// A boundary node between two others in one quad (the middle of a fan of boundary edges)
// keeps the boundary's own angle there, which no later move changes: the strip's pairing costs
// it a hundred degrees more, and kept loop vertices take over projection nodes where it is
// left. Before, 9 of these 40 blobs had an angle out of range, up to 163.8 degrees.
TEST(Buffer_layers, coarse_irregular_polygons_meet_45_135)
{
  std::mt19937 random(7);
  for(int i = 0; i < 40; ++i) {
    const int n = 10 + int(random() % 36);
    const double amplitude = 0.02 + 0.13 * (double(random()) / 4294967296.0);
    const std::string name = "blob " + std::to_string(i) + " (" + std::to_string(n) + " vertices)";
    expect_angles_45_135(mesh_and_check(polygons({ coarse_blob(random, n, amplitude) }), name), name);
  }
}

// A sector of the unit disc with apex angle alpha at the origin (its arc turning 5 degrees
// or less per edge): the corner cases of paper §5 around 45, 135, 180 and 270 degrees and a
// near cusp. Every one must give a valid mesh with the apex a vertex; the angles are printed.
// Those that meet [45, 135] today must keep doing so.
Domain sector(double alpha_degrees)
{
  const int n = (std::max)(4, int(std::ceil(alpha_degrees / 5)));
  std::vector<Point> p{ Point(0, 0) };
  for(int k = 0; k <= n; ++k) {
    const double t = (-alpha_degrees / 2 + alpha_degrees * k / n) * pi / 180;
    p.emplace_back(std::cos(t), std::sin(t));
  }
  return polygons({ p });
}

TEST(Buffer_layers, corner_cases_give_valid_meshes)
{
  // 1, 2 and 5 degrees: needles (their sides sized as a narrowing channel; without it the
  // first two failed after 8 rounds and the third took 28731 quads)
  for(double alpha : { 1.0, 2.0, 5.0, 44.0, 46.0, 90.0, 134.0, 136.0, 179.0, 181.0, 269.0, 271.0, 300.0, 359.0 }) {
    const std::string name = "sector " + std::to_string(int(alpha));
    const Figures f = mesh_and_check(sector(alpha), name);
    // from 46 degrees up every angle is in range since the strip's extra chain nodes (before:
    // only 90, 136, 269 and 300; the 181-degree sector had 0.9565 of its angles in range
    // before the rotated bisectors, 0.9995 before the extra nodes)
    if(alpha > 45.0)
      expect_angles_45_135(f, name);
  }
}

// the (quad, corner) pairs of the mesh vertex at `p`
std::vector<std::pair<std::size_t, int>> corners_at(const Mesh& m, const Point& p)
{
  std::vector<std::pair<std::size_t, int>> result;
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c)
      if(m.points[m.quads[q][c]] == p) result.emplace_back(q, c);
  return result;
}

// Paper §5, Fig. 8(b): an apex under 45 degrees is one quad, which keeps the input's angle and
// has its other angles in [alpha, 180 - alpha]. Two quads shared such a tip before the strip's
// extra chain nodes (Lake Superior's 15-degree corner: 4.6 and 10.4 degrees).
// Only the apex's own angle is forced: the apex quad's other three (they sum to 360 - alpha)
// fit in [45, 135]. While the strip's cost allowed them [alpha, 180 - alpha] the 6, 10 and
// 11.5-degree apexes kept 136.5, 140.6 and 156.3 degrees there (bird's 11.5-degree tip:
// 138.8); while a sliding point kept a tenth of its edge from its neighbours, apexes under 6
// degrees did too (the node beside the apex could not reach the F point it pairs with).
TEST(Buffer_layers, acute_corners_are_spanned_by_one_quad)
{
  for(double alpha : { 1.0, 2.0, 5.0, 6.0, 10.0, 11.5, 15.0, 30.0, 44.0 }) {
    const std::string name = "sector " + std::to_string(alpha);
    SCOPED_TRACE(name);
    Mesh m;
    mesh_and_check(sector(alpha), name, QM::Mesh_criteria_2<K>(), &m);
    if(m.quads.empty()) continue;
    const auto apex = corners_at(m, Point(0, 0));
    ASSERT_EQ(apex.size(), 1u);
    const auto [q, c] = apex.front();
    EXPECT_NEAR(qm2_checks::corner_angle(m, q, c), alpha, 1e-6);
    for(int j = 1; j < 4; ++j) {
      const double a = qm2_checks::corner_angle(m, q, (c + j) % 4);
      EXPECT_GE(a, 45 - 1e-9);
      EXPECT_LE(a, 135 + 1e-9);
    }
  }
}

// A thin island spike in a box: its tip is a corner of 360 - width degrees on the domain's side.
Domain box_with_spiked_island(double width_degrees)
{
  const double h = std::tan(width_degrees * pi / 360);
  std::vector<Point> island{ Point(6, 5 - 2 * h), Point(8, 5), Point(6, 5 + 2 * h) };
  for(int i = 2; i <= 10; ++i) // the rest of a unit circle about (5, 5), clockwise: a hole
    island.emplace_back(5 + std::cos(2 * pi * i / 12), 5 + std::sin(2 * pi * i / 12));
  return polygons({ { Point(0, 0), Point(10, 0), Point(10, 10), Point(0, 10) }, island }, { Point(5, 5) });
}

// the angles at mesh vertex `corner` of the quads around it
std::vector<double> angles_at(const Mesh& m, const Point& corner)
{
  std::vector<double> angles;
  for(const auto& [q, c] : corners_at(m, corner)) angles.push_back(qm2_checks::corner_angle(m, q, c));
  return angles;
}

// Paper §5, Fig. 8(d): a corner over 270 degrees is split by a fan of at least three quads, each
// within [45, 135]. Before the fan the strip gave such a corner two quads (170 degrees each at
// the NACA 0012 trailing edge) and the 2-degree spike failed after 8 rounds. Until the
// pairing could place extra chain nodes in any gap, the spikes of 2 and 30 degrees kept a
// corner angle of 149 and 165 degrees (and the 1-degree spike 137); until corners from 225
// degrees got fans, the 20-degree spike's had 156.
TEST(Buffer_layers, corners_over_270_degrees_get_a_fan_within_45_135)
{
  std::vector<std::pair<std::string, std::pair<Domain, Point>>> cases;
  for(double width : { 1.0, 2.0, 6.0, 10.0, 20.0, 30.0 })
    cases.push_back({ "spike " + std::to_string(int(width)), { box_with_spiked_island(width), Point(8, 5) } });
  cases.push_back({ "naca0012 sharp trailing edge", { load("naca0012/naca0012_sharp.poly"), Point(1, 0) } });
  cases.push_back({ "sector 300", { sector(300), Point(0, 0) } });
  cases.push_back({ "sector 359", { sector(359), Point(0, 0) } });
  for(const auto& c : cases) {
    SCOPED_TRACE(c.first);
    const Domain& d = c.second.first;
    const Point& corner = c.second.second;
    ASSERT_NE(std::find(d.points.begin(), d.points.end(), corner), d.points.end());
    Mesh m;
    mesh_and_check(d, c.first, QM::Mesh_criteria_2<K>(), &m);
    if(m.quads.empty()) continue;
    const std::vector<double> angles = angles_at(m, corner);
    EXPECT_GE(angles.size(), 3u);
    std::string list;
    for(double a : angles) {
      EXPECT_GE(a, 45 - 1e-9);
      EXPECT_LE(a, 135 + 1e-9);
      list += " " + std::to_string(a);
    }
    std::printf("[buffer] %-28s %s: %zu quads, angles at the corner:%s\n", c.first.c_str(),
                qm2_test::exact_constructions ? "epeck" : "epick", m.quads.size(), list.c_str());
  }
}

// Corners from 225 to 270 degrees get a fan of three quads too: two would each take 112.5 to
// 135 degrees and their split is never even (the guitar's exactly perpendicular notch at
// (33.3, 7.42) gave 110 and 160 degrees); three take 75 or more each. An L's notch is exactly
// 270 degrees (270.0000000000003 in doubles: the test before, over 270 + 1e-6, missed it).
TEST(Buffer_layers, corners_of_225_to_270_degrees_get_a_fan_of_three)
{
  std::vector<std::pair<std::string, std::pair<Domain, Point>>> cases;
  const std::vector<Point> l_shape{ Point(0, 0), Point(4, 0), Point(4, 1), Point(1, 1), Point(1, 3), Point(0, 3) };
  cases.push_back({ "L notch", { polygons({ l_shape }), Point(1, 1) } });
  for(double alpha : { 250.0, 269.0 })
    cases.push_back({ "sector " + std::to_string(int(alpha)), { sector(alpha), Point(0, 0) } });
  for(const auto& c : cases) {
    SCOPED_TRACE(c.first);
    Mesh m;
    const Figures f = mesh_and_check(c.second.first, c.first, QM::Mesh_criteria_2<K>(), &m);
    if(m.quads.empty()) continue;
    const std::vector<double> angles = angles_at(m, c.second.second);
    EXPECT_EQ(angles.size(), 3u);
    for(double a : angles) {
      EXPECT_GE(a, 45 - 1e-9);
      EXPECT_LE(a, 135 + 1e-9);
    }
    expect_angles_45_135(f, c.first);
  }
  // the guitar: 17 angles out before, all at its corners of 225 to 300 degrees
  expect_angles_45_135(mesh_and_check(load("guitar/guitar.poly"), "guitar"), "guitar");
}

// The multi-element air foils of ../shared/data (read when present): every angle in
// [45, 135]. The notches filled by apply_connectivity_templates() must leave alone a notch facing a corner
// that needs a fan of three (one next to the 30P30N main element's 355-degree trailing edge
// took the fan's room: a 179.9-degree quad in a later round) and notches from 95 degrees (a
// fill over airfoil_3elem_jigsaw's 101-degree notch at (0.5, 0.906) gave 2 angles out).
// Without the two rules airfoil_3elem_jigsaw has angles in [44.55, 164.16].
TEST(Buffer_layers, multi_element_airfoils_meet_45_135)
{
  for(const std::string name : { "airfoil_30p30n/airfoil_30p30n.poly", "airfoil_3elem_jigsaw/airfoil_3elem_jigsaw.poly" }) {
    if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
      GTEST_SKIP() << "no " << name << " in the shared data";
    expect_angles_45_135(mesh_and_check(load(name), name), name);
  }
}

// `d` turned by `degrees` and scaled by `scale` about the centroid of its points (as a user
// sets an air foil's angle of attack), in the order of operations of the sweeps that found
// the cases below, so that their doubles are the same
Domain turned_about_centroid(Domain d, double degrees, double scale)
{
  double cx = 0, cy = 0;
  for(const Point& p : d.points) { cx += to_d(p.x()); cy += to_d(p.y()); }
  cx /= double(d.points.size());
  cy /= double(d.points.size());
  const double turn = degrees * (pi / 180), c = scale * std::cos(turn), s = scale * std::sin(turn);
  auto move = [&](const Point& p) {
    const double x = to_d(p.x()) - cx, y = to_d(p.y()) - cy;
    return Point(cx + c * x - s * y, cy + s * x + c * y);
  };
  for(Point& p : d.points) p = move(p);
  for(Point& p : d.holes) p = move(p);
  return d;
}

// A comb of 7 prongs 0.7 wide, slits 0.3 between them (issue 26's comb, with slots no power of
// two wide): turned, its mesh is about the unturned one's, without pockets of fine cells.
// Turned 33 degrees, a blob of cells a tenth of a slit wide stood at one top corner of every
// prong (the narrow-region rule read the next prong's collinear top as across the domain):
// 1978 quads against 1334 unturned. Whole pipeline: angles, aspect ratio 5 at most.
TEST(Buffer_layers, a_turned_comb_has_no_pockets)
{
  std::vector<Point> outline = { Point(0, 0), Point(6.7, 0) };
  for(int k = 6; k >= 0; --k) {
    outline.insert(outline.end(), { Point(k + 0.7, 3), Point(k, 3) });
    if(k > 0) outline.insert(outline.end(), { Point(k, 1), Point(k - 0.3, 1) });
  }
  const Domain comb = polygons({ outline });
  const std::size_t unturned = Mesher(comb).run().quads.size();
  for(double degrees : { 7.0, 20.0, 33.0, 45.0, 61.0 }) {
    SCOPED_TRACE(degrees);
    const Domain turned = turned_about_centroid(comb, degrees, 1);
    const Mesh m = Mesher(turned).run();
    const QM::Mesh_quality_2 q = QM::compute_quality(m);
    EXPECT_TRUE(q.is_valid());
    EXPECT_GE(q.min_angle, 45 - 1e-9);
    EXPECT_LE(q.max_angle, 135 + 1e-9);
    EXPECT_LE(q.max_aspect_ratio, 5);
    EXPECT_LE(double(m.quads.size()), 1.2 * double(unturned)) << m.quads.size() << " against " << unturned;
  }
}

// The 30P30N turned about its vertices' centroid and scaled by 1.37 (as a user sets an angle
// of attack): turned 11 degrees, in its third round two elements' buffer nodes met across a
// slot, a hanging node the whole-mesh check found but no buffer check asked to refine, and
// the rounds ended on the second round, 3 quads out (42.5 degrees). Such places are refined
// now. Since the sliding points' wider reach that turn meets no such round; turned 113
// degrees, rounds 3 and 4 were refined for the check alone, and since slits of the outside
// are sized by their own width, turned 85 degrees and scaled by 7.3, round 2 was. Since the
// requests of one round refine one level together, none of 1800 positions meets such a round
// (even turns by 1, 2, 5 and 10, odd turns to 179 degrees by 1.37, 3.1 and 7.3): every round
// that does must ask for cells.
TEST(Buffer_layers, where_the_whole_mesh_check_fails_is_refined)
{
  const std::string name = "airfoil_30p30n/airfoil_30p30n.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain d = turned_about_centroid(load(name), 85, 7.3);
  Mesher mesher(d);
  const Mesh m = mesher.run(Stage::BUFFER2);
  expect_angles_45_135(check_whole_domain(d, m, "30P30N turned 85, x7.3"), "30P30N turned 85, x7.3");
  for(const auto& r : mesher.round_figures()) {
    if(!r.valid && r.invalid_quads == 0) {
      EXPECT_GT(r.refinement_requests, 0u) << "round " << r.round;
    }
  }
}

// A reflex tip's fan of three: its outer F points came from the core and left the middle quad
// too much of the corner, and no refinement round balanced it. The
// 30P30N turned 123 degrees and scaled by 7.3 (about the origin): slivers of 28.6 degrees at
// a slat cusp; the 3-element air foil turned 41 degrees and scaled by 7.3 about its vertices'
// centroid: 103, 144 and 73 degrees at a 320-degree trailing edge. The outer F points now
// turn about the corner.
TEST(Buffer_layers, fans_at_reflex_tips_turn_their_outer_points)
{
  const std::string slats = "airfoil_30p30n/airfoil_30p30n.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + slats))
    GTEST_SKIP() << "no " << slats << " in the shared data";
  Domain d = load(slats);
  const double turn = 123 * (pi / 180), c = std::cos(turn), s = std::sin(turn);
  auto move = [&](const Point& p) {
    const double x = to_d(p.x()), y = to_d(p.y());
    return Point(7.3 * (c * x - s * y), 7.3 * (s * x + c * y));
  };
  for(Point& p : d.points) p = move(p);
  for(Point& p : d.holes) p = move(p);
  expect_angles_45_135(mesh_and_check(d, "30P30N turned 123, x7.3"), "30P30N turned 123, x7.3");
  const std::string three = "airfoil_3elem_jigsaw/airfoil_3elem_jigsaw.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + three))
    GTEST_SKIP() << "no " << three << " in the shared data";
  expect_angles_45_135(mesh_and_check(turned_about_centroid(load(three), 41, 7.3), "3-element turned 41, x7.3"),
                       "3-element turned 41, x7.3");
}

// no angle of `m` over 135 degrees, and every one under 45 at an input point of `d`, within
// `slack` degrees
void expect_45_135_but_at_input_corners(const Domain& d, const Mesh& m, const std::string& label, double slack = 1e-9)
{
  const std::set<Point> input(d.points.begin(), d.points.end());
  for(std::size_t q = 0; q < m.quads.size(); ++q)
    for(int c = 0; c < 4; ++c) {
      const double a = qm2_checks::corner_angle(m, q, c);
      EXPECT_LE(a, 135 + slack) << label << ": quad " << q;
      if(a < 45 - slack) {
        EXPECT_TRUE(input.count(m.points[m.quads[q][c]]) != 0) << label << ": " << a << " degrees off the input corners";
      }
    }
}

// The bird (../shared/data, skipped when absent) and its mirror image: every angle under 45
// degrees is at an input corner (its tips, 11.5 degrees the sharpest), and none is over 135,
// the sharp corners' quads included. The mirrored bird kept 137.4 degrees in the quad
// spanning its 11.5-degree tip while that quad's other angles counted less beyond [45, 135].
TEST(Buffer_layers, bird_and_its_mirror_image_meet_45_135_but_at_sharp_corners)
{
  const std::string name = "bird/bird.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  Domain mirrored = load(name);
  for(Point& p : mirrored.points) p = Point(-p.x(), p.y());
  for(Point& p : mirrored.holes) p = Point(-p.x(), p.y());
  for(const auto& [domain, label] : { std::make_pair(load(name), std::string("bird")),
                                      std::make_pair(mirrored, std::string("mirrored bird")) }) {
    Mesh m;
    mesh_and_check(domain, label, QM::Mesh_criteria_2<K>(), &m);
    expect_45_135_but_at_input_corners(domain, m, label);
  }
}

// Meshes a random domain of test/data through the buffer stages with `mesher` and checks the
// whole mesh: valid and conforming, every angle in [45, 135] but at input corners (within
// `slack` degrees), and no buffer quad reported out.
void expect_random_case_meets_45_135(Mesher& mesher, const Domain& d, const std::string& label, double slack = 1e-9)
{
  ASSERT_FALSE(d.points.empty()) << label;
  const Mesh m = mesher.run(Stage::BUFFER2);
  check_whole_domain(d, m, label);
  expect_45_135_but_at_input_corners(d, m, label, slack);
  EXPECT_EQ(mesher.buffer_report().bad_angle_quads, 0u) << label;
}

// A random 2-opt polygon with a 2.9-degree needle and a hole (random_domains.py --seed 1,
// domain 22): the node beside the needle's tip, kept a tenth of the tip's long edge from the
// next node, left 22.5 and 157.5 degrees beside the tip round after round (exit status 4).
TEST(Buffer_layers, a_needle_tip_node_slides_up_to_the_quads_it_serves)
{
  const Domain d = load_test_data("random_twoopt_1_22.poly");
  Mesher mesher(d);
  expect_random_case_meets_45_135(mesher, d, "random 2-opt needle");
}

// A random 2-opt polygon with five holes and a 2.8-degree spike, 2.8e-3 across at (-1717,
// 2064) (random_sweep.py --seed 3, domain 97): a quad with three boundary nodes in a row on
// one input edge, whose middle one only slides along it, stayed at 179.993 degrees round
// after round (exit status 4), the coordinates' rounding passing it as convex, so the strip's
// pairing did not take its middle node out. Epick only (about 3 s).
TEST(Buffer_layers, a_flat_fan_far_from_the_origin_is_taken_out)
{
  if(qm2_test::exact_constructions)
    GTEST_SKIP() << "the Epick run covers it (3 s)";
  const Domain d = load_test_data("random_twoopt_3_97.poly");
  Mesher mesher(d);
  // within the verifier's slack: one angle is 45 - 9.4e-8, the coordinates' rounding there
  expect_random_case_meets_45_135(mesher, d, "random 2-opt far from the origin", 1e-7);
}

// A convex 82-gon with four holes, 4.2e6 from the origin with cells of 0.0156 there
// (random_domains.py --seed 11, domain 50): doubles hold its angles to about 4e-6 degrees.
// The optimiser counted a quad out of [45, 135] only 1e-6 degrees past the bound, the final
// check (as the verifier) 1e-7 past it: it moved a core vertex to make an angle of
// 135.00000037 degrees, and five refinement rounds left that quad out (exit 4). It now
// counts a quad out as the check does (two rounds; three since slits of the outside are
// sized by their own width, four since the requests of one round refine one level together).
TEST(Buffer_layers, the_optimiser_counts_an_angle_out_as_the_final_check_does)
{
  const Domain d = load_test_data("random_convex_11_50.poly");
  Mesher mesher(d);
  expect_random_case_meets_45_135(mesher, d, "random convex polygon far from the origin", 1e-7);
  EXPECT_LE(mesher.rounds(), 4);
}

// A random 2-opt polygon with two holes, 1.7e5 from the origin (random_domains.py --seed 19,
// domain 16): a loop vertex of 161 degrees (no corner: it turns by less than the feature
// angle) was the middle node of a fan of boundary edges, a quad of 161 degrees there that
// no move can open; the pairing paid a hundred degrees more for it and chose it round after
// round (exit 4). Such a fan now costs as a flat corner: two rounds, none out (three since
// the quadtree's boundary band narrowed to one cell along straight stretches: the first
// round's core is cut by a narrow passage, the second is the two-round mesh's first).
TEST(Buffer_layers, a_wide_loop_vertex_is_not_the_middle_of_a_fan)
{
  const Domain d = load_test_data("random_twoopt_19_16.poly");
  Mesher mesher(d);
  expect_random_case_meets_45_135(mesher, d, "random 2-opt with a wide loop vertex", 1e-7);
  EXPECT_LE(mesher.rounds(), 3);
}

// Corners over 270 degrees whose fans may take four F points: a strip took four at all of
// them or at none, by the cost of its whole loop; each corner now takes what pairs the quads
// about it better. A convex 76-gon with three holes (random_domains.py --seed 11, domain 23)
// had two such corners on one strip, one taking four; since slits of the outside are sized
// by their own width its core no longer has them. A convex 12-gon with five holes (seed 1,
// domain 59) had five, one taking four, until the requests of one round refined one level
// together. A convex 17-gon with four holes, 9.5e6 from the origin (random_domains.py
// --seed 1, domain 62), had two, one taking four, until the quadtree's boundary band narrowed
// to one cell along straight stretches. A star of 188 vertices with a hole, 6.9e6 from the
// origin (random_domains.py --seed 11, domain 36), has two on one strip, one taking four.
TEST(Buffer_layers, the_corners_of_one_strip_take_four_fan_points_one_by_one)
{
  const Domain d = load_test_data("random_star_11_36.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  const Mesh m = mesher.run(Stage::BUFFER2);
  check_whole_domain(d, m, "random convex polygon with reflex corners");
  const QM::Buffer_report& report = mesher.buffer_report();
  EXPECT_EQ(report.bad_angle_quads, 0u);
  EXPECT_GE(report.fans_that_may_take_four, 2u);
  EXPECT_GT(report.fans_of_four, 0u);
  EXPECT_LT(report.fans_of_four, report.fans_that_may_take_four);
}

// The same domain up to the templates: 2.8e-3 across at 2.7e3 from the origin, its angles are
// known to about 1e-3 degrees on its finest cells, and the template searches followed the
// coordinates' rounding, step after step of a few units in the last place, each lowering the
// excesses by 1e-7 degrees: 1368 core vertices moved and the stage took 0.20 s (Epick).
// Gains under the angles' rounding are none: 407 vertices move, in 0.03 s, with 17 buffer-side
// angles left out of Lemma 2's range instead of 20.
TEST(Buffer_layers, template_searches_far_from_the_origin_stop_at_the_rounding)
{
  const Domain d = load_test_data("random_twoopt_3_97.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  mesher.run(Stage::TEMPLATES);
  EXPECT_LE(mesher.buffer_report().searched_vertices, 600u);
  EXPECT_LE(mesher.buffer_report().buffer_angles_out, 20u);
}

// A random star with notches of 290 to 330 degrees (random_domains.py --seed 5, domain 31):
// the middle quad of a notch's fan of three starts flat (as wide as 161.6 degrees at the
// corner and at its F point). Moving the F point alone leaves the corner's angle the worst,
// turning the fan's outer points alone leaves the F point's: the optimiser kept neither
// until a move could lower the angles' excess with the worst unchanged. Then every fan of
// three opens in the first round; before, four stayed out and waited for refinement rounds.
// Since slits of the outside are sized by their own width, one notch's first core leaves it
// a fan of two (not the optimiser's part): a round refines it, and every fan is in the end.
TEST(Buffer_layers, a_fan_at_a_notch_opens_in_the_first_round)
{
  const Domain d = load_test_data("random_star_5_31.poly");
  ASSERT_FALSE(d.points.empty());
  const Loops loops = QM::extract_loops(d);
  Mesher mesher(d);
  mesher.build_quadtree();
  Mesh first = mesher.core_mesh();
  mesher.clear_buffer_zone(first);
  mesher.fill_buffer_zone(first);
  const Mesh last = mesher.run(Stage::BUFFER2);
  std::size_t notches = 0, first_round_fans = 0;
  for(std::size_t l = 0; l < loops.loops.size(); ++l)
    for(std::size_t k = 0; k < loops.loops[l].vertices.size(); ++k) {
      if(interior_angle(d, loops, l, k) <= 270) continue;
      ++notches;
      const Point& corner = d.points[loops.loops[l].vertices[k]];
      const std::string where = "(" + std::to_string(to_d(corner.x())) + ", " + std::to_string(to_d(corner.y())) + ")";
      for(const Mesh* m : std::array<const Mesh*, 2>{ &first, &last }) {
        const auto fan = corners_at(*m, corner);
        if(m == &first && fan.size() < 3) continue;
        first_round_fans += m == &first;
        EXPECT_GE(fan.size(), 3u) << "notch at " << where;
        for(const auto& [q, c] : fan)
          for(int j = 0; j < 4; ++j) {
            const double a = qm2_checks::corner_angle(*m, q, j);
            EXPECT_TRUE(a >= 45 - 1e-9 && a <= 135 + 1e-9) << a << " degrees in the fan at " << where;
          }
      }
    }
  EXPECT_GE(notches, 4u);
  EXPECT_GE(first_round_fans + 1, notches);
}

// Lake Superior (from ../shared/data, skipped when absent) moved by (2^20, -2^20), which only
// rounds its coordinates, and mirrored or turned a quarter there: every angle in [45, 135]
// but at its 15-degree corner. Moved, it kept 157.9 degrees; turned, the 15-degree tip's quad
// kept 159 to 161 round after round: the points beside the tip could not slide, since their
// chain neighbours, a 1e-10 off their short edge's line by rounding, were more than 1e-9 of
// the edge's length off it.
TEST(Buffer_layers, lake_superior_far_from_the_origin_meets_45_135_but_at_its_sharp_corner)
{
  const std::string name = "lake_superior/lake_superior.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain lake = load(name);
  for(int variant = 0; variant < 4; ++variant) {
    const bool mirrored = variant % 2 == 1, turned = variant >= 2;
    auto moved = [&](const Point& p) {
      const K::FT x = mirrored ? -p.x() : p.x();
      return turned ? Point(-p.y() + 1048576, x - 1048576) : Point(x + 1048576, p.y() - 1048576);
    };
    Domain d = lake;
    for(Point& p : d.points) p = moved(p);
    for(Point& p : d.holes) p = moved(p);
    const std::string label = std::string("Lake Superior moved") + (mirrored ? ", mirrored" : "") + (turned ? ", turned" : "");
    Mesh m;
    mesh_and_check(d, label, QM::Mesh_criteria_2<K>(), &m);
    expect_45_135_but_at_input_corners(d, m, label, 1e-7); // the buffer check's slack
  }
}

// the loops of `d` but its first (the outer one) whose vertices all lie in the box, as holes
// (with their hole points) in that box, or in `frame` if given
Domain islands_in_box(const Domain& d, double x0, double x1, double y0, double y1,
                      const CGAL::Bbox_2* frame = nullptr)
{
  Domain out;
  const CGAL::Bbox_2 box = frame != nullptr ? *frame : CGAL::Bbox_2(x0, y0, x1, y1);
  out.points = { Point(box.xmin(), box.ymin()), Point(box.xmax(), box.ymin()), Point(box.xmax(), box.ymax()),
                 Point(box.xmin(), box.ymax()) };
  out.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 } };
  std::vector<std::size_t> next(d.points.size(), std::size_t(-1));
  for(const auto& s : d.segments) next[s[0]] = s[1];
  std::vector<bool> seen(d.points.size(), false);
  bool outer = true;
  for(const auto& s : d.segments) {
    if(seen[s[0]]) continue;
    std::vector<std::size_t> loop;
    for(std::size_t v = s[0]; !seen[v]; v = next[v]) { seen[v] = true; loop.push_back(v); }
    const bool inside = std::all_of(loop.begin(), loop.end(), [&](std::size_t v) {
      const Point& p = d.points[v];
      return p.x() > x0 && p.x() < x1 && p.y() > y0 && p.y() < y1;
    });
    if(std::exchange(outer, false) || !inside) continue;
    CGAL::Polygon_2<K> polygon;
    const std::size_t base = out.points.size();
    for(std::size_t k = 0; k < loop.size(); ++k) {
      out.points.push_back(d.points[loop[k]]);
      polygon.push_back(d.points[loop[k]]);
      out.segments.push_back({ base + k, base + (k + 1) % loop.size() });
    }
    for(const Point& h : d.holes)
      if(polygon.bounded_side(h) == CGAL::ON_BOUNDED_SIDE) out.holes.push_back(h);
  }
  return out;
}

// Twelve Bahamas islands (from ../shared/data, skipped when absent) in a box: every angle
// under 45 degrees is at an input corner and none is over 135. A 294-degree island tip at
// (-77.86802, 24.28109) kept a fan of two, with 167 degrees in one quad, round after round:
// the pairing took two quads of about 147 degrees over a fan of three whose middle F point was
// flat for the moment (wide_side_of_reflex_fan()).
TEST(Buffer_layers, twelve_bahamas_islands_meet_45_135_but_at_sharp_corners)
{
  const std::string name = "bahamas_islands/bahamas_islands.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain d = islands_in_box(load(name), -78.1, -77.8, 24.1, 24.4);
  ASSERT_EQ(d.holes.size(), 12u);
  Mesh m;
  mesh_and_check(d, "twelve Bahamas islands", QM::Mesh_criteria_2<K>(), &m);
  // the buffer's final check's slack (Buffer_layers::verifier_slack, verify_mesh.py's):
  // coordinates near 78 with cells of 1e-6 hold an angle to about 1e-9 degrees
  expect_45_135_but_at_input_corners(d, m, "twelve Bahamas islands", 1e-7);
}

// Two Bahamas islands where they lie, in the bounding box of all 276 (so that the quadtree's
// lattice, and with it the strips, are as in the whole file). The island's 281-degree tip at
// (-77.94317, 24.33101) ends a straight coast along which the ladder of projection quads
// cannot switch phase; with three F points on the tip's node that phase left the pairing a
// fan of two (145.9 degrees, every refinement round; 146.0 in the whole file). Four F points
// make a fan of three in either phase (may_take_four_fan_points()).
TEST(Buffer_layers, a_reflex_tip_after_a_straight_coast_gets_a_fan_of_three)
{
  const std::string name = "bahamas_islands/bahamas_islands.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain all = load(name);
  const CGAL::Bbox_2 bbox = CGAL::bbox_2(all.points.begin(), all.points.end());
  const Domain d = islands_in_box(all, -77.96, -77.83, 24.31, 24.40, &bbox);
  ASSERT_EQ(d.holes.size(), 2u);
  Mesh m;
  mesh_and_check(d, "two Bahamas islands", QM::Mesh_criteria_2<K>(), &m);
  expect_45_135_but_at_input_corners(d, m, "two Bahamas islands", 1e-7);
  const auto tip = std::find_if(d.points.begin(), d.points.end(), [](const Point& p) {
    return std::abs(CGAL::to_double(p.x()) + 77.94317) < 1e-5 && std::abs(CGAL::to_double(p.y()) - 24.33101) < 1e-5;
  });
  ASSERT_NE(tip, d.points.end());
  EXPECT_EQ(angles_at(m, *tip).size(), 3u);
}

// A unit square with 64 square holes [i/8 + 1/32, i/8 + 3/32]^2: corners of 90 and 270
// degrees only, on the quadtree's lattice. Seven 270-degree hole corners kept a fan of two
// (134.8 and 135.2 degrees) round after round: a corner of exactly 270 (to rounding) was not
// yet one that a fan of two leaves out of range (a reviewer's find).
TEST(Buffer_layers, a_grid_of_square_holes_meets_45_135)
{
  std::vector<std::vector<Point>> loops{ rectangle(0, 0, 1, 1) };
  std::vector<Point> seeds;
  for(int i = 0; i < 8; ++i)
    for(int j = 0; j < 8; ++j) {
      loops.push_back(rectangle(i / 8.0 + 1 / 32.0, j / 8.0 + 1 / 32.0, i / 8.0 + 3 / 32.0, j / 8.0 + 3 / 32.0));
      seeds.emplace_back(i / 8.0 + 1 / 16.0, j / 8.0 + 1 / 16.0);
    }
  expect_angles_45_135(mesh_and_check(polygons(loops, seeds), "64 square holes"), "64 square holes");
}

TEST(Buffer_layers, dumbbell_with_a_narrow_channel_meets_45_135)
{
  expect_angles_45_135(mesh_and_check(polygons({ dumbbell() }, {}), "dumbbell"), "dumbbell");
}

// Arms 0.126 and 0.13 wide turned near 45 degrees (an L and a cross): about 4.2 cells across,
// where the clearance left a staircase one cell thick and peeled it whole from the arm's dead
// end. The core stopped 0.3 short of the end and one buffer quad spanned the rest (19.9
// degrees at the L's end; the refinement at its corners never brought the core back, six
// rounds). Refining over such a quad's whole area does, in one more round.
std::vector<Point> turned(const std::vector<std::array<double, 2>>& p, double degrees)
{
  const double c = std::cos(degrees * pi / 180), s = std::sin(degrees * pi / 180);
  std::vector<Point> q;
  for(const auto& xy : p) q.emplace_back(c * xy[0] - s * xy[1], s * xy[0] + c * xy[1]);
  return q;
}

// an L with arms of width w and length 1, and a cross of arms w wide, 2 across
std::vector<std::array<double, 2>> ell(double w)
{
  return { { 0, 0 }, { 1, 0 }, { 1, w }, { w, w }, { w, 1 }, { 0, 1 } };
}
std::vector<std::array<double, 2>> cross(double w)
{
  const double a = w / 2;
  return { { -1, -a }, { -a, -a }, { -a, -1 }, { a, -1 }, { a, -a }, { 1, -a },
           { 1, a },   { a, a },   { a, 1 },   { -a, 1 }, { -a, a }, { -1, a } };
}

TEST(Buffer_layers, arms_turned_near_45_degrees_meet_45_135)
{
  for(const auto& [name, width, degrees] :
      std::vector<std::tuple<std::string, double, double>>{ { "L", 0.13, 45.37 }, { "L", 0.13, 45.87 },
                                                            { "L", 0.126, 45.87 }, { "L", 0.126, 26.37 },
                                                            { "cross", 0.13, 45.37 }, { "cross", 0.13, 44.37 },
                                                            { "cross", 0.126, 44.37 }, { "cross", 0.126, 45.87 } }) {
    const std::string label = name + " " + std::to_string(width) + " turned " + std::to_string(degrees);
    const Domain d = polygons({ turned(name == "L" ? ell(width) : cross(width), degrees) });
    expect_angles_45_135(mesh_and_check(d, label), label);
  }
}

// A round whose buffer has invalid quads refines at their corners only. Requests over the
// whole area of the invalid quads (752 not convex across a thin hole's flat side, many
// spanning tens of cells) asked for 1.8 million cells: the cell budget error after 18 s and
// 1.5 GB, or with fewer requests 939061 quads; at the corners the next rounds give 71170
// quads, all within [45, 135]. About 12 s: Epick only.
TEST(Buffer_layers, an_invalid_round_refines_at_its_invalid_quads_only)
{
  if(qm2_test::exact_constructions)
    GTEST_SKIP() << "the Epick run covers it (12 s)";
  const Domain d = load_test_data("ellipse_holes_250.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  Mesh m;
  ASSERT_NO_THROW(m = mesher.run(Stage::BUFFER2));
  const Figures f = check_whole_domain(d, m, "disc with thin elliptic holes");
  expect_angles_45_135(f, "disc with thin elliptic holes");
  EXPECT_LT(f.quads, 100000u);
  for(const auto& r : mesher.round_figures()) {
    if(!r.valid && r.invalid_quads > 0) {
      EXPECT_LE(r.refinement_requests, 8 * r.invalid_quads) << "round " << r.round;
    }
  }
}

// The rounds say why they ended with quads out: the first L above, at most 6 levels deep
// (its arms' ends need 7), cannot be refined where its quads are out.
TEST(Buffer_layers, the_rounds_say_why_they_end)
{
  const Domain d = polygons({ turned(ell(0.13), 45.37) });
  Mesher shallow(d, QM::Mesh_criteria_2<K>(0, 0, 6));
  shallow.run(Stage::BUFFER2);
  EXPECT_GT(shallow.buffer_report().bad_angle_quads, 0u);
  EXPECT_EQ(shallow.rounds_end(), Mesher::Rounds_end::FINEST_CELLS);
  Mesher deep(d);
  deep.run(Stage::BUFFER2);
  EXPECT_EQ(deep.buffer_report().bad_angle_quads, 0u);
  EXPECT_EQ(deep.rounds_end(), Mesher::Rounds_end::NONE);
}

// An ellipse 1 long and 0.03 wide (semi-axes), 200 points: a thin sliver whose strips are
// long ladders. Before each gap of the strip could take an extra chain node, the pairing had
// to shear them (363 angles out, as wide as [11.4, 180.0]).
TEST(Buffer_layers, thin_elliptic_sliver_meets_45_135)
{
  std::vector<Point> p;
  for(int i = 0; i < 200; ++i) {
    const double t = 2 * pi * i / 200;
    p.emplace_back(std::cos(t), 0.03 * std::sin(t));
  }
  expect_angles_45_135(mesh_and_check(polygons({ p }, {}), "sliver 1 x 0.03"), "sliver");
}

TEST(Buffer_layers, tiny_disc_far_from_the_origin_meets_45_135)
{
  std::vector<Point> p;
  for(const Point& q : disc(0, 0, 0.5e-4, 64)) p.emplace_back(1e5 + q.x(), 1e5 + q.y());
  expect_angles_45_135(mesh_and_check(polygons({ p }, {}), "disc 1e-4 at 1e5"), "far disc");
}

// An island with straight sides split into collinear runs and a reflex notch: the strip near
// (6.37, 7.64) paired a flat fan of boundary nodes; taking its middle node out made the
// triangle count odd, the node came back, and every refinement round ended with "1 buffer
// quads are not convex ... after 8 refinement rounds" (both kernels; as in bahamas_islands).
TEST(Buffer_layers, island_with_collinear_runs_has_no_flat_fan)
{
  const std::vector<Point> island = {
    Point(9.392282422062733, 7.328923306226726), Point(8.61043742449289, 7.779162563781551),
    Point(7.828592426923048, 8.229401821336376), Point(7.3266418115836345, 8.752670225955875),
    Point(6.8246911962442205, 9.275938630575375), Point(6.834851917625443, 8.953711717099033),
    Point(6.845012639006665, 8.63148480362269), Point(6.855173360387887, 8.309257890146348),
    Point(6.8653340817691095, 7.987030976670007), Point(5.691853889358281, 6.916383993904188),
    Point(5.941887473391832, 6.63238124883526), Point(6.191921057425382, 6.348378503766332),
    Point(6.441954641458931, 6.064375758697404), Point(6.691988225492482, 5.780373013628475),
    Point(7.837980670092542, 6.774900650501053)
  };
  const Figures f = mesh_and_check(polygons({ rectangle(0, 0, 10, 10), island }, { Point(7.5, 7.5) }),
                                   "island with collinear runs");
  EXPECT_GT(f.quads, 0u);
  EXPECT_GE(f.share_45_135, 0.99); // measured 0.9992
}

// Lake Superior: too slow for a unit test (Epick: 7871 quads, 2 rounds, 2.2 s; at 9d349a3
// 15.7 s, nearly all in Buffer_layers::pair_strip, and a vertex in no quad).
TEST(Buffer_layers, DISABLED_lake_superior)
{
  const Figures f = mesh_and_check(load("lake_superior/lake_superior.poly"), "lake superior");
  EXPECT_GE(f.share_45_135, 0.97);
  EXPECT_LT(f.seconds, 2.0);
}

// ---- 2. stage semantics ---------------------------------------------------------------------

// the directed boundary edges (used by one quad) of a quad list
std::vector<std::pair<std::size_t, std::size_t>> boundary_edges(const std::vector<std::array<std::size_t, 4>>& quads)
{
  std::set<std::pair<std::size_t, std::size_t>> directed;
  for(const auto& q : quads)
    for(int c = 0; c < 4; ++c) directed.insert({q[c], q[(c + 1) % 4]});
  std::vector<std::pair<std::size_t, std::size_t>> b;
  for(const auto& e : directed)
    if(!directed.count({e.second, e.first})) b.push_back(e);
  return b;
}

// exact: every corner of every quad a strict left turn
std::size_t corners_not_left(const Mesh& m)
{
  const auto orientation = K().orientation_2_object();
  std::size_t bad = 0;
  for(const auto& q : m.quads)
    for(int c = 0; c < 4; ++c)
      bad += orientation(m.points[q[c]], m.points[q[(c + 1) % 4]], m.points[q[(c + 2) % 4]]) != CGAL::LEFT_TURN;
  return bad;
}

// the buffer-side angle at each core boundary vertex, by vertex (degrees; the core on the
// left of its boundary, so the buffer is on the right)
std::map<std::size_t, double> buffer_side_angles_at(const Mesh& m)
{
  const auto b = boundary_edges(m.quads);
  std::map<std::size_t, std::size_t> prev;
  for(const auto& e : b) prev[e.second] = e.first;
  std::map<std::size_t, double> angles;
  for(const auto& e : b)
    angles[e.first] = QM::internal::right_side_angle(QM::internal::to_point_2d(m.points[prev[e.first]]),
                                                     QM::internal::to_point_2d(m.points[e.first]),
                                                     QM::internal::to_point_2d(m.points[e.second]));
  return angles;
}

std::vector<double> buffer_side_angles(const Mesh& m)
{
  std::vector<double> angles;
  for(const auto& [v, beta] : buffer_side_angles_at(m)) angles.push_back(beta);
  return angles;
}

void check_stages(const Domain& d, const std::string& name, std::size_t min_moved)
{
  SCOPED_TRACE(name);
  Mesher mesher(d);
  const Mesh clearance = mesher.run(Stage::CLEARANCE);
  ASSERT_EQ(mesher.rounds(), 1);
  ASSERT_TRUE(qm2_checks::is_conforming(clearance));

  // TEMPLATES: the same quads, core boundary vertices moved (notches out, corners in), core
  // angles kept; a new quad (and point) over each notch that could not move
  const Mesh templates = mesher.run(Stage::TEMPLATES);
  ASSERT_EQ(mesher.rounds(), 1); // else the quadtree differs and nothing below compares
  // these cores have no jammed corner to split (a split replaces a quad: see
  // a_jammed_convex_corner_is_split_in_three)
  ASSERT_EQ(mesher.buffer_report().split_corners, 0u);
  const std::size_t filled = mesher.buffer_report().filled_notches;
  ASSERT_EQ(templates.quads.size(), clearance.quads.size() + filled);
  EXPECT_TRUE(std::equal(clearance.quads.begin(), clearance.quads.end(), templates.quads.begin()));
  ASSERT_EQ(templates.points.size(), clearance.points.size() + filled);
  EXPECT_TRUE(qm2_checks::is_conforming(templates));
  EXPECT_EQ(corners_not_left(templates), 0u);
  const auto range = qm2_checks::angle_range(templates);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
  std::set<std::size_t> on_boundary;
  for(const auto& e : boundary_edges(clearance.quads)) on_boundary.insert(e.first);
  std::size_t moved = 0, moved_inside = 0;
  for(std::size_t v = 0; v < clearance.points.size(); ++v)
    if(templates.points[v] != clearance.points[v]) {
      ++moved;
      moved_inside += on_boundary.count(v) == 0;
    }
  const auto& report = mesher.buffer_report();
  const std::size_t reported = report.moved_notches + report.cut_corners + report.searched_vertices;
  EXPECT_EQ(moved_inside, report.shaped_interior) << "interior core vertices moved";
  EXPECT_GE(moved, min_moved);
  EXPECT_GE(reported, moved); // a vertex may move in more than one pass
  EXPECT_LE(reported, 3 * moved);
  // each new quad: the unmoved notch, its neighbour on the boundary (or an earlier new
  // quad's point), the new point, the other neighbour
  auto on_boundary_or_new = [&](std::size_t v) { return on_boundary.count(v) || v >= clearance.points.size(); };
  for(std::size_t q = clearance.quads.size(); q < templates.quads.size(); ++q) {
    const auto& Q = templates.quads[q];
    EXPECT_TRUE(on_boundary.count(Q[0]) && on_boundary_or_new(Q[1]) && on_boundary_or_new(Q[3])) << "quad " << q;
    EXPECT_GE(Q[2], clearance.points.size()) << "quad " << q;
  }
  std::size_t notches_before = 0, notches_after = 0;
  for(double a : buffer_side_angles(clearance)) notches_before += a < 112.5 - 1e-9;
  for(double a : buffer_side_angles(templates)) notches_after += a < 112.5 - 1e-9;
  EXPECT_LT(notches_after, notches_before);
  std::printf("[buffer] stages %-20s %s: %zu core quads, %zu boundary vertices, %zu moved (%zu reported), "
              "%zu filled, notches %zu -> %zu\n",
              name.c_str(), qm2_test::exact_constructions ? "epeck" : "epick", clearance.quads.size(),
              on_boundary.size(), moved, reported, filled, notches_before, notches_after);

  // BUFFER1: one quad per core boundary vertex, on the core's boundary, off the input's (a
  // filled notch's new point took its place on the boundary: as many as before)
  const Mesh first = mesher.run(Stage::BUFFER1);
  ASSERT_EQ(mesher.rounds(), 1);
  std::set<std::size_t> on_core_boundary;
  for(const auto& e : boundary_edges(templates.quads)) on_core_boundary.insert(e.first);
  EXPECT_EQ(on_core_boundary.size(), on_boundary.size());
  const std::size_t added = mesher.buffer_report().first_layer_quads;
  EXPECT_EQ(added, on_core_boundary.size());
  ASSERT_EQ(first.quads.size(), templates.quads.size() + added);
  EXPECT_EQ(first.points.size(), templates.points.size() + added);
  EXPECT_TRUE(std::equal(templates.quads.begin(), templates.quads.end(), first.quads.begin()));
  EXPECT_TRUE(qm2_checks::is_conforming(first));
  EXPECT_EQ(corners_not_left(first), 0u);
  // each new quad has two core boundary vertices and two new ones
  for(std::size_t q = templates.quads.size(); q < first.quads.size(); ++q) {
    int core = 0;
    for(int c = 0; c < 4; ++c) core += on_core_boundary.count(first.quads[q][c]) ? 1 : 0;
    EXPECT_EQ(core, 2) << "first-layer quad " << q;
  }
  // its boundary neither touches nor crosses the input boundary (exact predicates), and
  // every new vertex is strictly inside the domain
  const Loops loops = QM::extract_loops(d);
  std::vector<K::Segment_2> segs;
  for(const auto& s : d.segments) segs.emplace_back(d.points[s[0]], d.points[s[1]]);
  std::size_t touching = 0;
  for(const auto& e : boundary_edges(first.quads)) {
    const K::Segment_2 edge(first.points[e.first], first.points[e.second]);
    for(const auto& s : segs) touching += CGAL::do_intersect(edge, s) ? 1 : 0;
  }
  EXPECT_EQ(touching, 0u) << "first-layer boundary edge / input segment pairs that meet";
  std::vector<CGAL::Polygon_2<K>> polys;
  for(const auto& l : loops.loops) polys.push_back(QM::loop_polygon_2(d, l));
  std::size_t outside = 0;
  for(std::size_t v = templates.points.size(); v < first.points.size(); ++v) {
    int inside = 0;
    for(const auto& poly : polys) inside += poly.bounded_side(first.points[v]) == CGAL::ON_BOUNDED_SIDE;
    outside += inside % 2 == 0;
  }
  EXPECT_EQ(outside, 0u) << "first buffer points not strictly inside the domain";

  // BUFFER2: the whole domain
  const Mesh whole = mesher.run(Stage::BUFFER2);
  const Figures f = check_whole_domain(d, whole, name + " buffer2");
  EXPECT_GT(f.quads, first.quads.size());
}

// a square of side 2 |half| about (cx, cy), turned by `degrees`
std::vector<Point> turned_square(double cx, double cy, double half, double degrees)
{
  std::vector<Point> p;
  for(int k = 0; k < 4; ++k) {
    const double t = (degrees + 45 + 90 * k) * pi / 180;
    p.emplace_back(cx + half * std::sqrt(2.0) * std::cos(t), cy + half * std::sqrt(2.0) * std::sin(t));
  }
  return p;
}

// the angle (degrees) from the direction of segment (a, b) to the domain's boundary nearest its
// middle, the boundary's loops run with the domain on their left (the core's boundary has the
// core on its left); at a loop vertex the smaller of the angles to its two edges
double boundary_edge_angle(const Domain& d, const Loops& loops, const P2d& a, const P2d& b)
{
  const P2d m = CGAL::midpoint(a, b);
  const V2d e = b - a;
  auto angle_to = [&](const V2d& t) {
    return std::atan2(CGAL::determinant(e, t), CGAL::scalar_product(e, t)) * 180 / pi;
  };
  double best_distance = HUGE_VAL, angle = 0;
  for(const auto& loop : loops.loops) {
    const std::size_t n = loop.vertices.size();
    auto xy = [&](std::size_t k) { return QM::internal::to_point_2d(d.points[loop.vertices[k % n]]); };
    for(std::size_t k = 0; k < n; ++k) {
      const P2d p = xy(k), q = xy(k + 1);
      const double t = QM::internal::nearest_segment_parameter(m, p, q);
      const double dist = QM::internal::point_segment_distance(m, p, q);
      if(dist >= best_distance) continue;
      best_distance = dist;
      angle = angle_to(q - p);
      const V2d other = t == 0 ? p - xy(k + n - 1)
                                : xy(k + 2) - q;
      if(t == 0 || t == 1)
        angle = std::abs(angle) < std::abs(angle_to(other)) ? angle : angle_to(other);
    }
  }
  return angle;
}

// Lemma 2 (§4.4) on what the templates stage returns (on adaptive cores at most `max_outside`
// buffer-side angles out), where the paper proves it (cores uniform
// along the boundary): every core angle in [45, 135], every buffer-side angle of the core
// boundary in [112.5, 225], every boundary edge angle in [-90, 90]. Opening the notches alone
// (before the corner cuts) left 8, 19 and 27 buffer-side angles out on these three, mostly
// 90-degree notches on 45-degree staircases: every other notch there cannot open without
// flattening the corners beside it.
void check_lemma_2(const Domain& d, const std::string& name, std::size_t max_outside = 0,
                   std::size_t max_away_from_corners = 0)
{
  SCOPED_TRACE(name);
  Mesher mesher(d);
  const Mesh clearance = mesher.run(Stage::CLEARANCE);
  const Mesh templates = mesher.run(Stage::TEMPLATES);
  ASSERT_EQ(mesher.rounds(), 1);
  const auto range = qm2_checks::angle_range(templates);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
  auto outside = [](const Mesh& m) {
    std::size_t n = 0;
    for(double a : buffer_side_angles(m)) n += a < 112.5 - 1e-6 || a > 225 + 1e-6;
    return n;
  };
  const std::size_t before = outside(clearance), after = outside(templates);
  EXPECT_LE(after, max_outside) << "buffer-side angles outside [112.5, 225]";
  // the report counts them as this test does, and tells those beside input corners (§5's)
  EXPECT_EQ(mesher.buffer_report().buffer_angles_out, after);
  EXPECT_LE(mesher.buffer_report().buffer_angles_out_away_from_corners, max_away_from_corners);
  const Loops loops = QM::extract_loops(d);
  double worst_edge_angle = 0;
  for(const auto& e : boundary_edges(templates.quads)) {
    const P2d a = QM::internal::to_point_2d(templates.points[e.first]);
    const P2d b = QM::internal::to_point_2d(templates.points[e.second]);
    worst_edge_angle = (std::max)(worst_edge_angle, std::abs(boundary_edge_angle(d, loops, a, b)));
  }
  EXPECT_LE(worst_edge_angle, 90 + 1e-6);
  std::printf("[buffer] lemma 2 %-18s %s: %zu boundary vertices, buffer-side angles outside [112.5, 225]: "
              "%zu -> %zu; core angles [%.1f, %.1f], boundary edge angles within %.1f\n",
              name.c_str(), qm2_test::exact_constructions ? "epeck" : "epick", buffer_side_angles(templates).size(),
              before, after, range.min, range.max, worst_edge_angle);
}

TEST(Buffer_layers, templates_meet_lemma_2_on_uniform_cores)
{
  check_lemma_2(disc_domain(), "disc");
  check_lemma_2(polygons({ rectangle(0, 0, 1, 1), turned_square(0.5, 0.5, 0.25, 30) }, { Point(0.5, 0.5) }),
                "square, island 30");
  check_lemma_2(polygons({ wavy_blob() }), "wavy blob");
}

// A notch barely out at a transition template's corner, beside which no move of it or its
// window helps and a quad over it searched within 30 degrees of the bisector pushes a
// neighbour out. The quad's fourth corner lies on a thin band 45 degrees off the bisector (135
// degrees at it, little at the neighbour), found by searching the quad's and the betas' excess
// together (barely_out_start(); without it this blob keeps 1 buffer-side angle out). A
// generated blob with three blob holes had one until loop vertices took cells of 2 s_i,
// another (transform_sweep.py blobs, seed 43) until the quadtree's boundary band narrowed to
// one cell along straight stretches; seed 38's has one now.
TEST(Buffer_layers, a_notch_barely_out_is_filled_off_its_bisector)
{
  const Domain d = load_test_data("blob_notch_barely_out_38.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  mesher.run(Stage::TEMPLATES);
  EXPECT_GE(mesher.buffer_report().filled_notches, 1u);
  check_lemma_2(d, "blob 38");
}

// Adaptive cores (../shared/data, skipped when absent): the bisector steps and the lattice's
// left 18 of Lake Superior's 2310 buffer-side angles out and 16 of the guitar's 1110 (quads
// that are not squares, transition templates' 45-degree corners); the plane searches, the core
// giving way, the filled notches searched off the bisector and the windows of five moving
// together leave 8 and 5, most beside the domain's sharp corners or spikes (§5, not Lemma 2)
// or notches whose core angles are all 45 degrees with no room to fill them. Away from input
// corners one is left: Lake Superior's tongue tip at (0.4978, -0.6299), a quad far from a
// square. The guitar's notch of 99.7 degrees at (35.28, 6.18), whose four core angles include
// two of 45, is filled (notches from 95 degrees are filled away from input corners only);
// naca0012's two convex corners jammed by transition templates are split (next test). (Not
// the bird here: a boundary edge at its tail's sharp corner is at 106 degrees to the boundary,
// as before; see the test after.)
TEST(Buffer_layers, templates_nearly_meet_lemma_2_on_adaptive_cores)
{
  struct Case { std::string name; std::size_t outside, away_from_corners; };
  for(const Case& c : { Case{ "lake_superior/lake_superior.poly", 10, 1 }, Case{ "guitar/guitar.poly", 6, 1 },
                        Case{ "naca0012/naca0012.poly", 3, 0 } }) {
    if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + c.name))
      GTEST_SKIP() << "no " << c.name << " in the shared data";
    check_lemma_2(load(c.name), c.name, c.outside, c.away_from_corners);
  }
}

// A convex corner of the core whose one quad is jammed by a transition template (45 degrees
// at a neighbour, 135 opposite) cannot be cut: naca0012's (0.0710, -0.0456) stayed at 108
// degrees (beta 252) whatever moved. Its quad split in three through the midpoints of its
// boundary edges and its centre frees it. The bird has two such corners, (-2.2835, -8.0477)
// and (-0.7625, -8.2169) (naca0012's is no longer jammed since the quadtree's boundary band
// narrowed along straight stretches). The split quads keep every core angle in [45, 135]
// (check_lemma_2).
TEST(Buffer_layers, a_jammed_convex_corner_is_split_in_three)
{
  const std::string name = "bird/bird.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain d = load(name);
  Mesher mesher(d);
  const Mesh templates = mesher.run(Stage::TEMPLATES);
  EXPECT_EQ(mesher.buffer_report().split_corners, 2u);
  // the corner's vertex is still a core boundary vertex, now within [112.5, 225]
  const P2d corner{ -2.283467956, -8.047671173 };
  double nearest = HUGE_VAL, beta = 0;
  for(const auto& [v, angle] : buffer_side_angles_at(templates)) {
    const double d = QM::internal::length_2d(QM::internal::to_point_2d(templates.points[v]) - corner);
    if(d < nearest) {
      nearest = d;
      beta = angle;
    }
  }
  EXPECT_LT(nearest, 1e-3);
  EXPECT_GE(beta, 112.5 - 1e-6);
  EXPECT_LE(beta, 225 + 1e-6);
}

// Narrow channels leave tongues of core one or two cells wide, whose tips turn by 180
// degrees over a few vertices, each at the end of quads whose other corners are at 45 or
// 135: no vertex can move alone. Five consecutive vertices moving in turn (search_window())
// brought the bird's tips at (-0.768, -8.228) and (-0.646, -8.153) in (5 buffer-side angles
// out before, 2 after); since the quadtree's boundary band narrowed along straight
// stretches the bird's core has no such tips, and the 3-element air foil in its far field
// has one: 1 buffer-side angle out without the windows, none with them.
TEST(Buffer_layers, tongue_tips_move_with_their_neighbours)
{
  const std::string name = "airfoil_3elem_jigsaw/airfoil_3elem_jigsaw_farfield20.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain d = load(name);
  Mesher mesher(d);
  const Mesh templates = mesher.run(Stage::TEMPLATES);
  std::size_t outside = 0;
  for(double a : buffer_side_angles(templates)) outside += a < 112.5 - 1e-6 || a > 225 + 1e-6;
  EXPECT_EQ(outside, 0u);
  const auto range = qm2_checks::angle_range(templates);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
}

// Lemma 3 on the first buffer layer of adaptive cores, as the stage leaves it (before the
// strip and the optimisation): its quads' angles lie in [45, 135] but beside the domain's
// sharp corners (within three of the quad's sides of a loop vertex turning by 20 degrees or
// more: §5's fans and rotated bisectors take over there). Before the first buffer points'
// directions were kept near the bisector, Lake Superior's tongue tip at (0.4979, -0.6300) had
// 169 and 28 degrees and the bird's tip at (-1.455, -8.406) 164 and 35: the nearest boundary
// point across a narrow channel had turned them. The river has one quad of 39.9 degrees
// where the core's cells double in size along a straight bank, (4.03928e7, 3.56312e6): the
// boundary band is two cells wide there, not three, and the optimiser mends it.
TEST(Buffer_layers, first_layer_meets_lemma_3_away_from_sharp_corners)
{
  for(const std::string name : { "lake_superior/lake_superior.poly", "guitar/guitar.poly", "bird/bird.poly", "river/river.poly",
                                 "naca0012/naca0012.poly", "airfoil_30p30n/airfoil_30p30n.poly" }) {
    SCOPED_TRACE(name);
    const std::size_t allowed = name == "river/river.poly" ? 1 : 0;
    if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
      GTEST_SKIP() << "no " << name << " in the shared data";
    const Domain d = load(name);
    const Loops loops = QM::extract_loops(d);
    std::vector<P2d> corners;
    for(std::size_t l = 0; l < loops.loops.size(); ++l)
      for(std::size_t k = 0; k < loops.loops[l].vertices.size(); ++k)
        if(std::abs(interior_angle(d, loops, l, k) - 180) >= 20)
          corners.push_back(QM::internal::to_point_2d(d.points[loops.loops[l].vertices[k]]));
    Mesher mesher(d);
    const Mesh first = mesher.run(Stage::BUFFER1); // the layer: its round's last quads
    const std::size_t layer = mesher.buffer_report().first_layer_quads;
    ASSERT_GT(layer, 0u);
    std::size_t outside = 0, beside_corners = 0;
    for(std::size_t q = first.quads.size() - layer; q < first.quads.size(); ++q) {
      std::array<P2d, 4> P;
      for(int k = 0; k < 4; ++k) P[k] = QM::internal::to_point_2d(first.points[first.quads[q][k]]);
      double lo = 180, hi = 0, side = 0;
      P2d centre = CGAL::ORIGIN;
      for(int k = 0; k < 4; ++k) {
        const P2d &a = P[(k + 3) % 4], &b = P[k], &c = P[(k + 1) % 4];
        const double ux = a.x() - b.x(), uy = a.y() - b.y(), wx = c.x() - b.x(), wy = c.y() - b.y();
        const double angle = std::acos(std::clamp((ux * wx + uy * wy) / std::hypot(ux, uy) / std::hypot(wx, wy), -1.0, 1.0)) * 180 / pi;
        lo = (std::min)(lo, angle);
        hi = (std::max)(hi, angle);
        side = (std::max)(side, std::hypot(wx, wy));
        centre = centre + (b - CGAL::ORIGIN) / 4;
      }
      if(lo >= 45 - 1e-6 && hi <= 135 + 1e-6) continue;
      const bool beside = std::any_of(corners.begin(), corners.end(), [&](const P2d& c) {
        return std::hypot(c.x() - centre.x(), c.y() - centre.y()) < 3 * side;
      });
      (beside ? beside_corners : outside) += 1;
    }
    EXPECT_LE(outside, allowed) << "first-layer quads outside [45, 135] away from sharp corners";
    std::printf("[buffer] lemma 3 %-34s %s: %zu first-layer quads, outside [45, 135]: %zu beside sharp corners, %zu elsewhere\n",
                name.c_str(), qm2_test::exact_constructions ? "epeck" : "epick", layer, beside_corners, outside);
  }
}

// the buffer-side angles of `core`'s boundary within [112.5, 225], its core angles within
// [45, 135]
void expect_lemma_2_angles(const Mesh& core)
{
  for(double a : buffer_side_angles(core)) {
    EXPECT_GE(a, 112.5 - 1e-6);
    EXPECT_LE(a, 225.0 + 1e-6);
  }
  const auto range = qm2_checks::angle_range(core);
  EXPECT_GE(range.min, 45 - 1e-9);
  EXPECT_LE(range.max, 135 + 1e-9);
}

// a core of 3 x 3 cells 2 wide and 1 high, [0, 6] x [0, 3]: not squares, so the bisector steps
// leave buffer-side angles out
Mesh wide_cell_core()
{
  Mesh core;
  for(int i = 0; i <= 3; ++i)
    for(int j = 0; j <= 3; ++j) core.points.emplace_back(2 * i, j);
  for(std::size_t i = 0; i < 3; ++i)
    for(std::size_t j = 0; j < 3; ++j)
      core.quads.push_back({ 4 * i + j, 4 * (i + 1) + j, 4 * (i + 1) + j + 1, 4 * i + j + 1 });
  return core;
}

// A 3 x 3 block of 2 x 1 rectangles: each corner of the block is a convex corner whose one
// quad is not a square. The bisector steps of template 1(b) stop it at 125.7 degrees (234.3
// on the buffer side: 0.3 e cuts too little, 0.41 e too much), the plane search off the
// bisector at 135.
TEST(Buffer_layers, templates_search_the_plane_where_the_bisector_steps_fail)
{
  Mesh core = wide_cell_core();
  const Domain d = polygons({ disc(3, 1.5, 6, 64) });
  const Loops loops = QM::extract_loops(d);
  QM::internal::Buffer_layers<K> layers(core, std::vector<double>(core.points.size(), 2.0), d, loops, K());
  ASSERT_TRUE(layers.match_loops());
  layers.apply_boundary_templates({});
  expect_lemma_2_angles(core);
}

// A transition template (the cell [0, 2]^2 with its upper and left sides split: the quads
// B (2, 0), (2, 2), (1, 2), M and B, M, (0, 1), (0, 0), M = (1, 1) the cell's centre) at the
// core's notch B, beside coarse cells on its right: B's two 45-degree corners keep its core
// angles at 270 wherever B alone goes. With M giving way B leaves the notch; with M fixed
// (a domain's isolated point) it cannot.
Mesh notch_at_a_transition_template()
{
  Mesh m;
  const std::vector<std::array<double, 2>> xy{ { 2, 0 }, { 2, 2 }, { 1, 2 }, { 1, 1 }, { 0, 1 }, { 0, 0 },
                                               { 0, 2 }, { 0, 3 }, { 1, 3 }, { 2, 3 }, { -1, 0 }, { -1, 1 },
                                               { -1, 2 }, { -1, 3 }, { 4, 0 }, { 4, 2 }, { 2, -2 }, { 4, -2 } };
  for(const auto& p : xy) m.points.emplace_back(p[0], p[1]);
  auto at = [&](double x, double y) {
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(xy[v][0] == x && xy[v][1] == y) return v;
    return std::size_t(-1);
  };
  m.quads = { { at(2, 0), at(2, 2), at(1, 2), at(1, 1) },    { at(2, 0), at(1, 1), at(0, 1), at(0, 0) },
              { at(1, 1), at(1, 2), at(0, 2), at(0, 1) },    { at(0, 2), at(1, 2), at(1, 3), at(0, 3) },
              { at(1, 2), at(2, 2), at(2, 3), at(1, 3) },    { at(-1, 0), at(0, 0), at(0, 1), at(-1, 1) },
              { at(-1, 1), at(0, 1), at(0, 2), at(-1, 2) }, { at(-1, 2), at(0, 2), at(0, 3), at(-1, 3) },
              { at(2, 0), at(4, 0), at(4, 2), at(2, 2) },    { at(2, -2), at(4, -2), at(4, 0), at(2, 0) } };
  return m;
}

TEST(Buffer_layers, the_core_gives_way_at_a_transition_templates_notch)
{
  const Domain d = polygons({ disc(1.5, 0.5, 5, 64) });
  const Loops loops = QM::extract_loops(d);
  for(bool fixed : { false, true }) {
    SCOPED_TRACE(fixed ? "M fixed" : "M free");
    Mesh core = notch_at_a_transition_template();
    const std::size_t B = 0, M = 3;
    QM::internal::Buffer_layers<K> layers(core, std::vector<double>(core.points.size(), 2.0), d, loops, K());
    ASSERT_TRUE(layers.match_loops());
    layers.apply_boundary_templates(fixed ? std::vector<std::size_t>{ M } : std::vector<std::size_t>{});
    const auto cycles = QM::internal::mesh_boundary_cycles(core.quads, core.points.size());
    ASSERT_EQ(cycles.size(), 1u);
    const auto& c = cycles[0];
    const std::size_t i = std::size_t(std::find(c.begin(), c.end(), B) - c.begin()), n = c.size();
    ASSERT_LT(i, n);
    const double beta = QM::internal::right_side_angle(QM::internal::to_point_2d(core.points[c[(i + n - 1) % n]]),
                                                       QM::internal::to_point_2d(core.points[B]),
                                                       QM::internal::to_point_2d(core.points[c[(i + 1) % n]]));
    if(fixed) {
      EXPECT_EQ(core.points[M], Point(1, 1));
      EXPECT_LT(beta, 112.5);
    } else {
      EXPECT_NE(core.points[M], Point(1, 1));
      EXPECT_GE(beta, 112.5 - 1e-6);
      EXPECT_LE(beta, 225.0 + 1e-6);
    }
    const auto range = qm2_checks::angle_range(core);
    EXPECT_GE(range.min, 45 - 1e-9);
    EXPECT_LE(range.max, 135 + 1e-9);
  }
}

TEST(Buffer_layers, stages_on_the_disc)
{
  check_stages(disc_domain(), "disc", 8);
}

TEST(Buffer_layers, stages_on_the_square_with_an_island)
{
  check_stages(square_with_island(), "square with island", 4);
}

TEST(Buffer_layers, stages_on_triangle_A)
{
  check_stages(load("triangle_A/triangle_A.poly"), "triangle A", 4);
}

// run() returns the best valid round, kept from its round when a later angle round was worse:
// the mesher's state must then be that round's, so the stages run again on its quadtree give
// the same mesh and the same buffer report. (Lake Superior took four rounds and returned an
// earlier one until its notch of 90 degrees facing a fan of three was filled; now it takes
// two and returns the last, and no input at hand returns an earlier round.)
TEST(Buffer_layers, the_returned_round_is_the_mesher_state)
{
  const Domain d = load("lake_superior/lake_superior.poly");
  Mesher mesher(d);
  const Mesh m = mesher.run(Stage::BUFFER2);
  ASSERT_GE(mesher.rounds(), 2);
  const auto report = mesher.buffer_report();
  Mesh again = mesher.core_mesh();
  mesher.clear_buffer_zone(again);
  mesher.fill_buffer_zone(again);
  EXPECT_EQ(again.quads, m.quads);
  EXPECT_EQ(again.points, m.points);
  EXPECT_EQ(mesher.buffer_report().bad_angle_quads, report.bad_angle_quads);
  EXPECT_EQ(mesher.buffer_report().second_layer_quads, report.second_layer_quads);
  // the whole-mesh check run() keeps is the returned mesh's, not the last round's
  ASSERT_TRUE(mesher.quality().has_value());
  const CGAL::Quad_mesher_2::Mesh_quality_2 q = CGAL::Quad_mesher_2::compute_quality(m);
  EXPECT_EQ(mesher.quality()->number_of_quads, q.number_of_quads);
  EXPECT_EQ(mesher.quality()->min_angle, q.min_angle);
  EXPECT_EQ(mesher.quality()->max_angle, q.max_angle);
  EXPECT_EQ(mesher.quality()->angle_histogram, q.angle_histogram);
  mesher.run(Stage::CLEARANCE);
  EXPECT_FALSE(mesher.quality().has_value());
}

// Each round builds the quadtree anew with the requests of every round before it: a round
// whose requests split no cell (finer cells refused) is repeated, figure for figure, by every
// round after it. The rounds end there, with the error the 16th would give (a 128-gon hole
// 1e-7 from the side of a unit square repeated its seventh round nine times, 27 s each: 350 s,
// now 119 s). Here a square hole 0.01 above the bottom of a unit square, narrow regions left
// unresolved and at most depth 7: no core is left between them, and the fourth round (824
// quads; 1652 while the requests of one round compounded, 1484 before axis-parallel domains
// lost the root grid's margin, 796 since the boundary band narrowed along straight
// stretches) was repeated twelve times.
TEST(Buffer_layers, the_rounds_end_when_their_refinement_splits_no_cell)
{
  const Domain d = polygons({ rectangle(0, 0, 1, 1), { Point(0.3, 0.01), Point(0.3, 0.5), Point(0.7, 0.5), Point(0.7, 0.01) } },
                            { Point(0.5, 0.25) });
  QM::Mesh_criteria_2<K> criteria(0, 0, 7);
  criteria.set_resolve_narrow_regions(false);
  Mesher mesher(d, criteria);
  std::string error;
  try {
    mesher.run(Stage::BUFFER2);
  } catch(const QM::Meshing_error& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("no core mesh is left near loop 1"), std::string::npos) << error;
  EXPECT_NE(error.find("after 4 refinement rounds; finer cells are refused there: the maximum depth 7"), std::string::npos)
    << error;
  EXPECT_EQ(mesher.rounds(), 4);
  ASSERT_EQ(mesher.round_figures().size(), 4u);
  EXPECT_EQ(mesher.round_figures().back().quads, 796u);
  EXPECT_FALSE(mesher.round_figures().back().valid);
}

// The round observer sees each round as it ends (the tool's -v prints them so: a hard input
// can take minutes a round), once per round, with the figures round_figures() keeps
// (random_convex_11_23 takes two rounds; naca0012_sharp, random_star_5_31 and
// random_convex_2_20, which took three, two and two, now take one)
TEST(Buffer_layers, the_round_observer_sees_every_round_as_it_ends)
{
  const Domain d = load_test_data("random_convex_11_23.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  std::vector<Mesher::Round_figures> seen;
  mesher.set_round_observer([&](const Mesher::Round_figures& f) {
    EXPECT_EQ(mesher.round_figures().size(), seen.size() + 1); // the round just ended
    EXPECT_EQ(&f, &mesher.round_figures().back());
    EXPECT_EQ(mesher.rounds(), f.round);
    seen.push_back(f);
  });
  mesher.run(Stage::BUFFER2);
  const std::vector<Mesher::Round_figures> figures = mesher.round_figures(); // the next run() clears them
  ASSERT_GE(figures.size(), 2u);
  ASSERT_EQ(seen.size(), figures.size());
  EXPECT_EQ(int(seen.size()), mesher.rounds());
  for(std::size_t r = 0; r < seen.size(); ++r) {
    SCOPED_TRACE("round " + std::to_string(r + 1));
    EXPECT_EQ(seen[r].round, int(r + 1));
    EXPECT_EQ(seen[r].quads, figures[r].quads);
    EXPECT_EQ(seen[r].invalid_quads, figures[r].invalid_quads);
    EXPECT_EQ(seen[r].bad_angle_quads, figures[r].bad_angle_quads);
    EXPECT_EQ(seen[r].bad_angle_quads_by_layer, figures[r].bad_angle_quads_by_layer);
    EXPECT_EQ(figures[r].bad_angle_quads_by_layer[0] + figures[r].bad_angle_quads_by_layer[1]
                + figures[r].bad_angle_quads_by_layer[2], figures[r].bad_angle_quads);
    EXPECT_EQ(seen[r].valid, figures[r].valid);
    EXPECT_EQ(seen[r].refinement_requests, figures[r].refinement_requests);
    EXPECT_EQ(seen[r].seconds, figures[r].seconds);
    EXPECT_GT(seen[r].seconds, 0.0);
  }
  // an empty observer is not called; a run without rounds past the clearance calls none
  mesher.set_round_observer(Mesher::Round_observer());
  mesher.run(Stage::BUFFER2);
  EXPECT_EQ(seen.size(), figures.size());
  mesher.set_round_observer([&](const Mesher::Round_figures& f) { seen.push_back(f); });
  mesher.run(Stage::CLEARANCE);
  EXPECT_EQ(seen.size(), figures.size());
}

// An invalid round is refined where its angles are out too (away from its invalid quads), not
// for validity first: a convex 35-gon with a 3.8 degree notch and a hole (random_sweep.py
// --seed 2, domain 20) had one quad not convex and one angle out in its first round, and took
// a valid round more with the angle out. Since slits of the outside are sized by their own
// width its first round is valid; a convex 27-gon with three holes (random_sweep.py --seed
// 1, domain 29) had one quad not convex and three angles out in its first round, until the
// boundary band narrowed along straight stretches (a third round then mends a core quad); a
// convex 89-gon with five holes (--seed 11, domain 53) has one quad not convex and three
// angles out in its first round.
TEST(Buffer_layers, an_invalid_round_is_refined_at_its_angles_out_too)
{
  const Domain d = load_test_data("random_convex_11_53.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  mesher.run(Stage::BUFFER2);
  const auto& figures = mesher.round_figures();
  ASSERT_GE(figures.size(), 2u);
  EXPECT_FALSE(figures[0].valid);
  EXPECT_GT(figures[0].bad_angle_quads, 0u);
  EXPECT_EQ(figures.size(), 2u);
  EXPECT_TRUE(figures.back().valid);
  EXPECT_EQ(figures.back().bad_angle_quads, 0u);
}

// A random 2-opt polygon with four holes and a corner cut 0.0059 of its side
// (random_sweep.py --seed 4, domain 67): the optimiser slid a boundary point so near the end
// every buffer stage on `core` (cells of side 2 at most), with `memo` keeping the moves
Mesh buffered(Mesh core, const Domain& d, QM::internal::Move_memo* memo, QM::Buffer_report& report)
{
  const Loops loops = QM::extract_loops(d);
  QM::internal::Buffer_layers<K> layers(core, std::vector<double>(core.points.size(), 2.0), d, loops, K(), memo);
  EXPECT_TRUE(layers.match_loops());
  layers.apply_boundary_templates({});
  layers.apply_connectivity_templates();
  layers.build_first_layer();
  layers.build_second_layer();
  layers.optimize({});
  report = layers.report();
  return core;
}

// A round whose moves start from the states of the round before recalls where they ended
// instead of searching again (move_memo.h), with the same mesh as a search: here every state
// is the last round's.
TEST(Buffer_layers, moves_from_the_last_rounds_states_are_recalled_with_the_same_result)
{
  const Mesh core = wide_cell_core();
  const Domain d = polygons({ disc(3, 1.5, 6, 64) });
  QM::Buffer_report searched, first_round, second_round;
  const Mesh without = buffered(core, d, nullptr, searched);
  QM::internal::Move_memo memo;
  memo.next_round();
  const Mesh first = buffered(core, d, &memo, first_round);
  memo.next_round();
  const Mesh second = buffered(core, d, &memo, second_round);
  for(const Mesh* m : { &first, &second }) {
    EXPECT_TRUE(m->points == without.points);
    EXPECT_TRUE(m->quads == without.quads);
  }
  EXPECT_EQ(searched.moves_recalled, 0u);
  EXPECT_GT(searched.moves_searched, 0u);
  EXPECT_EQ(first_round.moves_searched + first_round.moves_recalled, searched.moves_searched);
  EXPECT_EQ(second_round.moves_searched, 0u);
  EXPECT_EQ(second_round.moves_recalled, searched.moves_searched);
  // the templates' plane searches are recalled too, with the counts they make
  EXPECT_GT(searched.searched_vertices, 0u);
  EXPECT_EQ(second_round.searched_vertices, searched.searched_vertices);
  EXPECT_EQ(second_round.shaped_interior, searched.shaped_interior);
}

// the templates stage on `core` (local sizes: its longest edge at each vertex), with `memo`
// keeping the moves
Mesh templated(Mesh core, const Domain& d, QM::internal::Move_memo* memo, QM::Buffer_report& report)
{
  std::vector<double> size(core.points.size(), 0.0);
  for(const auto& q : core.quads)
    for(int k = 0; k < 4; ++k) {
      const double len = std::sqrt(CGAL::to_double(CGAL::squared_distance(core.points[q[k]], core.points[q[(k + 1) % 4]])));
      for(std::size_t v : { q[k], q[(k + 1) % 4] }) size[v] = (std::max)(size[v], len);
    }
  const Loops loops = QM::extract_loops(d);
  QM::internal::Buffer_layers<K> layers(core, size, d, loops, K(), memo);
  EXPECT_TRUE(layers.match_loops()) << layers.report().failure;
  layers.apply_boundary_templates({});
  layers.apply_connectivity_templates();
  report = layers.report();
  return core;
}

// A template search may move the interior core around its vertex too (relax_interior()):
// recalled from the round before, it moves the same vertices to the same places, with the
// same counts. A random 2-opt polygon with four holes (random_sweep.py --seed 4, domain 67):
// 28 searches, 8 interior vertices moved.
TEST(Buffer_layers, template_searches_are_recalled_with_the_interior_they_moved)
{
  const Domain d = load_test_data("random_twoopt_4_67.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  const Mesh core = mesher.run(Stage::CLEARANCE);
  QM::Buffer_report searched, first_round, second_round;
  const Mesh without = templated(core, d, nullptr, searched);
  QM::internal::Move_memo memo;
  memo.next_round();
  const Mesh first = templated(core, d, &memo, first_round);
  memo.next_round();
  const Mesh second = templated(core, d, &memo, second_round);
  for(const Mesh* m : { &first, &second }) {
    EXPECT_TRUE(m->points == without.points);
    EXPECT_TRUE(m->quads == without.quads);
  }
  EXPECT_GT(searched.shaped_interior, 0u);
  EXPECT_GT(searched.moves_searched, 0u);
  EXPECT_EQ(second_round.moves_searched, 0u);
  EXPECT_EQ(second_round.moves_recalled, searched.moves_searched);
  EXPECT_EQ(second_round.searched_vertices, searched.searched_vertices);
  EXPECT_EQ(second_round.shaped_interior, searched.shaped_interior);
}

// Moves are forgotten after a round that did not see them; the last round's are found.
TEST(Buffer_layers, the_move_memo_keeps_this_round_and_the_last)
{
  QM::internal::Move_memo memo;
  QM::internal::State_hash a, b;
  a.add(1.0);
  b.add(2.0);
  const QM::internal::Point_2d pa(1, 2), pb(3, 4);
  QM::internal::Point_2d found;
  memo.insert(a, pa);
  ASSERT_TRUE(memo.find(a, found));
  EXPECT_EQ(found, pa);
  EXPECT_FALSE(memo.find(b, found));
  memo.next_round(); // a is the last round's
  memo.insert(b, pb);
  ASSERT_TRUE(memo.find(b, found));
  EXPECT_EQ(found, pb);
  memo.next_round(); // b is the last round's; a was neither seen nor found in the round before
  EXPECT_FALSE(memo.find(a, found));
  ASSERT_TRUE(memo.find(b, found)); // found, it is kept for the next round
  memo.next_round();
  EXPECT_TRUE(memo.find(b, found));
  for(int k = 0; k < 5000; ++k) { // past the first table size: it grows
    QM::internal::State_hash h;
    h.add(std::uint64_t(k));
    memo.insert(h, QM::internal::Point_2d(k, -k));
  }
  for(int k = 0; k < 5000; k += 997) {
    QM::internal::State_hash h;
    h.add(std::uint64_t(k));
    ASSERT_TRUE(memo.find(h, found));
    EXPECT_EQ(found, QM::internal::Point_2d(k, -k));
  }
}

// The rounds after the first refine the quadtree around their requests only: most of their
// moves start where the round before left them and are recalled.
TEST(Buffer_layers, later_rounds_recall_most_moves)
{
  const Domain d = load_test_data("random_convex_11_23.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  mesher.run(Stage::BUFFER2);
  ASSERT_GE(mesher.rounds(), 2);
  EXPECT_GT(mesher.buffer_report().moves_recalled, 4 * mesher.buffer_report().moves_searched);
}

// of its input edge that the edge meeting it there passed within the whole-mesh check's
// tolerance, a node on the other side's edge: an invalid first round. A point sliding on an
// input edge keeps the shortest edge's length from the edges at its ends.
TEST(Buffer_layers, a_sliding_point_keeps_clear_of_the_next_input_edge)
{
  const Domain d = load_test_data("random_twoopt_4_67.poly");
  ASSERT_FALSE(d.points.empty());
  Mesher mesher(d);
  const Mesh m = mesher.run(Stage::BUFFER2);
  for(const auto& round : mesher.round_figures())
    EXPECT_TRUE(round.valid) << "round " << round.round;
  check_whole_domain(d, m, "random 2-opt with a corner cut");
  expect_45_135_but_at_input_corners(d, m, "random 2-opt with a corner cut");
}

// The refinement template of the cell [0, 4]^2 (four corner squares and eight kites with 45
// degrees at the centre (2, 2)) without its upper-left quadrant: the centre is a notch of the
// core whose core angles are all 45 degrees, as Lake Superior's (0.8877, -0.6432) was.
Mesh template_without_a_quadrant()
{
  Mesh m;
  const std::vector<std::array<double, 2>> xy{ { 0, 0 }, { 1, 0 }, { 2, 0 }, { 3, 0 }, { 4, 0 }, { 0, 1 }, { 1, 1 },
                                               { 3, 1 }, { 4, 1 }, { 0, 2 }, { 2, 2 }, { 4, 2 }, { 3, 3 }, { 4, 3 },
                                               { 2, 4 }, { 3, 4 }, { 4, 4 } };
  for(const auto& p : xy) m.points.emplace_back(p[0], p[1]);
  auto at = [&](double x, double y) {
    for(std::size_t v = 0; v < xy.size(); ++v)
      if(xy[v][0] == x && xy[v][1] == y) return v;
    return std::size_t(-1);
  };
  m.quads = { { at(0, 0), at(1, 0), at(1, 1), at(0, 1) }, { at(1, 0), at(2, 0), at(2, 2), at(1, 1) },
              { at(2, 0), at(3, 0), at(3, 1), at(2, 2) }, { at(3, 0), at(4, 0), at(4, 1), at(3, 1) },
              { at(3, 1), at(4, 1), at(4, 2), at(2, 2) }, { at(2, 2), at(4, 2), at(4, 3), at(3, 3) },
              { at(3, 3), at(4, 3), at(4, 4), at(3, 4) }, { at(2, 2), at(3, 3), at(3, 4), at(2, 4) },
              { at(0, 1), at(1, 1), at(2, 2), at(0, 2) } };
  return m;
}

// A notch that cannot move (its core angles are all 45 degrees) gets a new core quad over it
// (paper §4.4's templates fill the buffer too): left alone, its two first-layer quads split
// its 90 degrees and one had 44.9 (Lake Superior, lake_superior_jigsaw; beside a transition
// template, naca0012's (0.0827, -0.0501) had 44.2 and its neighbour 135.03).
TEST(Buffer_layers, a_notch_that_cannot_move_is_filled)
{
  Mesh core = template_without_a_quadrant();
  for(std::size_t q = 0; q < core.quads.size(); ++q) ASSERT_GT(qm2_checks::signed_area(core, q), 0);
  const Domain d = polygons({ disc(2, 2, 5, 64) });
  const Loops loops = QM::extract_loops(d);
  const std::size_t core_quads = core.quads.size();
  QM::internal::Buffer_layers<K> layers(core, std::vector<double>(core.points.size(), 4.0), d, loops, K());
  ASSERT_TRUE(layers.match_loops());
  layers.apply_boundary_templates({});
  EXPECT_EQ(core.points[10], Point(2, 2)); // the centre cannot move
  layers.apply_connectivity_templates();
  EXPECT_EQ(layers.report().filled_notches, 1u);
  EXPECT_EQ(core.quads.size(), core_quads + 1);
  // Y searched off the bisector and the vertices around it again: on it Y kept 226.4 degrees
  expect_lemma_2_angles(core);
  layers.build_first_layer();
  layers.build_second_layer();
  layers.optimize({});
  layers.check_quads();
  EXPECT_EQ(layers.report().invalid_quads, 0u);
  // every quad at the centre within [45, 135]: the six kites, and the new quad
  const auto at_centre = corners_at(core, Point(2, 2));
  EXPECT_EQ(at_centre.size(), 7u);
  for(const auto& [q, c] : at_centre)
    for(int k = 0; k < 4; ++k) {
      const double a = qm2_checks::corner_angle(core, q, k);
      EXPECT_GE(a, 45.0 - 1e-9) << "quad " << q << (k == c ? ", at the centre" : "");
      EXPECT_LE(a, 135.0 + 1e-9) << "quad " << q << (k == c ? ", at the centre" : "");
    }
}

template <class Skip>
std::vector<std::array<std::size_t, 4>> grid_quads(int nx, int ny, Skip skip);

// n x n squares of side `side` from (x0, y0), counter-clockwise
void add_grid(Mesh& m, double x0, double y0, int n, double side)
{
  const std::size_t first = m.points.size();
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i) m.points.emplace_back(x0 + side * i, y0 + side * j);
  for(auto q : grid_quads(n, n, [](int, int) { return false; })) {
    for(std::size_t& v : q) v += first;
    m.quads.push_back(q);
  }
}

// Two pieces of core following one loop, cut apart by a narrow passage (two 4 x 4 rooms
// joined by a channel 0.8 wide, a piece of 3 x 3 squares in each): the refinement is asked
// across the passage, with cells under its half width, not along the smaller piece (which
// grew, round after round, while the passage stayed closed: 87770 to 99230 quads in four
// rounds on a random star, seed 4 domain 75, then rounds of a minute).
TEST(Buffer_layers, a_core_cut_off_by_a_narrow_passage_is_refined_across_it)
{
  const Domain d = polygons({ { Point(0, 0), Point(4, 0), Point(4, 2.6), Point(6, 2.6), Point(6, 0), Point(10, 0),
                                Point(10, 4), Point(6, 4), Point(6, 3.4), Point(4, 3.4), Point(4, 4), Point(0, 4) } });
  const Loops loops = QM::extract_loops(d);
  Mesh core;
  add_grid(core, 0.6, 0.6, 3, 0.9);
  add_grid(core, 6.8, 1.0, 3, 0.8); // (6.8, 3.4) nearest the other piece's (3.3, 3.3), across the channel
  QM::internal::Buffer_layers<K> layers(core, std::vector<double>(core.points.size(), 1.0), d, loops, K());
  EXPECT_FALSE(layers.match_loops());
  EXPECT_EQ(layers.report().dropped_core_pieces, 0u);
  std::size_t in_passage = 0;
  for(const auto& [p, size] : layers.requests().for_validity)
    if(p.x() > 4 && p.x() < 6) {
      ++in_passage;
      EXPECT_TRUE(p.y() > 2.6 && p.y() < 3.4) << p;
      EXPECT_LE(size, 0.4) << p;
    }
  EXPECT_GE(in_passage, 1u);
}

// A room with a channel tapering to a tip, the core a block of squares in the room and
// `channel` (n x n squares of side `side` from (x0, y0)) in the channel, cut off from it:
// whether the buffer stages match the loops, and how many pieces they dropped
std::pair<bool, std::size_t> match_with_a_piece_in_a_channel(double x0, double y0, int n, double side,
                                                             bool piece_holds_a_fixed_point = false)
{
  const Domain d = polygons({ { Point(0, 0), Point(4, 0), Point(4, 1.5), Point(12, 2), Point(4, 2.5), Point(4, 4),
                                Point(0, 4) } });
  const Loops loops = QM::extract_loops(d);
  Mesh core;
  add_grid(core, 0.6, 0.6, 3, 0.9);
  std::vector<double> size(core.points.size(), 0.9);
  const std::size_t piece_first_point = core.points.size();
  add_grid(core, x0, y0, n, side);
  size.resize(core.points.size(), side);
  const std::size_t quads = core.quads.size();
  QM::internal::Buffer_layers<K> layers(core, size, d, loops, K());
  const std::vector<std::size_t> fixed = piece_holds_a_fixed_point ? std::vector<std::size_t>{ piece_first_point }
                                                                   : std::vector<std::size_t>{};
  const bool matched = layers.match_loops(fixed);
  const std::size_t dropped = layers.report().dropped_core_pieces;
  EXPECT_EQ(core.quads.size(), dropped == 0 ? quads : 9u);
  return { matched, dropped };
}

// A piece of core at most two of its cells across, cut off from the rest along a tapering
// channel (a random 2-opt polygon's 0.4-degree needle, random_domains.py --seed 12, domain
// 37): refining there made new pieces farther along the channel as fast as it joined them,
// 16 rounds to 383323 quads with two angles left out. Such a piece is dropped, and the
// buffer fills its place: 3 rounds, 39583 quads, none out.
TEST(Buffer_layers, a_small_piece_of_core_cut_off_in_a_channel_is_dropped)
{
  EXPECT_EQ(match_with_a_piece_in_a_channel(5.9, 1.875, 1, 0.25), std::make_pair(true, std::size_t(1)));
  EXPECT_EQ(match_with_a_piece_in_a_channel(5.9, 1.8, 2, 0.2), std::make_pair(true, std::size_t(1)));
  // three cells across: refined as a piece cut off by a narrow passage
  EXPECT_EQ(match_with_a_piece_in_a_channel(5.9, 1.8, 3, 0.13), std::make_pair(false, std::size_t(0)));
  // a domain's isolated point is never lost
  EXPECT_EQ(match_with_a_piece_in_a_channel(5.9, 1.875, 1, 0.25, true), std::make_pair(false, std::size_t(0)));
  const Domain d = load_test_data("random_twoopt_12_37.poly");
  Mesher mesher(d);
  expect_random_case_meets_45_135(mesher, d, "random 2-opt with a needle along a channel");
  EXPECT_LE(mesher.rounds(), 4);
}

// ---- 3. determinism -------------------------------------------------------------------------
// (each binary has one kernel, so Epick and Epeck are not compared here: two runs must give
// the same mesh, point for point)

void check_deterministic(const Domain& d, const std::string& name, bool third_run = false)
{
  SCOPED_TRACE(name);
  Mesher a(d), b(d);
  const Mesh ma = a.run(Stage::BUFFER2);
  const Mesh mb = b.run(Stage::BUFFER2);
  EXPECT_EQ(a.rounds(), b.rounds());
  EXPECT_EQ(ma.quads, mb.quads);
  ASSERT_EQ(ma.points.size(), mb.points.size());
  std::size_t differ = 0;
  for(std::size_t v = 0; v < ma.points.size(); ++v) differ += ma.points[v] != mb.points[v];
  EXPECT_EQ(differ, 0u);
  if(third_run) { // on the same mesher object: nothing of the first run leaks into it
    const Mesh mc = a.run(Stage::BUFFER2);
    EXPECT_EQ(ma.quads, mc.quads);
    ASSERT_EQ(ma.points.size(), mc.points.size());
    for(std::size_t v = 0; v < ma.points.size(); ++v) differ += ma.points[v] != mc.points[v];
    EXPECT_EQ(differ, 0u);
  }
  std::printf("[buffer] deterministic %-20s %s: %zu quads, %zu vertices\n", name.c_str(),
              qm2_test::exact_constructions ? "epeck" : "epick", ma.quads.size(), ma.points.size());
}

TEST(Buffer_layers, two_runs_give_the_same_mesh_disc)
{
  check_deterministic(disc_domain(), "disc", true);
}

TEST(Buffer_layers, two_runs_give_the_same_mesh_disc_with_hole)
{
  check_deterministic(disc_with_hole(0.1, 0.5, 64), "disc with hole");
}

TEST(Buffer_layers, two_runs_give_the_same_mesh_triangle_A)
{
  check_deterministic(load("triangle_A/triangle_A.poly"), "triangle A");
}

// Scaling by powers of two and translating by dyadic offsets (exact in doubles: the disc's
// points are on the 2^-20 grid) keep the quadtree's lattice: the same topology.
TEST(Buffer_layers, power_of_two_scaling_and_translation_give_the_same_topology)
{
  auto grid_disc = [](double cx, double cy, double scale) {
    std::vector<Point> p;
    for(int i = 0; i < 32; ++i) {
      const double x = std::round(std::cos(2 * pi * i / 32) * 0x1p20) * 0x1p-20;
      const double y = std::round(std::sin(2 * pi * i / 32) * 0x1p20) * 0x1p-20;
      p.emplace_back(cx + scale * x, cy + scale * y);
    }
    return polygons({p});
  };
  const Domain base_domain = grid_disc(0, 0, 1);
  Mesher base_mesher(base_domain);
  const Mesh base = base_mesher.run(Stage::BUFFER2);
  ASSERT_GT(base.quads.size(), 0u);
  for(const auto& t : std::vector<std::array<double, 3>>{{1, 1024, -512}, {1024, 0, 0}, {0x1p-14, 3, 0.5}}) {
    const Domain d = grid_disc(t[1], t[2], t[0]);
    Mesher mesher(d);
    const Mesh m = mesher.run(Stage::BUFFER2);
    EXPECT_EQ(m.quads, base.quads) << "scale " << t[0] << ", translation (" << t[1] << ", " << t[2] << ")";
    EXPECT_EQ(m.points.size(), base.points.size());
    check_whole_domain(d, m, "scaled disc " + std::to_string(t[0]));
  }
}

// ---- 4. bad input ---------------------------------------------------------------------------

TEST(Buffer_layers, point_cloud_is_an_error)
{
  Domain d;
  for(const Point& p : disc(0, 0, 1, 16)) d.points.push_back(p);
  Mesher mesher(d);
  EXPECT_THROW(mesher.run(Stage::BUFFER2), QM::Meshing_error);
  EXPECT_THROW(mesher.run(Stage::BUFFER1), QM::Meshing_error);
  EXPECT_THROW(mesher.run(Stage::TEMPLATES), QM::Meshing_error);
}

TEST(Buffer_layers, self_intersecting_loop_is_an_error_naming_a_segment)
{
  // a bow tie: segments 0 (0,0)-(1,1) and 2 (1,0)-(0,1) cross at (0.5, 0.5)
  const Domain d = polygons({{Point(0, 0), Point(1, 1), Point(1, 0), Point(0, 1)}});
  Mesher mesher(d);
  try {
    mesher.run(Stage::BUFFER2);
    ADD_FAILURE() << "no error for a self-intersecting loop";
  } catch(const QM::Meshing_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("segment"), std::string::npos) << msg;
    std::printf("[buffer] bow tie: %s\n", msg.c_str());
  }
}

// ---- 5. internal helpers --------------------------------------------------------------------

// an nx-by-ny grid of unit quads, counter-clockwise, vertex (i, j) at j * (nx + 1) + i,
// without the quads for which skip(i, j) holds
template <class Skip>
std::vector<std::array<std::size_t, 4>> grid_quads(int nx, int ny, Skip skip)
{
  std::vector<std::array<std::size_t, 4>> quads;
  auto v = [nx](int i, int j) { return std::size_t(j * (nx + 1) + i); };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      if(!skip(i, j)) quads.push_back({v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1)});
  return quads;
}

double cycle_area(const std::vector<std::size_t>& c, int nx)
{
  double a = 0;
  for(std::size_t k = 0; k < c.size(); ++k) {
    const std::size_t p = c[k], q = c[(k + 1) % c.size()];
    const double px = double(p % (nx + 1)), py = double(p / (nx + 1));
    const double qx = double(q % (nx + 1)), qy = double(q / (nx + 1));
    a += px * qy - qx * py;
  }
  return a / 2;
}

// consecutive cycle vertices are joined by a boundary edge, in its direction
void expect_follows_edges(const std::vector<std::size_t>& c, const std::vector<std::array<std::size_t, 4>>& quads)
{
  const auto b = boundary_edges(quads);
  const std::set<std::pair<std::size_t, std::size_t>> edges(b.begin(), b.end());
  for(std::size_t k = 0; k < c.size(); ++k)
    EXPECT_TRUE(edges.count({c[k], c[(k + 1) % c.size()]})) << c[k] << " -> " << c[(k + 1) % c.size()];
}

TEST(Buffer_layers_helpers, mesh_boundary_cycles_of_a_2x2_grid)
{
  const auto quads = grid_quads(2, 2, [](int, int) { return false; });
  const auto cycles = QM::internal::mesh_boundary_cycles(quads, 9);
  ASSERT_EQ(cycles.size(), 1u);
  ASSERT_EQ(cycles[0].size(), 8u);
  EXPECT_EQ(std::set<std::size_t>(cycles[0].begin(), cycles[0].end()),
            (std::set<std::size_t>{0, 1, 2, 3, 5, 6, 7, 8})); // all but the centre, 4
  EXPECT_DOUBLE_EQ(cycle_area(cycles[0], 2), 4.0);            // counter-clockwise
  expect_follows_edges(cycles[0], quads);
}

TEST(Buffer_layers_helpers, mesh_boundary_cycles_of_an_annulus)
{
  // a 3x3 grid without its centre quad: the outer cycle (12 vertices) counter-clockwise, the
  // inner one (4) clockwise
  const auto quads = grid_quads(3, 3, [](int i, int j) { return i == 1 && j == 1; });
  const auto cycles = QM::internal::mesh_boundary_cycles(quads, 16);
  ASSERT_EQ(cycles.size(), 2u);
  const auto& outer = cycles[0].size() > cycles[1].size() ? cycles[0] : cycles[1];
  const auto& inner = cycles[0].size() > cycles[1].size() ? cycles[1] : cycles[0];
  EXPECT_EQ(outer.size(), 12u);
  ASSERT_EQ(inner.size(), 4u);
  EXPECT_DOUBLE_EQ(cycle_area(outer, 3), 9.0);
  EXPECT_DOUBLE_EQ(cycle_area(inner, 3), -1.0);
  EXPECT_EQ(std::set<std::size_t>(inner.begin(), inner.end()), (std::set<std::size_t>{5, 6, 9, 10}));
  expect_follows_edges(outer, quads);
  expect_follows_edges(inner, quads);
  // unused points are on no cycle
  EXPECT_EQ(QM::internal::mesh_boundary_cycles(quads, 20).size(), 2u);
}

TEST(Buffer_layers_helpers, loop_locator_closest)
{
  // the unit square (counter-clockwise) and a small square far to the right
  QM::internal::Loop_locator locator({{P2d{0, 0}, P2d{1, 0}, P2d{1, 1}, P2d{0, 1}},
                                      {P2d{10, 0}, P2d{11, 0}, P2d{11, 1}, P2d{10, 1}}});
  EXPECT_DOUBLE_EQ(locator.length(0), 4.0);
  EXPECT_DOUBLE_EQ(locator.arc(0, 2), 2.0);

  auto h = locator.closest(P2d{0.5, -0.3}, 0.5);
  EXPECT_EQ(h.loop, 0u);
  EXPECT_EQ(h.edge, 0u);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  EXPECT_DOUBLE_EQ(h.dist, 0.3);
  EXPECT_DOUBLE_EQ(h.point.x(), 0.5);
  EXPECT_DOUBLE_EQ(h.point.y(), 0.0);
  EXPECT_DOUBLE_EQ(locator.param(h), 0.5);

  // inside, nearest the top edge (edge 2 runs from (1,1) to (0,1))
  h = locator.closest(P2d{0.25, 0.9}, 0.01); // a radius too small: the search widens
  EXPECT_EQ(h.loop, 0u);
  EXPECT_EQ(h.edge, 2u);
  EXPECT_NEAR(h.t, 0.75, 1e-15);
  EXPECT_NEAR(h.dist, 0.1, 1e-15);
  EXPECT_NEAR(locator.param(h), 2.75, 1e-15);

  // beyond a corner: the corner itself
  h = locator.closest(P2d{2, 2}, 0.1);
  EXPECT_EQ(h.loop, 0u);
  EXPECT_DOUBLE_EQ(h.dist, std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(h.point.x(), 1.0);
  EXPECT_DOUBLE_EQ(h.point.y(), 1.0);

  // nearer the second loop, or restricted to the first
  h = locator.closest(P2d{9, 0.5}, 1);
  EXPECT_EQ(h.loop, 1u);
  EXPECT_EQ(h.edge, 3u);
  EXPECT_DOUBLE_EQ(h.dist, 1.0);
  h = locator.closest(P2d{9, 0.5}, 1, 0);
  EXPECT_EQ(h.loop, 0u);
  EXPECT_EQ(h.edge, 1u);
  EXPECT_DOUBLE_EQ(h.dist, 8.0);
}

TEST(Buffer_layers_helpers, right_side_angle)
{
  using QM::internal::right_side_angle;
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{1, 0}, P2d{2, 0}), 180.0, 1e-12); // straight
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{1, 0}, P2d{1, 1}), 270.0, 1e-12); // left turn
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{1, 0}, P2d{1, -1}), 90.0, 1e-12); // right turn
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{1, 0}, P2d{2, -1}), 135.0, 1e-12);
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{1, 0}, P2d{0, 1}), 315.0, 1e-12);
  // the angle on the right plus the one on the left is 360
  EXPECT_NEAR(right_side_angle(P2d{0, 0}, P2d{3, 1}, P2d{2, 5}) + right_side_angle(P2d{2, 5}, P2d{3, 1}, P2d{0, 0}),
              360.0, 1e-12);
  // a counter-clockwise square: 90 degrees inside (left), 270 outside (right)
  EXPECT_NEAR(right_side_angle(P2d{1, 1}, P2d{0, 1}, P2d{0, 0}), 270.0, 1e-12);
}

TEST(Buffer_layers_helpers, right_bisector)
{
  using QM::internal::right_bisector;
  const double r = std::sqrt(0.5);
  auto expect = [](V2d v, double x, double y) {
    EXPECT_NEAR(v.x(), x, 1e-15);
    EXPECT_NEAR(v.y(), y, 1e-15);
  };
  expect(right_bisector(P2d{0, 0}, P2d{1, 0}, P2d{2, 0}), 0, -1);   // straight: the right normal
  expect(right_bisector(P2d{0, 0}, P2d{1, 0}, P2d{1, 1}), r, -r);   // left turn: the reflex side
  expect(right_bisector(P2d{0, 0}, P2d{1, 0}, P2d{1, -1}), -r, -r); // right turn: into the corner
  expect(right_bisector(P2d{0, 0}, P2d{5, 0}, P2d{0, 0}), -1, 0);   // a spike: back along a -> b
  // unit length whatever the edge lengths, and it halves the angle on the right
  const P2d a{-3, 1}, b{0.5, 0.25}, c{2, 7};
  const V2d d = right_bisector(a, b, c);
  EXPECT_NEAR(std::hypot(d.x(), d.y()), 1.0, 1e-15);
  const P2d tip = b + d;
  EXPECT_NEAR(QM::internal::right_side_angle(a, b, tip), QM::internal::right_side_angle(a, b, c) / 2, 1e-9);
}

// The bird (../shared/data, skipped when absent): no refinement round leaves an inverted
// buffer quad. The templates leave the core boundary beside input corners to the corners'
// fans (near_input_corner()); searched there too, the bird had a round with inverted quads.
TEST(Buffer_layers, bird_has_no_round_with_inverted_quads)
{
  const std::string name = "bird/bird.poly";
  if(!std::ifstream(std::string(QM2_SHARED_DATA_DIR) + "/" + name))
    GTEST_SKIP() << "no " << name << " in the shared data";
  const Domain d = load(name);
  Mesher mesher(d);
  mesher.run(Stage::BUFFER2);
  ASSERT_FALSE(mesher.round_figures().empty());
  for(const auto& r : mesher.round_figures()) {
    EXPECT_EQ(r.invalid_quads, 0u) << "round " << r.round;
    EXPECT_TRUE(r.valid) << "round " << r.round;
  }
}


// The optimiser's fold decision: the corners at a vertex, as wedges, must wind once around it.
// Decided exactly on the doubles, it holds far from the origin on small cells, where an angle
// sum is off by more than a fixed tolerance: a point sliding on an edge at (4e7, 3.5e6) and
// its two neighbours are collinear only up to their rounding.
TEST(Buffer_layers_helpers, corners_fold_only_when_they_wind_twice)
{
  using QM::internal::times_wedges_cover;
  typedef std::vector<std::pair<P2d, P2d>> Wedges;
  const P2d E{1, 0}, N{0, 1}, W{-1, 0}, S{0, -1};
  const Wedges ring{ { E, N }, { N, W }, { W, S }, { S, E } }; // four quads' corners, ccw
  EXPECT_EQ(times_wedges_cover(P2d{0, 0}, ring), 1u);
  EXPECT_EQ(times_wedges_cover(P2d{0.4, 0.3}, ring), 1u); // off centre, inside its ring
  EXPECT_EQ(times_wedges_cover(P2d{2, 0}, ring), 2u);     // pulled out of its ring: folded
  EXPECT_EQ(times_wedges_cover(P2d{0, 0}, Wedges{ { E, N }, { N, S }, { S, E } }), 1u); // a flat corner
  EXPECT_EQ(times_wedges_cover(P2d{0, 0}, Wedges{ { E, N }, { N, E } }), 1u); // two quads, one reflex
  // a corner of angle zero leaves the doubles no certain side: the exact count
  EXPECT_EQ(times_wedges_cover(P2d{0, 0}, Wedges{ { N, N }, { E, N }, { N, W }, { W, S }, { S, E } }), 1u);
  EXPECT_EQ(times_wedges_cover(P2d{0, 0}, Wedges{ { E, N }, { N, E }, { W, W } }), 1u);
  EXPECT_EQ(times_wedges_cover(P2d{2, 0}, Wedges{ { E, N }, { N, W }, { W, S }, { S, E }, { N, N } }), 2u);

  // v sliding between A and B (the domain on their left), its quads' corners from B to C and
  // from C to A, and the outside's corner from A back to B
  const double X = 40378712.34567, Y = 3552170.98765, h = 0.0371;
  const P2d A{X, Y}, B{X + 3 * h, Y + 2 * h};
  const P2d v = QM::internal::along_2d(A, B, 0.37);
  const P2d C = v + QM::internal::Vector_2d(-2 * h, 3 * h);
  EXPECT_EQ(times_wedges_cover(v, Wedges{ { B, C }, { C, A }, { A, B } }), 1u);
  const double sum = QM::internal::corner_angle_degrees(C, v, B) + QM::internal::corner_angle_degrees(A, v, C);
  EXPECT_GT(std::abs(sum - 180.0), 1e-6) << "an angle-sum test with tolerance 1e-6 would call this a fold";
  // the same corners folded over: C on the outside
  const P2d C_out = v + QM::internal::Vector_2d(2 * h, -3 * h);
  EXPECT_EQ(times_wedges_cover(v, Wedges{ { B, C_out }, { C_out, A }, { A, B } }), 2u);
}

} // namespace qm2_buffer_tests
