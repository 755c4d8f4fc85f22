// SPDX-License-Identifier: MIT
/// @file
/// @brief Which segments meet a triangle (closed sets, exact predicates), through a uniform grid
/// over the segments: the distributed constraint insertion's first test (dist/constraints.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dist/global_mesh.hpp"

namespace dtm::dist {

struct TouchSegment {
    XY p;
    XY q;
};

/// Whether the closed segment @p s meets the closed triangle @p t (counter-clockwise) or, with
/// @p hull_edge, the closed segment t[0]-t[1].
[[nodiscard]] bool segment_touches(const TouchSegment& s,
                                   const std::array<XY, 3>& t,
                                   bool hull_edge);

/// A uniform grid of square cells about the median segment's length; each segment is listed in
/// every cell its bounding strip reaches in each row (a superset of the cells it crosses).
class SegmentGrid {
public:
    explicit SegmentGrid(const std::vector<TouchSegment>& segments);
    /// Appends to @p out every segment meeting the triangle (as segment_touches), ascending.
    void touching(const std::array<XY, 3>& t,
                  bool hull_edge,
                  std::vector<std::uint32_t>& out) const;

private:
    [[nodiscard]] std::uint32_t column(double x) const noexcept;
    [[nodiscard]] std::uint32_t row(double y) const noexcept;
    template <class Visit>
    void cells_of(const TouchSegment& s, Visit&& visit) const;

    const std::vector<TouchSegment>& segments_;
    double x0_ = 0.0, y0_ = 0.0, w_ = 1.0, h_ = 1.0;
    std::uint32_t columns_ = 1, rows_ = 1;
    std::vector<std::uint64_t> offsets_;  ///< per cell, into ids_ (CSR)
    std::vector<std::uint32_t> ids_;
};

}  // namespace dtm::dist
