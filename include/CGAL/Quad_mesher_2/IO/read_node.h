// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers

#ifndef CGAL_QUAD_MESHER_2_IO_READ_NODE_H
#define CGAL_QUAD_MESHER_2_IO_READ_NODE_H

#include <CGAL/Quad_mesher_2/Domain_2.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace CGAL {
namespace Quad_mesher_2 {
namespace IO {
/// \ingroup PkgQuadMesher2IO
/// What a point-file reader does with two points at exactly the same place: report the file
/// and lines (the default), or keep both for the mesher, which merges and counts them.
enum class Duplicate_points { REJECT, KEEP };

namespace internal {

// Shared machinery of the text readers (`read_node.h`, `read_poly.h`, `read_xy.h`,
// `read_WKT.h`). Every error is one message `SOURCE:LINE: problem`.

/// Coordinates larger than this in absolute value are rejected: squaring them would overflow.
constexpr double max_coordinate_magnitude = 1e150;

inline std::string format_double(double v)
{
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.17g", v);
  return buf;
}

inline std::string format_point(double x, double y)
{
  return "(" + format_double(x) + ", " + format_double(y) + ")";
}

/// Quotes a token for an error message, shortening it if it is long.
inline std::string quote(std::string_view tok)
{
  std::string s;
  const std::size_t max_len = 40;
  for(std::size_t i = 0; i < tok.size() && i < max_len; ++i) {
    const unsigned char c = static_cast<unsigned char>(tok[i]);
    if(c < 32 || c >= 127) { char b[8]; std::snprintf(b, sizeof(b), "\\x%02X", c); s += b; }
    else s += static_cast<char>(c);
  }
  if(tok.size() > max_len) s += "...";
  return "\"" + s + "\"";
}

/// Parses the whole token as a decimal floating-point number (a leading '+' is allowed).
/// Returns false if the token is not entirely a number; non-finite values are returned as
/// parsed (the caller decides).
inline bool parse_double(std::string_view tok, double& v)
{
  const char* b = tok.data();
  const char* e = b + tok.size();
  if(b != e && *b == '+') { ++b; if(b != e && (*b == '-' || *b == '+')) return false; }
  if(b == e) return false;
  auto res = std::from_chars(b, e, v, std::chars_format::general);
  if(res.ec == std::errc::result_out_of_range) {
    // from_chars leaves v unchanged on overflow/underflow: decide with strtod, and report
    // an overflow as the largest double (so that it is rejected as too large, not non-finite).
    v = std::strtod(std::string(tok).c_str(), nullptr);
    if(std::isinf(v)) v = std::copysign((std::numeric_limits<double>::max)(), v);
    return res.ptr == e;
  }
  return res.ec == std::errc() && res.ptr == e;
}

/// Parses the whole token as a decimal integer (a leading '+' is allowed).
inline bool parse_integer(std::string_view tok, long long& v)
{
  const char* b = tok.data();
  const char* e = b + tok.size();
  if(b != e && *b == '+') { ++b; if(b != e && (*b == '-' || *b == '+')) return false; }
  if(b == e) return false;
  auto res = std::from_chars(b, e, v, 10);
  return res.ec == std::errc() && res.ptr == e;
}

/// A whole text file in memory, read line by line. `#` starts a comment that runs to the end
/// of the line; blank and comment-only lines are skipped; tokens are separated by blanks,
/// tabs or carriage returns (the `\r` of CRLF line ends; `normalise_text()` has made every
/// other one a line feed).
class Text_lines
{
public:
  Text_lines(std::string&& text, std::string source)
    : m_text(std::move(text)), m_source(std::move(source))
  {}

  const std::string& source() const { return m_source; }
  const std::string& text() const { return m_text; }
  bool is_empty() const { return m_text.empty(); }

