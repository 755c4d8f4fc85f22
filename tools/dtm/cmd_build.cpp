// SPDX-License-Identifier: MIT
// dtm build INPUTS... -o OUTDIR: the main job. Reads every input, triangulates, and writes the
// whole product set into OUTDIR:
//   tin.ply  tin.2dm  surface.vtp  dem.tif  hillshade.tif  contours.gpkg  dtm.qgs  report.json
// and with --base BASE the volume products of the TIN against BASE in volume/ (products::
// write_volume_products: volume.json, volume.txt, difference TIN and GeoTIFF, cut_fill.gpkg,
// zero_lines.dxf), shown as a cut/fill map in dtm.qgs.
// Everything is written into a temporary sibling folder first (".OUTDIR.tmp-<pid>"); only when
// every product is complete are the files moved into OUTDIR, so a failed or cancelled run leaves
// no partial file and never replaces a good product from an earlier run.
//
// Defaults chosen from the data when not given:
//   --cell      half the mean point spacing sqrt(planimetric area / TIN vertices), rounded down
//               to 1, 2, 2.5 or 5 x 10^k (at least two cells between neighbouring points, so the
//               DEM keeps the detail of the survey), enlarged if the DEM would pass 50 million
//               cells;
//   --interval  the z range divided by 20, rounded down the same way (about 20 contour levels);
//               every 5th level is an index contour.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include "command.hpp"
#include "dtm/algo/contour.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/contour_writer.hpp"
#include "dtm/io/formats/qgis_project.hpp"
#include "dtm/io/formats/report.hpp"
#include "dtm/io/grid_writer.hpp"
#include "dtm/io/inputs.hpp"
#include "dtm/io/tin_file.hpp"
#include "dtm/products/volume.hpp"
#include "input_args.hpp"
#include "terminal_progress.hpp"
#include "tin_args.hpp"

namespace dtm::cli {
namespace {

namespace fs = std::filesystem;

struct BuildArgs {
    InputArgs input;
    InputArgs base;  ///< --base BASE...: compare the TIN with this surface
    std::string out_dir;
    double cell = 0.0;
    double interval = 0.0;
    std::size_t index_every = 5;
    TriangulateOptions tin;
    bool quiet = false;
};

/// The temporary sibling of OUTDIR that receives every product; removed unless committed.
class Staging {
public:
    explicit Staging(fs::path out_dir) : out_(std::move(out_dir)) {
        if (out_.filename().empty()) {
            out_ = out_.parent_path();  // "out/" -> "out"
        }
        std::error_code exists_error;
        if (fs::exists(out_, exists_error) && !fs::is_directory(out_, exists_error)) {
            throw UsageError("build: -o " + out_.string() + " is a file, not a folder");
        }
        const fs::path parent = out_.parent_path().empty() ? fs::path(".") : out_.parent_path();
        temp_ = parent / ("." + out_.filename().string() + ".tmp-" + std::to_string(::getpid()));
        std::error_code ec;
        fs::create_directories(parent, ec);
        fs::remove_all(temp_, ec);
        if (!fs::create_directory(temp_, ec) || ec) {
            throw Error("build: cannot create the temporary folder " + temp_.string() + ": " +
                        ec.message());
        }
    }
    Staging(const Staging&) = delete;
    Staging& operator=(const Staging&) = delete;
    ~Staging() {
        std::error_code ec;
        fs::remove_all(temp_, ec);
    }
    [[nodiscard]] fs::path operator/(const std::string& name) const { return temp_ / name; }

