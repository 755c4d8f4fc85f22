// SPDX-License-Identifier: MIT
/// @file
/// @brief Internal: the distributed DEM tiles and contour pieces made from the TIN's triangles
/// as the ranks hold them (dist::surface_mesh), shared by `dtm grid`, `dtm contour` and
/// `dtm build` when distributed.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "dist/mesh_vertices.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/core/grid.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/dist/comm.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/grid_writer.hpp"

namespace dtm::products::detail {

/// Collective: the exact box of the vertices of all ranks' meshes (empty when no rank has one).
[[nodiscard]] Box2 mesh_box(dist::Comm& comm, const dist::SurfaceMesh& mine);

/// Collective: the exact least and greatest height of all ranks' mesh vertices.
[[nodiscard]] std::pair<double, double> height_range(dist::Comm& comm,
                                                     const dist::SurfaceMesh& mine);

struct DemTiles {
    std::uint64_t filled = 0;                  ///< cells with data, all tiles
    std::vector<std::filesystem::path> tiles;  ///< in row order
};

/// Collective: the linear surface of the triangles in @p mine sampled on @p spec, rank r writing
/// its block of rows as "<vrt stem>-r-of-P.tif", then rank 0 the VRT @p vrt over them.
/// @throws OptionError beyond 2^36 cells (check_dem_size); Error on every rank when a write fails.
DemTiles write_dem_tiles(dist::Comm& comm,
                         const GridSpec& spec,
                         dist::SurfaceMesh mine,
                         const std::filesystem::path& vrt,
                         const io::GridWriteOptions& write,
                         const Progress& progress);

/// Collective, once the DEM @p dem (a VRT over write_dem_tiles' tiles) is in place: its
/// derivative @p kind in the same row blocks, rank r writing "<target stem>-r-of-P.tif" from its
/// rows and one more on each side (io::write_dem_derivative_rows: the cells gdaldem gives the
/// whole DEM), then rank 0 the VRT @p target over them. Returns the tiles, in row order.
/// @throws Error on every rank when a read or write fails.
std::vector<std::filesystem::path> write_derivative_tiles(dist::Comm& comm,
                                                          const GridSpec& spec,
                                                          const std::filesystem::path& dem,
                                                          const std::filesystem::path& target,
                                                          io::DemDerivative kind,
                                                          const std::string& crs_wkt);

struct ContourPieces {
    std::uint64_t lines = 0;
    std::vector<std::filesystem::path> pieces;  ///< in level order
};

/// Collective: the contour lines of @p levels on the linear surface of @p mine, every line whole
/// in the GeoPackage of the rank owning its level, then rank 0 writes the OGR VRT @p vrt.
ContourPieces write_contour_pieces(dist::Comm& comm,
                                   dist::SurfaceMesh mine,
                                   const std::vector<ContourLevel>& levels,
                                   const ContourOptions& options,
                                   const std::filesystem::path& vrt,
                                   const io::ContourWriteOptions& write,
                                   const Progress& progress);

}  // namespace dtm::products::detail
