// SPDX-License-Identifier: MIT
// Rasterisation speed: a jittered-grid TIN of about 10^6 vertices (S-JTSK offsets) to a
// 2000 x 2000 DEM in memory, all threads and one thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dtm/algo/rasterize.hpp"
#include "jittered_grid_tin.hpp"

namespace {

dtm::Tin bench_tin(int n) { return dtm::bench::jittered_grid_tin(n, 42); }

const dtm::Tin& shared_tin() {
    static const dtm::Tin tin = bench_tin(1000);
    return tin;
}

void BM_Rasterize2000(benchmark::State& state) {
    const dtm::Tin& tin = shared_tin();
    const dtm::GridSpec spec{
        .xmin = -750'000.0, .ymax = -1'048'000.0, .cell = 1.0, .cols = 2000, .rows = 2000};
    for (auto _ : state) {
        const dtm::Grid grid =
            dtm::rasterize(tin, spec, {.threads = static_cast<unsigned>(state.range(0))});
        benchmark::DoNotOptimize(grid.values.data());
    }
    state.SetItemsProcessed(state.iterations() * 4'000'000);
}
BENCHMARK(BM_Rasterize2000)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
