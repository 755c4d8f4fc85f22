// SPDX-License-Identifier: MIT
// TIN to DEM by scan conversion.
//
// The linear surface of a TIN is the barycentric interpolation of each triangle's vertex
// heights; the cubic (Clough-Tocher) and natural-neighbour surfaces are evaluated per triangle
// by a "shader" chosen once per run (interpolation.hpp). A DEM samples the surface at cell
// centres (GDAL's "pixel is area" convention; gdal_grid -a linear samples the same points).
//
// 1. Bucketing (sequential, O(triangles)). The raster is cut into bands of whole rows. Each
//    triangle goes into the bucket of every band its y-extent overlaps (a CSR array: counts,
//    prefix sums, fill), so a band only looks at the triangles that can touch it.
// 2. Scan conversion (parallel over bands, tbb::parallel_pipeline). For every triangle of the
//    band and every row whose centre line crosses its y-extent, the x-interval of the triangle
//    on that line is estimated in floating point (error bounded by a margin tol far above the
//    few rounding errors involved) and widened by one cell; candidate centres are then examined
//    from both ends inwards. A centre farther than tol from the estimated ends is decided by the
//    estimate; one within tol is tested exactly with orient2d. The triangle meets a row in one
//    segment (convexity), so every centre between the first and the last accepted one is inside
//    without further tests: the exact predicate decides every close call, the rest is fast.
// 3. Output (serial, in order): finished bands go to the GridSink north to south while later
//    bands are still being computed; at most a few bands are alive at once (bounded memory).
//
// Ties. A centre on an edge shared by two triangles belongs to exactly one of them by the
// top-left rule of rasterisers (an edge a->b of a counter-clockwise triangle owns its points if
// it goes downwards, or is horizontal going west); an edge on the border of the TIN (hull,
// boundary, hole: no neighbour) always owns its points, so the domain is closed. Values on an
// edge are interpolated along the edge from its lexicographically smaller end (x, then y;
// linear: the segment; cubic: the edge's cubic), so either triangle would give the same bits
// whatever the vertex numbers (a distributed DEM numbers them differently on every rank); a
// centre on a vertex gets the vertex height exactly.
//
// References: J. Pineda, "A parallel algorithm for polygon rasterization", SIGGRAPH 1988 (edge
// functions, top-left rule); J. R. Shewchuk, "Adaptive precision floating-point arithmetic and
// fast robust geometric predicates", 1997 (orient2d).
#include "dtm/algo/rasterize.hpp"

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
#include <vector>

#include "algo/detail/raster_vertex_order.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

/// Triangles per band, as a CSR array.
struct Buckets {
    std::size_t band_rows = 1;
    std::size_t band_count = 0;
    std::vector<std::size_t> offsets;  ///< band_count + 1
    std::vector<TriangleIndex> triangles;
    std::vector<std::array<std::int32_t, 2>> rows;  ///< per triangle: first and last row touched
};

/// Conservative range of rows whose centre line may meet [ylo, yhi]; empty when first > last.
struct RowRange {
    std::ptrdiff_t first = 0;
    std::ptrdiff_t last = -1;
};

RowRange rows_touching(const GridSpec& spec, double ylo, double yhi) {
    const double lo = std::floor((spec.ymax - yhi) / spec.cell - 0.5);
    const double hi = std::ceil((spec.ymax - ylo) / spec.cell - 0.5);
    const double max_row = static_cast<double>(spec.rows) - 1.0;
    RowRange r;
    if (!(hi >= 0.0) || !(lo <= max_row)) {
        return r;
    }
    r.first = static_cast<std::ptrdiff_t>(std::max(lo, 0.0));
    r.last = static_cast<std::ptrdiff_t>(std::min(hi, max_row));
    return r;
}

RowRange triangle_rows(const Tin& tin, const Triangle& t, const GridSpec& spec) {
    const Point3& a = tin.vertices[t.v[0]];
    const Point3& b = tin.vertices[t.v[1]];
    const Point3& c = tin.vertices[t.v[2]];
    return rows_touching(spec, std::min({a.y, b.y, c.y}), std::max({a.y, b.y, c.y}));
}

