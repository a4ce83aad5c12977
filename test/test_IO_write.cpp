// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Tests for the writers of CGAL/Quad_mesher_2/IO/: each file is written, parsed back here
// and compared exactly with the mesh.

#include <CGAL/Quad_mesher_2/IO/write_INP.h>
#include <CGAL/Quad_mesher_2/IO/write_MSH.h>
#include <CGAL/Quad_mesher_2/IO/write_OFF.h>
#include <CGAL/Quad_mesher_2/IO/write_SU2.h>
#include <CGAL/Quad_mesher_2/IO/write_SVG.h>
#include <CGAL/Quad_mesher_2/IO/write_VTU.h>
#include <CGAL/Quad_mesher_2/IO/write_quad_mesh.h>
#include <CGAL/Quad_mesher_2/Quad_mesh_2.h>

#include "qm2_test_kernel.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
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

/// The test mesh with its boundary edges, markers 3, 7, 5 and -2 in no order.
inline Mesh make_marked_test_mesh()
{
  Mesh m = make_test_mesh();
  m.boundary_edges = {{0, 1, 3}, {1, 4, 7}, {4, 5, 3}, {5, 2, -2}, {2, 3, 5}, {3, 0, 3}};
  return m;
}

/// The marked test mesh in two regions: quad 0 of attribute 2.5 (tag 1), quad 1 of
/// attribute 7 (tag 7).
inline Mesh make_regions_test_mesh()
{
  Mesh m = make_marked_test_mesh();
  m.regions = { { 7, true, 7.0 }, { 1, true, 2.5 } };
  m.quad_regions = { 1, 0 };
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
  std::vector<std::array<long long, 3>> edges;    // boundary edges: 0-based ends, marker
  std::vector<int> quad_regions;                  // each quad's region tag, where the file has them
};

