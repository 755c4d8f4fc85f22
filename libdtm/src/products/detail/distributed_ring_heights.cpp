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
#include <span>
#include <vector>

#include "algo/detail/ghost_mesh.hpp"
#include "dist/constraints.hpp"
#include "dist/mesh_vertices.hpp"
#include "dtm/algo/surface_sampler.hpp"
#include "dtm/core/error.hpp"
#include "dtm/dist/partition.hpp"
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

}  // namespace

std::vector<double> heights_on_surface(dist::Comm& comm,
                                       const dist::SurfaceMesh& mine,
                                       std::span<const Point2> at) {
    Tin tin = dist::surface_tin(mine);
    link_neighbours(tin);  // the sampler walks them
    const SurfaceSampler sampler(tin);
    SurfaceSampler::Cursor cursor;
    std::vector<Sample> here(at.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
        const double z = sampler.height(at[i], cursor);
        if (!std::isnan(z)) here[i].inside_z = z, here[i].inside = 1;
        const VertexIndex v = sampler.nearest_vertex(at[i]);
        if (v == no_vertex) continue;
        const double dx = tin.vertices[v].x - at[i].x, dy = tin.vertices[v].y - at[i].y;
        here[i].nearest_d2 = dx * dx + dy * dy;
        here[i].nearest_id = mine.vertices[v].id;
        here[i].nearest_z = tin.vertices[v].z;
    }
    const std::vector<dist::Bytes> all =
        comm.allgatherv(dist::to_bytes(std::span<const Sample>(here)));
    std::vector<Sample> best(at.size());
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
    std::vector<double> z(at.size());
    for (std::size_t i = 0; i < at.size(); ++i) {
        z[i] = best[i].inside != 0 ? best[i].inside_z : best[i].nearest_z;
    }
    return z;
}

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
    std::vector<Point3*> wanted;
    std::vector<Point2> at;
    for (auto* rings : {&lines.boundaries, &lines.holes}) {
        for (Polyline& l : *rings) {
            for (Point3& p : l.points) {
                if (!std::isnan(p.z)) continue;
                wanted.push_back(&p);
                at.push_back(p.xy());
            }
        }
    }
    const std::vector<double> z = heights_on_surface(comm, mine, at);
    for (std::size_t i = 0; i < wanted.size(); ++i) wanted[i]->z = z[i];
}

void soft_heights_from_surface(dist::Comm& comm,
                               dist::MergedShare& merged,
                               const std::vector<dist::GlobalSegment>& segments,
                               const Progress& progress) {
    // The first surface: the vertices with heights and the segments that are not soft alone.
    std::vector<dist::Point> known;
    for (const dist::Vertex& v : merged.vertices) {
        if (v.z_known) known.push_back({v.p.x, v.p.y, v.id});
    }
    dist::Share share = dist::partition_points(comm, std::move(known), {}, progress.sub(0.0, 0.3));
    dist::DistributedMesh kernel =
        dist::triangulate_share(comm, std::move(share), {}, progress.sub(0.3, 0.8));
    std::vector<dist::GlobalSegment> hard;
    for (const dist::GlobalSegment& s : segments) {
        if (s.bits != ::dtm::detail::constraint_soft) hard.push_back(s);
    }
    if (!hard.empty()) dist::insert_constraints(comm, kernel, hard, progress.sub(0.8, 1.0));
    comm.set_phase("soft heights");
    const dist::SurfaceMesh mine = dist::surface_mesh(comm, merged, std::move(kernel));
    // The vertices without heights, all ranks' in ascending number (ranks hold ascending runs).
    struct Unknown {
        std::uint64_t id;
        Point2 at;
    };
    std::vector<Unknown> own;
    for (const dist::Vertex& v : merged.vertices) {
        if (!v.z_known) own.push_back({v.id, v.p.xy()});
    }
    const std::vector<Unknown> all =
        dist::concatenated<Unknown>(comm.allgatherv(dist::to_bytes(std::span<const Unknown>(own))));
    std::vector<Point2> at;
    for (const Unknown& u : all) at.push_back(u.at);
    const std::vector<double> z = heights_on_surface(comm, mine, at);
    for (std::size_t i = 0; i < all.size(); ++i) {
        if (dist::Vertex* v = merged.kept(all[i].id)) {
            v->p.z = z[i];
            v->z_known = true;
        }
    }
}

}  // namespace dtm::products::detail
