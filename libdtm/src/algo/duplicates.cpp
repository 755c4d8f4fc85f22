// SPDX-License-Identifier: MIT
//
// Counting repeated xy positions with an open-addressing table of indices (half empty, so probes
// are short), the same hashing as the duplicate merge of triangulate() (detail/input_merge.cpp).
#include "dtm/algo/duplicates.hpp"

#include <cstdint>
#include <vector>

#include "algo/detail/position_hash.hpp"

namespace dtm {

std::size_t count_repeated_positions(std::span<const Point3> points)
{
    constexpr std::uint32_t empty = 0xffffffffu;
    const std::size_t capacity = detail::position_table_capacity(points.size());
    std::vector<std::uint32_t> table(capacity, empty);
    std::size_t repeated = 0;
    constexpr std::size_t ahead = 16;  // prefetch distance: the table is far larger than the caches
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i + ahead < points.size()) {
            const Point3& next = points[i + ahead];
            __builtin_prefetch(&table[detail::position_slot(next.x, next.y, capacity)]);
        }
        const Point3& p = points[i];
        for (std::size_t slot = detail::position_slot(p.x, p.y, capacity);;
             slot = (slot + 1) & (capacity - 1)) {
            const std::uint32_t j = table[slot];
            if (j == empty) {
                table[slot] = static_cast<std::uint32_t>(i);
                break;
            }
            if (points[j].x == p.x && points[j].y == p.y) {
                ++repeated;
                break;
            }
        }
    }
    return repeated;
}

}  // namespace dtm
