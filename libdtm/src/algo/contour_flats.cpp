// SPDX-License-Identifier: MIT
// Flat triangles of a TIN built from contour lines, and their removal.
//
// A Delaunay TIN of contour vertices joins points of one line wherever the line bends back on
// itself or closes: those triangles lie flat at the line's level, and the DEM and contours
// derived from it are terraced. The fix follows the skeleton idea of Thibault and Gold:
//
//  1. Flat regions: the connected components of the flat triangles, joined through edges that
//     are not constrained (a contour separates the two sides of its own line).
//  2. Skeleton nodes: the midpoints of each region's unconstrained edges. Such an edge joins the
//     two banks of the region (two points of the contour), so its midpoint lies on the region's
//     medial axis, at distance d0 (half the edge) from the contour. A region triangle without
//     such an edge (cornered by constraints and the border) gets its centroid. Nodes of one
//     triangle are linked, which makes the skeleton a graph.
//  3. Openings: region edges shared with a non-flat triangle. Beyond them the ground goes to
//     another level z1 (the apex of that triangle). A multi-source Dijkstra from the openings
//     gives every node its distance d1 to the nearest other level (along the skeleton, then to
//     the apex) and that level's z1; the node's height is z0 + (z1 - z0) d0 / (d0 + d1),
//     strictly between the neighbouring levels, rising along the spur or valley axis towards
//     the next contour. The openings' own midpoints are not inserted: that would reshape the
//     non-flat triangle beyond, which is right as it is (and measurably worse when changed).
//  4. Enclosed regions (no opening): a closed contour around no point. The levels just outside
//     its line tell a summit (they are lower) from a pit; the heights rise (fall) from the
//     contour to half the interval beyond z0 at the node farthest from the contour (a cone),
//     and that estimate is reported. A region closed only by the TIN's border (a contour that
//     leaves the map) is extrapolated with the slope beyond its contour, at most a quarter
//     interval, and not reported.
//  5. Real flats stay: a region with a spot height at its level (a survey point; for a lake,
//     the water level), or touching a breakline the caller marks as a flat outline.
//  6. The heights: the band of each node is set by 3-4 (between z0 and z1, or z0 and half an
//     interval beyond); the height itself is the smooth surface of the contour TIN there (the
//     Clough-Tocher cubic, not creased at the contours), kept strictly inside the band, and
//     the skeleton estimate above where the cubic has no value. The cubic knows the shape: at a
//     contour vertex the network's gradient points across the line, so inside a spur or a ring
//     it rises or falls as the ground does (on the analytic test terrain it halves the error of
//     the new heights against the formula alone).
//  7. The TIN is built again with the nodes as points (each node is on an edge of a flat
//     triangle, so every flat triangle is split; a second round catches what is left).
//
// References: D. Thibault and C. M. Gold, "Terrain reconstruction from contours by skeleton
// construction", GeoInformatica 4(4), 2000; C. M. Gold and S. Snoeyink, "A one-step crust and
// skeleton extraction algorithm", Algorithmica 30, 2001.
#include "dtm/algo/contour_flats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <unordered_map>

#include "algo/detail/edge_kinds.hpp"
#include "dtm/algo/interpolation.hpp"

