// SPDX-License-Identifier: MIT
#include "algo/detail/label_index.hpp"

#include <algorithm>
#include <utility>

namespace dtm::detail {

void BoxIndex::insert(const LabelBox& box) {
    const auto id = static_cast<std::uint32_t>(boxes_.size());
    boxes_.push_back(box);
    seen_.push_back(0);
    grid_.for_cells(box.bounds(), [&](std::uint64_t key) { cells_[key].push_back(id); });
}

bool BoxIndex::overlaps_any(const LabelBox& box) const {
    if (++stamp_ == 0) {  // wrapped: forget every stamp
        std::fill(seen_.begin(), seen_.end(), 0U);
        stamp_ = 1;
    }
    bool hit = false;
    grid_.for_cells(box.bounds(), [&](std::uint64_t key) {
        if (hit) return;
        const auto it = cells_.find(key);
        if (it == cells_.end()) return;
        for (const std::uint32_t id : it->second) {
            if (seen_[id] == stamp_) continue;
            seen_[id] = stamp_;
            if (overlaps(box, boxes_[id])) {
                hit = true;
                return;
            }
        }
    });
    return hit;
}

SegmentIndex::SegmentIndex(std::span<const LinePoints> lines, double cell)
    : lines_(lines), grid_(cell) {
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    for (std::size_t l = 0; l < lines.size(); ++l) {
        for (std::size_t i = 0; i + 1 < lines[l].size(); ++i) {
            const auto id = static_cast<std::uint32_t>(segments_.size());
            segments_.push_back({static_cast<std::uint32_t>(l), static_cast<std::uint32_t>(i)});
            Box2 b;
            b.add(lines[l][i]);
            b.add(lines[l][i + 1]);
            grid_.for_cells(b, [&](std::uint64_t key) { entries.emplace_back(key, id); });
        }
    }
    std::sort(entries.begin(), entries.end());
    members_.reserve(entries.size());
    cells_.reserve(entries.size() / 4 + 1);
    for (std::size_t i = 0; i < entries.size();) {
        std::size_t j = i;
        while (j < entries.size() && entries[j].first == entries[i].first) {
            members_.push_back(entries[j].second);
            ++j;
        }
        cells_.emplace(entries[i].first, std::make_pair(static_cast<std::uint32_t>(i),
                                                        static_cast<std::uint32_t>(j)));
        i = j;
    }
    seen_.assign(segments_.size(), 0U);
}

void SegmentIndex::next_stamp() const {
    if (++stamp_ == 0) {
        std::fill(seen_.begin(), seen_.end(), 0U);
        stamp_ = 1;
    }
}

}  // namespace dtm::detail
