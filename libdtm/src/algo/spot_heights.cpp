// SPDX-License-Identifier: MIT
// Spot-height selection on a TIN.
//   1. Critical vertices of the piecewise-linear surface (Banchoff, "Critical points and
//      curvature for embedded polyhedra", J. Differential Geometry 1, 1967; Edelsbrunner,
//      Harer, Zomorodian, "Hierarchical Morse-Smale complexes for piecewise linear 2-manifolds",
//      DCG 30, 2003): walking round an interior vertex's link, the number of changes between
//      higher and lower neighbours is 0 at a summit or pit, 2 at a regular vertex and 4 or more
//      at a saddle. Equal heights are ordered by vertex index (simulation of simplicity), so
//      flat ground gives no critical points of its own.
//   2. A map shows the critical points that hold at the map's scale: a summit (pit) must be
//      strictly higher (lower) than every other vertex within the spacing radius, a saddle must
//      show at least two higher and two lower sectors (eight 45-degree sectors, mean height
//      difference) within it. Survey noise makes many link-level extremes that fail this test.
//      Near the TIN border (within about half the radius) the disc is partly empty and nothing
//      is called critical. Searches visit the nearest grid cells first, so a noise extreme is
//      refuted early; saddles are tried at a quarter of the radius before the whole disc.
//   3. Greedy thinning in priority order (summits highest first, pits lowest first, saddles by
//      relief, then regular vertices nearest to the centres of a spacing-sized grid, a second
//      pass on the half-shifted grid), keeping every pair at least the spacing apart: a
//      Poisson-disc-like spread as in the spot-height generalisation of topographic maps.
#include "dtm/algo/spot_heights.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

#include "algo/detail/label_index.hpp"

