// SPDX-License-Identifier: MIT
/// @file
/// @brief `mpirun -np P dtm build POINTS -o OUT`: the main job on all ranks of an MPI job (R-E3
/// and R-P5 of docs/distributed.md). One output folder, staged and committed atomically by rank
/// 0 once every rank's files are in it (a shared file system, as for every distributed product):
///   tin.ply                         the TIN, byte for byte the serial one (MPI-IO);
///   surface.pvtp, surface-r-of-P.vtp  VTK pieces, rank r's triangles;
///   dem.vrt, dem-r-of-P.tif         the DEM, rank r's rows, the serial cells bit for bit;
///   contours.vrt, contours-r-of-P.gpkg  the contour lines, each whole in one piece;
///   dtm.qgs                         a QGIS project over the VRTs, in the TIN's CRS;
///   report.json                     the serial report's sections, `distributed` beside them.
/// The cell and interval rules are the serial build's, from exact measures (areas as exact sums,
/// so the same on every number of ranks). Not made when distributed: hillshade.tif, tin.2dm,
/// map.pdf, contour labels and spot heights, volumes (the tools refuse `--base`).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/products/distributed_tin.hpp"
#include "dtm/products/report.hpp"

namespace dtm::products {

struct DistributedBuildOptions {
    DistributedSource source;
    std::filesystem::path out_dir;
    double cell = 0.0;            ///< DEM cell; 0: default_cell() of the TIN (rules.hpp)
    double interval = 0.0;        ///< contour interval; 0: default_interval()
    std::size_t index_every = 5;  ///< every n-th level is an index contour (0: none)
    /// Vertices or triangles beyond which tin.ply is written as the tiled TIN tin.json (a PLY
    /// indexes 2^31 - 1; tests lower it).
    std::uint64_t ply_limit = 2147483647;
    /// How the report's rules name options (BuildOptions::wording).
    std::function<std::string(std::string_view)> wording;
};

/// Collective. @returns the report (as rank 0 wrote it into report.json; the same on every
/// rank). @throws InputError, UsageError, Error or Cancelled on every rank; @p out_dir is then
/// unchanged.
BuildReport distributed_build(dist::Comm& comm,
                              const DistributedBuildOptions& options,
                              const Progress& progress);

}  // namespace dtm::products
