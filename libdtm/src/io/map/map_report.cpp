// SPDX-License-Identifier: MIT
// The map report as JSON: the layout (pages, their extents and sizes), the contour and spot
// height counts, every placed contour label with its page box (for independent overlap checks)
// and every wanted label position that found no room, with the reason.
#include "dtm/io/json_writer.hpp"
#include "dtm/io/map/map.hpp"

namespace dtm::io::map {
namespace {

void box(JsonWriter& json, std::string_view key, const Box2& b) {
    json.begin_array(key, JsonWriter::Layout::inline_);
    for (const double v : {b.xmin, b.ymin, b.xmax, b.ymax}) json.value({}, v);
    json.end();
}

}  // namespace

std::string map_report_json(const MapReport& r) {
    JsonWriter json;
    json.begin_object();
    json.value("output", r.output.generic_string());
    json.value("georeferenced", r.georeferenced);
    json.value("paper", r.layout.paper);
    json.value("index_page", r.index_page);
    json.value("sheet_rows", static_cast<std::size_t>(r.layout.rows));
    json.value("sheet_columns", static_cast<std::size_t>(r.layout.cols));
    json.begin_array("pages");
    for (const PageFrame& p : r.layout.pages) {
        json.begin_object();
        json.value("name", p.name);
        json.value("scale", p.scale);
        json.value("width_mm", p.width_mm);
        json.value("height_mm", p.height_mm);
        box(json, "extent", p.extent);
        json.end();
    }
    json.end();
    json.begin_object("contours");
    json.value("interval", r.interval);
    json.value("index_every", r.index_every);
    json.value("lines", r.contour_lines);
    json.value("index_lines", r.index_lines);
    json.end();
    json.begin_object("labels");
    json.value("placed", r.labels.size());
    json.value("not_placed", r.label_failures.size());
    json.value("index_lines_too_short", r.lines_too_short);
    std::size_t crossing = 0;
    for (const LabelRecord& l : r.labels) crossing += l.crosses_lines ? 1 : 0;
    json.value("interrupting_other_contours", crossing);
    json.begin_array("placed_labels");
    for (const LabelRecord& l : r.labels) {
        json.begin_object();
        json.value("page", l.page);
        json.value("text", l.text);
        json.value("level", l.level);
        json.value("x", l.centre.x);
        json.value("y", l.centre.y);
        json.value("angle_deg", l.angle_deg);
        json.begin_array("page_box_mm", JsonWriter::Layout::inline_);
        for (const Point2& c : l.box) {
            json.begin_array({}, JsonWriter::Layout::inline_);
            json.value({}, c.x);
            json.value({}, c.y);
            json.end();
        }
        json.end();
        json.end();
    }
    json.end();
    json.begin_array("failures");
    for (const FailureRecord& f : r.label_failures) {
        json.begin_object();
        json.value("page", f.page);
        json.value("level", f.level);
        json.value("x", f.where.x);
        json.value("y", f.where.y);
        json.value("reason", to_string(f.reason));
        json.end();
    }
    json.end();
    json.end();
    json.begin_object("spot_heights");
    json.value("selected", r.spots_selected);
    json.value("drawn", r.spots_drawn);
    json.value("left_out_for_lack_of_room", r.spot_labels_failed);
    json.value("summits", r.summits);
    json.value("pits", r.pits);
    json.value("saddles", r.saddles);
    json.end();
    json.value("seconds", r.seconds);
    json.end();
    return json.str();
}

}  // namespace dtm::io::map
