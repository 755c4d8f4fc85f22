// SPDX-License-Identifier: MIT
/// @file
/// @brief LandXML 1.2 TIN surfaces (docs/formats.md "LandXML"): the writer streams a Surface with
/// Pnts ("northing easting elevation"), Faces and SourceData breaklines/boundaries; the reader
/// (expat, ADR 0006) gives the TIN as stored or its points and lines. Sources:
/// src/io/formats/landxml/.
#pragma once

#include <filesystem>

#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"
#include "dtm/io/reader.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Writes @p tin as LandXML 1.2 to exactly @p path (write_tin() adds atomicity). Faces
/// counter-clockwise in (easting, northing), point ids 1..n in vertex order; constrained edges
/// become SourceData breaklines (hard: "standard", soft: "nondestructive"), boundary rings
/// Boundary "outer", hole rings "void". @throws Error if the file cannot be written.
void write_landxml(const Tin& tin,
                   const std::filesystem::path& path,
                   const TinWriteOptions& options);

/// The reader table's entry. The first surface (or ReadOptions::surface): its visible faces as a
/// TIN (i="1" faces left out: holes), oriented counter-clockwise, every point as a vertex, the
/// SourceData lines as breaklines, boundaries and holes (their segments that are TIN edges also
/// as constrained edges); with ReadOptions::retriangulate the points and lines only.
/// @throws InputError naming the file, line and what was wrong.
[[nodiscard]] ReadResult read_landxml(const InputFile& file,
                                      const ReadOptions& options,
                                      const Progress& progress = {});

/// True for a file whose root element is LandXML.
[[nodiscard]] bool is_landxml(const FileHead& head);

}  // namespace dtm::io