    /// Moves every file of the temporary folder into OUTDIR (same file system: renames).
    void commit(const std::vector<std::string>& files) const {
        std::error_code ec;
        fs::create_directories(out_, ec);
        if (ec) {
            throw Error("build: cannot create " + out_.string() + ": " + ec.message());
        }
        for (const std::string& name : files) {
            fs::rename(temp_ / name, out_ / name, ec);
            if (ec) {
                throw Error("build: cannot move " + name + " into " + out_.string() + ": " +
                            ec.message());
            }
        }
    }

private:
    fs::path out_;
    fs::path temp_;
};

/// Largest of 1, 2, 2.5, 5 x 10^k not above @p value (value > 0).
double nice_floor(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    const double mantissa = value / power;
    for (const double step : {5.0, 2.5, 2.0}) {
        if (mantissa >= step) {
            return step * power;
        }
    }
    return power;
}

/// Smallest of 1, 2, 2.5, 5 x 10^k above @p value.
double nice_next(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    for (const double step : {2.0, 2.5, 5.0, 10.0}) {
        if (step * power > value * (1.0 + 1e-12)) {
            return step * power;
        }
    }
    return 10.0 * power;
}

double default_cell(const SurfaceStats& surface) {
    const double spacing =
        std::sqrt(surface.planimetric_area /
                  static_cast<double>(std::max<std::size_t>(surface.vertex_count, 1)));
    double cell = nice_floor(std::max(spacing / 2.0, 1e-3));
    const double width = surface.extent.xmax - surface.extent.xmin;
    const double height = surface.extent.ymax - surface.extent.ymin;
    while ((width / cell + 1.0) * (height / cell + 1.0) > 50e6) {
        cell = nice_next(cell);
    }
    return cell;
}

double default_interval(const SurfaceStats& surface) {
    const double range = surface.z_max - surface.z_min;
    return range > 0.0 ? nice_floor(range / 20.0) : 1.0;
}

/// Times the stages of the run for the report.
class Stopwatch {
public:
    void lap(std::string stage) {
        const auto now = std::chrono::steady_clock::now();
        timings_.push_back({std::move(stage), std::chrono::duration<double>(now - last_).count()});
        last_ = now;
    }
    [[nodiscard]] std::vector<io::StageTime> timings() const { return timings_; }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
    std::vector<io::StageTime> timings_;
};

struct BuildState {
    io::LoadedInputs inputs;
    TriangulateResult result;
    SurfaceStats surface;
    io::BuildReport report;
    std::vector<std::string> files;  ///< written into the staging folder, in order
    std::size_t survey_points = 0;   ///< survey points given to the triangulator
    products::VolumeReport volume;   ///< with --base
};

/// With --base: the volume products of the TIN against the base, into volume/.
void write_volume(const BuildArgs& args, BuildState& state, const Staging& staging,
                  const Progress& progress) {
    if (args.base.inputs.empty()) {
        return;
    }
    products::VolumeJob job;
    InputArgs base = args.base;
    base.load = args.input.load;
    job.base = {"base", to_load_options(base), args.tin};
    job.threads = args.tin.threads;
    const products::Surface surface =
        products::load_surface(job.base, state.inputs.crs_wkt, progress.sub(0.0, 0.3));
    state.volume.crs_wkt = state.inputs.crs_wkt;
    state.volume.top = "the built TIN";
    state.volume.base = surface.description();
    if (!surface.transformed_from.empty()) {
        state.volume.notes.push_back("the base was reprojected from " + surface.transformed_from);
    }
    std::error_code ec;
    fs::create_directory(staging / "volume", ec);
    products::write_volume_products(state.result.tin, &surface.tin, job, staging / "volume",
                                    state.volume, progress.sub(0.3, 1.0));
    state.files.emplace_back("volume");
}

void triangulate_inputs(const BuildArgs& args, BuildState& state, const Progress& progress) {
    if (state.inputs.tin) {
        // A dtm PLY TIN as input: products are derived from it as it is.
        state.result.tin = std::move(*state.inputs.tin);
        state.inputs.tin.reset();
        state.result.stats.points_in = state.result.tin.vertices.size();
        state.survey_points = state.result.tin.vertices.size();
        state.result.input_to_vertex.resize(state.result.tin.vertices.size());
        for (std::size_t i = 0; i < state.result.input_to_vertex.size(); ++i) {
            state.result.input_to_vertex[i] = static_cast<VertexIndex>(i);
        }
        return;
    }
    // The input is consumed: its memory goes as soon as the vertices are merged.
    state.survey_points = state.inputs.terrain.points.size();
    state.result = triangulate(std::move(state.inputs.terrain), args.tin, progress);
    state.inputs.terrain = TerrainInput{};
}

void write_tins(BuildState& state, const Staging& staging, const Progress& progress) {
    io::TinWriteOptions options;
    options.crs_wkt = state.inputs.crs_wkt;
    const char* names[] = {"tin.ply", "tin.2dm", "surface.vtp"};
    for (std::size_t i = 0; i < 3; ++i) {
        progress.report(static_cast<double>(i) / 3.0, "writing the TIN");
        io::write_tin(state.result.tin, staging / names[i], options);
        state.files.emplace_back(names[i]);
    }
    progress.report(1.0, "writing the TIN");
}

GridSpec write_dem(const BuildArgs& args,
                   BuildState& state,
                   const Staging& staging,
                   const Progress& progress) {
    const double cell = args.cell > 0.0 ? args.cell : default_cell(state.surface);
    state.report.cell_rule = args.cell > 0.0 ? "given (--cell)"
                                             : "half the mean point spacing, rounded down to "
                                               "1, 2, 2.5 or 5 x 10^k";
    const GridSpec spec = snapped_grid_spec(tin_bounds(state.result.tin), cell);
    io::GridWriteOptions options;
    options.crs_wkt = state.inputs.crs_wkt;
    io::GridWriter writer(staging / "dem.tif", spec, options);
    rasterize(state.result.tin, spec, RasterizeOptions{}, writer, progress.sub(0.0, 0.8));
    writer.commit();
    state.files.emplace_back("dem.tif");
    progress.report(0.8, "hillshade");
    io::write_dem_derivative(staging / "dem.tif", staging / "hillshade.tif",
                             io::DemDerivative::hillshade);
    state.files.emplace_back("hillshade.tif");
    progress.report(1.0, "hillshade");
    return spec;
}

void write_contours(const BuildArgs& args,
                    BuildState& state,
                    const Staging& staging,
                    const Progress& progress) {
    ContourOptions options;
    options.interval = args.interval > 0.0 ? args.interval : default_interval(state.surface);
    options.index_every = args.index_every;
    state.report.contour_interval = options.interval;
    state.report.index_every = options.index_every;
    state.report.interval_rule = args.interval > 0.0 ? "given (--interval)"
                                                     : "z range / 20, rounded down to 1, 2, 2.5 "
                                                       "or 5 x 10^k";
    state.report.contour_levels =
        contour_levels(state.surface.z_min, state.surface.z_max, options).size();
    io::ContourWriteOptions write_options;
    write_options.crs_wkt = state.inputs.crs_wkt;
    io::ContourWriter writer(staging / "contours.gpkg", write_options);
    contour(state.result.tin, options, writer, progress);
    writer.commit();
    state.report.contour_lines = writer.feature_count();
    state.files.emplace_back("contours.gpkg");
}

void write_project(const BuildState& state, const Staging& staging) {
    io::QgisProject project;
    project.title = "dtm build";
    project.crs_wkt = state.inputs.crs_wkt;
    project.extent = state.surface.extent;
    project.z_min = state.surface.z_min;
    project.z_max = state.surface.z_max;
    project.dem = "dem.tif";
    project.hillshade = "hillshade.tif";
    project.contours = "contours.gpkg";
    project.contour_layer = "contours";
    project.elevation_field = "elevation";
    project.index_field = "index";
    project.index_interval =
        state.report.contour_interval *
        static_cast<double>(std::max<std::size_t>(state.report.index_every, 1));
    project.mesh = "tin.2dm";
    if (!state.volume.files.empty()) {
        project.cut_fill = "volume/cut_fill.gpkg";
    }
    io::write_qgis_project(project, staging / "dtm.qgs");
}

void fill_report(BuildState& state) {
    io::BuildReport& r = state.report;
    r.inputs = state.inputs.summaries;
    r.skipped_lines = state.inputs.skipped_lines;
    r.crs_wkt = state.inputs.crs_wkt;
    r.accounting = account_inputs(state.result, state.survey_points);
    r.triangulation = state.result.stats;
    r.conflicts = state.result.conflicts;
    r.surface = state.surface;
}

/// One short paragraph on stdout: what was built and where the report is.
void print_summary(const BuildState& state, const std::string& out_dir) {
    const io::BuildReport& r = state.report;
    const PointFate& points = r.accounting.survey_points;
    std::printf(
        "dtm build: %zu points read (%zu used, %zu merged duplicates, %zu outside the "
        "boundary or in holes), %zu bad lines skipped\n",
        points.total, points.used, points.merged, points.removed, r.skipped_lines);
    std::printf(
        "dtm build: TIN %zu vertices, %zu triangles, %zu constrained edges, %zu breakline "
        "conflicts; DEM %zu x %zu cells of %g; %zu contour lines every %g\n",
        r.surface.vertex_count, r.surface.triangle_count, r.surface.constraint_count,
        r.conflicts.size(), r.dem.cols, r.dem.rows, r.dem.cell, r.contour_lines,
        r.contour_interval);
    std::printf("dtm build: products and report.json in %s\n", out_dir.c_str());
}

int run_build(const BuildArgs& args) {
    const Progress progress = terminal_progress("build", args.quiet);
    Stopwatch clock;
    BuildState state;
    Staging staging(args.out_dir);

    state.inputs = io::load_inputs(to_load_options(args.input), progress.sub(0.0, 0.1));
    clock.lap("read");
    triangulate_inputs(args, state, progress.sub(0.1, 0.45));
    state.surface = surface_stats(state.result.tin);
    if (state.surface.triangle_count == 0) {
        throw InputError(
            "build: the triangulation has no triangle (is everything outside the "
            "boundary?)");
    }
    clock.lap("triangulate");
    write_tins(state, staging, progress.sub(0.45, 0.6));
    clock.lap("write_tin");
    state.report.dem = write_dem(args, state, staging, progress.sub(0.6, 0.8));
    clock.lap("dem");
    write_contours(args, state, staging, progress.sub(0.8, 0.9));
    clock.lap("contours");
    write_volume(args, state, staging, progress.sub(0.9, 0.95));
    if (!args.base.inputs.empty()) {
        clock.lap("volume");
    }
    write_project(state, staging);
    state.files.emplace_back("dtm.qgs");
    clock.lap("project");

    fill_report(state);
    state.report.timings = clock.timings();
    state.report.outputs = state.files;
    state.report.outputs.emplace_back("report.json");
    io::write_report(state.report, staging / "report.json");
    state.files.emplace_back("report.json");
    progress.report(0.99, "moving the products into place");
    staging.commit(state.files);
    progress.report(1.0, "done");
    if (!args.quiet) {
        print_summary(state, args.out_dir);
        if (!state.volume.files.empty()) {
            const VolumeResult& v = state.volume.volume;
            std::printf("dtm build: against the base: fill %.3f, cut %.3f, net %.3f (volume/)\n",
                        v.fill, v.cut, v.net());
        }
    }
    if (state.inputs.crs_wkt.empty()) {
        std::fprintf(stderr,
                     "dtm build: warning: the inputs carry no CRS (give --crs): the products and "
                     "the QGIS project have none\n");
    }
    return 0;
}

}  // namespace

Command build_command() {
    return {"build",
            "The main job: TIN, DEM, hillshade, contours, VTK surface, 2DM mesh, QGIS project "
            "and report into one folder (with --base: volumes and a cut/fill map too)",
            [](CLI::App& app) {
                auto args = std::make_shared<BuildArgs>();
                add_input_options(app, args->input);
                add_surface_options(app, "base", args->base);
                app.add_option("-o,--output", args->out_dir, "Output folder (created if needed)")
                    ->required();
                app.add_option("--cell", args->cell,
                               "DEM cell size in CRS units (default: half the mean point "
                               "spacing, rounded down to 1, 2, 2.5, 5 x 10^k)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--interval", args->interval,
                               "Contour interval (default: z range / 20, rounded down to 1, 2, "
                               "2.5, 5 x 10^k)")
                    ->check(CLI::PositiveNumber);
                app.add_option("--index-every", args->index_every,
                               "Every N-th contour level is an index contour (default 5)");
                add_tin_options(app, args->tin);
                app.add_flag("-q,--quiet", args->quiet, "No progress bar");
                return [args]() { return run_build(*args); };
            }};
}

}  // namespace dtm::cli
