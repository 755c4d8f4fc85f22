// SPDX-License-Identifier: MIT
// HPGL plan reader: bytes -> plot (hpgl_lexer, hpgl_pe, hpgl_plot) -> spot heights and lines
// by pen role (hpgl_plan_heights, hpgl_plan_lines) -> ground coordinates (hpgl_georef) -> ReadResult.
// See docs/formats.md, section "HPGL", for the user-facing rules.
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

constexpr std::array<std::pair<std::string_view, PenRole>, 8> role_names{{
    {"points", PenRole::points},
    {"breakline", PenRole::breakline},
    {"soft-breakline", PenRole::soft_breakline},
    {"soft_breakline", PenRole::soft_breakline},
    {"soft", PenRole::soft_breakline},
    {"boundary", PenRole::boundary},
    {"hole", PenRole::hole},
    {"ignore", PenRole::ignore},
}};

std::string_view trim(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

int parse_pen(std::string_view text, std::string_view option)
{
    text = trim(text);
    int pen = 0;
    bool ok = !text.empty() && text.size() <= 6;
    for (const char c : text) {
        ok = ok && c >= '0' && c <= '9';
        if (ok) pen = pen * 10 + (c - '0');
    }
    if (!ok) throw UsageError(std::string(option) + ": '" + std::string(text) + "' is not a pen number");
    return pen;
}

std::string read_bytes(const std::filesystem::path& path)
{
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

    Point3 place(const Point3& p, bool counts_for_z)
    {
        const Point2 g = transform.apply({p.x, p.y});
        box.add(g);
        if (counts_for_z) {
            zmin = std::min(zmin, p.z);
            zmax = std::max(zmax, p.z);
        }
        return {g.x, g.y, p.z};
    }
};

void emit(hpgl::TerrainPlan& plan, const std::filesystem::path& path, Output& out)
{
    TerrainInput& t = out.result.terrain;
    for (const hpgl::SpotHeight& s : plan.spots) t.points.push_back(out.place({s.at.x, s.at.y, s.z}, true));
    for (hpgl::RoleLine& line : plan.lines) {
        Polyline poly;
        poly.closed = line.closed;
        poly.source = path.string() + ":byte " + std::to_string(line.offset);
        const bool hard = line.role != PenRole::soft_breakline && line.height_vertices > 0;
        for (Point3& p : line.points) p = out.place(p, hard);
        poly.points = std::move(line.points);
        switch (line.role) {
        case PenRole::breakline: t.breaklines.push_back(std::move(poly)); break;
        case PenRole::soft_breakline: t.soft_breaklines.push_back(std::move(poly)); break;
        case PenRole::boundary: t.boundaries.push_back(std::move(poly)); break;
        case PenRole::hole: t.holes.push_back(std::move(poly)); break;
        default: break;
        }
    }
}

void summarize(const hpgl::Plot& plot, const hpgl::TerrainPlan& plan, hpgl::Georeference& geo, Output& out)
{
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
        w.push_back(std::to_string(plot.unknown_instructions) + " instructions not understood and skipped (" +
                    plot.unknown_names + ")");
    }
    w.insert(w.end(), plan.warnings.begin(), plan.warnings.end());
    w.insert(w.end(), geo.notes.begin(), geo.notes.end());
    w.push_back(std::to_string(plot.labels.size()) + " labels, " + std::to_string(plan.height_labels) +
                " spot heights (" + std::to_string(plan.height_labels - plan.labels_without_marker) +
                " on markers), " + std::to_string(plan.markers) + " markers (" + std::to_string(plan.crosses) +
                " crosses)");
}

}  // namespace

std::string_view pen_role_name(PenRole role) noexcept
{
    switch (role) {
    case PenRole::points: return "points";
    case PenRole::breakline: return "breakline";
    case PenRole::soft_breakline: return "soft-breakline";
    case PenRole::boundary: return "boundary";
    case PenRole::hole: return "hole";
    case PenRole::ignore: return "ignore";
    }
    return "ignore";
}

std::map<int, PenRole> parse_pen_roles(std::string_view text)
{
    std::map<int, PenRole> roles;
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trim(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (item.empty()) continue;
        const auto equals = item.find('=');
        if (equals == std::string_view::npos) {
            throw UsageError("--hpgl-pens: '" + std::string(item) + "' is not PEN=ROLE (for example 2=breakline)");
        }
        const int pen = parse_pen(item.substr(0, equals), "--hpgl-pens");
        const std::string_view name = trim(item.substr(equals + 1));
        const auto found = std::find_if(role_names.begin(), role_names.end(),
                                        [&](const auto& entry) { return entry.first == name; });
        if (found == role_names.end()) {
            throw UsageError("--hpgl-pens: unknown role '" + std::string(name) +
                             "' (expected points, breakline, soft-breakline, boundary, hole or ignore)");
        }
        roles[pen] = found->second;
    }
    return roles;
}

std::vector<int> parse_pen_list(std::string_view text)
{
    std::vector<int> pens;
    while (!text.empty()) {
        const auto comma = text.find(',');
        const std::string_view item = trim(text.substr(0, comma));
        text = comma == std::string_view::npos ? std::string_view{} : text.substr(comma + 1);
        if (!item.empty()) pens.push_back(parse_pen(item, "--hpgl-height-pens"));
    }
    return pens;
}

ReadResult read_hpgl(const InputFile& file, const LoadOptions& options, const Progress& progress)
{
    const HpglOptions& hpgl_options = options.hpgl;
    if (!(hpgl_options.marker_radius_mm >= 0.0) || !std::isfinite(hpgl_options.marker_radius_mm)) {
        throw UsageError("--hpgl-marker-radius must be a non-negative number of millimetres");
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
