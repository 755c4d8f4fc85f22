// SPDX-License-Identifier: MIT
// The one table from library option fields to dtm's flags. A field the library names in a message
// but missing here would reach the user in backquotes: tests/cli/option_names_test.cpp checks
// that every `field` in the library's string literals has a row.
#include "option_names.hpp"

#include <algorithm>
#include <array>
#include <utility>

namespace dtm::cli {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 51> flags{{
    // io::LoadOptions: the files of each role (TerrainInput's members)
    {"breaklines", "--breaklines"},
    {"soft_breaklines", "--soft-breaklines"},
    {"boundaries", "--boundary"},
    {"holes", "--holes"},
    // io::CrsOptions
    {"default_crs", "--crs"},
    {"target_crs", "--target-crs"},
    // io::ReadOptions
    {"skip_bad_lines", "--skip-bad-lines"},
    {"columns", "--columns"},
    {"layer", "--layer"},
    {"where", "--where"},
    {"z_field", "--z-field"},
    {"retriangulate", "--retriangulate"},
    {"surface", "--surface"},
    {"classes", "--classes"},
    {"thin", "--thin"},
    {"hpgl.pens", "--hpgl-pens"},
    {"hpgl.height_pens", "--hpgl-height-pens"},
    {"hpgl.marker_radius_mm", "--hpgl-marker-radius"},
    {"hpgl.scale", "--hpgl-scale"},
    {"hpgl.origin", "--hpgl-origin"},
    {"hpgl.rotation_deg", "--hpgl-rotation"},
    {"hpgl.control_file", "--hpgl-control"},
    // TriangulateOptions
    {"snap_distance", "--snap"},
    {"duplicates", "--duplicates"},
    {"max_edge", "--max-edge"},
    {"z_tolerance", "--z-tolerance"},
    {"threads", "--threads"},
    {"tiles", "--tiles"},
    // products::build, io::GridWriteOptions, ContourOptions
    {"out_dir", "-o"},
    {"cell", "--cell"},
    {"interval", "--interval"},
    {"index_every", "--index-every"},
    {"cog", "--cog"},
    {"levels", "--levels"},
    // io::check_output: the outputs of tin, grid, contour and methods
    {"output", "-o"},
    {"report", "--report"},
    {"hillshade", "--hillshade"},
    {"slope", "--slope"},
    {"aspect", "--aspect"},
    // io::map::MapOptions, products::BuildOptions::map_scale
    {"scale", "--scale"},
    {"paper", "--paper"},
    {"extent", "--extent"},
    {"sheets", "--sheets"},
    {"map_scale", "--map-scale"},
    {"subdivisions", "--subdivisions"},
    // DemReduceOptions (products::SurfaceOptions::dem)
    {"dem.clip_radius", "--dem-clip-radius"},
    {"dem.max_error", "--dem-max-error"},
    // products::ContourFileOptions
    {"spot_heights", "--spot-heights"},
    // products::CheckJob, ProfileJob, SectionsJob
    {"interpolation", "--interpolation"},
    {"plot_format", "--plot"},
    {"stats", "--stats"},
}};

}  // namespace

std::string_view flag_of(std::string_view field) noexcept {
    for (const auto& [name, flag] : flags) {
        if (name == field) return flag;
    }
    return {};
}

std::string cli_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    std::size_t at = 0;
    while (at < text.size()) {
        const std::size_t open = text.find('`', at);
        const std::size_t close = open == std::string_view::npos ? open : text.find('`', open + 1);
        if (close == std::string_view::npos) break;
        const std::string_view flag = flag_of(text.substr(open + 1, close - open - 1));
        out.append(text.substr(at, open - at));
        if (flag.empty()) {
            out.append(text.substr(open, 1));  // not a field: keep the backquote, go on after it
            at = open + 1;
        } else {
            out.append(flag);
            at = close + 1;
        }
    }
    out.append(text.substr(std::min(at, text.size())));
    return out;
}

}  // namespace dtm::cli
