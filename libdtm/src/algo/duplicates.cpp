// SPDX-License-Identifier: MIT
//
// Counting repeated xy positions with the duplicate search of triangulate()
// (detail/exact_duplicates.cpp).
#include "dtm/algo/duplicates.hpp"

#include <vector>

#include "algo/detail/exact_duplicates.hpp"

namespace dtm {

std::size_t count_repeated_positions(std::span<const Point3> points) {
    const detail::BigArray<VertexIndex> first = detail::first_occurrences(points);
    std::size_t repeated = 0;
    for (std::size_t i = 0; i < first.size(); ++i) repeated += first[i] != i ? 1 : 0;
    return repeated;
}

}  // namespace dtm
