// SPDX-License-Identifier: MIT
// Rasterisation speed: a jittered-grid TIN of about 10^6 vertices (S-JTSK offsets) to a
// 2000 x 2000 DEM in memory, all threads and one thread; linear, cubic (gradient estimate
// included) and natural neighbour, and the cubic gradient estimate alone.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dtm/algo/gradients.hpp"
#include "dtm/algo/rasterize.hpp"
#include "jittered_grid_tin.hpp"

namespace {

dtm::Tin bench_tin(int n) { return dtm::bench::jittered_grid_tin(n, 42); }

const dtm::Tin& shared_tin() {
    static const dtm::Tin tin = bench_tin(1000);
    return tin;
}

void rasterize_2000(benchmark::State& state, dtm::Interpolation method) {
    const dtm::Tin& tin = shared_tin();
    const dtm::GridSpec spec{
        .xmin = -750'000.0, .ymax = -1'048'000.0, .cell = 1.0, .cols = 2000, .rows = 2000};
    const auto threads = static_cast<unsigned>(state.range(0));
    for (auto _ : state) {
        const dtm::Grid grid = dtm::rasterize(
            tin, spec,
            {.threads = threads, .interpolation = method, .gradients = {.threads = threads}});
        benchmark::DoNotOptimize(grid.values.data());
    }
    state.SetItemsProcessed(state.iterations() * 4'000'000);
}

void BM_Rasterize2000(benchmark::State& state) {
    rasterize_2000(state, dtm::Interpolation::linear);
}
BENCHMARK(BM_Rasterize2000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RasterizeCubic2000(benchmark::State& state) {
    rasterize_2000(state, dtm::Interpolation::cubic);
}
BENCHMARK(BM_RasterizeCubic2000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RasterizeNatural2000(benchmark::State& state) {
    rasterize_2000(state, dtm::Interpolation::natural);
}
BENCHMARK(BM_RasterizeNatural2000)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Gradients(benchmark::State& state) {
    const dtm::Tin& tin = shared_tin();
    for (auto _ : state) {
        const dtm::TinGradients g =
            dtm::estimate_gradients(tin, {.threads = static_cast<unsigned>(state.range(0))});
        benchmark::DoNotOptimize(g.gradient.data());
        state.counters["iterations"] = g.iterations;
    }
}
BENCHMARK(BM_Gradients)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
