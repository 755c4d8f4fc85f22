// SPDX-License-Identifier: MIT
//
// First-use renumbering of a TIN's vertices, in parallel with the sequential result.
//
// Sequentially, vertex v gets the next number the first time a corner refers to it, scanning the
// triangles in order and each triangle's corners in order. So v's number is the rank of its first
// corner (3 t + i, the smallest corner that refers to v) among all first corners. In parallel:
// (1) every corner lowers its vertex's first corner by an atomic minimum, (2) every block of
// triangles counts the first corners it holds, a prefix sum gives each block its first number, and
// the block numbers its first corners in order (copying their vertices), (3) every corner takes
// its vertex's new number (in a copy, or in place for make_vertices_coherent).
#include "algo/detail/raster_vertex_order.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <utility>
#include <vector>

#include "algo/detail/big_array.hpp"

namespace dtm::detail {
namespace {

constexpr std::size_t block = std::size_t{1} << 14;  ///< triangles per block

/// Runs @p body(b, lo, hi) for every block b of triangles [lo, hi), in parallel.
template <class Body>
void for_blocks(std::size_t count, const Body& body) {
    const std::size_t blocks = (count + block - 1) / block;
    tbb::parallel_for(std::size_t{0}, blocks,
                      [&](std::size_t b) { body(b, b * block, std::min(count, (b + 1) * block)); });
}

/// Steps (1) and (2): the vertices in first-use order, and in @p renumber every vertex's new
/// number (no_vertex for a vertex no triangle uses). Fresh arrays: huge pages, faulted in on all
/// threads (assign_fresh).
std::vector<Point3> first_use_vertices(const Tin& tin, std::vector<VertexIndex>& renumber) {
    const std::size_t count = tin.triangles.size();
    const std::size_t blocks = (count + block - 1) / block;
    constexpr std::uint64_t unused = ~std::uint64_t{0};
    std::vector<std::uint64_t> first;  // first corner 3 t + i
    assign_fresh(first, tin.vertices.size(), unused);
    for_blocks(count, [&](std::size_t, std::size_t lo, std::size_t hi) {
        for (std::size_t t = lo; t < hi; ++t) {
            for (std::size_t i = 0; i < 3; ++i) {
                std::atomic_ref<std::uint64_t> cell(first[tin.triangles[t].v[i]]);
                const std::uint64_t corner = 3 * t + i;
                std::uint64_t held = cell.load(std::memory_order_relaxed);
                while (corner < held && !cell.compare_exchange_weak(held, corner)) {
                }
            }
        }
    });
    std::vector<std::size_t> start(blocks + 1, 0);
    for_blocks(count, [&](std::size_t b, std::size_t lo, std::size_t hi) {
        std::size_t here = 0;
        for (std::size_t t = lo; t < hi; ++t) {
            for (std::size_t i = 0; i < 3; ++i) here += first[tin.triangles[t].v[i]] == 3 * t + i;
        }
        start[b + 1] = here;
    });
    for (std::size_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
    std::vector<Point3> vertices;
    assign_fresh(vertices, start[blocks], Point3{});
    assign_fresh(renumber, tin.vertices.size(), no_vertex);
    for_blocks(count, [&](std::size_t b, std::size_t lo, std::size_t hi) {
        std::size_t next = start[b];
        for (std::size_t t = lo; t < hi; ++t) {
            for (std::size_t i = 0; i < 3; ++i) {
                const VertexIndex v = tin.triangles[t].v[i];
                if (first[v] != 3 * t + i) continue;
                renumber[v] = static_cast<VertexIndex>(next);
                vertices[next++] = tin.vertices[v];
            }
        }
    });
    return vertices;
}

}  // namespace

Tin with_coherent_vertices(const Tin& tin) {
    std::vector<VertexIndex> renumber;
    Tin out;
    out.vertices = first_use_vertices(tin, renumber);
    assign_fresh(out.triangles, tin.triangles.size(), Triangle{});
    for_blocks(tin.triangles.size(), [&](std::size_t, std::size_t lo, std::size_t hi) {
        for (std::size_t t = lo; t < hi; ++t) {
            Triangle tri = tin.triangles[t];
            for (VertexIndex& v : tri.v) v = renumber[v];
            out.triangles[t] = tri;
        }
    });
    return out;
}

bool has_coherent_vertices(const Tin& tin) noexcept {
    std::size_t next = 0;  // the number the next first use must carry
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) {
            if (v > next) return false;
            next += v == next ? 1 : 0;
        }
    }
    return true;
}

void make_vertices_coherent(Tin& tin) {
    std::vector<VertexIndex> renumber;
    std::vector<Point3> vertices = first_use_vertices(tin, renumber);
    for_blocks(tin.triangles.size(), [&](std::size_t, std::size_t lo, std::size_t hi) {
        for (std::size_t t = lo; t < hi; ++t) {
            for (VertexIndex& v : tin.triangles[t].v) v = renumber[v];
        }
    });
    tin.vertices = std::move(vertices);
}

}  // namespace dtm::detail