/// Rows [first, first + count) of the spec: the part of the raster computed.
struct RowWindow {
    std::size_t first = 0;
    std::size_t count = 0;
};

Buckets make_buckets(const Tin& tin,
                     const GridSpec& spec,
                     RowWindow window,
                     std::size_t band_rows) {
    Buckets buckets;
    buckets.band_rows = band_rows;
    buckets.band_count = (window.count + band_rows - 1) / band_rows;
    buckets.offsets.assign(buckets.band_count + 1, 0);
    buckets.rows.resize(tin.triangles.size());
    const auto w0 = static_cast<std::ptrdiff_t>(window.first);
    const auto w1 = static_cast<std::ptrdiff_t>(window.first + window.count) - 1;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t i = range.begin(); i != range.end(); ++i) {
                              const RowRange r = triangle_rows(tin, tin.triangles[i], spec);
                              buckets.rows[i] = {static_cast<std::int32_t>(std::max(r.first, w0)),
                                                 static_cast<std::int32_t>(std::min(r.last, w1))};
                          }
                      });
    const auto each_band = [&](std::size_t i, auto&& fn) {
        const auto [first, last] = buckets.rows[i];
        if (first > last) {
            return;
        }
        for (std::size_t b = (static_cast<std::size_t>(first) - window.first) / band_rows;
             b <= (static_cast<std::size_t>(last) - window.first) / band_rows; ++b) {
            fn(b);
        }
    };
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        each_band(i, [&](std::size_t b) { ++buckets.offsets[b + 1]; });
    }
    for (std::size_t b = 0; b < buckets.band_count; ++b) {
        buckets.offsets[b + 1] += buckets.offsets[b];
    }
    buckets.triangles.resize(buckets.offsets.back());
    std::vector<std::size_t> fill(buckets.offsets.begin(), buckets.offsets.end() - 1);
    for (std::size_t i = 0; i < tin.triangles.size(); ++i) {
        each_band(i, [&](std::size_t b) {
            buckets.triangles[fill[b]++] = static_cast<TriangleIndex>(i);
        });
    }
    return buckets;
}

/// One triangle prepared for scan conversion.
class ScanTriangle {
public:
    ScanTriangle(const Tin& tin, const Triangle& t) : tri_(t) {
        for (int i = 0; i < 3; ++i) {
            p_[i] = &tin.vertices[t.v[static_cast<std::size_t>(i)]];
        }
        const Point3& a = *p_[0];
        const double bx = p_[1]->x - a.x, by = p_[1]->y - a.y, bz = p_[1]->z - a.z;
        const double cx = p_[2]->x - a.x, cy = p_[2]->y - a.y, cz = p_[2]->z - a.z;
        const double det = bx * cy - cx * by;
        dzdx_ = (bz * cy - cz * by) / det;
        dzdy_ = (bx * cz - cx * bz) / det;
        for (int e = 0; e < 3; ++e) {
            owns_[e] = edge_owns_ties(e);
        }
    }

    /// x-interval of the triangle on the line y (floating point, approximate); false if the line
    /// misses the triangle (this test is exact).
    bool span(double y, double& xl, double& xr, double& tol) const {
        bool hit = false;
        xl = std::numeric_limits<double>::infinity();
        xr = -xl;
        double magnitude = 0.0;
        for (int e = 0; e < 3; ++e) {
            const Point3& a = *p_[(e + 1) % 3];
            const Point3& b = *p_[(e + 2) % 3];
            if (y < std::min(a.y, b.y) || y > std::max(a.y, b.y)) {
                continue;
            }
            hit = true;
            magnitude = std::max({magnitude, std::abs(a.x), std::abs(b.x)});
            if (a.y == b.y) {
                xl = std::min({xl, a.x, b.x});
                xr = std::max({xr, a.x, b.x});
            } else {
                const double x = a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
                xl = std::min(xl, x);
                xr = std::max(xr, x);
            }
        }
        // A few rounding errors of size eps * magnitude at most; the margin is 10^4 times that.
        tol = 1e-12 * magnitude + std::numeric_limits<double>::min();
        return hit;
    }

