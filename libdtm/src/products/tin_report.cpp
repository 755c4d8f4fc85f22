// SPDX-License-Identifier: MIT
// dtm tin's report and stats documents (products/tin_report.hpp).
#include "dtm/products/tin_report.hpp"

#include <fstream>

#include "dtm/algo/criteria.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"

namespace dtm::products {

void optimize_json(io::JsonWriter& json, const OptimizeStats& o) {
    using Layout = io::JsonWriter::Layout;
    if (o.criterion == Criterion::delaunay) return;
    json.begin_object("optimize", Layout::inline_);
    json.value("criterion", criterion_name(o.criterion));
    json.value("flips", static_cast<std::size_t>(o.flips));
    json.value("improvable_before", o.improvable_before);
    json.value("improvable_after", o.improvable_after);
    json.value("converged", o.converged);
    for (const auto& [key, q] :
         {std::pair{"quality_before", &o.before}, {"quality_after", &o.after}}) {
        json.begin_object(key, Layout::inline_);
        json.value("worst", q->worst);
        json.value("mean", q->mean);
        json.value("sum", q->sum);
        json.end();
    }
    json.value("seconds", o.seconds);
    json.end();
}

std::string tin_report_json(const TriangulateResult& r) {
    using Layout = io::JsonWriter::Layout;
    io::JsonWriter json;
    json.begin_object();
    json.value("duplicates_merged", r.merges.size());
    json.begin_array("merges");
    const auto point = [&json](const char* key, const Point3& p) {
        json.begin_array(key, Layout::inline_);
        for (const double c : {p.x, p.y, p.z}) json.value({}, c);
        json.end();
    };
    for (const DuplicateMerge& m : r.merges) {
        json.begin_object({}, Layout::inline_);
        json.value("kept_input", m.kept_input);
        json.value("merged_input", m.merged_input);
        point("kept", m.kept);
        point("merged", m.merged);
        json.end();
    }
    json.end();
    json.begin_array("conflicts");
    for (const ConstraintConflict& c : r.conflicts) {
        json.begin_object({}, Layout::inline_);
        json.value("x", c.at.x);
        json.value("y", c.at.y);
        json.value("z_first", c.z_first);
        json.value("z_second", c.z_second);
        json.end();
    }
    json.end();
    optimize_json(json, r.stats.optimize);
    json.end();
    return json.str();
}

void write_tin_report(const std::filesystem::path& path, const TriangulateResult& result) {
    io::AtomicOutput out(path);
    {
        std::ofstream f(out.temp_path(), std::ios::binary);
        f << tin_report_json(result);
        if (!f) throw Error("cannot write the report " + path.string());
    }
    out.commit();
}

std::string tin_stats_json(const Surface& surface,
                           std::size_t skipped_lines,
                           const TinTimes& seconds) {
    using Layout = io::JsonWriter::Layout;
    const TriangulateResult& result = surface.result;
    const TriangulateStats& s = result.stats;
    io::JsonWriter json;
    json.begin_object({}, Layout::inline_);
    json.value("ranks", std::size_t{1});
    json.value("points_in", s.points_in);
    json.value("duplicates_merged", s.duplicates_merged);
    json.value("skipped_lines", skipped_lines);
    json.value("vertices", result.tin.vertices.size());
    json.value("triangles", result.tin.triangles.size());
    json.value("constrained_edges", result.tin.constraints.size());
    json.value("intersections", s.intersections);
    json.value("conflicts", s.conflicts);
    json.value("removed_triangles", s.removed_triangles);
    if (surface.contour_flats) {
        const ContourFlatsReport& f = *surface.contour_flats;
        json.begin_object("contour_flats", Layout::inline_);
        json.value("flat_before", f.flat_before);
        json.value("triangles_before", f.triangles_before);
        json.value("flat_after", f.flat_after);
        json.value("points_added", f.points_added);
        json.value("regions", f.regions);
        json.value("real_flats", f.true_flats);
        json.value("estimated_peaks", f.peaks.size());
        json.end();
    }
    json.begin_object("seconds", Layout::inline_);
    json.value("read", seconds.read);
    json.value("triangulate", s.seconds_triangulate);
    json.value("constrain", s.seconds_constrain);
    json.value("write", seconds.write);
    json.value("total", seconds.total);
    json.end();
    optimize_json(json, s.optimize);
    json.end();
    return json.str();
}

std::string distributed_tin_stats_json(const DistributedTinResult& r, double total_seconds) {
    using Layout = io::JsonWriter::Layout;
    io::JsonWriter json;
    json.begin_object({}, Layout::inline_);
    json.value("ranks", static_cast<std::size_t>(r.ranks));
    json.value("points_in", r.points);
    json.value("duplicates_merged", r.points + r.crossings - r.vertices);
    json.value("skipped_lines", r.skipped_lines);
    json.value("vertices", r.vertices);
    json.value("triangles", r.triangles);
    json.value("constrained_edges", r.constrained_edges);
    json.value("removed_triangles", r.removed_triangles);
    json.value("bytes_sent", r.bytes_sent);
    json.value("band_triangles", r.band_triangles);
    json.value("widenings", static_cast<std::size_t>(r.widenings));
    json.value("tiles", r.tiles.size());  // 0: one PLY
    json.begin_object("seconds", Layout::inline_);
    json.value("total", total_seconds);
    json.end();
    json.end();
    return json.str();
}

}  // namespace dtm::products
