// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm sections`: cross-sections across an alignment at a station interval, with the cut
/// and fill areas between the first two surfaces, the average-end-area volumes next to the exact
/// volumes of the slabs between sections, a sheet of section plots, CSV, GeoPackage and JSON.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/algo/sections.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/products/surface_input.hpp"

namespace dtm::products {

struct SectionsJob {
    std::vector<SurfaceSource> surfaces;  ///< first: top (design, later survey); second: base
    std::filesystem::path alignment;
    io::LoadOptions reader;
    SectionOptions options;
    double exaggeration = 2.0;
    std::string plot_format = "pdf";  ///< pdf (sheets), svg or png (one file per section), ""
    unsigned threads = 0;
};

struct SectionRow {
    SectionLine line;
    SectionAreas areas;  ///< between the first two surfaces (zero with one surface)
};

struct SectionsReport {
    std::vector<SectionRow> sections;
    std::vector<SlabVolume> exact;  ///< slab k: between sections k and k + 1
    std::vector<SlabVolume> end_area;
    double end_area_fill = 0.0;
    double end_area_cut = 0.0;
    double exact_fill = 0.0;
    double exact_cut = 0.0;
    std::vector<std::string> surfaces;
    std::vector<std::string> notes;
    std::vector<std::string> files;
};

/// @throws InputError naming the file for an alignment outside the surfaces; as load_surface.
SectionsReport run_sections(const SectionsJob& job,
                            const std::filesystem::path& out_dir,
                            const Progress& progress = {});

}  // namespace dtm::products