    /// Exact: does the triangle own the point (inside, or on an edge it owns)? Returns
    /// outside, inside, on_edge + e or on_vertex + i.
    [[nodiscard]] int classify(double x, double y) const {
        int on_edge = -1;
        int zero_count = 0;
        for (int e = 0; e < 3; ++e) {
            const Point3& a = *p_[(e + 1) % 3];
            const Point3& b = *p_[(e + 2) % 3];
            const int s = geom::orient2d(a.x, a.y, b.x, b.y, x, y);
            if (s < 0 || (s == 0 && !owns_[e])) {
                return outside;
            }
            if (s == 0) {
                on_edge = e;
                ++zero_count;
            }
        }
        if (zero_count >= 2) {
            for (int i = 0; i < 3; ++i) {
                if (p_[i]->x == x && p_[i]->y == y) {
                    return on_vertex + i;
                }
            }
            return inside;  // unreachable for a non-degenerate triangle
        }
        return on_edge >= 0 ? on_edge_0 + on_edge : inside;
    }

    static constexpr int outside = -1;
    static constexpr int inside = 0;
    static constexpr int on_edge_0 = 1;
    static constexpr int on_vertex = 4;

    [[nodiscard]] double vertex_z(int i) const { return p_[i]->z; }

    /// Height at a point known to be inside (used for the filled interior of a span).
    [[nodiscard]] double plane(double x, double y) const {
        return p_[0]->z + dzdx_ * (x - p_[0]->x) + dzdy_ * (y - p_[0]->y);
    }

    /// Index of the horizontal edge lying on the line y, or -1.
    [[nodiscard]] int horizontal_edge_at(double y) const {
        for (int e = 0; e < 3; ++e) {
            if (p_[(e + 1) % 3]->y == y && p_[(e + 2) % 3]->y == y) {
                return e;
            }
        }
        return -1;
    }

    /// Edge @p e (opposite vertex e) as corners (from, to), from its lexicographically smaller
    /// end, and the parameter of (x, y) along it.
    void edge_parameter(int e, double x, double y, int& from, int& to, double& t) const {
        from = (e + 1) % 3;
        to = (e + 2) % 3;
        if (p_[to]->x < p_[from]->x || (p_[to]->x == p_[from]->x && p_[to]->y < p_[from]->y)) {
            std::swap(from, to);
        }
        const Point3& p = *p_[from];
        const Point3& q = *p_[to];
        const double dx = q.x - p.x, dy = q.y - p.y;
        t = ((x - p.x) * dx + (y - p.y) * dy) / (dx * dx + dy * dy);
    }

    /// Linear interpolation along edge @p e (opposite vertex e), from its smaller end.
    [[nodiscard]] double along_edge(int e, double x, double y) const {
        int from = 0, to = 0;
        double t = 0.0;
        edge_parameter(e, x, y, from, to, t);
        return p_[from]->z + t * (p_[to]->z - p_[from]->z);
    }

private:
    /// Top-left rule; border edges own their points.
    [[nodiscard]] bool edge_owns_ties(int e) const {
        if (tri_.n[static_cast<std::size_t>(e)] == no_triangle) {
            return true;
        }
        const Point3& a = *p_[(e + 1) % 3];
        const Point3& b = *p_[(e + 2) % 3];
        return b.y < a.y || (b.y == a.y && b.x < a.x);
    }

    const Triangle& tri_;
    const Point3* p_[3]{};
    double dzdx_ = 0.0;
    double dzdy_ = 0.0;
    bool owns_[3]{};
};

/// Heights of the linear surface: the triangle's plane.
class LinearShader {
public:
    void begin(const ScanTriangle& tri, TriangleIndex) { tri_ = &tri; }
    [[nodiscard]] double interior(double x, double y) const { return tri_->plane(x, y); }
    [[nodiscard]] double on_edge(int e, double x, double y) const {
        return tri_->along_edge(e, x, y);
    }

private:
    const ScanTriangle* tri_ = nullptr;
};

