// SPDX-License-Identifier: MIT
// Checks of a TIN read from a file: one exact orientation test per face, and one pass over the
// edges for the constrained edges (a hash set of the few constraints, not of all edges).
#include "tin_checks.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_set>

#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm::io::detail {
namespace {

std::uint64_t key(VertexIndex a, VertexIndex b) {
    if (a > b) std::swap(a, b);
    return (std::uint64_t{a} << 32) | b;
}

}  // namespace

void check_tin_from_file(const Tin& tin) {
    const std::size_t nv = tin.vertices.size();
    const auto bad = [&](const Triangle& f) {
        return f.v[0] >= nv || f.v[1] >= nv || f.v[2] >= nv ||
               geom::orient2d(tin.vertex(f.v[0]), tin.vertex(f.v[1]), tin.vertex(f.v[2])) <= 0;
    };
    // The faces are tested in parallel; the first bad one (the smallest index) is reported.
    const std::size_t first_bad = tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 14), tin.triangles.size(),
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t found) {
            for (std::size_t t = r.begin(); t < r.end() && t < found; ++t) {
                if (bad(tin.triangles[t])) return t;
            }
            return found;
        },
        [](std::size_t a, std::size_t b) { return std::min(a, b); });
    for (std::size_t t = first_bad; t < tin.triangles.size(); ++t) {
        const Triangle& f = tin.triangles[t];
        if (f.v[0] >= nv || f.v[1] >= nv || f.v[2] >= nv) {
            throw InputError("face " + std::to_string(t) + " refers to a missing vertex");
        }
        if (geom::orient2d(tin.vertex(f.v[0]), tin.vertex(f.v[1]), tin.vertex(f.v[2])) <= 0) {
            throw InputError("face " + std::to_string(t) + " (vertices " + std::to_string(f.v[0]) +
                             ", " + std::to_string(f.v[1]) + ", " + std::to_string(f.v[2]) +
                             ") is clockwise or degenerate; expected counter-clockwise faces");
        }
    }
    if (tin.constraints.empty()) return;
    std::unordered_set<std::uint64_t> missing;
    for (const ConstrainedEdge& e : tin.constraints) {
        if (e.a >= nv || e.b >= nv || e.a == e.b) {
            throw InputError("constrained edge " + std::to_string(e.a) + "-" + std::to_string(e.b) +
                             " refers to a missing vertex or to one vertex twice");
        }
        missing.insert(key(e.a, e.b));
    }
    for (const Triangle& f : tin.triangles) {
        for (int i = 0; i < 3 && !missing.empty(); ++i)
            missing.erase(key(f.v[i], f.v[(i + 1) % 3]));
    }
    if (!missing.empty()) {
        const std::uint64_t k = *missing.begin();
        throw InputError("constrained edge " + std::to_string(k >> 32) + "-" +
                         std::to_string(k & 0xffffffffU) + " is not an edge of any face");
    }
}

ReadResult read_tin_input(const InputFile& file,
                          const Progress& progress,
                          const char* format,
                          LoadedTin (*load)(const std::filesystem::path&)) {
    if (file.role != InputRole::points) {
        throw InputError(file.path, 0, 0,
                         std::string("a ") + format +
                             " is a survey input (the surface itself), not a line or ring input");
    }
    progress.report(0.0, std::string("reading the ") + format);
    LoadedTin loaded = load(file.path);
    ReadResult result;
    result.terrain.points = loaded.tin.vertices;
    result.crs_wkt = std::move(loaded.crs_wkt);
    result.summary.path = file.path;
    result.summary.format = format;
    result.summary.triangles = loaded.tin.triangles.size();
    result.tin = std::move(loaded.tin);
    return result;
}

}  // namespace dtm::io::detail
