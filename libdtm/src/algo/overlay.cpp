// SPDX-License-Identifier: MIT
// Overlay of two TINs: the convex pieces where a top triangle overlaps a base triangle.
//
// Both surfaces are piecewise linear, so over each piece the height difference is one linear
// function: integrating it piece by piece is exact (volume.cpp). Finding the pieces:
//
// 1. Candidates. The base triangles are bucketed in a uniform grid (detail/triangle_grid). For a
//    top triangle, the base triangles listed in the cells its bounding box touches are the
//    candidates, each visited once (the grid keeps every cell's list in groups by where each
//    triangle's cell range starts); those whose boxes overlap the top triangle's are examined.
// 2. Overlap, exactly. Two convex polygons have disjoint interiors exactly when the line of an
//    edge of one of them has the other on its closed outer side (separating axis theorem); the
//    18 orient2d signs of each triangle's corners against the other's edges decide it.
// 3. Corners, exactly decided. The intersection of two triangles is the convex hull of: the
//    corners of each inside the closed other, and the proper crossings of their edges (the signs
//    of both edges' ends against the other edge are strictly opposite). All of these come from the
//    same 18 signs; a top corner at the same place as a base corner is kept once.
// 4. Coordinates, computed. A crossing of top edge (u, v) with base edge (p, q), both taken from
//    their smaller vertex index, is u + t (v - u) with t = D(p,q,u) / (D(p,q,u) - D(p,q,v)) from
//    the floating-point orientation determinants D; its heights are interpolated along each edge.
//    Every piece that has the crossing computes the same bits. A corner of one TIN on an edge of
//    the other gets the other's height by interpolation along that edge (again the same from both
//    triangles of the edge); a corner inside gets it from the triangle's plane; a corner at the
//    place of a vertex of the other gets that vertex's height exactly.
// 5. Order. The corners (at most six distinct ones) are sorted by angle around their mean. They
//    are distinct points of a convex polygon; two that floating point could order wrongly lie
//    within rounding distance of each other, where the order changes the area only by rounding.
//
// Work is split into chunks of consecutive top triangles (spatially coherent in a dtm TIN) run in
// parallel; each chunk's pieces go to the caller's function, which keeps per-chunk results, so
// sums combined in chunk order do not depend on the thread count.
//
// References: M. de Berg et al., "Computational Geometry", 3rd ed., ch. 2 (map overlay);
// J. R. Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", 1997; S. Gottschalk, "Separating axis theorem", TR96-024, UNC 1996.
#include "dtm/algo/overlay.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <memory>
#include <utility>
#include <vector>

#include "algo/detail/triangle_grid.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

/// One triangle with its corner indices, as the clipper reads it.
using Tri = detail::PackedTriangle;
using detail::height_at;

constexpr std::size_t next(std::size_t i) { return i == 2 ? 0 : i + 1; }

/// Floating-point orientation determinant, the formula of orient2d's filter.
inline double det(double ax, double ay, double bx, double by, double cx, double cy) {
    return (ax - cx) * (by - cy) - (ay - cy) * (bx - cx);
}

std::array<double, 2> slope(const Tri& t) {
    const double ux = t.x[1] - t.x[0];
    const double uy = t.y[1] - t.y[0];
    const double uz = t.z[1] - t.z[0];
    const double vx = t.x[2] - t.x[0];
    const double vy = t.y[2] - t.y[0];
    const double vz = t.z[2] - t.z[0];
    const double d = ux * vy - uy * vx;
    if (d == 0.0) {
        return {0.0, 0.0};
    }
    return {(uz * vy - uy * vz) / d, (ux * vz - uz * vx) / d};
}

/// Parameter along (u -> v) where it crosses the line p -> q.
double crossing_parameter(
    double ux, double uy, double vx, double vy, double px, double py, double qx, double qy) {
    const double du = det(px, py, qx, qy, ux, uy);
    const double dv = det(px, py, qx, qy, vx, vy);
    const double denominator = du - dv;
    if (denominator == 0.0) {
        return 0.5;
    }
    return std::clamp(du / denominator, 0.0, 1.0);
}