/// Heights of the Clough-Tocher surface: one patch per triangle.
class CubicShader {
public:
    CubicShader(const Tin& tin, const TinGradients& gradients) : surface_(tin, gradients) {}
    void begin(const ScanTriangle& tri, TriangleIndex t) {
        tri_ = &tri;
        patch_ = surface_.patch(t);
    }
    [[nodiscard]] double interior(double x, double y) const { return patch_.value(x, y); }
    [[nodiscard]] double on_edge(int e, double x, double y) const {
        int from = 0, to = 0;
        double t = 0.0;
        tri_->edge_parameter(e, x, y, from, to, t);
        return patch_.edge_value(from, to, t);
    }

private:
    CubicSurface surface_;
    CloughTocherPatch patch_;
    const ScanTriangle* tri_ = nullptr;
};

/// Heights of the natural-neighbour surface: one cavity per centre.
class NaturalShader {
public:
    NaturalShader(const NaturalNeighbourSurface& surface, NaturalNeighbourSurface::Workspace& ws)
        : surface_(surface), ws_(ws) {}
    void begin(const ScanTriangle&, TriangleIndex t) { t_ = t; }
    [[nodiscard]] double interior(double x, double y) const {
        return surface_.value(t_, x, y, ws_);
    }
    [[nodiscard]] double on_edge(int, double x, double y) const { return interior(x, y); }

private:
    const NaturalNeighbourSurface& surface_;
    NaturalNeighbourSurface::Workspace& ws_;
    TriangleIndex t_ = 0;
};

/// Scan-converts one triangle over the rows [row0, row0 + row_count) into @p band.
template <class Shader>
void scan_triangle(const Tin& tin,
                   TriangleIndex index,
                   std::array<std::int32_t, 2> rows,
                   const GridSpec& spec,
                   std::size_t row0,
                   std::size_t row_count,
                   std::span<float> band,
                   Shader& shader) {
    const auto first = std::max<std::ptrdiff_t>(rows[0], static_cast<std::ptrdiff_t>(row0));
    const auto last =
        std::min<std::ptrdiff_t>(rows[1], static_cast<std::ptrdiff_t>(row0 + row_count) - 1);
    if (first > last) {
        return;
    }
    const ScanTriangle tri(tin, tin.triangles[index]);
    shader.begin(tri, index);
    const double max_col = static_cast<double>(spec.cols) - 1.0;
    for (auto r = static_cast<std::size_t>(first); r <= static_cast<std::size_t>(last); ++r) {
        const double y = spec.center_y(r);
        double xl = 0.0, xr = 0.0, tol = 0.0;
        if (!tri.span(y, xl, xr, tol)) {
            continue;
        }
        const double clo = std::max(std::ceil((xl - spec.xmin) / spec.cell - 0.5) - 1.0, 0.0);
        const double chi = std::min(std::floor((xr - spec.xmin) / spec.cell - 0.5) + 1.0, max_col);
        if (clo > chi) {
            continue;
        }
        const int flat = tri.horizontal_edge_at(y);
        // Fast path: centres farther than tol from the estimated span ends are decided by the
        // estimate (clearly outside, or strictly inside the span on a row that is not a
        // horizontal edge); only the others go to the exact test.
        const auto owns = [&](std::size_t c, float& z) {
            const double x = spec.center_x(c);
            if (x < xl - tol || x > xr + tol) {
                return false;
            }
            if (flat < 0 && x > xl + tol && x < xr - tol) {
                z = static_cast<float>(shader.interior(x, y));
                return true;
            }
            const int hit = tri.classify(x, y);
            if (hit == ScanTriangle::outside) {
                return false;
            }
            z = static_cast<float>(hit >= ScanTriangle::on_vertex
                                       ? tri.vertex_z(hit - ScanTriangle::on_vertex)
                                   : hit >= ScanTriangle::on_edge_0
                                       ? shader.on_edge(hit - ScanTriangle::on_edge_0, x, y)
                                       : shader.interior(x, y));
            return true;
        };
        float* out = band.data() + (r - row0) * spec.cols;
        auto lo = static_cast<std::size_t>(clo);
        auto hi = static_cast<std::size_t>(chi);
        float z = 0.0F;
        while (lo <= hi && !owns(lo, z)) {
            ++lo;
        }
        if (lo > hi) {
            continue;
        }
        out[lo] = z;
        while (hi > lo && !owns(hi, z)) {
            --hi;
        }
        out[hi] = z;
        for (std::size_t c = lo + 1; c < hi; ++c) {
            const double x = spec.center_x(c);
            out[c] =
                static_cast<float>(flat >= 0 ? shader.on_edge(flat, x, y) : shader.interior(x, y));
        }
    }
}

