// SPDX-License-Identifier: MIT
// Contour lines of a TIN.
//
// 1. Levels: base + k * interval (or a fixed list) that cut the TIN's height range, with the
//    convention that a vertex on a level counts as slightly above it (zmin < level <= zmax).
// 2. Bucketing (sequential, O(triangles + crossings)): each triangle is crossed by the levels
//    with tzmin < level <= tzmax, found by binary search; a CSR array lists, per level, the
//    crossed triangles in ascending order (this fixes the output order: deterministic).
// 3. Tracing (parallel over levels, tbb::parallel_pipeline): per level, chains are walked through
//    the triangle adjacency (see contour_trace.cpp), split where a doubled piece was marked,
//    optionally smoothed inside their triangle strip (contour_smooth.cpp), and cleaned of
//    zero-length parts.
// 4. Output (serial, in level order): lines go to the ContourSink while later levels are still
//    being traced, so memory holds only a few levels at once.
// On the cubic and natural surfaces the same tracing runs on a refinement of the TIN that
// samples the surface (contour_refined.cpp).
//
// Contours of different levels never meet: on the linear surface of a triangle the level sets
// are disjoint parallel segments, and every output point is computed from its edge alone.
#include "dtm/algo/contour.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "algo/detail/contour_refined.hpp"
#include "algo/detail/contour_smooth.hpp"
#include "algo/detail/contour_trace.hpp"
#include "dtm/core/error.hpp"

namespace dtm {
namespace {

bool is_index(long long number, std::size_t every) {
    if (every == 0) {
        return false;
    }
    const auto k = static_cast<long long>(every);
    return ((number % k) + k) % k == 0;
}

std::vector<ContourLevel> fixed_levels(double zmin, double zmax, const ContourOptions& options) {
    std::vector<double> values = options.fixed_levels;
    std::sort(values.begin(), values.end());
    values.erase(std::unique(values.begin(), values.end()), values.end());
    std::vector<ContourLevel> levels;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) {
            throw UsageError("contour: level " + std::to_string(values[i]) + " is not finite");
        }
        if (zmin < values[i] && values[i] <= zmax) {
            const auto number = static_cast<long long>(i);
            levels.push_back({values[i], number, is_index(number, options.index_every)});
        }
    }
    return levels;
}

/// The levels [first, last) of a level list.
struct LevelRange {
    std::size_t first = 0, last = 0;
};

/// Per level, the crossed triangles (CSR).
struct LevelBuckets {
    std::vector<std::size_t> offsets;
    std::vector<TriangleIndex> triangles;
};

LevelBuckets bucket_levels(const Tin& tin, const std::vector<double>& values) {
    // Per vertex, the number of levels at or below its height (levels strictly above it start
    // there); a triangle is crossed by the levels [min, max) of its three vertex numbers, since
    // upper_bound is monotone. Both passes run in parallel; then a counting sort per level.
    std::vector<std::uint32_t> vertex_level(tin.vertices.size());
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, tin.vertices.size(), 1 << 14),
        [&](const tbb::blocked_range<std::size_t>& r) {
            for (std::size_t v = r.begin(); v != r.end(); ++v) {
                vertex_level[v] = static_cast<std::uint32_t>(
                    std::upper_bound(values.begin(), values.end(), tin.vertices[v].z) -
                    values.begin());
            }
        });
    std::vector<std::array<std::uint32_t, 2>> ranges(tin.triangles.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t i = r.begin(); i != r.end(); ++i) {
                              const auto& v = tin.triangles[i].v;
                              const std::uint32_t a = vertex_level[v[0]], b = vertex_level[v[1]],
                                                  c = vertex_level[v[2]];
                              ranges[i] = {std::min({a, b, c}), std::max({a, b, c})};
                          }
                      });
    LevelBuckets buckets;
    buckets.offsets.assign(values.size() + 1, 0);
    for (const auto& [lo, hi] : ranges) {
        for (std::uint32_t k = lo; k < hi; ++k) {
            ++buckets.offsets[k + 1];
        }
    }
    for (std::size_t k = 0; k < values.size(); ++k) {
        buckets.offsets[k + 1] += buckets.offsets[k];
    }
    buckets.triangles.resize(buckets.offsets.back());
    std::vector<std::size_t> fill(buckets.offsets.begin(), buckets.offsets.end() - 1);
    for (std::size_t i = 0; i < ranges.size(); ++i) {
        for (std::uint32_t k = ranges[i][0]; k < ranges[i][1]; ++k) {
            buckets.triangles[fill[k]++] = static_cast<TriangleIndex>(i);
        }
    }
    return buckets;
}

