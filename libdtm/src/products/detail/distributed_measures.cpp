// SPDX-License-Identifier: MIT
// The measures of a distributed TIN (distributed_measures.hpp). Nothing here is a floating-point
// reduction: minima and maxima are exact, the areas go through a long accumulator
// (algo/detail/long_sum.hpp) whose integer limbs add across ranks, so the rules that read them
// (default_cell, default_interval) decide as the serial build does.
#include "products/detail/distributed_measures.hpp"

#include <algorithm>
#include <cstring>
#include <limits>
#include <map>

#include "algo/detail/area_terms.hpp"
#include "algo/detail/long_sum.hpp"
#include "products/detail/distributed_pieces.hpp"

namespace dtm::products::detail {
namespace {

/// The first corner of the serial TIN's first triangle, from the rank that holds it.
Point3 serial_origin(dist::Comm& comm, const dist::SurfaceMesh& mine) {
    constexpr std::int64_t none = std::numeric_limits<std::int64_t>::max();
    std::int64_t first = none;
    for (const dist::SurfaceFace& f : mine.faces) {
        first = std::min(first, static_cast<std::int64_t>(f.face));
    }
    const std::int64_t global = comm.allreduce(first, dist::Reduce::min);
    std::vector<Point3> corner;
    if (first == global && first != none) {
        for (const dist::SurfaceFace& f : mine.faces) {
            if (static_cast<std::int64_t>(f.face) == first)
                corner.push_back(mine.vertices[f.v[0]].p);
        }
    }
    const auto all = dist::concatenated<Point3>(
        comm.allgatherv(dist::to_bytes(std::span<const Point3>(corner))));
    return all.empty() ? Point3{} : all.front();
}

/// The sum over all ranks of each rank's exact partial sum.
double global_sum(dist::Comm& comm, ::dtm::detail::LongSum& partial) {
    auto limbs = partial.limbs();
    comm.allreduce(std::span<std::int64_t>(limbs), dist::Reduce::sum);
    ::dtm::detail::LongSum total;
    total.from_limbs(limbs);
    return total.value();
}

}  // namespace

SurfaceStats distributed_surface_stats(dist::Comm& comm,
                                       const dist::SurfaceMesh& mine,
                                       std::uint64_t vertex_count,
                                       std::uint64_t triangle_count,
                                       std::uint64_t constraint_count) {
    SurfaceStats stats;
    stats.vertex_count = vertex_count;
    stats.triangle_count = triangle_count;
    stats.constraint_count = constraint_count;
    stats.extent = mesh_box(comm, mine);
    const auto [zmin, zmax] = height_range(comm, mine);
    const Point3 origin = serial_origin(comm, mine);
    ::dtm::detail::LongSum planimetric, surface;
    for (const dist::SurfaceFace& f : mine.faces) {
        const auto terms = ::dtm::detail::area_terms(
            origin, mine.vertices[f.v[0]].p, mine.vertices[f.v[1]].p, mine.vertices[f.v[2]].p);
        planimetric.add(terms.planimetric);
        surface.add(terms.surface);
    }
    stats.planimetric_area = global_sum(comm, planimetric);
    stats.surface_area = global_sum(comm, surface);
    if (triangle_count > 0) {  // as surface_stats: 0 without triangles
        stats.z_min = zmin;
        stats.z_max = zmax;
    }
    return stats;
}

std::uint64_t used_vertex_count(dist::Comm& comm, const dist::SurfaceMesh& mine) {
    // A vertex named on several ranks is counted once, by the rank its number hashes to.
    const auto ranks = static_cast<std::uint64_t>(comm.size());
    std::vector<dist::Bytes> out(ranks);
    for (const dist::SurfaceVertex& v : mine.vertices) dist::append_value(out[v.id % ranks], v.id);
    comm.set_phase("report");
    std::vector<std::uint64_t> ids;
    for (const dist::Bytes& bytes : comm.alltoallv(std::move(out))) {
        const auto got = dist::from_bytes<std::uint64_t>(bytes);
        ids.insert(ids.end(), got.begin(), got.end());
    }
    std::sort(ids.begin(), ids.end());
    const auto distinct = std::unique(ids.begin(), ids.end()) - ids.begin();
    return static_cast<std::uint64_t>(comm.allreduce(distinct, dist::Reduce::sum));
}

std::vector<std::pair<std::string, std::uint64_t>> phase_bytes(dist::Comm& comm) {
    dist::Bytes mine;  // "name\0" and 8 bytes, per phase
    for (const auto& [phase, traffic] : comm.traffic()) {
        for (const char c : phase) mine.push_back(static_cast<std::byte>(c));
        mine.push_back(std::byte{0});
        dist::append_value(mine, traffic.bytes);
    }
    std::map<std::string, std::uint64_t> sums;
    for (const dist::Bytes& bytes : comm.allgatherv(std::move(mine))) {
        std::size_t at = 0;
        while (at < bytes.size()) {
            std::string name;
            while (bytes[at] != std::byte{0}) name += static_cast<char>(bytes[at++]);
            std::uint64_t value = 0;
            std::memcpy(&value, bytes.data() + at + 1, sizeof value);
            at += 1 + sizeof value;
            sums[name] += value;
        }
    }
    return {sums.begin(), sums.end()};
}

}  // namespace dtm::products::detail
