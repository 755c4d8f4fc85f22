// SPDX-License-Identifier: MIT
/// @file
/// @brief The exact clipping behind Thiessen polygons (algo/thiessen.cpp): one Voronoi region
/// intersected with one triangle of the clip region, by Sutherland and Hodgman's algorithm on a
/// convex polygon whose vertices are symbolic (an input point, the crossing of a region edge with
/// a bisector, the meeting of two bisectors), so that every inside/outside decision is an exact
/// predicate on input coordinates; and the pieces of one region merged into polygons.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dtm/algo/thiessen.hpp"

namespace dtm::detail {

/// A symbolic vertex. input: region vertex a. edge: the crossing of region edge a-b (a < b) with
/// the bisector of the cell's site and site c. bisectors: the meeting of the bisectors of the
/// cell's site with sites a and b (a < b), a Voronoi vertex.
struct Sym {
    enum Kind : std::uint8_t { input, edge, bisectors } kind = input;
    std::uint32_t a = 0, b = 0, c = 0;
    friend bool operator==(const Sym&, const Sym&) = default;
    friend auto operator<=>(const Sym&, const Sym&) = default;
};

/// The line an edge of a piece lies on: region edge a -> b, or the bisector with site a.
struct Support {
    enum Kind : std::uint8_t { region_edge, bisector } kind = region_edge;
    std::uint32_t a = 0, b = 0;
};

struct PieceVertex {
    Sym at;
    Support out;  ///< the edge from this vertex to the next
};
using Piece = std::vector<PieceVertex>;

class CellClipper {
public:
    CellClipper(std::span<const Point3> sites, std::span<const Point3> region_vertices)
        : sites_(sites), region_(region_vertices) {}

    /// The region of site @p g (the half-planes towards its Voronoi neighbours @p neighbours,
    /// in increasing order) intersected with the counter-clockwise triangle @p tri of region
    /// vertices. @p out is left empty when the intersection has no area.
    void clip(std::uint32_t g,
              std::span<const VertexIndex> neighbours,
              const std::array<VertexIndex, 3>& tri,
              Piece& out) const;

    /// Coordinates of @p v in the cell of site @p g (the same for every cell sharing it).
    [[nodiscard]] Point2 position(std::uint32_t g, const Sym& v) const;

private:
    std::span<const Point3> sites_;
    std::span<const Point3> region_;

    /// > 0: v is strictly nearer to site k than to g (outside g's half-plane), 0 on the
    /// bisector, < 0 inside.
    [[nodiscard]] int side(std::uint32_t g, const Sym& v, std::uint32_t k) const;
    [[nodiscard]] Sym crossing(const Support& s, std::uint32_t k) const;
};

/// The polygons of site @p g's cell from its @p pieces (one per region triangle it meets):
/// the two copies of each region edge between two pieces cancel, the remaining edges are linked
/// into rings, grouped into polygons (rings with a bisector edge are outer rings; rings of region
/// edges alone keep the region's orientation: outer or hole).
void merge_pieces(std::uint32_t g,
                  const std::vector<Piece>& pieces,
                  const CellClipper& clipper,
                  std::span<const Point3> region_vertices,
                  ThiessenCell& out);

}  // namespace dtm::detail
