// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Real domains (paper §5, §6): the whole run, refinement rounds included, on the shared cases
// of `../shared/data` beside the repository (a case whose file is missing is skipped with a
// message). Counters: quads, refinement rounds, ns per quad.
//
//   bench_cases --benchmark_out=cases.json --benchmark_out_format=json

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/IO/read_domain.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <benchmark/benchmark.h>

#include "bench_run.h"

#include <string>

namespace {

template <class K>
void BM_case(benchmark::State& state, const std::string& relative)
{
  CGAL::Quad_mesher_2::Domain_2<K> domain;
  std::string error;
  if(!CGAL::Quad_mesher_2::IO::read_domain(std::string(QM2_SHARED_DATA_DIR) + "/" + relative, domain, &error)) {
    state.SkipWithError(error.c_str());
    return;
  }
  run_mesher(state, CGAL::Quad_mesher_2::Stage::BUFFER2,
             [&] { return CGAL::Quad_mesher_2::Quadtree_mesher_2<K>(domain); });
}

void BM_epick(benchmark::State& state, const std::string& c) { BM_case<CGAL::Epick>(state, c); }
void BM_epeck(benchmark::State& state, const std::string& c) { BM_case<CGAL::Epeck>(state, c); }

} // namespace

#define QM2_CASE(name, file)                                                                        \
  BENCHMARK_CAPTURE(BM_epick, name, std::string(file))->Unit(benchmark::kMillisecond)->UseRealTime(); \
  BENCHMARK_CAPTURE(BM_epeck, name, std::string(file))->Unit(benchmark::kMillisecond)->UseRealTime()

QM2_CASE(triangle_A, "triangle_A/triangle_A.poly");
QM2_CASE(naca0012, "naca0012/naca0012.poly");
QM2_CASE(guitar, "guitar/guitar.poly");
QM2_CASE(river, "river/river.poly");
QM2_CASE(lake_superior, "lake_superior/lake_superior.poly");
QM2_CASE(bird, "bird/bird.poly");
QM2_CASE(airfoil_30p30n, "airfoil_30p30n/airfoil_30p30n.poly");
QM2_CASE(greenland, "greenland/greenland.poly");

BENCHMARK_MAIN();
