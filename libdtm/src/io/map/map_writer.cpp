// SPDX-License-Identifier: MIT
// The map product: contours and spot heights from the TIN, the sheet layout, each page placed
// and drawn on a cairo Canvas, then the PDF georeferenced by GDAL, all into a temporary file
// renamed onto the target at the end (AtomicOutput). Without an extent or paper the sheet is the
// surface with a margin, grown at the bottom when the furniture would otherwise cover it.
#include <ogr_spatialref.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <memory>

#include "dtm/algo/contour.hpp"
#include "dtm/algo/rasterize.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/extension.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/map/map.hpp"
#include "dtm/io/map/pdf_georef.hpp"
#include "io/map/map_detail.hpp"

namespace dtm::io::map {
namespace {

using detail::MapData;

double nice_floor(double value) {
    const double power = std::pow(10.0, std::floor(std::log10(value)));
    const double mantissa = value / power;
    for (const double step : {5.0, 2.5, 2.0}) {
        if (mantissa >= step) return step * power;
    }
    return power;
}

std::string today() {
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::tm tm{};
    gmtime_r(&now, &tm);
    char buf[16];
    std::strftime(buf, sizeof buf, "%Y-%m-%d", &tm);
    return buf;
}

/// Metres per CRS unit, the CRS's display name, and the direction of true north at @p centre.
void describe_crs(MapData& data, Point2 centre, double& unit_m) {
    unit_m = 1.0;
    const std::string& wkt = data.options.crs_wkt;
    if (wkt.empty()) return;
    OGRSpatialReference srs;
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (srs.SetFromUserInput(wkt.c_str()) != OGRERR_NONE) {
        throw UsageError("map: the CRS is not understood");
    }
    if (srs.IsGeographic()) {
        throw UsageError(
            "map: the surface is in geographic coordinates (degrees); a map at scale needs a "
            "projected CRS (give `target_crs`, e.g. EPSG:5514 or a UTM zone)");
    }
    if (srs.IsProjected() || srs.IsLocal()) unit_m = srs.GetLinearUnits();
    if (!(unit_m > 0.0)) unit_m = 1.0;
    data.unit = unit_m == 1.0 ? " m" : " units";
    data.sjtsk = crs_is_sjtsk(wkt);
    const char* name = srs.GetName();
    const std::string label = crs_label(wkt);
    data.crs_name = name != nullptr ? name : label;
    if (!label.empty() && label != data.crs_name) data.crs_name += " (" + label + ")";
    if (!srs.IsProjected()) return;
    std::unique_ptr<OGRSpatialReference> geo(srs.CloneGeogCS());
    if (!geo) return;
    geo->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    std::unique_ptr<OGRCoordinateTransformation> to_geo(
        OGRCreateCoordinateTransformation(&srs, geo.get()));
    std::unique_ptr<OGRCoordinateTransformation> to_proj(
        OGRCreateCoordinateTransformation(geo.get(), &srs));
    if (!to_geo || !to_proj) return;
    double x = centre.x, y = centre.y;
    if (!to_geo->Transform(1, &x, &y)) return;
    double nx = x, ny = y + 0.01;  // 0.01 degree north
    if (!to_proj->Transform(1, &nx, &ny)) return;
    const double dx = nx - centre.x;
    const double dy = ny - centre.y;
    if (std::hypot(dx, dy) == 0.0) return;
    data.north_deg = -std::atan2(dx, dy) * 180.0 / 3.14159265358979323846;
    data.north_known = true;
}

int spot_decimals(const MapOptions& o) {
    if (o.spot_decimals >= 0) return std::min(o.spot_decimals, 6);
    if (o.scale <= 1000.0) return 2;
    if (o.scale <= 5000.0) return 1;
    return 0;
}

/// The surface with a margin, grown to the right or at the bottom when the furniture would
/// otherwise cover the surface: the smallest page whose furniture lies off the surface.
Box2 automatic_extent(const MapData& data, const LayoutRequest& base) {
    const double mm = base.scale / (1000.0 * base.unit_m);  // ground units per page mm
    const double margin = 12.0 * mm;
    const Box2 e{data.surface.xmin - margin, data.surface.ymin - margin, data.surface.xmax + margin,
                 data.surface.ymax + margin};
    LayoutRequest r = base;
    r.extent = e;
    const PageFrame page = layout_map(r).pages.front();  // throws when the site fits no paper
    const draw::TitleBlock block = detail::title_block(data, page, {});
    const detail::FurnitureSize z = detail::furniture_size(data, page, block);
    const double inset = data.style.furniture_inset_mm;
    std::vector<Box2> candidates{e};
    const auto grown = [&](double right_mm, double bottom_mm) {
        Box2 g = e;
        g.xmax += right_mm * mm;
        g.ymin -= bottom_mm * mm;
        candidates.push_back(g);
    };
    // the furniture goes beside or below the surface with a clear gap (its own margin and the
    // spot heights and grid labels at the surface edge stay visible)
    const double clear = inset + 6.0 - margin / mm;
    grown(z.column_w + clear, 0.0);
    grown(0.0, z.row_h + clear);
    grown(z.row_w + clear, 0.0);
    grown(0.0, z.column_h + clear);
    std::stable_sort(candidates.begin() + 1, candidates.end(), [](const Box2& a, const Box2& b) {
        return (a.xmax - a.xmin) * (a.ymax - a.ymin) < (b.xmax - b.xmin) * (b.ymax - b.ymin);
    });
    for (const Box2& c : candidates) {
        r.extent = c;
        MapLayout layout;
        try {
            layout = layout_map(r);
            const PageFrame& p = layout.pages.front();
            const detail::Furniture f = detail::plan_furniture(
                data, p, detail::title_block(data, p, {}), detail::surface_coverage(data, p));
            if (f.cover < 0.02) return c;
        } catch (const UsageError&) {
            // larger than A0 or too small for the furniture: try the next
        }
    }
    return candidates.back();
}

MapData prepare(const Tin& tin,
                const MapOptions& options,
                double& unit_m,
                const Progress& progress) {
    MapData data;
    data.tin = &tin;
    data.options = options;
    data.date = options.date.empty() ? today() : options.date;
    data.surface = tin_bounds(tin);
    if (tin.triangles.empty() || data.surface.empty()) {
        throw InputError("map: the surface has no triangle to draw");
    }
    describe_crs(data,
                 {(data.surface.xmin + data.surface.xmax) / 2.0,
                  (data.surface.ymin + data.surface.ymax) / 2.0},
                 unit_m);
    double zmin = tin.vertices[tin.triangles[0].v[0]].z;
    double zmax = zmin;
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) {
            zmin = std::min(zmin, tin.vertices[v].z);
            zmax = std::max(zmax, tin.vertices[v].z);
        }
    }
    data.interval = options.interval > 0.0 ? options.interval
                                           : (zmax > zmin ? nice_floor((zmax - zmin) / 20.0) : 1.0);
    data.index_every = options.index_every;
    ContourOptions co;
    co.interval = data.interval;
    co.base = options.base;
    co.index_every = options.index_every;
    data.contours = contour(tin, co, progress);
    data.constraints = constraint_lines(tin);
    data.mask = detail::surface_mask(tin, data.surface);
    data.spot_decimals = spot_decimals(options);
    return data;
}

