// SPDX-License-Identifier: MIT
//
// The distributed DEM (distributed_dem.hpp). After the distributed surface:
//   1. every rank lists its real triangles, the vertices they name (coordinates and heights,
//      each once) and which edges lie on the hull (dist/mesh_vertices: the tie rule of
//      rasterize needs it);
//   2. the grid: the serial rule (snapped_grid_spec of the TIN's box, or the extent), the box
//      being the exact minimum and maximum of the ranks' boxes (one allgather);
//   3. each triangle goes to every rank whose row block its rows may reach (rows_touching, the
//      rasteriser's own conservative test) with its vertices, indexed per destination (one
//      alltoallv of vertices, one of triangles: 16 bytes a triangle and about 16 a vertex);
//   4. each rank builds a Tin of what it received and rasterises its rows only (the row window
//      of rasterize): a cell's value depends only on the triangle that owns its centre, never on
//      the vertex numbers or triangle order, so it is the serial DEM's value;
//   5. tiles are written (GridWriter, atomic), then rank 0 writes the VRT (write_dem_vrt);
//   6. hillshade, slope and aspect (gdaldem) in the same row blocks, each rank reading its rows
//      and one more on each side from the DEM's VRT (write_dem_derivative_rows), rank 0 writing
//      a VRT over them: a derivative's cell depends on its 3 x 3 neighbourhood only.
#include "dtm/products/distributed_dem.hpp"

#include <algorithm>
#include <string>

#include "dist/mesh_vertices.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/dem.hpp"
#include "products/detail/distributed_pieces.hpp"
#include "products/detail/distributed_surface.hpp"
#include "products/detail/surface_routing.hpp"

namespace dtm::products {
namespace {

/// The first row of rank r's block: rows are split as evenly as integers allow (rows are at
/// most 2^36 and ranks far below 2^27: the product fits).
std::size_t block_start(const GridSpec& spec, int r, int ranks) {
    return spec.rows * static_cast<std::size_t>(r) / static_cast<std::size_t>(ranks);
}

/// The tiles beside @p vrt of the ranks whose row block is not empty, in row order.
std::vector<io::DemTile> row_block_tiles(const GridSpec& spec,
                                         const std::filesystem::path& vrt,
                                         int ranks) {
    std::vector<io::DemTile> tiles;
    for (int r = 0; r < ranks; ++r) {
        const std::size_t lo = block_start(spec, r, ranks), hi = block_start(spec, r + 1, ranks);
        if (hi > lo) tiles.push_back({dem_tile_path(vrt, r, ranks), lo, hi - lo});
    }
    return tiles;
}

std::vector<std::filesystem::path> files_of(const std::vector<io::DemTile>& tiles) {
    std::vector<std::filesystem::path> files;
    for (const io::DemTile& tile : tiles) files.push_back(tile.file);
    return files;
}

/// The grid `dtm grid` chooses: the extent, or the TIN's box (exact min and max over ranks).
GridSpec grid_of(dist::Comm& comm,
                 const dist::SurfaceMesh& surface,
                 const DistributedDemOptions& options) {
    if (options.extent) return dem_grid_spec({}, options.cell, options.extent);
    return dem_grid_spec(detail::mesh_box(comm, surface), options.cell, std::nullopt);
}

/// Every face goes to the ranks whose row blocks its rows may reach.
Tin route_to_row_blocks(dist::Comm& comm, const GridSpec& spec, dist::SurfaceMesh surface) {
    const int ranks = comm.size();
    std::vector<std::size_t> starts;
    for (int r = 0; r <= ranks; ++r) starts.push_back(block_start(spec, r, ranks));
    const auto owner = [&](std::size_t row) {  // the last rank whose block starts at or before
        return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), row) -
                                        starts.begin()) -
               1;
    };
    const auto destinations = [&](const dist::SurfaceFace& f,
                                  const std::vector<dist::SurfaceVertex>& vertices) {
        double ylo = vertices[f.v[0]].p.y, yhi = ylo;
        for (const std::uint32_t v : f.v) {
            ylo = std::min(ylo, vertices[v].p.y);
            yhi = std::max(yhi, vertices[v].p.y);
        }
        std::size_t first = 0, last = 0;
        if (!rows_touching(spec, ylo, yhi, first, last)) return detail::RankRange{};
        return detail::RankRange{owner(first), owner(last)};
    };
    comm.set_phase("dem triangles");
    return detail::route_faces(comm, std::move(surface), destinations, detail::Links::border_only);
}

/// Counts the cells with data and passes the rows on at their rows in the tile.
class TileSink final : public GridSink {
public:
    TileSink(GridSink& tile, std::size_t first_row, float nodata)
        : tile_(tile), first_row_(first_row), nodata_(nodata) {}
    void write_rows(std::size_t first_row,
                    std::size_t row_count,
                    std::span<const float> values) override {
        for (const float v : values) filled += v != nodata_ ? 1 : 0;
        tile_.write_rows(first_row - first_row_, row_count, values);
    }
    std::uint64_t filled = 0;

private:
    GridSink& tile_;
    std::size_t first_row_;
    float nodata_;
};

}  // namespace

std::filesystem::path dem_tile_path(const std::filesystem::path& vrt, int rank, int ranks) {
    return detail::piece_path(vrt, rank, ranks, "tif");
}

