// SPDX-License-Identifier: MIT
// Build step "map": map.pdf, the contour map sheet on A3 (io::map::write_map) at the given scale
// or default_map_scale(); its sheet is kept for the QGIS project's print layout.
#include <array>

#include "build_steps.hpp"
#include "dtm/io/map/map.hpp"
#include "dtm/products/map.hpp"

namespace dtm::products::detail {
namespace {

std::array<double, 4> box(const io::draw::Rect& r) { return {r.x, r.y, r.width, r.height}; }

io::QgisLayout print_layout(const io::map::MapReport& map) {
    const io::map::PageFrame& page = map.layout.pages.front();
    const io::map::PageFurniture& f = map.furniture.front();
    io::QgisLayout layout;
    layout.width_mm = page.width_mm;
    layout.height_mm = page.height_mm;
    layout.extent = page.extent;
    layout.scale = page.scale;
    layout.grid_interval = f.grid_step;
    layout.sjtsk = map.sjtsk;
    layout.title = f.block.title;
    layout.fields = f.block.fields;
    layout.title_box = box(f.title);
    layout.legend_box = box(f.legend);
    layout.scale_bar_box = box(f.scale_bar);
    layout.north_box = box(f.north);
    return layout;
}

}  // namespace

void write_map_sheet(BuildContext& context, const Progress& progress) {
    io::map::MapOptions options;
    options.scale = context.options.map_scale > 0.0 ? context.options.map_scale
                                                    : default_map_scale(context.surface.extent);
    options.paper = io::draw::paper_named("A3");
    options.interval = context.report.contour_interval;
    options.index_every = context.report.index_every;
    options.crs_wkt = context.crs_wkt;
    if (context.inputs != nullptr) {
        for (const io::InputSummary& in : *context.inputs) {
            options.sources.push_back(in.path.filename().string());
        }
    }
    const io::map::MapReport map =
        io::map::write_map(context.tin, options, context.out.add("map.pdf"), progress);
    context.report.map_scale = options.scale;
    context.report.map_labels = map.labels.size();
    context.report.map_label_failures = map.label_failures.size();
    context.report.map_spot_heights = map.spots_drawn;
    context.map_layout = print_layout(map);
}

}  // namespace dtm::products::detail