namespace dtm {
namespace {

bool is_flat(const Tin& tin, const Triangle& t) {
    const double z = tin.vertices[t.v[0]].z;
    return tin.vertices[t.v[1]].z == z && tin.vertices[t.v[2]].z == z;
}

/// Which TIN vertices are survey points (spot heights) or on a flat outline.
struct VertexRoles {
    std::vector<std::uint8_t> spot;
    std::vector<std::uint8_t> outline;
};

VertexRoles vertex_roles(const TerrainInput& input,
                         std::size_t survey_points,
                         const TriangulateResult& r,
                         const ContourFlatsOptions& options) {
    VertexRoles roles;
    roles.spot.assign(r.tin.vertices.size(), 0);
    roles.outline.assign(r.tin.vertices.size(), 0);
    const auto vertex = [&](std::size_t combined) {
        return combined < r.input_to_vertex.size() ? r.input_to_vertex[combined] : no_vertex;
    };
    for (std::size_t i = 0; i < survey_points; ++i) {
        if (const VertexIndex v = vertex(i); v != no_vertex) {
            roles.spot[v] = 1;
        }
    }
    std::size_t first = input.points.size();  // combined numbering: points, then breaklines
    for (std::size_t k = 0; k < input.breaklines.size(); ++k) {
        const bool outline = std::find(options.flat_outlines.begin(), options.flat_outlines.end(),
                                       k) != options.flat_outlines.end();
        for (std::size_t j = 0; outline && j < input.breaklines[k].points.size(); ++j) {
            if (const VertexIndex v = vertex(first + j); v != no_vertex) {
                roles.outline[v] = 1;
            }
        }
        first += input.breaklines[k].points.size();
    }
    return roles;
}

/// A point to add and the band of heights it must stay inside (the neighbouring levels).
struct Candidate {
    Point3 point;  ///< with the skeleton estimate of its height
    double lo = 0.0, hi = 0.0;
};

/// A summit or pit: the candidate at its middle.
struct PeakAt {
    std::size_t candidate = 0;
    double contour = 0.0;
    bool summit = true;
};

/// One skeleton node: a point of the region's medial axis.
struct Node {
    Point2 at;
    double d0 = 0.0;  ///< distance to the banks (half the edge it is the midpoint of)
};

/// Finds the flat regions of a TIN and the skeleton points that remove them.
class FlatRegions {
public:
    FlatRegions(const Tin& tin, const VertexRoles& roles, const ContourFlatsOptions& options)
        : tin_(tin),
          roles_(roles),
          options_(options),
          kinds_(detail::triangle_edge_kinds(tin)),
          region_(tin.triangles.size(), none) {}

    /// Appends the skeleton points to @p added and the summits and pits to @p peaks; fills
    /// the report's region counts.
    void run(std::vector<Candidate>& added,
             std::vector<PeakAt>& peaks,
             ContourFlatsReport& report) {
        for (TriangleIndex t = 0; t < tin_.triangles.size(); ++t) {
            if (region_[t] == none && is_flat(tin_, tin_.triangles[t])) {
                grow(t, static_cast<std::uint32_t>(regions_++));
                ++report.regions;
                fix_region(added, peaks, report);
            }
        }
    }

private:
    static constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

    [[nodiscard]] bool constrained(TriangleIndex t, std::size_t e) const {
        return kinds_[t][e] != detail::plain_edge;
    }

    /// The region of @p seed: flat triangles joined through unconstrained edges.
    void grow(TriangleIndex seed, std::uint32_t id) {
        members_.assign(1, seed);
        region_[seed] = id;
        for (std::size_t k = 0; k < members_.size(); ++k) {
            const TriangleIndex t = members_[k];
            for (std::size_t e = 0; e < 3; ++e) {
                const TriangleIndex u = tin_.triangles[t].n[e];
                if (u != no_triangle && !constrained(t, e) && region_[u] == none &&
                    is_flat(tin_, tin_.triangles[u])) {
                    region_[u] = id;
                    members_.push_back(u);
                }
            }
        }
    }

    [[nodiscard]] Point2 xy(VertexIndex v) const { return tin_.vertices[v].xy(); }
    static double distance(Point2 a, Point2 b) { return std::hypot(a.x - b.x, a.y - b.y); }

