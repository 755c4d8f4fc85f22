// SPDX-License-Identifier: MIT
/// @file
/// @brief VTK XML PolyData (.vtp) surface for ParaView and VTK-based viewers, written with VTK's
/// own vtkXMLPolyDataWriter.
#pragma once

#include <filesystem>
#include <vector>

#include "dtm/core/tin.hpp"
#include "dtm/io/tin_file.hpp"

namespace dtm::io {

/// Writes @p tin as a .vtp PolyData to exactly @p path (the caller provides atomicity):
/// - points: the TIN vertices in double precision (x, y, z);
/// - polys: one triangle cell per TIN triangle, in TIN order;
/// - lines: one two-point line cell per constrained edge (breaklines, boundaries, holes); VTK
///   numbers line cells before polygon cells;
/// - point data `elevation` (double, the active scalars);
/// - cell data `constraint_kind` (int: -1 for triangles, else the ConstraintKind value).
/// The CRS is stored in field data as the string array `crs_wkt` when options.crs_wkt is set.
/// @throws Error if VTK fails to write the file.
void write_vtp(const Tin& tin, const std::filesystem::path& path, const TinWriteOptions& options);

/// Writes the parallel PolyData summary (.pvtp) of the pieces @p pieces, each a .vtp of
/// write_vtp beside @p path (named by file name), to exactly @p path: ParaView and
/// vtkXMLPPolyDataReader open the pieces as one surface. @throws Error if it cannot be written.
void write_pvtp(const std::filesystem::path& path,
                const std::vector<std::filesystem::path>& pieces);

}  // namespace dtm::io
