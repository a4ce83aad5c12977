// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests of the domain readers in CGAL/Quad_mesher_2/IO/: .poly, .node, .xy, WKT, read_domain.

#include "qm2_fifo.h"
#include "qm2_test_kernel.h"
#include "qm2_time_bounds.h"

#include <CGAL/Quad_mesher_2/Domain_2.h>
#include <CGAL/Quad_mesher_2/Domain_loops_2.h>
#include <CGAL/Quad_mesher_2/IO/read_WKT.h>
#include <CGAL/Quad_mesher_2/IO/read_domain.h>
#include <CGAL/Quad_mesher_2/IO/read_node.h>
#include <CGAL/Quad_mesher_2/IO/read_poly.h>
#include <CGAL/Quad_mesher_2/IO/read_xy.h>

#include <CGAL/Polygon_2_algorithms.h>

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace qm2_test_io_read {

using K = qm2_test::K;
using Domain = CGAL::Quad_mesher_2::Domain_2<K>;
using Point_2 = K::Point_2;
namespace QIO = CGAL::Quad_mesher_2::IO;
namespace fs = std::filesystem;

inline const char* kernel_name() { return qm2_test::exact_constructions ? "epeck" : "epick"; }

inline fs::path scratch_path()
{
  return fs::temp_directory_path() /
         ("qm2_test_io_read_" + std::string(kernel_name()) + "_" + std::to_string(::getpid()));
}

/// A scratch directory private to this process (both kernel binaries may run at once).
inline fs::path scratch_dir()
{
  static const fs::path dir = [] {
    fs::path d = scratch_path();
    fs::create_directories(d);
    return d;
  }();
  return dir;
}

/// Removes the scratch directory at exit.
struct Scratch_cleanup
{
  ~Scratch_cleanup()
  {
    std::error_code ec;
    fs::remove_all(scratch_path(), ec);
  }
};
inline Scratch_cleanup scratch_cleanup;

inline std::string write_file(const std::string& name, const std::string& content)
{
  const fs::path p = scratch_dir() / name;
  std::ofstream out(p, std::ios::binary);
  out << content;
  return p.string();
}

inline bool is_empty(const Domain& d) { return d.points.empty() && d.segments.empty() && d.holes.empty(); }

inline bool same_domain(const Domain& a, const Domain& b)
{
  return a.points == b.points && a.segments == b.segments && a.holes == b.holes;
}

/// Expects a failed read with an error `FILE:LINE: ...` that contains `keyword`.
inline void expect_error(bool ok, const Domain& d, const std::string& err, const std::string& file,
                         std::size_t line, const std::string& keyword)
{
  EXPECT_FALSE(ok);
  EXPECT_TRUE(is_empty(d));
  const std::string prefix = file + ":" + std::to_string(line) + ": ";
  EXPECT_EQ(err.rfind(prefix, 0), 0u) << "error: " << err << "\nexpected prefix: " << prefix;
  EXPECT_NE(err.find(keyword), std::string::npos) << "error: " << err << "\nexpected key word: " << keyword;
}

/// A square with a square hole, 1-based, with markers and comments.
inline std::string square_with_hole_poly(int base)
{
  std::ostringstream s;
  const int b = base;
  s << "# square with a hole\n8 2 1 1\n";
  const double xy[8][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {2, 2}, {8, 2}, {8, 8}, {2, 8}};
  for(int i = 0; i < 8; ++i) s << (i + b) << " " << xy[i][0] << " " << xy[i][1] << " 0.5 " << (i < 4 ? 1 : 2) << "\n";
  s << "8 1  # segments\n";
  for(int i = 0; i < 4; ++i) s << (i + b) << " " << (i + b) << " " << ((i + 1) % 4 + b) << " 1\n";
  for(int i = 0; i < 4; ++i) s << (i + 4 + b) << " " << (i + 4 + b) << " " << ((i + 1) % 4 + 4 + b) << " 2\n";
  s << "1\n" << b << " 5 5\n";
  return s.str();
}

/// Writes `d` as a .poly with the given index base (full double precision).
inline std::string to_poly(const Domain& d, int base)
{
  std::ostringstream s;
  s << std::setprecision(17);
  s << d.points.size() << " 2 0 0\n";
  for(std::size_t i = 0; i < d.points.size(); ++i)
    s << (i + base) << " " << CGAL::to_double(d.points[i].x()) << " " << CGAL::to_double(d.points[i].y()) << "\n";
  s << d.segments.size() << " 0\n";
  for(std::size_t i = 0; i < d.segments.size(); ++i)
    s << (i + base) << " " << (d.segments[i][0] + base) << " " << (d.segments[i][1] + base) << "\n";
  s << d.holes.size() << "\n";
  for(std::size_t i = 0; i < d.holes.size(); ++i)
    s << (i + base) << " " << CGAL::to_double(d.holes[i].x()) << " " << CGAL::to_double(d.holes[i].y()) << "\n";
  return s.str();
}

struct Counts { std::size_t vertices = 0, segments = 0, holes = 0; bool found = false; };

inline Counts read_check_counts(const fs::path& check)
{
  Counts c;
  std::ifstream in(check);
  std::string line;
  const std::regex re(R"(vertices:\s*(\d+)\s+segments:\s*(\d+)\s+hole points:\s*(\d+))");
  while(std::getline(in, line)) {
    std::smatch m;
    if(std::regex_search(line, m, re)) {
      c.vertices = std::stoul(m[1]); c.segments = std::stoul(m[2]); c.holes = std::stoul(m[3]);
      c.found = true;
      break;
    }
  }
  return c;
}

struct Bad_case
{
  const char* name;
  const char* content;
  std::size_t line;
  const char* keyword;
};

// Expects the loops of `d` to be a square with no twin and a crack, its own twin, of the loop
// vertices `crack` (along it and back).
inline void expect_the_square_and_a_crack(const Domain& d, const std::vector<std::size_t>& crack)
{
  const auto loops = CGAL::Quad_mesher_2::extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 2u);
  const std::size_t l = loops.loops[0].twin == 0 ? 0 : 1;
  EXPECT_EQ(loops.loops[l].twin, l);
  EXPECT_EQ(loops.loops[l].vertices, crack);
  EXPECT_EQ(loops.loops[1 - l].twin, std::size_t(-1));
}

} // namespace qm2_test_io_read

// ---------------------------------------------------------------------------------------------
// Real data

TEST(IO_read, RealPolyCasesMatchCheckCounts)
{
  using namespace qm2_test_io_read;
  const fs::path dir(QM2_SHARED_DATA_DIR);
  if(!fs::is_directory(dir)) GTEST_SKIP() << "no shared data directory " << dir;
  std::size_t n = 0;
  for(const auto& sub : fs::directory_iterator(dir)) {
    if(!sub.is_directory()) continue;
    for(const auto& f : fs::directory_iterator(sub.path())) {
      if(f.path().extension() != ".poly") continue;
      const std::string stem = f.path().stem().string();
      const fs::path check = sub.path() / (stem == sub.path().filename().string() ? "CHECK.txt" : "CHECK_" + stem + ".txt");
      const Counts c = read_check_counts(check);
      ASSERT_TRUE(c.found) << "no counts in " << check;
      Domain d;
      std::string err;
      ASSERT_TRUE(QIO::read_poly(f.path().string(), d, &err)) << err;
      EXPECT_EQ(d.points.size(), c.vertices) << f.path();
      EXPECT_EQ(d.segments.size(), c.segments) << f.path();
      EXPECT_EQ(d.holes.size(), c.holes) << f.path();
      for(const auto& s : d.segments) {
        ASSERT_LT(s[0], d.points.size());
        ASSERT_LT(s[1], d.points.size());
      }
      ++n;
    }
  }
  EXPECT_GE(n, 13u);
}

