// SPDX-License-Identifier: MIT
/// @file
/// @brief The main job: a survey in, every product in one folder, written atomically, with a
/// report of what happened. `dtm build` is this function behind its options.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/algo/interpolation.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/products/report.hpp"
#include "dtm/products/surface.hpp"

namespace dtm::products {

struct BuildOptions {
    TriangulateOptions triangulate;
    /// The flat triangles of contour input (lines with heights from ReadOptions::z_field) are
    /// removed by default (products::surface, algo/contour_flats.hpp).
    ContourFlats contour_flats = ContourFlats::automatic;
    /// Inputs whose breaklines outline real flats (lakes), loaded after the other breaklines.
    std::vector<std::filesystem::path> flat_areas;
    /// Raster DEM inputs: cells near the survey dropped, the rest thinned (algo/dem_reduce.hpp).
    DemReduceOptions dem;
    /// The surface the DEM samples and the contours follow (one estimate shared by both).
    Interpolation interpolation = Interpolation::linear;
    double cell = 0.0;            ///< DEM cell size in CRS units; 0: default_cell() (rules.hpp)
    double interval = 0.0;        ///< contour interval; 0: default_interval()
    std::size_t index_every = 5;  ///< every n-th contour level is an index contour (0: none)
    double map_scale = 0.0;       ///< 1 : map_scale of map.pdf; 0: default_map_scale() (map.hpp)
    /// Step "volume": the files of a base surface (a dtm TIN, or terrain triangulated with
    /// `triangulate`); the TIN is compared with it (products::write_volume_products into
    /// volume/, a cut/fill map in dtm.qgs). No files: no volume step.
    io::LoadOptions base;
    /// How texts written into the products (the report's warnings and rules) name options.
    /// Empty: as the library does, `field`; tools/dtm passes its flag spelling.
    std::function<std::string(std::string_view)> wording;
};

/// Reads @p inputs (io::load_inputs), takes their surface (products::surface) and runs the
/// product steps, each writing its files into one io::AtomicDirectory: tin.ply, tin.2dm,
/// surface.vtp (step "write_tin"), dem.tif, hillshade.tif ("dem"), contours.gpkg ("contours"),
/// map.pdf ("map"), with a base volume/ ("volume"), dtm.qgs with a print layout of the map sheet
/// and, with a base, a cut/fill map ("project"), then report.json; only when all are complete do
/// they move into @p out_dir (created if needed; other files there are left alone). The steps are
/// listed in src/products/build.cpp: a new product is one more step there, with its options here
/// and its section in BuildReport.
/// @returns the report, as written to report.json.
/// @throws OptionError if @p out_dir is a file (`out_dir`); InputError for unreadable inputs or a
/// surface without triangles; Error; Cancelled. @p out_dir is unchanged whenever it throws.
BuildReport build(const io::LoadOptions& inputs,
                  const std::filesystem::path& out_dir,
                  const BuildOptions& options = {},
                  const Progress& progress = {});

}  // namespace dtm::products
