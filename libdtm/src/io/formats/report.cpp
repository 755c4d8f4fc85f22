// SPDX-License-Identifier: MIT
// JSON report of `dtm build`, written with a small streaming JSON builder (no dependency).
// Numbers use the shortest text that reads back to the same double; NaN and infinities, which
// JSON cannot hold, become null.
#include "dtm/io/formats/report.hpp"

#include <ogr_spatialref.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>

#include "dtm/core/error.hpp"
#include "io/formats/detail/json_builder.hpp"

namespace dtm::io {
namespace {

using Json = detail::JsonBuilder;

void write_inputs(Json& json, const BuildReport& report) {
    json.open('[', "inputs");
    for (const InputSummary& in : report.inputs) {
        json.open('{');
        json.value("path", in.path.generic_string());
        json.value("format", in.format);
        json.value("crs", in.crs);
        json.value("points", in.points);
        json.value("breaklines", in.breaklines);
        json.value("breakline_vertices", in.breakline_vertices);
        json.value("boundaries", in.boundaries);
        json.value("holes", in.holes);
        json.value("duplicates", in.duplicates);
        json.value("skipped_lines", in.skipped_lines);
        json.open('[', "warnings");
        for (const std::string& warning : in.warnings) {
            json.value({}, warning);
        }
        json.close(']');
        json.close('}');
    }
    json.close(']');
}

void write_crs(Json& json, const std::string& wkt) {
    std::string name;
    std::string authority;
    if (!wkt.empty()) {
        OGRSpatialReference srs;
        if (srs.SetFromUserInput(wkt.c_str()) == OGRERR_NONE) {
            if (srs.GetAuthorityName(nullptr) == nullptr) {
                srs.AutoIdentifyEPSG();
            }
            name = srs.GetName() != nullptr ? srs.GetName() : "";
            if (srs.GetAuthorityName(nullptr) != nullptr &&
                srs.GetAuthorityCode(nullptr) != nullptr) {
                authority = std::string(srs.GetAuthorityName(nullptr)) + ":" +
                            srs.GetAuthorityCode(nullptr);
            }
        }
    }
    json.open('{', "crs");
    json.value("name", name);
    json.value("authority", authority);
    json.value("wkt", wkt);
    json.close('}');
}

void write_fate(Json& json, std::string_view key, const PointFate& fate) {
    json.open('{', key);
    json.value("read", fate.total);
    json.value("used", fate.used);
    json.value("merged_duplicates", fate.merged);
    json.value("outside_boundary_or_in_hole", fate.removed);
    json.close('}');
}

void write_points(Json& json, const BuildReport& report) {
    const InputAccounting& a = report.accounting;
    json.open('{', "points");
    write_fate(json, "survey_points", a.survey_points);
    write_fate(json, "line_vertices", a.line_vertices);
    json.value("skipped_bad_lines", report.skipped_lines);
    json.value("total_accounted",
               a.survey_points.total + a.line_vertices.total + report.skipped_lines);
    json.close('}');
}

void write_tin(Json& json, const BuildReport& report) {
    json.open('{', "tin");
    json.value("vertices", report.surface.vertex_count);
    json.value("triangles", report.surface.triangle_count);
    json.value("constrained_edges", report.surface.constraint_count);
    json.value("breakline_intersections", report.triangulation.intersections);
    json.value("removed_triangles", report.triangulation.removed_triangles);
    json.close('}');
    json.open('{', "conflicts");
    json.value("count", report.conflicts.size());
    json.open('[', "items");
    for (std::size_t i = 0; i < report.conflicts.size() && i < report_conflict_limit; ++i) {
        const ConstraintConflict& c = report.conflicts[i];
        json.open('{');
        json.value("x", c.at.x);
        json.value("y", c.at.y);
        json.value("z_first", c.z_first);
        json.value("z_second", c.z_second);
        json.value("difference", std::fabs(c.z_first - c.z_second));
        json.close('}');
    }
    json.close(']');
    json.close('}');
}

void write_surface(Json& json, const BuildReport& report) {
    const SurfaceStats& s = report.surface;
    json.open('{', "extent");
    json.value("xmin", s.extent.xmin);
    json.value("ymin", s.extent.ymin);
    json.value("xmax", s.extent.xmax);
    json.value("ymax", s.extent.ymax);
    json.close('}');
    json.open('{', "z_range");
    json.value("min", s.z_min);
    json.value("max", s.z_max);
    json.close('}');
    json.open('{', "area");
    json.value("planimetric", s.planimetric_area);
    json.value("surface_3d", s.surface_area);
    json.value("ratio", s.planimetric_area > 0.0 ? s.surface_area / s.planimetric_area : 0.0);
    json.close('}');
}

void write_products(Json& json, const BuildReport& report) {
    json.open('{', "dem");
    json.value("cell", report.dem.cell);
    json.value("cell_rule", report.cell_rule);
    json.value("cols", report.dem.cols);
    json.value("rows", report.dem.rows);
    json.value("xmin", report.dem.xmin);
    json.value("ymax", report.dem.ymax);
    json.close('}');
    json.open('{', "contours");
    json.value("interval", report.contour_interval);
    json.value("index_every", report.index_every);
    json.value("interval_rule", report.interval_rule);
    json.value("levels", report.contour_levels);
    json.value("lines", report.contour_lines);
    json.close('}');
    json.open('{', "timings_seconds");
    double total = 0.0;
    for (const StageTime& t : report.timings) {
        json.value(t.stage, t.seconds);
        total += t.seconds;
    }
    json.value("total", total);
    json.close('}');
    json.open('[', "outputs");
    for (const std::string& file : report.outputs) {
        json.value({}, file);
    }
    json.close(']');
}

}  // namespace

std::string report_json(const BuildReport& report) {
    Json json;
    json.open('{');
    json.value("dtm_version", DTM_VERSION);
    write_inputs(json, report);
    write_crs(json, report.crs_wkt);
    write_points(json, report);
    write_tin(json, report);
    write_surface(json, report);
    write_products(json, report);
    json.close('}');
    return json.str();
}

void write_report(const BuildReport& report, const std::filesystem::path& path) {
    const std::string text = report_json(report);
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    file.write(text.data(), static_cast<std::streamsize>(text.size()));
    file.close();
    if (!file) {
        throw Error("report: cannot write " + path.string());
    }
}

}  // namespace dtm::io
