// SPDX-License-Identifier: MIT
// Contouring speed: a jittered-grid TIN of about 10^6 vertices with 120 m of relief, 1 m
// interval, lines collected by a counting sink (no file I/O), all threads and one thread.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "dtm/algo/contour.hpp"

namespace {

dtm::Tin contour_bench_tin(int n) {
    std::mt19937 rng(7);
    const double h = 2000.0 / (n - 1);
    std::uniform_real_distribution<double> jitter(-0.2 * h, 0.2 * h);
    dtm::Tin tin;
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = i * h + (i > 0 && i < n - 1 ? jitter(rng) : 0.0);
            const double y = j * h + (j > 0 && j < n - 1 ? jitter(rng) : 0.0);
            tin.vertices.push_back(
                {-750'000.0 + x, -1'050'000.0 + y,
                 300.0 + 40.0 * std::sin(x / 300.0) * std::cos(y / 250.0) + 0.02 * x});
        }
    }
    const auto id = [n](int i, int j) { return static_cast<std::uint32_t>(j * n + i); };
    const auto tri = [n](int i, int j, int k) {
        return static_cast<std::uint32_t>(2 * (j * (n - 1) + i) + k);
    };
    for (int j = 0; j + 1 < n; ++j) {
        for (int i = 0; i + 1 < n; ++i) {
            dtm::Triangle a{{id(i, j), id(i + 1, j), id(i + 1, j + 1)}, {}};
            dtm::Triangle b{{id(i, j), id(i + 1, j + 1), id(i, j + 1)}, {}};
            a.n = {i + 2 < n ? tri(i + 1, j, 1) : dtm::no_triangle, tri(i, j, 1),
                   j > 0 ? tri(i, j - 1, 1) : dtm::no_triangle};
            b.n = {j + 2 < n ? tri(i, j + 1, 0) : dtm::no_triangle,
                   i > 0 ? tri(i - 1, j, 0) : dtm::no_triangle, tri(i, j, 0)};
            tin.triangles.push_back(a);
            tin.triangles.push_back(b);
        }
    }
    return tin;
}

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