namespace dtm {
namespace {

/// Vertices bucketed by a square grid, for radius queries.
class VertexGrid {
public:
    VertexGrid(const Tin& tin, const std::vector<VertexIndex>& ids, double cell)
        : tin_(tin), grid_(cell), cell_(cell) {
        std::vector<std::pair<std::uint64_t, VertexIndex>> entries;
        entries.reserve(ids.size());
        for (const VertexIndex v : ids) {
            const Point3& p = tin.vertices[v];
            entries.emplace_back(detail::CellGrid::key(grid_.index(p.x), grid_.index(p.y)), v);
        }
        std::sort(entries.begin(), entries.end());
        members_.reserve(entries.size());
        for (std::size_t i = 0; i < entries.size();) {
            std::size_t j = i;
            while (j < entries.size() && entries[j].first == entries[i].first) {
                members_.push_back(entries[j++].second);
            }
            cells_.emplace(entries[i].first, std::make_pair(i, j));
            i = j;
        }
    }
    /// Calls f(v) for every vertex within @p radius of @p c, cells nearest to @p c first (so
    /// that a search for a counter-example ends early); stops when f returns true and then
    /// returns true. With @p stride > 1 only every stride-th vertex of a cell is visited.
    template <class F>
    bool any_within(Point2 c, double radius, F&& f, std::size_t stride = 1) const {
        const double r2 = radius * radius;
        const std::int64_t ci = grid_.index(c.x);
        const std::int64_t cj = grid_.index(c.y);
        const auto rings = static_cast<std::int64_t>(std::ceil(radius / cell_)) + 1;
        for (std::int64_t k = 0; k <= rings; ++k) {
            for (std::int64_t i = ci - k; i <= ci + k; ++i) {
                const bool edge = i == ci - k || i == ci + k;
                for (std::int64_t j = cj - k; j <= cj + k; j += edge ? 1 : 2 * k) {
                    const auto it = cells_.find(detail::CellGrid::key(i, j));
                    if (it != cells_.end()) {
                        for (std::size_t s = it->second.first; s < it->second.second; s += stride) {
                            const Point3& p = tin_.vertices[members_[s]];
                            const double dx = p.x - c.x;
                            const double dy = p.y - c.y;
                            if (dx * dx + dy * dy <= r2 && f(members_[s])) return true;
                        }
                    }
                    if (k == 0) break;
                }
            }
        }
        return false;
    }
    /// Number of vertices in the cells within @p radius of @p c (at least the disc's).
    [[nodiscard]] std::size_t count_near(Point2 c, double radius) const {
        std::size_t n = 0;
        Box2 box;
        box.add(c.x - radius, c.y - radius);
        box.add(c.x + radius, c.y + radius);
        grid_.for_cells(box, [&](std::uint64_t key) {
            const auto it = cells_.find(key);
            if (it != cells_.end()) n += it->second.second - it->second.first;
        });
        return n;
    }
    /// True when the cell of @p c or one of its eight neighbours holds a vertex with f(v).
    template <class F>
    [[nodiscard]] bool near_cells_hold(Point2 c, F&& f) const {
        const std::int64_t ci = grid_.index(c.x);
        const std::int64_t cj = grid_.index(c.y);
        for (std::int64_t i = ci - 1; i <= ci + 1; ++i) {
            for (std::int64_t j = cj - 1; j <= cj + 1; ++j) {
                const auto it = cells_.find(detail::CellGrid::key(i, j));
                if (it == cells_.end()) continue;
                for (std::size_t s = it->second.first; s < it->second.second; ++s) {
                    if (f(members_[s])) return true;
                }
            }
        }
        return false;
    }
    [[nodiscard]] double cell() const noexcept { return cell_; }

private:
    const Tin& tin_;
    detail::CellGrid grid_;
    double cell_;
    std::vector<VertexIndex> members_;
    std::unordered_map<std::uint64_t, std::pair<std::size_t, std::size_t>> cells_;
};

struct Topology {
    std::vector<std::uint8_t> used;
    std::vector<std::uint8_t> border;
    std::vector<std::uint16_t> changes;  ///< sign changes round the link
    std::vector<std::uint8_t> has_higher;
    double area = 0.0;
};

bool higher(const Tin& tin, VertexIndex a, VertexIndex b) {
    const double za = tin.vertices[a].z;
    const double zb = tin.vertices[b].z;
    return za > zb || (za == zb && a > b);
}

Topology link_topology(const Tin& tin) {
    const std::size_t n = tin.vertices.size();
    Topology t;
    t.used.assign(n, 0);
    t.border.assign(n, 0);
    t.changes.assign(n, 0);
    t.has_higher.assign(n, 0);
    for (const Triangle& tri : tin.triangles) {
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = tri.v[i];
            const VertexIndex b = tri.v[(i + 1) % 3];
            const VertexIndex c = tri.v[(i + 2) % 3];
            t.used[a] = 1;
            const bool hb = higher(tin, b, a);
            const bool hc = higher(tin, c, a);
            if (hb != hc && t.changes[a] < 0xffff) ++t.changes[a];
            if (hb || hc) t.has_higher[a] = 1;
            if (tri.n[i] == no_triangle) t.border[b] = t.border[c] = 1;
        }
        const Point3& p = tin.vertices[tri.v[0]];
        const Point3& q = tin.vertices[tri.v[1]];
        const Point3& r = tin.vertices[tri.v[2]];
        t.area += 0.5 * std::abs((q.x - p.x) * (r.y - p.y) - (r.x - p.x) * (q.y - p.y));
    }
    return t;
}

SpotKind link_kind(const Topology& t, VertexIndex v) {
    if (t.border[v] != 0) return SpotKind::regular;
    if (t.changes[v] == 0) return t.has_higher[v] != 0 ? SpotKind::pit : SpotKind::summit;
    return t.changes[v] >= 4 ? SpotKind::saddle : SpotKind::regular;
}

struct Candidate {
    VertexIndex v;
    SpotKind kind;
    double priority;  ///< larger first within a kind
};

/// Relief of a saddle at @p radius: sum of |mean height difference| over sectors when the
/// sectors alternate at least twice between higher and lower; 0 otherwise.
double saddle_relief(const Tin& tin, const VertexGrid& grid, VertexIndex v, double radius) {
    constexpr int sectors = 8;
    std::array<double, sectors> sum{};
    std::array<int, sectors> count{};
    const Point3& c = tin.vertices[v];
    // the sector means need a sample, not every vertex of a large disc
    const std::size_t stride = std::max<std::size_t>(1, grid.count_near(c.xy(), radius) / 2048);
    grid.any_within(
        c.xy(), radius,
        [&](VertexIndex u) {
            if (u == v) return false;
            const Point3& p = tin.vertices[u];
            const double dx = p.x - c.x;
            const double dy = p.y - c.y;
            // octant 0..7 counter-clockwise from east, by comparisons only
            int s = 0;
            if (dy >= 0.0) {
                s = dx >= 0.0 ? (dx >= dy ? 0 : 1) : (-dx <= dy ? 2 : 3);
            } else {
                s = dx < 0.0 ? (-dx >= -dy ? 4 : 5) : (dx <= -dy ? 6 : 7);
            }
            sum[static_cast<std::size_t>(s)] += p.z - c.z;
            ++count[static_cast<std::size_t>(s)];
            return false;
        },
        stride);
    std::array<double, sectors> means{};
    std::size_t m = 0;
    for (int s = 0; s < sectors; ++s) {
        const auto k = static_cast<std::size_t>(s);
        if (count[k] > 0) means[m++] = sum[k] / count[k];
    }
    int flips = 0;
    double relief = 0.0;
    for (std::size_t i = 0; i < m; ++i) {
        const double a = means[i];
        const double b = means[(i + 1) % m];
        if ((a > 0.0) != (b > 0.0)) ++flips;
        relief += std::abs(a);
    }
    return flips >= 4 ? relief : 0.0;
}

/// Critical candidates that hold at @p radius, in priority order.
std::vector<Candidate> critical_candidates(const Tin& tin,
                                           const Topology& t,
                                           const std::vector<VertexIndex>& inside,
                                           const VertexGrid& grid,
                                           double radius,
                                           const Progress& progress) {
    std::vector<Candidate> out;
    for (std::size_t n = 0; n < inside.size(); ++n) {
        if (n % 65536 == 0) progress.check();
        const VertexIndex v = inside[n];
        const SpotKind kind = link_kind(t, v);
        if (kind == SpotKind::regular) continue;
        const Point3& p = tin.vertices[v];
        // Near the TIN border the disc is partly empty: no extreme can be told there (the
        // grid's cells are half the radius: a border vertex in a neighbouring cell is near).
        if (grid.near_cells_hold(p.xy(), [&](VertexIndex u) { return t.border[u] != 0; })) {
            continue;
        }
        if (kind == SpotKind::saddle) {
            // a cheap test at a quarter of the radius first: most survey noise fails it
            if (saddle_relief(tin, grid, v, radius / 4.0) == 0.0) continue;
            const double relief = saddle_relief(tin, grid, v, radius);
            if (relief > 0.0) out.push_back({v, kind, relief});
            continue;
        }
        // strictly: a vertex as high (low) within the radius makes the place a plateau
        const bool beaten = grid.any_within(p.xy(), radius, [&](VertexIndex u) {
            return u != v &&
                   (kind == SpotKind::summit ? tin.vertices[u].z >= p.z : tin.vertices[u].z <= p.z);
        });
        if (!beaten) out.push_back({v, kind, kind == SpotKind::summit ? p.z : -p.z});
    }
    std::stable_sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
        if (a.kind != b.kind) return a.kind < b.kind;
        return a.priority > b.priority;
    });
    return out;
}

