// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: giving the pages of an array's consumed front back to the system while the
/// array lives on (a rank's peak memory when one large array is turned into another).
#pragma once

#include <cstdint>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dtm::dist {

/// Gives the whole pages inside [from, to) back to the system: their contents must not be read
/// again (they read as zeros if they are). Pages dropped before cost little to drop again.
inline void drop_pages(const void* from, const void* to) noexcept {
#if defined(__linux__)
    constexpr std::uintptr_t page = 4096;
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(from) + page - 1) / page * page;
    const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(to) / page * page;
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_DONTNEED);
#else
    (void)from;
    (void)to;
#endif
}

}  // namespace dtm::dist
