// SPDX-License-Identifier: MIT
// dtm map: read -> surface -> the map sheet (io::map::write_map).
#include "dtm/products/map.hpp"

#include <algorithm>

#include "dtm/products/surface.hpp"

namespace dtm::products {

io::map::MapReport map(const io::LoadOptions& inputs,
                       const std::filesystem::path& output,
                       MapJob job,
                       const Progress& progress) {
    io::LoadedInputs loaded = io::load_inputs(inputs, progress.sub(0.0, 0.2));
    if (job.map.crs_wkt.empty()) job.map.crs_wkt = loaded.crs_wkt;
    if (job.map.sources.empty()) {
        for (const io::InputSummary& in : loaded.summaries) {
            job.map.sources.push_back(in.path.filename().string());
        }
    }
    const Surface s = surface(loaded, job.triangulate, progress.sub(0.2, 0.5));
    return io::map::write_map(s.result.tin, job.map, output, progress.sub(0.5, 1.0));
}

double default_map_scale(const Box2& extent, double unit_m) {
    const double margin = 0.1 * std::max(extent.xmax - extent.xmin, extent.ymax - extent.ymin);
    const double s = io::map::largest_fitting_scale(extent.xmax - extent.xmin + 2.0 * margin,
                                                    extent.ymax - extent.ymin + 2.0 * margin,
                                                    unit_m, 297.0, 420.0);
    return s > 0.0 ? s : 100000.0;
}

}  // namespace dtm::products
