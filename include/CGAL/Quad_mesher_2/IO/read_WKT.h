// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_READ_WKT_H
#define CGAL_QUAD_MESHER_2_IO_READ_WKT_H

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/enum.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <exception>
#include <istream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
namespace internal {

/// A minimal WKT lexer over a whole text, tracking line numbers.
class Wkt_lexer
{
public:
  Wkt_lexer(const std::string& text, const std::string& source) : m_s(text), m_source(source) {}

  void skip_space()
  {
    while(m_pos < m_s.size()) {
      const char c = m_s[m_pos];
      if(c == '\n') { ++m_line; ++m_pos; }
      else if(c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') ++m_pos;
      else break;
    }
  }
  bool at_end() { skip_space(); return m_pos >= m_s.size(); }
  char peek() { skip_space(); return m_pos < m_s.size() ? m_s[m_pos] : '\0'; }
  bool accept(char c) { if(peek() == c) { ++m_pos; return true; } return false; }
  std::size_t line() { skip_space(); return m_line; }

  /// A word of letters (upper-cased), or empty if the next character is not a letter.
  std::string word()
  {
    skip_space();
    std::string w;
    while(m_pos < m_s.size() && std::isalpha(static_cast<unsigned char>(m_s[m_pos])))
      w += static_cast<char>(std::toupper(static_cast<unsigned char>(m_s[m_pos++])));
    return w;
  }
  /// The next token up to a blank, a comma, a parenthesis or a semicolon (which ends the
  /// EWKT prefix `SRID=4326;`).
  std::string_view token()
  {
    skip_space();
    const std::size_t b = m_pos;
    while(m_pos < m_s.size()) {
      const char c = m_s[m_pos];
      if(c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == ',' || c == '(' || c == ')' || c == ';') break;
      ++m_pos;
    }
    if(m_pos == b && m_pos < m_s.size()) ++m_pos;  // a single punctuation character
    return std::string_view(m_s.data() + b, m_pos - b);
  }
  std::string_view peek_token()
  {
    const std::size_t p = m_pos, l = m_line;
    std::string_view t = token();
    m_pos = p; m_line = l;
    return t;
  }
  std::string where() { return m_source + ":" + std::to_string(line()) + ": "; }
  std::string where(std::size_t l) const { return m_source + ":" + std::to_string(l) + ": "; }
  std::string found()
  {
    if(at_end()) return "end of file";
    return quote(peek_token());
  }

private:
  const std::string& m_s;
  const std::string& m_source;
  std::size_t m_pos = 0;
  std::size_t m_line = 1;
};

/// The keywords the reader accepts, as messages list them.
constexpr const char* wkt_keywords =
    "POLYGON, MULTIPOLYGON, LINESTRING, MULTILINESTRING, POINT, MULTIPOINT or GEOMETRYCOLLECTION";

/// A parenthesised list of coordinates: a ring or a linestring.
struct Wkt_path
{
  std::vector<std::array<double, 2> > xy;
  std::vector<std::size_t> lines;
  std::size_t line = 0;       // line of the opening parenthesis
};

struct Wkt_ring : Wkt_path
{
  std::size_t polygon = 0;    // 1-based polygon number in the file
  std::size_t index = 0;      // 1-based ring number in its polygon (1 = outer ring)
  std::string describe() const
  {
    return index == 1 ? "the outer ring of polygon " + std::to_string(polygon)
                      : "inner ring " + std::to_string(index - 1) + " (a hole) of polygon " + std::to_string(polygon);
  }
};

/// A LINESTRING: an open polyline, a crack in the domain.
struct Wkt_linestring : Wkt_path
{
  std::size_t number = 0;     // 1-based linestring number in the file
  std::string describe() const { return "linestring " + std::to_string(number); }
};

struct Wkt_data
{
  std::vector<Wkt_ring> rings;
  std::vector<Wkt_linestring> linestrings;
  std::vector<std::array<double, 2> > points;   // POINT / MULTIPOINT
  std::vector<std::size_t> point_lines;
};

class Wkt_parser
{
public:
  Wkt_parser(Wkt_lexer& lex, Wkt_data& data, std::string& msg) : m_lex(lex), m_data(data), m_msg(msg) {}

  /// One geometry, after an optional EWKT `SRID=...;` prefix: several polygons go in one
  /// MULTIPOLYGON and mixed ones in one GEOMETRYCOLLECTION, so that a second one, most likely
  /// a file joined to another by mistake, is not meshed silently.
  bool parse()
  {
    bool found = false;
    while(!m_lex.at_end()) {
      if(m_lex.accept(';')) continue;
      const std::size_t line = m_lex.line();
      const std::string kw = m_lex.word();
      if(kw.empty()) return fail(std::string("expected a WKT geometry keyword (") + wkt_keywords + "), found " + m_lex.found());
      if(kw == "SRID") {  // EWKT prefix `SRID=4326;`
        if(!m_lex.accept('=')) return fail("expected '=' after SRID, found " + m_lex.found());
        m_lex.token();
        if(!m_lex.accept(';')) return fail("expected ';' after the SRID, found " + m_lex.found());
        continue;
      }
      if(found)
        return fail_at(line, "a second WKT geometry (" + kw + "): a file holds one; put several polygons in one "
                             "MULTIPOLYGON, or mixed geometries in one GEOMETRYCOLLECTION");
      if(!geometry(kw, line, true)) return false;
      found = true;
    }
    if(!found) return fail("no WKT geometry found (empty file)");
    if(m_data.rings.empty() && !m_data.linestrings.empty())
      return fail_at(m_data.linestrings.front().line,
                     m_data.linestrings.front().describe() + " but no polygon: a linestring is a crack in a domain, "
                     "and a domain needs a POLYGON or MULTIPOLYGON (with the linestrings in one GEOMETRYCOLLECTION)");
    if(m_data.rings.empty() && m_data.points.empty()) return fail("all WKT geometries are EMPTY: no points");
    return true;
  }

private:
  bool fail(const std::string& problem) { m_msg = m_lex.where() + problem; return false; }
  bool fail_at(std::size_t line, const std::string& problem) { m_msg = m_lex.where(line) + problem; return false; }

