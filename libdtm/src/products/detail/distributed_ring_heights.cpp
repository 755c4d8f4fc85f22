// SPDX-License-Identifier: MIT
//
// Ring heights from a first surface, distributed (distributed_ring_heights.hpp). Serially,
// boundary and hole vertices on no survey point take the height of the TIN of the points and
// hard breaklines (algo/line_heights.cpp, step 2): SurfaceSampler's value, which depends on the
// position only (a vertex's z; on an edge, interpolated from its lower-numbered end; inside, the
// barycentric formula over the triangle's corners in the TIN's order) and, off the TIN, on the
// nearest vertex (the lowest number of equally near ones). Here the first surface is the
// distributed TIN of the same input without the rings; each rank samples the Tin of its own
// triangles (vertices in ascending number, corners as in the serial TIN, so the same formulas
// give the same bits), and per ring vertex the ranks' answers are gathered: the first rank whose
// triangles hold it, else the nearest vertex over all ranks by (squared distance, number).
#include "products/detail/distributed_ring_heights.hpp"

#include <cmath>
#include <limits>
#include <vector>

#include "dist/mesh_vertices.hpp"
#include "dtm/algo/surface_sampler.hpp"
#include "dtm/core/error.hpp"
#include "products/detail/distributed_surface.hpp"

namespace dtm::products::detail {
namespace {

/// One rank's answer for one ring vertex.
struct Sample {
    double inside_z = 0.0;
    std::uint64_t inside = 0;  ///< 1 when this rank's triangles hold the position
    double nearest_d2 = std::numeric_limits<double>::infinity();
    std::uint64_t nearest_id = ~std::uint64_t{0};
    double nearest_z = 0.0;
};

Tin tin_of(const dist::SurfaceMesh& mesh) {
    Tin tin;
    tin.vertices.reserve(mesh.vertices.size());
    for (const dist::SurfaceVertex& v : mesh.vertices) tin.vertices.push_back(v.p);
    tin.triangles.reserve(mesh.faces.size());
    for (const dist::SurfaceFace& f : mesh.faces) {
        Triangle t;
        t.v = {f.v[0], f.v[1], f.v[2]};
        tin.triangles.push_back(t);
    }
    link_neighbours(tin);
    return tin;
}

}  // namespace

bool rings_lack_heights(const TerrainInput& lines) {
    for (const auto* rings : {&lines.boundaries, &lines.holes}) {
        for (const Polyline& l : *rings) {
            for (const Point3& p : l.points) {
                if (std::isnan(p.z)) return true;
            }
        }
    }
    return false;
}

void ring_heights_from_surface(dist::Comm& comm,
                               const DistributedSource& source,
                               std::uint64_t points,
                               TerrainInput& lines,
                               const Progress& progress) {
    if (points < 3) {
        throw InputError(
            "boundary/hole vertices have no heights and there are fewer than 3 "
            "survey points to take them from");
    }
    DistributedSource first;  // the serial step's TriangulateOptions: all defaults
    first.input = source.input;
    first.read = source.read;
    first.default_crs = source.default_crs;
    for (const io::InputFile& f : source.lines) {
        if (f.role == io::InputRole::breaklines) first.lines.push_back(f);
    }
    DistributedSurface surface = distributed_surface(comm, first, progress);
    comm.set_phase("ring heights");
    const dist::SurfaceMesh mine =
        dist::surface_mesh(comm, surface.merged, std::move(surface.kernel));
    surface = {};
    const Tin tin = tin_of(mine);
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    std::vector<Point3*> wanted;
    for (auto* rings : {&lines.boundaries, &lines.holes}) {
        for (Polyline& l : *rings) {
            for (Point3& p : l.points) {
                if (std::isnan(p.z)) wanted.push_back(&p);
            }
        }
    }
    std::vector<Sample> here(wanted.size());
    for (std::size_t i = 0; i < wanted.size(); ++i) {
        const Point2 q = wanted[i]->xy();
        const double z = sampler.height(q, cursor);
        if (!std::isnan(z)) here[i].inside_z = z, here[i].inside = 1;
        const VertexIndex v = sampler.nearest_vertex(q);
        if (v == no_vertex) continue;
        const double dx = tin.vertices[v].x - q.x, dy = tin.vertices[v].y - q.y;
        here[i].nearest_d2 = dx * dx + dy * dy;
        here[i].nearest_id = mine.vertices[v].id;
        here[i].nearest_z = tin.vertices[v].z;
    }
    const std::vector<dist::Bytes> all =
        comm.allgatherv(dist::to_bytes(std::span<const Sample>(here)));
    std::vector<Sample> best(wanted.size());
    for (const dist::Bytes& bytes : all) {
        const std::vector<Sample> theirs = dist::from_bytes<Sample>(bytes);
        for (std::size_t i = 0; i < theirs.size() && i < best.size(); ++i) {
            const Sample& s = theirs[i];
            Sample& b = best[i];
            if (s.inside != 0 && b.inside == 0) b.inside_z = s.inside_z, b.inside = 1;
            if (s.nearest_d2 < b.nearest_d2 ||
                (s.nearest_d2 == b.nearest_d2 && s.nearest_id < b.nearest_id)) {
                b.nearest_d2 = s.nearest_d2;
                b.nearest_id = s.nearest_id;
                b.nearest_z = s.nearest_z;
            }
        }
    }
    for (std::size_t i = 0; i < wanted.size(); ++i) {
        wanted[i]->z = best[i].inside != 0 ? best[i].inside_z : best[i].nearest_z;
    }
}

}  // namespace dtm::products::detail