void select_spots(MapData& data, const MapLayout& layout, const Progress& progress) {
    const MapOptions& o = data.options;
    if (o.spots == SpotMode::none) return;
    SpotHeightOptions so;
    so.all = o.spots == SpotMode::all;
    so.spacing = o.spot_spacing_mm * layout.pages.front().units_per_mm();
    so.max_count = o.spots == SpotMode::count ? std::max<std::size_t>(o.spot_count, 1) : 0;
    so.extent = layout.covered;
    data.spots = select_spot_heights(*data.tin, so, progress).spots;
}

void add_page(MapReport& report, const detail::PageResult& r) {
    report.furniture.push_back(r.furniture);
    report.labels.insert(report.labels.end(), r.labels.begin(), r.labels.end());
    report.label_failures.insert(report.label_failures.end(), r.failures.begin(), r.failures.end());
    report.lines_too_short += r.lines_too_short;
    report.spots_drawn += r.spots_drawn;
    report.spot_labels_failed += r.spot_labels_failed;
}

/// The index page: the covered area fitted into the paper with room for the furniture.
PageFrame index_frame(const MapLayout& layout, double unit_m) {
    const PageFrame& sheet = layout.pages.front();
    const double w = layout.covered.xmax - layout.covered.xmin;
    const double h = layout.covered.ymax - layout.covered.ymin;
    // fit into 55 % of the page so that the furniture has a free corner
    const double s = std::max(w * 1000.0 * unit_m / (sheet.width_mm * 0.55),
                              h * 1000.0 * unit_m / (sheet.height_mm * 0.55));
    PageFrame p = sheet;
    const double power = std::pow(10.0, std::floor(std::log10(s)));
    p.scale = 10.0 * power;
    for (const double m : {1.0, 2.0, 2.5, 5.0}) {  // the next round scale
        if (m * power >= s * (1.0 - 1e-12)) {
            p.scale = m * power;
            break;
        }
    }
    p.name = "index";
    const double gw = sheet.width_mm * p.units_per_mm();
    const double gh = sheet.height_mm * p.units_per_mm();
    const double cx = layout.covered.xmin + w / 2.0 + gw * 0.12;  // room to the lower right
    const double cy = layout.covered.ymin + h / 2.0 - gh * 0.12;
    p.extent = {cx - gw * 0.62, cy - gh * 0.38, cx + gw * 0.38, cy + gh * 0.62};
    return p;
}

}  // namespace

