// SPDX-License-Identifier: MIT
/// @file
/// @brief The map product: a survey in, the contour map sheet out (`dtm map`), and the scale
/// rule of the map.pdf that products::build() writes. The drawing is io::map::write_map.
#pragma once

#include <filesystem>

#include "dtm/algo/triangulate.hpp"
#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/map/map.hpp"

namespace dtm::products {

struct MapJob {
    TriangulateOptions triangulate;
    io::map::MapOptions map;  ///< crs_wkt and sources are filled from the inputs when empty
};

/// Reads @p inputs, takes their surface (products::surface: a TIN as it is, else triangulated)
/// and draws the map sheet into @p output (.pdf, .svg or .png), atomically.
/// @throws InputError, UsageError (see io::map::write_map), Error, Cancelled
[[nodiscard]] io::map::MapReport map(const io::LoadOptions& inputs,
                                     const std::filesystem::path& output,
                                     MapJob job,
                                     const Progress& progress = {});

/// The scale of build's map.pdf, an A3 sheet centred on the site: the largest usual survey
/// scale at which @p extent (CRS units of @p unit_m metres) with a 10 % margin fits A3.
[[nodiscard]] double default_map_scale(const Box2& extent, double unit_m = 1.0);

}  // namespace dtm::products
