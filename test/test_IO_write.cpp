// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests for the writers of CGAL/Quad_mesher_2/IO/: each file is written, parsed back here
// and compared exactly with the mesh.

#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
#include <CGAL/Quad_mesher_2/IO/write_OFF.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/IO/write_VTU.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include "qm2_test_kernel.h"

#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace qm2_test_io_write {

using Point = qm2_test::Point_2;
using Mesh = CGAL::Quad_mesher_2::Quad_mesh_2<Point>;

/// Two quads with awkward coordinates (thirds, tiny and large values) under both kernels.
inline Mesh make_test_mesh()
{
  const qm2_test::FT third = qm2_test::FT(1) / qm2_test::FT(3);
  Mesh m;
  m.points = {Point(0, 0),           Point(third, qm2_test::FT(1e-7)), Point(third, 1),
              Point(-123456.789, 1), Point(1, 0.1),                    Point(1, 1)};
  m.quads = {{0, 1, 2, 3}, {1, 4, 5, 2}};
  return m;
}

inline double xd(const Point& p) { return CGAL::to_double(p.x()); }
inline double yd(const Point& p) { return CGAL::to_double(p.y()); }

/// A temporary directory for this process (unique per kernel and run), removed at exit.
class Temp_dir
{
public:
  Temp_dir()
  {
#if defined(QM2_TEST_KERNEL_EPECK)
    const std::string kernel = "epeck";
#else
    const std::string kernel = "epick";
#endif
    std::mt19937_64 rng{std::random_device{}()};
    m_path = std::filesystem::temp_directory_path() /
             ("qm2_io_write_" + kernel + "_" + std::to_string(rng()));
    std::filesystem::create_directories(m_path);
  }
  ~Temp_dir()
  {
    std::error_code ec;
    std::filesystem::remove_all(m_path, ec);
  }
  const std::filesystem::path& path() const { return m_path; }

private:
  std::filesystem::path m_path;
};

/// A path in the temporary directory.
inline std::string temp_path(const std::string& name)
{
  static const Temp_dir dir;
  return (dir.path() / name).string();
}

inline std::string slurp(const std::string& filename)
{
  std::ifstream in(filename, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline std::size_t count_occurrences(const std::string& text, const std::string& what)
{
  std::size_t n = 0;
  for(std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + 1))
    ++n;
  return n;
}

/// What a reader recovers from a file.
struct Read_back
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 4>> quads; // 0-based
};