namespace detail {

Box2 mesh_box(dist::Comm& comm, const dist::SurfaceMesh& mine) {
    Box2 box;
    for (const dist::SurfaceVertex& v : mine.vertices) box.add(v.p);
    return box_over_ranks(comm, box);
}

DemTiles write_dem_tiles(dist::Comm& comm,
                         const GridSpec& spec,
                         dist::SurfaceMesh mine,
                         const std::filesystem::path& vrt,
                         const io::GridWriteOptions& write,
                         const Progress& progress) {
    check_dem_size(spec);
    const Tin tin = route_to_row_blocks(comm, spec, std::move(mine));

    const int rank = comm.rank(), ranks = comm.size();
    const std::size_t first = block_start(spec, rank, ranks);
    const std::size_t rows = block_start(spec, rank + 1, ranks) - first;
    std::uint64_t filled = 0;
    on_ranks(comm, rows > 0, [&] {
        GridSpec tile = spec;
        tile.rows = rows;
        tile.ymax = spec.ymax - static_cast<double>(first) * spec.cell;
        io::GridWriter writer(dem_tile_path(vrt, rank, ranks), tile, write);
        TileSink sink(writer, first, write.nodata);
        rasterize(tin, spec,
                  {.nodata = write.nodata, .threads = 0, .first_row = first, .row_count = rows},
                  sink, progress);
        writer.commit();
        filled = sink.filled;
    });
    DemTiles result;
    result.filled = static_cast<std::uint64_t>(
        comm.allreduce(static_cast<std::int64_t>(filled), dist::Reduce::sum));
    const std::vector<io::DemTile> tiles = row_block_tiles(spec, vrt, ranks);
    result.tiles = files_of(tiles);
    on_ranks(comm, rank == 0, [&] { io::write_dem_vrt(vrt, spec, tiles, write); });
    return result;
}

std::vector<std::filesystem::path> write_derivative_tiles(dist::Comm& comm,
                                                          const GridSpec& spec,
                                                          const std::filesystem::path& dem,
                                                          const std::filesystem::path& target,
                                                          io::DemDerivative kind,
                                                          const std::string& crs_wkt) {
    const int rank = comm.rank(), ranks = comm.size();
    const std::size_t first = block_start(spec, rank, ranks);
    const std::size_t rows = block_start(spec, rank + 1, ranks) - first;
    on_ranks(comm, rows > 0, [&] {
        io::write_dem_derivative_rows(dem, dem_tile_path(target, rank, ranks), kind, first, rows);
    });
    const std::vector<io::DemTile> tiles = row_block_tiles(spec, target, ranks);
    on_ranks(comm, rank == 0, [&] { io::write_derivative_vrt(target, spec, tiles, crs_wkt); });
    return files_of(tiles);
}

}  // namespace detail

void check_distributed_dem_outputs(const DistributedDemOptions& options, int ranks) {
    const std::vector<DemDerivativeFile> derived =
        dem_derivatives(options.hillshade, options.slope, options.aspect);
    for (const auto& [file, kind] : derived) {
        if (io::lower_extension(file) != "vrt") {
            const std::string field = io::dem_derivative_name(kind);
            throw OptionError(field, "with a tiled DEM, `" + field +
                                         "` is one GeoTIFF per rank and a VRT over them too: "
                                         "give `" +
                                         field + "` NAME.vrt, not " + file.string());
        }
    }
    io::check_output(options.output, io::OutputKind::raster, "output");
    for (const auto& [file, kind] : derived) {
        io::check_output(file, io::OutputKind::raster, io::dem_derivative_name(kind));
    }
    for (const auto& [file, kind] : derived) {
        io::check_output(dem_tile_path(file, 0, ranks), io::OutputKind::raster,
                         io::dem_derivative_name(kind));
    }
}

DistributedDemResult distributed_dem(dist::Comm& comm,
                                     const DistributedDemOptions& options,
                                     const Progress& progress) {
    DistributedDemResult result;
    detail::DistributedSurface surface =
        detail::distributed_surface(comm, options.source, progress.sub(0.0, 0.6));
    static_cast<DistributedCounts&>(result) = detail::counts_of(comm, surface);

    detail::report_progress(progress, 0.6, "rasterize");
    comm.set_phase("dem vertices");
    dist::SurfaceMesh mine = dist::surface_mesh(comm, surface.merged, std::move(surface.kernel));
    const io::GridWriteOptions write{.crs_wkt = std::move(surface.crs_wkt),
                                     .nodata = options.nodata};
    surface = {};  // the kernel's mesh is no longer needed
    result.spec = grid_of(comm, mine, options);
    detail::DemTiles tiles =
        detail::write_dem_tiles(comm, result.spec, std::move(mine), options.output, write,
                                comm.rank() == 0 ? progress.sub(0.7, 0.95) : Progress{});
    result.filled = tiles.filled;
    result.tiles = std::move(tiles.tiles);
    for (const auto& [file, kind] :
         dem_derivatives(options.hillshade, options.slope, options.aspect)) {
        comm.set_phase("dem derivatives");
        for (std::filesystem::path& tile : detail::write_derivative_tiles(
                 comm, result.spec, options.output, file, kind, write.crs_wkt)) {
            result.derived_tiles.push_back(std::move(tile));
        }
    }
    result.bytes_sent = detail::bytes_sent(comm);
    detail::report_progress(progress, 1.0, "done");
    return result;
}

}  // namespace dtm::products
