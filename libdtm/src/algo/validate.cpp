// SPDX-License-Identifier: MIT
//
// Invariant checkers for a Tin. They use only the exact predicates, so a reported violation is a
// real one, never round-off. verify_constraints follows each input segment through the TIN along
// constrained edges, allowing vertices exactly on the segment and vertices added where
// constraints cross (those are the only vertices of a TIN that no input point gave).
#include "dtm/algo/validate.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

constexpr std::size_t max_problems = 10;

void add(CheckReport& report, const std::string& problem) {
    if (report.problems.size() < max_problems) report.problems.push_back(problem);
}

std::uint64_t edge_key(VertexIndex a, VertexIndex b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(a) << 32) | b;
}

struct XyHash {
    std::size_t operator()(const std::pair<double, double>& p) const noexcept {
        return std::hash<double>()(p.first) * 31u ^ std::hash<double>()(p.second);
    }
};

/// q lies on segment a-b: exactly, or within rounding of it. After two breaklines cross, each is
/// continued from the rounded intersection point, and a vertex exactly on such a piece can sit a
/// few units of the last place off the original segment: 1 micrometre plus 1e-9 of the length.
bool on_or_next_to(const Point3& a, const Point3& b, const Point3& q) {
    const double lo_x = std::min(a.x, b.x), hi_x = std::max(a.x, b.x);
    const double lo_y = std::min(a.y, b.y), hi_y = std::max(a.y, b.y);
    if (geom::orient2d(a, b, q) == 0)
        return lo_x <= q.x && q.x <= hi_x && lo_y <= q.y && q.y <= hi_y;
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double length = std::hypot(dx, dy);
    const double tolerance = 1e-6 + 1e-9 * length;
    const double distance = std::abs(dx * (q.y - a.y) - dy * (q.x - a.x)) / length;
    return distance <= tolerance && lo_x - tolerance <= q.x && q.x <= hi_x + tolerance &&
           lo_y - tolerance <= q.y && q.y <= hi_y + tolerance;
}

/// Uniform grid of the TIN's triangles (by bounding box, about one triangle per cell), built on
/// first use: where a point lies (inside a triangle or on its border, or outside the TIN) and
/// which vertices lie near a segment. Used only for segments the chain search did not find.
class TriangleGrid {
public:
    explicit TriangleGrid(const Tin& tin) : tin_(tin) {
        for (const Point3& v : tin.vertices) box_.add(v);
        const double w = std::max(box_.xmax - box_.xmin, 1e-300);
        const double h = std::max(box_.ymax - box_.ymin, 1e-300);
        const double cells = std::max<double>(1.0, static_cast<double>(tin.triangles.size()));
        cell_ = std::max(std::sqrt(w * h / cells), std::max(w, h) * 1e-9);
        cols_ = static_cast<std::size_t>(w / cell_) + 1;
        rows_ = static_cast<std::size_t>(h / cell_) + 1;
        buckets_.resize(cols_ * rows_);
        for (TriangleIndex t = 0; t < tin.triangles.size(); ++t) {
            Box2 b;
            for (const VertexIndex v : tin.triangles[t].v) b.add(tin.vertices[v]);
            for (std::size_t r = row(b.ymin); r <= row(b.ymax); ++r) {
                for (std::size_t c = col(b.xmin); c <= col(b.xmax); ++c) {
                    buckets_[r * cols_ + c].push_back(t);
                }
            }
        }
    }

    /// p lies in a triangle of the TIN or on its border.
    [[nodiscard]] bool covers(const Point2& p) const {
        if (p.x < box_.xmin || p.x > box_.xmax || p.y < box_.ymin || p.y > box_.ymax) return false;
        for (const TriangleIndex t : buckets_[row(p.y) * cols_ + col(p.x)]) {
            const auto& v = tin_.triangles[t].v;
            const Point3 &a = tin_.vertices[v[0]], &b = tin_.vertices[v[1]],
                         &c = tin_.vertices[v[2]];
            if (geom::orient2d(a, b, p) >= 0 && geom::orient2d(b, c, p) >= 0 &&
                geom::orient2d(c, a, p) >= 0) {
                return true;
            }
        }
        return false;
    }

