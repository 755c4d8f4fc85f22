// SPDX-License-Identifier: MIT
// Contouring speed: a jittered-grid TIN of about 10^6 vertices with 120 m of relief, 1 m
// interval, lines collected by a counting sink (no file I/O), all threads and one thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dtm/algo/contour.hpp"
#include "jittered_grid_tin.hpp"

namespace {

dtm::Tin contour_bench_tin(int n) { return dtm::bench::jittered_grid_tin(n, 7); }

class CountingSink final : public dtm::ContourSink {
public:
    void add(const dtm::ContourLevel&, std::span<const dtm::Point3> line, bool) override {
        points += line.size();
        ++lines;
    }
    std::size_t points = 0;
    std::size_t lines = 0;
};

void BM_Contour1m(benchmark::State& state) {
    static const dtm::Tin tin = contour_bench_tin(1000);
    for (auto _ : state) {
        CountingSink sink;
        dtm::contour(tin, {.interval = 1.0, .threads = static_cast<unsigned>(state.range(0))},
                     sink);
        state.counters["lines"] = static_cast<double>(sink.lines);
        state.counters["points"] = static_cast<double>(sink.points);
    }
}
BENCHMARK(BM_Contour1m)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
