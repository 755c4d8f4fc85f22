// SPDX-License-Identifier: MIT
// Rasters of the map page: where the surface is (to keep the furniture off it) and the hillshade
// underlay. Both sample the TIN with dtm's rasterizer on a grid aligned with the page. The
// hillshade is Horn's gradient (B. K. P. Horn, "Hill shading and the reflectance map", Proc.
// IEEE 69(1), 1981), the method and default sun (azimuth 315, altitude 45 degrees) of gdaldem;
// it is drawn as dark grey with an alpha growing as the slope turns away from the sun, so flat
// ground and lit slopes stay paper white under the contours.
#include <algorithm>
#include <cmath>
#include <memory>

#include "dtm/algo/rasterize.hpp"
#include "io/map/map_detail.hpp"

namespace dtm::io::map::detail {
namespace {

GridSpec page_grid(const PageFrame& page, int columns, int rows) {
    GridSpec spec;
    spec.xmin = page.extent.xmin;
    spec.ymax = page.extent.ymax;
    spec.cols = static_cast<std::size_t>(columns);
    spec.rows = static_cast<std::size_t>(rows);
    spec.cell = (page.extent.xmax - page.extent.xmin) / columns;
    return spec;
}

}  // namespace

std::shared_ptr<const Grid> surface_mask(const Tin& tin, const Box2& surface) {
    const double longest = std::max(surface.xmax - surface.xmin, surface.ymax - surface.ymin);
    const double cell = std::max(longest / 800.0, 1e-9);
    return std::make_shared<Grid>(rasterize(tin, snapped_grid_spec(surface, cell)));
}

CoverageFn surface_coverage(const MapData& data, const PageFrame& page) {
    std::shared_ptr<const Grid> mask = data.mask;
    return [mask, page](const draw::Rect& r) {
        const GridSpec& g = mask->spec;
        const Box2 b = page.ground_box(r);
        const double step = std::max(g.cell, std::min(b.xmax - b.xmin, b.ymax - b.ymin) / 64.0);
        std::size_t inside = 0;
        std::size_t total = 0;
        for (double y = b.ymin + step / 2.0; y < b.ymax; y += step) {
            for (double x = b.xmin + step / 2.0; x < b.xmax; x += step) {
                ++total;
                const double c = std::floor((x - g.xmin) / g.cell);
                const double rr = std::floor((g.ymax - y) / g.cell);
                if (c < 0 || rr < 0 || c >= static_cast<double>(g.cols) ||
                    rr >= static_cast<double>(g.rows)) {
                    continue;
                }
                if (!mask->is_nodata(static_cast<std::size_t>(rr), static_cast<std::size_t>(c))) {
                    ++inside;
                }
            }
        }
        return total == 0 ? 0.0 : static_cast<double>(inside) / static_cast<double>(total);
    };
}

std::vector<std::uint8_t> hillshade_rgba(
    const Tin& tin, const PageFrame& page, int columns, int rows, const Progress& progress) {
    const GridSpec spec = page_grid(page, columns, rows);
    const Grid g = rasterize(tin, spec, RasterizeOptions{}, progress);
    const auto w = static_cast<std::ptrdiff_t>(columns);
    const auto h = static_cast<std::ptrdiff_t>(rows);
    const double pi = 3.14159265358979323846;
    const double azimuth = 315.0 * pi / 180.0;
    const double altitude = 45.0 * pi / 180.0;
    const double lx = std::cos(altitude) * std::sin(azimuth);
    const double ly = std::cos(altitude) * std::cos(azimuth);
    const double lz = std::sin(altitude);
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(w * h) * 4, 0);
    const auto at = [&](std::ptrdiff_t r, std::ptrdiff_t c, double centre) {
        if (r < 0 || c < 0 || r >= h || c >= w) return centre;
        const auto ur = static_cast<std::size_t>(r);
        const auto uc = static_cast<std::size_t>(c);
        return g.is_nodata(ur, uc) ? centre : static_cast<double>(g.at(ur, uc));
    };
    for (std::ptrdiff_t r = 0; r < h; ++r) {
        for (std::ptrdiff_t c = 0; c < w; ++c) {
            if (g.is_nodata(static_cast<std::size_t>(r), static_cast<std::size_t>(c))) continue;
            const double z = g.at(static_cast<std::size_t>(r), static_cast<std::size_t>(c));
            const double a = at(r - 1, c - 1, z), b = at(r - 1, c, z), cc = at(r - 1, c + 1, z);
            const double d = at(r, c - 1, z), f = at(r, c + 1, z);
            const double gg = at(r + 1, c - 1, z), hh = at(r + 1, c, z), i = at(r + 1, c + 1, z);
            const double east = ((cc + 2 * f + i) - (a + 2 * d + gg)) / (8.0 * spec.cell);
            const double north = ((a + 2 * b + cc) - (gg + 2 * hh + i)) / (8.0 * spec.cell);
            const double norm = std::sqrt(east * east + north * north + 1.0);
            const double shade = std::max(0.0, (-east * lx - north * ly + lz) / norm);
            // flat ground and lit slopes stay paper white, slopes away from the sun darken
            const double alpha = std::clamp((lz - shade) * 1.1, 0.0, 0.55);
            std::uint8_t* px = &rgba[static_cast<std::size_t>(r * w + c) * 4];
            px[0] = px[1] = px[2] = 40;
            px[3] = static_cast<std::uint8_t>(std::lround(alpha * 255.0));
        }
    }
    return rgba;
}

}  // namespace dtm::io::map::detail
