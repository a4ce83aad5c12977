// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The quad-mesher tool end to end: it is run as a user would run it.

#include "qm2_fifo.h"
#include "qm2_test_kernel.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#ifdef QM2_CLI_PATH

namespace qm2_test_cli {

const std::string kernel_name = qm2_test::exact_constructions ? "epeck" : "epick";

struct Cli_run
{
  int status;
  std::string out, err;
};

std::string slurp(const std::filesystem::path& p)
{
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::filesystem::path scratch(const std::string& name)
{
  auto dir = std::filesystem::temp_directory_path() / ("qm2_cli_" + kernel_name);
  std::filesystem::create_directories(dir);
  return dir / name;
}

Cli_run run(const std::string& args)
{
  // one pair of files per test: ctest runs tests in parallel processes
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  auto out = scratch(test + ".stdout"), err = scratch(test + ".stderr");
  std::string cmd = std::string(QM2_CLI_PATH) + " " + args + " >" + out.string() + " 2>" + err.string();
  int raw = std::system(cmd.c_str());
  return { WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, slurp(out), slurp(err) };
}

const std::string lake = std::string(QM2_DATA_DIR) + "/lake_superior/lake_superior.poly";

TEST(quad_mesher_cli, meshes_lake_superior_with_every_output_and_a_report)
{
  auto msh = scratch("lake.msh"), svg = scratch("lake.svg"), vtu = scratch("lake.vtu"),
       off = scratch("lake.off"), json = scratch("lake.json");
  Cli_run r = run(lake + " --stop-after quadtree --kernel " + kernel_name + " -o " + msh.string() + " -o " +
              svg.string() + " -o " + vtu.string() + " -o " + off.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  for(const auto& f : { msh, svg, vtu, off })
    EXPECT_GT(std::filesystem::file_size(f), 1000u) << f;
  EXPECT_NE(slurp(msh).find("$MeshFormat\n4.1"), std::string::npos);
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_GT(report["quads"].get<int>(), 1000);
  EXPECT_GT(report["vertices"].get<int>(), 1000);
  EXPECT_GE(report["min_angle"].get<double>(), 45 - 1e-9);
  EXPECT_LE(report["max_angle"].get<double>(), 135 + 1e-9);
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  EXPECT_EQ(report["validity"]["hanging_nodes"].get<int>(), 0);
  EXPECT_EQ(report["validity"]["boundary_loops"].get<int>(), 1);
  EXPECT_GE(report["quadtree_depth"].get<int>(), 6);
  EXPECT_EQ(report["kernel"], kernel_name);
  EXPECT_EQ(report["input"]["points"].get<int>(), 518);
  EXPECT_EQ(report["input"]["segments"].get<int>(), 518);
  for(const char* stage : { "read", "refine", "balance", "refinement_templates", "quality", "write", "total" })
    EXPECT_TRUE(report["seconds"].contains(stage)) << stage;
  EXPECT_EQ(report["angle_histogram_5deg"].size(), 72u);
}

TEST(quad_mesher_cli, solver_formats_carry_the_segment_markers)
{
  // the .poly's segment markers: 1 on the far field, 2 on the air foil
  const std::string naca = std::string(QM2_DATA_DIR) + "/naca0012/naca0012_sharp.poly";
  auto msh = scratch("naca.msh"), su2 = scratch("naca.su2"), inp = scratch("naca.inp"), vtu = scratch("naca.vtu");
  Cli_run r = run(naca + " --kernel " + kernel_name + " -o " + msh.string() + " -o " + su2.string() + " -o " +
                  inp.string() + " -o " + vtu.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string m = slurp(msh), s = slurp(su2), i = slurp(inp), v = slurp(vtu);
  EXPECT_NE(m.find("$PhysicalNames\n3\n1 1 \"marker_1\"\n1 2 \"marker_2\"\n2 1 \"domain\"\n"), std::string::npos);
  EXPECT_NE(s.find("NMARK= 2\nMARKER_TAG= 1\n"), std::string::npos);
  EXPECT_NE(s.find("\nMARKER_TAG= 2\n"), std::string::npos);
  EXPECT_NE(i.find("\n*NSET, NSET=marker_1\n"), std::string::npos);
  EXPECT_NE(i.find("\n*NSET, NSET=marker_2\n"), std::string::npos);
  EXPECT_NE(i.find("\n*SURFACE, NAME=marker_2, TYPE=ELEMENT\n"), std::string::npos);
  EXPECT_NE(v.find("Name=\"marker\""), std::string::npos);
  // the same quads in each: the count the SU2 file gives, in the others
  const std::size_t at = s.find("NELEM= ") + 7;
  const std::string quads = s.substr(at, s.find('\n', at) - at);
  EXPECT_NE(m.find("\n2 1 3 " + quads + "\n"), std::string::npos) << quads;
  EXPECT_NE(i.find("\n" + quads + ", "), std::string::npos);
  // a format the tool does not write is a usage error naming those it does
  r = run(naca + " -o " + scratch("naca.stl").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find(".su2, .inp"), std::string::npos) << r.err;
}

// Land around a lake holding an island, with Triangle's regional attributes: each region's
// quads come out as a group of every format that has them, and the report counts them.
TEST(quad_mesher_cli, regional_attributes_come_out_as_region_groups)
{
  auto poly = scratch("island.poly"), msh = scratch("island.msh"), inp = scratch("island.inp"),
       vtu = scratch("island.vtu"), json = scratch("island.json");
  const std::string land_lake_island = "12 2 0 0\n1 0 0\n2 4 0\n3 4 3\n4 0 3\n5 1 0.7\n6 3.2 0.6\n7 3.1 2.3\n"
                                       "8 0.9 2.4\n9 1.7 1.2\n10 2.5 1.3\n11 2.4 1.8\n12 1.6 1.7\n12 0\n1 1 2\n"
                                       "2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n7 7 8\n8 8 5\n9 9 10\n10 10 11\n"
                                       "11 11 12\n12 12 9\n1\n1 1.2 1.0\n";
  std::ofstream(poly) << land_lake_island << "2\n1 0.3 0.3 7\n2 2.0 1.5 2.5 0.002\n";
  Cli_run r = run(poly.string() + " --kernel " + kernel_name + " -o " + msh.string() + " -o " + inp.string() + " -o " +
                  vtu.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const auto report = nlohmann::json::parse(slurp(json));
  ASSERT_EQ(report["regions"].size(), 2u);
  EXPECT_EQ(report["regions"][0]["tag"], 7);
  EXPECT_EQ(report["regions"][0]["attribute"], 7.0);
  EXPECT_EQ(report["regions"][1]["tag"], 1);
  EXPECT_EQ(report["regions"][1]["attribute"], 2.5);
  EXPECT_EQ(report["regions"][0]["quads"].get<std::size_t>() + report["regions"][1]["quads"].get<std::size_t>(),
            report["quads"].get<std::size_t>());
  EXPECT_EQ(report["input"]["regional_attributes"], 2);
  const std::string m = slurp(msh);
  EXPECT_NE(m.find("2 7 \"region_7\"\n2 1 \"region_1\"\n$EndPhysicalNames\n"), std::string::npos) << m.substr(0, 300);
  EXPECT_NE(slurp(inp).find("\n*ELSET, ELSET=region_1\n"), std::string::npos);
  EXPECT_NE(slurp(vtu).find("Name=\"attribute\""), std::string::npos);
  // no attributes: two regions all the same, tags 1 and 2, attributes null
  std::ofstream(poly) << land_lake_island;
  r = run(poly.string() + " -o " + msh.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(msh).find("2 1 \"region_1\"\n2 2 \"region_2\"\n"), std::string::npos);
  EXPECT_TRUE(nlohmann::json::parse(slurp(json))["regions"][1]["attribute"].is_null());
  // an attribute in the lake is named with its file line
  std::ofstream(poly) << land_lake_island << "1\n1 1.2 1.0 3\n";
  r = run(poly.string() + " -o " + msh.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("regional attribute 1 (line 30) (1.2, 1) lies outside the domain"), std::string::npos) << r.err;
}

TEST(quad_mesher_cli, both_kernels_give_the_same_mesh)
{
  auto a = scratch("k_epick.json"), b = scratch("k_epeck.json"), m = scratch("k.off");
  ASSERT_EQ(run(lake + " -o " + m.string() + " --kernel epick --report " + a.string()).status, 0);
  ASSERT_EQ(run(lake + " -o " + m.string() + " --kernel epeck --report " + b.string()).status, 0);
  auto ja = nlohmann::json::parse(slurp(a)), jb = nlohmann::json::parse(slurp(b));
  EXPECT_EQ(ja["quads"], jb["quads"]);
  EXPECT_EQ(ja["vertices"], jb["vertices"]);
  EXPECT_EQ(ja["quadtree_depth"], jb["quadtree_depth"]);
  // the stage times add up over the refinement rounds (Lake Superior takes two): they
  // account for nearly the whole run, not for its last round only
  for(const auto& j : { ja, jb }) {
    ASSERT_GT(j["buffer"]["refinement_rounds"].get<int>(), 0);
    double stages = 0;
    for(const auto& s : j["seconds"].items())
      if(s.key() != "total") stages += s.value().get<double>();
    EXPECT_GT(stages, 0.7 * j["seconds"]["total"].get<double>());
    EXPECT_LE(stages, 1.01 * j["seconds"]["total"].get<double>() + 1e-3);
  }
}

// Lemma 2 as the templates leave it, in the report: bird's core has 5 buffer-side angles
// outside [112.5, 225], all within 2h of input corners (§5's), and two jammed convex corners
// split in three; the guitar's has 4, one of them away from corners. (Bird's had 8, two away
// from corners, until the quadtree's boundary band narrowed to one cell along straight
// stretches; Lake Superior's had one away from corners and one corner split until it
// narrowed from three cells to two: 9, none and none.)
TEST(quad_mesher_cli, the_report_counts_lemma_2_at_the_templates_stage)
{
  auto json = scratch("l2.json"), m = scratch("l2.off");
  const std::string bird = std::string(QM2_SHARED_DATA_DIR) + "/bird/bird.poly";
  ASSERT_EQ(run(bird + " -o " + m.string() + " --stop-after templates --report " + json.string()).status, 0);
  auto buffer = nlohmann::json::parse(slurp(json))["buffer"];
  EXPECT_EQ(buffer["buffer_angles_out"].get<int>(), 5);
  EXPECT_EQ(buffer["buffer_angles_out_away_from_corners"].get<int>(), 0);
  EXPECT_EQ(buffer["corners_split"].get<int>(), 2);
  const std::string guitar = std::string(QM2_SHARED_DATA_DIR) + "/guitar/guitar.poly";
  ASSERT_EQ(run(guitar + " -o " + m.string() + " --stop-after templates --report " + json.string()).status, 0);
  buffer = nlohmann::json::parse(slurp(json))["buffer"];
  EXPECT_EQ(buffer["buffer_angles_out"].get<int>(), 4);
  EXPECT_EQ(buffer["buffer_angles_out_away_from_corners"].get<int>(), 1);
}

TEST(quad_mesher_cli, sizing_options_change_the_mesh)
{
  auto a = scratch("s_default.json"), b = scratch("s_max.json"), m = scratch("s.off");
  ASSERT_EQ(run(lake + " -o " + m.string() + " --report " + a.string()).status, 0);
  ASSERT_EQ(run(lake + " -o " + m.string() + " --max-size 0.01 --report " + b.string()).status, 0);
  EXPECT_GT(nlohmann::json::parse(slurp(b))["quads"].get<int>(), nlohmann::json::parse(slurp(a))["quads"].get<int>());
  Cli_run r = run(lake + " -o " + m.string() + " --max-depth 5");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("maximum depth 5"), std::string::npos) << r.err;
}

TEST(quad_mesher_cli, bad_input_gives_a_clear_error)
{
  auto bad = scratch("bad.poly"), m = scratch("bad.msh");
  std::ofstream(bad) << "3 2 0 0\n1 0 0\n2 1 nan\n3 0 1\n";
  Cli_run r = run(bad.string() + " -o " + m.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("bad.poly"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(":3"), std::string::npos) << r.err;
  r = run(scratch("missing.poly").string() + " -o " + m.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("missing.poly"), std::string::npos) << r.err;
}

TEST(quad_mesher_cli, never_overwrites_the_input_and_refuses_directories)
{
  auto copy = scratch("keep.poly"), m = scratch("keep.msh"), dir = scratch("dir.poly");
  std::filesystem::copy_file(lake, copy, std::filesystem::copy_options::overwrite_existing);
  const std::string before = slurp(copy);
  EXPECT_EQ(run(copy.string() + " -o " + m.string() + " --report " + copy.string()).status, 2);
  EXPECT_EQ(run(copy.string() + " -o " + m.string() + " -o " + m.string()).status, 2);
  std::filesystem::remove(m);
  const std::string dotted = (m.parent_path() / "." / m.filename()).string();
  EXPECT_EQ(run(copy.string() + " -o " + m.string() + " -o " + dotted).status, 2); // not there yet
  EXPECT_EQ(run(copy.string() + " -o " + m.string() + " --report " + m.string()).status, 2);
  EXPECT_EQ(slurp(copy), before);
  std::filesystem::create_directories(dir);
  Cli_run r = run(dir.string() + " -o " + m.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

// A run that cannot write one of its outputs writes none: the files already there stay as
// they were, and no partial file is left beside them.
TEST(quad_mesher_cli, an_output_that_cannot_be_written_leaves_the_others_untouched)
{
  auto m = scratch("untouched.msh"), svg = scratch("untouched.svg"), json = scratch("untouched.json");
  std::ofstream(m) << "kept\n";
  std::filesystem::remove(svg);
  std::filesystem::remove(json);
  const std::string nowhere = (scratch("no_such_dir") / "out.vtu").string();
  Cli_run r = run(lake + " -o " + m.string() + " -o " + svg.string() + " -o " + nowhere + " --report " + json.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cannot write " + nowhere), std::string::npos) << r.err;
  EXPECT_EQ(slurp(m), "kept\n");
  EXPECT_FALSE(std::filesystem::exists(svg));
  EXPECT_FALSE(std::filesystem::exists(json));
  for(const auto& e : std::filesystem::directory_iterator(m.parent_path()))
    EXPECT_NE(e.path().filename().string().rfind(".untouched.", 0), 0u) << e.path(); // ours, hidden
  r = run(lake + " -o " + m.string() + " -o " + svg.string() + " --report " + json.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_NE(slurp(m), "kept\n");
  EXPECT_TRUE(std::filesystem::exists(svg) && std::filesystem::exists(json));
  // an output named by a symbolic link is written into the file it points to
  auto link = scratch("untouched_link.msh"), real = scratch("untouched_real.dat");
  std::filesystem::remove(link);
  std::ofstream(real) << "old\n";
  std::filesystem::create_symlink(real, link);
  r = run(lake + " -o " + link.string());
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(slurp(real).rfind("$MeshFormat", 0), 0u);
}

TEST(quad_mesher_cli, cell_budget_stops_huge_meshes_cleanly)
{
  Cli_run r = run(lake + " -o " + scratch("big.msh").string() + " --stop-after quadtree --max-size 1e-5 --max-cells 100000");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("cell budget of 100000"), std::string::npos) << r.err;
  // within the largest budget, 1.7e11 cells of side 1e-6 (terabytes) ended in a bare "out of
  // memory": the room for them is taken before any cell is made, and its failure named
  r = run(lake + " -o " + scratch("big.msh").string() + " --stop-after quadtree --max-size 1e-6 --max-cells 1099511627776");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("more than memory holds, though within the cell budget of 1099511627776"), std::string::npos) << r.err;
  // a point cloud grew its tree until memory ran out (3.6 GB in 16 s under a 4 GB limit)
  const auto cloud = scratch("budget_cloud.xy");
  std::ofstream(cloud) << "0 0\n1 0\n1 1\n0 1\n";
  r = run(cloud.string() + " -o " + scratch("big.msh").string() + " --stop-after quadtree --max-size 1e-5 --max-cells 1099511627776");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("more than memory holds, though within the cell budget of 1099511627776"), std::string::npos) << r.err;
}

// Only regular files are read: a FIFO without a writer blocked the tool for ever.
TEST(quad_mesher_cli, a_fifo_or_a_device_is_refused_at_once)
{
  const auto fifo = scratch("input_fifo.poly"), m = scratch("fifo.msh");
  std::filesystem::remove(fifo);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  qm2_test::open_fifo_for_writing_after(fifo.string(), std::chrono::seconds(10));
  const auto start = std::chrono::steady_clock::now();
  Cli_run r = run(fifo.string() + " -o " + m.string());
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find(fifo.string() + ": is not a regular file (a FIFO)"), std::string::npos) << r.err;
  r = run("/dev/zero -o " + m.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("/dev/zero: is not a regular file (a character device)"), std::string::npos) << r.err;
}

TEST(quad_mesher_cli, usage_errors)
{
  auto m = scratch("u.msh");
  EXPECT_EQ(run(lake + " -o " + scratch("u.xyz").string()).status, 2);
  // bad usage is exit status 2, as the README says (CLI11's own codes were 105 and 106)
  EXPECT_EQ(run(lake + " -o " + m.string() + " --stop-after nonsense").status, 2);
  EXPECT_EQ(run(lake + " -o " + m.string() + " --kernel double").status, 2);
  EXPECT_EQ(run(lake).status, 2); // no output
  EXPECT_EQ(run(lake + " -o " + m.string() + " --max-size -1").status, 2);
  EXPECT_EQ(run(lake + " -o " + m.string() + " --max-size abc").status, 2);
  EXPECT_EQ(run(lake + " -o " + m.string() + " --curves spline --max-turning-angle 0.01").status, 2); // below 0.1
  // the spline options do nothing to polygon loops: refused, not ignored
  for(const char* option : { "--max-turning-angle 10", "--chord-error 0.1" })
    for(const char* curves : { "", " --curves polygon" }) {
      const Cli_run r = run(lake + " -o " + m.string() + " --stop-after quadtree" + curves + " " + option);
      EXPECT_EQ(r.status, 2) << option << curves;
      EXPECT_NE(r.err.find("quad-mesher: " + std::string(option).substr(0, std::string(option).find(' ')) +
                           " applies only with --curves spline"), std::string::npos) << r.err;
    }
  for(const char* size : { "nan", "inf", "-inf" }) { // not through to the library (exit 1 for nan)
    const Cli_run r = run(lake + " -o " + m.string() + " --min-size " + size);
    EXPECT_EQ(r.status, 2) << size;
    EXPECT_LT(r.err.size(), 400u) << r.err; // no 310-digit range
  }
  for(const char* cells : { "0", "-5", "1e6", "99999999999999999999" }) { // 1e20 was taken silently
    const Cli_run r = run(lake + " -o " + m.string() + " --max-cells " + cells);
    EXPECT_EQ(r.status, 2) << cells;
    EXPECT_NE(r.err.find("must be a whole number from 1 to"), std::string::npos) << r.err;
  }
  EXPECT_EQ(run(lake + " -o " + m.string() + " --no-such-option").status, 2);
  EXPECT_EQ(run("-o " + m.string()).status, 2); // no input
}

TEST(quad_mesher_cli, clearance_keeps_a_valid_core_mesh_inside_the_domain)
{
  auto msh = scratch("clear.msh"), json = scratch("clear.json");
  Cli_run r = run(lake + " --stop-after clearance --kernel " + kernel_name + " -o " + msh.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  EXPECT_GE(report["min_angle"].get<double>(), 45 - 1e-9);
  EXPECT_LE(report["max_angle"].get<double>(), 135 + 1e-9);
  const auto& removed = report["clearance_removed"];
  EXPECT_GT(removed["outside"].get<int>(), 0);
  EXPECT_GT(removed["crossing_boundary"].get<int>(), 0);
  EXPECT_GT(removed["near_boundary"].get<int>(), 0);
  EXPECT_GE(report["validity"]["boundary_loops"].get<int>(), 7); // the shore and 6 islands at least
  // a point cloud has no boundary to clear
  auto xy = scratch("clear.xy");
  std::ofstream(xy) << "0 0\n1 1\n";
  EXPECT_EQ(run(xy.string() + " --stop-after clearance -o " + msh.string()).status, 1);
}

TEST(quad_mesher_cli, spline_curves_are_decomposed)
{
  auto poly = scratch("blob.poly"), msh = scratch("blob.msh"), json = scratch("blob.json");
  {
    std::ofstream out(poly);
    out << "8 2 0 0\n";
    for(int k = 0; k < 8; ++k)
      out << k + 1 << " " << std::cos(k * M_PI / 4) * (k % 2 ? 1.0 : 1.4) << " " << std::sin(k * M_PI / 4) << "\n";
    out << "8 0\n";
    for(int k = 0; k < 8; ++k)
      out << k + 1 << " " << k + 1 << " " << (k + 1) % 8 + 1 << "\n";
    out << "0\n";
  }
  Cli_run r = run(poly.string() + " --curves spline --stop-after clearance -o " + msh.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["curves"], "spline");
  EXPECT_TRUE(report["seconds"].contains("curves"));
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  EXPECT_NE(run(poly.string() + " --curves bezier -o " + msh.string()).status, 0);
  r = run(poly.string() + " --curves spline --max-turning-angle 10 --chord-error 0.01 --stop-after clearance -o " + msh.string());
  EXPECT_EQ(r.status, 0) << r.err;
}

TEST(quad_mesher_cli, spline_errors_name_the_files_vertices_and_lines)
{
  // A simple control polygon with a narrow slit, 1-based after a comment: its spline crosses
  // itself. The message named the loop "starting at point 0" and the crossing segments by
  // their 0-based place in the decomposition ("segments 67 (vertices 67 ..."), with no line.
  auto slit = scratch("slit.poly"), msh = scratch("slit.msh");
  std::ofstream(slit) << "# slit\n8 2 0 0\n1 0 0\n2 10 0\n3 10 10\n4 5.1 10\n5 5.1 1\n6 4.9 1\n7 4.9 10\n8 0 10\n"
                         "8 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 7\n7 7 8\n8 8 1\n0\n";
  Cli_run r = run(slit.string() + " --curves spline --kernel " + kernel_name + " -o " + msh.string());
  EXPECT_EQ(r.status, 1);
  for(const char* part : { "slit.poly: outer loop of 8 control points starting at point 1 (line 3) (0, 0): ",
                           "segments on the spline from 4 (line 6) to 5 (line 7) (vertices new (",
                           "and on the spline from 6 (line 8) to 7 (line 9) (vertices new (" })
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err << "\nlacks: " << part;

  // The hole's spline bulges over the outer loop's straight side x = 0.8: the check of the
  // decomposed domain names the control points and spans as the file does too.
  auto bulge = scratch("bulge.poly");
  {
    std::ofstream out(bulge);
    out << "17 2 0 0\n1 0.8 0\n2 10 0\n3 10 10\n4 0.8 10\n";
    for(int k = 5; k <= 13; ++k) out << k << " 0.8 " << 14 - k << "\n";
    out << "14 1 1\n15 3 1\n16 3 3\n17 1 3\n17 0\n";
    for(int k = 1; k <= 13; ++k) out << k << " " << k << " " << k % 13 + 1 << "\n";
    for(int k = 14; k <= 17; ++k) out << k << " " << k << " " << (k - 13) % 4 + 14 << "\n";
    out << "1\n1 2 2\n";
  }
  r = run(bulge.string() + " --curves spline --kernel " + kernel_name + " -o " + msh.string());
  EXPECT_EQ(r.status, 1);
  for(const char* part : { "bulge.poly: after curve decomposition the boundary is not valid",
                           "segments on the spline from 11 (line 12) to 12 (line 13) (vertices 11 (line 12) (0.8, 3) and new (",
                           "and on the spline from 14 (line 15) to 17 (line 18) (vertices new (" })
    EXPECT_NE(r.err.find(part), std::string::npos) << r.err << "\nlacks: " << part;
}

TEST(quad_mesher_cli, point_cloud_points_become_vertices)
{
  auto xy = scratch("cloud.xy"), msh = scratch("cloud.msh"), json = scratch("cloud.json");
  {
    std::ofstream out(xy);
    out.precision(17);
    for(int i = 0; i < 200; ++i)
      out << std::fmod(i * 0.618033988749895, 1.0) << " " << std::fmod(i * 0.414213562373095, 1.0) << "\n";
  }
  Cli_run r = run(xy.string() + " -o " + msh.string() + " --kernel " + kernel_name + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["stop_after"], "points");
  EXPECT_EQ(report["points_as_vertices"].get<int>(), 200);
  EXPECT_LE(report["max_aspect_ratio_at_points"].get<double>(), 1.5);
  EXPECT_GE(report["min_angle"].get<double>(), 45 - 1e-9);
  EXPECT_LE(report["max_angle"].get<double>(), 135 + 1e-9);
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  // every input point is a node of the written mesh, digit for digit (the writer gives each
  // double its shortest round-trip text)
  std::string mesh = slurp(msh);
  std::ifstream in(xy);
  double x, y;
  int found = 0;
  auto shortest = [](double v) {
    char text[32];
    return std::string(text, std::to_chars(text, text + sizeof(text), v).ptr);
  };
  while(in >> x >> y)
    found += mesh.find("\n" + shortest(x) + " " + shortest(y) + " 0\n") != std::string::npos;
  EXPECT_EQ(found, 200);
}

// A point cloud in [0,1]^2 is meshed inside [-0.15, 1.15]^2 (its bounding box with a margin),
// around every point, at both stages: not over the root grid, [-0.125, 1.875]^2 there.
TEST(quad_mesher_cli, point_cloud_is_meshed_over_its_own_extent)
{
  auto xy = scratch("extent.xy"), off = scratch("extent.off");
  {
    std::ofstream out(xy);
    out.precision(17);
    out << "0 0\n1 1\n";
    for(int i = 1; i < 50; ++i)
      out << std::fmod(i * 0.618033988749895, 1.0) << " " << std::fmod(i * 0.414213562373095, 1.0) << "\n";
  }
  for(const char* stage : { "quadtree", "points" }) {
    SCOPED_TRACE(stage);
    Cli_run r = run(xy.string() + " --stop-after " + stage + " --kernel " + kernel_name + " -o " + off.string());
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream in(off);
    std::string header;
    std::size_t vertices = 0, faces = 0, edges = 0;
    in >> header >> vertices >> faces >> edges;
    ASSERT_EQ(header, "OFF");
    double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL, x, y, z;
    for(std::size_t v = 0; v < vertices && in >> x >> y >> z; ++v) {
      xmin = (std::min)(xmin, x);
      ymin = (std::min)(ymin, y);
      xmax = (std::max)(xmax, x);
      ymax = (std::max)(ymax, y);
    }
    ASSERT_TRUE(in) << "truncated OFF";
    EXPECT_GE(xmin, -0.15);
    EXPECT_GE(ymin, -0.15);
    EXPECT_LE(xmax, 1.15);
    EXPECT_LE(ymax, 1.15);
    // with a margin around the points
    EXPECT_LE(xmin, -0.1);
    EXPECT_LE(ymin, -0.1);
    EXPECT_GE(xmax, 1.1);
    EXPECT_GE(ymax, 1.1);
  }
  EXPECT_NE(run("--help").out.find("a point cloud (no segments) is meshed over its points' bounding box"),
            std::string::npos);
}

TEST(quad_mesher_cli, duplicate_points_are_named_or_merged_on_request)
{
  auto xy = scratch("dups.xy"), msh = scratch("dups.msh"), json = scratch("dups.json");
  std::ofstream(xy) << "0 0\n1 0.5\n0.25 0.75\n1 0.5\n0 0\n";
  Cli_run r = run(xy.string() + " -o " + msh.string());
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("dups.xy:4: duplicate point"), std::string::npos) << r.err;
  r = run(xy.string() + " --merge-duplicates -o " + msh.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.err.find("merged 2 duplicate"), std::string::npos) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["input"]["merged_duplicate_points"].get<int>(), 2);
  EXPECT_EQ(report["points_as_vertices"].get<int>(), 3);
}

// A WKT LINESTRING in a polygon is a crack: the mesh is the one of the same .poly, whose
// dangling segments the mesher keeps as mesh edges.
TEST(quad_mesher_cli, a_wkt_linestring_is_meshed_as_the_crack_of_the_same_poly)
{
  auto wkt = scratch("crack.wkt"), poly = scratch("crack.poly"), from_wkt = scratch("crack_wkt.off"),
       from_poly = scratch("crack_poly.off"), json = scratch("crack.json");
  std::ofstream(wkt) << "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0)),\nLINESTRING (1 1.5, 2 2, 3 2.2))\n";
  std::ofstream(poly) << "7 2 0 0\n1 0 0\n2 4 0\n3 4 4\n4 0 4\n5 1 1.5\n6 2 2\n7 3 2.2\n"
                         "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 5 6\n6 6 7\n0\n";
  Cli_run r = run(wkt.string() + " --kernel " + kernel_name + " -o " + from_wkt.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["input"]["points"].get<int>(), 7);
  EXPECT_EQ(report["input"]["segments"].get<int>(), 6);
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  r = run(poly.string() + " --kernel " + kernel_name + " -o " + from_poly.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(from_wkt), slurp(from_poly));
}

// Polygons of a MULTIPOLYGON sharing edges are regions of one domain: a 2 x 2 grid meshes as
// the .poly of its 9 points and 12 segments in the reader's order, one region a polygon; an
// island polygon filling a lake ring is a region, not a hole.
TEST(quad_mesher_cli, wkt_polygons_sharing_edges_mesh_as_regions_of_the_same_poly)
{
  auto wkt = scratch("grid.wkt"), poly = scratch("grid.poly"), from_wkt = scratch("grid_wkt.off"),
       from_poly = scratch("grid_poly.off"), json = scratch("grid.json");
  std::ofstream(wkt) << "MULTIPOLYGON (((0 0, 1 0, 1 1, 0 1, 0 0)), ((1 0, 2 0, 2 1, 1 1, 1 0)),\n"
                        "((0 1, 1 1, 1 2, 0 2, 0 1)), ((1 1, 2 1, 2 2, 1 2, 1 1)))\n";
  std::ofstream(poly) << "9 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 2 0\n6 2 1\n7 1 2\n8 0 2\n9 2 2\n12 0\n"
                         "1 1 2\n2 2 3\n3 3 4\n4 4 1\n5 2 5\n6 5 6\n7 6 3\n8 3 7\n9 7 8\n10 8 4\n11 6 9\n12 9 7\n0\n";
  Cli_run r = run(wkt.string() + " --kernel " + kernel_name + " -o " + from_wkt.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  auto report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["input"]["segments"].get<int>(), 12);
  EXPECT_EQ(report["regions"].size(), 4u);
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
  r = run(poly.string() + " --kernel " + kernel_name + " -o " + from_poly.string());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(slurp(from_wkt), slurp(from_poly));

  std::ofstream(wkt) << "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 3 1, 3 3, 1 3, 1 1)),\n"
                        "((1 1, 1 3, 3 3, 3 1, 1 1)))\n";
  r = run(wkt.string() + " --kernel " + kernel_name + " -o " + from_wkt.string() + " --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  report = nlohmann::json::parse(slurp(json));
  EXPECT_EQ(report["input"]["holes"].get<int>(), 0);
  EXPECT_EQ(report["regions"].size(), 2u);
  EXPECT_TRUE(report["validity"]["valid"].get<bool>());
}

TEST(quad_mesher_cli, boundary_layers_on_an_air_foil)
{
  const std::string naca = std::string(QM2_DATA_DIR) + "/naca0012/naca0012_sharp.poly";
  const auto m = scratch("bl.msh"), report = scratch("bl.json");
  const std::string layers = " --boundary-layers 5 --first-height 1e-3 --growth 1.2";
  Cli_run r = run(naca + " -o " + m.string() + " --report " + report.string() + layers + " --kernel " + kernel_name);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(slurp(report));
  ASSERT_TRUE(j.contains("boundary_layers"));
  const auto& w = j["boundary_layers"]["walls"][0];
  EXPECT_EQ(w["marker"].get<int>(), 2); // the air foil's loop, the hole
  EXPECT_NEAR(w["first_height"]["min"].get<double>(), 1e-3, 1e-5);
  EXPECT_NEAR(w["first_height"]["max"].get<double>(), 1e-3, 1e-5);
  EXPECT_GE(w["fans"].get<int>(), 1); // the trailing edge
  EXPECT_TRUE(j["validity"]["valid"].get<bool>());
  // usage: the layer options need each other; bad values and unknown walls are named
  EXPECT_EQ(run(naca + " -o " + m.string() + " --boundary-layers 5").status, 2);
  EXPECT_EQ(run(naca + " -o " + m.string() + " --first-height 1e-3").status, 2);
  EXPECT_EQ(run(naca + " -o " + m.string() + " --boundary-layers 0 --first-height 1e-3").status, 2);
  r = run(naca + " -o " + m.string() + " --boundary-layers 5 --first-height -1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("first boundary-layer height"), std::string::npos) << r.err;
  EXPECT_EQ(run(naca + " -o " + m.string() + layers + " --growth 0.5").status, 2);
  EXPECT_EQ(run(naca + " -o " + m.string() + layers + " --stop-after buffer1").status, 2);
  r = run(naca + " -o " + m.string() + layers + " --wall-markers 9");
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("no segment carries wall marker 9"), std::string::npos) << r.err;
}

TEST(quad_mesher_cli, help_lists_every_option_and_verbose_prints_stages)
{
  Cli_run r = run("--help");
  EXPECT_EQ(r.status, 0);
  for(const char* opt : { "--output", "--report", "--kernel", "--stop-after", "--max-size", "--min-size", "--max-depth", "--verbose" })
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  r = run(lake + " -o " + scratch("v.off").string() + " --verbose");
  EXPECT_EQ(r.status, 0);
  for(const char* stage : { "stage refine:", "stage balance:", "stage refinement_templates:", "stage points:" })
    EXPECT_NE(r.err.find(stage), std::string::npos) << stage;
}

// -v prints each refinement round, as it ends (Lake Superior takes four)
TEST(quad_mesher_cli, verbose_prints_each_round)
{
  auto json = scratch("rounds.json");
  Cli_run r = run(lake + " -o " + scratch("rounds.off").string() + " --verbose --report " + json.string());
  ASSERT_EQ(r.status, 0) << r.err;
  const int rounds = nlohmann::json::parse(slurp(json))["buffer"]["refinement_rounds"].get<int>() + 1;
  ASSERT_GE(rounds, 2);
  for(int k = 1; k <= rounds; ++k) {
    const std::size_t at = r.err.find("round " + std::to_string(k) + ": ");
    ASSERT_NE(at, std::string::npos) << k << "\n" << r.err;
    const std::string line = r.err.substr(at, r.err.find('\n', at) - at);
    for(const char* part : { " quads, ", "valid, ", " buffer quads not convex, ", " with an unforced angle out (",
                             " core, ", " first layer, ", " second layer), ", " refinement requests, " })
      EXPECT_NE(line.find(part), std::string::npos) << part << " in " << line;
    EXPECT_EQ(line.substr(line.size() - 2), " s") << line;
  }
  EXPECT_EQ(r.err.find("round " + std::to_string(rounds + 1) + ": "), std::string::npos) << r.err;
  // the report lists the same rounds, each with its unforced angles out by layer (the first
  // round's are the stages' own, Lemmas 3 and 4 before any refinement for angles)
  const auto listed = nlohmann::json::parse(slurp(json))["rounds"];
  ASSERT_EQ(int(listed.size()), rounds);
  for(int k = 0; k < rounds; ++k) {
    const auto& f = listed[std::size_t(k)];
    EXPECT_EQ(f["round"].get<int>(), k + 1);
    const auto& layers = f["quads_outside_45_135_not_forced_by_layer"];
    EXPECT_EQ(layers["core"].get<int>() + layers["first_layer"].get<int>() + layers["second_layer"].get<int>(),
              f["quads_outside_45_135_not_forced"].get<int>());
    EXPECT_NE(r.err.find("round " + std::to_string(k + 1) + ": " + std::to_string(f["quads"].get<int>()) + " quads"),
              std::string::npos);
  }
  EXPECT_GT(listed[0]["quads_outside_45_135_not_forced"].get<int>(), 0); // why Lake Superior takes rounds
  EXPECT_EQ(listed[std::size_t(rounds - 1)]["quads_outside_45_135_not_forced"].get<int>(), 0);
}

// An L with arms 0.13 wide turned 45.37 degrees: its arms' ends need a refinement round
// (cells at depth 7). At most 6 levels deep the rounds cannot refine there; the warning and
// the report say so, and say nothing when the rounds leave no quad out.
TEST(quad_mesher_cli, the_warning_says_why_the_rounds_left_angles_out)
{
  const auto poly = scratch("ell.poly");
  std::ofstream(poly) << "6 2 0 0\n1 0 0\n2 0.70252577269438166 0.7116583019259749\n"
                         "3 0.61001019344400498 0.80298665237624456\n4 -0.001187228800107118 0.18384392970064634\n"
                         "5 -0.62032995147570524 0.79504135194475833\n6 -0.7116583019259749 0.70252577269438166\n"
                         "6 0\n1 1 2\n2 2 3\n3 3 4\n4 4 5\n5 5 6\n6 6 1\n0\n";
  const auto json = scratch("ell.json");
  // written with unforced angles out: exit status 4; stopped before the buffer stages, which
  // alone promise the bound, 0
  Cli_run shallow = run(poly.string() + " -o " + scratch("ell.off").string() + " --max-depth 6 --report " + json.string());
  ASSERT_EQ(shallow.status, 4) << shallow.err;
  EXPECT_GT(std::filesystem::file_size(scratch("ell.off")), 100u);
  EXPECT_EQ(run(poly.string() + " -o " + scratch("ell.off").string() + " --max-depth 6 --stop-after templates").status, 0);
  EXPECT_NE(shallow.err.find("that no input corner forces: refining there needs cells finer than the quadtree may "
                             "make (the maximum depth 6)"),
            std::string::npos)
    << shallow.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(json))["buffer"]["rounds_end"], "finest cells");
  Cli_run deep = run(poly.string() + " -o " + scratch("ell.off").string() + " --report " + json.string());
  ASSERT_EQ(deep.status, 0) << deep.err;
  EXPECT_EQ(deep.err.find("warning"), std::string::npos) << deep.err;
  EXPECT_EQ(nlohmann::json::parse(slurp(json))["buffer"]["rounds_end"], "none");
}

} // namespace qm2_test_cli

#endif // QM2_CLI_PATH
