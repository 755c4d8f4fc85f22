// SPDX-License-Identifier: MIT
// Uniform-grid indexes for label placement: the boxes placed so far (and obstacles), and the
// segments of every line that a label must not be crossed by. Cells are square, in CRS units;
// a box or segment is registered in every cell its bounding box touches.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "dtm/algo/label_box.hpp"
#include "dtm/core/point.hpp"

namespace dtm::detail {

/// Integer cell coordinates of a square grid anchored at the origin.
class CellGrid {
public:
    explicit CellGrid(double cell) : cell_(cell > 0.0 && std::isfinite(cell) ? cell : 1.0) {}
    [[nodiscard]] std::int64_t index(double v) const noexcept {
        return static_cast<std::int64_t>(std::floor(v / cell_));
    }
    [[nodiscard]] static std::uint64_t key(std::int64_t i, std::int64_t j) noexcept {
        return (static_cast<std::uint64_t>(i) << 32) ^
               (static_cast<std::uint64_t>(j) & 0xffffffffU);
    }
    /// Calls f(key) for every cell that @p box touches.
    template <class F>
    void for_cells(const Box2& box, F&& f) const {
        const std::int64_t i0 = index(box.xmin), i1 = index(box.xmax);
        const std::int64_t j0 = index(box.ymin), j1 = index(box.ymax);
        for (std::int64_t i = i0; i <= i1; ++i) {
            for (std::int64_t j = j0; j <= j1; ++j) f(key(i, j));
        }
    }

private:
    double cell_;
};

/// Boxes placed so far; answers "does this box overlap any of them?".
class BoxIndex {
public:
    explicit BoxIndex(double cell) : grid_(cell) {}
    void insert(const LabelBox& box);
    [[nodiscard]] bool overlaps_any(const LabelBox& box) const;
    [[nodiscard]] std::size_t size() const noexcept { return boxes_.size(); }

private:
    CellGrid grid_;
    std::vector<LabelBox> boxes_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
    mutable std::vector<std::uint32_t> seen_;  // per box: the query stamp that last saw it
    mutable std::uint32_t stamp_ = 0;
};

/// A polyline handed to SegmentIndex: its points in CRS units.
using LinePoints = std::span<const Point2>;

/// The segments of a fixed set of polylines; answers "which segments pass through this box?".
class SegmentIndex {
public:
    SegmentIndex(std::span<const LinePoints> lines, double cell);
    /// Calls f(line, first_vertex) for every segment crossing the interior of @p box; stops early
    /// and returns true as soon as f returns true.
    template <class F>
    bool any_crossing(const LabelBox& box, F&& f) const {
        next_stamp();
        bool hit = false;
        grid_.for_cells(box.bounds(), [&](std::uint64_t key) {
            if (hit) return;
            const auto it = cells_.find(key);
            if (it == cells_.end()) return;
            for (std::uint32_t s = it->second.first; s < it->second.second && !hit; ++s) {
                const std::uint32_t id = members_[s];
                if (seen_[id] == stamp_) continue;
                seen_[id] = stamp_;
                const Segment& seg = segments_[id];
                const Point2 p = lines_[seg.line][seg.first];
                const Point2 q = lines_[seg.line][seg.first + 1];
                if (crosses(box, p, q) && f(seg.line, seg.first)) hit = true;
            }
        });
        return hit;
    }

private:
    struct Segment {
        std::uint32_t line;
        std::uint32_t first;
    };
    void next_stamp() const;

    std::span<const LinePoints> lines_;
    CellGrid grid_;
    std::vector<Segment> segments_;
    std::vector<std::uint32_t> members_;  // segment ids grouped by cell
    std::unordered_map<std::uint64_t, std::pair<std::uint32_t, std::uint32_t>> cells_;
    mutable std::vector<std::uint32_t> seen_;
    mutable std::uint32_t stamp_ = 0;
};

}  // namespace dtm::detail