    /// The vertices of triangles in the cells around segment a-b for which keep(v) holds.
    template <class Keep>
    [[nodiscard]] std::vector<VertexIndex> vertices_near(const Point3& a,
                                                         const Point3& b,
                                                         Keep keep) const {
        std::set<VertexIndex> found;
        for (std::size_t r = row(std::min(a.y, b.y)); r <= row(std::max(a.y, b.y)); ++r) {
            for (std::size_t c = col(std::min(a.x, b.x)); c <= col(std::max(a.x, b.x)); ++c) {
                for (const TriangleIndex t : buckets_[r * cols_ + c]) {
                    for (const VertexIndex v : tin_.triangles[t].v) {
                        if (keep(v)) found.insert(v);
                    }
                }
            }
        }
        return {found.begin(), found.end()};
    }

private:
    [[nodiscard]] std::size_t col(double x) const {
        const double i = std::floor((x - box_.xmin) / cell_);
        return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(cols_ - 1)));
    }
    [[nodiscard]] std::size_t row(double y) const {
        const double i = std::floor((y - box_.ymin) / cell_);
        return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(rows_ - 1)));
    }

    const Tin& tin_;
    Box2 box_;
    double cell_ = 1.0;
    std::size_t cols_ = 1;
    std::size_t rows_ = 1;
    std::vector<std::vector<TriangleIndex>> buckets_;
};

}  // namespace

CheckReport verify_tin(const Tin& tin,
                       const TerrainInput& input,
                       std::span<const VertexIndex> input_to_vertex,
                       Criterion criterion) {
    CheckReport all = verify_topology(tin);
    const auto append = [&all](const CheckReport& r) {
        all.problems.insert(all.problems.end(), r.problems.begin(), r.problems.end());
    };
    if (criterion == Criterion::delaunay) {
        append(verify_constrained_delaunay(tin));
    } else {
        for (const auto& [a, b] : improvable_edges(tin, criterion, 5)) {
            all.problems.push_back("edge " + std::to_string(a) + "-" + std::to_string(b) +
                                   " is not locally optimal under " +
                                   std::string(criterion_name(criterion)));
        }
    }
    append(verify_constraints(tin, input, input_to_vertex));
    return all;
}

std::string CheckReport::text() const {
    std::ostringstream out;
    for (const std::string& p : problems) out << p << '\n';
    return out.str();
}

CheckReport verify_topology(const Tin& tin) {
    CheckReport report;
    const std::size_t nv = tin.vertices.size();
    const std::size_t nt = tin.triangles.size();
    std::unordered_map<std::uint64_t, int> edge_use;
    edge_use.reserve(3 * nt);
    for (std::size_t t = 0; t < nt; ++t) {
        const Triangle& tri = tin.triangles[t];
        const std::string name = "triangle " + std::to_string(t);
        if (tri.v[0] >= nv || tri.v[1] >= nv || tri.v[2] >= nv) {
            add(report, name + ": vertex index out of range");
            continue;
        }
        if (geom::orient2d(tin.vertex(tri.v[0]), tin.vertex(tri.v[1]), tin.vertex(tri.v[2])) <= 0) {
            add(report, name + ": not counter-clockwise (or degenerate)");
        }
        for (int i = 0; i < 3; ++i) {
            const VertexIndex a = tri.v[(i + 1) % 3];
            const VertexIndex b = tri.v[(i + 2) % 3];
            if (++edge_use[edge_key(a, b)] > 2) add(report, name + ": edge used by 3 triangles");
            const TriangleIndex n = tri.n[i];
            if (n == no_triangle) continue;
            if (n >= nt) {
                add(report, name + ": neighbour index out of range");
                continue;
            }
            const Triangle& other = tin.triangles[n];
            bool back = false;
            for (int j = 0; j < 3; ++j) {
                back = back ||
                       (other.n[j] == t && other.v[(j + 1) % 3] == b && other.v[(j + 2) % 3] == a);
            }
            if (!back)
                add(report, name + ": neighbour " + std::to_string(n) + " does not link back");
        }
    }
    for (const ConstrainedEdge& c : tin.constraints) {
        if (!edge_use.count(edge_key(c.a, c.b))) {
            add(report, "constraint " + std::to_string(c.a) + "-" + std::to_string(c.b) +
                            " is not an edge of the TIN");
        }
    }
    return report;
}