  bool expect(char c, const std::string& context)
  {
    if(m_lex.accept(c)) return true;
    return fail(std::string("expected '") + c + "' " + context + ", found " + m_lex.found());
  }

  bool is_empty_keyword()
  {
    if(!std::isalpha(static_cast<unsigned char>(m_lex.peek()))) return false;
    const std::string_view t = m_lex.peek_token();
    if(t.size() == 5) {
      std::string u(t);
      for(char& c : u) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      if(u == "EMPTY") { m_lex.word(); return true; }
    }
    return false;
  }

  bool coordinate(std::array<double, 2>& p, std::size_t& line)
  {
    line = m_lex.line();
    for(int i = 0; i < 2; ++i) {
      const char c = m_lex.peek();
      if(c == ',' || c == ')' || c == '(' || c == '\0')
        return fail(std::string("expected the ") + (i == 0 ? "x" : "y") + " coordinate, found " + m_lex.found());
      const std::string_view tok = m_lex.token();
      std::string problem;
      if(!read_coordinate(tok, p[i], problem, [&]() { return std::string(i == 0 ? "the x coordinate" : "the y coordinate"); }))
        return fail_at(m_lex.line(), problem);
    }
    const char c = m_lex.peek();
    if(c != ',' && c != ')') {
      double z;
      const std::string_view t = m_lex.peek_token();
      if(parse_double(t, z)) return fail("a third coordinate " + quote(t) + ": only 2D WKT is supported");
      return fail("expected ',' or ')' after the coordinates, found " + m_lex.found());
    }
    return true;
  }

  /// The geometry whose keyword `kw` was read on `line`. A collection may not nest: its
  /// members are the six other types.
  bool geometry(const std::string& kw, std::size_t line, bool top_level)
  {
    const bool collection = kw == "GEOMETRYCOLLECTION";
    if(collection && !top_level)
      return fail_at(line, "a GEOMETRYCOLLECTION inside a GEOMETRYCOLLECTION is not supported");
    if(!collection && kw != "POLYGON" && kw != "MULTIPOLYGON" && kw != "LINESTRING" && kw != "MULTILINESTRING" &&
       kw != "POINT" && kw != "MULTIPOINT")
      return fail_at(line, "unsupported WKT geometry type " + quote(kw) + " (expected " + wkt_keywords + ")");
    if(std::isalpha(static_cast<unsigned char>(m_lex.peek()))) {
      const std::size_t l2 = m_lex.line();
      const std::string tag = m_lex.word();
      if(tag == "EMPTY") return true;
      if(tag == "Z" || tag == "M" || tag == "ZM")
        return fail_at(l2, kw + " " + tag + ": only 2D WKT is supported");
      return fail_at(l2, "expected '(' or EMPTY after " + kw + ", found " + quote(tag));
    }
    if(collection) return collection_body();
    if(kw == "POINT") return point_body();
    if(kw == "MULTIPOINT") return multipoint_body();
    if(kw == "POLYGON") return polygon_body();
    if(kw == "LINESTRING") return linestring_body();
    if(kw == "MULTILINESTRING") return multilinestring_body();
    return multipolygon_body();
  }

  bool collection_body()
  {
    if(!expect('(', "after GEOMETRYCOLLECTION")) return false;
    do {
      const std::size_t line = m_lex.line();
      const std::string kw = m_lex.word();
      if(kw.empty()) return fail("expected a WKT geometry keyword in GEOMETRYCOLLECTION, found " + m_lex.found());
      if(!geometry(kw, line, false)) return false;
    } while(m_lex.accept(','));
    return expect(')', "or ',' in GEOMETRYCOLLECTION");
  }

  bool point_body()
  {
    if(!expect('(', "after POINT")) return false;
    std::array<double, 2> p = {0, 0};
    std::size_t line = 0;
    if(!coordinate(p, line)) return false;
    if(!expect(')', "after the coordinates of POINT")) return false;
    m_data.points.push_back(p);
    m_data.point_lines.push_back(line);
    return true;
  }

  bool multipoint_body()
  {
    if(!expect('(', "after MULTIPOINT")) return false;
    do {
      if(is_empty_keyword()) continue;
      const bool paren = m_lex.accept('(');
      std::array<double, 2> p = {0, 0};
      std::size_t line = 0;
      if(!coordinate(p, line)) return false;
      if(paren && !expect(')', "after a point of MULTIPOINT")) return false;
      m_data.points.push_back(p);
      m_data.point_lines.push_back(line);
    } while(m_lex.accept(','));
    return expect(')', "or ',' in MULTIPOINT");
  }