/// The crossing of top edge k of @p a with base edge j of @p b (a proper crossing).
OverlayCorner crossing(const Tri& a, std::size_t k, const Tri& b, std::size_t j) {
    std::size_t au = k;
    std::size_t av = next(k);
    if (a.v[av] < a.v[au]) {
        std::swap(au, av);
    }
    std::size_t bu = j;
    std::size_t bv = next(j);
    if (b.v[bv] < b.v[bu]) {
        std::swap(bu, bv);
    }
    const double ta =
        crossing_parameter(a.x[au], a.y[au], a.x[av], a.y[av], b.x[bu], b.y[bu], b.x[bv], b.y[bv]);
    const double tb =
        crossing_parameter(b.x[bu], b.y[bu], b.x[bv], b.y[bv], a.x[au], a.y[au], a.x[av], a.y[av]);
    OverlayCorner c;
    c.kind = CornerKind::crossing;
    c.x = a.x[au] + ta * (a.x[av] - a.x[au]);
    c.y = a.y[au] + ta * (a.y[av] - a.y[au]);
    c.z_top = a.z[au] + ta * (a.z[av] - a.z[au]);
    c.z_base = b.z[bu] + tb * (b.z[bv] - b.z[bu]);
    c.top_u = a.v[au];
    c.top_v = a.v[av];
    c.base_u = b.v[bu];
    c.base_v = b.v[bv];
    return c;
}

/// Sorts the corners counter-clockwise by angle around their mean.
void sort_corners(OverlayCorner* c, std::size_t n) {
    double mx = 0.0;
    double my = 0.0;
    for (std::size_t i = 1; i < n; ++i) {
        mx += c[i].x - c[0].x;
        my += c[i].y - c[0].y;
    }
    mx = c[0].x + mx / static_cast<double>(n);
    my = c[0].y + my / static_cast<double>(n);
    const auto lower = [](double dx, double dy) { return dy < 0.0 || (dy == 0.0 && dx < 0.0); };
    const auto before = [&](const OverlayCorner& p, const OverlayCorner& q) {
        const double px = p.x - mx;
        const double py = p.y - my;
        const double qx = q.x - mx;
        const double qy = q.y - my;
        const bool lp = lower(px, py);
        const bool lq = lower(qx, qy);
        if (lp != lq) {
            return lq;
        }
        return px * qy - py * qx > 0.0;
    };
    for (std::size_t i = 1; i < n; ++i) {
        const OverlayCorner key = c[i];
        std::size_t j = i;
        while (j > 0 && before(key, c[j - 1])) {
            c[j] = c[j - 1];
            --j;
        }
        c[j] = key;
    }
}

/// The intersection polygon of triangles @p a (top) and @p b (base) into @p out; returns the
/// number of corners, 0 when the interiors do not overlap.
std::size_t clip(const Tri& a, const Tri& b, OverlayCorner* out) {
    // sa[i][j]: orientation of a's corner i against b's edge j; sb[j][k]: b's corner j against
    // a's edge k.
    std::array<std::array<int, 3>, 3> sa{};
    for (std::size_t j = 0; j < 3; ++j) {
        const std::size_t j1 = next(j);
        bool all_out = true;
        for (std::size_t i = 0; i < 3; ++i) {
            sa[i][j] = geom::orient2d(b.x[j], b.y[j], b.x[j1], b.y[j1], a.x[i], a.y[i]);
            all_out = all_out && sa[i][j] <= 0;
        }
        if (all_out) {
            return 0;
        }
    }
    std::array<std::array<int, 3>, 3> sb{};
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t k1 = next(k);
        bool all_out = true;
        for (std::size_t j = 0; j < 3; ++j) {
            sb[j][k] = geom::orient2d(a.x[k], a.y[k], a.x[k1], a.y[k1], b.x[j], b.y[j]);
            all_out = all_out && sb[j][k] <= 0;
        }
        if (all_out) {
            return 0;
        }
    }
    std::size_t n = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        if (sa[i][0] >= 0 && sa[i][1] >= 0 && sa[i][2] >= 0) {
            OverlayCorner& c = out[n++];
            c = OverlayCorner{};
            c.kind = CornerKind::top_vertex;
            c.x = a.x[i];
            c.y = a.y[i];
            c.z_top = a.z[i];
            c.z_base = height_at(b, sa[i], a.x[i], a.y[i]);
            c.top_u = a.v[i];
        }
    }
    for (std::size_t j = 0; j < 3; ++j) {
        if (sb[j][0] < 0 || sb[j][1] < 0 || sb[j][2] < 0) {
            continue;
        }
        bool shared = false;
        for (std::size_t i = 0; i < 3; ++i) {
            shared = shared || (a.x[i] == b.x[j] && a.y[i] == b.y[j]);
        }
        if (shared) {
            continue;
        }
        OverlayCorner& c = out[n++];
        c = OverlayCorner{};
        c.kind = CornerKind::base_vertex;
        c.x = b.x[j];
        c.y = b.y[j];
        c.z_top = height_at(a, sb[j], b.x[j], b.y[j]);
        c.z_base = b.z[j];
        c.base_u = b.v[j];
    }
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t k1 = next(k);
        for (std::size_t j = 0; j < 3; ++j) {
            const std::size_t j1 = next(j);
            if (sb[j][k] * sb[j1][k] < 0 && sa[k][j] * sa[k1][j] < 0) {
                out[n++] = crossing(a, k, b, j);
            }
        }
    }
    sort_corners(out, n);
    return n;
}

