// SPDX-License-Identifier: MIT
// Volume between two TINs of about 10^6 triangles each (S-JTSK offsets): two jittered grids of
// different seeds (all threads and one thread), and two Delaunay TINs of independent uniform
// random points (the overlay's worst usual case: about 5.7 pieces per triangle). The issue's
// target: under 2 s on 2 cores. bench/compare_volume.sh measures the whole `dtm volume` run and
// its peak memory.
#include <benchmark/benchmark.h>

#include <random>

#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/volume.hpp"
#include "jittered_grid_tin.hpp"

namespace {

const dtm::Tin& grid_tin(unsigned seed) {
    static const dtm::Tin a = dtm::bench::jittered_grid_tin(708, 1);
    static const dtm::Tin b = dtm::bench::jittered_grid_tin(708, 2);
    return seed == 1 ? a : b;
}

dtm::Tin random_tin(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 2000.0);
    dtm::TerrainInput in;
    for (const auto& [x, y] :
         {std::pair{0.0, 0.0}, {2000.0, 0.0}, {2000.0, 2000.0}, {0.0, 2000.0}}) {
        in.points.push_back({-750'000.0 + x, -1'050'000.0 + y, 300.0});
    }
    for (int i = 0; i < 500'000; ++i) {
        const double x = u(rng);
        const double y = u(rng);
        in.points.push_back(
            {-750'000.0 + x, -1'050'000.0 + y,
             300.0 + 0.01 * x + (seed == 1 ? 1.0 : -1.0) * 0.5 * std::sin(y / 50.0)});
    }
    return dtm::triangulate(in).tin;
}

const dtm::Tin& uniform_tin(unsigned seed) {
    static const dtm::Tin a = random_tin(1);
    static const dtm::Tin b = random_tin(2);
    return seed == 1 ? a : b;
}

void BM_VolumeJitteredGrids(benchmark::State& state) {
    const dtm::Tin& a = grid_tin(1);
    const dtm::Tin& b = grid_tin(2);
    for (auto _ : state) {
        const auto r = dtm::volume(a, b, {.threads = static_cast<unsigned>(state.range(0))});
        benchmark::DoNotOptimize(r.fill);
        state.counters["pieces"] = static_cast<double>(r.pieces);
    }
    state.counters["triangles"] = static_cast<double>(a.triangles.size());
}
BENCHMARK(BM_VolumeJitteredGrids)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_VolumeUniformDelaunay(benchmark::State& state) {
    const dtm::Tin& a = uniform_tin(1);
    const dtm::Tin& b = uniform_tin(2);
    for (auto _ : state) {
        const auto r = dtm::volume(a, b, {.threads = static_cast<unsigned>(state.range(0))});
        benchmark::DoNotOptimize(r.fill);
        state.counters["pieces"] = static_cast<double>(r.pieces);
    }
    state.counters["triangles"] = static_cast<double>(a.triangles.size());
}
BENCHMARK(BM_VolumeUniformDelaunay)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
