// SPDX-License-Identifier: MIT
// Reading the analyses' inputs through io::load_inputs: surfaces (a dtm TIN as it is, anything
// else triangulated), lines, areas and control points, all brought into one CRS.
#include "dtm/products/surface_input.hpp"

#include <tbb/parallel_for.h>

#include <cmath>
#include <exception>
#include <utility>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/crs.hpp"
#include "dtm/products/surface.hpp"

namespace dtm::products {
namespace {

/// Loads @p options; when @p crs_wkt is set and the files carry a different CRS, loads them
/// again reprojected into it. @p transformed receives the files' own CRS label then.
io::LoadedInputs load_in(io::LoadOptions options,
                         const std::string& crs_wkt,
                         std::string& transformed,
                         const Progress& progress) {
    io::LoadedInputs in = io::load_inputs(options, progress);
    if (!crs_wkt.empty() && !in.crs_wkt.empty() && !io::crs_equivalent(in.crs_wkt, crs_wkt)) {
        transformed = io::crs_label(in.crs_wkt);
        options.crs.target_crs = crs_wkt;
        in = io::load_inputs(options, progress);
        in.crs_wkt = crs_wkt;
    } else if (in.crs_wkt.empty()) {
        in.crs_wkt = crs_wkt;
    }
    return in;
}

io::LoadOptions with_file(const io::LoadOptions& reader,
                          const std::filesystem::path& path,
                          io::InputRole role) {
    io::LoadOptions options = reader;
    options.files = {{path, role}};
    return options;
}

bool closed(const Polyline& p) {
    return p.closed || (p.points.size() >= 4 && p.points.front().x == p.points.back().x &&
                        p.points.front().y == p.points.back().y);
}

}  // namespace

std::string LoadedSurface::description() const {
    std::string out;
    for (const io::InputSummary& s : inputs) {
        if (!out.empty()) {
            out += " + ";
        }
        out += s.path.generic_string();
    }
    return out;
}

LoadedSurface load_surface(const SurfaceSource& source,
                           const std::string& crs_wkt,
                           const Progress& progress) {
    LoadedSurface s;
    s.name = source.name;
    io::LoadedInputs in = load_in(source.load, crs_wkt, s.transformed_from, progress.sub(0.0, 0.3));
    s.crs_wkt = in.crs_wkt;
    Surface built = surface(in, source.triangulation, progress.sub(0.3, 1.0));
    s.inputs = std::move(in.summaries);
    s.tin = std::move(built.result.tin);
    s.from_tin = built.from_tin;
    if (s.tin.triangles.empty()) {
        throw InputError(source.load.files.front().path, 0, 0,
                         "the " + source.name + " surface has no triangle");
    }
    progress.report(1.0, "reading the " + source.name + " surface");
    return s;
}

std::vector<LoadedSurface> load_surfaces(const std::vector<SurfaceSource>& sources,
                                         std::vector<std::string>& notes,
                                         const Progress& progress) {
    const std::size_t n = sources.size();
    const auto part = [&](std::size_t i) {
        return progress.sub(static_cast<double>(i) / static_cast<double>(n),
                            static_cast<double>(i + 1) / static_cast<double>(n));
    };
    std::vector<LoadedSurface> out(n);
    std::vector<std::exception_ptr> errors(n);
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
        try {
            out[i] = load_surface(sources[i], {}, part(i));
        } catch (...) {
            errors[i] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : errors) {
        if (e) {
            std::rethrow_exception(e);
        }
    }
    for (std::size_t i = 1; i < n; ++i) {
        const std::string& crs = out.front().crs_wkt;
        if (out[i].crs_wkt.empty()) {
            out[i].crs_wkt = crs;
        } else if (!crs.empty() && !io::crs_equivalent(out[i].crs_wkt, crs)) {
            out[i] = load_surface(sources[i], crs, part(i));
            notes.push_back(out[i].name + " reprojected from " + out[i].transformed_from +
                            " into " + io::crs_label(crs));
        }
    }
    return out;
}

std::vector<Polyline> load_lines(const std::filesystem::path& path,
                                 const io::LoadOptions& reader,
                                 const std::string& crs_wkt) {
    std::string transformed;
    io::LoadedInputs in =
        load_in(with_file(reader, path, io::InputRole::breaklines), crs_wkt, transformed, {});
    std::vector<Polyline> lines = std::move(in.terrain.breaklines);
    for (Polyline& l : lines) {
        if (l.source.empty()) {
            l.source = path.generic_string();
        }
    }
    if (lines.empty()) {
        throw InputError(path, 0, 0, "expected lines (LineString features), found none");
    }
    return lines;
}

TerrainInput load_area(const std::filesystem::path& path,
                       const io::LoadOptions& reader,
                       const std::string& crs_wkt) {
    std::string transformed;
    io::LoadOptions options = with_file(reader, path, io::InputRole::boundary);
    io::LoadedInputs in = load_in(options, crs_wkt, transformed, {});
    TerrainInput area;
    for (std::vector<Polyline>* rings : {&in.terrain.boundaries, &in.terrain.holes}) {
        for (Polyline& ring : *rings) {
            if (!closed(ring)) {
                throw InputError(path, 0, 0,
                                 (ring.source.empty() ? std::string("a ring") : ring.source) +
                                     ": the polygon does not close (its last vertex is not its "
                                     "first)");
            }
            if (ring.closed && !(ring.points.front() == ring.points.back())) {
                ring.points.push_back(ring.points.front());
            }
            for (Point3& p : ring.points) {
                if (std::isnan(p.z)) {
                    p.z = 0.0;
                }
            }
        }
    }
    area.boundaries = std::move(in.terrain.boundaries);
    area.holes = std::move(in.terrain.holes);
    if (area.boundaries.empty()) {
        throw InputError(path, 0, 0, "expected a polygon (or a closed line), found none");
    }
    return area;
}

ControlPoints load_points(const std::filesystem::path& path,
                          const io::LoadOptions& reader,
                          const std::string& crs_wkt) {
    std::string transformed;
    io::LoadOptions options = with_file(reader, path, io::InputRole::points);
    io::LoadedInputs in = load_in(options, crs_wkt, transformed, {});
    ControlPoints out;
    out.points = std::move(in.terrain.points);
    out.ids = std::move(in.labels.ids);
    out.ids.resize(out.points.size());
    for (std::size_t i = 0; i < out.ids.size(); ++i) {
        if (out.ids[i].empty()) {
            out.ids[i] = std::to_string(i + 1);
        }
    }
    out.crs_wkt = in.crs_wkt;
    if (out.points.empty()) {
        throw InputError(path, 0, 0, "expected control points, found none");
    }
    return out;
}

}  // namespace dtm::products
