// SPDX-License-Identifier: MIT
// HPGL plan reader: bytes -> plot (hpgl_lexer, hpgl_pe, hpgl_plot) -> spot heights and lines
// by pen role (hpgl_plan_heights, hpgl_plan_lines) -> ground coordinates (hpgl_georef) ->
// ReadResult. See docs/formats.md, section "HPGL", for the user-facing rules.
#include "dtm/io/formats/hpgl.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>

#include "dtm/core/error.hpp"
#include "io/formats/hpgl/hpgl_georef.hpp"
#include "io/formats/hpgl/hpgl_plan.hpp"
#include "io/formats/hpgl/hpgl_plot.hpp"

namespace dtm::io {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path, 0, 0, "cannot open the file");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw InputError(path, 0, 0, "read error");
    return bytes;
}

struct Output {
    const hpgl::Affine& transform;
    ReadResult& result;
    Box2 box;
    double zmin = std::numeric_limits<double>::infinity();
    double zmax = -std::numeric_limits<double>::infinity();

    Point3 place(const Point3& p, bool counts_for_z) {
        const Point2 g = transform.apply({p.x, p.y});
        box.add(g);
        if (counts_for_z) {
            zmin = std::min(zmin, p.z);
            zmax = std::max(zmax, p.z);
        }
        return {g.x, g.y, p.z};
    }
};

void emit(hpgl::TerrainPlan& plan, const std::filesystem::path& path, Output& out) {
    TerrainInput& t = out.result.terrain;
    for (const hpgl::SpotHeight& s : plan.spots)
        t.points.push_back(out.place({s.at.x, s.at.y, s.z}, true));
    for (hpgl::RoleLine& line : plan.lines) {
        Polyline poly;
        poly.closed = line.closed;
        poly.source = path.string() + ":byte " + std::to_string(line.offset);
        const bool hard = line.role != PenRole::soft_breakline && line.height_vertices > 0;
        for (Point3& p : line.points) p = out.place(p, hard);
        poly.points = std::move(line.points);
        switch (line.role) {
            case PenRole::breakline:
                t.breaklines.push_back(std::move(poly));
                break;
            case PenRole::soft_breakline:
                t.soft_breaklines.push_back(std::move(poly));
                break;
            case PenRole::boundary:
                t.boundaries.push_back(std::move(poly));
                break;
            case PenRole::hole:
                t.holes.push_back(std::move(poly));
                break;
            default:
                break;
        }
    }
}

void summarize(const hpgl::Plot& plot,
               const hpgl::TerrainPlan& plan,
               hpgl::Georeference& geo,
               Output& out) {
    InputSummary& s = out.result.summary;
    const TerrainInput& t = out.result.terrain;
    s.format = "hpgl";
    s.points = t.points.size();
    s.breaklines = t.breaklines.size() + t.soft_breaklines.size();
    for (const auto* lines : {&t.breaklines, &t.soft_breaklines}) {
        for (const Polyline& l : *lines) s.breakline_vertices += l.points.size();
    }
    s.boundaries = t.boundaries.size();
    s.holes = t.holes.size();
    if (!out.box.empty()) s.bbox = {out.box.xmin, out.box.ymin, out.box.xmax, out.box.ymax};
    if (out.zmin <= out.zmax) s.z_range = {out.zmin, out.zmax};
    s.skipped_lines = plot.problems;
    auto& w = s.warnings;
    w.insert(w.end(), plot.warnings.begin(), plot.warnings.end());
    if (plot.unknown_instructions > 0) {
        w.push_back(std::to_string(plot.unknown_instructions) +
                    " instructions not understood and skipped (" + plot.unknown_names + ")");
    }
    w.insert(w.end(), plan.warnings.begin(), plan.warnings.end());
    w.insert(w.end(), geo.notes.begin(), geo.notes.end());
    w.push_back(std::to_string(plot.labels.size()) + " labels, " +
                std::to_string(plan.height_labels) + " spot heights (" +
                std::to_string(plan.height_labels - plan.labels_without_marker) + " on markers), " +
                std::to_string(plan.markers) + " markers (" + std::to_string(plan.crosses) +
                " crosses)");
}

}  // namespace

std::string_view pen_role_name(PenRole role) noexcept {
    switch (role) {
        case PenRole::points:
            return "points";
        case PenRole::breakline:
            return "breakline";
        case PenRole::soft_breakline:
            return "soft-breakline";
        case PenRole::boundary:
            return "boundary";
        case PenRole::hole:
            return "hole";
        case PenRole::ignore:
            return "ignore";
    }
    return "ignore";
}

ReadResult read_hpgl(const InputFile& file, const ReadOptions& options, const Progress& progress) {
    const HpglOptions& hpgl_options = options.hpgl;
    if (!(hpgl_options.marker_radius_mm >= 0.0) || !std::isfinite(hpgl_options.marker_radius_mm)) {
        throw OptionError("hpgl.marker_radius_mm",
                          "`hpgl.marker_radius_mm` must be a non-negative number of millimetres");
    }
    hpgl::Georeference geo = hpgl::make_georeference(hpgl_options);
    progress.report(0.0, "reading HPGL");
    const std::string bytes = read_bytes(file.path);
    hpgl::PlotOptions plot_options;
    plot_options.circle_marker_radius = hpgl_options.marker_radius_mm * hpgl::units_per_mm;
    plot_options.strict = !options.skip_bad_lines;
    hpgl::Plot plot = hpgl::plot_hpgl(bytes, file.path, plot_options, progress.sub(0.0, 0.9));
    hpgl::TerrainPlan plan = hpgl::build_terrain_plan(plot, hpgl_options);
    std::vector<hpgl::PlotLine>().swap(plot.lines);  // the plan holds what is needed; free memory
    progress.check();

    ReadResult result;
    result.summary.path = file.path;
    Output out{geo.transform, result, {}};
    emit(plan, file.path, out);
    summarize(plot, plan, geo, out);
    progress.report(1.0, "reading HPGL");
    return result;
}

}  // namespace dtm::io
