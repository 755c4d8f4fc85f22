// SPDX-License-Identifier: MIT
/// @file
/// @brief Hash of an xy position for open-addressing tables of exact duplicates.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

namespace dtm::detail {

/// Slot of position (x, y) in a table of @p capacity slots (a power of two). -0.0 and 0.0 hash
/// alike, as they compare equal.
inline std::size_t position_slot(double x, double y, std::size_t capacity) noexcept
{
    const auto bits = [](double v) { return std::bit_cast<std::uint64_t>(v == 0.0 ? 0.0 : v); };
    const std::uint64_t bx = bits(x);
    const std::uint64_t by = bits(y);
    std::uint64_t h = (bx * 0x9e3779b97f4a7c15ull) ^ (by + 0x7f4a7c159e3779b9ull + (bx << 6));
    h ^= h >> 29;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 32;
    return static_cast<std::size_t>(h) & (capacity - 1);
}

/// The smallest power of two of at least twice @p count (at least 16): a table half empty.
inline std::size_t position_table_capacity(std::size_t count) noexcept
{
    std::size_t capacity = 16;
    while (capacity < 2 * count) capacity *= 2;
    return capacity;
}

}  // namespace dtm::detail