/// A strict reader for the MSH 4.1 ASCII subset our writer produces.
inline bool parse_msh41(const std::string& text, Read_back& out)
{
  std::istringstream in(text);
  std::string tok;
  auto expect = [&](const std::string& s) { return (in >> tok) && tok == s; };
  double version = 0;
  int file_type = -1, data_size = 0;
  if(!expect("$MeshFormat") || !(in >> version >> file_type >> data_size) || version != 4.1 ||
     file_type != 0 || data_size != 8 || !expect("$EndMeshFormat"))
    return false;
  std::size_t np = 0, nc = 0, ns = 0, nv = 0;
  if(!expect("$Entities") || !(in >> np >> nc >> ns >> nv) || np != 0 || nc != 0 || ns != 1 || nv != 0)
    return false;
  int surface_tag = 0;
  double bb[6];
  std::size_t nphys = 0, nbound = 0;
  if(!(in >> surface_tag >> bb[0] >> bb[1] >> bb[2] >> bb[3] >> bb[4] >> bb[5] >> nphys >> nbound) ||
     nphys != 0 || nbound != 0 || !expect("$EndEntities"))
    return false;

  std::size_t nblocks = 0, nnodes = 0, mintag = 0, maxtag = 0;
  if(!expect("$Nodes") || !(in >> nblocks >> nnodes >> mintag >> maxtag))
    return false;
  out.points.assign(nnodes, {0, 0, 0});
  for(std::size_t b = 0; b < nblocks; ++b) {
    int dim = 0, tag = 0, param = 0;
    std::size_t n = 0;
    if(!(in >> dim >> tag >> param >> n) || dim != 2 || tag != surface_tag || param != 0)
      return false;
    std::vector<std::size_t> tags(n);
    for(auto& t : tags)
      if(!(in >> t) || t < 1 || t > nnodes)
        return false;
    for(std::size_t t : tags) {
      std::string sx, sy, sz; // via strings: std::stod round-trips max_digits10 output exactly
      if(!(in >> sx >> sy >> sz))
        return false;
      out.points[t - 1] = {std::stod(sx), std::stod(sy), std::stod(sz)};
    }
  }
  if(!expect("$EndNodes"))
    return false;

  std::size_t nelem = 0;
  if(!expect("$Elements") || !(in >> nblocks >> nelem >> mintag >> maxtag))
    return false;
  for(std::size_t b = 0; b < nblocks; ++b) {
    int dim = 0, tag = 0, type = 0;
    std::size_t n = 0;
    if(!(in >> dim >> tag >> type >> n) || dim != 2 || tag != surface_tag || type != 3)
      return false;
    for(std::size_t e = 0; e < n; ++e) {
      std::size_t etag = 0;
      std::array<std::size_t, 4> q;
      if(!(in >> etag >> q[0] >> q[1] >> q[2] >> q[3]))
        return false;
      for(auto& v : q) {
        if(v < 1 || v > nnodes)
          return false;
        --v;
      }
      out.quads.push_back(q);
    }
  }
  return out.quads.size() == nelem && expect("$EndElements");
}

/// The whitespace-separated tokens between the `>` of the opening tag that contains
/// `marker` and the next `</DataArray>`.
inline std::vector<std::string> vtu_data_array(const std::string& text, const std::string& marker)
{
  std::vector<std::string> tokens;
  const std::size_t at = text.find(marker);
  if(at == std::string::npos)
    return tokens;
  const std::size_t open = text.find('>', at);
  const std::size_t close = text.find("</DataArray>", open);
  std::istringstream in(text.substr(open + 1, close - open - 1));
  std::string tok;
  while(in >> tok)
    tokens.push_back(tok);
  return tokens;
}

inline bool parse_vtu(const std::string& text, Read_back& out)
{
  if(text.find("<VTKFile type=\"UnstructuredGrid\"") == std::string::npos)
    return false;
  const std::vector<std::string> pts = vtu_data_array(text, "Name=\"Points\"");
  const std::vector<std::string> conn = vtu_data_array(text, "Name=\"connectivity\"");
  const std::vector<std::string> offs = vtu_data_array(text, "Name=\"offsets\"");
  const std::vector<std::string> types = vtu_data_array(text, "Name=\"types\"");
  if(pts.size() % 3 != 0 || conn.size() % 4 != 0 || offs.size() != conn.size() / 4 ||
     types.size() != offs.size())
    return false;
  for(std::size_t i = 0; i < pts.size(); i += 3)
    out.points.push_back({std::stod(pts[i]), std::stod(pts[i + 1]), std::stod(pts[i + 2])});
  for(std::size_t c = 0; c < offs.size(); ++c) {
    if(std::stoul(types[c]) != 9 || std::stoul(offs[c]) != 4 * (c + 1))
      return false;
    out.quads.push_back({std::stoul(conn[4 * c]), std::stoul(conn[4 * c + 1]),
                         std::stoul(conn[4 * c + 2]), std::stoul(conn[4 * c + 3])});
  }
  return true;
}

