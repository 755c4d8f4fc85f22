// SPDX-License-Identifier: MIT
/// @file
/// @brief TIN to DEM: the TIN surface (linear, cubic or natural neighbour) sampled at cell
/// centres, streamed in row bands to a sink so that a big raster never sits in memory at once.
#pragma once

#include <cstddef>
#include <span>

#include "dtm/algo/interpolation.hpp"
#include "dtm/core/grid.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct RasterizeOptions {
    float nodata = -9999.0F;  ///< value of cells whose centre lies outside every triangle
    /// Rows per band (0: automatic, about one million cells per band). Memory in flight is about
    /// (2 x threads + 1) bands of Float32.
    std::size_t band_rows = 0;
    unsigned threads = 0;  ///< worker threads (0: all cores); never changes the result
    /// The surface sampled (see interpolation.hpp); ignored by the overload that takes a
    /// prepared TinInterpolant.
    Interpolation interpolation = Interpolation::linear;
    GradientOptions gradients{};  ///< for Interpolation::cubic
    /// The rows computed: [first_row, first_row + row_count) of the spec (row_count 0: to the
    /// last row). The sink gets only these, with their row numbers in the spec, and each cell
    /// has the value the whole raster gives it (one rank's part of a tiled DEM).
    std::size_t first_row = 0;
    std::size_t row_count = 0;
};

/// The rows of @p spec whose centre line may meet the y-interval [ylo, yhi] (conservative: a
/// superset), as [first, last]; false if there are none. Which triangles a row band needs.
[[nodiscard]] bool rows_touching(
    const GridSpec& spec, double ylo, double yhi, std::size_t& first, std::size_t& last);

/// Receives the raster in consecutive bands of whole rows, north to south, from one thread at a
/// time. Implemented by raster writers (GDAL), by tests, and by the in-memory collector.
class GridSink {
public:
    virtual ~GridSink() = default;
    /// @param first_row index of the first row of the band
    /// @param row_count rows in the band
    /// @param values    row_count x spec.cols values, row-major
    virtual void write_rows(std::size_t first_row,
                            std::size_t row_count,
                            std::span<const float> values) = 0;
};

/// Samples the TIN surface at every cell centre of @p spec and streams the rows to @p sink.
/// A centre inside a triangle (or on its edge) gets the surface's height there (linear: the
/// plane of the triangle's vertices); a centre outside every triangle (outside the hull, the
/// boundary, in a hole) gets options.nodata. Inside tests are exact (orient2d); a centre on an
/// edge shared by two triangles is assigned to exactly one of them and gets the same value from
/// either (linear and cubic: the edge's own curve, evaluated from its lexicographically smaller
/// end, so vertex numbers never matter); a centre on a vertex gets the vertex height.
/// Bands are computed in parallel and handed to the sink in order. Memory: the bands in flight
/// plus a copy of the TIN with its vertices renumbered in first-use order (cache-friendly reads).
/// @throws Cancelled
void rasterize(const Tin& tin,
               const GridSpec& spec,
               const RasterizeOptions& options,
               GridSink& sink,
               const Progress& progress = {});

/// Same, sampling a prepared interpolant of @p tin (options.interpolation is ignored), so that
/// a DEM and contours can share one gradient estimate.
void rasterize(const Tin& tin,
               const TinInterpolant& interpolant,
               const GridSpec& spec,
               const RasterizeOptions& options,
               GridSink& sink,
               const Progress& progress = {});

/// Convenience for small rasters: the whole grid in memory.
[[nodiscard]] Grid rasterize(const Tin& tin,
                             const GridSpec& spec,
                             const RasterizeOptions& options = {},
                             const Progress& progress = {});

/// Bounding box of the TIN's triangle vertices in xy (empty if there are no triangles).
[[nodiscard]] Box2 tin_bounds(const Tin& tin);

}  // namespace dtm