  /// `( x y, ... )`, a ring or a linestring as `what` says
  bool path(Wkt_path& r, const std::string& what)
  {
    r.line = m_lex.line();
    if(!expect('(', "to open " + what)) return false;
    do {
      std::array<double, 2> p = {0, 0};
      std::size_t line = 0;
      if(!coordinate(p, line)) return false;
      r.xy.push_back(p);
      r.lines.push_back(line);
    } while(m_lex.accept(','));
    return expect(')', "or ',' in " + what);
  }

  bool polygon_body()
  {
    if(is_empty_keyword()) return true;
    if(!expect('(', "to open a polygon")) return false;
    ++m_polygons;
    std::size_t index = 0;
    do {
      if(is_empty_keyword()) continue;
      Wkt_ring r;
      r.polygon = m_polygons;
      r.index = ++index;
      if(!path(r, "a ring")) return false;
      m_data.rings.push_back(std::move(r));
    } while(m_lex.accept(','));
    return expect(')', "or ',' after a ring");
  }

  bool multipolygon_body()
  {
    if(!expect('(', "after MULTIPOLYGON")) return false;
    do {
      if(!polygon_body()) return false;
    } while(m_lex.accept(','));
    return expect(')', "or ',' after a polygon of MULTIPOLYGON");
  }

  bool linestring_body()
  {
    if(is_empty_keyword()) return true;
    Wkt_linestring s;
    s.number = ++m_linestrings;
    if(!path(s, "a linestring")) return false;
    m_data.linestrings.push_back(std::move(s));
    return true;
  }

  bool multilinestring_body()
  {
    if(!expect('(', "after MULTILINESTRING")) return false;
    do {
      if(!linestring_body()) return false;
    } while(m_lex.accept(','));
    return expect(')', "or ',' after a linestring of MULTILINESTRING");
  }

