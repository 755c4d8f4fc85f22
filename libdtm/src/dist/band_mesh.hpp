// SPDX-License-Identifier: MIT
/// @file
/// @brief A band of triangles around a cut, as a mesh access for ghost_merge (R-S1, R-S2 of
/// docs/distributed.md).
///
/// A merge of two subtrees A | B deletes a triangle of A only if its circumdisk holds a point of
/// B, so only if the disk reaches across the cut; the same for B. The band of a merge is those
/// triangles of both sides, every ghost (the merge walks the hulls) and the spare slots it
/// writes, widened by rings of neighbours. BandMesh gives ghost_merge the same accessors as the
/// kernel's mesh over global slots; touching a slot outside the band throws BandTooNarrow, and
/// the caller widens the band and runs the merge again from the same start, so a narrow band
/// costs a retry, never a different answer.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "algo/detail/ghost_merge.hpp"
#include "dist/global_mesh.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::dist {

/// The merge needed a slot (or a vertex) the band does not hold.
class BandTooNarrow : public std::runtime_error {
public:
    explicit BandTooNarrow(std::uint64_t missing_slot)
        : std::runtime_error("band too narrow"), slot(missing_slot) {}
    std::uint64_t slot;
};

class BandMesh {
public:
    using Vertex = std::uint64_t;
    using Edge = std::uint64_t;
    static constexpr Vertex ghost_vertex = global_ghost;
    static constexpr Edge half_edge(std::uint64_t t, unsigned i) noexcept { return t << 2 | i; }

    void add(std::uint64_t slot, const GlobalTriangle& t) { tris_.emplace(slot, t); }
    void add_point(std::uint64_t v, XY p) { points_.emplace(v, p); }
    [[nodiscard]] bool has(std::uint64_t slot) const noexcept { return tris_.contains(slot); }
    [[nodiscard]] const std::unordered_map<std::uint64_t, GlobalTriangle>& triangles()
        const noexcept {
        return tris_;
    }
    [[nodiscard]] const std::unordered_map<std::uint64_t, XY>& points() const noexcept {
        return points_;
    }

    [[nodiscard]] Vertex& org(Edge h) { return at(h >> 2).v[h & 3u]; }
    [[nodiscard]] Vertex dest(Edge h) { return org(detail::edge_next(h)); }
    [[nodiscard]] Edge& twin(Edge h) { return at(h >> 2).n[h & 3u]; }
    void bond(Edge a, Edge b) {
        twin(a) = b;
        twin(b) = a;
    }
    void set_triangle(std::uint64_t t, Vertex a, Vertex b, Vertex c) { at(t).v = {a, b, c}; }
    [[nodiscard]] int orient(Vertex a, Vertex b, Vertex c) const {
        const XY& p = point(a);
        const XY& q = point(b);
        const XY& r = point(c);
        return geom::orient2d(p.x, p.y, q.x, q.y, r.x, r.y);
    }
    [[nodiscard]] bool incircle(Vertex a, Vertex b, Vertex c, Vertex d) const {
        const XY& p = point(a);
        const XY& q = point(b);
        const XY& r = point(c);
        const XY& s = point(d);
        return geom::incircle(p.x, p.y, q.x, q.y, r.x, r.y, s.x, s.y) > 0;
    }
    /// The strict order of a cut's frame (kd_order.hpp's Before).
    [[nodiscard]] bool before(int frame, Vertex a, Vertex b) const {
        const XY& p = point(a);
        const XY& q = point(b);
        if (frame == 0) return p.x < q.x || (p.x == q.x && p.y < q.y);
        return p.y < q.y || (p.y == q.y && p.x > q.x);
    }

private:
    GlobalTriangle& at(std::uint64_t slot) {
        const auto it = tris_.find(slot);
        if (it == tris_.end()) throw BandTooNarrow(slot);
        return it->second;
    }
    [[nodiscard]] const XY& point(Vertex v) const {
        const auto it = points_.find(v);
        if (it == points_.end()) throw std::logic_error("band triangle without its vertex");
        return it->second;
    }

    std::unordered_map<std::uint64_t, GlobalTriangle> tris_;
    std::unordered_map<std::uint64_t, XY> points_;
};

/// Whether the circumdisk of the real triangle (a, b, c) may reach the other side of a cut by
/// @p axis at @p cut (the cut point's coordinate on that axis): beyond it when @p left (a
/// triangle of A), before it otherwise. Floating point with a safety margin: it may include too
/// much, never too little (nearly flat triangles are always in).
bool circumdisk_reaches(XY a, XY b, XY c, int axis, double cut, bool left) noexcept;

/// The slots of @p mesh in [first, last) that seed the band of one side: its ghosts and the real
/// triangles whose circumdisks may reach across.
std::vector<std::uint64_t> band_seeds(const LocalMesh& mesh,
                                      std::uint64_t first,
                                      std::uint64_t last,
                                      int axis,
                                      double cut,
                                      bool left);

}  // namespace dtm::dist
