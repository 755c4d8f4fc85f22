// SPDX-License-Identifier: MIT
// Contours of the smooth surfaces, traced on a refinement of the TIN.
//
// The level sets of a C1 cubic (or of the natural-neighbour surface) are smooth curves; tracing
// them exactly and robustly (several crossings per edge, tangencies, saddles inside a
// triangle) is hard, tracing a linear surface is not. So each triangle is cut as the cubic is
// defined, into its three Clough-Tocher sub-triangles (corner, corner, centroid), and each of
// those into m^2 pieces on a regular lattice:
//
//            c (centroid)          the lattice points of sub-triangle (A, B, c):
//           / \                        A + (a/m)(B - A) + (b/m)(c - A),  a, b >= 0, a + b <= m
//          /___\                   the points on the triangle's edge A B are shared with the
//         /\   /\                  neighbour across it, those on the inner edges (A c, B c)
//        /__\ /__\                 with the next sub-triangle: one vertex each, with one
//       A----------B               height, so the refinement is a valid TIN.
//
// Every lattice point gets the surface's height; the refinement is then contoured exactly like
// any TIN (contour.cpp), so the lines are continuous, closed where they close, and lines of
// different levels never cross. The refined lines follow the smooth surface to within its
// deviation from a plane over a piece, a fraction 1/m^2 of that over a sub-triangle.
//
// Memory stays bounded: the levels are processed in batches, each refining only the triangles
// whose height range (the Bezier ordinates' range of the cubic patch, or the lattice heights)
// a level of the batch cuts, about four million pieces per batch.
#include "algo/detail/contour_refined.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "algo/detail/contour_trace.hpp"
#include "dtm/core/error.hpp"

namespace dtm::detail {
namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

/// Index arithmetic of the refinement of one triangle with m divisions per sub-triangle edge.
/// Sub-triangle k lies on the triangle's edge k (opposite corner k) with corners
/// A = v[k + 1], B = v[k + 2] and the centroid. Its pieces: up(a, b) = (L(a,b), L(a+1,b),
/// L(a,b+1)) for a + b <= m - 1 and down(a, b) = (L(a+1,b), L(a+1,b+1), L(a,b+1)) for
/// a + b <= m - 2, row by row.
class Lattice {
public:
    explicit Lattice(std::uint32_t m)
        : m_(m),
          interior_((m - 1) * (m > 1 ? m - 2 : 0) / 2),
          local_(1 + 3 * (m - 1) + 3 * interior_) {}

    [[nodiscard]] std::uint32_t m() const { return m_; }
    /// New vertices of a triangle not on its edges: the centroid, the inner edges, the pieces'
    /// interiors.
    [[nodiscard]] std::uint32_t local_vertices() const { return local_; }
    [[nodiscard]] std::uint32_t pieces() const { return 3 * m_ * m_; }
    [[nodiscard]] std::uint32_t up(std::uint32_t k, std::uint32_t a, std::uint32_t b) const {
        return k * m_ * m_ + b * (2 * m_ - b) + 2 * a;
    }
    [[nodiscard]] std::uint32_t down(std::uint32_t k, std::uint32_t a, std::uint32_t b) const {
        return up(k, a, b) + 1;
    }
    /// Local index of the point at b / m from corner c towards the centroid (0 < b < m); the
    /// centroid itself is local 0.
    [[nodiscard]] std::uint32_t inner(std::uint32_t c, std::uint32_t b) const {
        return 1 + c * (m_ - 1) + (b - 1);
    }
    /// Local index of the interior lattice point (a, b) of sub-triangle k (a, b >= 1).
    [[nodiscard]] std::uint32_t interior(std::uint32_t k, std::uint32_t a, std::uint32_t b) const {
        // rows b = 1 .. m - 2 hold m - 1 - b points each
        const std::uint32_t row = (b - 1) * (m_ - 1) - (b - 1) * b / 2;
        return 1 + 3 * (m_ - 1) + k * interior_ + row + (a - 1);
    }

private:
    std::uint32_t m_;
    std::uint32_t interior_;
    std::uint32_t local_;
};

/// Per triangle: the range of its refinement's heights (a bound of it for cubic).
struct Ranges {
    std::vector<double> lo, hi;
};

/// The positions of the lattice points of triangle t that it computes itself: its local points
/// and the points of the edges it owns. Edge points run from the edge's lower-numbered vertex,
/// so both triangles of an edge would compute the same coordinates.
class LocalPoints {
public:
    LocalPoints(const Tin& tin, const Lattice& lattice) : tin_(tin), lattice_(lattice) {}

