// SPDX-License-Identifier: MIT
// dtm grid INPUTS... -o DEM --cell C [--extent xmin,ymin,xmax,ymax] [--nodata V] [--cog]
//          [--interpolation linear|cubic|natural] [--hillshade FILE] [--slope FILE] [--aspect FILE]
// The TIN surface sampled at cell centres (parse -> options -> library -> report). A .vrt
// output, and any run under mpirun, is the tiled DEM: one GeoTIFF per rank and a VRT.
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "command.hpp"
#include "contour_flats_args.hpp"
#include "distributed.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/in_process.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/products/dem.hpp"
#include "dtm/products/distributed_dem.hpp"
#include "dtm/products/surface.hpp"
#include "input_args.hpp"
#include "interpolation_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

struct GridArgs {
    InputArgs input;
    TriangulateOptions tin;
    products::ContourFlats flats = products::ContourFlats::automatic;
    std::string output;
    double cell = 0.0;
    std::string extent;
    float nodata = -9999.0F;
    bool cog = false;
    Interpolation interpolation = Interpolation::linear;
    std::string hillshade, slope, aspect;
    bool quiet = false;
};

/// "xmin,ymin,xmax,ymax" -> Box2. @throws UsageError
Box2 parse_extent(const std::string& text) {
    std::vector<double> v;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        try {
            std::size_t used = 0;
            v.push_back(std::stod(item, &used));
            if (used != item.size()) {
                throw std::invalid_argument(item);
            }
        } catch (const std::exception&) {
            throw UsageError("grid: --extent '" + text + "': '" + item + "' is not a number");
        }
    }
    if (v.size() != 4 || !(v[2] > v[0]) || !(v[3] > v[1])) {
        throw UsageError("grid: --extent '" + text +
                         "': expected xmin,ymin,xmax,ymax with xmax > xmin and ymax > ymin");
    }
    return {v[0], v[1], v[2], v[3]};
}

/// The library's DEM options from the command line (the extent parsed).
products::DemOptions dem_options(const GridArgs& args) {
    products::DemOptions o;
    o.cell = args.cell;
    if (!args.extent.empty()) o.extent = parse_extent(args.extent);
    o.nodata = args.nodata;
    o.cog = args.cog;
    o.interpolation = args.interpolation;
    o.threads = args.tin.threads;
    o.hillshade = args.hillshade;
    o.slope = args.slope;
    o.aspect = args.aspect;
    return o;
}

void print_summary(const GridSpec& spec, std::uint64_t filled, const std::string& output) {
    std::ostringstream extent;
    extent.precision(15);
    extent << spec.xmin << "," << spec.ymin() << "," << spec.xmax() << "," << spec.ymax;
    std::cout << "grid: " << spec.cols << " x " << spec.rows << " cells of " << spec.cell
              << " sampled at cell centres, extent " << extent.str() << ", " << filled
              << " cells with data -> " << output << '\n';
    if (filled == 0) {
        std::cerr << "dtm grid: warning: no cell centre lies on the TIN (check --extent)\n";
    }
}

/// A DEM as a VRT over one GeoTIFF per rank, on the ranks of an MPI job or on this process
/// alone: what the distributed run covers, or a clear refusal.
int run_grid_tiled(const GridArgs& args, dist::Comm& comm) {
    check_distributed_input("grid", args.input, args.tin);
    const auto refuse = [](const std::string& what) {
        throw UsageError("grid: a tiled DEM (.vrt output, or mpirun) does not take " + what +
                         " yet");
    };
    if (io::lower_extension(args.output) != "vrt") {
        throw UsageError(
            "grid: a distributed DEM is one GeoTIFF per rank and a VRT over them: "
            "give -o NAME.vrt, not " +
            args.output);
    }
    if (args.interpolation != Interpolation::linear) refuse("`interpolation` other than linear");
    if (args.cog) refuse("`cog`");
    const products::DistributedDemOptions options{
        .source = distributed_source(args.input, args.tin),
        .cell = args.cell,
        .extent = dem_options(args).extent,
        .nodata = args.nodata,
        .output = args.output,
        .hillshade = args.hillshade,
        .slope = args.slope,
        .aspect = args.aspect};
    products::check_distributed_dem_outputs(options, comm.size());
    const products::DistributedDemResult r = products::distributed_dem(
        comm, options, prints() ? terminal_progress("grid", args.quiet) : Progress{});
    if (prints()) {
        print_summary(r.spec, r.filled,
                      args.output + " (" + std::to_string(r.tiles.size()) + " GeoTIFF tile" +
                          (r.tiles.size() == 1 ? "" : "s") + " beside it)");
    }
    return 0;
}

