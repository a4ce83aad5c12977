// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Point clouds (paper §3): the whole run, from the points to a mesh with every point a
// vertex. Random points (fixed seed) in the unit square, 10^3 to 10^5 of them. Counters:
// quads, quads per point, ns per point.
//
//   bench_points --benchmark_out=points.json --benchmark_out_format=json

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <benchmark/benchmark.h>

#include <random>

namespace {

template <class K>
void BM_point_cloud(benchmark::State& state)
{
  CGAL::Quad_mesher_2::Domain_2<K> domain;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  for(std::int64_t i = 0; i < state.range(0); ++i)
    domain.points.emplace_back(u(rng), u(rng));
  std::size_t quads = 0;
  for(auto _ : state) {
    CGAL::Quad_mesher_2::Quadtree_mesher_2<K> mesher(domain);
    auto mesh = mesher.run();
    quads = mesh.quads.size();
    benchmark::DoNotOptimize(mesh.points.data());
  }
  state.counters["quads"] = double(quads);
  state.counters["quads_per_point"] = double(quads) / double(state.range(0));
  state.counters["ns_per_point"] =
    benchmark::Counter(double(state.range(0)) * state.iterations() * 1e-9,
                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

BENCHMARK_TEMPLATE(BM_point_cloud, CGAL::Epick)
  ->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_point_cloud, CGAL::Epeck)
  ->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
