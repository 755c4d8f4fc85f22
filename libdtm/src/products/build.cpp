// SPDX-License-Identifier: MIT
// The main job: read -> surface -> product steps -> report -> commit.
//
//   io::load_inputs ─> LoadedInputs ─> products::surface ─> Tin
//   (every reader)      (one CRS)      (as is, or triangulate)
//     ─┬─ write_tin ─> tin.ply tin.2dm surface.vtp
//      ├─ dem ───────> dem.tif hillshade.tif
//      ├─ contours ──> contours.gpkg
//      ├─ map ───────> map.pdf
//      ├─ volume ────> volume/ (with a base)
//      ├─ project ───> dtm.qgs
//      └─ report ────> report.json
//
// Every file goes into one io::AtomicDirectory, committed only after the report: a failed or
// cancelled run leaves the output folder as it was. The steps run in the order of the table
// below; each is timed into the report under its stage name and owns a slice of the progress.
#include "dtm/products/build.hpp"

#include <chrono>
#include <system_error>
#include <utility>
#include <vector>

#include "build_steps.hpp"
#include "dtm/algo/surface_stats.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/output_check.hpp"
#include "dtm/products/surface.hpp"

namespace dtm::products {
namespace {

namespace fs = std::filesystem;

/// The product steps, in order. A new product: a step function (its own file), a row here (with
/// `wanted` when an option turns it on), its options in BuildOptions, its section in BuildReport.
constexpr detail::BuildStep steps[] = {
    {"write_tin", 0.60, nullptr, &detail::write_tin_files},
    {"dem", 0.80, nullptr, &detail::write_dem},
    {"contours", 0.90, nullptr, &detail::write_contours},
    {"map", 0.95, nullptr, &detail::write_map_sheet},
    {"volume", 0.97, &detail::wants_volume, &detail::write_volume},
    {"project", 0.97, nullptr, &detail::write_project},
};

/// Progress of reading and triangulating (the steps follow).
constexpr double read_end = 0.10;
constexpr double triangulate_end = 0.40;
constexpr double surface_end = 0.45;

/// Times the stages of the run for the report.
class Stopwatch {
public:
    void lap(std::string_view stage) {
        const auto now = std::chrono::steady_clock::now();
        timings_.push_back(
            {std::string(stage), std::chrono::duration<double>(now - last_).count()});
        last_ = now;
    }
    [[nodiscard]] std::vector<StageTime> take() { return std::move(timings_); }

private:
    std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
    std::vector<StageTime> timings_;
};

fs::path folder(fs::path out_dir) {
    return out_dir.filename().empty() ? out_dir.parent_path() : out_dir;  // "out/" -> "out"
}

}  // namespace

BuildReport build(const io::LoadOptions& inputs,
                  const fs::path& out_dir,
                  const BuildOptions& options,
                  const Progress& progress) {
    const fs::path target = folder(out_dir);
    io::check_output(target, io::OutputKind::folder, "out_dir");  // before any input is read
    Stopwatch clock;
    io::AtomicDirectory out(target);
    io::LoadedInputs loaded = io::load_inputs(inputs, progress.sub(0.0, read_end));
    clock.lap("read");
    SurfaceOptions surface_options;
    surface_options.triangulate = options.triangulate;
    surface_options.contour_flats = options.contour_flats;
    surface_options.lines_are_contours = !inputs.read.z_field.empty();
    surface_options.flat_areas = options.flat_areas;
    surface_options.dem = options.dem;
    Surface s = surface(loaded, surface_options, progress.sub(read_end, triangulate_end));
    const SurfaceStats stats = surface_stats(s.result.tin);
    if (stats.triangle_count == 0) {
        throw InputError(
            "build: the triangulation has no triangle (is everything outside the "
            "boundary?)");
    }
    GradientOptions gradients;
    gradients.threads = options.triangulate.threads;
    gradients.crease_at_breaklines = !s.contour_input;
    const TinInterpolant interpolant = TinInterpolant::prepare(
        s.result.tin, options.interpolation, gradients, progress.sub(triangulate_end, surface_end));
    clock.lap("triangulate");

    BuildReport report;
    report.contour_flats = std::move(s.contour_flats);
    report.dem_cells = s.dem;
    report.interpolation = interpolation_name(options.interpolation);
    detail::BuildContext context{options, s.result.tin, interpolant, loaded.crs_wkt,
                                 stats,   out,          report,      &loaded.summaries,
                                 {}};
    double at = surface_end;
    for (const detail::BuildStep& step : steps) {
        if (step.wanted != nullptr && !step.wanted(options)) continue;
        step.run(context, progress.sub(at, step.progress_end));
        at = step.progress_end;
        clock.lap(step.stage);
    }

    report.inputs = std::move(loaded.summaries);
    for (io::InputSummary& summary : report.inputs) {
        for (std::string& warning : summary.warnings) warning = context.worded(warning);
    }
    report.skipped_lines = loaded.skipped_lines;
    report.crs_wkt = loaded.crs_wkt;
    report.accounting = account_inputs(s.result, s.survey_points);
    report.triangulation = s.result.stats;
    report.conflicts = s.result.conflicts;
    report.surface = stats;
    report.timings = clock.take();
    report.outputs = out.files();
    report.outputs.emplace_back("report.json");
    write_report(report, out.add("report.json"));
    progress.report(0.99, "moving the products into place");
    out.commit();
    progress.report(1.0, "done");
    return report;
}

}  // namespace dtm::products