MapReport write_map(const Tin& tin,
                    const MapOptions& options,
                    const std::filesystem::path& output,
                    const Progress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const std::string ext = lower_extension(output);
    if (ext != "pdf" && ext != "svg" && ext != "png") {
        throw UsageError("map: cannot write '" + output.string() +
                         "': the extension must be .pdf, .svg or .png");
    }
    double unit_m = 1.0;
    MapData data = prepare(tin, options, unit_m, progress.sub(0.0, 0.15));
    LayoutRequest request;
    request.data = data.surface;
    request.extent = options.extent;
    request.paper = options.paper;
    request.orientation = options.orientation;
    request.scale = options.scale;
    request.unit_m = unit_m;
    request.sheets = options.sheets;
    if (!request.extent && !request.paper && !request.sheets) {
        request.extent = automatic_extent(data, request);
    }
    MapReport report;
    report.output = output;
    report.layout = layout_map(request);
    if (ext != "pdf" && report.layout.pages.size() > 1) {
        throw UsageError("map: " + std::to_string(report.layout.pages.size()) +
                         " sheets need a PDF (SVG and PNG hold one page)");
    }
    select_spots(data, report.layout, progress.sub(0.15, 0.25));
    report.interval = data.interval;
    report.index_every = data.index_every;
    report.contour_lines = data.contours.size();
    for (const Contour& c : data.contours) report.index_lines += c.level.index ? 1 : 0;
    report.spots_selected = data.spots.size();
    report.sjtsk = data.sjtsk;
    for (const SpotHeight& s : data.spots) {
        report.summits += s.kind == SpotKind::summit;
        report.pits += s.kind == SpotKind::pit;
        report.saddles += s.kind == SpotKind::saddle;
    }

    const std::vector<PageFrame>& sheets = report.layout.pages;
    std::vector<PageFrame> frames;  // in page order, for the georeferencing
    report.index_page = sheets.size() > 1;
    AtomicOutput out(output);
    {
        draw::Canvas canvas(out.temp_path(), sheets.front().width_mm, sheets.front().height_mm,
                            options.png_dpi);
        if (report.index_page) {
            frames.push_back(index_frame(report.layout, unit_m));
            detail::draw_index_page(canvas, data, report.layout, frames.back());
            canvas.new_page();
        }
        for (std::size_t i = 0; i < sheets.size(); ++i) {
            const double a =
                0.25 + 0.7 * static_cast<double>(i) / static_cast<double>(sheets.size());
            const double b =
                0.25 + 0.7 * static_cast<double>(i + 1) / static_cast<double>(sheets.size());
            const std::string sheet_text =
                sheets.size() > 1 ? sheets[i].name + " of " + std::to_string(sheets.size()) : "";
            add_page(report,
                     detail::draw_page(canvas, data, sheets[i], sheet_text, progress.sub(a, b)));
            frames.push_back(sheets[i]);
            if (i + 1 < sheets.size()) canvas.new_page();
        }
        progress.report(0.95, "writing");
        canvas.finish();
    }
    if (ext == "pdf" && !options.crs_wkt.empty()) {
        georeference_pdf(out.temp_path(), frames, options.crs_wkt);
        report.georeferenced = true;
    }
    out.commit();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.report(1.0, "done");
    return report;
}

}  // namespace dtm::io::map
