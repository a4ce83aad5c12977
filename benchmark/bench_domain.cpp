// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Smooth domains (paper §4): a disc with an off-centre hole, polygons of 256 and 128 vertices,
// meshed with a maximum cell size of 2^-k of the radius, stage by stage: up to the clearance,
// up to the templates, the first and the second buffer layer (the whole pipeline, refinement
// rounds included), and the speed target: about 10^6 quads through the second layer.
// Counters: quads, refinement rounds, ns per quad.
//
//   bench_domain --benchmark_out=domain.json --benchmark_out_format=json

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <benchmark/benchmark.h>

#include "bench_run.h"

#include <cmath>

namespace {

// of radius `scale`
template <class K>
CGAL::Quad_mesher_2::Domain_2<K> disc_with_hole(double scale = 1)
{
  CGAL::Quad_mesher_2::Domain_2<K> d;
  auto loop = [&](double cx, double cy, double r, std::size_t n) {
    const std::size_t base = d.points.size();
    for(std::size_t i = 0; i < n; ++i) {
      const double t = 2 * 3.14159265358979323846 * double(i) / double(n);
      d.points.emplace_back(scale * (cx + r * std::cos(t)), scale * (cy + r * std::sin(t)));
      d.segments.push_back({ base + i, base + (i + 1) % n });
    }
  };
  loop(0, 0, 1, 256);
  loop(0.3, 0.1, 0.3, 128);
  d.holes.emplace_back(scale * 0.3, scale * 0.1);
  return d;
}

template <class K>
void BM_domain(benchmark::State& state, CGAL::Quad_mesher_2::Stage last, double scale)
{
  const auto domain = disc_with_hole<K>(scale);
  const CGAL::Quad_mesher_2::Mesh_criteria_2<K> criteria(std::ldexp(1.0, -int(state.range(0))));
  run_mesher(state, last, [&] { return CGAL::Quad_mesher_2::Quadtree_mesher_2<K>(domain, criteria); });
}

void BM_epick(benchmark::State& state, CGAL::Quad_mesher_2::Stage last, double scale = 1)
{
  BM_domain<CGAL::Epick>(state, last, scale);
}
void BM_epeck(benchmark::State& state, CGAL::Quad_mesher_2::Stage last, double scale = 1)
{
  BM_domain<CGAL::Epeck>(state, last, scale);
}

using CGAL::Quad_mesher_2::Stage;

} // namespace

// max cell size 2^-5 .. 2^-9 of the radius: about 10^4 to 10^6 quads
BENCHMARK_CAPTURE(BM_epick, clearance, Stage::CLEARANCE)
  ->DenseRange(5, 9, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_epick, templates, Stage::TEMPLATES)
  ->DenseRange(5, 9, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_epick, buffer1, Stage::BUFFER1)
  ->DenseRange(5, 9, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_epick, buffer2, Stage::BUFFER2)
  ->DenseRange(5, 9, 2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_epeck, buffer2, Stage::BUFFER2)
  ->DenseRange(5, 9, 2)->Unit(benchmark::kMillisecond)->UseRealTime();

// the target, 10^6 quads in 2 s: cells are powers of two, so the disc grows instead,
// by 1.18 (1.39 times the area) at 2^-9 for 1.05·10^6 quads
BENCHMARK_CAPTURE(BM_epick, million, Stage::BUFFER2, 1.18)
  ->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_epeck, million, Stage::BUFFER2, 1.18)
  ->Arg(9)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
