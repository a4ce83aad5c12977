// Copyright (c) 2026 Quad_mesher_2 contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s): Quad_mesher_2 developers
//
// The timed loop the domain benchmarks share: a fresh mesher per iteration, run up to a stage,
// and the counters quads, refinement rounds and ns per quad.

#ifndef QM2_BENCH_RUN_H
#define QM2_BENCH_RUN_H

#include <CGAL/Quad_mesher_2/Quadtree_mesher_2.h>

#include <benchmark/benchmark.h>

#include <cstddef>

// `make_mesher()` returns a new `Quadtree_mesher_2`
template <class Make_mesher>
void run_mesher(benchmark::State& state, CGAL::Quad_mesher_2::Stage last, Make_mesher make_mesher)
{
  std::size_t quads = 0;
  int rounds = 0;
  for(auto _ : state) {
    auto mesher = make_mesher();
    auto mesh = mesher.run(last);
    quads = mesh.quads.size();
    rounds = mesher.rounds();
    benchmark::DoNotOptimize(mesh.points.data());
  }
  state.counters["quads"] = double(quads);
  state.counters["rounds"] = double(rounds);
  state.counters["ns_per_quad"] =
    benchmark::Counter(double(quads) * state.iterations() * 1e-9,
                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

#endif // QM2_BENCH_RUN_H
