// SPDX-License-Identifier: MIT
/// @file
/// @brief A contour file with its labels (`dtm contour`, build's contours.gpkg): the lines traced
/// into io::ContourWriter and, where the format holds them (DXF, GeoPackage), the index contour
/// numbers and optional spot heights placed by algo/contour_annotation.hpp at a drawing scale.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

#include "dtm/algo/contour.hpp"
#include "dtm/algo/contour_annotation.hpp"
#include "dtm/algo/interpolation.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm::products {

struct ContourFileOptions {
    std::string crs_wkt;
    std::string layer = "contours";  ///< the lines' layer (GeoPackage)
    /// Index contour numbers in DXF and GeoPackage files (formats of one layer get none).
    bool labels = true;
    bool spot_heights = false;  ///< spot heights with their labels (DXF and GeoPackage only)
    /// 1 : label_scale is the drawing scale of the texts (CRS units taken as metres); 0:
    /// default_map_scale() of the TIN's extent (map.hpp).
    double label_scale = 0.0;
    /// Text size, spacing, spot spacing and decimals (units_per_mm comes from label_scale).
    ContourAnnotationOptions annotation;
};

struct ContourFileReport {
    std::size_t lines = 0;
    bool annotated = false;
    double label_scale = 0.0;
    double text_height = 0.0;  ///< CRS units
    std::size_t labels = 0;
    std::size_t label_failures = 0;  ///< wanted label positions without room
    std::size_t spots = 0;
    std::size_t spot_labels_failed = 0;
};

/// Traces the contours of @p tin (on @p interpolant, or when it is null on options.surface) into
/// @p path and adds the labels. @throws OptionError (`spot_heights`) when the format cannot hold
/// them; UsageError for an unknown extension; Error; Cancelled
ContourFileReport write_contour_file(const Tin& tin,
                                     const TinInterpolant* interpolant,
                                     const ContourOptions& options,
                                     const std::filesystem::path& path,
                                     const ContourFileOptions& file,
                                     const Progress& progress = {});

}  // namespace dtm::products