    /// Fills @p out with the local points, then (m - 1) points per edge e with own[e].
    void make(TriangleIndex t, const std::array<bool, 3>& own, std::vector<Point2>& out) const {
        const Triangle& tri = tin_.triangles[t];
        const std::uint32_t m = lattice_.m();
        const double md = static_cast<double>(m);
        const Point3* v[3] = {&tin_.vertices[tri.v[0]], &tin_.vertices[tri.v[1]],
                              &tin_.vertices[tri.v[2]]};
        const Point2 c{(v[0]->x + v[1]->x + v[2]->x) / 3.0, (v[0]->y + v[1]->y + v[2]->y) / 3.0};
        out.assign(lattice_.local_vertices(), {});
        out[0] = c;
        for (std::uint32_t k = 0; k < 3; ++k) {
            for (std::uint32_t b = 1; b < m; ++b) {
                const double s = b / md;
                out[lattice_.inner(k, b)] = {v[k]->x + s * (c.x - v[k]->x),
                                             v[k]->y + s * (c.y - v[k]->y)};
            }
        }
        for (std::uint32_t k = 0; k < 3; ++k) {
            const Point3& a = *v[(k + 1) % 3];
            const Point3& b = *v[(k + 2) % 3];
            for (std::uint32_t j = 1; j + 1 < m; ++j) {
                for (std::uint32_t i = 1; i + j < m; ++i) {
                    const double s = i / md, r = j / md;
                    out[lattice_.interior(k, i, j)] = {a.x + s * (b.x - a.x) + r * (c.x - a.x),
                                                       a.y + s * (b.y - a.y) + r * (c.y - a.y)};
                }
            }
        }
        for (std::size_t e = 0; e < 3; ++e) {
            if (!own[e]) {
                continue;
            }
            VertexIndex p = tri.v[(e + 1) % 3], q = tri.v[(e + 2) % 3];
            if (q < p) {
                std::swap(p, q);
            }
            const Point3& a = tin_.vertices[p];
            const Point3& b = tin_.vertices[q];
            for (std::uint32_t i = 1; i < m; ++i) {
                const double s = i / md;
                out.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
            }
        }
    }

private:
    const Tin& tin_;
    const Lattice& lattice_;
};

Ranges height_ranges(const Tin& tin, const TinInterpolant& interpolant, const Lattice& lattice) {
    Ranges r;
    r.lo.resize(tin.triangles.size());
    r.hi.resize(tin.triangles.size());
    tbb::enumerable_thread_specific<TinEvaluator> evaluators(tin, interpolant);
    const CubicSurface cubic(tin, interpolant.gradients());
    const LocalPoints local(tin, lattice);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin.triangles.size(), 1 << 10),
                      [&](const tbb::blocked_range<std::size_t>& range) {
                          std::vector<Point2> points;
                          std::vector<double> z;
                          TinEvaluator& eval = evaluators.local();
                          for (std::size_t t = range.begin(); t != range.end(); ++t) {
                              const auto id = static_cast<TriangleIndex>(t);
                              if (interpolant.method() == Interpolation::cubic) {
                                  std::tie(r.lo[t], r.hi[t]) = cubic.patch(id).bounds();
                                  continue;
                              }
                              local.make(id, {true, true, true}, points);
                              z.resize(points.size());
                              eval.values(id, points, z);
                              double lo = std::numeric_limits<double>::infinity(), hi = -lo;
                              for (const double h : z) {
                                  lo = std::min(lo, h);
                                  hi = std::max(hi, h);
                              }
                              for (const VertexIndex v : tin.triangles[t].v) {
                                  lo = std::min(lo, tin.vertices[v].z);
                                  hi = std::max(hi, tin.vertices[v].z);
                              }
                              // Both triangles of an edge evaluate its points; allow for their
                              // rounding.
                              const double pad = 1e-9 * (std::abs(lo) + std::abs(hi) + 1.0);
                              r.lo[t] = lo - pad;
                              r.hi[t] = hi + pad;
                          }
                      });
    return r;
}