/// A strict reader for the MSH 4.1 ASCII subset our writer produces. Its boundary edges
/// get the marker their curve's physical name gives (`marker_3`, `marker_m3` for -3); its
/// quads the region tag of their surface's physical group `region_3` (none for `domain`).
inline bool parse_msh41(const std::string& text, Read_back& out)
{
  std::istringstream in(text);
  std::string tok;
  auto expect = [&](const std::string& s) { return (in >> tok) && tok == s; };
  double version = 0;
  int file_type = -1, data_size = 0;
  if(!expect("$MeshFormat") || !(in >> version >> file_type >> data_size) || version != 4.1 ||
     file_type != 0 || data_size != 8)
    return false;
  if(!expect("$EndMeshFormat") || !(in >> tok))
    return false;
  std::map<int, int> marker_of_physical; // of the curves' physical tags
  std::set<int> region_physicals;        // the surfaces' physical tags named region_<tag>
  bool domain_physical = false;
  if(tok == "$PhysicalNames") {
    std::size_t n = 0;
    if(!(in >> n))
      return false;
    for(std::size_t i = 0; i < n; ++i) {
      int dim = 0, tag = 0;
      std::string name;
      if(!(in >> dim >> tag >> name))
        return false;
      if(dim == 2) {
        if(tag == 1 && name == "\"domain\"" && !domain_physical && region_physicals.empty())
          domain_physical = true;
        else if(name == "\"region_" + std::to_string(tag) + "\"" && !domain_physical && region_physicals.insert(tag).second)
          continue;
        else
          return false;
      }
      if(dim == 1) {
        if(name.rfind("\"marker_", 0) != 0 || marker_of_physical.count(tag) != 0)
          return false;
        const std::string number = name.substr(8, name.size() - 9);
        marker_of_physical[tag] = number[0] == 'm' ? -std::stoi(number.substr(1)) : std::stoi(number);
      }
    }
    if(!expect("$EndPhysicalNames") || !(in >> tok))
      return false;
  }
  std::size_t np = 0, nc = 0, ns = 0, nv = 0;
  if(tok != "$Entities" || !(in >> np >> nc >> ns >> nv) || np != 0 || nc != marker_of_physical.size() || ns < 1 ||
     nv != 0 || (ns > 1) != !region_physicals.empty())
    return false;
  double bb[6];
  std::map<int, int> marker_of_curve;
  for(std::size_t c = 0; c < nc; ++c) {
    int curve = 0, physical = 0;
    std::size_t nphys = 0, npoints = 0;
    if(!(in >> curve >> bb[0] >> bb[1] >> bb[2] >> bb[3] >> bb[4] >> bb[5] >> nphys >> physical >> npoints) ||
       nphys != 1 || npoints != 0 || marker_of_physical.count(physical) == 0)
      return false;
    marker_of_curve[curve] = marker_of_physical[physical];
  }
  std::map<int, int> region_of_surface; // -1: the one surface "domain", or none
  std::set<int> bounding_curves;
  for(std::size_t k = 0; k < ns; ++k) {
    int surface_tag = 0, physical = -1;
    std::size_t nphys = 0, nbound = 0;
    if(!(in >> surface_tag >> bb[0] >> bb[1] >> bb[2] >> bb[3] >> bb[4] >> bb[5] >> nphys) || nphys > 1)
      return false;
    if(nphys == 1 && !(in >> physical))
      return false;
    const bool named = region_physicals.count(physical) != 0;
    if(nphys == 1 && !named && !(physical == 1 && domain_physical))
      return false;
    if(!(in >> nbound))
      return false;
    for(std::size_t i = 0; i < nbound; ++i)
      if(!(in >> tok) || marker_of_curve.count(std::stoi(tok)) == 0)
        return false;
      else
        bounding_curves.insert(std::stoi(tok));
    region_of_surface[surface_tag] = named ? physical : -1;
  }
  if(bounding_curves.size() != nc || !expect("$EndEntities"))
    return false;

  std::size_t nblocks = 0, nnodes = 0, mintag = 0, maxtag = 0;
  if(!expect("$Nodes") || !(in >> nblocks >> nnodes >> mintag >> maxtag))
    return false;
  out.points.assign(nnodes, {0, 0, 0});
  std::vector<bool> seen(nnodes, false);
  for(std::size_t b = 0; b < nblocks; ++b) {
    int dim = 0, tag = 0, param = 0;
    std::size_t n = 0;
    if(!(in >> dim >> tag >> param >> n) || dim != 2 || region_of_surface.count(tag) == 0 || param != 0)
      return false;
    std::vector<std::size_t> tags(n);
    for(auto& t : tags)
      if(!(in >> t) || t < 1 || t > nnodes || seen[t - 1])
        return false;
      else
        seen[t - 1] = true;
    for(std::size_t t : tags) {
      std::string sx, sy, sz; // via strings: std::stod round-trips max_digits10 output exactly
      if(!(in >> sx >> sy >> sz))
        return false;
      out.points[t - 1] = {std::stod(sx), std::stod(sy), std::stod(sz)};
    }
  }
  if(std::find(seen.begin(), seen.end(), false) != seen.end() || !expect("$EndNodes"))
    return false;

  // quads by element tag (1..m, in any block order), then the lines from m + 1 on
  std::size_t nelem = 0;
  if(!expect("$Elements") || !(in >> nblocks >> nelem >> mintag >> maxtag))
    return false;
  std::map<std::size_t, std::pair<std::array<std::size_t, 4>, int>> quads;
  std::size_t next_line_tag = 0;
  for(std::size_t b = 0; b < nblocks; ++b) {
    int dim = 0, tag = 0, type = 0;
    std::size_t n = 0;
    if(!(in >> dim >> tag >> type >> n))
      return false;
    const bool is_quads = dim == 2 && region_of_surface.count(tag) != 0 && type == 3 && next_line_tag == 0;
    const bool lines = dim == 1 && marker_of_curve.count(tag) != 0 && type == 1 && !quads.empty();
    if(!is_quads && !lines)
      return false;
    if(lines && next_line_tag == 0)
      next_line_tag = quads.size() + 1;
    for(std::size_t e = 0; e < n; ++e) {
      std::size_t etag = 0;
      std::array<std::size_t, 4> q{};
      if(!(in >> etag) || (lines && etag != next_line_tag++) || (is_quads && quads.count(etag) != 0))
        return false;
      for(int k = 0; k < (is_quads ? 4 : 2); ++k) {
        if(!(in >> q[k]) || q[k] < 1 || q[k] > nnodes)
          return false;
        --q[k];
      }
      if(is_quads)
        quads[etag] = { q, region_of_surface[tag] };
      else
        out.edges.push_back({(long long)q[0], (long long)q[1], marker_of_curve[tag]});
    }
  }
  std::size_t expected_tag = 1;
  for(const auto& [etag, quad] : quads) {
    if(etag != expected_tag++)
      return false;
    out.quads.push_back(quad.first);
    if(quad.second >= 0)
      out.quad_regions.push_back(quad.second);
  }
  return (out.quad_regions.empty() || out.quad_regions.size() == out.quads.size())
         && out.quads.size() + out.edges.size() == nelem && expect("$EndElements");
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

/// Reads the quads, then the lines (the boundary edges, with their `marker`), of a VTU file.
inline bool parse_vtu(const std::string& text, Read_back& out)
{
  if(text.find("<VTKFile type=\"UnstructuredGrid\"") == std::string::npos)
    return false;
  const std::vector<std::string> pts = vtu_data_array(text, "Name=\"Points\"");
  const std::vector<std::string> conn = vtu_data_array(text, "Name=\"connectivity\"");
  const std::vector<std::string> offs = vtu_data_array(text, "Name=\"offsets\"");
  const std::vector<std::string> types = vtu_data_array(text, "Name=\"types\"");
  const std::vector<std::string> markers = vtu_data_array(text, "Name=\"marker\"");
  if(pts.size() % 3 != 0 || types.size() != offs.size() || markers.size() != offs.size())
    return false;
  for(std::size_t i = 0; i < pts.size(); i += 3)
    out.points.push_back({std::stod(pts[i]), std::stod(pts[i + 1]), std::stod(pts[i + 2])});
  std::size_t begin = 0;
  for(std::size_t c = 0; c < offs.size(); ++c) {
    const std::size_t type = std::stoul(types[c]), end = std::stoul(offs[c]);
    const long long marker = std::stoll(markers[c]);
    if(end > conn.size() || end != begin + (type == 9 ? 4 : 2))
      return false;
    if(type == 9 && out.edges.empty() && marker == 0)
      out.quads.push_back({std::stoul(conn[begin]), std::stoul(conn[begin + 1]), std::stoul(conn[begin + 2]),
                           std::stoul(conn[begin + 3])});
    else if(type == 3)
      out.edges.push_back({std::stoll(conn[begin]), std::stoll(conn[begin + 1]), marker});
    else
      return false; // another type, or a quad after the lines
    begin = end;
  }
  return begin == conn.size();
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

/// A strict reader for the SU2 files our writer produces: the boundary edges' markers are
/// their MARKER_TAGs.
inline bool parse_su2(const std::string& text, Read_back& out)
{
  std::istringstream in(text);
  std::string key;
  std::size_t nelem = 0, npoin = 0, nmark = 0, index = 0;
  if(!(in >> key) || key != "NDIME=" || !(in >> index) || index != 2 || !(in >> key) || key != "NELEM=" || !(in >> nelem))
    return false;
  for(std::size_t e = 0; e < nelem; ++e) {
    int type = 0;
    std::array<std::size_t, 4> q;
    if(!(in >> type >> q[0] >> q[1] >> q[2] >> q[3] >> index) || type != 9 || index != e)
      return false;
    out.quads.push_back(q);
  }
  if(!(in >> key) || key != "NPOIN=" || !(in >> npoin))
    return false;
  for(std::size_t p = 0; p < npoin; ++p) {
    std::string sx, sy;
    if(!(in >> sx >> sy >> index) || index != p)
      return false;
    out.points.push_back({std::stod(sx), std::stod(sy), 0.0});
  }
  if(!(in >> key) || key != "NMARK=" || !(in >> nmark))
    return false;
  for(std::size_t m = 0; m < nmark; ++m) {
    long long marker = 0;
    std::size_t n = 0;
    if(!(in >> key) || key != "MARKER_TAG=" || !(in >> marker >> key) || key != "MARKER_ELEMS=" || !(in >> n))
      return false;
    for(std::size_t e = 0; e < n; ++e) {
      int type = 0;
      long long a = 0, b = 0;
      if(!(in >> type >> a >> b) || type != 3 || a < 0 || b < 0 || a >= (long long)npoin || b >= (long long)npoin)
        return false;
      out.edges.push_back({a, b, marker});
    }
  }
  return !(in >> key);
}

/// The data lines of an Abaqus file after each keyword line, split at commas.
inline std::vector<std::pair<std::string, std::vector<std::vector<std::string>>>> inp_sections(const std::string& text)
{
  std::vector<std::pair<std::string, std::vector<std::vector<std::string>>>> sections;
  std::istringstream in(text);
  std::string line;
  while(std::getline(in, line)) {
    if(line.rfind("*", 0) == 0) {
      sections.push_back({line, {}});
      continue;
    }
    std::vector<std::string> fields;
    std::istringstream f(line);
    std::string field;
    while(std::getline(f, field, ','))
      fields.push_back(field);
    if(sections.empty())
      return {};
    sections.back().second.push_back(fields);
  }
  return sections;
}

/// An Abaqus file's element surfaces: by name, the (element, face) pairs of the element sets
/// it names (faces 1 to 4).
typedef std::map<std::string, std::set<std::pair<std::size_t, int>>> Inp_surfaces;

/// Reads the numbers of an Abaqus set's data lines (16 a line at most, increasing, each once)
/// into `set`; false if they break those rules or reach `limit`.
inline bool read_inp_set(const std::vector<std::vector<std::string>>& lines, std::size_t limit, std::set<std::size_t>& set)
{
  for(const auto& f : lines) {
    if(f.size() > 16)
      return false;
    for(const std::string& number : f)
      if(!set.insert(std::stoul(number)).second || *set.rbegin() != std::stoul(number) || *set.rbegin() > limit)
        return false;
  }
  return true;
}

/// Reads the nodes and quads of an Abaqus file as our writer writes it, its node sets (nodes
/// from 0) and its element surfaces (elements from 1).
inline bool parse_inp(const std::string& text, Read_back& out, std::map<std::string, std::set<std::size_t>>& nsets,
                      Inp_surfaces* surfaces = nullptr)
{
  const auto sections = inp_sections(text);
  if(sections.size() < 3 || sections[0].first != "*HEADING" || sections[1].first != "*NODE" ||
     sections[2].first != "*ELEMENT, TYPE=CPS4, ELSET=domain")
    return false;
  for(const auto& f : sections[1].second) {
    if(f.size() != 3 || std::stoul(f[0]) != out.points.size() + 1)
      return false;
    out.points.push_back({std::stod(f[1]), std::stod(f[2]), 0.0});
  }
  for(const auto& f : sections[2].second) {
    if(f.size() != 5 || std::stoul(f[0]) != out.quads.size() + 1)
      return false;
    out.quads.push_back({std::stoul(f[1]) - 1, std::stoul(f[2]) - 1, std::stoul(f[3]) - 1, std::stoul(f[4]) - 1});
  }
  std::map<std::string, std::set<std::size_t>> elsets;
  const std::string nset = "*NSET, NSET=", elset = "*ELSET, ELSET=", surface = "*SURFACE, NAME=", element = ", TYPE=ELEMENT";
  for(std::size_t s = 3; s < sections.size(); ++s) {
    const std::string& head = sections[s].first;
    if(head.rfind(nset, 0) == 0) {
      std::set<std::size_t> nodes;
      if(!read_inp_set(sections[s].second, out.points.size(), nodes))
        return false;
      for(std::size_t node : nodes)
        nsets[head.substr(nset.size())].insert(node - 1);
    } else if(head.rfind(elset, 0) == 0) {
      if(!read_inp_set(sections[s].second, out.quads.size(), elsets[head.substr(elset.size())]))
        return false;
    } else if(head.rfind(surface, 0) == 0 && head.size() > element.size()
              && head.compare(head.size() - element.size(), element.size(), element) == 0) {
      const std::string name = head.substr(surface.size(), head.size() - surface.size() - element.size());
      for(const auto& f : sections[s].second) {
        if(f.size() != 2 || f[1].size() != 3 || f[1].substr(0, 2) != " S" || elsets.count(f[0]) == 0)
          return false;
        const int face = f[1][2] - '0';
        if(face < 1 || face > 4)
          return false;
        for(std::size_t e : elsets[f[0]])
          if(surfaces != nullptr) (*surfaces)[name].insert({e, face});
      }
    } else {
      return false;
    }
  }
  return true;
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
  // the edges as a set: the writers group them by marker
  std::vector<std::array<long long, 3>> edges;
  for(const auto& e : m.boundary_edges)
    edges.push_back({(long long)e.v0, (long long)e.v1, e.marker});
  std::vector<std::array<long long, 3>> read = r.edges;
  std::sort(edges.begin(), edges.end());
  std::sort(read.begin(), read.end());
  EXPECT_EQ(read, edges);
}

/// `m` written as MSH 4.1, and what parse_msh41() reads back from it, checked to be `m`
inline std::pair<std::string, Read_back> msh_read_back(const Mesh& m)
{
  std::ostringstream os;
  EXPECT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(os, m));
  Read_back r;
  EXPECT_TRUE(parse_msh41(os.str(), r)) << os.str();
  expect_same(m, r);
  return { os.str(), r };
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

TEST(IOWrite, MSHBoundaryEdgesByMarker)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_marked_test_mesh();
  const std::string text = msh_read_back(m).first;
  // a marker is not positive: physical tags 1..4 by increasing marker, names keep the markers
  EXPECT_NE(text.find("$PhysicalNames\n5\n1 1 \"marker_m2\"\n1 2 \"marker_3\"\n1 3 \"marker_5\"\n"
                      "1 4 \"marker_7\"\n2 1 \"domain\"\n$EndPhysicalNames\n"),
            std::string::npos) << text;
  // the quads first, tags 1 and 2; then marker -2's curve 1 with its one line, tag 3
  EXPECT_NE(text.find("$Elements\n5 8 1 8\n2 1 3 2\n1 1 2 3 4\n2 2 5 6 3\n1 1 1 1\n3 6 3\n"), std::string::npos)
    << text;
  // every marker positive: the markers are the physical tags
  Mesh positive = m;
  positive.boundary_edges[3].marker = 7;
  std::ostringstream pos;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(pos, positive));
  EXPECT_NE(pos.str().find("$PhysicalNames\n4\n1 3 \"marker_3\"\n1 5 \"marker_5\"\n1 7 \"marker_7\"\n"),
            std::string::npos) << pos.str();
  Read_back rp;
  ASSERT_TRUE(parse_msh41(pos.str(), rp));
  expect_same(positive, rp);
}