/// Drops consecutive equal points; returns false when fewer than two distinct points remain.
bool clean_line(std::vector<Point3>& line, bool& closed) {
    line.erase(std::unique(line.begin(), line.end()), line.end());
    if (closed && line.size() < 4) {
        if (line.size() == 3) {  // P, Q, P: a doubled piece, keep it once as an open line
            line.pop_back();
            closed = false;
        } else {
            return false;
        }
    }
    return line.size() >= 2;
}

/// Splits a raw chain at its skipped steps into output pieces (as sub-chains).
std::vector<detail::RawChain> split_chain(const detail::RawChain& chain) {
    const std::size_t steps = chain.triangles.size();
    const auto skipped = std::find(chain.skip.begin(), chain.skip.end(), std::uint8_t{1});
    if (skipped == chain.skip.end()) {
        return {chain};
    }
    // Start right after a skipped step: a closed chain becomes open there.
    const auto begin =
        chain.closed ? static_cast<std::size_t>(skipped - chain.skip.begin()) + 1 : 0;
    std::vector<detail::RawChain> pieces;
    detail::RawChain piece;
    for (std::size_t n = 0; n < steps; ++n) {
        const std::size_t s = (begin + n) % steps;
        if (chain.skip[s] != 0) {
            if (!piece.triangles.empty()) {
                pieces.push_back(std::move(piece));
            }
            piece = {};
            continue;
        }
        if (piece.points.empty()) {
            piece.points.push_back(chain.points[s]);
            piece.edges.push_back(chain.edges[s]);
        }
        piece.triangles.push_back(chain.triangles[s]);
        piece.skip.push_back(0);
        piece.points.push_back(chain.points[s + 1]);
        piece.edges.push_back(chain.edges[s + 1]);
    }
    if (!piece.triangles.empty()) {
        pieces.push_back(std::move(piece));
    }
    return pieces;
}

/// Smoothing bounds: the midpoints to the neighbouring levels (infinite at the ends).
std::pair<double, double> level_band(const std::vector<double>& values,
                                     std::size_t k,
                                     const ContourOptions& options) {
    const double inf = std::numeric_limits<double>::infinity();
    double below = k > 0 ? 0.5 * (values[k - 1] + values[k]) : -inf;
    double above = k + 1 < values.size() ? 0.5 * (values[k] + values[k + 1]) : inf;
    if (options.fixed_levels.empty()) {  // levels outside the TIN's range still bound the band
        below = values[k] - 0.5 * options.interval;
        above = values[k] + 0.5 * options.interval;
    }
    return {below, above};
}

std::vector<Contour> trace_one_level(const Tin& tin,
                                     const ContourLevel& level,
                                     std::span<const TriangleIndex> crossing,
                                     std::pair<double, double> band,
                                     unsigned smooth,
                                     std::vector<std::uint8_t>& visited,
                                     const detail::EdgeCrossing* edge_crossing) {
    std::vector<detail::RawChain> chains;
    detail::trace_level(tin, level.value, crossing, visited, chains, edge_crossing);
    std::vector<Contour> out;
    for (const detail::RawChain& chain : chains) {
        for (detail::RawChain& piece : split_chain(chain)) {
            Contour c{level, {}, piece.closed};
            c.line = smooth > 0 ? detail::smooth_chain(tin, piece, band, smooth)
                                : std::move(piece.points);
            if (clean_line(c.line, c.closed)) {
                out.push_back(std::move(c));
            }
        }
    }
    return out;
}

