// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_WRITE_SVG_H
#define CGAL_QUAD_MESHER_2_IO_WRITE_SVG_H

#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>
#include <CGAL/Quad_mesher_2/internal/quad_geometry.h>
#include <CGAL/Quad_mesher_2/internal/write_common.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <iomanip>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
namespace internal {

/// Number of colour classes for angle deviations in [0, 45] degrees (one per degree);
/// class `svg_bad_class` is for quads with an angle outside [45, 135].
constexpr int svg_ok_classes = 46;
constexpr int svg_bad_class = svg_ok_classes;

/// Colour class of a quad whose largest |angle - 90| is `deviation` degrees.
inline int svg_colour_class(double deviation)
{
  if(!(deviation <= 45.0 + 1e-7))
    return svg_bad_class;
  return (std::min)(int(std::lround(deviation)), svg_ok_classes - 1);
}

/// `#rrggbb` of a colour class: hue from green (120, deviation 0) through yellow to orange
/// (30, deviation 45); red for `svg_bad_class`.
inline std::string svg_colour(int c)
{
  double hue = 0, sat = 0.85, light = 0.5;
  if(c != svg_bad_class)
    hue = 120.0 - 90.0 * double(c) / double(svg_ok_classes - 1);
  else
    light = 0.45;
  // HSL to RGB.
  const double chroma = (1 - std::abs(2 * light - 1)) * sat;
  const double hp = hue / 60.0;
  const double x = chroma * (1 - std::abs(std::fmod(hp, 2.0) - 1));
  double r = 0, g = 0, b = 0;
  if(hp < 1) { r = chroma; g = x; }
  else if(hp < 2) { r = x; g = chroma; }
  else { g = chroma; b = x; }
  const double mm = light - chroma / 2;
  char buf[8];
  auto to8 = [](double v) { return int(std::lround((std::min)(1.0, (std::max)(0.0, v)) * 255)); };
  std::snprintf(buf, sizeof(buf), "#%02x%02x%02x", to8(r + mm), to8(g + mm), to8(b + mm));
  return std::string(buf);
}

typedef Quad_mesher_2::internal::Point_2d Svg_point;
typedef std::array<Svg_point, 2> Svg_segment;

/// Where the picture's points go: x to the right and y up from the bounding box of the
/// quads' vertices and the segments, its larger side scaled to 1000 units.
struct Svg_frame
{
  double xmin = 0, ymin = 0, xmax = 0, ymax = 0, scale = 1;

  template <class Quad>
  Svg_frame(const std::vector<Svg_point>& pts, const std::vector<Quad>& quads, const std::vector<Svg_segment>& segs)
  {
    bool empty = true;
    auto add = [&](const Svg_point& p) {
      if(empty) {
        xmin = xmax = p.x();
        ymin = ymax = p.y();
        empty = false;
      } else {
        xmin = (std::min)(xmin, p.x());
        xmax = (std::max)(xmax, p.x());
        ymin = (std::min)(ymin, p.y());
        ymax = (std::max)(ymax, p.y());
      }
    };
    for(const auto& q : quads)
      for(std::size_t v : q) add(pts[v]);
    for(const auto& seg : segs) {
      add(seg[0]);
      add(seg[1]);
    }
    const double extent = (std::max)(xmax - xmin, ymax - ymin);
    scale = extent > 0 ? 1000.0 / extent : 1.0;
  }

