// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// Stage 1 (paper §4.2, Fig. 3(b)): refine by point spacing, strong balance, 2-refinement
// templates. Random points (fixed seed) in the unit square; the sweep over the number of
// points gives meshes from about 10^4 to 10^7 quads. Counters: quads, ns per quad, quadtree
// depth, and the process's peak resident memory per quad.
//
//   bench_quadtree --benchmark_out=quadtree.json --benchmark_out_format=json

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <benchmark/benchmark.h>

#include <random>
#include <sys/resource.h>

namespace {

template <class K>
CGAL::Quad_mesher_2::Domain_2<K> random_points(std::size_t n)
{
  CGAL::Quad_mesher_2::Domain_2<K> domain;
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(0, 1);
  domain.points.reserve(n);
  for(std::size_t i = 0; i < n; ++i)
    domain.points.emplace_back(u(rng), u(rng));
  return domain;
}

double peak_rss_bytes()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) * 1024.0;
}

template <class K>
void BM_quadtree_and_templates(benchmark::State& state)
{
  const auto domain = random_points<K>(std::size_t(state.range(0)));
  std::size_t quads = 0;
  int depth = 0;
  CGAL::Quad_mesher_2::Mesh_criteria_2<K> criteria;
  criteria.set_points_as_vertices(false); // stage 1 alone
  for(auto _ : state) {
    CGAL::Quad_mesher_2::Quadtree_mesher_2<K> mesher(domain, criteria);
    auto mesh = mesher.run(CGAL::Quad_mesher_2::Stage::QUADTREE);
    quads = mesh.quads.size();
    depth = mesher.quadtree().depth();
    benchmark::DoNotOptimize(mesh.points.data());
  }
  state.counters["quads"] = double(quads);
  state.counters["depth"] = depth;
  state.counters["ns_per_quad"] =
    benchmark::Counter(double(quads) * state.iterations() * 1e-9,
                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["peak_rss_bytes_per_quad"] = peak_rss_bytes() / double(quads);
}

} // namespace

// Sizes grow so that peak RSS (monotone over the process) belongs to the current size.
BENCHMARK_TEMPLATE(BM_quadtree_and_templates, CGAL::Epick)
  ->RangeMultiplier(4)->Range(1 << 10, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_TEMPLATE(BM_quadtree_and_templates, CGAL::Epeck)
  ->RangeMultiplier(4)->Range(1 << 10, 1 << 20)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