void run_levels(const Tin& tin,
                const std::vector<ContourLevel>& levels,
                LevelRange range,
                const LevelBuckets& buckets,
                const ContourOptions& options,
                ContourSink& sink,
                const Progress& progress,
                const detail::EdgeCrossing* edge_crossing) {
    std::vector<double> values;
    for (const ContourLevel& l : levels) {
        values.push_back(l.value);
    }
    tbb::enumerable_thread_specific<std::vector<std::uint8_t>> visited(
        [&] { return std::vector<std::uint8_t>(tin.triangles.size(), 0); });
    std::size_t next = range.first;
    auto source = [&](tbb::flow_control& fc) -> std::size_t {
        if (next == range.last) {
            fc.stop();
        }
        return next++;
    };
    // Each level's lines live in `traced` (owned here), and only level indices travel through the
    // pipeline: when a cancellation unwinds it, nothing in flight can be left undestroyed.
    std::vector<std::vector<Contour>> traced(levels.size());
    auto compute = [&](std::size_t k) -> std::size_t {
        progress.check();
        const std::span<const TriangleIndex> crossing(buckets.triangles.data() + buckets.offsets[k],
                                                      buckets.offsets[k + 1] - buckets.offsets[k]);
        traced[k] = trace_one_level(tin, levels[k], crossing, level_band(values, k, options),
                                    options.smooth, visited.local(), edge_crossing);
        return k;
    };
    auto emit = [&](std::size_t k) {
        for (const Contour& c : traced[k]) {
            sink.add(c.level, c.line, c.closed);
        }
        std::vector<Contour>().swap(traced[k]);
        progress.report(static_cast<double>(k + 1 - range.first) /
                            static_cast<double>(range.last - range.first),
                        "contour");
    };
    const auto tokens = static_cast<std::size_t>(2 * tbb::this_task_arena::max_concurrency());
    tbb::parallel_pipeline(
        tokens,
        tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order, source) &
            tbb::make_filter<std::size_t, std::size_t>(tbb::filter_mode::parallel, compute) &
            tbb::make_filter<std::size_t, void>(tbb::filter_mode::serial_in_order, emit));
}

class ContourCollector final : public ContourSink {
public:
    explicit ContourCollector(std::vector<Contour>& out) : out_(out) {}
    void add(const ContourLevel& level, std::span<const Point3> line, bool closed) override {
        out_.push_back({level, std::vector<Point3>(line.begin(), line.end()), closed});
    }

private:
    std::vector<Contour>& out_;
};

}  // namespace

std::vector<ContourLevel> contour_levels(double zmin, double zmax, const ContourOptions& options) {
    if (!options.fixed_levels.empty()) {
        return fixed_levels(zmin, zmax, options);
    }
    if (!(options.interval > 0.0) || !std::isfinite(options.interval) ||
        !std::isfinite(options.base)) {
        throw UsageError("contour: the interval must be a positive number");
    }
    if (!(zmin <= zmax)) {
        return {};
    }
    const double i = options.interval, b = options.base;
    auto k_lo = static_cast<long long>(std::floor((zmin - b) / i));
    while (b + static_cast<double>(k_lo) * i <= zmin) {
        ++k_lo;
    }
    while (b + static_cast<double>(k_lo - 1) * i > zmin) {
        --k_lo;
    }
    const double count = std::floor((zmax - b) / i) - static_cast<double>(k_lo) + 2.0;
    if (count > static_cast<double>(options.max_levels)) {
        throw UsageError("contour: interval " + std::to_string(i) + " gives about " +
                         std::to_string(static_cast<long long>(count)) + " levels (limit " +
                         std::to_string(options.max_levels) + ")");
    }
    std::vector<ContourLevel> levels;
    for (long long k = k_lo; b + static_cast<double>(k) * i <= zmax; ++k) {
        levels.push_back({b + static_cast<double>(k) * i, k, is_index(k, options.index_every)});
    }
    return levels;
}