TEST(IO_read, ExampleLakeSuperior)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_poly(std::string(QM2_DATA_DIR) + "/lake_superior/lake_superior.poly", d, &err)) << err;
  EXPECT_EQ(d.points.size(), 518u);
  EXPECT_EQ(d.segments.size(), 518u);
  EXPECT_EQ(d.holes.size(), 6u);
  EXPECT_FALSE(d.is_point_cloud());
}

// ---------------------------------------------------------------------------------------------
// .poly features

TEST(IO_read, PolyZeroAndOneBasedGiveTheSameDomain)
{
  using namespace qm2_test_io_read;
  Domain d0, d1;
  std::string err;
  std::istringstream s0(square_with_hole_poly(0)), s1(square_with_hole_poly(1));
  ASSERT_TRUE(QIO::read_poly(s0, d0, &err)) << err;
  ASSERT_TRUE(QIO::read_poly(s1, d1, &err)) << err;
  EXPECT_EQ(d0.points.size(), 8u);
  EXPECT_EQ(d0.segments.size(), 8u);
  ASSERT_EQ(d0.holes.size(), 1u);
  EXPECT_EQ(d0.segments[0], (std::array<std::size_t, 2>{0, 1}));
  EXPECT_EQ(d0.points[2], Point_2(10, 10));
  EXPECT_EQ(d0.holes[0], Point_2(5, 5));
  EXPECT_TRUE(same_domain(d0, d1));

  // The same with a real case, rewritten 0-based.
  Domain real, real0;
  ASSERT_TRUE(QIO::read_poly(std::string(QM2_DATA_DIR) + "/lake_superior/lake_superior.poly", real, &err)) << err;
  const std::string f0 = write_file("lake0.poly", to_poly(real, 0));
  ASSERT_TRUE(QIO::read_poly(f0, real0, &err)) << err;
  EXPECT_TRUE(same_domain(real, real0));
}

TEST(IO_read, PolyCoordinatesAreTheParsedDoubles)
{
  using namespace qm2_test_io_read;
  std::istringstream s("2 2 0 0\n1 0.1 -1e-300\n2 +1.5E3 123456789.123456789\n0 0\n0\n");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_poly(s, d, &err)) << err;
  ASSERT_EQ(d.points.size(), 2u);
  EXPECT_TRUE(d.is_point_cloud());
  EXPECT_EQ(d.points[0].x(), K::FT(0.1));
  EXPECT_EQ(d.points[0].y(), K::FT(-1e-300));
  EXPECT_EQ(d.points[1].x(), K::FT(1500.0));
  EXPECT_EQ(d.points[1].y(), K::FT(123456789.123456789));
}