inline bool parse_off(const std::string& text, Read_back& out)
{
  std::istringstream in(text);
  std::string header;
  std::size_t nv = 0, nf = 0, ne = 0;
  if(!(in >> header >> nv >> nf >> ne) || header != "OFF")
    return false;
  for(std::size_t i = 0; i < nv; ++i) {
    std::string sx, sy, sz;
    if(!(in >> sx >> sy >> sz))
      return false;
    out.points.push_back({std::stod(sx), std::stod(sy), std::stod(sz)});
  }
  for(std::size_t i = 0; i < nf; ++i) {
    std::size_t k = 0;
    std::array<std::size_t, 4> q;
    if(!(in >> k >> q[0] >> q[1] >> q[2] >> q[3]) || k != 4)
      return false;
    out.quads.push_back(q);
  }
  std::string extra;
  return !(in >> extra);
}

/// Exact comparison of what was read back with the mesh.
inline void expect_same(const Mesh& m, const Read_back& r)
{
  ASSERT_EQ(r.points.size(), m.points.size());
  ASSERT_EQ(r.quads.size(), m.quads.size());
  for(std::size_t i = 0; i < m.points.size(); ++i) {
    EXPECT_EQ(r.points[i][0], xd(m.points[i])) << "point " << i;
    EXPECT_EQ(r.points[i][1], yd(m.points[i])) << "point " << i;
    EXPECT_EQ(r.points[i][2], 0.0) << "point " << i;
  }
  for(std::size_t i = 0; i < m.quads.size(); ++i)
    EXPECT_EQ(r.quads[i], m.quads[i]) << "quad " << i;
}

} // namespace qm2_test_io_write

TEST(IOWrite, MSHRoundTrip)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(os, m));
  EXPECT_EQ(os.str().rfind("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n", 0), 0u);
  Read_back r;
  ASSERT_TRUE(parse_msh41(os.str(), r)) << os.str();
  expect_same(m, r);

  const std::string path = temp_path("mesh.msh");
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(path, m));
  EXPECT_EQ(slurp(path), os.str());
}

TEST(IOWrite, VTURoundTrip)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(os, m));
  const std::string text = os.str();
  EXPECT_NE(text.find("NumberOfPoints=\"6\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_NE(text.find("</VTKFile>"), std::string::npos);
  EXPECT_EQ(vtu_data_array(text, "Name=\"scaled_jacobian\"").size(), m.quads.size());
  Read_back r;
  ASSERT_TRUE(parse_vtu(text, r)) << text;
  expect_same(m, r);

  const std::string path = temp_path("mesh.vtu");
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(path, m));
  EXPECT_EQ(slurp(path), text);
}

TEST(IOWrite, OFFRoundTrip)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_OFF(os, m));
  Read_back r;
  ASSERT_TRUE(parse_off(os.str(), r)) << os.str();
  expect_same(m, r);

  const std::string path = temp_path("mesh.off");
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_OFF(path, m));
  EXPECT_EQ(slurp(path), os.str());
}

TEST(IOWrite, EmptyMesh)
{
  using namespace qm2_test_io_write;
  const Mesh m;
  Read_back r_msh, r_vtu, r_off;
  std::ostringstream msh, vtu, off, svg;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(msh, m));
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(vtu, m));
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_OFF(off, m));
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(svg, m));
  EXPECT_TRUE(parse_msh41(msh.str(), r_msh));
  EXPECT_TRUE(parse_vtu(vtu.str(), r_vtu));
  EXPECT_TRUE(parse_off(off.str(), r_off));
  EXPECT_TRUE(r_msh.points.empty() && r_vtu.points.empty() && r_off.points.empty());
  EXPECT_EQ(count_occurrences(svg.str(), "<polygon"), 0u);
}

TEST(IOWrite, StreamFormatIsRestored)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_test_mesh();
  std::ostringstream os;
  os.precision(3);
  os.setf(std::ios::fixed, std::ios::floatfield);
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(os, m));
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(os, m));
  EXPECT_EQ(os.precision(), 3);
  EXPECT_EQ(os.flags() & std::ios::floatfield, std::ios::fixed);
}

