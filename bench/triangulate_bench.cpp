// SPDX-License-Identifier: MIT
// Google Benchmark of the triangulation kernel (one thread and all threads), without I/O.
// The comparison with CGAL in the same run is bench/compare_cgal.sh.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dtm/algo/triangulate.hpp"

namespace {

dtm::TerrainInput uniform(std::size_t n, bool breaklines) {
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(0.0, 10'000.0);
    dtm::TerrainInput input;
    input.points.resize(n);
    for (auto& p : input.points) {
        const double x = u(rng), y = u(rng);
        p = {-750'000.0 + x, -1'050'000.0 + y, 300.0 + 0.01 * x};
    }
    if (breaklines) {  // parallel zig-zag lines in separate bands: never cross
        const std::size_t lines = 500;
        for (std::size_t k = 0; k < lines; ++k) {
            dtm::Polyline line;
            const double y = 10'000.0 * (static_cast<double>(k) + 0.5) / lines;
            for (double x = 1.0; x < 9'999.0; x += 10.0) {
                line.points.push_back(
                    {-750'000.0 + x, -1'050'000.0 + y + 3.0 * std::sin(x), 300.0});
            }
            input.breaklines.push_back(std::move(line));
        }
    }
    return input;
}

void run(benchmark::State& state, bool breaklines, unsigned threads) {
    const dtm::TerrainInput input = uniform(static_cast<std::size_t>(state.range(0)), breaklines);
    dtm::TriangulateOptions options;
    options.threads = threads;
    for (auto _ : state) {
        auto result = dtm::triangulate(input, options);
        benchmark::DoNotOptimize(result.tin.triangles.data());
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

void BM_Delaunay1Thread(benchmark::State& s) { run(s, false, 1); }
void BM_Delaunay2Threads(benchmark::State& s) { run(s, false, 2); }
void BM_Breaklines1Thread(benchmark::State& s) { run(s, true, 1); }

}  // namespace

BENCHMARK(BM_Delaunay1Thread)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Delaunay2Threads)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Breaklines1Thread)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