TEST(IO_read, PolyTolerates)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  // CRLF, tabs, comments after data, missing optional header fields, a trailing
  // regional-attribute section.
  std::istringstream s("# c\r\n3\r\n1\t0 0 # a\r\n2 1 0\r\n3 0 1\r\n\r\n3 1\r\n1 1 2 5\r\n2 2 3 0\r\n3 3 1 -2\r\n0\r\n1\r\n1 0.2 0.2 7 0.1\r\n");
  ASSERT_TRUE(QIO::read_poly(s, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.segments.size(), 3u);
  EXPECT_TRUE(d.holes.empty());
  EXPECT_EQ(d.segment_markers, (std::vector<int>{ 5, 0, -2 })); // one per segment, as given
  // Regions 0-based with an attribute alone (Triangle's maximum area is optional), comments after.
  std::istringstream r("3\n1 0 0\n2 1 0\n3 0 1\n3\n1 1 2\n2 2 3\n3 3 1\n0\n2 # regions\n0 0.2 0.2 7\n1 0.3 0.2 -1 -1\n# end\n\n");
  ASSERT_TRUE(QIO::read_poly(r, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_TRUE(d.segment_markers.empty()); // the header announces none
  // kept: points, attributes and maximum areas (a negative one is none, as in Triangle)
  ASSERT_EQ(d.region_attributes.size(), 2u);
  EXPECT_EQ(d.region_attributes[0].point, Point_2(0.2, 0.2));
  EXPECT_EQ(d.region_attributes[0].attribute, 7);
  EXPECT_EQ(d.region_attributes[0].max_area, 0);
  EXPECT_EQ(d.region_attributes[1].attribute, -1);
  EXPECT_EQ(d.region_attributes[1].max_area, 0);
  EXPECT_EQ(d.region_attribute_labels, (std::vector<std::string>{ "0 (line 11)", "1 (line 12)" }));
}

TEST(IO_read, PolyWithZeroVerticesReadsTheNodeBesideIt)
{
  using namespace qm2_test_io_read;
  const std::string full = square_with_hole_poly(1);
  // Split into a .node (header + vertices) and a .poly with 0 vertices.
  std::istringstream in(full);
  std::string line, node, poly = "0 2 0 0\n";
  int k = 0;
  while(std::getline(in, line)) {
    if(k < 10) node += line + "\n"; else poly += line + "\n";
    ++k;
  }
  write_file("split.node", node);
  const std::string pf = write_file("split.poly", poly);
  Domain a, b;
  std::string err;
  std::istringstream sf(full);
  ASSERT_TRUE(QIO::read_poly(sf, a, &err)) << err;
  ASSERT_TRUE(QIO::read_poly(pf, b, &err)) << err;
  EXPECT_TRUE(same_domain(a, b));

  // Errors: the stream overload cannot find the .node; a missing .node; an error in the .node
  // is reported against the .node.
  std::istringstream sp(poly);
  EXPECT_FALSE(QIO::read_poly(sp, b, &err));
  EXPECT_NE(err.find("<stream>:1: "), std::string::npos) << err;
  EXPECT_NE(err.find(".node"), std::string::npos) << err;
  const std::string lone = write_file("lonely.poly", poly);
  EXPECT_FALSE(QIO::read_poly(lone, b, &err));
  EXPECT_TRUE(is_empty(b));
  EXPECT_NE(err.find("lonely.node"), std::string::npos) << err;
  const std::string bad_node = write_file("badnode.node", "2 2 0 0\n1 0 0\n2 x 1\n");
  const std::string bad_poly = write_file("badnode.poly", "0 2 0 0\n1 0\n1 1 2\n0\n");
  expect_error(QIO::read_poly(bad_poly, b, &err), b, err, bad_node, 3, "expected a number");
}

TEST(IO_read, PolySegmentIndicesOutOfRangeNamesTheCount)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  const std::string f = write_file("lake.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2 600\n0\n");
  expect_error(QIO::read_poly(f, d, &err), d, err, f, 7,
               "segment 2 refers to vertex 600, but there are 3 vertices (1-based)");
}

TEST(IO_read, PolyMalformedCases)
{
  using namespace qm2_test_io_read;
  // A valid triangle for reference: 3 vertices (lines 1-4), 3 segments (5-8), 0 holes (9).
  const Bad_case cases[] = {
    {"empty", "", 1, "empty file"},
    {"only_comments", "# nothing\n\n# here\n", 3, "no data"},
    {"truncated_vertices", "4 2 0 0\n1 0 0\n2 1 0\n", 3, "end of file"},
    {"truncated_segments", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n", 7, "end of file"},
    {"missing_segment_header", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", 4, "segment header is missing"},
    {"missing_hole_header", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n", 8, "hole header is missing"},
    {"truncated_holes", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n2\n1 0.2 0.2\n", 10, "end of file"},
    {"negative_vertex_count", "-3 2 0 0\n", 1, "negative"},
    {"negative_segment_count", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n-1 0\n", 5, "negative"},
    {"negative_hole_count", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n-2\n", 6, "negative"},
    {"fractional_count", "3.5 2 0 0\n", 1, "expected an integer"},
    {"non_numeric_count", "three 2 0 0\n", 1, "expected an integer"},
    {"dimension_3", "3 3 0 0\n1 0 0 0\n", 1, "dimension must be 2"},
    {"bad_vertex_marker_count", "3 2 0 2\n", 1, "must be 0 or 1"},
    {"segment_marker_beyond_int", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 1\n1 1 2 1\n2 2 3 4294967296\n3 3 1 1\n0\n", 7,
     "marker of segment 2 is out of range"},
    {"header_garbage", "3 2 0 0 9\n", 1, "unexpected text"},
    {"non_numeric_x", "3 2 0 0\n1 0 0\n2 abc 0\n3 0 1\n", 3, "expected a number for the x coordinate of vertex 2"},
    {"non_numeric_y", "3 2 0 0\n1 0 0\n2 1 0x\n3 0 1\n", 3, "expected a number for the y coordinate"},
    {"missing_y", "3 2 0 0\n1 0 0\n2 1\n3 0 1\n", 3, "only one coordinate"},
    {"vertex_trailing_garbage", "3 2 0 0\n1 0 0\n2 1 0 junk\n3 0 1\n", 3, "unexpected text \"junk\""},
    {"vertex_bad_marker", "3 2 0 1\n1 0 0 1\n2 1 0 a\n3 0 1 1\n", 3, "boundary marker"},
    // A line short of what its header announces (Triangle's default of 0 hid a lost column).
    {"vertex_missing_marker", "3 2 0 1\n1 0 0 1\n2 1 0\n3 0 1 1\n", 3,
     "vertex 2 has 0 value(s) after its coordinates, but the header (line 1) announces 0 attribute(s) and 1 marker(s)"},
    {"vertex_missing_attribute", "3 2 2 1\n1 0 0 5 6 1\n2 1 0 5 1\n3 0 1 5 6 1\n", 3,
     "vertex 2 has 2 value(s) after its coordinates, but the header (line 1) announces 2 attribute(s) and 1 marker(s)"},
    {"vertex_missing_attributes", "# x\n3 2 1\n0 0 0 5\n1 1 0 5\n2 0 1\n", 5, "vertex 2 has 0 value(s)"},
    {"nan", "3 2 0 0\n1 0 0\n2 nan 0\n3 0 1\n", 3, "not finite"},
    {"inf", "3 2 0 0\n1 0 0\n2 1 0\n3 0 -inf\n", 4, "not finite"},
    {"infinity", "3 2 0 0\n1 0 0\n2 Infinity 0\n3 0 1\n", 3, "not finite"},
    {"too_large", "3 2 0 0\n1 0 0\n2 1e151 0\n3 0 1\n", 3, "too large"},
    {"overflow", "3 2 0 0\n1 0 0\n2 1 -1e400\n3 0 1\n", 3, "too large"},
    {"first_index_5", "3 2 0 0\n5 0 0\n6 1 0\n7 0 1\n", 2, "must be 0 or 1"},
    {"skipped_index", "3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n", 4, "out of sequence"},
    {"repeated_index", "3 2 0 0\n1 0 0\n1 1 0\n2 0 1\n", 3, "out of sequence"},
    {"duplicate_point", "3 2 0 0\n1 0 0\n2 1 0\n3 0 0\n0 0\n0\n", 4,
     "duplicate point: vertex 3 (line 4) and vertex 1 (line 2) are both at (0, 0)"},
    {"segment_vertex_zero_in_1_based", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 0 1\n0\n", 6, "refers to vertex 0"},
    {"segment_vertex_3_in_0_based", "3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 1 3\n0\n", 6, "3 vertices (0-based)"},
    {"segment_non_numeric", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 b\n0\n", 6, "expected an integer vertex index"},
    {"segment_missing_end", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1\n0\n", 6, "two vertex indices"},
    {"segment_trailing_garbage", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 2 3\n0\n", 6, "unexpected text"},
    {"segment_missing_marker", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 1\n1 1 2 1\n2 2 3\n0\n", 7,
     "segment 2 has no boundary marker, but the segment header (line 5) announces 1 marker"},
    {"segment_bad_marker_count", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 2\n", 5, "must be 0 or 1"},
    {"segment_skipped_index", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n3 2 3\n0\n", 7, "out of sequence"},
    {"zero_length_segment", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 3 3\n0\n", 7, "zero length"},
    {"duplicate_segment", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 2 1\n0\n", 8,
     "duplicate segment: segment 3 (line 8) and segment 1 (line 6)"},
    {"hole_non_numeric", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1\n1 0.2 y\n", 7, "expected a number for the y coordinate of hole 1"},
    {"hole_nan", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1\n1 NaN 0.2\n", 7, "not finite"},
    {"hole_trailing_garbage", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n1\n1 0.2 0.2 0.3\n", 7, "unexpected text"},
    // After the holes only the optional regional-attribute section may follow (it was all
    // ignored, junk included).
    {"junk_after_holes", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\njunk here\n", 10,
     "unexpected text \"junk\" after the holes"},
    {"junk_after_regions", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n1\n1 0.2 0.2 7 0.1\n\n2 2\n", 13,
     "unexpected text \"2\" after the last section (the regional attributes, header line 10)"},
    {"negative_region_count", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n-1\n", 7, "negative"},
    {"truncated_regions", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n2\n1 0.2 0.2 7\n", 8, "end of file"},
    {"region_without_attribute", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2\n", 8,
     "region 1 needs two coordinates and an attribute"},
    {"region_bad_area", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2 7 big\n", 8,
     "expected a finite number for the maximum area of region 1"},
    {"region_overflowing_area", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2 1 -1e400\n", 8,
     "expected a finite number for the maximum area of region 1, found \"-1e400\""},
    {"region_infinite_attribute", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2 inf\n", 8,
     "expected a finite number for the attribute of region 1, found \"inf\""},
    {"region_trailing_garbage", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n1\n1 0.2 0.2 7 0.1 9\n", 8, "unexpected text"},
    {"region_skipped_index", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n2\n0 0.2 0.2 7\n2 0.3 0.2 7\n", 9, "out of sequence"},
  };
  for(const Bad_case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = write_file(std::string(c.name) + ".poly", c.content);
    Domain d;
    d.points.push_back(Point_2(7, 7));  // must be cleared
    std::string err;
    expect_error(QIO::read_poly(f, d, &err), d, err, f, c.line, c.keyword);
    // The stream overload gives the same message with the given source name.
    std::istringstream in(c.content);
    std::string err2;
    EXPECT_FALSE(QIO::read_poly(in, d, &err2, "src.poly"));
    EXPECT_EQ(err2.rfind("src.poly:" + std::to_string(c.line) + ": ", 0), 0u) << err2;
    // A null error pointer is allowed.
    std::istringstream in3(c.content);
    EXPECT_FALSE(QIO::read_poly(in3, d));
  }
}

TEST(IO_read, MissingFile)
{
  using namespace qm2_test_io_read;
  const std::string f = (scratch_dir() / "does_not_exist.poly").string();
  Domain d;
  std::string err;
  EXPECT_FALSE(QIO::read_poly(f, d, &err));
  EXPECT_EQ(err.rfind(f + ": ", 0), 0u) << err;
  EXPECT_NE(err.find("cannot open"), std::string::npos) << err;
  for(const char* ext : {".node", ".xy", ".wkt"}) {
    const std::string g = (scratch_dir() / (std::string("does_not_exist") + ext)).string();
    err.clear();
    EXPECT_FALSE(QIO::read_domain(g, d, &err));
    EXPECT_NE(err.find(g + ": cannot open"), std::string::npos) << err;
  }
}

// Only regular files are opened: opening a FIFO with no writer blocked for ever, and
// /dev/zero read as an "empty file". A symbolic link counts as the file it names.
TEST(IO_read, NonRegularFilesAreRefusedBeforeOpening)
{
  using namespace qm2_test_io_read;
  const std::string fifo = (scratch_dir() / "fifo.poly").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  qm2_test::open_fifo_for_writing_after(fifo, std::chrono::seconds(10));
  Domain d;
  std::string err;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(QIO::read_poly(fifo, d, &err));
  EXPECT_EQ(err, fifo + ": is not a regular file (a FIFO)");
  EXPECT_FALSE(QIO::read_domain(fifo, d, &err));
  EXPECT_EQ(err, fifo + ": is not a regular file (a FIFO)");
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));

  const std::string zero = (scratch_dir() / "zero.xy").string();
  fs::create_symlink("/dev/zero", zero);
  for(const std::string& f : { std::string("/dev/zero"), zero }) {
    d.points.push_back(Point_2(1, 1));
    EXPECT_FALSE(QIO::read_domain(f, d, &err));
    EXPECT_TRUE(is_empty(d));
    EXPECT_EQ(err, f + ": is not a regular file (a character device)");
  }
  EXPECT_FALSE(QIO::read_xy(zero, d, &err));
  EXPECT_EQ(err, zero + ": is not a regular file (a character device)");
  const std::string dir = (scratch_dir() / "dir.wkt").string();
  fs::create_directories(dir);
  EXPECT_FALSE(QIO::read_domain(dir, d, &err));
  EXPECT_EQ(err, dir + ": is a directory, not a file");
}

// A UTF-8 byte order mark is skipped and CR (old Mac), CRLF and LF line ends all end lines,
// in every format: each file gives the domain its LF twin gives, and errors name the line an
// editor shows.
TEST(IO_read, ByteOrderMarkAndEveryLineEnd)
{
  using namespace qm2_test_io_read;
  const std::pair<const char*, std::string> formats[] = {
    { ".poly", square_with_hole_poly(1) },
    { ".node", "# comment\n3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n" },
    { ".xy", "0 0\n1 0 # comment\n\n0 1\n" },
    { ".wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0),\n(1 1, 1 3, 3 3, 3 1, 1 1))\n" } };
  auto with_line_ends = [](std::string text, const char* end) {
    for(std::size_t i = text.find('\n'); i != std::string::npos; i = text.find('\n', i + std::strlen(end)))
      text.replace(i, 1, end);
    return text;
  };
  for(const auto& [ext, text] : formats) {
    Domain lf;
    std::string err;
    ASSERT_TRUE(QIO::read_domain(write_file(std::string("lf") + ext, text), lf, &err)) << err;
    for(const char* end : { "\r", "\r\n", "\n" })
      for(const char* bom : { "", "\xEF\xBB\xBF" }) {
        SCOPED_TRACE(std::string(ext) + " " + QIO::internal::quote(std::string(bom) + end));
        const std::string content = bom + with_line_ends(text, end);
        Domain d;
        ASSERT_TRUE(QIO::read_domain(write_file(std::string("ends") + ext, content), d, &err)) << err;
        EXPECT_EQ(d.points, lf.points);
        EXPECT_EQ(d.segments, lf.segments);
        EXPECT_EQ(d.holes, lf.holes);
        if(ext == std::string(".xy")) { // the stream overloads too
          std::istringstream in(content);
          ASSERT_TRUE(QIO::read_xy(in, d, &err)) << err;
          EXPECT_EQ(d.points, lf.points);
        }
        // the third line's error names line 3
        const std::string bad = write_file(std::string("ends_bad") + ext, bom + with_line_ends("\n\nbad\n", end));
        EXPECT_FALSE(QIO::read_domain(bad, d, &err));
        EXPECT_EQ(err.rfind(bad + ":3: ", 0), 0u) << err;
      }
  }
}

TEST(IO_read, DuplicatePointsFoundQuicklyAmongMany)
{
  using namespace qm2_test_io_read;
  // 200000 distinct points, the last equal to point 1234 (1-based): a quadratic search would
  // be far too slow, and the message must name both.
  std::ostringstream s;
  const std::size_t n = 200000;
  s << n << " 2 0 0\n";
  for(std::size_t i = 1; i < n; ++i) s << i << " " << (i % 1000) << " " << (i / 1000) << "\n";
  s << n << " " << (1234 % 1000) << " " << (1234 / 1000) << "\n0 0\n0\n";
  std::istringstream in(s.str());
  Domain d;
  std::string err;
  EXPECT_FALSE(QIO::read_poly(in, d, &err, "many.poly"));
  EXPECT_EQ(err, "many.poly:200001: duplicate point: vertex 200000 (line 200001) and vertex 1234 (line 1235) are both at (234, 1)");
}

// ---------------------------------------------------------------------------------------------
// .node and .xy

TEST(IO_read, NodeFile)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  const std::string ok = write_file("pts.node", "3 2 1 1\n0 0 0 9 1\n1 1 0 9 1\n2 0.5 2 9 0\n# Generated by hand\n");
  ASSERT_TRUE(QIO::read_node(ok, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 3u);
  EXPECT_TRUE(d.is_point_cloud());
  EXPECT_EQ(d.points[2], Point_2(0.5, 2));

  const Bad_case cases[] = {
    {"n_empty", "", 1, "empty file"},
    {"n_truncated", "3 2 0 0\n1 0 0\n2 1 0\n", 3, "end of file"},
    {"n_zero", "0 2 0 0\n", 1, "no vertices"},
    {"n_trailing", "2 2 0 0\n1 0 0\n2 1 0\n3 0 1\n", 4, "after the last vertex"},
    {"n_dim", "2 1 0 0\n", 1, "dimension"},
    {"n_dup", "2 2 0 0\n1 0 0\n2 0 0\n", 3, "duplicate point"},
    {"n_missing_marker", "2 2 0 1\n1 0 0 1\n2 1 0\n", 3, "announces 0 attribute(s) and 1 marker(s)"},
  };
  for(const Bad_case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = write_file(std::string(c.name) + ".node", c.content);
    expect_error(QIO::read_node(f, d, &err), d, err, f, c.line, c.keyword);
  }
}

TEST(IO_read, XyFile)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  std::istringstream in("# points\n1 2\n\n  3.5\t-4 # tab\n5 6 0\n5 7 0.0\n");
  ASSERT_TRUE(QIO::read_xy(in, d, &err)) << err;
  ASSERT_EQ(d.points.size(), 4u);
  EXPECT_EQ(d.points[1], Point_2(3.5, -4));
  EXPECT_TRUE(d.segments.empty());
  EXPECT_TRUE(d.holes.empty());

  const Bad_case cases[] = {
    {"x_empty", "", 1, "empty file"},
    {"x_comments", "# a\n# b\n", 2, "no data"},
    {"x_one_column", "1 2\n3\n", 2, "only one coordinate"},
    {"x_third_nonzero", "1 2\n3 4 5\n", 2, "third coordinate"},
    {"x_third_text", "1 2\n3 4 abc\n", 2, "unexpected text"},
    {"x_four_columns", "1 2 0 0\n", 1, "unexpected text"},
    {"x_non_numeric", "1 2\n3 4\nx 5\n", 3, "expected a number for the x coordinate"},
    {"x_nan", "1 2\n3 -nan\n", 2, "not finite"},
    {"x_large", "1 2\n-2e150 4\n", 2, "too large"},
    {"x_dup", "1 2\n3 4\n5 6\n3 4\n", 4, "duplicate point: point 4 (line 4) and point 2 (line 2)"},
  };
  for(const Bad_case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = write_file(std::string(c.name) + ".xy", c.content);
    expect_error(QIO::read_xy(f, d, &err), d, err, f, c.line, c.keyword);
  }
}

TEST(IO_read, MillionPointsReadFast)
{
  using namespace qm2_test_io_read;
  std::string text;
  const std::size_t n = 1000000;
  text.reserve(n * 24);
  char buf[64];
  for(std::size_t i = 0; i < n; ++i) {
    std::snprintf(buf, sizeof(buf), "%.9g %.9g\n", (i % 1000) * 0.001 + 1e-7 * (i / 1000), (i / 1000) * 0.37);
    text += buf;
  }
  const std::string f = write_file("million.xy", text);
  Domain d;
  std::string err;
  const auto t0 = std::chrono::steady_clock::now();
  ASSERT_TRUE(QIO::read_xy(f, d, &err)) << err;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(d.points.size(), n);
  RecordProperty("seconds", std::to_string(seconds));
  EXPECT_LT(seconds, qm2_test::time_bound(10.0)) << "reading 10^6 points took " << seconds << " s";
  fs::remove(f);
}

// ---------------------------------------------------------------------------------------------
// WKT

TEST(IO_read, WktPolygonWithHoleGetsASeedInsideTheHole)
{
  using namespace qm2_test_io_read;
  // An L-shaped hole: its centroid (about (3.9, 3.9)) lies outside it.
  const std::string wkt = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0),\n"
                          "         (1 1, 1 9, 2 9, 2 2, 9 2, 9 1, 1 1))\n";
  Domain d;
  std::string err;
  std::istringstream in(wkt);
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 10u);
  EXPECT_EQ(d.segments.size(), 10u);
  ASSERT_EQ(d.holes.size(), 1u);
  const std::vector<Point_2> outer = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const std::vector<Point_2> hole = {{1, 1}, {1, 9}, {2, 9}, {2, 2}, {9, 2}, {9, 1}};
  EXPECT_EQ(CGAL::bounded_side_2(hole.begin(), hole.end(), d.holes[0], K()), CGAL::ON_BOUNDED_SIDE);
  EXPECT_EQ(CGAL::bounded_side_2(outer.begin(), outer.end(), d.holes[0], K()), CGAL::ON_BOUNDED_SIDE);
  // Every ring is a closed chain.
  std::vector<int> degree(d.points.size(), 0);
  for(const auto& s : d.segments) { ++degree[s[0]]; ++degree[s[1]]; }
  for(int deg : degree) EXPECT_EQ(deg, 2);
}

TEST(IO_read, WktHoleSeedAvoidsIslandsInTheHole)
{
  using namespace qm2_test_io_read;
  // A land polygon with a lake; an island polygon fills most of the lake.
  const std::string wkt = "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2)),\n"
                          "              ((2.5 2.5, 7.5 2.5, 7.5 7.5, 2.5 7.5, 2.5 2.5)))";
  Domain d;
  std::string err;
  std::istringstream in(wkt);
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 12u);
  EXPECT_EQ(d.segments.size(), 12u);
  ASSERT_EQ(d.holes.size(), 1u);
  const std::vector<Point_2> lake = {{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  const std::vector<Point_2> island = {{2.5, 2.5}, {7.5, 2.5}, {7.5, 7.5}, {2.5, 7.5}};
  EXPECT_EQ(CGAL::bounded_side_2(lake.begin(), lake.end(), d.holes[0], K()), CGAL::ON_BOUNDED_SIDE);
  EXPECT_EQ(CGAL::bounded_side_2(island.begin(), island.end(), d.holes[0], K()), CGAL::ON_UNBOUNDED_SIDE);
}

// OGC forbids overlapping polygons: one inside another's area (not in a hole) became a hole
// of it by the loops' nesting, and its area was lost without a word (a 4 x 4 square with a
// unit square polygon inside: area 15).
TEST(IO_read, WktPolygonInsideAnotherIsAnError)
{
  using namespace qm2_test_io_read;
  for(const std::string& wkt : { std::string("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0)), ((1 1, 2 1, 2 2, 1 2, 1 1)))"),
                                std::string("GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nPOLYGON ((0 0, 2 0, 2 2, 0 2, 0 0)))") }) {
    Domain d;
    std::string err;
    std::istringstream in(wkt);
    EXPECT_FALSE(QIO::read_WKT(in, d, &err)) << wkt;
    EXPECT_NE(err.find("the outer ring of polygon 2 lies inside polygon 1 (line 1)"), std::string::npos) << err;
  }
  // the same square in the other's hole is an island: fine
  const std::string island = "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (0.5 0.5, 3 0.5, 3 3, 0.5 3, 0.5 0.5)),"
                             " ((1 1, 2 1, 2 2, 1 2, 1 1)))";
  Domain d;
  std::string err;
  std::istringstream in(island);
  EXPECT_TRUE(QIO::read_WKT(in, d, &err)) << err;
}

TEST(IO_read, WktManyHolesAndTouchingRings)
{
  using namespace qm2_test_io_read;
  // Thin triangular holes (seed must be strictly inside each) and a hole touching the outer
  // ring at a vertex (the vertex is shared).
  const std::string wkt = "polygon((0 0, 100 0, 100 100, 0 100, 0 0),"
                          " (10 10, 90 10.001, 10 10.002, 10 10),"
                          " (0 100, 10 80, 20 90, 0 100),"
                          " (50 50, 50.000001 50, 50 50.000001, 50 50))";
  Domain d;
  std::string err;
  std::istringstream in(wkt);
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 4u + 3 + 2 + 3);
  EXPECT_EQ(d.segments.size(), 4u + 3 + 3 + 3);
  ASSERT_EQ(d.holes.size(), 3u);
  const std::vector<std::vector<Point_2> > holes = {
    {{10, 10}, {90, 10.001}, {10, 10.002}}, {{0, 100}, {10, 80}, {20, 90}}, {{50, 50}, {50.000001, 50}, {50, 50.000001}}};
  for(std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(CGAL::bounded_side_2(holes[i].begin(), holes[i].end(), d.holes[i], K()), CGAL::ON_BOUNDED_SIDE) << i;
}

TEST(IO_read, WktPointCloud)
{
  using namespace qm2_test_io_read;
  std::istringstream in("GEOMETRYCOLLECTION (MULTIPOINT ((0 0), (1 0), 2 2),\nPOINT (3 3),\nPOINT EMPTY)\n");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 4u);
  EXPECT_TRUE(d.is_point_cloud());
  EXPECT_TRUE(d.holes.empty());
}

// A LINESTRING in a collection with a polygon is a crack: an open polyline of segments after
// the rings', in its order, named by linestring and line.
TEST(IO_read, WktLinestringInAPolygonIsACrack)
{
  using namespace qm2_test_io_read;
  std::istringstream in("GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\n"
                        "LINESTRING (1 1, 2 2,\n3 1), LINESTRING EMPTY)");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  ASSERT_EQ(d.points.size(), 7u);
  ASSERT_EQ(d.segments.size(), 6u);
  EXPECT_EQ(d.points[5], Point_2(2, 2));
  EXPECT_EQ(d.segments[4], (Domain::Segment{4, 5}));
  EXPECT_EQ(d.segments[5], (Domain::Segment{5, 6}));
  EXPECT_EQ(d.point_label(6), "3 of linestring 1 (line 3)");
  EXPECT_EQ(d.segment_label(5), "2 of linestring 1 (line 2)");
  EXPECT_TRUE(d.holes.empty());
  expect_the_square_and_a_crack(d, {4, 5, 6, 5});
}

// Polygons of a MULTIPOLYGON (or POLYGONs of a GEOMETRYCOLLECTION) sharing an edge share its
// two vertices and one segment: two regions meshed together, the segment between them twice
// in the loops, once each way.
TEST(IO_read, WktPolygonsSharingAnEdgeShareOneSegment)
{
  using namespace qm2_test_io_read;
  for(const std::string& wkt : { std::string("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)),\n((1 0, 2 0, 2 1, 1 1, 1 0)))"),
                                std::string("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0)),\n"
                                            "POLYGON ((1 1, 2 1, 2 0, 1 0, 1 1)))") }) {
    SCOPED_TRACE(wkt);
    Domain d;
    std::string err;
    std::istringstream in(wkt);
    ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
    EXPECT_EQ(d.points.size(), 6u);
    ASSERT_EQ(d.segments.size(), 7u);
    EXPECT_EQ(d.segments[1], (Domain::Segment{1, 2}));
    EXPECT_EQ(d.segment_label(1), "2 of the outer ring of polygon 1 (line 1)");
    EXPECT_TRUE(d.holes.empty());
    const auto loops = CGAL::Quad_mesher_2::extract_loops(d);
    ASSERT_EQ(loops.loops.size(), 2u);
    EXPECT_EQ(loops.loops[0].edge_twins[1], (std::array<std::size_t, 2>{1, 0}));
    EXPECT_EQ(loops.loops[1].region, 1u);
  }
}

// A 2 x 2 grid of squares: its middle vertex has 4 segments; 4 faces, one region each, every
// inner segment an edge of two of them.
TEST(IO_read, WktGridOfFourSquaresIsFourRegions)
{
  using namespace qm2_test_io_read;
  std::istringstream in("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 0, 2 0, 2 1, 1 1, 1 0)),\n"
                        "((0 1, 1 1, 1 2, 0 2, 0 1)), ((1 1, 2 1, 2 2, 1 2, 1 1)))");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 9u);
  EXPECT_EQ(d.segments.size(), 12u);
  const auto loops = CGAL::Quad_mesher_2::extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 4u);
  const std::size_t none = std::size_t(-1);
  for(std::size_t l = 0; l < 4; ++l) {
    SCOPED_TRACE(l);
    EXPECT_TRUE(loops.loops[l].is_outer);
    EXPECT_EQ(loops.loops[l].region, l);
    std::size_t twinned = 0;
    for(const auto& t : loops.loops[l].edge_twins) twinned += t[0] != none;
    EXPECT_EQ(twinned, 2u);
    EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, l), 1);
  }
  // three triangles meeting at a point: a junction of 3 segments
  std::istringstream three("MULTIPOLYGON (((0 0, 2 0, 1 1, 0 0)), ((2 0, 2 2, 1 1, 2 0)), ((2 2, 0 2, 0 0, 1 1, 2 2)))");
  ASSERT_TRUE(QIO::read_WKT(three, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 5u);
  EXPECT_EQ(d.segments.size(), 7u);
  EXPECT_EQ(CGAL::Quad_mesher_2::extract_loops(d).loops.size(), 3u);
}

// An island given as its own polygon, filling a lake: the hole ring and the island's outer
// ring are one loop, an interface, and the hole gets no seed (it would make the island a hole).
// An island filling a hole partly leaves the seed in the rest of it.
TEST(IO_read, WktPolygonFillingAHoleIsARegionNotAHole)
{
  using namespace qm2_test_io_read;
  std::istringstream in("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1)),\n"
                        "((1 1, 1 3, 3 3, 3 1, 1 1)))");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 8u);
  EXPECT_EQ(d.segments.size(), 8u);
  EXPECT_TRUE(d.holes.empty());
  EXPECT_TRUE(d.every_hole_marked);
  auto loops = CGAL::Quad_mesher_2::extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 3u);
  EXPECT_EQ(loops.loops[1].twin, 2u);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 0), 12);
  EXPECT_EQ(CGAL::Quad_mesher_2::region_area(d, loops, 1), 4);

  // tiled by two polygons, beside a second lake, which keeps its seed
  std::istringstream tiled("MULTIPOLYGON (((0 0, 6 0, 6 4, 0 4, 0 0), (1 1, 2 1, 3 1, 3 3, 2 3, 1 3, 1 1),\n"
                           "(4 1, 5 1, 5 3, 4 3, 4 1)), ((2 1, 3 1, 3 3, 2 3, 2 1)), ((1 1, 2 1, 2 3, 1 3, 1 1)))");
  ASSERT_TRUE(QIO::read_WKT(tiled, d, &err)) << err;
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_EQ(d.holes[0].x() > 4 && d.holes[0].x() < 5, true);
  loops = CGAL::Quad_mesher_2::extract_loops(d);
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, loops), 24 - 2);

  // half the lake is an island: the seed is in the other half
  std::istringstream half("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1)),\n((1 1, 3 1, 3 3, 1 1)))");
  ASSERT_TRUE(QIO::read_WKT(half, d, &err)) << err;
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_LT(d.holes[0].x(), d.holes[0].y());
  EXPECT_EQ(CGAL::Quad_mesher_2::domain_area(d, CGAL::Quad_mesher_2::extract_loops(d)), 14);
}

// Adjacent polygons whose shared boundary is split at different vertices: a vertex of one
// inside the other's edge. The reader does not split the edge; the domain's checks refuse it,
// naming both places as the file does.
TEST(IO_read, WktTVertexBetweenPolygonsIsNamedByRingAndLine)
{
  using namespace qm2_test_io_read;
  std::istringstream in("MULTIPOLYGON (((0 0, 1 0, 1 2, 0 2, 0 0)),\n((1 0, 2 0, 2 2, 1 2, 1 1, 1 0)))");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  std::string msg;
  try {
    CGAL::Quad_mesher_2::extract_loops(d);
  } catch(const CGAL::Quad_mesher_2::Meshing_error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("vertex 5 of the outer ring of polygon 2 (line 2) (1, 1) lies on segment 2 of the outer ring of "
                     "polygon 1 (line 1) (segments may meet only at their ends: split that segment there)"),
            std::string::npos) << msg;
}

// Polygons whose interiors overlap stay an error: crossing rings (the domain's checks) or a
// shared edge with both on one side (the reader); one inside the other is
// WktPolygonInsideAnotherIsAnError.
TEST(IO_read, WktOverlappingPolygonsAreAnError)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  std::istringstream crossing("MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)),\n((1 -1, 3 -1, 3 1, 1 1, 1 -1)))");
  ASSERT_TRUE(QIO::read_WKT(crossing, d, &err)) << err;
  std::string msg;
  try {
    CGAL::Quad_mesher_2::extract_loops(d);
  } catch(const CGAL::Quad_mesher_2::Meshing_error& e) {
    msg = e.what();
  }
  EXPECT_NE(msg.find("of the outer ring of polygon 2 (line 2)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("cross"), std::string::npos) << msg;
  std::istringstream one_side("MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)),\n((2 0, 2 2, 1 1, 2 0)))");
  ASSERT_FALSE(QIO::read_WKT(one_side, d, &err));
  EXPECT_NE(err.find("<stream>:2: edge 1 of the outer ring of polygon 2 (line 2) from (2, 0) to (2, 2) is also edge 2 of "
                     "the outer ring of polygon 1 (line 1): polygons 1 and 2 overlap"), std::string::npos) << err;
}

// Two linestrings of a MULTILINESTRING that meet end to end share the vertex there: one crack.
TEST(IO_read, WktMultilinestringOfTwoMeetingAtAVertex)
{
  using namespace qm2_test_io_read;
  std::istringstream in("GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\n"
                        "MULTILINESTRING ((1 1, 2 2), EMPTY,\n(3 1, 2 2)))");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  ASSERT_EQ(d.points.size(), 7u);
  ASSERT_EQ(d.segments.size(), 6u);
  EXPECT_EQ(d.segments[4], (Domain::Segment{4, 5}));
  EXPECT_EQ(d.segments[5], (Domain::Segment{6, 5}));
  EXPECT_EQ(d.segment_label(5), "1 of linestring 2 (line 3)");
  expect_the_square_and_a_crack(d, {4, 5, 6, 5});
}

// A linestring ending on a polygon's vertex takes that vertex's index: a crack from a corner,
// which the face walks along and back.
TEST(IO_read, WktLinestringEndingOnAPolygonVertexSharesIt)
{
  using namespace qm2_test_io_read;
  std::istringstream in("GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (2 2, 4 4))");
  Domain d;
  std::string err;
  ASSERT_TRUE(QIO::read_WKT(in, d, &err)) << err;
  ASSERT_EQ(d.points.size(), 5u);
  ASSERT_EQ(d.segments.size(), 5u);
  EXPECT_EQ(d.segments[4], (Domain::Segment{4, 2}));
  // a crack from a corner: the face walks along it and back from the shared vertex
  const auto loops = CGAL::Quad_mesher_2::extract_loops(d);
  ASSERT_EQ(loops.loops.size(), 1u);
  EXPECT_EQ(loops.loops[0].vertices, (std::vector<std::size_t>{0, 1, 2, 4, 2, 3}));
  EXPECT_EQ(loops.loops[0].edge_twins[2], (std::array<std::size_t, 2>{0, 3}));
}

// The boundary checks run after reading; their messages name vertices and segments as the
// file does (a 1-based .poly: "segment 3 (line 8)", not the 0-based index 2), and WKT ones
// by ring and line.
TEST(IO_read, LaterErrorsUseTheFilesNumbersAndLines)
{
  using namespace qm2_test_io_read;
  auto loop_error = [](const Domain& d) {
    try {
      CGAL::Quad_mesher_2::extract_loops(d);
    } catch(const CGAL::Quad_mesher_2::Meshing_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Domain d;
  std::string err;
  const std::string bowtie = write_file("bowtie1.poly", "# a bowtie\n4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n"
                                                        "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n1\n1 5 5\n");
  ASSERT_TRUE(QIO::read_poly(bowtie, d, &err)) << err;
  std::string msg = loop_error(d);
  for(const char* part : { "segments 1 (line 8) (vertices 1 (line 3) (0, 0) and 2 (line 4) (1, 1))",
                           "and 3 (line 10) (vertices 3 (line 5) (1, 0) and 4 (line 6) (0, 1))", "cross" })
    EXPECT_NE(msg.find(part), std::string::npos) << msg << "\nlacks: " << part;

  const std::string open = write_file("open1.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2 0\n1 1 2\n2 2 3\n0\n");
  ASSERT_TRUE(QIO::read_poly(open, d, &err)) << err;
  msg = loop_error(d);
  EXPECT_NE(msg.find("the open polyline of 2 segments from vertex 1 (line 2) (0, 0) to vertex 3 (line 4) (0, 1) (segment 1 (line 6))"),
            std::string::npos) << msg;

  // a hole point in the domain, in no hole, is the problem, not the loop around it (which the
  // message blamed, "the domain lies on neither side of the loop ...")
  const std::string stray = write_file("stray_hole.poly", "8 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 0 10\n5 2 2\n6 8 2\n7 8 8\n8 2 8\n"
                                                          "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n"
                                                          "2\n1 5 5\n2 1 1\n");
  ASSERT_TRUE(QIO::read_poly(stray, d, &err)) << err;
  msg = loop_error(d);
  EXPECT_EQ(msg.rfind("hole point 2 (line 21) (1, 1) is in no hole: it lies inside the loop of 4 vertices starting at "
                      "vertex 1 (line 2) (0, 0) (segment 1 (line 11)) and outside the loops within it, in the domain", 0), 0u)
      << msg;

  // rings of two polygons that cross (the reader leaves crossings to the domain's checks)
  const std::string wkt = write_file("bowtie1.wkt", "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0),\n(2 2, 8 2, 8 8, 2 8, 2 2)),\n"
                                                    "((12 1, 12 12, 1 12, 1 1, 12 1)))");
  ASSERT_TRUE(QIO::read_WKT(wkt, d, &err)) << err;
  msg = loop_error(d);
  EXPECT_NE(msg.find("of the outer ring of polygon 2 (line 3)"), std::string::npos) << msg;
}

TEST(IO_read, WktMalformedCases)
{
  using namespace qm2_test_io_read;
  const Bad_case cases[] = {
    {"w_empty", "", 1, "empty file"},
    {"w_blank", "\n\n", 3, "no WKT geometry"},
    {"w_unsupported", "\nCIRCULARSTRING (0 0, 1 1, 2 0)", 2, "unsupported WKT geometry type"},
    {"w_z", "POLYGON Z ((0 0 0, 1 0 0, 0 1 0, 0 0 0))", 1, "only 2D"},
    {"w_third_coordinate", "POLYGON ((0 0, 1 0 5, 0 1, 0 0))", 1, "only 2D"},
    {"w_non_numeric", "POLYGON ((0 0,\n1 zero, 0 1, 0 0))", 2, "expected a number for the y coordinate"},
    {"w_nan", "POINT (nan 1)", 1, "not finite"},
    {"w_large", "POINT (1 1e200)", 1, "too large"},
    {"w_truncated", "POLYGON ((0 0, 1 0,\n 0 1", 2, "end of file"},
    {"w_missing_paren", "POLYGON ((0 0, 1 0, 0 1, 0 0)", 1, "expected ')'"},
    {"w_two_vertices", "POLYGON ((0 0, 1 0, 0 0))", 1, "at least 3"},
    {"w_unclosed", "POLYGON ((0 0, 1 0,\n1 1, 0 1))", 2, "is not closed: it ends at (0, 1)"},
    {"w_not_simple", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0),\n(2 2, 8 8, 2 8, 8 2, 2 2))", 2, "not simple"},
    {"w_collinear", "POLYGON ((0 0, 1 0, 2 0, 0 0))", 1, "not simple"},
    {"w_repeated_vertex", "POLYGON ((0 0, 4 0, 2 2, 4 4, 0 4, 2 2, 0 0))", 1, "duplicate point"},
    {"w_zero_length_edge", "POLYGON ((0 0, 1 0, 1 0, 0 1, 0 0))", 1, "zero-length"},
    {"w_duplicate_points", "GEOMETRYCOLLECTION (MULTIPOINT (0 0, 1 1),\nPOINT (1 1))", 2, "duplicate point"},
    {"w_point_on_ring_vertex", "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)),\nPOINT (1 0))", 2, "already a ring vertex"},
    // one geometry a file: a second one, even of the same type, is most likely a mistake
    {"w_two_polygons", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n\nPOLYGON ((5 0, 6 0, 6 1, 5 0))", 3,
     "a second WKT geometry (POLYGON): a file holds one; put several polygons in one MULTIPOLYGON"},
    {"w_point_after_polygon", "SRID=4326;POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0));\nPOINT (9 9)", 2, "a second WKT geometry (POINT)"},
    {"w_nested_collection", "GEOMETRYCOLLECTION (POINT (0 0),\nGEOMETRYCOLLECTION (POINT (1 1)))", 2,
     "a GEOMETRYCOLLECTION inside a GEOMETRYCOLLECTION"},
    {"w_collection_member", "GEOMETRYCOLLECTION (POINT (0 0), (1 1))", 1, "expected a WKT geometry keyword in GEOMETRYCOLLECTION"},
    // polygons may share an edge side by side, not on one side of it, nor rings of one polygon
    {"w_shared_edge_one_side", "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)),\n((0 0, 2 0, 2 1, 0 1, 0 0)))", 2,
     "edge 1 of the outer ring of polygon 2 (line 2) from (0, 0) to (2, 0) is also edge 1 of the outer ring of polygon 1 "
     "(line 1): polygons 1 and 2 overlap"},
    {"w_equal_polygons", "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 1 1, 0 0)),\nPOLYGON ((1 1, 1 0, 0 0, 1 1)))", 2,
     "polygons 1 and 2 overlap"},
    {"w_shared_edge_outside_the_hole", "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1)),\n"
     "((1 1, 3 1, 3 0.5, 1 0.5, 1 1)))", 2, "polygons 1 and 2 overlap"},
    {"w_rings_of_one_polygon_share_an_edge", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0),\n(0 0, 2 1, 4 0, 0 0))", 2,
     "edge 3 of inner ring 1 (a hole) of polygon 1 (line 2) from (0, 0) to (4, 0) is also edge 1 of the outer ring of "
     "polygon 1 (line 1): the rings of a polygon may touch at a vertex, not share an edge"},
    {"w_hole_cut_in_two", "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0),\n(1 1, 2 1, 3 1, 3 3, 2 3, 1 3, 1 1)),\n"
     "((2 1, 2.5 2, 2 3, 1.5 2, 2 1)))", 2,
     "the polygons inside inner ring 1 (a hole) of polygon 1 cut the hole into 2 parts"},
    {"w_garbage_after", "POINT (1 1) )", 1, "expected a WKT geometry keyword"},
    // linestrings: cracks in a polygon
    {"w_lone_linestring", "\nLINESTRING (0 0, 1 1)", 2,
     "linestring 1 but no polygon: a linestring is a crack in a domain, and a domain needs a POLYGON"},
    {"w_linestring_with_points", "GEOMETRYCOLLECTION (POINT (5 5), POLYGON EMPTY,\nMULTILINESTRING (EMPTY, (0 0, 1 1)))", 2,
     "linestring 1 but no polygon"},
    {"w_only_empty_linestrings", "GEOMETRYCOLLECTION (LINESTRING EMPTY, MULTILINESTRING EMPTY)", 1, "all WKT geometries are EMPTY"},
    {"w_linestring_z", "LINESTRING Z (0 0 0, 1 1 1)", 1, "LINESTRING Z: only 2D"},
    {"w_multilinestring_m", "MULTILINESTRING M ((0 0 0, 1 1 1))", 1, "MULTILINESTRING M: only 2D"},
    {"w_linestring_third_coordinate", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1 5, 2 2))", 2,
     "a third coordinate \"5\": only 2D"},
    {"w_linestring_one_vertex", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1))", 2,
     "linestring 1 has 1 distinct vertex, (1, 1); a linestring needs at least 2"},
    {"w_linestring_one_distinct_vertex", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\n"
     "MULTILINESTRING ((1 1, 2 2),\n(3 3,\n3 3)))", 3, "linestring 2 has 1 distinct vertex, (3, 3)"},
    {"w_linestring_zero_length", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1, 2 2,\n2 2, 3 1))", 3,
     "linestring 1 has a zero-length segment: vertex (2, 2) is repeated (lines 2 and 3)"},
    {"w_linestring_closed", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1, 2 1, 2 2,\n1 1))", 3,
     "linestring 1 is closed: it ends at its first point (1, 1) (lines 2 and 3); a closed polyline is a polygon ring"},
    {"w_point_on_linestring", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1, 2 2),\nPOINT (2 2))", 3,
     "duplicate point: (2, 2) (line 3) is already a linestring vertex (line 2)"},
    {"w_linestring_on_an_edge", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (4 0, 4 4))", 2,
     "duplicate segment: segment 1 of linestring 1 (line 2) from (4, 0) to (4, 4) is also segment 2 of the outer ring of "
     "polygon 1 (line 1)"},
    {"w_linestring_unclosed_paren", "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1, 2 2)", 2,
     "expected ')' or ',' in GEOMETRYCOLLECTION"},
  };
  for(const Bad_case& c : cases) {
    SCOPED_TRACE(c.name);
    const std::string f = write_file(std::string(c.name) + ".wkt", c.content);
    Domain d;
    std::string err;
    expect_error(QIO::read_WKT(f, d, &err), d, err, f, c.line, c.keyword);
  }
}