TEST(IOWrite, SVGOnePolygonPerQuadYUpAndColours)
{
  using namespace qm2_test_io_write;
  // A unit square (all 90 degrees) and a sheared neighbour with 30/150-degree corners.
  Mesh m;
  m.points = {Point(0, 0), Point(1, 0), Point(1, 1), Point(0, 1), Point(3, 0), Point(3, 1)};
  m.quads = {{0, 1, 2, 3}};
  std::ostringstream one;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(one, m));
  const std::string s1 = one.str();
  EXPECT_EQ(count_occurrences(s1, "<polygon"), 1u);
  // Scaled to 1000 units, y flipped: (0,0) is drawn at the bottom left.
  EXPECT_NE(s1.find("points=\"0,1000 1000,1000 1000,0 0,0\""), std::string::npos) << s1;
  EXPECT_NE(s1.find("viewBox="), std::string::npos);
  EXPECT_NE(s1.find("<g class=\"c0\">"), std::string::npos); // green class for 90 degrees

  m.points.push_back(Point(4.7320508075688772, 1)); // 1 + 2 + sqrt(3): a 30-degree corner at 4
  m.quads = {{0, 1, 2, 3}, {1, 4, 6, 2}};
  std::vector<std::pair<Point, Point>> segments = {{Point(0, 0), Point(1, 0)}, {Point(1, 0), Point(3, 0)}};
  std::ostringstream two;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(two, m, segments));
  const std::string s2 = two.str();
  EXPECT_EQ(count_occurrences(s2, "<polygon"), 2u);
  EXPECT_NE(s2.find("<g class=\"c46\">"), std::string::npos) << s2; // red: outside [45,135]
  EXPECT_NE(s2.find("#1f5fd6"), std::string::npos);               // segment overlay
  const std::size_t overlay = s2.find("#1f5fd6");
  ASSERT_NE(overlay, std::string::npos);
  const std::size_t d_begin = s2.find("d=\"", overlay) + 3;
  const std::string d = s2.substr(d_begin, s2.find('"', d_begin) - d_begin);
  EXPECT_EQ(count_occurrences(d, "M"), 2u) << d;
  EXPECT_EQ(count_occurrences(d, "L"), 2u) << d;
  // Larger side 4.732 -> 1000 units; y = 0 is the bottom edge, at 1 * 1000 / 4.732 (y up).
  EXPECT_EQ(d.rfind("M0,211.325L211.325,211.325M", 0), 0u) << d;
  EXPECT_NE(s2.find("<rect"), std::string::npos);        // legend

  const std::string path = temp_path("mesh.svg");
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(path, m, segments));
  EXPECT_EQ(slurp(path), s2);
}

TEST(IOWrite, SVGManyQuads)
{
  using namespace qm2_test_io_write;
  Mesh m;
  const std::size_t n = 30;
  for(std::size_t j = 0; j <= n; ++j)
    for(std::size_t i = 0; i <= n; ++i)
      m.points.push_back(Point(double(i), double(j)));
  for(std::size_t j = 0; j < n; ++j)
    for(std::size_t i = 0; i < n; ++i)
      m.quads.push_back({j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i});
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SVG(os, m));
  EXPECT_EQ(count_occurrences(os.str(), "<polygon"), n * n);
  EXPECT_LT(os.str().size(), 100 * n * n + 4000); // about 100 bytes per quad at most
}