/// Builds the refinement of the triangles @p selected (ascending) of @p tin.
class Refiner {
public:
    Refiner(const Tin& tin, const TinInterpolant& interpolant, const Lattice& lattice)
        : tin_(tin),
          interpolant_(interpolant),
          lattice_(lattice),
          local_(tin, lattice),
          position_(tin.triangles.size(), none) {}

    Tin refine(const std::vector<TriangleIndex>& selected) {
        const std::uint32_t m = lattice_.m();
        for (std::size_t j = 0; j < selected.size(); ++j) {
            position_[selected[j]] = static_cast<std::uint32_t>(j);
        }
        // Vertex numbering: the TIN's vertices, then per selected triangle its local points
        // and the points of the edges it owns (an edge is owned by the lower-numbered of its
        // selected triangles).
        std::vector<std::array<bool, 3>> own(selected.size());
        std::vector<std::array<std::uint32_t, 3>> edge_base(selected.size());
        std::vector<std::uint32_t> base(selected.size() + 1);
        base[0] = static_cast<std::uint32_t>(tin_.vertices.size());
        for (std::size_t j = 0; j < selected.size(); ++j) {
            const Triangle& tri = tin_.triangles[selected[j]];
            std::uint32_t count = lattice_.local_vertices();
            for (std::size_t e = 0; e < 3; ++e) {
                const TriangleIndex u = tri.n[e];
                own[j][e] = u == no_triangle || position_[u] == none || selected[j] < u;
                if (own[j][e]) {
                    edge_base[j][e] = base[j] + count;
                    count += m - 1;
                }
            }
            if (static_cast<double>(base[j]) + count > std::numeric_limits<std::uint32_t>::max()) {
                throw Error("contour: the refinement has too many vertices; lower `subdivisions`");
            }
            base[j + 1] = base[j] + count;
        }
        for (std::size_t j = 0; j < selected.size(); ++j) {
            const Triangle& tri = tin_.triangles[selected[j]];
            for (std::size_t e = 0; e < 3; ++e) {
                if (!own[j][e]) {
                    const std::uint32_t k = position_[tri.n[e]];
                    edge_base[j][e] = edge_base[k][shared_edge(tri.n[e], selected[j])];
                }
            }
        }
        Tin out;
        out.vertices.resize(base.back());
        std::copy(tin_.vertices.begin(), tin_.vertices.end(), out.vertices.begin());
        out.triangles.resize(selected.size() * lattice_.pieces());
        tbb::enumerable_thread_specific<TinEvaluator> evaluators(tin_, interpolant_);
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, selected.size(), 1 << 8),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              std::vector<Point2> points;
                              std::vector<double> z;
                              for (std::size_t j = r.begin(); j != r.end(); ++j) {
                                  local_.make(selected[j], own[j], points);
                                  z.resize(points.size());
                                  evaluators.local().values(selected[j], points, z);
                                  for (std::size_t i = 0; i < points.size(); ++i) {
                                      out.vertices[base[j] + i] = {points[i].x, points[i].y, z[i]};
                                  }
                                  fill_pieces(selected, j, base[j], edge_base[j], out);
                              }
                          });
        for (const TriangleIndex t : selected) {
            position_[t] = none;
        }
        return out;
    }