// ---------------------------------------------------------------------------------------------
// read_domain

TEST(IO_read, ReadDomainDispatchesByExtension)
{
  using namespace qm2_test_io_read;
  Domain d;
  std::string err;
  const std::string poly = write_file("disp.POLY", square_with_hole_poly(1));
  ASSERT_TRUE(QIO::read_domain(poly, d, &err)) << err;
  EXPECT_EQ(d.segments.size(), 8u);
  EXPECT_EQ(d.holes.size(), 1u);

  const std::string node = write_file("disp.node", "2 2 0 0\n1 0 0\n2 1 1\n");
  ASSERT_TRUE(QIO::read_domain(node, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 2u);

  for(const char* ext : {".xy", ".txt", ".pts", ".dat"}) {
    const std::string xy = write_file(std::string("disp") + ext, "0 0\n1 1\n2 0\n");
    ASSERT_TRUE(QIO::read_domain(xy, d, &err)) << err;
    EXPECT_EQ(d.points.size(), 3u) << ext;
    EXPECT_TRUE(d.is_point_cloud());
    // The .xy reader rejects what the .poly reader would need: a header-looking first line
    // "3 2 0 0" is 4 columns.
    const std::string bad = write_file(std::string("dispbad") + ext, "3 2 0 0\n");
    EXPECT_FALSE(QIO::read_domain(bad, d, &err));
    EXPECT_NE(err.find(bad + ":1: unexpected text"), std::string::npos) << err;
  }

  const std::string wkt = write_file("disp.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))");
  ASSERT_TRUE(QIO::read_domain(wkt, d, &err)) << err;
  EXPECT_EQ(d.points.size(), 8u);
  EXPECT_EQ(d.holes.size(), 1u);

  for(const char* name : {"disp.off", "disp", "dir.poly/disp"}) {
    const std::string f = write_file(name == std::string("dir.poly/disp") ? "disp_noext" : name, "1 2\n");
    const std::string path = name == std::string("dir.poly/disp") ? (scratch_dir() / "dir.poly" / "disp").string() : f;
    d.points.push_back(Point_2(1, 1));
    err.clear();
    EXPECT_FALSE(QIO::read_domain(path, d, &err));
    EXPECT_TRUE(is_empty(d));
    EXPECT_EQ(err.rfind(path + ": unknown file extension", 0), 0u) << err;
  }
}