  double X(const Svg_point& p) const { return (p.x() - xmin) * scale; }
  double Y(const Svg_point& p) const { return (ymax - p.y()) * scale; }
  double width() const { return (xmax - xmin) * scale; }
  double height() const { return (ymax - ymin) * scale; }
};

/// The edges' stroke width: a twentieth of the mean edge length, within [1e-3, 2].
template <class Quad>
double svg_stroke_width(const std::vector<Svg_point>& pts, const std::vector<Quad>& quads, double scale)
{
  double sum_len = 0;
  std::size_t n_len = 0;
  for(const auto& q : quads)
    for(int k = 0; k < 4; ++k) {
      sum_len += Quad_mesher_2::internal::length_2d(pts[q[(k + 1) % 4]] - pts[q[k]]);
      ++n_len;
    }
  const double stroke = n_len > 0 ? 0.05 * sum_len * scale / double(n_len) : 1.0;
  return (std::min)(2.0, (std::max)(1e-3, stroke));
}

/// The quads' indices grouped by their colour class.
template <class Quad>
std::vector<std::vector<std::size_t>> svg_quads_by_class(const std::vector<Svg_point>& pts, const std::vector<Quad>& quads)
{
  std::vector<std::vector<std::size_t>> by_class(svg_bad_class + 1);
  for(std::size_t i = 0; i < quads.size(); ++i) {
    const auto& q = quads[i];
    const std::array<Svg_point, 4> g = { pts[q[0]], pts[q[1]], pts[q[2]], pts[q[3]] };
    by_class[svg_colour_class(Quad_mesher_2::internal::quad_max_angle_deviation(g))].push_back(i);
  }
  return by_class;
}

/// The margin around the picture (the legend is below it, within the margin's width).
constexpr double svg_margin = 20;

/// The classes the legend shows.
constexpr std::array<int, 4> svg_legend_classes = { 0, 23, 45, svg_bad_class };

/// The `<svg>` element's opening, its title and the style of every class drawn or in the legend.
inline void write_svg_header(std::ostream& out, double width, double height, std::size_t quads, std::size_t points,
                             const std::vector<std::vector<std::size_t>>& by_class)
{
  const double margin = svg_margin, legend_h = 60, legend_w = 760;
  const double vb_w = (std::max)(width, legend_w) + 2 * margin;
  const double vb_h = height + 2 * margin + legend_h;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << vb_w
      << "\" height=\"" << vb_h << "\" viewBox=\"" << -margin << ' ' << -margin << ' ' << vb_w
      << ' ' << vb_h << "\">\n"
      << "<title>" << quads << " quads, " << points << " vertices</title>\n"
      << "<style>";
  for(int c = 0; c <= svg_bad_class; ++c)
    if(!by_class[c].empty() || std::count(svg_legend_classes.begin(), svg_legend_classes.end(), c) > 0)
      out << ".c" << c << "{fill:" << svg_colour(c) << "}";
  out << "</style>\n";
}

/// One `<polygon>` a quad, in one group per colour class.
template <class Quad>
void write_svg_quads(std::ostream& out, const std::vector<Svg_point>& pts, const std::vector<Quad>& quads,
                     const std::vector<std::vector<std::size_t>>& by_class, const Svg_frame& frame, double stroke)
{
  out << "<g stroke=\"#222222\" stroke-width=\"" << stroke << "\" stroke-linejoin=\"round\">\n";
  Quad_mesher_2::internal::Text_buffer text(out, 6);
  for(int c = 0; c <= svg_bad_class; ++c) {
    if(by_class[c].empty())
      continue;
    text << "<g class=\"c" << c << "\">\n";
    for(std::size_t i : by_class[c]) {
      const auto& q = quads[i];
      text << "<polygon points=\"";
      for(int k = 0; k < 4; ++k)
        text << (k ? " " : "") << frame.X(pts[q[k]]) << ',' << frame.Y(pts[q[k]]);
      text << "\"/>\n";
    }
    text << "</g>\n";
  }
  text.flush();
  out << "</g>\n";
}

/// The segments as one blue path, three strokes wide.
inline void write_svg_segments(std::ostream& out, const std::vector<Svg_segment>& segs, const Svg_frame& frame,
                               double stroke)
{
  if(segs.empty())
    return;
  out << "<path fill=\"none\" stroke=\"#1f5fd6\" stroke-width=\"" << 3 * stroke
      << "\" stroke-linecap=\"round\" d=\"";
  for(const auto& seg : segs)
    out << 'M' << frame.X(seg[0]) << ',' << frame.Y(seg[0]) << 'L' << frame.X(seg[1]) << ',' << frame.Y(seg[1]);
  out << "\"/>\n";
}

/// The colour legend, its top at `y`.
inline void write_svg_legend(std::ostream& out, double y)
{
  const char* labels[] = { "90&#176;", "67.5&#176; / 112.5&#176;", "45&#176; / 135&#176;",
                           "outside [45&#176;, 135&#176;]" };
  out << "<g font-family=\"sans-serif\" font-size=\"16\" stroke=\"#222222\" stroke-width=\"0.5\">\n";
  for(int i = 0; i < 4; ++i) {
    const double lx = 190.0 * i;
    out << "<rect class=\"c" << svg_legend_classes[i] << "\" x=\"" << lx << "\" y=\"" << y
        << "\" width=\"20\" height=\"20\"/>"
        << "<text stroke=\"none\" fill=\"#222222\" x=\"" << lx + 26 << "\" y=\"" << y + 16
        << "\">" << labels[i] << "</text>\n";
  }
  out << "<text stroke=\"none\" fill=\"#222222\" x=\"0\" y=\"" << y + 44
      << "\">colour: worst corner angle of each quad</text>\n</g>\n";
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Draws `mesh` as an SVG picture and, on top of it in blue, the `segments` (for instance the
/// input domain's boundary). Each quad is one `<polygon>`, filled with a colour given by its
/// worst corner angle: green when every angle is 90 degrees, shading through yellow to orange
/// as the worst angle approaches 45 or 135 degrees, red when some angle lies outside
/// [45, 135] (inverted and non-convex quads included). Edges are thin dark lines whose width
/// is proportional to the mean edge length. The y axis points up; the picture is scaled so
/// that the larger side of the bounding box measures 1000 units, the `viewBox` fits the
/// bounding box plus a margin and a small colour legend below it. Coordinates are written
/// with 6 significant digits to keep files small (~100 bytes per quad).
/// Returns `false`, without throwing, if the stream fails or a quad index is out of range.
template <class Point_2>
bool write_SVG(std::ostream& os, const Quad_mesh_2<Point_2>& mesh,
               const std::vector<std::pair<Point_2, Point_2>>& segments)
{
  if(!Quad_mesher_2::internal::quad_indices_in_range(mesh))
    return false;
  return Quad_mesher_2::internal::guarded_write(os, [&](std::ostream& out) {
    std::vector<internal::Svg_point> pts;
    pts.reserve(mesh.points.size());
    for(const Point_2& p : mesh.points)
      pts.push_back(Quad_mesher_2::internal::to_point_2d(p));
    std::vector<internal::Svg_segment> segs;
    segs.reserve(segments.size());
    for(const auto& seg : segments)
      segs.push_back({ Quad_mesher_2::internal::to_point_2d(seg.first), Quad_mesher_2::internal::to_point_2d(seg.second) });
    const internal::Svg_frame frame(pts, mesh.quads, segs);
    const double stroke = internal::svg_stroke_width(pts, mesh.quads, frame.scale);
    const auto by_class = internal::svg_quads_by_class(pts, mesh.quads);
    out << std::setprecision(6);
    internal::write_svg_header(out, frame.width(), frame.height(), mesh.quads.size(), mesh.points.size(), by_class);
    internal::write_svg_quads(out, pts, mesh.quads, by_class, frame, stroke);
    internal::write_svg_segments(out, segs, frame, stroke);
    internal::write_svg_legend(out, frame.height() + internal::svg_margin);
    out << "</svg>\n";
    return out.good();
  });
}

/// \ingroup PkgQuadMesher2IO
/// Draws `mesh` as an SVG picture (see the overload with segments).
template <class Point_2>
bool write_SVG(std::ostream& os, const Quad_mesh_2<Point_2>& mesh)
{
  return CGAL::Quad_mesher_2::IO::write_SVG(os, mesh, std::vector<std::pair<Point_2, Point_2>>());
}

/// \ingroup PkgQuadMesher2IO
/// Writes the SVG picture of `mesh` and `segments` to the file `filename`.
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_SVG(const std::string& filename, const Quad_mesh_2<Point_2>& mesh,
               const std::vector<std::pair<Point_2, Point_2>>& segments)
{
  return Quad_mesher_2::internal::write_to_file(
    filename, [&](std::ostream& os) { return CGAL::Quad_mesher_2::IO::write_SVG(os, mesh, segments); });
}

/// \ingroup PkgQuadMesher2IO
/// Writes the SVG picture of the part of `mesh` in `window` to the file `filename`: the quads
/// with a vertex in it (the picture fits them) and the segments with an end in it. Returns
/// `false` if the file cannot be written.
template <class Point_2>
bool write_SVG(const std::string& filename, const Quad_mesh_2<Point_2>& mesh,
               const std::vector<std::pair<Point_2, Point_2>>& segments, const CGAL::Bbox_2& window)
{
  auto inside = [&](const Point_2& p) {
    const Quad_mesher_2::internal::Point_2d q = Quad_mesher_2::internal::to_point_2d(p);
    return window.xmin() <= q.x() && q.x() <= window.xmax() && window.ymin() <= q.y() && q.y() <= window.ymax();
  };
  Quad_mesh_2<Point_2> part;
  part.points = mesh.points;
  for(const auto& q : mesh.quads)
    if(std::any_of(q.begin(), q.end(), [&](std::size_t v) { return v < mesh.points.size() && inside(mesh.points[v]); }))
      part.quads.push_back(q);
  std::vector<std::pair<Point_2, Point_2>> near;
  for(const auto& s : segments)
    if(inside(s.first) || inside(s.second)) near.push_back(s);
  return CGAL::Quad_mesher_2::IO::write_SVG(filename, part, near);
}

/// \ingroup PkgQuadMesher2IO
/// Writes the SVG picture of `mesh` to the file `filename`.
/// Returns `false` if the file cannot be written.
template <class Point_2>
bool write_SVG(const std::string& filename, const Quad_mesh_2<Point_2>& mesh)
{
  return CGAL::Quad_mesher_2::IO::write_SVG(filename, mesh, std::vector<std::pair<Point_2, Point_2>>());
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_WRITE_SVG_H
