// SPDX-License-Identifier: MIT
/// @file
/// @brief `dtm profile`: exact sections of one or more surfaces along the lines of a file:
/// profile.csv (every breakpoint: line, surface, run, chainage, x, y, z), profile.gpkg and
/// profile.dxf (3-D polylines, one per continuous run), and a plot per line (PDF pages, or one
/// SVG/PNG per line).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "dtm/algo/profile.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/products/surface_input.hpp"

namespace dtm::products {

struct ProfileJob {
    std::vector<SurfaceSource> surfaces;  ///< the first surface's CRS is the job's
    std::filesystem::path lines;
    io::LoadOptions line_reader;
    double exaggeration = 10.0;
    double station_interval = 0.0;    ///< labelled stations (0: automatic)
    std::string plot_format = "pdf";  ///< pdf, svg, png, or "" for no plot
    unsigned threads = 0;
};

struct ProfileReport {
    std::size_t lines = 0;
    std::vector<std::string> surfaces;  ///< names (file stems)
    std::size_t breakpoints = 0;
    std::size_t gaps = 0;           ///< runs beyond the first on each (line, surface)
    double read_seconds = 0.0;      ///< reading (and triangulating) the surfaces and the lines
    double sections_seconds = 0.0;  ///< cutting every section and writing every product
    std::vector<std::string> files;
    std::vector<std::string> notes;
};

/// @throws InputError naming the file and feature for a line outside every surface; others as
/// load_surface / load_lines.
ProfileReport run_profile(const ProfileJob& job,
                          const std::filesystem::path& out_dir,
                          const Progress& progress = {});

}  // namespace dtm::products
