// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_READ_POLY_H
#define CGAL_QUAD_MESHER_2_IO_READ_POLY_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <exception>
#include <istream>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
namespace internal {

/// Reads the vertex section of a `.poly` file into `v`, `count` the number it lists: if 0, the
/// vertices are read from `node_file` (may be empty: an error then).
inline bool read_poly_vertices(Text_lines& r, const std::string& node_file, Vertex_list& v, long long& count,
                               std::string& msg)
{
  if(!read_vertex_section(r, v, count, msg)) return false;
  if(count == 0) {
    if(node_file.empty()) {
      msg = r.where(v.header_line) + "the .poly file lists 0 vertices, so they are in a separate .node file; "
                                     "read it with the file-name overload";
      return false;
    }
    std::string text;
    if(!slurp_file(node_file, text, msg)) {
      msg = r.where(v.header_line) + "the .poly file lists 0 vertices, but its .node file cannot be read: " + msg;
      return false;
    }
    Text_lines nr(std::move(text), node_file);
    if(!read_node_text(nr, v, msg)) return false;
  } else if(!check_duplicate_vertices(v, msg)) {
    return false;
  }
  return true;
}

/// The lines of a section, numbered from `base`, and what they hold.
template <class Item>
struct Poly_section
{
  std::vector<Item> items;
  std::vector<std::size_t> lines;
  std::size_t base = 0;
};

/// Reads one segment line, `<index> <a> <b> [marker]`, with `markers` markers: its endpoints
/// into `s`, 0-based, and its marker, if it has one, into `marker`.
inline bool read_poly_segment(const Text_lines& r, const Vertex_list& v, long long markers, std::size_t header_line,
                              std::array<std::size_t, 2>& s, int& marker, std::string& msg)
{
  const std::size_t nv = v.xy.size();
  const std::size_t base = v.base;
  const std::size_t line_tokens = 3 + static_cast<std::size_t>(markers);
  if(r.size() < 3) { msg = r.here() + "segment " + std::string(r[0]) + " needs two vertex indices (expected: index a b)"; return false; }
  for(int e = 0; e < 2; ++e) {
    long long a = 0;
    if(!parse_integer(r[1 + e], a)) {
      msg = r.here() + "expected an integer vertex index in segment " + std::string(r[0]) + ", found " + quote(r[1 + e]);
      return false;
    }
    if(a < static_cast<long long>(base) || a >= static_cast<long long>(nv + base)) {
      msg = r.here() + "segment " + std::string(r[0]) + " refers to vertex " + std::string(r[1 + e]) + ", but there are " +
            std::to_string(nv) + " vertices (" + base_name(base) + "): out of range";
      return false;
    }
    s[e] = static_cast<std::size_t>(a) - base;
  }
  if(r.size() > line_tokens) {
    msg = r.here() + "unexpected text " + quote(r[line_tokens]) + " after segment " + std::string(r[0]) + " (the header announces " +
          std::to_string(markers) + " marker(s))";
    return false;
  }
  // The marker the header announces, as for the vertices (Triangle would default it to 0).
  if(r.size() < line_tokens) {
    msg = r.here() + "segment " + std::string(r[0]) + " has no boundary marker, but the segment header (line " +
          std::to_string(header_line) + ") announces 1 marker";
    return false;
  }
  long long m = 0;
  if(r.size() == 4 && !parse_integer(r[3], m)) {
    msg = r.here() + "expected an integer boundary marker of segment " + std::string(r[0]) + ", found " + quote(r[3]);
    return false;
  }
  // the mesh's boundary edges carry it as an int, as Triangle does
  if(m < (std::numeric_limits<int>::min)() || m > (std::numeric_limits<int>::max)()) {
    msg = r.here() + "the boundary marker of segment " + std::string(r[0]) + " is out of range: " + std::string(r[3]);
    return false;
  }
  marker = static_cast<int>(m);
  if(s[0] == s[1]) {
    msg = r.here() + "segment " + std::string(r[0]) + " has zero length: both ends are vertex " + std::to_string(s[0] + base);
    return false;
  }
  return true;
}

/// Reads the segment section: `<#segments> [<#boundary markers (0|1)>]`, then
/// `<index> <a> <b> [marker]`; `markers` gets one per segment if the header announces them.
inline bool read_poly_segments(Text_lines& r, const Vertex_list& v, Poly_section<std::array<std::size_t, 2> >& segments,
                               std::vector<int>& markers, std::string& msg)
{
  const std::size_t base = v.base;
  if(!r.next()) { msg = r.where(r.end_line()) + "unexpected end of file: the segment header is missing"; return false; }
  const std::size_t seg_header_line = r.line();
  long long nseg = 0, nmark = 0;
  if(!read_count(r[0], nseg, r.here(), "the number of segments", msg)) return false;
  if(r.size() > 1) {
    if(!read_count(r[1], nmark, r.here(), "the number of segment boundary markers", msg)) return false;
    if(nmark > 1) { msg = r.here() + "the number of segment boundary markers must be 0 or 1, found " + std::string(r[1]); return false; }
  }
  if(r.size() > 2) { msg = r.here() + "unexpected text " + quote(r[2]) + " after the segment header"; return false; }
  const std::size_t ns = static_cast<std::size_t>(nseg);
  std::vector<std::array<std::size_t, 2> >& segs = segments.items;
  std::vector<std::size_t>& seg_lines = segments.lines;
  const std::size_t cap = r.text().size() / 6 + 1;
  segs.reserve((std::min)(ns, cap));
  seg_lines.reserve((std::min)(ns, cap));
  for(std::size_t i = 0; i < ns; ++i) {
    if(!next_indexed_line(r, i, ns, segments.base, "segment", "segments", "the segment header", seg_header_line, false, msg))
      return false;
    std::array<std::size_t, 2> s;
    int marker = 0;
    if(!read_poly_segment(r, v, nmark, seg_header_line, s, marker, msg)) return false;
    segs.push_back(s);
    if(nmark == 1) markers.push_back(marker);
    seg_lines.push_back(r.line());
  }
  std::size_t d1 = 0, d2 = 0;
  if(find_duplicate_segment(segs, d1, d2)) {
    msg = r.where(seg_lines[d2]) + "duplicate segment: segment " + std::to_string(d2 + segments.base) + " (line " +
          std::to_string(seg_lines[d2]) + ") and segment " + std::to_string(d1 + segments.base) + " (line " +
          std::to_string(seg_lines[d1]) + ") both join vertices " + std::to_string(segs[d2][0] + base) + " and " +
          std::to_string(segs[d2][1] + base);
    return false;
  }
  return true;
}

/// Reads the hole section: `<#holes>`, then `<index> <x> <y>`.
inline bool read_poly_holes(Text_lines& r, Poly_section<std::array<double, 2> >& holes, std::string& msg)
{
  if(!r.next()) { msg = r.where(r.end_line()) + "unexpected end of file: the hole header is missing"; return false; }
  const std::size_t hole_header_line = r.line();
  long long nholes = 0;
  if(!read_count(r[0], nholes, r.here(), "the number of holes", msg)) return false;
  if(r.size() > 1) { msg = r.here() + "unexpected text " + quote(r[1]) + " after the hole header"; return false; }
  const std::size_t nh = static_cast<std::size_t>(nholes);
  const std::size_t cap = r.text().size() / 6 + 1;
  holes.items.reserve((std::min)(nh, cap));
  for(std::size_t i = 0; i < nh; ++i) {
    if(!next_indexed_line(r, i, nh, holes.base, "hole", "holes", "the hole header", hole_header_line, false, msg))
      return false;
    if(r.size() < 3) { msg = r.here() + "hole " + std::string(r[0]) + " needs two coordinates (expected: index x y)"; return false; }
    double x = 0, y = 0;
    std::string problem;
    if(!read_coordinate(r[1], x, problem, [&]() { return "the x coordinate of hole " + std::string(r[0]); }) ||
       !read_coordinate(r[2], y, problem, [&]() { return "the y coordinate of hole " + std::string(r[0]); })) {
      msg = r.here() + problem;
      return false;
    }
    if(r.size() > 3) { msg = r.here() + "unexpected text " + quote(r[3]) + " after hole " + std::string(r[0]); return false; }
    holes.items.push_back({x, y});
    holes.lines.push_back(r.line());
  }
  return true;
}

/// A regional attribute as read: the point, the attribute and the maximum area (0: none).
struct Poly_region
{
  std::array<double, 2> point;
  double attribute = 0, max_area = 0;
};

/// Reads the optional regional attributes: `<#regions>`, then `<index> <x> <y> <attribute>
/// [<maximum area>]` (Triangle requires the one value, the second is optional; a negative
/// maximum area means none, as in Triangle). Whatever follows is an error, not silently
/// dropped.
inline bool read_poly_regions(Text_lines& r, Poly_section<Poly_region>& regions, std::string& msg)
{
  if(r.next()) {
    const std::size_t region_header_line = r.line();
    long long nregions = 0;
    if(!parse_integer(r[0], nregions)) {
      msg = r.here() + "unexpected text " + quote(r[0]) + " after the holes (only a regional-attribute section may follow: "
                       "<#regions>, then <index> <x> <y> <attribute> [<maximum area>] per region)";
      return false;
    }
    if(nregions < 0) { msg = r.here() + "the number of regional attributes is negative (" + std::to_string(nregions) + ")"; return false; }
    if(r.size() > 1) { msg = r.here() + "unexpected text " + quote(r[1]) + " after the regional-attribute header"; return false; }
    const std::size_t nr = static_cast<std::size_t>(nregions);
    for(std::size_t i = 0; i < nr; ++i) {
      if(!next_indexed_line(r, i, nr, regions.base, "region", "regions", "the regional-attribute header", region_header_line,
                            false, msg))
        return false;
      if(r.size() < 4) {
        msg = r.here() + "region " + std::string(r[0]) + " needs two coordinates and an attribute (expected: index x y attribute [maximum area])";
        return false;
      }
      double x = 0, y = 0;
      std::string problem;
      if(!read_coordinate(r[1], x, problem, [&]() { return "the x coordinate of region " + std::string(r[0]); }) ||
         !read_coordinate(r[2], y, problem, [&]() { return "the y coordinate of region " + std::string(r[0]); })) {
        msg = r.here() + problem;
        return false;
      }
      if(r.size() > 5) { msg = r.here() + "unexpected text " + quote(r[5]) + " after region " + std::string(r[0]); return false; }
      Poly_region region{ { x, y } };
      for(std::size_t t = 3; t < r.size(); ++t) {
        double value = 0;
        // parse_double() gives an overflow as the largest double
        if(!parse_double(r[t], value) || !(std::abs(value) < (std::numeric_limits<double>::max)())) {
          msg = r.here() + "expected a finite number for the " + (t == 3 ? "attribute" : "maximum area") + " of region " +
                std::string(r[0]) + ", found " + quote(r[t]);
          return false;
        }
        (t == 3 ? region.attribute : region.max_area) = t == 3 ? value : (std::max)(value, 0.0);
      }
      regions.items.push_back(region);
      regions.lines.push_back(r.line());
    }
    if(r.next()) {
      msg = r.here() + "unexpected text " + quote(r[0]) + " after the last section (the regional attributes, header line " +
            std::to_string(region_header_line) + ")";
      return false;
    }
  }
  return true;
}

/// Reads the sections of a `.poly` file after its vertex header. If the `.poly` lists 0
/// vertices, `node_file` (may be empty) is the `.node` file holding them.
template <class K>
bool read_poly_text(Text_lines& r, const std::string& node_file, Domain_2<K>& out, std::string& msg)
{
  Vertex_list v;
  long long count = 0;
  Poly_section<std::array<std::size_t, 2> > segments;
  Poly_section<std::array<double, 2> > holes;
  Poly_section<Poly_region> regions;
  std::vector<int> markers;
  if(!read_poly_vertices(r, node_file, v, count, msg) || !read_poly_segments(r, v, segments, markers, msg) ||
     !read_poly_holes(r, holes, msg) || !read_poly_regions(r, regions, msg))
    return false;
  append_points<K>(v.xy, out.points);
  out.segments = std::move(segments.items);
  out.segment_markers = std::move(markers);
  append_points<K>(holes.items, out.holes);
  out.point_labels = file_labels(v.base, v.lines, count == 0 ? node_file : std::string());
  out.segment_labels = file_labels(segments.base, segments.lines);
  out.hole_labels = file_labels(holes.base, holes.lines);
  for(const Poly_region& region : regions.items)
    out.region_attributes.push_back({ typename K::Point_2(typename K::FT(region.point[0]), typename K::FT(region.point[1])),
                                      region.attribute, region.max_area });
  out.region_attribute_labels = file_labels(regions.base, regions.lines);
  return true;
}

template <class K>
bool read_poly_impl(std::string&& text, const std::string& source, const std::string& node_file,
                    Domain_2<K>& out, std::string* error)
{
  return guarded_read(source, out, error, [&](std::string& msg) {
    Text_lines r(std::move(text), source);
    if(read_poly_text(r, node_file, out, msg)) return true;
    return false;
  });
}

/// `dir/name.poly` -> `dir/name.node` (the extension is replaced, or `.node` appended).
inline std::string node_file_beside(const std::string& poly_file)
{
  const std::size_t slash = poly_file.find_last_of("/\\");
  const std::size_t dot = poly_file.find_last_of('.');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash)) return poly_file + ".node";
  return poly_file.substr(0, dot) + ".node";
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Reads a Triangle `.poly` file from `in` into `out` (replacing its content).
///
/// Sections: vertices (`<#vertices> [<dimension=2> [<#attributes> [<#markers (0|1)>]]]`, then
/// `<index> <x> <y> [attributes...] [marker]`), segments (`<#segments> [<#markers>]`, then
/// `<index> <a> <b> [marker]`), holes (`<#holes>`, then `<index> <x> <y>`). An optional
/// regional-attributes section after the holes (`<#regions>`, then `<index> <x> <y>
/// <attribute> [<maximum area>]`) goes to `Domain_2::region_attributes` (a maximum area of
/// 0 or below is none, as in Triangle); anything after it, or after the
/// holes if it is absent, is an error. `#` starts a comment. Vertex
/// indices are consecutive from 0 or 1: the first vertex decides, as in Triangle, and segment
/// endpoints use the same base; segment and hole numbers are consecutive from 0 or 1 too.
/// A vertex or segment line holds exactly the attributes and marker its header announces:
/// Triangle defaults missing ones to 0, here a short line is an error, as is an extra token.
/// The segments' markers, if the header announces them, go to `Domain_2::segment_markers`.
/// A `.poly` listing 0 vertices takes them from the `.node` file beside it, which only the
/// file-name overload can do.
///
/// Rejected with one message `SOURCE:LINE: problem` in `*error` (and `out` left empty):
/// empty or truncated input, negative or non-integer counts, dimension other than 2,
/// non-numeric tokens or trailing text, non-finite or too large (|v| > 1e150) coordinates,
/// out-of-sequence vertex indices, out-of-range segment endpoints, duplicate points,
/// zero-length segments and duplicate segments (in either direction). Never throws.
template <class K>
bool read_poly(std::istream& in, Domain_2<K>& out, std::string* error = nullptr,
               const std::string& source_name = "<stream>")
{
  std::string text, msg;
  if(!internal::slurp(in, text, source_name, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_poly_impl(std::move(text), source_name, std::string(), out, error);
}

/// \ingroup PkgQuadMesher2IO
/// Reads the Triangle `.poly` file `filename` (and, if it lists 0 vertices, the `.node` file
/// with the same stem); see the stream overload. Messages are prefixed with the file name.
template <class K>
bool read_poly(const std::string& filename, Domain_2<K>& out, std::string* error = nullptr)
{
  std::string text, msg;
  if(!internal::slurp_file(filename, text, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_poly_impl(std::move(text), filename, internal::node_file_beside(filename), out, error);
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_READ_POLY_H
