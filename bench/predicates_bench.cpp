// SPDX-License-Identifier: MIT
// Cost of dtm::geom::orient2d / incircle on the filtered fast path (random points at S-JTSK
// magnitude) and on the adaptive path (exactly collinear / cocircular points, nearly
// degenerate points), next to the plain non-robust determinant for reference.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/geom/predicates.hpp"

namespace {

using dtm::Point2;

constexpr double x0 = -750000.0;
constexpr double y0 = -1050000.0;
constexpr std::size_t count = 4096;  // points per pattern; fits in L1/L2

std::vector<Point2> random_points() {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::vector<Point2> p(count + 3);
    for (auto& q : p) {
        q = {x0 + u(rng), y0 + u(rng)};
    }
    return p;
}

/// Consecutive triples exactly collinear (binary-fraction grid at S-JTSK size).
std::vector<Point2> collinear_points() {
    std::vector<Point2> p(count + 3);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double t = static_cast<double>(i % 64) * 0.125;
        p[i] = {x0 + 3.0 * t, y0 + 4.0 * t};
    }
    return p;
}

/// Consecutive quadruples exactly cocircular: (5,0), (3,4), (-4,3), (0,-5) around moving centres.
std::vector<Point2> cocircular_points() {
    const Point2 offsets[4] = {{5, 0}, {3, 4}, {-4, 3}, {0, -5}};
    std::vector<Point2> p(count + 3);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double c = static_cast<double>(i / 4) * 0.25;
        p[i] = {x0 + c + offsets[i % 4].x, y0 + c + offsets[i % 4].y};
    }
    return p;
}

/// Millimetre grid: nearly (not exactly) collinear triples, no exact zeros.
std::vector<Point2> millimetre_points() {
    std::vector<Point2> p(count + 3);
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double k = static_cast<double>(i % 97);
        p[i] = {x0 + 0.001 * k, y0 + 0.003 * k};
    }
    return p;
}

int naive_orient(const Point2& a, const Point2& b, const Point2& c) {
    const double det = (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
    return (det > 0) - (det < 0);
}

template <class F>
void run_triples(benchmark::State& state, const std::vector<Point2>& p, F f) {
    for (auto _ : state) {
        int acc = 0;
        for (std::size_t i = 0; i < count; ++i) {
            acc += f(p[i], p[i + 1], p[i + 2]);
        }
        benchmark::DoNotOptimize(acc);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * count));
}

template <class F>
void run_quads(benchmark::State& state, const std::vector<Point2>& p, std::size_t stride, F f) {
    for (auto _ : state) {
        int acc = 0;
        for (std::size_t i = 0; i < count; i += stride) {
            acc += f(p[i], p[i + 1], p[i + 2], p[i + 3]);
        }
        benchmark::DoNotOptimize(acc);
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * (count / stride)));
}

auto orient = [](const Point2& a, const Point2& b, const Point2& c) {
    return dtm::geom::orient2d(a, b, c);
};
auto in_circle = [](const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
    return dtm::geom::incircle(a, b, c, d);
};

void BM_Orient2dNaiveRandom(benchmark::State& s) { run_triples(s, random_points(), naive_orient); }
void BM_Orient2dRandom(benchmark::State& s) { run_triples(s, random_points(), orient); }
void BM_Orient2dCollinear(benchmark::State& s) { run_triples(s, collinear_points(), orient); }
void BM_Orient2dMillimetre(benchmark::State& s) { run_triples(s, millimetre_points(), orient); }
void BM_IncircleRandom(benchmark::State& s) { run_quads(s, random_points(), 1, in_circle); }
void BM_IncircleCocircular(benchmark::State& s) { run_quads(s, cocircular_points(), 4, in_circle); }
void BM_IncircleMillimetre(benchmark::State& s) { run_quads(s, millimetre_points(), 1, in_circle); }

BENCHMARK(BM_Orient2dNaiveRandom);
BENCHMARK(BM_Orient2dRandom);
BENCHMARK(BM_Orient2dCollinear);
BENCHMARK(BM_Orient2dMillimetre);
BENCHMARK(BM_IncircleRandom);
BENCHMARK(BM_IncircleCocircular);
BENCHMARK(BM_IncircleMillimetre);

}  // namespace
