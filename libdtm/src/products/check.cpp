// SPDX-License-Identifier: MIT
// The check job: surface and control points in one CRS, heights through the SurfaceHeight
// interface, residuals and statistics (algo/check_points), CSV and JSON out.
#include "dtm/products/check.hpp"

#include <cstdio>
#include <fstream>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/io/output_check.hpp"

namespace dtm::products {
namespace fs = std::filesystem;
namespace {

void write_atomic(const fs::path& path, const std::string& text) {
    io::AtomicOutput out(path);
    {
        std::ofstream f(out.temp_path(), std::ios::binary);
        f << text;
        if (!f) {
            throw Error("cannot write " + path.string());
        }
    }
    out.commit();
}

}  // namespace

std::unique_ptr<SurfaceHeight> make_surface_height(const Tin& tin,
                                                   const TinInterpolant& interpolant) {
    if (interpolant.method() == Interpolation::linear) return std::make_unique<LinearSurface>(tin);
    return std::make_unique<InterpolatedSurface>(tin, interpolant);
}

std::string check_json(const CheckReport& r) {
    const CheckStatistics& s = r.stats;
    io::JsonWriter json;
    json.begin_object();
    json.value("residual", "point z - surface z");
    json.value("points", s.points);
    json.value("inside", s.inside);
    json.value("outside", s.outside);
    json.value("mean", s.mean);
    json.value("std_dev", s.std_dev);
    json.value("rmse", s.rmse);
    json.value("mean_abs", s.mean_abs);
    json.value("min", s.min);
    json.value("max", s.max);
    json.value("max_abs", s.max_abs);
    json.value("max_abs_id", r.max_abs_id);
    json.value("nssda_95", s.nssda_95);
    json.begin_object("abs_percentiles");
    json.value("p50", s.p50);
    json.value("p68.27", s.p68);
    json.value("p90", s.p90);
    json.value("p95", s.p95);
    json.value("p99", s.p99);
    json.end();
    json.begin_array("outside_ids");
    for (const std::string& id : r.outside_ids) {
        json.value({}, id);
    }
    json.end();
    json.end();
    return json.str();
}

CheckReport run_check(const CheckJob& job, const fs::path& csv, const Progress& progress) {
    io::check_output(csv, io::OutputKind::any_file, "output");  // before any input is read
    if (!job.stats.empty()) io::check_output(job.stats, io::OutputKind::any_file, "stats");
    const LoadedSurface surface = load_surface(job.surface, {}, progress.sub(0.0, 0.6));
    const ControlPoints points = load_points(job.points, job.point_reader, surface.crs_wkt);
    const TinInterpolant interpolant =
        TinInterpolant::prepare(surface.tin, job.interpolation, {}, progress.sub(0.6, 0.7));
    const std::unique_ptr<SurfaceHeight> height = make_surface_height(surface.tin, interpolant);
    const std::vector<CheckResult> results =
        check_points(*height, points.points, progress.sub(0.7, 0.9));
    CheckReport report;
    report.stats = check_statistics(results);
    std::string text = "id,x,y,z,surface_z,residual,status\n";
    char row[256];
    for (std::size_t i = 0; i < results.size(); ++i) {
        const Point3& p = points.points[i];
        if (results[i].inside) {
            std::snprintf(row, sizeof row, ",%.4f,%.4f,%.4f,%.6f,%.6f,inside\n", p.x, p.y, p.z,
                          results[i].surface_z, results[i].residual);
        } else {
            std::snprintf(row, sizeof row, ",%.4f,%.4f,%.4f,,,outside\n", p.x, p.y, p.z);
            report.outside_ids.push_back(points.ids[i]);
        }
        text += points.ids[i];
        text += row;
    }
    if (report.stats.inside > 0) {
        report.max_abs_id = points.ids[report.stats.max_abs_index];
    }
    write_atomic(csv, text);
    if (!job.stats.empty()) {
        write_atomic(job.stats, check_json(report));
    }
    progress.report(1.0, "done");
    return report;
}

}  // namespace dtm::products