int run_grid(const GridArgs& args) {
    if (dist::Comm* comm = distributed_comm()) return run_grid_tiled(args, *comm);
    if (io::lower_extension(args.output) == "vrt") {
        int status = 0;
        dist::run_in_process(1, [&](dist::Comm& comm) { status = run_grid_tiled(args, comm); });
        return status;
    }
    products::DemOptions options = dem_options(args);
    products::check_dem_outputs(args.output, options);
    const Progress progress = terminal_progress("grid", args.quiet);
    io::LoadedInputs inputs = io::load_inputs(to_load_options(args.input), progress.sub(0.0, 0.2));
    products::Surface surface = products::surface(
        inputs, surface_options(args.input, args.tin, args.flats), progress.sub(0.2, 0.5));
    if (surface.contour_flats && !args.quiet) print_contour_flats(*surface.contour_flats, "grid");
    if (surface.dem && !args.quiet) print_dem_report(*surface.dem, "grid");
    options.crease_at_breaklines = !surface.contour_input;
    const products::DemResult dem =
        products::write_dem(std::move(surface.result.tin), inputs.crs_wkt, options, args.output,
                            progress.sub(0.5, 1.0));
    print_summary(dem.spec, dem.filled, args.output);
    return 0;
}

}  // namespace

Command grid_command() {
    return {"grid", "DEM raster of the TIN sampled at cell centres (GeoTIFF or any GDAL format)",
            [](CLI::App& app) {
                auto args = std::make_shared<GridArgs>();
                add_input_options(app, args->input);
                add_tin_options(app, args->tin);
                add_contour_flats_options(app, args->flats);
                add_dem_options(app, args->input.dem);
                app.add_option("-o,--output", args->output,
                               "DEM file; the extension picks the GDAL driver (default .tif: "
                               "tiled DEFLATE Float32 GeoTIFF; .asc, .img, ...; .vrt: a VRT "
                               "over one GeoTIFF per rank, NAME-R-of-P.tif, as mpirun writes)")
                    ->required();
                app.add_option("--cell", args->cell, "Cell size in CRS units")
                    ->required()
                    ->check(CLI::PositiveNumber);
                app.add_option("--extent", args->extent,
                               "xmin,ymin,xmax,ymax: outer edges of the raster (default: the "
                               "TIN's bounding box snapped outwards to the cell size)");
                app.add_option("--nodata", args->nodata,
                               "Value of cells outside the TIN, the boundary and holes "
                               "(default -9999)");
                app.add_flag("--cog", args->cog, "Write a Cloud Optimized GeoTIFF");
                add_interpolation_option(app, "--interpolation", args->interpolation);
                app.add_option("--hillshade", args->hillshade, "Also write a hillshade (gdaldem)");
                app.add_option("--slope", args->slope, "Also write slope in degrees (gdaldem)");
                app.add_option("--aspect", args->aspect, "Also write aspect in degrees (gdaldem)");
                app.add_flag("-q,--quiet", args->quiet, "No progress on stderr");
                return [args]() { return run_grid(*args); };
            }};
}

}  // namespace dtm::cli
