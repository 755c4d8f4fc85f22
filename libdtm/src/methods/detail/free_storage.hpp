// SPDX-License-Identifier: MIT
/// @file
/// @brief Freeing a container's memory before the next phase of a method.
#pragma once

namespace dtm::methods::detail {

/// Replaces @p x by an empty value, freeing its heap storage now. `x = {}` does not do this
/// for a std::vector or an unordered map: it picks their initializer-list assignment, which
/// empties the container and keeps its capacity.
template <class T>
void free_storage(T& x) {
    x = T();
}

}  // namespace dtm::methods::detail