/// Regular vertices nearest to the centres of a grid of @p cell (shifted by @p shift cells).
std::vector<Candidate> spread_candidates(const Tin& tin,
                                         const std::vector<VertexIndex>& inside,
                                         double cell,
                                         double shift) {
    std::unordered_map<std::uint64_t, std::pair<double, VertexIndex>> best;
    const detail::CellGrid grid(cell);
    for (const VertexIndex v : inside) {
        const Point3& p = tin.vertices[v];
        const double x = p.x - shift * cell;
        const double y = p.y - shift * cell;
        const std::int64_t i = grid.index(x);
        const std::int64_t j = grid.index(y);
        const double cx = (static_cast<double>(i) + 0.5) * cell;
        const double cy = (static_cast<double>(j) + 0.5) * cell;
        const double d = (x - cx) * (x - cx) + (y - cy) * (y - cy);
        const auto [it, fresh] = best.try_emplace(detail::CellGrid::key(i, j), d, v);
        if (!fresh && (d < it->second.first || (d == it->second.first && v < it->second.second))) {
            it->second = {d, v};
        }
    }
    std::vector<std::pair<std::uint64_t, VertexIndex>> cells;
    cells.reserve(best.size());
    for (const auto& [key, value] : best) cells.emplace_back(key, value.second);
    std::sort(cells.begin(), cells.end());
    std::vector<Candidate> out;
    out.reserve(cells.size());
    for (const auto& c : cells) out.push_back({c.second, SpotKind::regular, 0.0});
    return out;
}