CheckReport verify_constrained_delaunay(const Tin& tin) {
    CheckReport report;
    std::unordered_set<std::uint64_t> constrained;
    for (const ConstrainedEdge& c : tin.constraints) constrained.insert(edge_key(c.a, c.b));
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        const Triangle& tri = tin.triangles[t];
        for (int i = 0; i < 3; ++i) {
            const TriangleIndex n = tri.n[i];
            if (n == no_triangle || n < t) continue;
            const VertexIndex a = tri.v[(i + 1) % 3];
            const VertexIndex b = tri.v[(i + 2) % 3];
            if (constrained.count(edge_key(a, b))) continue;
            const Triangle& other = tin.triangles[n];
            VertexIndex d = other.v[0] + other.v[1] + other.v[2] - a - b;
            if (geom::incircle(tin.vertex(tri.v[0]), tin.vertex(tri.v[1]), tin.vertex(tri.v[2]),
                               tin.vertex(d)) > 0) {
                add(report, "edge " + std::to_string(a) + "-" + std::to_string(b) +
                                " is not constrained Delaunay (vertex " + std::to_string(d) +
                                " inside the circumcircle of triangle " + std::to_string(t) + ")");
            }
        }
    }
    return report;
}

CheckReport verify_constraints(const Tin& tin,
                               const TerrainInput& input,
                               std::span<const VertexIndex> input_to_vertex) {
    CheckReport report;
    std::unordered_map<std::pair<double, double>, VertexIndex, XyHash> at;
    for (VertexIndex v = 0; v < tin.vertices.size(); ++v)
        at[{tin.vertices[v].x, tin.vertices[v].y}] = v;
    std::unordered_set<std::pair<double, double>, XyHash> given;
    for (const Point3& p : input.points) given.insert({p.x, p.y});
    std::vector<bool> used(tin.vertices.size(), false);
    for (const Triangle& t : tin.triangles) {
        for (const VertexIndex v : t.v) used[v] = true;
    }
    std::unordered_map<VertexIndex, std::vector<VertexIndex>> adjacent;
    for (const ConstrainedEdge& c : tin.constraints) {
        adjacent[c.a].push_back(c.b);
        adjacent[c.b].push_back(c.a);
    }
    // Segment va-vb is present when vb can be reached from va along constrained edges through
    // vertices on it (or added at crossings). A segment that leaves the surface (through the
    // boundary, into a hole, or with an end beyond it) is clipped there: with @p stations (its
    // ends and the TIN vertices on it, in order along it), a step from one station to the next
    // may also skip the piece between them when that piece lies off the surface.
    std::optional<TriangleGrid> grid;
    const auto chain_reaches = [&](VertexIndex va, VertexIndex vb,
                                   const std::vector<VertexIndex>& stations) {
        const Point3& pa = tin.vertices[va];
        const Point3& pb = tin.vertices[vb];
        const auto allowed = [&](VertexIndex v) {
            const Point3& q = tin.vertices[v];
            return on_or_next_to(pa, pb, q) || !given.count({q.x, q.y});
        };
        std::unordered_map<VertexIndex, std::size_t> station_of;
        for (std::size_t i = 0; i < stations.size(); ++i) station_of.emplace(stations[i], i);
        std::set<VertexIndex> seen{va};
        std::vector<VertexIndex> frontier{va};
        const auto reach = [&](VertexIndex w) {
            if (seen.insert(w).second) frontier.push_back(w);
        };
        while (!frontier.empty()) {
            const VertexIndex v = frontier.back();
            frontier.pop_back();
            if (v == vb) return true;
            for (const VertexIndex w : adjacent[v]) {
                if (w == vb || allowed(w)) reach(w);
            }
            const auto it = station_of.find(v);
            if (it == station_of.end() || it->second + 1 == stations.size()) continue;
            const Point3& p = tin.vertices[v];
            const Point3& q = tin.vertices[stations[it->second + 1]];
            if (!grid->covers({0.5 * (p.x + q.x), 0.5 * (p.y + q.y)})) {
                reach(stations[it->second + 1]);
            }
        }
        return false;
    };
    const auto present_where_inside = [&](VertexIndex va, VertexIndex vb) {
        if (!grid) grid.emplace(tin);
        const Point3& pa = tin.vertices[va];
        const Point3& pb = tin.vertices[vb];
        std::vector<VertexIndex> stations = grid->vertices_near(pa, pb, [&](VertexIndex v) {
            return v != va && v != vb && used[v] && on_or_next_to(pa, pb, tin.vertices[v]);
        });
        const double dx = pb.x - pa.x, dy = pb.y - pa.y;
        const auto along = [&](VertexIndex v) {
            return (tin.vertices[v].x - pa.x) * dx + (tin.vertices[v].y - pa.y) * dy;
        };
        std::sort(stations.begin(), stations.end(),
                  [&](VertexIndex x, VertexIndex y) { return along(x) < along(y); });
        stations.insert(stations.begin(), va);
        stations.push_back(vb);
        return chain_reaches(va, vb, stations);
    };
    // Combined input numbering of triangulate(): points, breaklines, boundaries, holes, soft.
    std::size_t next_input = input.points.size();
    const auto vertex_of = [&](const Point3& p, std::size_t combined) -> VertexIndex {
        if (!input_to_vertex.empty()) {
            return combined < input_to_vertex.size() ? input_to_vertex[combined] : no_vertex;
        }
        const auto it = at.find({p.x, p.y});
        return it == at.end() ? no_vertex : it->second;
    };
    const auto check_lines = [&](const std::vector<Polyline>& lines, const char* what) {
        for (std::size_t k = 0; k < lines.size(); ++k) {
            const auto& pts = lines[k].points;
            const std::size_t count = pts.size();
            const std::size_t base = next_input;
            next_input += count;
            for (std::size_t i = 0; i + 1 < count + (lines[k].closed ? 1 : 0); ++i) {
                const std::size_t j = (i + 1) % count;
                const VertexIndex va = vertex_of(pts[i], base + i);
                const VertexIndex vb = vertex_of(pts[j], base + j);
                const std::string name = std::string(what) + " " + std::to_string(k + 1) +
                                         " segment " + std::to_string(i + 1);
                if (va == no_vertex || vb == no_vertex) {
                    add(report, name + ": endpoint is not a TIN vertex");
                    continue;
                }
                if (va == vb) continue;
                if (!used[va] || !used[vb]) {  // an end beyond the boundary or in a hole
                    if (!present_where_inside(va, vb)) {
                        add(report, name +
                                        ": not present as constrained edges where it crosses "
                                        "the surface");
                    }
                    continue;
                }
                if (!chain_reaches(va, vb, {}) && !present_where_inside(va, vb)) {
                    add(report, name + ": not present as constrained edges");
                }
            }
        }
    };
    // All input vertices first (so "added" means added by the triangulator), then the chains.
    for (const auto* lines :
         {&input.breaklines, &input.soft_breaklines, &input.boundaries, &input.holes}) {
        for (const Polyline& line : *lines)
            for (const Point3& p : line.points) given.insert({p.x, p.y});
    }
    check_lines(input.breaklines, "breakline");
    check_lines(input.boundaries, "boundary");
    check_lines(input.holes, "hole");
    check_lines(input.soft_breaklines, "soft breakline");
    return report;
}

double tin_area(const Tin& tin) {
    double sum = 0.0;
    double compensation = 0.0;
    for (const Triangle& t : tin.triangles) {
        const Point3& a = tin.vertex(t.v[0]);
        const Point3& b = tin.vertex(t.v[1]);
        const Point3& c = tin.vertex(t.v[2]);
        const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
        const double y = area - compensation;
        const double s = sum + y;
        compensation = (s - sum) - y;
        sum = s;
    }
    return sum;
}

}  // namespace dtm