std::size_t choose_band_rows(const GridSpec& spec,
                             RowWindow window,
                             const RasterizeOptions& options) {
    if (options.band_rows > 0) {
        return options.band_rows;
    }
    constexpr std::size_t target_cells = std::size_t{1} << 18;
    return std::clamp<std::size_t>(target_cells / std::max<std::size_t>(spec.cols, 1), 1,
                                   std::max<std::size_t>(window.count, 1));
}

void run_pipeline(const Tin& tin,
                  const TinInterpolant& interpolant,
                  const GridSpec& spec,
                  const RasterizeOptions& options,
                  RowWindow window,
                  const Buckets& buckets,
                  GridSink& sink,
                  const Progress& progress) {
    const NaturalNeighbourSurface natural(tin, interpolant.barriers());
    tbb::enumerable_thread_specific<NaturalNeighbourSurface::Workspace> workspaces;
    const auto scan_band = [&](std::size_t b, std::size_t row0, std::size_t row_count,
                               std::span<float> values, auto& shader) {
        for (std::size_t k = buckets.offsets[b]; k < buckets.offsets[b + 1]; ++k) {
            const TriangleIndex t = buckets.triangles[k];
            scan_triangle(tin, t, buckets.rows[t], spec, row0, row_count, values, shader);
        }
    };
    std::size_t next = 0;
    const auto tokens = static_cast<std::size_t>(2 * tbb::this_task_arena::max_concurrency());
    auto source = [&](tbb::flow_control& fc) -> std::size_t {
        if (next == buckets.band_count) {
            fc.stop();
            return 0;
        }
        return next++;
    };
    // Band values live in `bands` (owned here) and only band indices travel through the
    // pipeline: when a cancellation unwinds it, nothing in flight can be left undestroyed.
    std::vector<std::vector<float>> bands(buckets.band_count);
    auto compute = [&](std::size_t b) -> std::size_t {
        progress.check();
        const std::size_t row0 = window.first + b * buckets.band_rows;
        const std::size_t row_count =
            std::min(buckets.band_rows, window.first + window.count - row0);
        std::vector<float> values(row_count * spec.cols, options.nodata);
        if (interpolant.method() == Interpolation::cubic) {
            CubicShader shader(tin, interpolant.gradients());
            scan_band(b, row0, row_count, values, shader);
        } else if (interpolant.method() == Interpolation::natural) {
            NaturalShader shader(natural, workspaces.local());
            scan_band(b, row0, row_count, values, shader);
        } else {
            LinearShader shader;
            scan_band(b, row0, row_count, values, shader);
        }
        bands[b] = std::move(values);
        return b;
    };
    auto emit = [&](std::size_t b) {
        const std::size_t row0 = window.first + b * buckets.band_rows;
        sink.write_rows(row0, bands[b].size() / spec.cols, bands[b]);
        std::vector<float>().swap(bands[b]);
        progress.report(static_cast<double>(b + 1) / static_cast<double>(buckets.band_count),
                        "rasterize");
    };
    tbb::parallel_pipeline(
        tokens,
        tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order, source) &
            tbb::make_filter<std::size_t, std::size_t>(tbb::filter_mode::parallel, compute) &
            tbb::make_filter<std::size_t, void>(tbb::filter_mode::serial_in_order, emit));
}

/// Collects the streamed bands into a Grid.
class GridCollector final : public GridSink {
public:
    explicit GridCollector(Grid& grid) : grid_(grid) {}
    void write_rows(std::size_t first_row, std::size_t, std::span<const float> values) override {
        std::copy(values.begin(), values.end(),
                  grid_.values.begin() + static_cast<std::ptrdiff_t>(first_row * grid_.spec.cols));
    }

private:
    Grid& grid_;
};

}  // namespace