/// Greedy selection keeping every pair at least @p spacing apart.
std::vector<SpotHeight> thin(const Tin& tin,
                             const std::vector<std::vector<Candidate>>& lists,
                             double spacing) {
    std::vector<SpotHeight> out;
    std::vector<std::uint8_t> taken(tin.vertices.size(), 0);
    std::vector<VertexIndex> chosen;
    std::unordered_map<std::uint64_t, std::vector<VertexIndex>> cells;
    const detail::CellGrid grid(spacing);
    const double s2 = spacing * spacing;
    for (const std::vector<Candidate>& list : lists) {
        for (const Candidate& c : list) {
            if (taken[c.v] != 0) continue;
            const Point3& p = tin.vertices[c.v];
            Box2 box;
            box.add(p.x - spacing, p.y - spacing);
            box.add(p.x + spacing, p.y + spacing);
            bool near = false;
            grid.for_cells(box, [&](std::uint64_t key) {
                const auto it = cells.find(key);
                if (near || it == cells.end()) return;
                for (const VertexIndex u : it->second) {
                    const Point3& q = tin.vertices[u];
                    if ((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y) < s2) {
                        near = true;
                        return;
                    }
                }
            });
            if (near) continue;
            taken[c.v] = 1;
            cells[detail::CellGrid::key(grid.index(p.x), grid.index(p.y))].push_back(c.v);
            out.push_back({c.v, p, c.kind});
        }
    }
    return out;
}

bool in_extent(const std::optional<Box2>& extent, const Point3& p) {
    return !extent || (p.x >= extent->xmin && p.x <= extent->xmax && p.y >= extent->ymin &&
                       p.y <= extent->ymax);
}

void count_kinds(SpotHeightResult& r) {
    for (const SpotHeight& s : r.spots) {
        switch (s.kind) {
            case SpotKind::summit:
                ++r.summits;
                break;
            case SpotKind::pit:
                ++r.pits;
                break;
            case SpotKind::saddle:
                ++r.saddles;
                break;
            case SpotKind::regular:
                ++r.regular;
                break;
        }
    }
}

}  // namespace

const char* to_string(SpotKind kind) noexcept {
    switch (kind) {
        case SpotKind::summit:
            return "summit";
        case SpotKind::pit:
            return "pit";
        case SpotKind::saddle:
            return "saddle";
        case SpotKind::regular:
            return "regular";
    }
    return "regular";
}

SpotHeightResult select_spot_heights(const Tin& tin,
                                     const SpotHeightOptions& options,
                                     const Progress& progress) {
    SpotHeightResult result;
    progress.report(0.0, "selecting spot heights");
    const Topology t = link_topology(tin);
    std::vector<VertexIndex> used;
    std::vector<VertexIndex> inside;
    for (VertexIndex v = 0; v < tin.vertices.size(); ++v) {
        if (t.used[v] == 0) continue;
        used.push_back(v);
        if (in_extent(options.extent, tin.vertices[v])) inside.push_back(v);
    }
    if (used.empty()) return result;
    double spacing = options.spacing;
    if (!(spacing > 0.0)) spacing = 4.0 * std::sqrt(t.area / static_cast<double>(used.size()));
    if (!(spacing > 0.0)) spacing = 1.0;
    result.spacing = spacing;
    if (options.all) {
        for (const VertexIndex v : inside)
            result.spots.push_back({v, tin.vertices[v], link_kind(t, v)});
        std::stable_sort(result.spots.begin(), result.spots.end(),
                         [](const SpotHeight& a, const SpotHeight& b) { return a.kind < b.kind; });
        count_kinds(result);
        progress.report(1.0, "selecting spot heights");
        return result;
    }
    const VertexGrid grid(tin, used, spacing / 2.0);
    std::vector<std::vector<Candidate>> lists;
    lists.push_back(critical_candidates(tin, t, inside, grid, spacing, progress.sub(0.0, 0.6)));
    progress.report(0.6, "selecting spot heights");
    for (;;) {
        lists.resize(1);
        lists.push_back(spread_candidates(tin, inside, spacing, 0.0));
        lists.push_back(spread_candidates(tin, inside, spacing, 0.5));
        result.spots = thin(tin, lists, spacing);
        progress.check();
        if (options.max_count == 0 || result.spots.size() <= options.max_count) break;
        const double ratio =
            static_cast<double>(result.spots.size()) / static_cast<double>(options.max_count);
        spacing *= std::max(1.02, std::sqrt(ratio));
    }
    result.spacing = spacing;
    count_kinds(result);
    progress.report(1.0, "selecting spot heights");
    return result;
}

}  // namespace dtm