    void fix_region(std::vector<Candidate>& added,
                    std::vector<PeakAt>& peaks,
                    ContourFlatsReport& report) {
        const std::uint32_t id = region_[members_.front()];
        const double z0 = tin_.vertices[tin_.triangles[members_.front()].v[0]].z;
        for (const TriangleIndex t : members_) {
            for (const VertexIndex v : tin_.triangles[t].v) {
                if (roles_.spot[v] || roles_.outline[v]) {
                    ++report.true_flats;
                    return;
                }
            }
        }
        nodes_.clear();
        links_.clear();
        std::unordered_map<std::uint64_t, std::uint32_t> node_of_edge;
        std::vector<std::pair<std::uint32_t, double>> openings;  // node, distance to the apex
        std::vector<double> opening_z1, outside, slopes;
        std::vector<std::uint32_t> local;
        bool on_border = false;
        for (const TriangleIndex t : members_) {
            const Triangle& tri = tin_.triangles[t];
            local.clear();
            for (std::size_t e = 0; e < 3; ++e) {
                const TriangleIndex u = tri.n[e];
                const VertexIndex a = tri.v[(e + 1) % 3], b = tri.v[(e + 2) % 3];
                if (u == no_triangle || constrained(t, e)) {
                    on_border = on_border || u == no_triangle;
                    if (u != no_triangle && region_[u] != id) {  // the ground beyond the wall
                        const Point3& c = tin_.vertices[apex(u, t)];
                        if (c.z != z0) {
                            outside.push_back(c.z);
                            // the slope there: the height step over the apex's distance from
                            // the wall
                            const Point2 pa = xy(a), pb = xy(b);
                            const double len = distance(pa, pb);
                            const double across = std::abs((pb.x - pa.x) * (c.y - pa.y) -
                                                           (pb.y - pa.y) * (c.x - pa.x)) /
                                                  len;
                            if (across > 0.0) {
                                slopes.push_back(std::abs(c.z - z0) / across);
                            }
                        }
                    }
                    continue;
                }
                const bool inner = region_[u] == id;
                const TriangleIndex owner = inner ? std::min(t, u) : t;
                const std::size_t edge = owner == t ? e : edge_to(u, t);
                const std::uint64_t key = std::uint64_t{owner} * 3 + edge;
                auto [it, fresh] =
                    node_of_edge.try_emplace(key, static_cast<std::uint32_t>(nodes_.size()));
                if (fresh) {
                    const Point2 pa = xy(a), pb = xy(b);
                    Node n;
                    n.at = {0.5 * (pa.x + pb.x), 0.5 * (pa.y + pb.y)};
                    n.d0 = 0.5 * distance(pa, pb);
                    nodes_.push_back(n);
                    if (!inner) {  // an opening onto the apex of u
                        const VertexIndex c = apex(u, t);
                        openings.push_back({it->second, distance(n.at, xy(c))});
                        opening_z1.push_back(tin_.vertices[c].z);
                    }
                }
                local.push_back(it->second);
            }
            if (local.empty()) {  // cornered by constraints and the border: its centroid
                Node n;
                const Point2 p0 = xy(tri.v[0]), p1 = xy(tri.v[1]), p2 = xy(tri.v[2]);
                n.at = {(p0.x + p1.x + p2.x) / 3.0, (p0.y + p1.y + p2.y) / 3.0};
                n.d0 = std::min({distance(n.at, p0), distance(n.at, p1), distance(n.at, p2)}) / 2;
                local.push_back(static_cast<std::uint32_t>(nodes_.size()));
                nodes_.push_back(n);
            }
            for (std::size_t i = 0; i < local.size(); ++i) {
                for (std::size_t j = i + 1; j < local.size(); ++j) {
                    links_.push_back({local[i], local[j]});
                }
            }
        }
        if (!openings.empty()) {
            // The nodes inside the region get heights towards the nearest opening's level; the
            // openings' own midpoints are only the sources (a point there would change the
            // non-flat triangle beyond, which is right as it is)
            std::vector<double> to_open(nodes_.size()), z1(nodes_.size());
            spread(skeleton_graph(), openings, opening_z1, to_open, z1);
            std::vector<std::uint8_t> is_opening(nodes_.size(), 0);
            for (const auto& o : openings) {
                is_opening[o.first] = 1;
            }
            // (a region of openings only, such as one triangle, does get them)
            const bool only_openings = openings.size() == nodes_.size();
            for (std::size_t i = 0; i < nodes_.size(); ++i) {
                const Node& n = nodes_[i];
                if (!is_opening[i] || only_openings) {
                    added.push_back(
                        {{n.at.x, n.at.y, z0 + (z1[i] - z0) * n.d0 / (n.d0 + to_open[i])},
                         std::min(z0, z1[i]),
                         std::max(z0, z1[i])});
                }
            }
            return;
        }
        if (outside.empty() || !options_.estimate_summits) {
            ++report.unresolved;
            return;
        }
        // An enclosed summit or pit: by the ground outside the contour.
        std::sort(outside.begin(), outside.end());
        const double typical = outside[outside.size() / 2];
        const bool summit = typical < z0;
        const double half = 0.5 * std::abs(z0 - typical);
        double far = 0.0;
        std::size_t top = 0;
        for (std::size_t i = 0; i < nodes_.size(); ++i) {
            if (nodes_[i].d0 > far) {
                far = nodes_[i].d0;
                top = i;
            }
        }
        // Inside a closed contour the heights rise (fall) to half an interval at the node
        // farthest from it. A region reaching the TIN's border is not closed: the ground there
        // is extrapolated with the slope just outside it, at most a quarter interval.
        std::sort(slopes.begin(), slopes.end());
        const double slope = slopes.empty() ? 0.0 : slopes[slopes.size() / 2];
        for (const Node& n : nodes_) {
            const double rise = on_border ? std::min(0.5 * half, slope * n.d0)
                                          : half * (far > 0.0 ? n.d0 / far : 1.0);
            added.push_back({{n.at.x, n.at.y, summit ? z0 + rise : z0 - rise},
                             summit ? z0 : z0 - half,
                             summit ? z0 + half : z0});
        }
        if (!on_border) {
            peaks.push_back({added.size() - nodes_.size() + top, z0, summit});
        }
    }

