// SPDX-License-Identifier: MIT
/// @file
/// @brief Kirkpatrick's point-location hierarchy (1983; thesis 000 §3.8.2 after [PREP85]):
/// from a triangulation inside a big triangle, repeatedly remove an independent set of
/// vertices of degree < 12 (never the big triangle's corners) and retriangulate the holes,
/// until only the big triangle is left; every new triangle points to the triangles of the
/// level below that it overlaps. A query descends from the big triangle, at each level into
/// the child that contains the point.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "dtm/core/tin.hpp"
#include "methods/detail/super_triangle.hpp"

namespace dtm::methods::detail {

class KirkpatrickHierarchy {
public:
    using Corners = std::array<VertexIndex, 3>;

    /// Builds the hierarchy of the triangulation @p triangles (counter-clockwise corners, the
    /// whole big triangle covered; vertex ids below @p vertex_count, the corners of @p st are
    /// never removed), which it keeps as its lowest level. Predicates through @p st.
    void build(std::vector<Corners> triangles, std::size_t vertex_count, SuperTriangle& st);

    /// A triangle of the lowest level (the triangulation given to build) containing @p q
    /// (closed); @p steps counts the triangles tested.
    [[nodiscard]] Corners locate(VertexIndex q, SuperTriangle& st, std::uint64_t& steps) const;

    [[nodiscard]] bool empty() const noexcept { return corners_.empty(); }
    [[nodiscard]] std::size_t levels() const noexcept { return levels_; }
    [[nodiscard]] std::size_t nodes() const noexcept { return corners_.size(); }
    [[nodiscard]] std::size_t bytes() const noexcept {
        return corners_.capacity() * sizeof(Corners) +
               (first_child_.capacity() + children_.capacity()) * sizeof(std::uint32_t);
    }
    /// Largest number of children of a node (Kirkpatrick's H).
    [[nodiscard]] std::size_t max_children() const noexcept { return max_children_; }

private:
    /// Nodes are numbered leaves first (the lowest level, no children), then the inner nodes
    /// in the order they were made. Inner node k (node leaves_ + k) has the children
    /// children_[first_child_[k], first_child_[k + 1]): made together, they lie side by side.
    std::vector<Corners> corners_;            ///< per node
    std::vector<std::uint32_t> first_child_;  ///< per inner node, and one past the last
    std::vector<std::uint32_t> children_;
    std::size_t leaves_ = 0;
    std::uint32_t root_ = 0;
    std::size_t levels_ = 0;
    std::size_t max_children_ = 0;
};

}  // namespace dtm::methods::detail
