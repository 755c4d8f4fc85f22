// SPDX-License-Identifier: MIT
// Thiessen polygons (dtm/algo/thiessen.hpp): the Voronoi regions of the sites, read off a
// Delaunay triangulation (a site's region is bounded by the bisectors with its Delaunay
// neighbours), clipped to a triangulated region.
//
// Pass 1, per region triangle T: from the site nearest to a corner of T (a greedy walk over the
// Delaunay neighbours, exact distance comparisons; all sites tied with it), visit the regions
// meeting T breadth first: a region's piece of T (thiessen_clip.hpp) names the neighbours across
// its bisector edges, whose regions meet T too. The pairs (site, triangle) are kept. Pass 2, per
// site and in parallel: its pieces again, merged into polygons. Collinear sites have no
// triangulation; their neighbours are the next ones along the line.
#include "dtm/algo/thiessen.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <numeric>

#include "algo/detail/thiessen_clip.hpp"
#include "dtm/algo/triangulate.hpp"
#include "dtm/algo/validate.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

/// The Delaunay neighbours of every site, sorted (compressed rows).
struct Neighbours {
    std::vector<std::size_t> first;
    std::vector<VertexIndex> list;
    [[nodiscard]] std::span<const VertexIndex> of(std::uint32_t v) const {
        return {list.data() + first[v], list.data() + first[v + 1]};
    }
};

Neighbours neighbours_of(std::span<const Point3> sites, const Tin& delaunay) {
    const std::size_t n = sites.size();
    std::vector<std::pair<VertexIndex, VertexIndex>> pairs;
    if (!delaunay.triangles.empty()) {
        pairs.reserve(delaunay.triangles.size() * 6);
        for (const Triangle& t : delaunay.triangles) {
            for (int i = 0; i < 3; ++i) {
                pairs.emplace_back(t.v[i], t.v[(i + 1) % 3]);
                pairs.emplace_back(t.v[(i + 1) % 3], t.v[i]);
            }
        }
    } else {
        std::vector<VertexIndex> order(n);
        std::iota(order.begin(), order.end(), 0u);
        std::sort(order.begin(), order.end(), [&](VertexIndex a, VertexIndex b) {
            return sites[a].x < sites[b].x || (sites[a].x == sites[b].x && sites[a].y < sites[b].y);
        });
        for (std::size_t i = 1; i < n; ++i) {
            pairs.emplace_back(order[i - 1], order[i]);
            pairs.emplace_back(order[i], order[i - 1]);
        }
    }
    std::sort(pairs.begin(), pairs.end());
    pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
    Neighbours nb;
    nb.first.assign(n + 1, 0);
    for (const auto& [a, b] : pairs) ++nb.first[a + 1];
    std::partial_sum(nb.first.begin(), nb.first.end(), nb.first.begin());
    nb.list.reserve(pairs.size());
    for (const auto& [a, b] : pairs) nb.list.push_back(b);
    return nb;
}

/// The site nearest to @p p, walking from @p start (a greedy walk over the Delaunay neighbours
/// ends at a nearest site).
std::uint32_t nearest_site(std::span<const Point3> sites,
                           const Neighbours& nb,
                           const Point3& p,
                           std::uint32_t start) {
    std::uint32_t g = start;
    for (bool moved = true; moved;) {
        moved = false;
        for (const VertexIndex h : nb.of(g)) {
            if (geom::compare_distances(p, sites[h], p, sites[g]) < 0) {
                g = h;
                moved = true;
                break;
            }
        }
    }
    return g;
}

}  // namespace

Tin clip_region_of_rings(std::span<const Polyline> boundaries, std::span<const Polyline> holes) {
    TerrainInput input;
    const auto flat = [](Polyline ring) {
        for (Point3& p : ring.points) p.z = 0.0;  // only the plan matters
        return ring;
    };
    for (const Polyline& r : boundaries) input.boundaries.push_back(flat(r));
    for (const Polyline& r : holes) input.holes.push_back(flat(r));
    return triangulate(std::move(input)).tin;
}