namespace detail {

void trace_contour_levels(const Tin& tin,
                          const std::vector<ContourLevel>& levels,
                          const ContourOptions& options,
                          ContourSink& sink,
                          const Progress& progress,
                          const EdgeCrossing* edge_crossing) {
    trace_level_range(tin, levels, 0, levels.size(), options, sink, progress, edge_crossing);
}

void trace_level_range(const Tin& tin,
                       const std::vector<ContourLevel>& levels,
                       std::size_t first,
                       std::size_t last,
                       const ContourOptions& options,
                       ContourSink& sink,
                       const Progress& progress,
                       const EdgeCrossing* edge_crossing) {
    last = std::min(last, levels.size());
    if (first >= last) {
        return;
    }
    std::vector<double> values;
    for (const ContourLevel& l : levels) {
        values.push_back(l.value);
    }
    const LevelBuckets buckets = bucket_levels(tin, values);
    progress.report(0.0, "contour");
    const LevelRange range{first, last};
    if (options.threads > 0) {
        tbb::task_arena arena(static_cast<int>(options.threads));
        arena.execute([&] {
            run_levels(tin, levels, range, buckets, options, sink, progress, edge_crossing);
        });
    } else {
        run_levels(tin, levels, range, buckets, options, sink, progress, edge_crossing);
    }
}

}  // namespace detail

void contour(const Tin& tin,
             const ContourOptions& options,
             ContourSink& sink,
             const Progress& progress) {
    if (options.surface != Interpolation::linear) {
        const auto prepare = [&] {
            return TinInterpolant::prepare(tin, options.surface, options.gradients,
                                           progress.sub(0.0, 0.2));
        };
        const TinInterpolant interpolant =
            options.threads > 0
                ? tbb::task_arena(static_cast<int>(options.threads)).execute(prepare)
                : prepare();
        detail::contour_refined(tin, interpolant, options, sink, progress.sub(0.2, 1.0));
        return;
    }
    // The height range of the triangles' vertices (a parallel reduction: min and max are exact).
    using Range = std::pair<double, double>;
    const double inf = std::numeric_limits<double>::infinity();
    const auto [zmin, zmax] = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14), Range{inf, -inf},
        [&](const tbb::blocked_range<std::size_t>& r, Range z) {
            for (std::size_t t = r.begin(); t < r.end(); ++t) {
                for (const VertexIndex v : tin.triangles[t].v) {
                    z.first = std::min(z.first, tin.vertices[v].z);
                    z.second = std::max(z.second, tin.vertices[v].z);
                }
            }
            return z;
        },
        [](Range a, Range b) {
            return Range{std::min(a.first, b.first), std::max(a.second, b.second)};
        });
    detail::trace_contour_levels(tin, contour_levels(zmin, zmax, options), options, sink, progress);
}

void contour(const Tin& tin,
             const TinInterpolant& interpolant,
             const ContourOptions& options,
             ContourSink& sink,
             const Progress& progress) {
    if (interpolant.method() == Interpolation::linear) {
        ContourOptions linear = options;
        linear.surface = Interpolation::linear;
        contour(tin, linear, sink, progress);
        return;
    }
    detail::contour_refined(tin, interpolant, options, sink, progress);
}

void contour_level_range(const Tin& tin,
                         const std::vector<ContourLevel>& levels,
                         std::size_t first,
                         std::size_t last,
                         const ContourOptions& options,
                         ContourSink& sink,
                         const Progress& progress) {
    detail::trace_level_range(tin, levels, first, last, options, sink, progress);
}

std::vector<Contour> contour(const Tin& tin,
                             const ContourOptions& options,
                             const Progress& progress) {
    std::vector<Contour> out;
    ContourCollector collector(out);
    contour(tin, options, collector, progress);
    return out;
}

}  // namespace dtm
