// SPDX-License-Identifier: MIT
/// @file
/// @brief The active edge list of the advancing-front methods (lecture 004's AEL, DeWall's
/// AFL): directed edges whose left side is still to be triangulated. Adding a triangle closes
/// each of its edges that is in the list and opens the reverse of every other one.
#pragma once

#include <cstdint>
#include <deque>
#include <unordered_set>

#include "dtm/core/tin.hpp"

namespace dtm::methods::detail {

class ActiveEdges {
public:
    struct Edge {
        VertexIndex a;
        VertexIndex b;
    };

    [[nodiscard]] static std::uint64_t key(VertexIndex a, VertexIndex b) noexcept {
        return (static_cast<std::uint64_t>(a) << 32) | b;
    }
    [[nodiscard]] bool contains(VertexIndex a, VertexIndex b) const {
        return live_.count(key(a, b)) != 0;
    }
    void open(VertexIndex a, VertexIndex b) {
        if (live_.insert(key(a, b)).second) queue_.push_back({a, b});
    }
    void close(VertexIndex a, VertexIndex b) { live_.erase(key(a, b)); }
    /// The triangle (a, b, c) counter-clockwise was made on the left of the active edge a->b
    /// (already taken): its other edges close their twins or open their reverses.
    void add_triangle(VertexIndex a, VertexIndex b, VertexIndex c) {
        for (const Edge e : {Edge{b, c}, Edge{c, a}}) {
            if (contains(e.a, e.b)) {
                close(e.a, e.b);
            } else {
                open(e.b, e.a);
            }
        }
    }
    /// The next active edge (first in, first out), false when none is left.
    bool take(Edge& e) {
        while (!queue_.empty()) {
            e = queue_.front();
            queue_.pop_front();
            if (live_.erase(key(e.a, e.b)) != 0) return true;
        }
        return false;
    }
    [[nodiscard]] std::size_t size() const noexcept { return live_.size(); }
    [[nodiscard]] std::size_t bytes() const noexcept {
        // Buckets, nodes (key + next pointer + hash), the queue's blocks.
        return live_.bucket_count() * sizeof(void*) + live_.size() * 32 +
               queue_.size() * sizeof(Edge);
    }

private:
    std::unordered_set<std::uint64_t> live_;
    std::deque<Edge> queue_;
};

}  // namespace dtm::methods::detail