TEST(IOWrite, TextBufferWritesNumbersAsTheStreamWould)
{
  // shortest round-trip text for doubles, %g with a precision when given one (the SVG's 6),
  // integers in full; pieces are handed on as the buffer fills
  const double values[] = { 0.0, -0.0, 1.0, 0.1, 1.0 / 3.0, -2.5e-17, 123456789.123, 1e300, 2.2250738585072014e-308, 1000.0,
                            999999.5, 1e-5 };
  std::ostringstream shortest, six, expected_six;
  {
    CGAL::Quad_mesher_2::internal::Text_buffer a(shortest), b(six, 6);
    for(int rep = 0; rep < 5000; ++rep) // past one piece
      for(double v : values) {
        a << v << ' ';
        b << v << ' ';
      }
    a << std::size_t(18446744073709551615ull) << '\n' << "end";
    a.flush();
    b.flush();
  }
  expected_six.precision(6);
  for(int rep = 0; rep < 5000; ++rep)
    for(double v : values) expected_six << v << ' ';
  EXPECT_EQ(six.str(), expected_six.str());
  std::istringstream in(shortest.str());
  for(int rep = 0; rep < 5000; ++rep)
    for(double v : values) {
      std::string token;
      in >> token;
      ASSERT_EQ(std::stod(token), v) << token; // reads back as the same double
      if(rep == 0) {
        EXPECT_LE(token.size(), 24u) << token;
      }
    }
  EXPECT_EQ(shortest.str().substr(shortest.str().size() - 24), "18446744073709551615\nend");
}

TEST(IOWrite, DispatchByExtension)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_test_mesh();
  const std::string dir = temp_path("");
  namespace QIO = CGAL::Quad_mesher_2::IO;
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.msh", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.vtu", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.off", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.svg", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "b.MSH", m)); // case-insensitive
  EXPECT_EQ(slurp(dir + "a.msh").rfind("$MeshFormat", 0), 0u);
  EXPECT_NE(slurp(dir + "a.vtu").find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_EQ(slurp(dir + "a.off").rfind("OFF\n", 0), 0u);
  EXPECT_NE(slurp(dir + "a.svg").find("<svg"), std::string::npos);
  EXPECT_EQ(slurp(dir + "b.MSH"), slurp(dir + "a.msh"));

  Read_back r;
  ASSERT_TRUE(parse_vtu(slurp(dir + "a.vtu"), r));
  expect_same(m, r);

  EXPECT_FALSE(QIO::write_quad_mesh(dir + "a.stl", m));
  EXPECT_FALSE(QIO::write_quad_mesh(dir + "noextension", m));
  EXPECT_FALSE(QIO::write_quad_mesh(dir + "dir.off/mesh", m));
  EXPECT_FALSE(std::filesystem::exists(dir + "a.stl"));
}

TEST(IOWrite, FailuresReturnFalse)
{
  using namespace qm2_test_io_write;
  namespace QIO = CGAL::Quad_mesher_2::IO;
  const Mesh m = make_test_mesh();
  const std::string bad = "/nonexistent_qm2_directory/sub/mesh";
  EXPECT_FALSE(QIO::write_MSH(bad + ".msh", m));
  EXPECT_FALSE(QIO::write_VTU(bad + ".vtu", m));
  EXPECT_FALSE(QIO::write_OFF(bad + ".off", m));
  EXPECT_FALSE(QIO::write_SVG(bad + ".svg", m));
  EXPECT_FALSE(QIO::write_quad_mesh(bad + ".msh", m));

  // A failed stream.
  std::ostringstream failed;
  failed.setstate(std::ios::badbit);
  EXPECT_FALSE(QIO::write_OFF(failed, m));
  EXPECT_FALSE(QIO::write_MSH(failed, m));

  // A stream that throws on failure: caught, reported as false.
  std::ofstream throwing;
  throwing.exceptions(std::ios::badbit | std::ios::failbit);
  EXPECT_NO_THROW(EXPECT_FALSE(QIO::write_VTU(throwing, m)));

  // Out-of-range quad index.
  Mesh broken = m;
  broken.quads.push_back({0, 1, 2, 42});
  std::ostringstream os;
  EXPECT_FALSE(QIO::write_MSH(os, broken));
  EXPECT_FALSE(QIO::write_VTU(os, broken));
  EXPECT_FALSE(QIO::write_OFF(os, broken));
  EXPECT_FALSE(QIO::write_SVG(os, broken));
}
