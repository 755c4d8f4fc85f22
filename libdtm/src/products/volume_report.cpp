// SPDX-License-Identifier: MIT
// volume.json (machine-readable, every figure) and volume.txt (a short protocol a surveyor can
// check and sign). Fill is where the top lies above the base, cut where it lies below.
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>

#include "dtm/io/formats/crs.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/products/volume.hpp"

namespace dtm::products {

std::string volume_json(const VolumeReport& r) {
    const VolumeResult& v = r.volume;
    io::JsonWriter json;
    json.begin_object();
    json.value("dtm_version", DTM_VERSION);
    json.value("crs", io::crs_label(r.crs_wkt));
    json.value("convention", "fill: top above base; cut: top below base; net = fill - cut");
    json.begin_object("top");
    json.value("source", r.top);
    json.value("triangles", r.top_triangles);
    json.end();
    json.begin_object("base");
    json.value("source", r.base);
    json.value("plane", v.base_is_plane);
    json.value("triangles", r.base_triangles);
    json.end();
    if (!r.within.empty()) {
        json.value("within", r.within);
    }
    json.begin_object("volume");
    json.value("fill", v.fill);
    json.value("cut", v.cut);
    json.value("net", v.net());
    json.value("swell_factor", r.swell);
    json.value("cut_loose", v.cut * r.swell);
    json.value("fill_bank", v.fill / r.swell);
    json.end();
    json.begin_object("area");
    json.value("fill", v.fill_area);
    json.value("cut", v.cut_area);
    json.value("unchanged", v.unchanged_area);
    json.value("overlap", v.overlap_area);
    json.value("top", v.top_area);
    if (v.base_is_plane) {
        json.null("base");
        json.null("base_only");
    } else {
        json.value("base", v.base_area);
        json.value("base_only", v.base_only_area);
    }
    json.value("top_only", v.top_only_area);
    json.value("fill_top_3d", v.fill_area_top_3d);
    json.value("fill_base_3d", v.fill_area_base_3d);
    json.value("cut_top_3d", v.cut_area_top_3d);
    json.value("cut_base_3d", v.cut_area_base_3d);
    json.end();
    json.begin_object("extremes");
    json.value("max_fill", v.max_fill);
    json.value("max_fill_x", v.max_fill_at.x);
    json.value("max_fill_y", v.max_fill_at.y);
    json.value("max_cut", v.max_cut);
    json.value("max_cut_x", v.max_cut_at.x);
    json.value("max_cut_y", v.max_cut_at.y);
    json.end();
    json.begin_object("map");
    json.value("fill_regions", r.fill_regions);
    json.value("cut_regions", r.cut_regions);
    json.value("zero_lines", r.zero_lines);
    json.value("zero_line_length", r.zero_line_length);
    json.value("difference_cell", r.cell);
    json.end();
    json.value("pieces", v.pieces);
    json.value("method",
               "exact: overlay of the two TINs (exact predicates), the height difference "
               "integrated in closed form over every piece, split at the zero line");
    json.begin_array("notes");
    for (const std::string& n : r.notes) {
        json.value({}, n);
    }
    json.end();
    json.begin_array("files");
    for (const std::string& f : r.files) {
        json.value({}, f);
    }
    json.end();
    json.end();
    return json.str();
}

std::string volume_protocol(const VolumeReport& r) {
    const VolumeResult& v = r.volume;
    std::string out;
    char line[512];
    const auto add = [&](const char* format, auto... args) {
        std::snprintf(line, sizeof line, format, args...);
        out += line;
    };
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char when[32];
    std::strftime(when, sizeof when, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    add("VOLUME PROTOCOL                                   dtm %s, %s\n\n", DTM_VERSION, when);
    add("Top surface (compared):   %s (%zu triangles)\n", r.top.c_str(), r.top_triangles);
    if (v.base_is_plane) {
        add("Base (reference):         %s\n", r.base.c_str());
    } else {
        add("Base (reference):         %s (%zu triangles)\n", r.base.c_str(), r.base_triangles);
    }
    if (!r.within.empty()) {
        add("Within:                   %s\n", r.within.c_str());
    }
    add("Coordinate system:        %s\n",
        r.crs_wkt.empty() ? "none given" : io::crs_label(r.crs_wkt).c_str());
    add("Method: exact TIN volume - both surfaces overlaid, the height difference integrated\n"
        "in closed form over each of %zu pieces (no grid, no sampling).\n\n",
        v.pieces);
    add("%-30s %16s %16s %16s %16s\n", "", "volume [m3]", "area 2-D [m2]", "area top [m2]",
        "area base [m2]");
    add("%-30s %16.3f %16.3f %16.3f %16.3f\n", "Fill (top above base)", v.fill, v.fill_area,
        v.fill_area_top_3d, v.fill_area_base_3d);
    add("%-30s %16.3f %16.3f %16.3f %16.3f\n", "Cut (top below base)", v.cut, v.cut_area,
        v.cut_area_top_3d, v.cut_area_base_3d);
    add("%-30s %16.3f\n", "Net (fill - cut)", v.net());
    add("%-30s %16s %16.3f\n", "Unchanged (top = base)", "", v.unchanged_area);
    add("%-30s %16s %16.3f\n", "Compared area (both exist)", "", v.overlap_area);
    add("%-30s %16s %16.3f\n", "Top only (no base, not counted)", "", v.top_only_area);
    if (!v.base_is_plane) {
        add("%-30s %16s %16.3f\n", "Base only (no top, not counted)", "", v.base_only_area);
    }
    out += "\n";
    add("Largest fill height: %.3f m at E %.3f, N %.3f\n", v.max_fill, v.max_fill_at.x,
        v.max_fill_at.y);
    add("Largest cut depth:   %.3f m at E %.3f, N %.3f\n", v.max_cut, v.max_cut_at.x,
        v.max_cut_at.y);
    if (r.swell != 1.0) {
        add("Swell factor %.3f: cut as loose material %.3f m3; fill as bank material %.3f m3\n",
            r.swell, v.cut * r.swell, v.fill / r.swell);
    }
    for (const std::string& n : r.notes) {
        add("Note: %s\n", n.c_str());
    }
    out += "\nComputed by: ______________________   Checked by: ______________________\n";
    out += "Date: ____________   Signature: ______________________\n";
    return out;
}

}  // namespace dtm::products
