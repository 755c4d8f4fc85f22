// SPDX-License-Identifier: MIT
/// @file
/// @brief Fail fast: an output checked before any input is read, so that a bad extension or an
/// unwritable folder costs nothing instead of a whole triangulation.
#pragma once

#include <filesystem>
#include <string>

namespace dtm::io {

/// What a writer will write at the path: the extension must be known to its table.
enum class OutputKind {
    tin,       ///< write_tin (tin_extensions)
    raster,    ///< GridWriter, write_dem_derivative (grid_extensions: GDAL raster drivers)
    contours,  ///< ContourWriter (contour_extensions)
    drawing,   ///< draw::Canvas: .pdf, .svg, .png
    any_file,  ///< any extension (a JSON report)
    folder,    ///< an AtomicDirectory target, created if needed
};

/// Checks that @p path can be written as @p kind: the extension is known (the message names it
/// and the known ones), the path is not a folder (a file for a folder output), and the folder
/// that will receive it exists (for a file) and is writable (a probe file is created and removed
/// in it, or in the nearest existing parent of a folder output).
/// @throws OptionError naming @p field (the options-struct member, as `field`).
void check_output(const std::filesystem::path& path, OutputKind kind, const std::string& field);

}  // namespace dtm::io
