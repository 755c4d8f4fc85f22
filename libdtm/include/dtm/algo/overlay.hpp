// SPDX-License-Identifier: MIT
/// @file
/// @brief The overlay of two TINs: every region where a triangle of one surface overlaps a
/// triangle of the other, as a convex polygon with the heights of both surfaces at its corners.
/// Volumes, difference surfaces and cut/fill maps are built on it.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>

#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

/// What a corner of an overlay piece is.
enum class CornerKind : std::uint8_t {
    top_vertex,   ///< a vertex of the top TIN (possibly also a base vertex at the same place)
    base_vertex,  ///< a vertex of the base TIN
    crossing,     ///< where an edge of the top TIN properly crosses an edge of the base TIN
};

/// A corner of an overlay piece. Every piece that has the same corner gets the same bits for it
/// (crossings are computed from the two edges in a fixed direction), so pieces fit together.
struct OverlayCorner {
    double x = 0.0;
    double y = 0.0;
    double z_top = 0.0;   ///< height of the top surface here
    double z_base = 0.0;  ///< height of the base surface here
    CornerKind kind = CornerKind::top_vertex;
    /// top_vertex: top_u is the vertex; base_vertex: base_u is the vertex; crossing: the top edge
    /// (top_u < top_v) and the base edge (base_u < base_v). Unused fields are no_vertex.
    VertexIndex top_u = no_vertex;
    VertexIndex top_v = no_vertex;
    VertexIndex base_u = no_vertex;
    VertexIndex base_v = no_vertex;
};

/// The intersection of one top triangle with one base triangle, of positive area.
struct OverlayPiece {
    TriangleIndex top_triangle = no_triangle;
    TriangleIndex base_triangle = no_triangle;  ///< no_triangle when the base is a plane
    std::array<double, 2> top_slope{};          ///< dz/dx, dz/dy of the top triangle's plane
    std::array<double, 2> base_slope{};         ///< the same for the base triangle
    std::span<const OverlayCorner> corners;     ///< counter-clockwise convex polygon, >= 3 corners
};

struct OverlayOptions {
    unsigned threads = 0;               ///< worker threads (0: all cores); never changes the result
    std::size_t chunk_triangles = 256;  ///< top triangles per chunk
};

/// Receives the pieces of one chunk of consecutive top triangles, from one worker thread at a
/// time per chunk (chunks run in parallel; chunk numbers are 0 .. chunk_count() - 1, in the order
/// of the top TIN's triangles, so per-chunk results combined in chunk order are deterministic).
using OverlayChunkFn = std::function<void(std::size_t chunk, std::span<const OverlayPiece> pieces)>;

/// The overlay of a top TIN with a base TIN or with a horizontal base plane.
/// Which triangles overlap, which corners each piece has (a vertex inside the other triangle,
/// an edge crossing) are decided exactly with orient2d on the input coordinates; only the
/// coordinates of crossings and the interpolated heights are computed in floating point.
class TinOverlay {
public:
    /// Indexes @p base; both TINs must outlive the overlay.
    TinOverlay(const Tin& top, const Tin& base, const OverlayOptions& options = {});
    /// A horizontal plane at @p base_z under (or over) the whole top TIN: the pieces are the top
    /// triangles themselves.
    TinOverlay(const Tin& top, double base_z, const OverlayOptions& options = {});
    TinOverlay(const TinOverlay&) = delete;
    TinOverlay& operator=(const TinOverlay&) = delete;
    ~TinOverlay();

    [[nodiscard]] std::size_t chunk_count() const noexcept;
    /// Computes every piece and passes them chunk by chunk to @p fn. @throws Cancelled
    void run(const OverlayChunkFn& fn, const Progress& progress = {}) const;
    /// Same, but @p fn is called on one thread at a time in chunk order (pieces are still
    /// computed in parallel, a few chunks ahead): for consumers that number what they see.
    void run_ordered(const OverlayChunkFn& fn, const Progress& progress = {}) const;
    /// Vertex counts of the two TINs (base 0 for a plane).
    void vertex_counts(std::size_t& top, std::size_t& base) const noexcept;
    /// Heap bytes of the index over the base.
    [[nodiscard]] std::size_t index_bytes() const noexcept;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace dtm