private:
    /// The edge of @p u whose other triangle is @p t.
    [[nodiscard]] std::size_t shared_edge(TriangleIndex u, TriangleIndex t) const {
        const auto& n = tin_.triangles[u].n;
        return n[0] == t ? 0 : (n[1] == t ? 1 : 2);
    }

    void fill_pieces(const std::vector<TriangleIndex>& selected,
                     std::size_t j,
                     std::uint32_t local_base,
                     const std::array<std::uint32_t, 3>& edge_base,
                     Tin& out) const {
        const std::uint32_t m = lattice_.m();
        const Triangle& tri = tin_.triangles[selected[j]];
        const auto first = static_cast<TriangleIndex>(j * lattice_.pieces());
        for (std::uint32_t k = 0; k < 3; ++k) {
            const std::uint32_t ca = (k + 1) % 3, cb = (k + 2) % 3;
            const VertexIndex va = tri.v[ca], vb = tri.v[cb];
            const auto id = [&](std::uint32_t a, std::uint32_t b) -> VertexIndex {
                if (b == 0) {
                    if (a == 0) return va;
                    if (a == m) return vb;
                    return edge_base[k] + (va < vb ? a - 1 : m - 1 - a);
                }
                if (a == 0) return local_base + (b == m ? 0 : lattice_.inner(ca, b));
                if (a + b == m) return local_base + lattice_.inner(cb, b);
                return local_base + lattice_.interior(k, a, b);
            };
            const auto link = [&](std::uint32_t piece, std::size_t e, TriangleIndex to) {
                out.triangles[first + piece].n[e] = to == no_triangle ? no_triangle : first + to;
            };
            for (std::uint32_t b = 0; b < m; ++b) {
                for (std::uint32_t a = 0; a + b < m; ++a) {
                    const std::uint32_t u = lattice_.up(k, a, b);
                    out.triangles[first + u].v = {id(a, b), id(a + 1, b), id(a, b + 1)};
                    // across (a+1,b)-(a,b+1): the down piece, or the next sub-triangle
                    link(u, 0,
                         a + b + 1 < m ? lattice_.down(k, a, b)
                                       : lattice_.up((k + 1) % 3, 0, m - 1 - a));
                    // across (a,b+1)-(a,b): the down piece to the left, or the previous one
                    link(u, 1,
                         a > 0 ? lattice_.down(k, a - 1, b)
                               : lattice_.up((k + 2) % 3, m - 1 - b, b));
                    if (b > 0) {
                        link(u, 2, lattice_.down(k, a, b - 1));
                    }
                    if (a + b + 1 < m) {
                        const std::uint32_t d = lattice_.down(k, a, b);
                        out.triangles[first + d].v = {id(a + 1, b), id(a + 1, b + 1), id(a, b + 1)};
                        link(d, 0, lattice_.up(k, a, b + 1));
                        link(d, 1, u);
                        link(d, 2, lattice_.up(k, a + 1, b));
                    }
                }
            }
            // The pieces on the triangle's edge k: across it, the neighbour's pieces in the
            // opposite order (or the border of the refinement).
            const TriangleIndex nb = tri.n[k];
            const std::uint32_t pos = nb == no_triangle ? none : position_[nb];
            for (std::uint32_t a = 0; a < m; ++a) {
                Triangle& piece = out.triangles[first + lattice_.up(k, a, 0)];
                if (pos == none) {
                    piece.n[2] = no_triangle;
                    continue;
                }
                const auto e = static_cast<std::uint32_t>(shared_edge(nb, selected[j]));
                piece.n[2] = static_cast<TriangleIndex>(pos * lattice_.pieces() +
                                                        lattice_.up(e, m - 1 - a, 0));
            }
        }
    }

    const Tin& tin_;
    const TinInterpolant& interpolant_;
    const Lattice& lattice_;
    LocalPoints local_;
    std::vector<std::uint32_t> position_;  ///< per TIN triangle: its place in the selection
};