    using Graph = std::vector<std::vector<std::pair<std::uint32_t, double>>>;

    [[nodiscard]] Graph skeleton_graph() const {
        Graph adjacent(nodes_.size());
        for (const auto& [a, b] : links_) {
            const double d = distance(nodes_[a].at, nodes_[b].at);
            adjacent[a].push_back({b, d});
            adjacent[b].push_back({a, d});
        }
        return adjacent;
    }

    /// Multi-source Dijkstra over the skeleton: from source nodes with their start distances
    /// and values, each node's distance to the nearest source and that source's value.
    static void spread(const Graph& adjacent,
                       const std::vector<std::pair<std::uint32_t, double>>& sources,
                       const std::vector<double>& source_value,
                       std::vector<double>& dist,
                       std::vector<double>& value) {
        dist.assign(adjacent.size(), std::numeric_limits<double>::infinity());
        using Item = std::pair<double, std::uint32_t>;
        std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
        for (std::size_t k = 0; k < sources.size(); ++k) {
            const auto [node, d] = sources[k];
            if (d < dist[node]) {
                dist[node] = d;
                value[node] = source_value[k];
                queue.push({d, node});
            }
        }
        while (!queue.empty()) {
            const auto [d, a] = queue.top();
            queue.pop();
            if (d > dist[a]) {
                continue;
            }
            for (const auto& [b, w] : adjacent[a]) {
                if (d + w < dist[b]) {
                    dist[b] = d + w;
                    value[b] = value[a];
                    queue.push({dist[b], b});
                }
            }
        }
    }

    /// The vertex of @p u opposite its edge shared with @p t.
    [[nodiscard]] VertexIndex apex(TriangleIndex u, TriangleIndex t) const {
        return tin_.triangles[u].v[edge_to(u, t)];
    }
    [[nodiscard]] std::size_t edge_to(TriangleIndex u, TriangleIndex t) const {
        const auto& n = tin_.triangles[u].n;
        return n[0] == t ? 0 : (n[1] == t ? 1 : 2);
    }