Tin clip_region_of_hull(const Tin& delaunay) {
    if (delaunay.triangles.empty()) {
        throw InputError(
            "the points are collinear: their convex hull has no area (give a boundary)");
    }
    // The boundary edges a -> b (counter-clockwise), chained into the hull cycle.
    std::vector<VertexIndex> next(delaunay.vertices.size(), no_vertex);
    VertexIndex start = no_vertex;
    for (const Triangle& t : delaunay.triangles) {
        for (int i = 0; i < 3; ++i) {
            if (t.n[i] != no_triangle) continue;
            const VertexIndex a = t.v[(i + 1) % 3];
            next[a] = t.v[(i + 2) % 3];
            start = a;
        }
    }
    std::vector<VertexIndex> cycle;
    VertexIndex v = start;
    do {
        cycle.push_back(v);
        v = next[v];
    } while (v != start && cycle.size() <= delaunay.vertices.size());
    TerrainInput input;
    const std::size_t k = cycle.size();
    for (std::size_t i = 0; i < k; ++i) {
        const Point3& p = delaunay.vertices[cycle[(i + k - 1) % k]];
        const Point3& q = delaunay.vertices[cycle[i]];
        const Point3& r = delaunay.vertices[cycle[(i + 1) % k]];
        if (geom::orient2d(p, q, r) != 0) input.points.push_back({q.x, q.y, 0.0});  // a corner
    }
    return triangulate(std::move(input)).tin;
}

ThiessenResult thiessen_cells(std::span<const Point3> sites,
                              const Tin& delaunay,
                              const Tin& region,
                              const Progress& progress) {
    ThiessenResult result;
    const std::size_t n = sites.size();
    result.cells.resize(n);
    result.region_area = tin_area(region);
    if (n == 0 || region.triangles.empty()) {
        result.empty_cells = n;
        return result;
    }
    const Neighbours nb = neighbours_of(sites, delaunay);
    const detail::CellClipper clipper(sites, region.vertices);

    // Pass 1: which regions meet which triangle.
    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (site, triangle)
    std::vector<std::uint32_t> stamp(n, no_vertex);
    std::vector<std::uint32_t> queue;
    detail::Piece piece;
    std::uint32_t start = 0;
    for (std::uint32_t t = 0; t < region.triangles.size(); ++t) {
        if ((t & 0xfffu) == 0)
            progress.report(0.4 * double(t) / double(region.triangles.size()), "clipping");
        const Triangle& tri = region.triangles[t];
        const Point3& corner = region.vertices[tri.v[0]];
        start = nearest_site(sites, nb, corner, start);
        queue.assign(1, start);
        stamp[start] = t;
        for (std::size_t i = 0; i < queue.size(); ++i) {  // every site tied with it
            for (const VertexIndex h : nb.of(queue[i])) {
                if (stamp[h] != t &&
                    geom::compare_distances(corner, sites[h], corner, sites[start]) == 0) {
                    stamp[h] = t;
                    queue.push_back(h);
                }
            }
        }
        for (std::size_t i = 0; i < queue.size(); ++i) {
            const std::uint32_t g = queue[i];
            clipper.clip(g, nb.of(g), tri.v, piece);
            if (piece.empty()) continue;
            pairs.emplace_back(g, t);
            for (const detail::PieceVertex& v : piece) {
                if (v.out.kind != detail::Support::bisector) continue;
                const std::uint32_t h = v.out.a;
                if (stamp[h] != t) {
                    stamp[h] = t;
                    queue.push_back(h);
                }
            }
        }
    }
    stamp = {};
    std::sort(pairs.begin(), pairs.end());
    std::vector<std::size_t> first(n + 1, 0);
    for (const auto& [g, t] : pairs) ++first[g + 1];
    std::partial_sum(first.begin(), first.end(), first.begin());

    // Pass 2: each site's pieces merged into its polygons.
    progress.report(0.4, "merging");
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1024), [&](const auto& range) {
        progress.check();
        std::vector<detail::Piece> pieces;
        for (std::size_t g = range.begin(); g != range.end(); ++g) {
            pieces.clear();
            for (std::size_t i = first[g]; i < first[g + 1]; ++i) {
                pieces.emplace_back();
                clipper.clip(static_cast<std::uint32_t>(g), nb.of(static_cast<std::uint32_t>(g)),
                             region.triangles[pairs[i].second].v, pieces.back());
            }
            ThiessenCell& cell = result.cells[g];
            detail::merge_pieces(static_cast<std::uint32_t>(g), pieces, clipper, region.vertices,
                                 cell);
            for (const detail::Piece& p : pieces) {
                for (const detail::PieceVertex& v : p) {
                    if (v.out.kind == detail::Support::bisector) cell.neighbours.push_back(v.out.a);
                }
            }
            std::sort(cell.neighbours.begin(), cell.neighbours.end());
            cell.neighbours.erase(std::unique(cell.neighbours.begin(), cell.neighbours.end()),
                                  cell.neighbours.end());
        }
    });
    for (const ThiessenCell& c : result.cells) result.empty_cells += c.polygons.empty() ? 1 : 0;
    progress.report(1.0, "clipped");
    return result;
}

}  // namespace dtm