/// Reusable per-chunk buffers.
struct ChunkBuffer {
    std::vector<OverlayCorner> corners;
    std::vector<OverlayPiece> pieces;
    std::vector<std::size_t> first;  ///< first corner of each piece

    void clear() {
        corners.clear();
        pieces.clear();
        first.clear();
    }
    void add(TriangleIndex ta,
             TriangleIndex tb,
             const std::array<double, 2>& top_slope,
             const std::array<double, 2>& base_slope,
             const OverlayCorner* c,
             std::size_t n) {
        first.push_back(corners.size());
        corners.insert(corners.end(), c, c + n);
        OverlayPiece piece;
        piece.top_triangle = ta;
        piece.base_triangle = tb;
        piece.top_slope = top_slope;
        piece.base_slope = base_slope;
        pieces.push_back(piece);
    }
    /// Points the pieces' spans into the (now stable) corner array.
    std::span<const OverlayPiece> finish() {
        for (std::size_t i = 0; i < pieces.size(); ++i) {
            const std::size_t end = i + 1 < pieces.size() ? first[i + 1] : corners.size();
            pieces[i].corners =
                std::span<const OverlayCorner>(corners.data() + first[i], end - first[i]);
        }
        return pieces;
    }
};

}  // namespace

struct TinOverlay::Impl {
    const Tin* top = nullptr;
    const Tin* base = nullptr;
    double base_z = 0.0;
    OverlayOptions options;
    detail::TriangleGrid grid;
    std::vector<detail::PackedTriangle> packed_top;

    [[nodiscard]] std::size_t chunk_count() const {
        const std::size_t size = std::max<std::size_t>(options.chunk_triangles, 1);
        return (top->triangles.size() + size - 1) / size;
    }

    void plane_chunk(std::size_t begin, std::size_t end, ChunkBuffer& buffer) const {
        std::array<OverlayCorner, 3> corners{};
        for (std::size_t t = begin; t < end; ++t) {
            const Tri& a = packed_top[t];
            for (std::size_t k = 0; k < 3; ++k) {
                corners[k] = OverlayCorner{};
                corners[k].x = a.x[k];
                corners[k].y = a.y[k];
                corners[k].z_top = a.z[k];
                corners[k].z_base = base_z;
                corners[k].top_u = a.v[k];
            }
            if (geom::orient2d(a.x[0], a.y[0], a.x[1], a.y[1], a.x[2], a.y[2]) > 0) {
                buffer.add(static_cast<TriangleIndex>(t), no_triangle, slope(a), {0.0, 0.0},
                           corners.data(), 3);
            }
        }
    }

    void tin_chunk(std::size_t begin, std::size_t end, ChunkBuffer& buffer) const {
        std::array<OverlayCorner, 12> corners{};
        for (std::size_t t = begin; t < end; ++t) {
            const Tri& a = packed_top[t];
            const Box2 ba = a.box();
            const std::array<double, 2> top_slope = slope(a);
            grid.for_each_candidate(ba, [&](TriangleIndex tb) {
                const detail::PackedTriangle& pb = grid.triangle(tb);
                const Box2& bb = grid.box(tb);
                if (ba.xmin < bb.xmax && bb.xmin < ba.xmax && ba.ymin < bb.ymax &&
                    bb.ymin < ba.ymax) {
                    const std::size_t n = clip(a, pb, corners.data());
                    if (n >= 3) {
                        buffer.add(static_cast<TriangleIndex>(t), tb, top_slope, slope(pb),
                                   corners.data(), n);
                    }
                }
            });
        }
    }

    void compute(std::size_t chunk, ChunkBuffer& buffer) const {
        const std::size_t size = std::max<std::size_t>(options.chunk_triangles, 1);
        const std::size_t begin = chunk * size;
        const std::size_t end = std::min(top->triangles.size(), begin + size);
        buffer.clear();
        if (base != nullptr) {
            tin_chunk(begin, end, buffer);
        } else {
            plane_chunk(begin, end, buffer);
        }
    }