  /// Moves to the next line that holds data; false at end of input.
  bool next()
  {
    while(m_pos < m_text.size()) {
      const std::size_t begin = m_pos;
      const void* nl = std::memchr(m_text.data() + begin, '\n', m_text.size() - begin);
      const std::size_t end =
        nl ? static_cast<std::size_t>(static_cast<const char*>(nl) - m_text.data()) : m_text.size();
      m_pos = (end < m_text.size()) ? end + 1 : end;
      ++m_line;
      m_tokens.clear();
      std::size_t i = begin;
      while(i < end) {
        const char c = m_text[i];
        if(c == '#') break;
        if(c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') { ++i; continue; }
        std::size_t j = i;
        while(j < end) {
          const char d = m_text[j];
          if(d == ' ' || d == '\t' || d == '\r' || d == '\f' || d == '\v' || d == '#') break;
          ++j;
        }
        m_tokens.emplace_back(m_text.data() + i, j - i);
        i = j;
      }
      if(!m_tokens.empty()) return true;
    }
    m_tokens.clear();
    return false;
  }

  /// 1-based number of the current line.
  std::size_t line() const { return m_line; }
  /// The line number to report for "unexpected end of file".
  std::size_t end_line() const
  {
    const std::size_t n = static_cast<std::size_t>(std::count(m_text.begin(), m_text.end(), '\n'));
    const std::size_t last = (m_text.empty() || m_text.back() == '\n') ? n : n + 1;
    return (std::max)(last, std::size_t(1));
  }
  const std::vector<std::string_view>& tokens() const { return m_tokens; }
  std::size_t size() const { return m_tokens.size(); }
  std::string_view operator[](std::size_t i) const { return m_tokens[i]; }

  std::string where(std::size_t line) const { return m_source + ":" + std::to_string(line) + ": "; }
  std::string here() const { return where(m_line); }

private:
  std::string m_text;
  std::string m_source;
  std::size_t m_pos = 0;
  std::size_t m_line = 0;
  std::vector<std::string_view> m_tokens;
};

inline void set_error(std::string* error, const std::string& msg)
{
  if(error) *error = msg;
}

// The frame every reader shares: `out` emptied, `parse(msg)` run, any exception turned into a
// message, and on failure `out` left empty and the one message reported.
template <class K, class Parse>
bool guarded_read(const std::string& source, Domain_2<K>& out, std::string* error, Parse parse)
{
  out = Domain_2<K>();
  std::string msg;
  try {
    if(parse(msg))
      return true;
  } catch(const std::exception& e) {
    msg = source + ": " + e.what();
  } catch(...) {
    msg = source + ": unknown error";
  }
  out = Domain_2<K>();
  set_error(error, msg);
  return false;
}

/// Drops a UTF-8 byte order mark, which editors on Windows put before the first line, and
/// turns each carriage return that does not start a CRLF (old Mac line ends) into a line feed:
/// the readers then see one kind of line end, and count lines as the user's editor does.
inline void normalise_text(std::string& text)
{
  if(text.compare(0, 3, "\xEF\xBB\xBF") == 0)
    text.erase(0, 3);
  for(std::size_t i = text.find('\r'); i != std::string::npos; i = text.find('\r', i + 1))
    if(i + 1 == text.size() || text[i + 1] != '\n')
      text[i] = '\n';
}

/// Reads a whole stream into memory. False (and a message) on a stream error.
inline bool slurp(std::istream& in, std::string& text, const std::string& source, std::string& msg)
{
  text.clear();
  if(!in) { msg = source + ": cannot read from the stream"; return false; }
  std::ostringstream ss;
  ss << in.rdbuf();
  if(in.bad()) { msg = source + ": read error"; return false; }
  text = std::move(ss).str();
  normalise_text(text);
  return true;
}

inline std::string file_type_name(std::filesystem::file_type type)
{
  switch(type) {
  case std::filesystem::file_type::fifo: return "a FIFO";
  case std::filesystem::file_type::character: return "a character device";
  case std::filesystem::file_type::block: return "a block device";
  case std::filesystem::file_type::socket: return "a socket";
  default: return "a special file";
  }
}

/// False, with a message naming `filename` and what it is, if it exists and is not a regular
/// file (or a link to one): opening a FIFO without a writer blocks for ever, and a device such
/// as /dev/zero reads as an empty or endless file. A missing file passes: opening it then
/// gives the system's reason.
inline bool is_regular_or_missing(const std::string& filename, std::string& msg)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_type type = fs::status(filename, ec).type();
  if(type == fs::file_type::regular || type == fs::file_type::not_found || type == fs::file_type::none)
    return true;
  msg = filename + (type == fs::file_type::directory ? std::string(": is a directory, not a file")
                                                   : ": is not a regular file (" + file_type_name(type) + ")");
  return false;
}

/// Opens and reads a whole file. False (and a message naming the file) if it cannot be read.
inline bool slurp_file(const std::string& filename, std::string& text, std::string& msg)
{
  text.clear();
  if(!is_regular_or_missing(filename, msg))
    return false;
  errno = 0;
  std::ifstream in(filename, std::ios::in | std::ios::binary);
  if(!in) {
    const int e = errno;
    msg = filename + ": cannot open file" + (e ? std::string(" (") + std::strerror(e) + ")" : std::string());
    return false;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if(size > 0) {
    try {
      text.resize(static_cast<std::size_t>(size));
    } catch(const std::exception&) {
      msg = filename + ": cannot read a file of " + std::to_string(size) + " bytes into memory";
      return false;
    }
    in.read(&text[0], size);
    if(in.gcount() != size) { msg = filename + ": read error (file could not be read completely)"; text.clear(); return false; }
    normalise_text(text);
    return true;
  }
  // No size to trust (files under /proc report 0): copy the stream.
  in.clear();
  in.seekg(0, std::ios::beg);
  return slurp(in, text, filename, msg);
}

/// Parses a coordinate token, checking that it is a finite number of sane magnitude.
/// Returns an empty string on success, else the problem (to be prefixed with `SOURCE:LINE: `).
/// `what` is only called on failure, so that the success path allocates nothing.
template <class What>
inline bool read_coordinate(std::string_view tok, double& v, std::string& problem, const What& what)
{
  if(!parse_double(tok, v)) {
    problem = "expected a number for " + what() + ", found " + quote(tok);
    return false;
  }
  if(!std::isfinite(v)) {
    problem = what() + " is not finite: " + quote(tok);
    return false;
  }
  if(std::fabs(v) > max_coordinate_magnitude) {
    problem = what() + " is too large: " + quote(tok) + " (|value| must be at most 1e150)";
    return false;
  }
  return true;
}

/// Parses a count token: a non-negative integer.
inline bool read_count(std::string_view tok, long long& v, const std::string& where,
                       const std::string& what, std::string& msg)
{
  if(!parse_integer(tok, v)) {
    msg = where + "expected an integer for " + what + ", found " + quote(tok);
    return false;
  }
  if(v < 0) {
    msg = where + what + " is negative (" + std::to_string(v) + ")";
    return false;
  }
  return true;
}

/// Finds two points with exactly equal coordinates. On success (a duplicate exists), `first`
/// and `second` are the indices (first < second) of the pair with the smallest `second`.
inline bool find_duplicate_point(const std::vector<std::array<double, 2> >& xy,
                                 std::size_t& first, std::size_t& second)
{
  struct Entry { double x, y; std::size_t i; };
  std::vector<Entry> v;
  v.reserve(xy.size());
  for(std::size_t i = 0; i < xy.size(); ++i) v.push_back(Entry{xy[i][0], xy[i][1], i});
  std::sort(v.begin(), v.end(), [](const Entry& a, const Entry& b) {
    if(a.x < b.x) return true;
    if(b.x < a.x) return false;
    if(a.y < b.y) return true;
    if(b.y < a.y) return false;
    return a.i < b.i;
  });
  bool found = false;
  for(std::size_t k = 1; k < v.size(); ++k) {
    if(v[k].x == v[k - 1].x && v[k].y == v[k - 1].y) {
      // v[k-1].i < v[k].i; only the first pair of a run matters (smallest two indices).
      if(k >= 2 && v[k - 2].x == v[k].x && v[k - 2].y == v[k].y) continue;
      if(!found || v[k].i < second) { first = v[k - 1].i; second = v[k].i; found = true; }
    }
  }
  return found;
}

/// Finds two segments joining the same two vertices (in either direction). On success,
/// `first` < `second` are the positions of the pair with the smallest `second`.
inline bool find_duplicate_segment(const std::vector<std::array<std::size_t, 2> >& segs,
                                   std::size_t& first, std::size_t& second)
{
  struct Entry { std::size_t a, b, i; };
  std::vector<Entry> v;
  v.reserve(segs.size());
  for(std::size_t i = 0; i < segs.size(); ++i)
    v.push_back(Entry{(std::min)(segs[i][0], segs[i][1]), (std::max)(segs[i][0], segs[i][1]), i});
  std::sort(v.begin(), v.end(), [](const Entry& l, const Entry& r) {
    if(l.a != r.a) return l.a < r.a;
    if(l.b != r.b) return l.b < r.b;
    return l.i < r.i;
  });
  bool found = false;
  for(std::size_t k = 1; k < v.size(); ++k) {
    if(v[k].a == v[k - 1].a && v[k].b == v[k - 1].b) {
      if(k >= 2 && v[k - 2].a == v[k].a && v[k - 2].b == v[k].b) continue;
      if(!found || v[k].i < second) { first = v[k - 1].i; second = v[k].i; found = true; }
    }
  }
  return found;
}

/// The vertex list of a Triangle `.node` file, or of a `.poly` file's first section.
struct Vertex_list
{
  std::vector<std::array<double, 2> > xy;
  std::vector<std::size_t> lines;  // line of each vertex
  std::size_t base = 0;            // 0 or 1: index of the first vertex, as in Triangle
  std::size_t header_line = 0;
  std::string source;
};

inline std::string base_name(std::size_t base) { return base == 0 ? "0-based" : "1-based"; }

/// Moves `r` to line `i` (from 0) of a section of `count` indexed lines, announced by
/// `header` on line `header_line`: the line must be there and start with the index
/// `base + i`, `base` (0 or 1) being set by the first line. `what` names one line's item
/// ("vertex"), `items` several; with `name_base` an index out of sequence is reported with
/// the numbering the section uses.
inline bool next_indexed_line(Text_lines& r, std::size_t i, std::size_t count, std::size_t& base, const std::string& what,
                              const std::string& items, const std::string& header, std::size_t header_line,
                              bool name_base, std::string& msg)
{
  if(!r.next()) {
    msg = r.where(r.end_line()) + "unexpected end of file: " + header + " (line " + std::to_string(header_line) +
          ") announces " + std::to_string(count) + " " + items + ", but only " + std::to_string(i) + " were found";
    return false;
  }
  long long idx = 0;
  if(!parse_integer(r[0], idx)) { msg = r.here() + "expected an integer " + what + " index, found " + quote(r[0]); return false; }
  if(i == 0) {
    if(idx != 0 && idx != 1) { msg = r.here() + "the first " + what + " index must be 0 or 1, found " + std::string(r[0]); return false; }
    base = static_cast<std::size_t>(idx);
  } else if(idx != static_cast<long long>(i + base)) {
    msg = r.here() + what + " index " + std::string(r[0]) + " out of sequence: expected " + std::to_string(i + base) +
          " (indices must be consecutive" + (name_base ? ", " + base_name(base) : std::string()) +
          "; an index was skipped or repeated)";
    return false;
  }
  return true;
}

// How messages after reading name the item of each line: its number in the file (from
// `base`) and its line, in `file` if that is not the file being read.
inline std::vector<std::string> file_labels(std::size_t base, const std::vector<std::size_t>& lines,
                                            const std::string& file = std::string())
{
  std::vector<std::string> labels;
  labels.reserve(lines.size());
  const std::string in = file.empty() ? std::string(" (line ") : " (" + file + " line ";
  for(std::size_t i = 0; i < lines.size(); ++i)
    labels.push_back(std::to_string(i + base) + in + std::to_string(lines[i]) + ")");
  return labels;
}

/// Reads the vertex header (`<#vertices> [<dimension> [<#attributes> [<#markers>]]]`,
/// missing fields default to 2, 0, 0 as in Triangle) and, if the count is not zero, the
/// vertices. `count` receives the announced number of vertices.
inline bool read_vertex_section(Text_lines& r, Vertex_list& out, long long& count, std::string& msg)
{
  out = Vertex_list();
  out.source = r.source();
  if(!r.next()) {
    msg = r.where(r.end_line()) + (r.is_empty() ? "empty file" : "no data (the file holds only comments or blank lines)");
    return false;
  }
  out.header_line = r.line();
  const std::string w = r.here();
  if(!read_count(r[0], count, w, "the number of vertices", msg)) return false;
  long long dim = 2, nattr = 0, nmark = 0;
  if(r.size() > 1) {
    if(!parse_integer(r[1], dim)) { msg = w + "expected an integer for the dimension, found " + quote(r[1]); return false; }
    if(dim != 2) { msg = w + "dimension must be 2, found " + std::string(r[1]); return false; }
  }
  if(r.size() > 2 && !read_count(r[2], nattr, w, "the number of vertex attributes", msg)) return false;
  if(r.size() > 3) {
    if(!read_count(r[3], nmark, w, "the number of vertex boundary markers", msg)) return false;
    if(nmark > 1) { msg = w + "the number of vertex boundary markers must be 0 or 1, found " + std::string(r[3]); return false; }
  }
  if(r.size() > 4) { msg = w + "unexpected text " + quote(r[4]) + " after the vertex header"; return false; }
  if(count == 0) return true;

  // Do not trust the count for the allocation: each vertex takes at least 6 bytes.
  const std::size_t cap = r.text().size() / 6 + 1;
  const std::size_t n = static_cast<std::size_t>(count);
  out.xy.reserve((std::min)(n, cap));
  out.lines.reserve((std::min)(n, cap));
  // Tokens on every vertex line. No line has as many tokens as the file has bytes, so capping
  // the attributes there cannot overflow and keeps the count exact for every line.
  const std::size_t line_tokens = 3 + static_cast<std::size_t>((std::min)(nattr, static_cast<long long>(r.text().size()))) +
                                  static_cast<std::size_t>(nmark);
  for(std::size_t i = 0; i < n; ++i) {
    if(!next_indexed_line(r, i, n, out.base, "vertex", "vertices", "the header", out.header_line, true, msg))
      return false;
    auto label = [&]() { return "vertex " + std::to_string(i + out.base); };
    if(r.size() < 3) { msg = r.here() + label() + " has " + (r.size() == 1 ? "no coordinates" : "only one coordinate") + " (expected: index x y)"; return false; }
    double x = 0, y = 0;
    std::string problem;
    if(!read_coordinate(r[1], x, problem, [&]() { return "the x coordinate of " + label(); }) ||
       !read_coordinate(r[2], y, problem, [&]() { return "the y coordinate of " + label(); })) {
      msg = r.here() + problem;
      return false;
    }
    if(r.size() > line_tokens) {
      const std::string wl = r.here();
      msg = wl + "unexpected text " + quote(r[line_tokens]) + " after " + label() + " (the header announces " +
            std::to_string(nattr) + " attribute(s) and " + std::to_string(nmark) + " marker(s))";
      return false;
    }
    // Every attribute and marker the header announces: Triangle would default missing ones to
    // 0, but a short line cannot say which value is missing, and the header says it is there.
    if(r.size() < line_tokens) {
      msg = r.here() + label() + " has " + std::to_string(r.size() - 3) + " value(s) after its coordinates, but the header (line " +
            std::to_string(out.header_line) + ") announces " + std::to_string(nattr) + " attribute(s) and " +
            std::to_string(nmark) + " marker(s)";
      return false;
    }
    // Attributes (ignored) must be numbers; the marker an integer.
    for(std::size_t t = 3; t < r.size(); ++t) {
      double dummy;
      const bool is_marker = (nmark == 1 && t == line_tokens - 1);
      long long m = 0;
      if(is_marker ? !parse_integer(r[t], m) : !parse_double(r[t], dummy)) {
        msg = r.here() + "expected " + (is_marker ? "an integer boundary marker" : "a number for an attribute") + " of " + label() +
              ", found " + quote(r[t]);
        return false;
      }
    }
    out.xy.push_back({x, y});
    out.lines.push_back(r.line());
  }
  return true;
}

inline bool check_duplicate_vertices(const Vertex_list& v, std::string& msg)
{
  std::size_t a = 0, b = 0;
  if(find_duplicate_point(v.xy, a, b)) {
    msg = v.source + ":" + std::to_string(v.lines[b]) + ": duplicate point: vertex " + std::to_string(b + v.base) +
          " (line " + std::to_string(v.lines[b]) + ") and vertex " + std::to_string(a + v.base) + " (line " +
          std::to_string(v.lines[a]) + ") are both at " + format_point(v.xy[b][0], v.xy[b][1]);
    return false;
  }
  return true;
}

/// Builds the points with the kernel's `Construct_point_2`.
template <class K>
void append_points(const std::vector<std::array<double, 2> >& xy, std::vector<typename K::Point_2>& pts, const K& k = K())
{
  typename K::Construct_point_2 cp = k.construct_point_2_object();
  pts.reserve(pts.size() + xy.size());
  for(const auto& p : xy) pts.push_back(cp(typename K::FT(p[0]), typename K::FT(p[1])));
}

inline bool read_node_text(Text_lines& r, Vertex_list& v, std::string& msg,
                           Duplicate_points duplicates = Duplicate_points::REJECT)
{
  long long count = 0;
  if(!read_vertex_section(r, v, count, msg)) return false;
  if(count == 0) { msg = r.where(v.header_line) + "the file lists no vertices"; return false; }
  if(r.next()) {
    msg = r.here() + "unexpected text " + quote(r[0]) + " after the last vertex (the header announces " +
          std::to_string(count) + " vertices)";
    return false;
  }
  return duplicates == Duplicate_points::KEEP || check_duplicate_vertices(v, msg);
}

template <class K>
bool read_node_impl(std::string&& text, const std::string& source, Domain_2<K>& out, std::string* error,
                    Duplicate_points duplicates)
{
  return guarded_read(source, out, error, [&](std::string& msg) {
    Text_lines r(std::move(text), source);
    Vertex_list v;
    if(read_node_text(r, v, msg, duplicates)) {
      append_points<K>(v.xy, out.points);
      out.point_labels = file_labels(v.base, v.lines);
      return true;
    }
    return false;
  });
}

} // namespace internal

/// \ingroup PkgQuadMesher2IO
/// Reads a Triangle `.node` file (points only) from `in` into `out` (replacing its content).
/// Format: `<#vertices> [<dimension=2> [<#attributes> [<#boundary markers (0|1)>]]]`, then one
/// line `<index> <x> <y> [attributes...] [marker]` per vertex, indices consecutive from 0 or 1
/// (the first decides); `#` starts a comment. Rejects non-numeric or trailing text, non-finite
/// or too large (|v| > 1e150) coordinates, truncation, out-of-sequence indices and duplicate
/// points. Returns `false` on failure, leaves `out` empty and sets `*error` to one message
/// `SOURCE:LINE: problem`. Never throws.
template <class K>
bool read_node(std::istream& in, Domain_2<K>& out, std::string* error = nullptr,
               const std::string& source_name = "<stream>",
               Duplicate_points duplicates = Duplicate_points::REJECT)
{
  std::string text, msg;
  if(!internal::slurp(in, text, source_name, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_node_impl(std::move(text), source_name, out, error, duplicates);
}

/// \ingroup PkgQuadMesher2IO
/// Reads the Triangle `.node` file `filename`; see the stream overload. Messages are
/// prefixed with `filename`.
template <class K>
bool read_node(const std::string& filename, Domain_2<K>& out, std::string* error = nullptr,
               Duplicate_points duplicates = Duplicate_points::REJECT)
{
  std::string text, msg;
  if(!internal::slurp_file(filename, text, msg)) { out = Domain_2<K>(); internal::set_error(error, msg); return false; }
  return internal::read_node_impl(std::move(text), filename, out, error, duplicates);
}

} // namespace IO
} // namespace Quad_mesher_2
} // namespace CGAL

#endif // CGAL_QUAD_MESHER_2_IO_READ_NODE_H
