// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the stars (fans of triangles) of a TIN's vertices, walked through the
/// neighbour links, and the numbering of their sectors for the gradient estimate.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "algo/detail/big_array.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::detail {

/// Corner i of triangle t.
struct Corner {
    TriangleIndex t = no_triangle;
    int i = 0;
};

/// The fans around every vertex: one per vertex (closed around an inner vertex, open at the
/// border), several at a pinch point of the domain. Found by one pass over the triangles; the
/// used vertices are listed in first-use order (the order of their first corner), which follows
/// the spatially coherent triangle order.
class VertexStars {
public:
    /// @p hard_edges: per triangle, bit e set when edge e is a hard breakline.
    VertexStars(const Tin& tin, std::span<const std::uint8_t> hard_edges);

    /// The used vertices in first-use order; a vertex's position in it is its rank. The
    /// functions below take ranks, so that a pass in rank order reads memory in order.
    [[nodiscard]] const BigArray<VertexIndex>& order() const { return order_; }
    /// Rank of @p v (no_vertex for an unused vertex).
    [[nodiscard]] std::uint32_t rank(VertexIndex v) const { return rank_[v]; }
    [[nodiscard]] std::uint32_t corner_count(std::uint32_t rank) const { return count_[rank]; }
    [[nodiscard]] std::uint32_t fan_count(std::uint32_t rank) const {
        return fan_offsets_[rank + 1] - fan_offsets_[rank];
    }
    /// Does a hard breakline end at the vertex of @p rank?
    [[nodiscard]] bool on_hard_edge(std::uint32_t rank) const { return split_[rank] != 0; }

    [[nodiscard]] VertexIndex vertex(Corner c) const {
        return tin_.triangles[c.t].v[static_cast<std::size_t>(c.i)];
    }
    /// Is the edge from corner c to corner c.i + k (k = 1, 2) a hard breakline?
    [[nodiscard]] bool hard(Corner c, int k) const {
        return ((hard_[c.t] >> ((c.i + 3 - k) % 3)) & 1U) != 0;
    }
    /// The next corner counter-clockwise around the vertex (across the edge to corner i + 2),
    /// or t == no_triangle at the border.
    [[nodiscard]] Corner ccw(Corner c) const { return across(c, (c.i + 1) % 3); }
    /// The next corner clockwise (across the edge to corner i + 1).
    [[nodiscard]] Corner cw(Corner c) const { return across(c, (c.i + 2) % 3); }

    /// For every fan of the vertex of @p rank: begin(open), then fn(corner) counter-clockwise
    /// from its start (an open fan starts at its clockwise-most triangle; a closed one at the
    /// triangle after its first hard edge, or anywhere).
    template <class Begin, class Fn>
    void for_each_fan(std::uint32_t rank, Begin&& begin, Fn&& fn) const {
        for (std::uint32_t f = fan_offsets_[rank]; f < fan_offsets_[rank + 1]; ++f) {
            const Corner start = fan_starts_[f];
            begin(cw(start).t == no_triangle);
            Corner c = start;
            for (std::size_t k = 0; k <= tin_.triangles.size(); ++k) {
                fn(c);
                c = ccw(c);
                if (c.t == no_triangle || c.t == start.t) {
                    break;
                }
            }
        }
    }

private:
    [[nodiscard]] Corner across(Corner c, int e) const {
        const TriangleIndex u = tin_.triangles[c.t].n[static_cast<std::size_t>(e)];
        if (u == no_triangle) {
            return {};
        }
        const VertexIndex v = vertex(c);
        const auto& uv = tin_.triangles[u].v;
        return {u, uv[0] == v ? 0 : (uv[1] == v ? 1 : 2)};
    }
    [[nodiscard]] Corner open_fan_start(Corner c) const;
    [[nodiscard]] Corner after_first_hard_edge(Corner c) const;

    const Tin& tin_;
    std::span<const std::uint8_t> hard_;
    BigArray<VertexIndex> order_;          ///< rank -> vertex
    BigArray<std::uint32_t> rank_;         ///< vertex -> rank
    BigArray<std::uint32_t> count_;        ///< per rank: corners
    BigArray<std::uint8_t> split_;         ///< per rank: on a hard breakline
    BigArray<std::uint32_t> fan_offsets_;  ///< per rank: its fans in fan_starts_
    BigArray<Corner> fan_starts_;
};

/// Sectors: the runs of a vertex's fans between hard breakline edges. The vertex of rank k has
/// its first sector k; vertices on hard breaklines get further sectors numbered from the used
/// vertex count on. Fills @p corner_sector (per triangle) and @p sector_vertex (per sector).
void number_sectors(const Tin& tin,
                    const VertexStars& stars,
                    std::vector<std::array<std::uint32_t, 3>>& corner_sector,
                    std::vector<VertexIndex>& sector_vertex);

}  // namespace dtm::detail