  Wkt_lexer& m_lex;
  Wkt_data& m_data;
  std::string& m_msg;
  std::size_t m_polygons = 0;
  std::size_t m_linestrings = 0;
};

struct Xy_hash
{
  std::size_t operator()(const std::array<double, 2>& p) const
  {
    std::uint64_t a, b;
    const double x = p[0] == 0 ? 0.0 : p[0];  // -0.0 == 0.0
    const double y = p[1] == 0 ? 0.0 : p[1];
    std::memcpy(&a, &x, sizeof a);
    std::memcpy(&b, &y, sizeof b);
    return static_cast<std::size_t>(a * 0x9E3779B97F4A7C15ull ^ (b + 0x7F4A7C159E3779B9ull + (a << 6) + (a >> 2)));
  }
};

/// Does ring `r` lie in ring `h` (in its closure)? Rings do not cross, so its first vertex off
/// `h` tells; if all of them are on `h`, it fills `h` or cuts it along chords.
template <class K>
bool ring_lies_in(const std::vector<std::vector<typename K::Point_2> >& rings, std::size_t r, std::size_t h, const K& k)
{
  const auto& H = rings[h];
  for(const auto& q : rings[r]) {
    const CGAL::Bounded_side s = CGAL::bounded_side_2(H.begin(), H.end(), q, k);
    if(s != CGAL::ON_BOUNDARY) return s == CGAL::ON_BOUNDED_SIDE;
  }
  return true;
}

/// Is `p` a valid seed for the hole bounded by ring `h`: strictly inside `h`, on no ring, and
/// not inside any other ring lying in `h` (an island in the hole)? Decided with exact
/// predicates (`bounded_side_2` through the traits).
template <class K>
bool is_valid_hole_seed(const typename K::Point_2& p, const std::vector<std::vector<typename K::Point_2> >& rings,
                        const std::vector<Bbox_2>& boxes, std::size_t h, const K& k)
{
  const auto& H = rings[h];
  if(CGAL::bounded_side_2(H.begin(), H.end(), p, k) != CGAL::ON_BOUNDED_SIDE) return false;
  const Bbox_2 pb = p.bbox();
  for(std::size_t r = 0; r < rings.size(); ++r) {
    if(r == h || !CGAL::do_overlap(boxes[r], pb)) continue;
    const auto& R = rings[r];
    const CGAL::Bounded_side bs = CGAL::bounded_side_2(R.begin(), R.end(), p, k);
    if(bs == CGAL::ON_BOUNDARY) return false;
    // p is inside R: fine if R encloses H (e.g. H's outer ring), not if R lies in H.
    if(bs == CGAL::ON_BOUNDED_SIDE && ring_lies_in(rings, r, h, k)) return false;
  }
  return true;
}

/// Finds a point strictly inside ring `h`, off every ring and outside every ring nested in `h`.
/// Candidates are built in double precision (a vertical line through `h`: the middle of the
/// gap just above its lowest crossing with `h`; then centroids of the ears of `h`) and each is
/// checked exactly with `is_valid_hole_seed`.
template <class K>
bool find_hole_seed(const std::vector<std::vector<typename K::Point_2> >& rings, const std::vector<Bbox_2>& boxes,
                    std::size_t h, const K& k, typename K::Point_2& seed)
{
  typedef typename K::Point_2 Point_2;
  typename K::Construct_point_2 cp = k.construct_point_2_object();
  const auto& H = rings[h];
  const std::size_t n = H.size();

  // 1. Vertical lines between consecutive distinct x of H, widest gaps first.
  std::vector<double> xs;
  xs.reserve(n);
  for(const Point_2& q : H) xs.push_back(CGAL::to_double(q.x()));
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<std::pair<double, double> > gaps;  // (width, c)
  for(std::size_t i = 1; i < xs.size(); ++i) {
    const double c = xs[i - 1] + (xs[i] - xs[i - 1]) / 2;
    if(c > xs[i - 1] && c < xs[i]) gaps.emplace_back(xs[i] - xs[i - 1], c);
  }
  std::sort(gaps.begin(), gaps.end(), [](const std::pair<double, double>& a, const std::pair<double, double>& b) {
    return a.first > b.first;
  });
  if(gaps.size() > 16) gaps.resize(16);
  auto crossing = [](const Point_2& a, const Point_2& b, double c, double& y) {
    const double ax = CGAL::to_double(a.x()), bx = CGAL::to_double(b.x());
    if((ax < c) == (bx < c)) return false;
    const double ay = CGAL::to_double(a.y()), by = CGAL::to_double(b.y());
    y = ay + (c - ax) * ((by - ay) / (bx - ax));
    return true;
  };
  for(const auto& g : gaps) {
    const double c = g.second;
    double y0 = 0;
    bool have0 = false;
    for(std::size_t i = 0; i < n; ++i) {
      double y;
      if(crossing(H[i], H[(i + 1) % n], c, y) && (!have0 || y < y0)) { y0 = y; have0 = true; }
    }
    if(!have0) continue;
    double y1 = 0;
    bool have1 = false;
    for(std::size_t r = 0; r < rings.size(); ++r) {
      if(boxes[r].xmin() > c || boxes[r].xmax() < c) continue;
      const auto& R = rings[r];
      for(std::size_t i = 0; i < R.size(); ++i) {
        double y;
        if(crossing(R[i], R[(i + 1) % R.size()], c, y) && y > y0 && (!have1 || y < y1)) { y1 = y; have1 = true; }
      }
    }
    if(!have1) continue;
    const double ym = y0 + (y1 - y0) / 2;
    if(!(ym > y0 && ym < y1)) continue;
    const Point_2 p = cp(typename K::FT(c), typename K::FT(ym));
    if(is_valid_hole_seed(p, rings, boxes, h, k)) { seed = p; return true; }
  }

  // 2. Centroids of the convex corners of H.
  const CGAL::Orientation o = CGAL::orientation_2(H.begin(), H.end(), k);
  typename K::Orientation_2 orient = k.orientation_2_object();
  for(std::size_t i = 0; i < n; ++i) {
    const Point_2& u = H[(i + n - 1) % n];
    const Point_2& v = H[i];
    const Point_2& w = H[(i + 1) % n];
    if(orient(u, v, w) != o) continue;
    const double x = (CGAL::to_double(u.x()) + CGAL::to_double(v.x()) + CGAL::to_double(w.x())) / 3;
    const double y = (CGAL::to_double(u.y()) + CGAL::to_double(v.y()) + CGAL::to_double(w.y())) / 3;
    const Point_2 p = cp(typename K::FT(x), typename K::FT(y));
    if(is_valid_hole_seed(p, rings, boxes, h, k)) { seed = p; return true; }
  }
  return false;
}

// how messages name a line of `source`
inline std::string wkt_where(const std::string& source, std::size_t line)
{
  return source + ":" + std::to_string(line) + ": ";
}

// Per-ring checks: closure, at least 3 distinct vertices, no repeated vertex, simplicity. Drops
// each ring's closing point and gives its points in `ring_points`.
template <class K>
bool check_wkt_rings(Wkt_data& data, const std::string& source, std::vector<std::vector<typename K::Point_2> >& ring_points,
                     const K& k, std::string& msg)
{
  auto where = [&](std::size_t line) { return wkt_where(source, line); };
  ring_points.assign(data.rings.size(), {});
  for(std::size_t ri = 0; ri < data.rings.size(); ++ri) {
    Wkt_ring& r = data.rings[ri];
    // an open ring is an error, not closed for the user: that would add an edge they did not give
    if(r.xy.size() >= 2 && r.xy.front() != r.xy.back()) {
      msg = where(r.lines.back()) + r.describe() + " is not closed: it ends at " +
            format_point(r.xy.back()[0], r.xy.back()[1]) + " (line " + std::to_string(r.lines.back()) +
            "), not at its first point " + format_point(r.xy.front()[0], r.xy.front()[1]) +
            " (WKT repeats the first point of a ring at its end)";
      return false;
    }
    if(r.xy.size() >= 2) { r.xy.pop_back(); r.lines.pop_back(); }
    std::size_t a = 0, b = 0;
    if(find_duplicate_point(r.xy, a, b)) {
      if(b == a + 1 || (a == 0 && b + 1 == r.xy.size())) {
        msg = where(r.lines[b]) + r.describe() + " has a zero-length edge: vertex " + format_point(r.xy[b][0], r.xy[b][1]) +
              " is repeated (lines " + std::to_string(r.lines[a]) + " and " + std::to_string(r.lines[b]) + ")";
      } else {
        msg = where(r.lines[b]) + r.describe() + " is not simple: it passes twice through " +
              format_point(r.xy[b][0], r.xy[b][1]) + " (lines " + std::to_string(r.lines[a]) + " and " +
              std::to_string(r.lines[b]) + "): duplicate point";
      }
      return false;
    }
    if(r.xy.size() < 3) {
      msg = where(r.line) + r.describe() + " has " + std::to_string(r.xy.size()) +
            " distinct vertices; a ring needs at least 3";
      return false;
    }
    append_points<K>(r.xy, ring_points[ri], k);
    if(!CGAL::is_simple_2(ring_points[ri].begin(), ring_points[ri].end(), k)) {
      msg = where(r.line) + r.describe() + " is not simple (two of its edges cross or touch, or it is degenerate)";
      return false;
    }
  }
  return true;
}

// Per-linestring checks: at least 2 distinct vertices, no zero-length segment, open (a closed
// one is a ring). Whether it lies in the domain is left to extract_loops(), which names the
// segment.
inline bool check_wkt_linestrings(const Wkt_data& data, const std::string& source, std::string& msg)
{
  auto at = [](const std::array<double, 2>& p) { return format_point(p[0], p[1]); };
  for(const Wkt_linestring& s : data.linestrings) {
    const std::vector<std::array<double, 2> >& xy = s.xy;
    if(std::all_of(xy.begin(), xy.end(), [&](const std::array<double, 2>& p) { return p == xy.front(); })) {
      msg = wkt_where(source, s.line) + s.describe() + " has 1 distinct vertex, " + at(xy.front()) +
            "; a linestring needs at least 2";
      return false;
    }
    for(std::size_t i = 1; i < xy.size(); ++i) {
      if(xy[i] != xy[i - 1]) continue;
      msg = wkt_where(source, s.lines[i]) + s.describe() + " has a zero-length segment: vertex " + at(xy[i]) +
            " is repeated (lines " + std::to_string(s.lines[i - 1]) + " and " + std::to_string(s.lines[i]) + ")";
      return false;
    }
    if(xy.front() == xy.back()) {
      msg = wkt_where(source, s.lines.back()) + s.describe() + " is closed: it ends at its first point " +
            at(xy.front()) + " (lines " + std::to_string(s.lines.front()) + " and " + std::to_string(s.lines.back()) +
            "); a closed polyline is a polygon ring: give it as a POLYGON, or as an inner ring for a hole";
      return false;
    }
  }
  return true;
}

// The domain's vertices and segments, numbered from the rings, linestrings and points of a WKT
// input, and how later messages name them: vertex or segment i of its ring or linestring, from 1.
// A ring edge joining the vertices of an earlier ring edge is that segment, and `ring_edges`
// lists both (check_wkt_shared_edges() says whether they may share it).
struct Wkt_numbering
{
  std::vector<std::array<double, 2> > xy;
  std::vector<std::size_t> lines;
  std::vector<std::array<std::size_t, 2> > segs;
  std::vector<std::size_t> seg_lines;
  std::vector<std::string> point_labels, segment_labels;
  std::vector<std::vector<std::size_t> > ring_segs;                  // per ring, the segment of each edge
  std::vector<std::vector<std::array<std::size_t, 2> > > ring_edges; // per segment, its (ring, edge)s
};

typedef std::unordered_map<std::array<double, 2>, std::size_t, Xy_hash> Wkt_index;

// how messages name vertex or segment `i` (0-based) of `path`, read on `line`
inline std::string wkt_label(std::size_t i, const std::string& path, std::size_t line)
{
  return std::to_string(i + 1) + " of " + path + " (line " + std::to_string(line) + ")";
}

// Numbers the vertices of a ring (`closed`) or a linestring and adds its segments in order; a
// vertex at the place of one already numbered (of a ring or a linestring) takes its index. A
// ring edge joining the two vertices of an earlier ring's edge, either way, is that segment
// (`ring_segments`, by their vertices, lowest first).
inline void number_wkt_path(const Wkt_path& path, const std::string& name, bool closed, Wkt_index& index,
                            std::map<std::array<std::size_t, 2>, std::size_t>* ring_segments, Wkt_numbering& n)
{
  std::vector<std::size_t> ids(path.xy.size());
  for(std::size_t i = 0; i < path.xy.size(); ++i) {
    auto ins = index.emplace(path.xy[i], n.xy.size());
    if(ins.second) {
      n.xy.push_back(path.xy[i]);
      n.lines.push_back(path.lines[i]);
      n.point_labels.push_back(wkt_label(i, name, path.lines[i]));
    }
    ids[i] = ins.first->second;
  }
  const std::size_t segments = closed ? ids.size() : ids.size() - 1;
  std::vector<std::size_t> edge_segs(segments);
  for(std::size_t i = 0; i < segments; ++i) {
    const std::size_t a = ids[i], b = ids[(i + 1) % ids.size()];
    if(ring_segments) {
      const auto ins = ring_segments->emplace(std::array<std::size_t, 2>{(std::min)(a, b), (std::max)(a, b)}, n.segs.size());
      edge_segs[i] = ins.first->second;
      if(!ins.second) continue;
    }
    n.segs.push_back({a, b});
    n.seg_lines.push_back(path.lines[i]);
    n.segment_labels.push_back(wkt_label(i, name, path.lines[i]));
  }
  if(!ring_segments) return;
  n.ring_edges.resize(n.segs.size());
  for(std::size_t i = 0; i < segments; ++i) n.ring_edges[edge_segs[i]].push_back({n.ring_segs.size(), i});
  n.ring_segs.push_back(std::move(edge_segs));
}

// Numbers the vertices, rings first, then linestrings, then points: rings and linestrings may
// meet at a vertex (they then share it), rings of two polygons may share an edge; isolated
// points must be new, and no other two segments may join the same vertices.
inline bool number_wkt_vertices(const Wkt_data& data, const std::string& source, Wkt_numbering& n, std::string& msg)
{
  auto where = [&](std::size_t line) { return wkt_where(source, line); };
  Wkt_index index;
  std::map<std::array<std::size_t, 2>, std::size_t> ring_segments;
  for(const Wkt_ring& r : data.rings) number_wkt_path(r, r.describe(), true, index, &ring_segments, n);
  const std::size_t ring_vertices = n.xy.size();
  for(const Wkt_linestring& s : data.linestrings) number_wkt_path(s, s.describe(), false, index, nullptr, n);
  const std::size_t path_vertices = n.xy.size();
  for(std::size_t i = 0; i < data.points.size(); ++i) {
    auto ins = index.emplace(data.points[i], n.xy.size());
    if(!ins.second) {
      const std::size_t j = ins.first->second;
      msg = where(data.point_lines[i]) + "duplicate point: " + format_point(data.points[i][0], data.points[i][1]) +
            " (line " + std::to_string(data.point_lines[i]) + ") is already " +
            (j < ring_vertices ? "a ring vertex" : j < path_vertices ? "a linestring vertex" : "a point") +
            " (line " + std::to_string(n.lines[j]) + ")";
      return false;
    }
    n.xy.push_back(data.points[i]);
    n.lines.push_back(data.point_lines[i]);
    n.point_labels.push_back(wkt_label(i, "the points", data.point_lines[i]));
  }
  std::size_t d1 = 0, d2 = 0;
  if(find_duplicate_segment(n.segs, d1, d2)) {
    const auto& s = n.segs[d2];
    msg = where(n.seg_lines[d2]) + "duplicate segment: segment " + n.segment_labels[d2] + " from " +
          format_point(n.xy[s[0]][0], n.xy[s[0]][1]) + " to " + format_point(n.xy[s[1]][0], n.xy[s[1]][1]) +
          " is also segment " + n.segment_labels[d1];
    return false;
  }
  return true;
}

// how messages name edge `e` ([ring, edge]) of the rings
inline std::string wkt_edge_label(const Wkt_data& data, const std::array<std::size_t, 2>& e)
{
  const Wkt_ring& r = data.rings[e[0]];
  return "edge " + wkt_label(e[1], r.describe(), r.lines[e[1]]);
}

// Rings of two polygons may share an edge with the polygons on either side of it (side by
// side, or one filling the other's hole), not on one side (they would overlap). A polygon lies
// left of its outer ring if that turns counterclockwise, right of its inner rings if they do.
// Rings of one polygon may touch at a vertex only, as OGC asks.
template <class K>
bool check_wkt_shared_edges(const Wkt_data& data, const std::string& source, const Wkt_numbering& n,
                            const std::vector<std::vector<typename K::Point_2> >& ring_points, const K& k,
                            std::string& msg)
{
  std::vector<bool> area_left(data.rings.size());
  for(std::size_t r = 0; r < data.rings.size(); ++r)
    area_left[r] = (CGAL::orientation_2(ring_points[r].begin(), ring_points[r].end(), k) == CGAL::COUNTERCLOCKWISE) ==
                   (data.rings[r].index == 1);
  // whether edge e has its polygon on the left of segment s, from its vertex 0 to its vertex 1
  auto polygon_left = [&](const std::array<std::size_t, 2>& e, std::size_t s) {
    return area_left[e[0]] == (n.xy[n.segs[s][0]] == data.rings[e[0]].xy[e[1]]);
  };
  for(std::size_t s = 0; s < n.ring_edges.size(); ++s)
    for(std::size_t j = 1; j < n.ring_edges[s].size(); ++j)
      for(std::size_t i = 0; i < j; ++i) {
        const std::array<std::size_t, 2>& a = n.ring_edges[s][i];
        const std::array<std::size_t, 2>& b = n.ring_edges[s][j];
        const std::size_t pa = data.rings[a[0]].polygon, pb = data.rings[b[0]].polygon;
        if(pa != pb && polygon_left(a, s) != polygon_left(b, s)) continue;
        const auto& sg = n.segs[s];
        msg = wkt_where(source, data.rings[b[0]].lines[b[1]]) + wkt_edge_label(data, b) + " from " +
              format_point(n.xy[sg[0]][0], n.xy[sg[0]][1]) + " to " + format_point(n.xy[sg[1]][0], n.xy[sg[1]][1]) +
              " is also " + wkt_edge_label(data, a) +
              (pa == pb ? ": the rings of a polygon may touch at a vertex, not share an edge"
                        : ": polygons " + std::to_string(pa) + " and " + std::to_string(pb) + " overlap, both lying on "
                          "one side of it; polygons may share an edge only side by side, or one filling the other's hole");
        return false;
      }
  return true;
}

template <class Point_2>
std::vector<Bbox_2> ring_boxes(const std::vector<std::vector<Point_2> >& ring_points)
{
  std::vector<Bbox_2> boxes;
  boxes.reserve(ring_points.size());
  for(const auto& R : ring_points) {
    Bbox_2 b = R.front().bbox();
    for(const Point_2& q : R) b += q.bbox();
    boxes.push_back(b);
  }
  return boxes;
}

// Polygons must not overlap (OGC): a polygon inside another's area, not in one of its holes,
// would become a hole of it by the nesting of the loops, and its area would be lost. Rings
// that cross are found by the domain's own checks; one vertex of an outer ring off the other
// polygon's rings tells whether it lies inside.
template <class K>
bool check_wkt_polygons_apart(const Wkt_data& data, const std::string& source,
                              const std::vector<std::vector<typename K::Point_2> >& ring_points,
                              const std::vector<Bbox_2>& boxes, const K& k, std::string& msg)
{
  typedef typename K::Point_2 Point_2;
  auto strictly_inside = [&](std::size_t ri, const Point_2& q) {
    return CGAL::bounded_side_2(ring_points[ri].begin(), ring_points[ri].end(), q, k) == CGAL::ON_BOUNDED_SIDE;
  };
  auto on_ring = [&](std::size_t ri, const Point_2& q) {
    return CGAL::bounded_side_2(ring_points[ri].begin(), ring_points[ri].end(), q, k) == CGAL::ON_BOUNDARY;
  };
  std::map<std::size_t, std::vector<std::size_t> > rings_of; // by polygon number
  for(std::size_t h = 0; h < data.rings.size(); ++h) rings_of[data.rings[h].polygon].push_back(h);
  for(std::size_t b = 0; b < data.rings.size(); ++b) {
    if(data.rings[b].index != 1) continue;
    for(std::size_t a = 0; a < data.rings.size(); ++a) {
      if(a == b || data.rings[a].index != 1 || !CGAL::do_overlap(boxes[a], boxes[b])) continue;
      const std::size_t poly = data.rings[a].polygon;
      const std::vector<std::size_t>& rings_of_a = rings_of[poly];
      const auto probe = std::find_if(ring_points[b].begin(), ring_points[b].end(), [&](const Point_2& q) {
        return std::none_of(rings_of_a.begin(), rings_of_a.end(), [&](std::size_t h) { return on_ring(h, q); });
      });
      if(probe == ring_points[b].end() || !strictly_inside(a, *probe)) continue;
      const bool in_a_hole = std::any_of(rings_of_a.begin(), rings_of_a.end(), [&](std::size_t h) {
        return data.rings[h].index != 1 && strictly_inside(h, *probe);
      });
      if(in_a_hole) continue;
      const std::size_t i = std::size_t(probe - ring_points[b].begin());
      msg = wkt_where(source, data.rings[b].lines[i]) + data.rings[b].describe() + " lies inside polygon " +
            std::to_string(poly) + " (line " + std::to_string(data.rings[a].line) + "): its vertex " +
            format_point(data.rings[b].xy[i][0], data.rings[b].xy[i][1]) + " (line " +
            std::to_string(data.rings[b].lines[i]) + ") is in that polygon's area; polygons must not "
            "overlap (an island in a hole is a polygon inside an inner ring)";
      return false;
    }
  }
  return true;
}

// The outer rings of the other polygons that lie in inner ring h: islands in the hole, at any
// depth.
template <class K>
std::vector<std::size_t> wkt_outer_rings_in(const Wkt_data& data, const std::vector<std::vector<typename K::Point_2> >& ring_points,
                                            const std::vector<Bbox_2>& boxes, std::size_t h, const K& k)
{
  std::vector<std::size_t> in_h;
  for(std::size_t r = 0; r < data.rings.size(); ++r)
    if(data.rings[r].index == 1 && data.rings[r].polygon != data.rings[h].polygon && CGAL::do_overlap(boxes[r], boxes[h]) &&
       ring_lies_in(ring_points, r, h, k))
      in_h.push_back(r);
  return in_h;
}

// The parts of the hole of inner ring h that no polygon covers, given the outer rings `in_h` of
// the polygons in it. Their segments and h's make a plane graph with E - V + C faces inside h
// (Euler), one inside each ring of `in_h` and the others uncovered. Less than 1 if they fill h.
inline std::ptrdiff_t wkt_uncovered_parts(const Wkt_numbering& n, std::size_t h, const std::vector<std::size_t>& in_h)
{
  std::vector<std::size_t> segs = n.ring_segs[h];
  for(std::size_t r : in_h) segs.insert(segs.end(), n.ring_segs[r].begin(), n.ring_segs[r].end());
  std::sort(segs.begin(), segs.end());
  segs.erase(std::unique(segs.begin(), segs.end()), segs.end());
  std::map<std::size_t, std::size_t> parent;  // union-find over the vertices
  auto find = [&](std::size_t v) {
    while(parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for(std::size_t s : segs)
    for(std::size_t v : n.segs[s]) parent.emplace(v, v);
  std::ptrdiff_t components = std::ptrdiff_t(parent.size());
  for(std::size_t s : segs) {
    const std::size_t a = find(n.segs[s][0]), b = find(n.segs[s][1]);
    if(a != b) { parent[a] = b; --components; }
  }
  return std::ptrdiff_t(segs.size()) - std::ptrdiff_t(parent.size()) + components - std::ptrdiff_t(in_h.size());
}

// Hole seeds, one per inner ring, in the part of its hole that the polygons inside it leave
// uncovered; none if they fill it (their domain). One seed marks one part: a hole that they
// cut into several is an error.
template <class K>
bool wkt_hole_seeds(const Wkt_data& data, const std::string& source, const Wkt_numbering& n,
                    const std::vector<std::vector<typename K::Point_2> >& ring_points, const std::vector<Bbox_2>& boxes,
                    const K& k, std::vector<typename K::Point_2>& holes, std::string& msg)
{
  for(std::size_t ri = 0; ri < data.rings.size(); ++ri) {
    if(data.rings[ri].index == 1) continue;
    const std::ptrdiff_t parts = wkt_uncovered_parts(n, ri, wkt_outer_rings_in(data, ring_points, boxes, ri, k));
    if(parts < 1) continue;
    if(parts > 1) {
      msg = wkt_where(source, data.rings[ri].line) + "the polygons inside " + data.rings[ri].describe() + " cut the hole into " +
            std::to_string(parts) + " parts; a hole is one part: give each part as an inner ring, or fill it with a polygon";
      return false;
    }
    typename K::Point_2 seed;
    if(!find_hole_seed(ring_points, boxes, ri, k, seed)) {
      msg = wkt_where(source, data.rings[ri].line) + "cannot find a point strictly inside " + data.rings[ri].describe() +
            " and outside every other ring (do rings cross each other?)";
      return false;
    }
    holes.push_back(seed);
  }
  return true;
}

template <class K>
bool wkt_to_domain(Wkt_data& data, const std::string& source, Domain_2<K>& out, std::string& msg)
{
  typedef typename K::Point_2 Point_2;
  const K k;
  std::vector<std::vector<Point_2> > ring_points;
  Wkt_numbering numbering;
  if(!check_wkt_rings(data, source, ring_points, k, msg) || !check_wkt_linestrings(data, source, msg) ||
     !number_wkt_vertices(data, source, numbering, msg) ||
     !check_wkt_shared_edges(data, source, numbering, ring_points, k, msg))
    return false;
  const std::vector<Bbox_2> boxes = ring_boxes(ring_points);
  std::vector<Point_2> holes;
  if(!check_wkt_polygons_apart(data, source, ring_points, boxes, k, msg) ||
     !wkt_hole_seeds(data, source, numbering, ring_points, boxes, k, holes, msg))
    return false;
  append_points<K>(numbering.xy, out.points, k);
  out.segments = std::move(numbering.segs);
  out.holes = std::move(holes);
  out.every_hole_marked = true;  // an inner ring a polygon fills has no seed, and is no hole
  out.point_labels = std::move(numbering.point_labels);
  out.segment_labels = std::move(numbering.segment_labels);
  return true;
}

template <class K>
bool read_WKT_impl(std::string&& text, const std::string& source, Domain_2<K>& out, std::string* error)
{
  return guarded_read(source, out, error, [&](std::string& msg) {
    Wkt_lexer lex(text, source);
    Wkt_data data;
    Wkt_parser parser(lex, data, msg);
    if(text.empty()) msg = source + ":1: empty file";
    else if(parser.parse() && wkt_to_domain(data, source, out, msg)) return true;
    return false;
  });
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Reads one WKT geometry into `out` (replacing its content): a `POLYGON`, `MULTIPOLYGON`,
/// `POINT`, `MULTIPOINT`, or a `GEOMETRYCOLLECTION` of these and of `LINESTRING`s and
/// `MULTILINESTRING`s (keywords case-insensitive, `EMPTY` allowed, an EWKT `SRID=...;` prefix
/// skipped). A second geometry after the first is an error naming its line: several polygons go
/// in one `MULTIPOLYGON`. Only 2D coordinates are accepted (`Z`/`M` are errors).
///
/// Each ring becomes a closed chain of segments; it must end at its first point, as WKT
/// asks (an open ring is an error, not closed silently). Each ring must have at least 3 distinct vertices, no repeated vertex and be
/// simple (`CGAL::is_simple_2`). A vertex at the place of one already read (exact
/// coordinates) is that vertex, and a ring edge joining the same two vertices as an earlier
/// ring's edge, either way, is that one segment: polygons sharing edges are regions of one
/// domain, meshed together (see `extract_loops()`). An edge shared by two rings of one
/// polygon, or by two polygons on one side of it (they overlap), or a POINT equal to another
/// point or ring vertex, is an error. For each inner ring (hole) a seed point is added to
/// `out.holes`: it lies strictly inside the hole ring, on no ring and outside every polygon
/// in the hole (islands), checked with exact predicates. An inner ring that the polygons in
/// it fill (an island given as its own polygon, a lake tiled by several) gets no seed, and
/// one they cut into several parts is an error; `out.every_hole_marked` is set, so a hole is
/// exactly a face holding a seed. Ring orientation is kept as in the file. A polygon inside
/// another polygon's area (not in one of its holes) is an error, as OGC forbids overlapping
/// polygons. Crossings between different rings, and a vertex of one ring inside another's
/// edge, are not detected here (the mesher's domain checks name them).
///
/// Each linestring becomes an open polyline of segments in its order, a crack in the domain
/// (see `extract_loops()`): it needs a polygon in the same collection, at least 2 distinct
/// vertices, no two equal consecutive ones, and a last point other than its first (a closed
/// one is a polygon ring). A vertex at the place of a ring's or another linestring's vertex is
/// that vertex; a segment joining the same two vertices as another, or a POINT there, is an
/// error. Whether it lies in the domain and meets no ring is left to `extract_loops()`, whose
/// messages name its vertices and segments as `2 of linestring 1 (line 3)`, and rings' as
/// `2 of the outer ring of polygon 1 (line 3)`.
///
/// Errors: one message `SOURCE:LINE: problem` in `*error`, `out` left empty. Never throws.
template <class K>
bool read_WKT(std::istream& in, Domain_2<K>& out, std::string* error = nullptr,
              const std::string& source_name = "<stream>")
{
  std::string text, msg;
  if(!internal::slurp(in, text, source_name, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_WKT_impl(std::move(text), source_name, out, error);
}

/// \ingroup PkgQuadMesher2IO
/// Reads the WKT file `filename`; see the stream overload.
template <class K>
bool read_WKT(const std::string& filename, Domain_2<K>& out, std::string* error = nullptr)
{
  std::string text, msg;
  if(!internal::slurp_file(filename, text, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_WKT_impl(std::move(text), filename, out, error);
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_READ_WKT_H