    template <class Fn>
    void in_arena(Fn&& fn) const {
        if (options.threads > 0) {
            tbb::task_arena arena(static_cast<int>(options.threads));
            arena.execute(fn);
        } else {
            fn();
        }
    }

    void run_ordered(const OverlayChunkFn& fn, const Progress& progress) const {
        const std::size_t chunks = chunk_count();
        std::size_t next_chunk = 0;
        in_arena([&] {
            const auto tokens =
                static_cast<std::size_t>(2 * tbb::this_task_arena::max_concurrency());
            tbb::parallel_pipeline(
                tokens,
                tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                                    [&](tbb::flow_control& control) -> std::size_t {
                                                        if (next_chunk == chunks) {
                                                            control.stop();
                                                            return 0;
                                                        }
                                                        return next_chunk++;
                                                    }) &
                    tbb::make_filter<std::size_t,
                                     std::pair<std::size_t, std::shared_ptr<ChunkBuffer>>>(
                        tbb::filter_mode::parallel,
                        [&](std::size_t chunk) {
                            progress.check();
                            auto buffer = std::make_shared<ChunkBuffer>();
                            compute(chunk, *buffer);
                            return std::pair{chunk, buffer};
                        }) &
                    tbb::make_filter<std::pair<std::size_t, std::shared_ptr<ChunkBuffer>>, void>(
                        tbb::filter_mode::serial_in_order,
                        [&](const std::pair<std::size_t, std::shared_ptr<ChunkBuffer>>& item) {
                            fn(item.first, item.second->finish());
                            progress.report(
                                static_cast<double>(item.first + 1) /
                                    static_cast<double>(std::max<std::size_t>(chunks, 1)),
                                "overlaying the surfaces");
                        }));
        });
        progress.report(1.0, "overlaying the surfaces");
    }

    void run(const OverlayChunkFn& fn, const Progress& progress) const {
        const std::size_t chunks = chunk_count();
        const std::size_t size = std::max<std::size_t>(options.chunk_triangles, 1);
        std::atomic<std::size_t> done{0};
        const auto body = [&](const tbb::blocked_range<std::size_t>& range) {
            ChunkBuffer buffer;
            buffer.corners.reserve(size * 40);
            buffer.pieces.reserve(size * 8);
            buffer.first.reserve(size * 8);
            for (std::size_t chunk = range.begin(); chunk != range.end(); ++chunk) {
                progress.check();
                compute(chunk, buffer);
                fn(chunk, buffer.finish());
                const std::size_t finished = done.fetch_add(1) + 1;
                progress.report(static_cast<double>(finished) / static_cast<double>(chunks),
                                "overlaying the surfaces");
            }
        };
        in_arena([&] { tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 4), body); });
        progress.report(1.0, "overlaying the surfaces");
    }
};

TinOverlay::TinOverlay(const Tin& top, const Tin& base, const OverlayOptions& options)
    : impl_(std::make_unique<Impl>()) {
    impl_->top = &top;
    impl_->base = &base;
    impl_->options = options;
    impl_->grid = detail::TriangleGrid(base);
    impl_->packed_top = detail::pack_triangles(top);
}

TinOverlay::TinOverlay(const Tin& top, double base_z, const OverlayOptions& options)
    : impl_(std::make_unique<Impl>()) {
    impl_->top = &top;
    impl_->base_z = base_z;
    impl_->options = options;
    impl_->packed_top = detail::pack_triangles(top);
}

TinOverlay::~TinOverlay() = default;

std::size_t TinOverlay::chunk_count() const noexcept { return impl_->chunk_count(); }

void TinOverlay::run(const OverlayChunkFn& fn, const Progress& progress) const {
    impl_->run(fn, progress);
}

void TinOverlay::run_ordered(const OverlayChunkFn& fn, const Progress& progress) const {
    impl_->run_ordered(fn, progress);
}

void TinOverlay::vertex_counts(std::size_t& top, std::size_t& base) const noexcept {
    top = impl_->top->vertices.size();
    base = impl_->base != nullptr ? impl_->base->vertices.size() : 0;
}

std::size_t TinOverlay::index_bytes() const noexcept {
    return impl_->grid.memory_bytes() +
           impl_->packed_top.capacity() * sizeof(detail::PackedTriangle);
}

}  // namespace dtm