    const Tin& tin_;
    const VertexRoles& roles_;
    const ContourFlatsOptions& options_;
    detail::TriangleEdgeKinds kinds_;
    std::vector<std::uint32_t> region_;
    std::size_t regions_ = 0;
    std::vector<TriangleIndex> members_;
    std::vector<Node> nodes_;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> links_;
};

std::size_t count_contour_lines(const TerrainInput& input) {
    std::size_t n = 0;
    for (const Polyline& line : input.breaklines) {
        const bool one_height =
            line.points.size() >= 2 &&
            std::all_of(line.points.begin(), line.points.end(),
                        [&](const Point3& p) { return p.z == line.points.front().z; });
        n += one_height ? 1 : 0;
    }
    return n;
}

/// The heights of the new points from the smooth surface of the contour TIN (the cubic, not
/// creased at the contours: at each contour vertex the network's gradient points across the
/// line, so inside a spur or a ring the cubic rises or falls as the ground does), kept strictly
/// inside each point's band of neighbouring levels; the skeleton estimate where the cubic
/// has no value. On the analytic test terrain this halves the error of the new heights.
std::vector<Point3> smooth_heights(const Tin& tin, const std::vector<Candidate>& candidates) {
    const TinInterpolant cubic =
        TinInterpolant::prepare(tin, Interpolation::cubic, {.crease_at_breaklines = false});
    TinEvaluator eval(tin, cubic);
    std::vector<Point3> out;
    out.reserve(candidates.size());
    TriangleIndex hint = 0;
    for (const Candidate& c : candidates) {
        Point3 p = c.point;
        const double z = eval.value_at(p.x, p.y, hint);
        const double margin = 1e-3 * (c.hi - c.lo);
        if (std::isfinite(z)) {
            p.z = std::clamp(z, c.lo + margin, c.hi - margin);
        }
        out.push_back(p);
    }
    return out;
}

}  // namespace

std::size_t count_flat_triangles(const Tin& tin) {
    std::size_t n = 0;
    for (const Triangle& t : tin.triangles) {
        n += is_flat(tin, t) ? 1 : 0;
    }
    return n;
}

ContourFlatsResult triangulate_contours(const TerrainInput& input,
                                        const ContourFlatsOptions& options,
                                        const Progress& progress) {
    ContourFlatsResult out;
    ContourFlatsReport& report = out.report;
    report.contour_lines = count_contour_lines(input);
    const std::size_t survey_points = input.points.size();
    const unsigned rounds = std::max(1U, options.max_rounds);
    TerrainInput current = input;
    const double steps = rounds + 1.0;
    out.triangulation = triangulate(current, options.triangulate, progress.sub(0.0, 1.0 / steps));
    report.triangles_before = out.triangulation.tin.triangles.size();
    report.flat_before = count_flat_triangles(out.triangulation.tin);
    for (unsigned round = 0; round < rounds; ++round) {
        const VertexRoles roles = vertex_roles(current, survey_points, out.triangulation, options);
        std::vector<Candidate> candidates;
        std::vector<PeakAt> peaks;
        ContourFlatsReport found;
        FlatRegions(out.triangulation.tin, roles, options).run(candidates, peaks, found);
        if (round == 0) {
            report.regions = found.regions;
            report.true_flats = found.true_flats;
        }
        report.unresolved = found.unresolved;
        if (candidates.empty()) {
            break;
        }
        const std::vector<Point3> added = smooth_heights(out.triangulation.tin, candidates);
        for (const PeakAt& p : peaks) {
            report.peaks.push_back({added[p.candidate], p.contour, p.summit});
        }
        ++report.rounds;
        current.points.insert(current.points.end(), added.begin(), added.end());
        out.added.insert(out.added.end(), added.begin(), added.end());
        out.triangulation = triangulate(current, options.triangulate,
                                        progress.sub((round + 1.0) / steps, (round + 2.0) / steps));
    }
    report.points_added = out.added.size();
    report.triangles_after = out.triangulation.tin.triangles.size();
    report.flat_after = count_flat_triangles(out.triangulation.tin);
    progress.report(1.0, "contour flats");
    return out;
}

}  // namespace dtm