TEST(IOWrite, MSHASurfaceAndAPhysicalGroupPerRegion)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_regions_test_mesh();
  const auto [text, r] = msh_read_back(m);
  EXPECT_EQ(r.quad_regions, (std::vector<int>{ 1, 7 }));
  EXPECT_NE(text.find("2 7 \"region_7\"\n2 1 \"region_1\"\n$EndPhysicalNames\n"), std::string::npos) << text;
  // quad 1 in surface 1 (region 7) first, quad 0 in surface 2; each keeps its tag
  EXPECT_NE(text.find("$Elements\n6 8 1 8\n2 1 3 1\n2 2 5 6 3\n2 2 3 1\n1 1 2 3 4\n"), std::string::npos) << text;

  // one region without an attribute: the one surface "domain", as without regions
  Mesh one = make_marked_test_mesh();
  std::ostringstream plain;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(plain, one));
  one.regions = { { 1, false, 0.0 } };
  one.quad_regions = { 0, 0 };
  std::ostringstream single;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_MSH(single, one));
  EXPECT_EQ(single.str(), plain.str());
  // a region index out of range is refused
  one.quad_regions = { 0, 1 };
  std::ostringstream bad;
  EXPECT_FALSE(CGAL::Quad_mesher_2::IO::write_MSH(bad, one));
}

