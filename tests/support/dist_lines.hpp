// SPDX-License-Identifier: MIT
/// @file
/// @brief Breakline inputs of the distributed tests and the serial insertion as their oracle.
#pragma once

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "algo/detail/constraint_batch.hpp"
#include "algo/detail/mesh_edit.hpp"
#include "algo/detail/segment_split.hpp"
#include "dist/constraints.hpp"
#include "support/dist_cases.hpp"

namespace dtm::test {

using dist::GlobalSegment;
using dist::GlobalTriangle;
using dist::Point;

struct LineCase {
    std::string name;
    std::vector<Point> points;  ///< id = index, crossing vertices appended
    std::vector<GlobalSegment> segments;
};

/// Chains through the points of thin bands (x-monotone across, y-monotone up, so each chain is
/// simple), a diagonal from the lowest to the highest point, split at their crossings.
inline LineCase with_lines(const test::DistCase& c) {
    detail::MergedInput in;
    double x0 = c.points[0].x, x1 = x0, y0 = c.points[0].y, y1 = y0;
    for (const Point& p : c.points) {
        in.vertices.push_back({p.x, p.y, 0.0});
        in.z_known.push_back(true);
        x0 = std::min(x0, p.x);
        x1 = std::max(x1, p.x);
        y0 = std::min(y0, p.y);
        y1 = std::max(y1, p.y);
    }
    // dashed: every other segment, between 0.15 and 0.45 of the other axis (apart from the rest)
    const auto chain = [&](bool across, double at, std::uint8_t bits, bool dashed = false) {
        std::vector<std::uint32_t> ids;
        for (std::uint32_t i = 0; i < c.points.size(); ++i) {
            const double tx = (c.points[i].x - x0) / (x1 - x0);
            const double ty = (c.points[i].y - y0) / (y1 - y0);
            const double t = across ? ty : tx;
            const double along = across ? tx : ty;
            if (t >= at && t < at + 0.02 && (!dashed || (along > 0.15 && along < 0.45)))
                ids.push_back(i);
        }
        std::sort(ids.begin(), ids.end(), [&](std::uint32_t a, std::uint32_t b) {
            const Point& p = c.points[a];
            const Point& q = c.points[b];
            return across ? std::pair{p.x, p.y} < std::pair{q.x, q.y}
                          : std::pair{p.y, p.x} < std::pair{q.y, q.x};
        });
        for (std::size_t k = 1; k < ids.size(); ++k)
            in.segments.push_back({ids[k - 1], ids[k], bits});
    };
    for (const double at : {0.1, 0.49, 0.8}) chain(true, at, detail::constraint_breakline);
    for (const double at : {0.3, 0.5}) chain(false, at, detail::constraint_soft);
    chain(false, 0.9, detail::constraint_breakline, true);
    const auto lowest =
        std::min_element(c.points.begin(), c.points.end(),
                         [](const Point& a, const Point& b) { return a.x + a.y < b.x + b.y; });
    const auto highest =
        std::max_element(c.points.begin(), c.points.end(),
                         [](const Point& a, const Point& b) { return a.x + a.y < b.x + b.y; });
    in.segments.push_back({static_cast<std::uint32_t>(lowest - c.points.begin()),
                           static_cast<std::uint32_t>(highest - c.points.begin()),
                           detail::constraint_breakline});
    const detail::SegmentSplit split = detail::split_segments(in, 0.001);
    if (!split.all_free) throw std::logic_error("with_lines: the split ran out of rounds");
    LineCase out{c.name, {}, {}};
    for (std::size_t i = 0; i < in.vertices.size(); ++i)
        out.points.push_back({in.vertices[i].x, in.vertices[i].y, i});
    for (const detail::InputSegment& s : in.segments) out.segments.push_back({s.a, s.b, s.bits});
    return out;
}

struct ConstrainedMesh {
    std::vector<GlobalTriangle> tris;
    std::vector<std::array<std::uint8_t, 3>> bits;
};

inline ConstrainedMesh serial_constrained(const LineCase& c) {
    using namespace dtm::detail;
    BigArray<KernelPoint> pts(c.points.size());
    for (std::size_t i = 0; i < c.points.size(); ++i) {
        pts[i] = {{c.points[i].x, c.points[i].y}, static_cast<std::uint32_t>(i)};
    }
    GhostMesh mesh;
    delaunay_divide_and_conquer(pts, mesh, DelaunayDcOptions{}, Progress{});
    std::vector<VertexId> kernel_of(c.points.size());
    for (std::size_t v = 0; v < mesh.points.size(); ++v)
        kernel_of[mesh.points[v].id] = static_cast<VertexId>(v);
    std::vector<InputSegment> segments;
    for (const GlobalSegment& s : c.segments) {
        segments.push_back({kernel_of[s.a], kernel_of[s.b], s.bits});
    }
    std::vector<double> z(mesh.points.size(), 0.0);
    MeshEditor editor(mesh, z, 0.0);
    insert_segments(editor, mesh, segments, true, Progress{});
    ConstrainedMesh r;
    for (const Triangle& t : mesh.tris) r.tris.push_back(dist::to_global(t, 0, 0));
    r.bits = mesh.bits;
    return r;
}

}  // namespace dtm::test
