// SPDX-License-Identifier: MIT
// `dtm voronoi` (dtm/products/voronoi.hpp): the distinct survey points, their Delaunay
// triangulation (the production kernel), the clip region (the boundary rings minus the holes,
// triangulated by the kernel, or the convex hull), the Thiessen polygons (algo/thiessen), one
// feature per point (io/voronoi_writer).
#include "dtm/products/voronoi.hpp"

#include <algorithm>
#include <string>

#include "algo/detail/exact_duplicates.hpp"
#include "dtm/algo/thiessen.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/voronoi_writer.hpp"

namespace dtm::products {
namespace {

/// The Delaunay triangulation of the distinct sites (vertex i = site i), or no triangles when
/// they are collinear or fewer than three.
Tin delaunay_of(const std::vector<Point3>& sites, unsigned threads, const Progress& progress) {
    if (sites.size() >= 3) {
        TriangulateOptions options;
        options.threads = threads;
        try {
            return triangulate(TerrainInput{sites, {}, {}, {}, {}, {}}, options, progress).tin;
        } catch (const InputError&) {
            // collinear: the Voronoi regions are parallel strips; no triangle
        }
    }
    Tin t;
    t.vertices = sites;
    return t;
}

}  // namespace

VoronoiCellsReport write_voronoi_cells(const io::LoadedInputs& inputs,
                                       const std::filesystem::path& output,
                                       const VoronoiCellsOptions& options,
                                       const Progress& progress) {
    io::VoronoiCellWriter::check_extension(output);  // fails before any work
    const TerrainInput& terrain = inputs.terrain;
    if (!terrain.breaklines.empty() || !terrain.soft_breaklines.empty()) {
        throw UsageError(
            "voronoi: breaklines make no Thiessen polygons (give points, and a boundary or holes)");
    }
    const std::vector<Point3>& points = inputs.tin ? inputs.tin->vertices : terrain.points;
    if (points.empty()) throw InputError("voronoi: the inputs hold no point");
    VoronoiCellsReport report;
    report.points = points.size();
    report.boundary = !terrain.boundaries.empty();
    // Distinct sites in input order; a duplicate's cell is its first point's.
    const auto first = dtm::detail::first_occurrences(points);
    std::vector<Point3> sites;
    std::vector<std::size_t> site_input;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (first[i] != i) continue;
        sites.push_back(points[i]);
        site_input.push_back(i);
    }
    report.duplicates = points.size() - sites.size();
    progress.report(0.0, "triangulating");
    const Tin delaunay = delaunay_of(sites, options.threads, progress.sub(0.0, 0.3));
    const Tin region = report.boundary ? clip_region_of_rings(terrain.boundaries, terrain.holes)
                                       : clip_region_of_hull(delaunay);
    const ThiessenResult cells = thiessen_cells(sites, delaunay, region, progress.sub(0.3, 0.85));
    report.region_area = cells.region_area;
    report.empty_cells = cells.empty_cells;

    const std::vector<std::string>& ids = inputs.labels.ids;
    const bool string_ids =
        std::any_of(ids.begin(), ids.end(), [](const std::string& s) { return !s.empty(); });
    io::VoronoiCellWriter writer(output, {inputs.crs_wkt, options.layer, string_ids});
    for (std::size_t s = 0; s < sites.size(); ++s) {
        if ((s & 0xffffu) == 0)
            progress.report(0.85 + 0.15 * double(s) / double(sites.size()), "writing");
        const ThiessenCell& cell = cells.cells[s];
        if (cell.polygons.empty()) continue;
        const std::size_t i = site_input[s];
        const std::string id = i < ids.size() && !ids[i].empty() ? ids[i] : std::to_string(i);
        writer.add(cell, id, i, sites[s].z);
        ++report.cells;
        report.cells_area += cell.area;
    }
    writer.commit();
    progress.report(1.0, "written");
    return report;
}

}  // namespace dtm::products