void rasterize(const Tin& tin,
               const TinInterpolant& interpolant,
               const GridSpec& spec,
               const RasterizeOptions& options,
               GridSink& sink,
               const Progress& progress) {
    if (spec.rows == 0 || spec.cols == 0) {
        return;
    }
    if (spec.rows > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) ||
        spec.cols > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw UsageError("rasterize: " + std::to_string(spec.cols) + " x " +
                         std::to_string(spec.rows) + " cells is too large");
    }
    // The interpolant is indexed by triangle, so it serves the renumbered copy as well.
    if (options.first_row > spec.rows) {
        throw UsageError("rasterize: first row " + std::to_string(options.first_row) +
                         " is beyond the " + std::to_string(spec.rows) + " rows");
    }
    const std::size_t rest = spec.rows - options.first_row;
    const RowWindow window{options.first_row,
                           options.row_count == 0 ? rest : std::min(options.row_count, rest)};
    if (window.count == 0) {
        return;
    }
    const Tin& surface = interpolant.surface(tin);
    Tin copy;  // only when the vertices are not in first-use order already
    if (!detail::has_coherent_vertices(surface)) copy = detail::with_coherent_vertices(surface);
    const Tin& local = copy.triangles.empty() ? surface : copy;
    const Buckets buckets =
        make_buckets(local, spec, window, choose_band_rows(spec, window, options));
    progress.report(0.0, "rasterize");
    const auto run = [&] {
        run_pipeline(local, interpolant, spec, options, window, buckets, sink, progress);
    };
    if (options.threads > 0) {
        tbb::task_arena arena(static_cast<int>(options.threads));
        arena.execute(run);
    } else {
        run();
    }
}

void rasterize(const Tin& tin,
               const GridSpec& spec,
               const RasterizeOptions& options,
               GridSink& sink,
               const Progress& progress) {
    if (options.interpolation == Interpolation::linear) {
        rasterize(tin, TinInterpolant{}, spec, options, sink, progress);
        return;
    }
    const auto prepare = [&] {
        return TinInterpolant::prepare(tin, options.interpolation, options.gradients,
                                       progress.sub(0.0, 0.3));
    };
    const TinInterpolant interpolant =
        options.threads > 0 ? tbb::task_arena(static_cast<int>(options.threads)).execute(prepare)
                            : prepare();
    rasterize(tin, interpolant, spec, options, sink, progress.sub(0.3, 1.0));
}

Grid rasterize(const Tin& tin,
               const GridSpec& spec,
               const RasterizeOptions& options,
               const Progress& progress) {
    Grid grid{spec, options.nodata, std::vector<float>(spec.cell_count(), options.nodata)};
    GridCollector collector(grid);
    rasterize(tin, spec, options, collector, progress);
    return grid;
}

bool rows_touching(
    const GridSpec& spec, double ylo, double yhi, std::size_t& first, std::size_t& last) {
    const RowRange r = rows_touching(spec, ylo, yhi);
    first = static_cast<std::size_t>(std::max<std::ptrdiff_t>(r.first, 0));
    last = static_cast<std::size_t>(std::max<std::ptrdiff_t>(r.last, 0));
    return r.first <= r.last;
}

Box2 tin_bounds(const Tin& tin) {
    // Exact minima and maxima: the same box for any split of the triangles (-0 and +0 made
    // one by the + 0.0 below, whichever the split met first).
    Box2 box = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 15), Box2{},
        [&](const tbb::blocked_range<std::size_t>& r, Box2 part) {
            for (std::size_t t = r.begin(); t != r.end(); ++t) {
                for (const VertexIndex v : tin.triangles[t].v) part.add(tin.vertices[v]);
            }
            return part;
        },
        [](Box2 a, const Box2& b) {
            if (!b.empty()) {
                a.add(b.xmin, b.ymin);
                a.add(b.xmax, b.ymax);
            }
            return a;
        });
    if (!box.empty()) box = {box.xmin + 0.0, box.ymin + 0.0, box.xmax + 0.0, box.ymax + 0.0};
    return box;
}

}  // namespace dtm
