// SPDX-License-Identifier: MIT
// Vertex stars and sectors. One sequential pass over the corners finds each vertex's first
// corner, its number of corners and of border edges (a vertex with two is on the border, with
// more it is a pinch point whose fans start at every corner without a clockwise neighbour);
// open fans are then walked clockwise to their start, in parallel. Sectors of vertices on hard
// breaklines are numbered by walking their fans.
#include "algo/detail/vertex_stars.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>

namespace dtm::detail {

VertexStars::VertexStars(const Tin& tin, std::span<const std::uint8_t> hard_edges)
    : tin_(tin), hard_(hard_edges) {
    const std::size_t n = tin.vertices.size();
    rank_.assign(n, no_vertex);
    order_.reserve(n);
    BigArray<std::uint32_t> first;  // per rank: its first corner
    first.reserve(n);
    // Ranks in first-use order; the other per-vertex data are indexed by rank, so that after
    // this pass every array is read in the triangles' order.
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        for (std::size_t i = 0; i < 3; ++i) {
            const VertexIndex v = tin.triangles[t].v[i];
            if (rank_[v] == no_vertex) {
                rank_[v] = static_cast<std::uint32_t>(order_.size());
                order_.push_back(v);
                first.push_back(static_cast<std::uint32_t>(3 * t + i));
            }
        }
    }
    const std::size_t used = order_.size();
    BigArray<std::uint8_t> border(used, 0);
    count_.assign(used, 0);
    split_.assign(used, 0);
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const Triangle& tri = tin.triangles[t];
        for (std::size_t i = 0; i < 3; ++i) {
            ++count_[rank_[tri.v[i]]];
            const std::uint32_t a = rank_[tri.v[(i + 1) % 3]], b = rank_[tri.v[(i + 2) % 3]];
            if (tri.n[i] == no_triangle) {
                border[a] = static_cast<std::uint8_t>(std::min(border[a] + 1, 255));
                border[b] = static_cast<std::uint8_t>(std::min(border[b] + 1, 255));
            }
            if ((hard_[t] >> i) & 1U) {
                split_[a] = split_[b] = 1;
            }
        }
    }
    // Fans: one per vertex except at pinch points (more than two border edges).
    std::vector<std::vector<Corner>> pinched;
    if (std::find_if(border.begin(), border.end(), [](std::uint8_t b) { return b > 2; }) !=
        border.end()) {
        pinched.resize(used);
        for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
            for (int i = 0; i < 3; ++i) {
                const Corner c{static_cast<TriangleIndex>(t), i};
                const std::uint32_t r = rank_[vertex(c)];
                if (border[r] > 2 && cw(c).t == no_triangle) {
                    pinched[r].push_back(c);
                }
            }
        }
    }
    fan_offsets_.assign(used + 1, 0);
    for (std::size_t r = 0; r < used; ++r) {
        const std::size_t fans = border[r] > 2 ? pinched[r].size() : 1;
        fan_offsets_[r + 1] = fan_offsets_[r] + static_cast<std::uint32_t>(fans);
    }
    fan_starts_.resize(fan_offsets_.back());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, used, 1 << 13),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          for (std::size_t r = range.begin(); r != range.end(); ++r) {
                              std::uint32_t f = fan_offsets_[r];
                              if (border[r] > 2) {
                                  for (const Corner c : pinched[r]) {
                                      fan_starts_[f++] = c;
                                  }
                                  continue;
                              }
                              const Corner c{first[r] / 3, static_cast<int>(first[r] % 3)};
                              fan_starts_[f] = border[r] > 0 ? open_fan_start(c)
                                               : split_[r]   ? after_first_hard_edge(c)
                                                             : c;
                          }
                      });
}

Corner VertexStars::open_fan_start(Corner c) const {
    for (std::size_t k = 0; k <= tin_.triangles.size(); ++k) {
        const Corner prev = cw(c);
        if (prev.t == no_triangle) {
            break;
        }
        c = prev;
    }
    return c;
}

Corner VertexStars::after_first_hard_edge(Corner c) const {
    const Corner start = c;
    for (std::size_t k = 0; k <= tin_.triangles.size(); ++k) {
        const Corner next = ccw(c);
        if (hard(c, 2)) {
            return next;
        }
        if (next.t == start.t) {
            break;
        }
        c = next;
    }
    return start;
}

void number_sectors(const Tin& tin,
                    const VertexStars& stars,
                    std::vector<std::array<std::uint32_t, 3>>& corner_sector,
                    std::vector<VertexIndex>& sector_vertex) {
    corner_sector.resize(tin.triangles.size());
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t t = r.begin(); t != r.end(); ++t) {
                              for (std::size_t i = 0; i < 3; ++i) {
                                  corner_sector[t][i] = stars.rank(tin.triangles[t].v[i]);
                              }
                          }
                      });
    sector_vertex.assign(stars.order().begin(), stars.order().end());
    for (std::uint32_t rank = 0; rank < stars.order().size(); ++rank) {
        if (!stars.on_hard_edge(rank)) {
            continue;
        }
        const VertexIndex v = stars.order()[rank];
        // Each fan starts after a hard edge (or at its open end); a new sector begins after
        // every hard edge crossed. The vertex's first sector is its rank.
        bool first_fan = true, first_corner = true;
        std::uint32_t sector = 0;
        const auto new_sector = [&] {
            sector = static_cast<std::uint32_t>(sector_vertex.size());
            sector_vertex.push_back(v);
        };
        stars.for_each_fan(
            rank,
            [&](bool) {
                if (first_fan) {
                    sector = rank;
                    first_fan = false;
                } else {
                    new_sector();
                }
                first_corner = true;
            },
            [&](Corner c) {
                if (!first_corner && stars.hard(c, 1)) {
                    new_sector();
                }
                first_corner = false;
                corner_sector[c.t][static_cast<std::size_t>(c.i)] = sector;
            });
    }
}

}  // namespace dtm::detail
