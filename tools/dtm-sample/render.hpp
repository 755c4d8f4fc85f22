// SPDX-License-Identifier: MIT
/// @file
/// @brief Renders the README picture from the products of `dtm build`: the DEM in the terrain
/// ramp of the QGIS project multiplied over its hillshade, with contours and outlines burnt in.
#pragma once

#include <filesystem>
#include <vector>

namespace dtm::sample {

struct RenderOptions {
    double z_factor = 4.0;  ///< vertical exaggeration of the hillshade
    /// Line files burnt in blue (breaklines). Holes and the outside of the boundary are NoData in
    /// the DEM and stay white.
    std::vector<std::filesystem::path> breaklines;
};

/// Reads dem.tif and contours.gpkg from @p build_dir and writes the picture to @p png.
/// @throws std::runtime_error naming the GDAL step that failed.
void render_picture(const std::filesystem::path& build_dir,
                    const std::filesystem::path& png,
                    const RenderOptions& options);

}  // namespace dtm::sample