/// The first s in [a0, a1] where the cubic with Bernstein ordinates @p b (over [a0, a1])
/// reaches @p level, if any: Bezier subdivision, skipping halves that stay below the level, and
/// bisection once a piece is monotone. The first crossing of a lower level always comes before
/// that of a higher one (the curve must pass the lower level to reach the higher).
bool first_crossing(
    const std::array<double, 4>& b, double a0, double a1, double level, int depth, double& out) {
    if (std::max({b[0], b[1], b[2], b[3]}) < level) {
        return false;
    }
    if (b[0] >= level) {
        out = a0;
        return true;
    }
    const auto at = [&](double u) {
        const double v = 1.0 - u;
        return v * v * v * b[0] + 3.0 * u * v * (v * b[1] + u * b[2]) + u * u * u * b[3];
    };
    if ((b[0] <= b[1] && b[1] <= b[2] && b[2] <= b[3]) || depth == 0) {
        double lo = 0.0, hi = 1.0;  // at(lo) < level <= at(hi) on a monotone piece
        for (int k = 0; k < 60 && (hi - lo) * (a1 - a0) > 1e-16; ++k) {
            const double mid = 0.5 * (lo + hi);
            (at(mid) < level ? lo : hi) = mid;
        }
        out = a0 + hi * (a1 - a0);
        return true;
    }
    // de Casteljau at 1/2
    const double m01 = 0.5 * (b[0] + b[1]), m12 = 0.5 * (b[1] + b[2]), m23 = 0.5 * (b[2] + b[3]);
    const double m012 = 0.5 * (m01 + m12), m123 = 0.5 * (m12 + m23);
    const double mid = 0.5 * (m012 + m123), am = 0.5 * (a0 + a1);
    return first_crossing({b[0], m01, m012, mid}, a0, am, level, depth - 1, out) ||
           first_crossing({mid, m123, m23, b[3]}, am, a1, level, depth - 1, out);
}

/// Places a contour point on a refinement edge at the cubic surface's own crossing: along an
/// edge of a piece the surface is one cubic polynomial (a piece lies in one Clough-Tocher
/// sub-triangle), known from four samples (0, 1/3, 2/3, 1 of the edge); the point is its first
/// crossing of the level from the below end. So every point lies on the cubic's level curve,
/// and along each edge the levels keep their order: lines still never cross. The patch used is
/// that of the lower-numbered TIN triangle at the edge, so both sides give the same bits.
class CubicEdgeCrossing final : public EdgeCrossing {
public:
    CubicEdgeCrossing(const Tin& refined,
                      const CubicSurface& cubic,
                      const std::vector<TriangleIndex>& selected,
                      std::uint32_t pieces)
        : refined_(refined), cubic_(cubic), selected_(selected), pieces_(pieces) {}

    [[nodiscard]] Point3 point(
        TriangleIndex t, int e, VertexIndex below, VertexIndex above, double level) const override {
        const Point3& p = refined_.vertices[below];
        const Point3& q = refined_.vertices[above];
        const double linear = (level - p.z) / (q.z - p.z);
        TriangleIndex macro = selected_[t / pieces_];
        const TriangleIndex other = refined_.triangles[t].n[static_cast<std::size_t>(e)];
        if (other != no_triangle) {
            macro = std::min(macro, selected_[other / pieces_]);
        }
        const CloughTocherPatch patch = cubic_.patch(macro);
        const auto at = [&](double s) {
            return patch.value(p.x + s * (q.x - p.x), p.y + s * (q.y - p.y));
        };
        const double g0 = p.z, g1 = at(1.0 / 3.0), g2 = at(2.0 / 3.0), g3 = q.z;
        const double c1 = (-5.0 * g0 + 18.0 * g1 - 9.0 * g2 + 2.0 * g3) / 6.0;
        const double c2 = (2.0 * g0 - 9.0 * g1 + 18.0 * g2 - 5.0 * g3) / 6.0;
        double s = linear;
        if (!first_crossing({g0, c1, c2, g3}, 0.0, 1.0, level, 40, s)) {
            s = linear;  // unreachable: g0 < level <= g3
        }
        return {p.x + s * (q.x - p.x), p.y + s * (q.y - p.y), level};
    }

private:
    const Tin& refined_;
    const CubicSurface& cubic_;
    const std::vector<TriangleIndex>& selected_;
    std::uint32_t pieces_;
};

