// SPDX-License-Identifier: MIT
// Loading every input of a subcommand into one TerrainInput in one planar CRS:
//   1. each file goes to its reader (the table in reader.cpp); the first TIN a reader returns
//      (a dtm .ply) is the surface, used as it is;
//   2. its CRS is the one the file carries, else CrsOptions::default_crs; S-JTSK positive (Y, X)
//   become
//      Krovak East-North; the summary is taken here, in the input's own CRS;
//   3. the output CRS is CrsOptions::target_crs, else the first input's CRS; a geographic output
//   CRS is
//      replaced by the UTM zone of the data (GeographicLib); every input is transformed into it;
// Line vertices without a height keep NaN z: triangulate() gives them one
// (algo/line_heights.hpp), and `dtm info` shows the lines as they are.
#include "dtm/io/inputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "dtm/algo/duplicates.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/io/reader.hpp"
#include "io/detail/file_crs.hpp"

namespace dtm::io {
namespace {

struct Loaded {
    ReadResult result;
    std::string crs_wkt;  ///< after CrsOptions::default_crs
};

/// The WKT of a CRS option; a definition GDAL does not know is an OptionError naming @p field.
std::string option_crs(const std::string& definition, const char* field) {
    try {
        return crs_to_wkt(definition);
    } catch (const UsageError& e) {
        throw OptionError(field, "`" + std::string(field) + "`: " + e.what());
    }
}

void summarize(InputSummary& s, const TerrainInput& t) {
    s.points = t.points.size();
    s.breaklines = t.breaklines.size() + t.soft_breaklines.size();
    s.breakline_vertices = 0;
    for (const auto* lines : {&t.breaklines, &t.soft_breaklines}) {
        for (const Polyline& l : *lines) s.breakline_vertices += l.points.size();
    }
    s.boundaries = t.boundaries.size();
    s.holes = t.holes.size() + t.hole_seeds.size();
    Box2 box;
    double zmin = std::numeric_limits<double>::infinity();
    double zmax = -zmin;
    const auto add = [&](const Point3& p) {
        box.add(p);
        if (std::isfinite(p.z)) {
            zmin = std::min(zmin, p.z);
            zmax = std::max(zmax, p.z);
        }
    };
    for (const Point3& p : t.points) add(p);
    for (const auto* lines : {&t.breaklines, &t.soft_breaklines, &t.boundaries, &t.holes}) {
        for (const Polyline& l : *lines) std::for_each(l.points.begin(), l.points.end(), add);
    }
    for (const Point2& p : t.hole_seeds) box.add(p);
    if (!box.empty()) s.bbox = {box.xmin, box.ymin, box.xmax, box.ymax};
    const double nan = std::numeric_limits<double>::quiet_NaN();
    s.z_range = zmin <= zmax ? std::array<double, 2>{zmin, zmax} : std::array<double, 2>{nan, nan};
    s.duplicates = count_repeated_positions(t.points);
}

Loaded read_one(const InputFile& file,
                const LoadOptions& options,
                const Progress& progress,
                std::optional<Tin>& tin) {
    Loaded loaded;
    loaded.result = find_reader(file.path).read(file, options.read, progress);
    if (loaded.result.tin) {
        if (tin) {
            loaded.result.summary.warnings.push_back(
                "only the first TIN input is used as a TIN; this one adds its vertices as points");
        } else {
            tin = std::move(loaded.result.tin);
        }
        loaded.result.tin.reset();
    }
    detail::identify_file_crs(file, loaded.result);
    loaded.crs_wkt = loaded.result.crs_wkt;
    if (loaded.crs_wkt.empty() && !options.crs.default_crs.empty()) {
        loaded.crs_wkt = option_crs(options.crs.default_crs, "default_crs");
    }
    InputSummary& s = loaded.result.summary;
    s.path = file.path;
    s.crs = crs_label(loaded.crs_wkt);
    if (crs_is_sjtsk(loaded.crs_wkt)) {
        const std::size_t n = sjtsk_to_east_north(loaded.result.terrain);
        if (n > 0) {
            s.warnings.push_back(std::to_string(n) +
                                 " positive S-JTSK (Y, X) coordinates converted to Krovak "
                                 "East-North (E = -Y, N = -X)");
        }
    }
    summarize(s, loaded.result.terrain);
    return loaded;
}

/// Output CRS (step 3) and the UTM zone when geographic inputs are projected by GeographicLib.
struct Target {
    std::string wkt;
    std::optional<UtmZone> utm;
};

Target choose_target(const LoadOptions& options, const std::vector<Loaded>& loaded) {
    Target target;
    if (!options.crs.target_crs.empty()) {
        target.wkt = target_crs_wkt(options.crs.target_crs);
        return target;
    }
    if (options.utm_zone) {  // chosen from the data by the caller (a distributed run's points)
        target.utm = options.utm_zone;
        target.wkt = crs_to_wkt("EPSG:" + std::to_string(options.utm_zone->epsg()));
        return target;
    }
    for (const Loaded& l : loaded) {
        if (l.crs_wkt.empty()) continue;
        if (!crs_is_geographic(l.crs_wkt)) {
            target.wkt = l.crs_wkt;
            return target;
        }
        const auto& b = l.result.summary.bbox;
        UtmZone zone = utm_zone_for((b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0);
        target.utm = zone;
        target.wkt = crs_to_wkt("EPSG:" + std::to_string(zone.epsg()));
        return target;
    }
    return target;
}

void to_target(Loaded& l, const Target& target) {
    const std::string name = l.result.summary.path.string();
    if (l.crs_wkt.empty() || target.wkt.empty()) {
        if (!target.wkt.empty()) {
            l.result.summary.warnings.push_back(
                "no CRS in the file and no `default_crs`: taken to be in the output CRS");
        }
        return;
    }
    if (crs_equivalent(l.crs_wkt, target.wkt)) return;
    if (target.utm && crs_is_geographic(l.crs_wkt)) {
        if (!crs_is_wgs84_like(l.crs_wkt)) {
            transform_terrain(l.result.terrain, l.crs_wkt, crs_to_wkt("EPSG:4326"), name);
        }
        project_to_utm(l.result.terrain, *target.utm, name);
        return;
    }
    transform_terrain(l.result.terrain, l.crs_wkt, target.wkt, name);
}

/// Moves @p from to the end of @p to; the first input's array is taken over, not copied (a
/// copy of the points would be the peak of reading).
template <class T>
void append(std::vector<T>& to, std::vector<T>& from) {
    if (to.empty()) {
        std::swap(to, from);
        return;
    }
    to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

void merge(LoadedInputs& out, Loaded& l) {
    TerrainInput& t = l.result.terrain;
    const std::size_t before = out.terrain.points.size();
    const bool labelled = !l.result.labels.ids.empty() || !out.labels.ids.empty();
    if (labelled) {
        out.labels.ids.resize(before);
        out.labels.codes.resize(before);
        append(out.labels.ids, l.result.labels.ids);
        append(out.labels.codes, l.result.labels.codes);
        out.labels.ids.resize(before + t.points.size());
        out.labels.codes.resize(before + t.points.size());
    }
    if (l.result.raster_cells) {
        out.dem_cells.push_back({before, before + t.points.size(), out.summaries.size()});
    }
    append(out.terrain.points, t.points);
    append(out.terrain.breaklines, t.breaklines);
    append(out.terrain.soft_breaklines, t.soft_breaklines);
    append(out.terrain.boundaries, t.boundaries);
    append(out.terrain.holes, t.holes);
    append(out.terrain.hole_seeds, t.hole_seeds);
    out.skipped_lines += l.result.summary.skipped_lines;
    out.summaries.push_back(std::move(l.result.summary));
}

}  // namespace

LoadedInputs load_inputs(const LoadOptions& options, const Progress& progress) {
    if (options.files.empty()) throw UsageError("expected at least one input file");
    LoadedInputs out;
    std::vector<Loaded> loaded;
    const double n = static_cast<double>(options.files.size());
    std::size_t tin_input = options.files.size();
    for (std::size_t i = 0; i < options.files.size(); ++i) {
        const double at = static_cast<double>(i);
        const bool had_tin = out.tin.has_value();
        loaded.push_back(
            read_one(options.files[i], options, progress.sub(at / n, (at + 1) / n), out.tin));
        if (!had_tin && out.tin) tin_input = i;
    }
    const Target target = choose_target(options, loaded);
    for (std::size_t i = 0; i < loaded.size(); ++i) {
        to_target(loaded[i], target);
        if (i == tin_input) out.tin->vertices = loaded[i].result.terrain.points;
        merge(out, loaded[i]);
    }
    out.crs_wkt = target.wkt;
    return out;
}

}  // namespace dtm::io
