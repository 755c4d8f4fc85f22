// SPDX-License-Identifier: MIT
// The JSON report of products::build(), written with io::JsonWriter (block layout, 2-space
// indentation; NaN and infinities become null).
#include "dtm/products/report.hpp"

#include <ogr_spatialref.h>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numeric>

#include "dtm/core/error.hpp"
#include "dtm/io/json_writer.hpp"

namespace dtm::products {
namespace {

void write_inputs(io::JsonWriter& json, const BuildReport& report) {
    json.begin_array("inputs");
    for (const io::InputSummary& in : report.inputs) {
        json.begin_object();
        json.value("path", in.path.generic_string());
        json.value("format", in.format);
        json.value("crs", in.crs);
        if (!in.crs_note.empty()) json.value("crs_note", in.crs_note);
        json.value("points", in.points);
        json.value("breaklines", in.breaklines);
        json.value("breakline_vertices", in.breakline_vertices);
        json.value("boundaries", in.boundaries);
        json.value("holes", in.holes);
        json.value("duplicates", in.duplicates);
        json.value("skipped_lines", in.skipped_lines);
        if (in.cloud) {  // a point cloud: where every record went (points = kept)
            json.begin_object("point_records");
            json.value("read", in.cloud->records);
            json.value("withheld", in.cloud->withheld);
            json.value("filtered_by_class", in.cloud->class_filtered);
            json.value("thinned", in.cloud->thinned);
            json.end();
        }
        json.begin_array("warnings");
        for (const std::string& warning : in.warnings) {
            json.value({}, warning);
        }
        json.end();
        json.end();
    }
    json.end();
}

void write_crs(io::JsonWriter& json, const std::string& wkt) {
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
    json.begin_object("crs");
    json.value("name", name);
    json.value("authority", authority);
    json.value("wkt", wkt);
    json.end();
}

void write_fate(io::JsonWriter& json, std::string_view key, const PointFate& fate) {
    json.begin_object(key);
    json.value("read", fate.total);
    json.value("used", fate.used);
    json.value("merged_duplicates", fate.merged);
    json.value("outside_boundary_or_in_hole", fate.removed);
    json.end();
}

/// A distributed build knows the fate of the vertices, not of each input point.
void write_distributed_points(io::JsonWriter& json, const BuildReport& report) {
    const DistributedRun& d = *report.distributed;
    json.begin_object("points");
    json.value("survey_points", d.survey_points);
    json.value("line_vertices", d.line_vertices);
    json.value("merged_duplicates", d.merged);
    json.value("breakline_crossing_vertices", d.crossing_vertices);
    json.value("vertices_in_no_triangle", d.unused_vertices);
    json.value("skipped_bad_lines", report.skipped_lines);
    json.value("total_accounted", d.survey_points + d.line_vertices + report.skipped_lines);
    json.end();
    json.begin_object("distributed");
    json.value("ranks", static_cast<std::size_t>(d.ranks));
    json.value("band_triangles", d.band_triangles);
    json.value("widenings", static_cast<std::size_t>(d.widenings));
    json.value("bytes_sent", d.bytes_sent);
    json.begin_object("bytes_sent_per_phase");
    for (const auto& [phase, bytes] : d.phase_bytes) json.value(phase, bytes);
    json.end();
    json.end();
}

void write_points(io::JsonWriter& json, const BuildReport& report) {
    if (report.distributed) {
        write_distributed_points(json, report);
        return;
    }
    const InputAccounting& a = report.accounting;
    json.begin_object("points");
    write_fate(json, "survey_points", a.survey_points);
    write_fate(json, "line_vertices", a.line_vertices);
    json.value("skipped_bad_lines", report.skipped_lines);
    json.value("total_accounted",
               a.survey_points.total + a.line_vertices.total + report.skipped_lines);
    json.end();
}

void write_tin(io::JsonWriter& json, const BuildReport& report) {
    json.begin_object("tin");
    json.value("vertices", report.surface.vertex_count);
    json.value("triangles", report.surface.triangle_count);
    json.value("constrained_edges", report.surface.constraint_count);
    json.value("breakline_intersections", report.triangulation.intersections);
    json.value("removed_triangles", report.triangulation.removed_triangles);
    json.end();
    if (report.contour_flats) {
        const ContourFlatsReport& f = *report.contour_flats;
        json.begin_object("contour_flats");
        json.value("triangles_before", f.triangles_before);
        json.value("flat_before", f.flat_before);
        json.value("triangles_after", f.triangles_after);
        json.value("flat_after", f.flat_after);
        json.value("regions", f.regions);
        json.value("real_flats", f.true_flats);
        json.value("unresolved", f.unresolved);
        json.value("points_added", f.points_added);
        json.begin_array("estimated_peaks");
        for (const EstimatedPeak& p : f.peaks) {
            json.begin_object({}, io::JsonWriter::Layout::inline_);
            json.value("kind", p.summit ? "summit" : "pit");
            json.value("x", p.at.x);
            json.value("y", p.at.y);
            json.value("z", p.at.z);
            json.value("contour", p.contour);
            json.end();
        }
        json.end();
        json.end();
    }
    if (report.dem_cells) {
        const DemReduceReport& d = *report.dem_cells;
        json.begin_object("dem_cells");
        json.value("cells", d.cells);
        json.value("clipped", d.clipped);
        json.value("kept", d.kept);
        json.value("passes", d.passes);
        json.value("vertices", d.vertices);
        json.value("max_error", d.max_error);
        json.value("rms_error", d.rms_error);
        json.value("measured", d.measured);
        json.value("outside", d.outside);
        json.value("over_error", d.over_error);
        json.end();
    }
    json.begin_object("conflicts");
    json.value("count", report.conflicts.size());
    json.begin_array("items");
    for (std::size_t i = 0; i < report.conflicts.size() && i < report_conflict_limit; ++i) {
        const ConstraintConflict& c = report.conflicts[i];
        json.begin_object();
        json.value("x", c.at.x);
        json.value("y", c.at.y);
        json.value("z_first", c.z_first);
        json.value("z_second", c.z_second);
        json.value("difference", std::fabs(c.z_first - c.z_second));
        json.end();
    }
    json.end();
    json.end();
}

void write_surface(io::JsonWriter& json, const BuildReport& report) {
    const SurfaceStats& s = report.surface;
    json.begin_object("extent");
    json.value("xmin", s.extent.xmin);
    json.value("ymin", s.extent.ymin);
    json.value("xmax", s.extent.xmax);
    json.value("ymax", s.extent.ymax);
    json.end();
    json.begin_object("z_range");
    json.value("min", s.z_min);
    json.value("max", s.z_max);
    json.end();
    json.begin_object("area");
    json.value("planimetric", s.planimetric_area);
    json.value("surface_3d", s.surface_area);
    json.value("ratio", s.planimetric_area > 0.0 ? s.surface_area / s.planimetric_area : 0.0);
    json.end();
}

void write_products(io::JsonWriter& json, const BuildReport& report) {
    json.begin_object("dem");
    json.value("interpolation", report.interpolation);
    json.value("cell", report.dem.cell);
    json.value("cell_rule", report.cell_rule);
    json.value("cols", report.dem.cols);
    json.value("rows", report.dem.rows);
    json.value("xmin", report.dem.xmin);
    json.value("ymax", report.dem.ymax);
    json.end();
    json.begin_object("contours");
    json.value("interval", report.contour_interval);
    json.value("index_every", report.index_every);
    json.value("interval_rule", report.interval_rule);
    json.value("levels", report.contour_levels);
    json.value("lines", report.contour_lines);
    json.value("label_scale", report.contour_label_scale);
    json.value("labels_placed", report.contour_labels);
    json.value("label_positions_without_room", report.contour_label_failures);
    json.value("spot_heights", report.contour_spot_heights);
    json.end();
    if (report.map_scale > 0.0) {
        json.begin_object("map");
        json.value("scale", report.map_scale);
        json.value("labels_placed", report.map_labels);
        json.value("label_positions_without_room", report.map_label_failures);
        json.value("spot_heights", report.map_spot_heights);
        json.end();
    }
    if (report.has_volume) {
        const VolumeResult& v = report.volume;
        json.begin_object("volume");  // the figures of volume/volume.json
        json.value("base", report.volume_base);
        json.value("fill", v.fill);
        json.value("cut", v.cut);
        json.value("net", v.net());
        json.value("fill_area", v.fill_area);
        json.value("cut_area", v.cut_area);
        json.value("top_only_area", v.top_only_area);
        json.value("base_only_area", v.base_only_area);
        json.end();
    }
    json.begin_object("timings_seconds");
    double total = 0.0;
    for (const StageTime& t : report.timings) {
        json.value(t.stage, t.seconds);
        total += t.seconds;
    }
    json.value("total", total);
    json.end();
    json.begin_array("outputs");
    for (const std::string& file : report.outputs) {
        json.value({}, file);
    }
    json.end();
}

}  // namespace

std::string report_json(const BuildReport& report) {
    io::JsonWriter json;
    json.begin_object();
    json.value("dtm_version", DTM_VERSION);
    write_inputs(json, report);
    write_crs(json, report.crs_wkt);
    write_points(json, report);
    write_tin(json, report);
    write_surface(json, report);
    write_products(json, report);
    json.end();
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

}  // namespace dtm::products