void run(const Tin& tin,
         const TinInterpolant& interpolant,
         const ContourOptions& options,
         ContourSink& sink,
         const Progress& progress) {
    if (options.subdivisions == 0 || options.subdivisions > 64) {
        throw UsageError("contour: `subdivisions` must be between 1 and 64");
    }
    const Lattice lattice(options.subdivisions);
    const Ranges ranges = height_ranges(tin, interpolant, lattice);
    double zmin = std::numeric_limits<double>::infinity(), zmax = -zmin;
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        zmin = std::min(zmin, ranges.lo[t]);
        zmax = std::max(zmax, ranges.hi[t]);
    }
    const std::vector<ContourLevel> levels = contour_levels(zmin, zmax, options);
    if (levels.empty()) {
        return;
    }
    // Per triangle, the levels lo < L <= hi cut it: [first, last) by binary search.
    std::vector<std::array<std::uint32_t, 2>> cut(tin.triangles.size());
    std::vector<std::size_t> per_level(levels.size() + 1, 0);
    const auto above = [&](double z) {
        return static_cast<std::uint32_t>(
            std::upper_bound(levels.begin(), levels.end(), z,
                             [](double h, const ContourLevel& l) { return h < l.value; }) -
            levels.begin());
    };
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        cut[t] = {above(ranges.lo[t]), above(ranges.hi[t])};
        ++per_level[cut[t][0]];
        --per_level[cut[t][1]];
    }
    // Batches of consecutive levels, each refining at most about four million pieces.
    const std::size_t budget = std::max<std::size_t>(1, (std::size_t{4} << 20) / lattice.pieces());
    Refiner refiner(tin, interpolant, lattice);
    const CubicSurface cubic(tin, interpolant.gradients());
    std::size_t crossing = 0;
    for (std::size_t k0 = 0; k0 < levels.size();) {
        std::size_t k1 = k0, load = 0;
        while (k1 < levels.size()) {
            crossing += per_level[k1];
            if (k1 > k0 && load + crossing > budget) {
                crossing -= per_level[k1];
                break;
            }
            load += crossing;
            ++k1;
        }
        progress.check();
        std::vector<TriangleIndex> selected;
        for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
            if (cut[t][0] < k1 && cut[t][1] > k0) {
                selected.push_back(static_cast<TriangleIndex>(t));
            }
        }
        const Tin refined = refiner.refine(selected);
        const std::vector<ContourLevel> batch(levels.begin() + static_cast<std::ptrdiff_t>(k0),
                                              levels.begin() + static_cast<std::ptrdiff_t>(k1));
        const double n = static_cast<double>(levels.size());
        const CubicEdgeCrossing cubic_crossing(refined, cubic, selected, lattice.pieces());
        trace_contour_levels(
            refined, batch, options, sink,
            progress.sub(static_cast<double>(k0) / n, static_cast<double>(k1) / n),
            interpolant.method() == Interpolation::cubic ? &cubic_crossing : nullptr);
        k0 = k1;
    }
}

}  // namespace

Tin refine_for_contours(const Tin& tin,
                        const TinInterpolant& interpolant,
                        const std::vector<TriangleIndex>& selected,
                        unsigned subdivisions) {
    const Lattice lattice(subdivisions);
    return Refiner(interpolant.surface(tin), interpolant, lattice).refine(selected);
}

void contour_refined(const Tin& given,
                     const TinInterpolant& interpolant,
                     const ContourOptions& options,
                     ContourSink& sink,
                     const Progress& progress) {
    const Tin& tin = interpolant.surface(given);
    if (options.threads > 0) {
        tbb::task_arena arena(static_cast<int>(options.threads));
        arena.execute([&] { run(tin, interpolant, options, sink, progress); });
    } else {
        run(tin, interpolant, options, sink, progress);
    }
}

}  // namespace dtm::detail