TEST(IOWrite, VTUAndINPCarryTheRegions)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_regions_test_mesh();
  std::ostringstream vtu;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(vtu, m));
  // the quads, then the six lines
  EXPECT_EQ(vtu_data_array(vtu.str(), "Name=\"region\""),
            (std::vector<std::string>{ "1", "7", "0", "0", "0", "0", "0", "0" }));
  EXPECT_EQ(vtu_data_array(vtu.str(), "Name=\"attribute\""),
            (std::vector<std::string>{ "2.5", "7", "0", "0", "0", "0", "0", "0" }));
  std::ostringstream inp;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_INP(inp, m));
  EXPECT_NE(inp.str().find("*ELSET, ELSET=region_7\n2\n*ELSET, ELSET=region_1\n1\n"), std::string::npos) << inp.str();
  // without regions, neither the fields nor the sets
  const Mesh plain = make_marked_test_mesh();
  std::ostringstream pv, pi;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(pv, plain));
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_INP(pi, plain));
  EXPECT_EQ(pv.str().find("Name=\"region\""), std::string::npos);
  EXPECT_EQ(pi.str().find("ELSET=region_"), std::string::npos);
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

TEST(IOWrite, VTUBoundaryEdgesAfterTheQuads)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_marked_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_VTU(os, m));
  const std::string text = os.str();
  EXPECT_NE(text.find("NumberOfPoints=\"6\" NumberOfCells=\"8\""), std::string::npos);
  EXPECT_EQ(vtu_data_array(text, "Name=\"types\""),
            (std::vector<std::string>{"9", "9", "3", "3", "3", "3", "3", "3"}));
  EXPECT_EQ(vtu_data_array(text, "Name=\"max_angle_deviation\"").size(), 8u);
  Read_back r;
  ASSERT_TRUE(parse_vtu(text, r)) << text;
  expect_same(m, r);
}

TEST(IOWrite, SU2QuadsPointsAndAMarkerPerTag)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_marked_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SU2(os, m));
  const std::string text = os.str();
  Read_back r;
  ASSERT_TRUE(parse_su2(text, r)) << text;
  expect_same(m, r);
  // the markers in increasing order, the edges of each in the mesh's order
  EXPECT_NE(text.find("NMARK= 4\nMARKER_TAG= -2\nMARKER_ELEMS= 1\n3 5 2\nMARKER_TAG= 3\nMARKER_ELEMS= 3\n"
                      "3 0 1\n3 4 5\n3 3 0\n"),
            std::string::npos) << text;
  Read_back unmarked;
  std::ostringstream plain;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_SU2(plain, make_test_mesh()));
  ASSERT_TRUE(parse_su2(plain.str(), unmarked)) << plain.str();
  EXPECT_NE(plain.str().find("NMARK= 0\n"), std::string::npos);
}

TEST(IOWrite, INPNodesElementsAndANodeSetPerMarker)
{
  using namespace qm2_test_io_write;
  const Mesh m = make_marked_test_mesh();
  std::ostringstream os;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_INP(os, m));
  Read_back r;
  std::map<std::string, std::set<std::size_t>> nsets;
  ASSERT_TRUE(parse_inp(os.str(), r, nsets)) << os.str();
  Mesh without_edges = m; // the edges' markers are in the node sets
  without_edges.boundary_edges.clear();
  expect_same(without_edges, r);
  const std::map<std::string, std::set<std::size_t>> expected = {
    {"marker_m2", {2, 5}}, {"marker_3", {0, 1, 3, 4, 5}}, {"marker_5", {2, 3}}, {"marker_7", {1, 4}}};
  EXPECT_EQ(nsets, expected);
  // each marker's element faces, face k from node k to node k + 1 of the element (from 1),
  // whichever way its boundary edges run
  Mesh reversed = m;
  for(auto& e : reversed.boundary_edges)
    std::swap(e.v0, e.v1);
  const Inp_surfaces expected_surfaces = {{"marker_m2", {{2, 3}}},
                                          {"marker_3", {{1, 1}, {2, 2}, {1, 4}}},
                                          {"marker_5", {{1, 3}}},
                                          {"marker_7", {{2, 1}}}};
  for(const Mesh& mesh : {m, reversed}) {
    std::ostringstream text;
    ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_INP(text, mesh));
    Read_back back;
    std::map<std::string, std::set<std::size_t>> node_sets;
    Inp_surfaces surfaces;
    ASSERT_TRUE(parse_inp(text.str(), back, node_sets, &surfaces)) << text.str();
    EXPECT_EQ(surfaces, expected_surfaces) << text.str();
  }
  // a boundary edge that is no side of a quad: no surface can hold it
  Mesh across = m;
  across.boundary_edges.push_back({0, 2, 1});
  std::ostringstream refused;
  EXPECT_FALSE(CGAL::Quad_mesher_2::IO::write_INP(refused, across));

  // 16 nodes a line at most
  Mesh strip;
  for(int i = 0; i <= 20; ++i) {
    strip.points.push_back(Point(i, 0));
    strip.points.push_back(Point(i, 1));
  }
  for(std::size_t i = 0; i < 20; ++i) {
    strip.quads.push_back({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
    strip.boundary_edges.push_back({2 * i, 2 * i + 2, 1});
  }
  std::ostringstream long_set;
  ASSERT_TRUE(CGAL::Quad_mesher_2::IO::write_INP(long_set, strip));
  Read_back rs;
  nsets.clear();
  ASSERT_TRUE(parse_inp(long_set.str(), rs, nsets)) << long_set.str();
  EXPECT_EQ(nsets["marker_1"].size(), 21u);
  EXPECT_EQ(nsets.size(), 1u);
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
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.su2", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "a.inp", m));
  ASSERT_TRUE(QIO::write_quad_mesh(dir + "b.MSH", m)); // case-insensitive
  EXPECT_EQ(slurp(dir + "a.msh").rfind("$MeshFormat", 0), 0u);
  EXPECT_NE(slurp(dir + "a.vtu").find("<VTKFile type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_EQ(slurp(dir + "a.off").rfind("OFF\n", 0), 0u);
  EXPECT_NE(slurp(dir + "a.svg").find("<svg"), std::string::npos);
  EXPECT_EQ(slurp(dir + "a.su2").rfind("NDIME= 2\n", 0), 0u);
  EXPECT_EQ(slurp(dir + "a.inp").rfind("*HEADING\n", 0), 0u);
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

  // Out-of-range boundary-edge index.
  Mesh bad_edge = make_marked_test_mesh();
  bad_edge.boundary_edges.push_back({0, 6, 1});
  std::ostringstream edge_os;
  EXPECT_FALSE(QIO::write_MSH(edge_os, bad_edge));
  EXPECT_FALSE(QIO::write_VTU(edge_os, bad_edge));
  EXPECT_FALSE(QIO::write_SU2(edge_os, bad_edge));
  EXPECT_FALSE(QIO::write_INP(edge_os, bad_edge));
  EXPECT_FALSE(QIO::write_SU2(bad + ".su2", m));
  EXPECT_FALSE(QIO::write_INP(bad + ".inp", m));

  // Out-of-range quad index.
  Mesh broken = m;
  broken.quads.push_back({0, 1, 2, 42});
  std::ostringstream os;
  EXPECT_FALSE(QIO::write_MSH(os, broken));
  EXPECT_FALSE(QIO::write_VTU(os, broken));
  EXPECT_FALSE(QIO::write_OFF(os, broken));
  EXPECT_FALSE(QIO::write_SVG(os, broken));
}
