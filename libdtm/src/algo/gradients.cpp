// SPDX-License-Identifier: MIT
// Vertex gradients for the C1 surface: Nielson's minimum-norm network, split at hard breaklines.
//
// 1. Sectors. Around a vertex, the triangles are cut into runs at the hard breakline edges
//    through it (walking the vertex's fan through the neighbour links, detail/vertex_stars);
//    each run is a sector with its own gradient. Most vertices touch no hard breakline: their
//    one sector is the vertex. Sectors are numbered in the order the triangles first use their
//    vertices, so the solver's reads follow the triangles' spatial order.
// 2. The network. Each edge (a, b) of length L, with d = b - a and height difference h, gets the
//    cubic Hermite curve defined by the heights and the slopes m_a = g_a.d/L, m_b = g_b.d/L of
//    the gradients of the sectors it bounds, and its energy
//        E = integral of (curve'')^2 = (4/L)(m_a^2 + m_a m_b + m_b^2) - (12/L^2) h (m_a + m_b)
//            + (12/L^3) h^2,
//    which is zero exactly when the curve is a straight line (for a linear surface, the exact
//    gradient makes every edge energy zero). A plain edge is one term; a hard breakline edge is
//    one term per side (each side's surface ends at the breakline); a border edge one term,
//    weighted 1/2: a border edge bounds one triangle only, and on the convex hull of scattered
//    points it is often long and far from the data of its triangle, so its curve is a weaker
//    witness of the slope than an inner edge (on the DEM-sampling cases of
//    bench/compare_accuracy.py the weight 1/2 lowered the cubic's RMSE by about 0.4 % on
//    average, docs/performance.md "Surface accuracy"; a linear surface still has energy 0).
// 3. The minimum of the sum over all edges is the solution of a sparse symmetric positive
//    definite system with one 2 x 2 block row per sector:
//        (sum 8 d d^T / L^3) g_p + sum_q (4 d d^T / L^3) g_q = sum 12 h d / L^3.
//    Each sector's row is built by a walk of its vertex's fan (in parallel, no shared writes).
//    Block Gauss-Seidel sweeps inside fixed chunks of sectors, Jacobi across chunks, solve it
//    in parallel; they converge fast because the diagonal blocks dominate (each off-diagonal
//    block is half of its edge's contribution to the diagonal). The start is the weighted
//    least-squares plane of each sector's edges (2/3 of the first Jacobi step). The chunks are
//    fixed, so the result never depends on the thread count.
//
// References: G. M. Nielson, "A method for interpolating scattered data based upon a minimum
// norm network", Mathematics of Computation 40(161), 1983; R. J. Renka, "Algorithm 624:
// Triangulation and interpolation at arbitrarily distributed points in the plane", ACM TOMS
// 10(4), 1984 (the same global estimate, solved by Gauss-Seidel).
#include "dtm/algo/gradients.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "algo/detail/big_array.hpp"
#include "algo/detail/edge_kinds.hpp"
#include "algo/detail/vertex_stars.hpp"
#include "dtm/core/error.hpp"

namespace dtm {
namespace {

using detail::BigArray;
using detail::Corner;
using detail::VertexStars;

/// The weight of a border edge's term in the network (every other edge has weight 1): see the
/// note at the top.
constexpr double border_weight = 0.5;

/// The block system of the network: per sector, a row of off-diagonal couplings.
struct NetworkSystem {
    BigArray<std::array<double, 3>> kinv;  ///< per sector, inverse diagonal block (xx, xy, yy)
    BigArray<Gradient> rhs;                ///< per sector
    BigArray<std::array<std::uint32_t, 2>> rows;  ///< per sector, its couplings [begin, end)
    struct Coupling {
        double ax, ay;         ///< 2 d / L^1.5: the coupling block is 4 d d^T / L^3 = a a^T
        std::uint32_t sector;  ///< the other end's sector
    };
    BigArray<Coupling> couplings;  ///< not zeroed: every used entry is written
};

/// Calls term(sector, far corner, weight) for every network term of @p v's sectors: each fan
/// edge once for the sector it lies in, and a hard edge once more for the sector on its other
/// side. A border edge (no triangle beyond it) has the weight border_weight, every other edge 1.
template <class Term>
void each_term_of(const VertexStars& stars,
                  const TinGradients& g,
                  std::uint32_t rank,
                  Term&& term) {
    const auto sector = [&](Corner c) {
        return g.corner_sector[c.t][static_cast<std::size_t>(c.i)];
    };
    Corner last{};
    bool open = false;
    const auto close_fan = [&] {
        if (open && last.t != no_triangle) {  // the border edge after the last triangle
            term(sector(last), Corner{last.t, (last.i + 2) % 3}, border_weight);
        }
    };
    stars.for_each_fan(
        rank,
        [&](bool fan_open) {
            close_fan();
            last = {};
            open = fan_open;
        },
        [&](Corner c) {
            const Corner prev = stars.cw(c);  // the triangle beyond the edge to corner i + 1
            term(sector(c), Corner{c.t, (c.i + 1) % 3},
                 prev.t == no_triangle ? border_weight : 1.0);
            if (stars.hard(c, 1) && prev.t != no_triangle) {
                term(sector(prev), Corner{prev.t, (prev.i + 2) % 3}, 1.0);
            }
            last = c;
        });
    close_fan();
}

/// A sector whose edges all point (nearly) one way, such as a thin fan between two breakline
/// edges, leaves its gradient across them undetermined: the network's energy does not depend
/// on it, and the diagonal block is (nearly) singular. Such a sector is pulled towards the
/// area-weighted mean of its triangles' planes by a term 10^-3 x the block's larger eigenvalue
/// (zero for a linear surface, where the planes are the exact gradient; well-conditioned sectors
/// are left as they are).
void regularise_undetermined(const VertexStars& stars,
                             const TinGradients& g,
                             const BigArray<Point3>& at_sector,
                             BigArray<std::array<double, 3>>& diag,
                             BigArray<Gradient>& rhs) {
    constexpr double ratio = 1e-3;
    for (std::size_t p = 0; p < diag.size(); ++p) {
        const auto [a, b, c] = diag[p];
        const double half_trace = 0.5 * (a + c);
        const double spread = std::sqrt(0.25 * (a - c) * (a - c) + b * b);
        const double largest = half_trace + spread, smallest = half_trace - spread;
        if (!(largest > 0.0) || smallest >= ratio * largest) {
            continue;
        }
        double sx = 0.0, sy = 0.0, weight = 0.0;
        const auto rank = stars.rank(g.sector_vertex[p]);
        stars.for_each_fan(
            rank, [](bool) {},
            [&](Corner k) {
                const auto& cs = g.corner_sector[k.t];
                if (cs[static_cast<std::size_t>(k.i)] != p) {
                    return;
                }
                const Point3 &q0 = at_sector[cs[0]], &q1 = at_sector[cs[1]], &q2 = at_sector[cs[2]];
                const double bx = q1.x - q0.x, by = q1.y - q0.y, bz = q1.z - q0.z;
                const double cx = q2.x - q0.x, cy = q2.y - q0.y, cz = q2.z - q0.z;
                const double det = bx * cy - cx * by;
                if (det == 0.0) {
                    return;
                }
                // area weight |det| / 2 times the plane's gradient (bz cy - cz by, bx cz - cx bz) /
                // det
                const double sign = det > 0.0 ? 0.5 : -0.5;
                sx += sign * (bz * cy - cz * by);
                sy += sign * (bx * cz - cx * bz);
                weight += 0.5 * std::abs(det);
            });
        if (weight <= 0.0) {
            continue;
        }
        const double tau = ratio * largest;
        diag[p][0] += tau;
        diag[p][2] += tau;
        rhs[p].dx += tau * sx / weight;
        rhs[p].dy += tau * sy / weight;
    }
}

NetworkSystem build_system(const Tin& tin,
                           const VertexStars& stars,
                           const TinGradients& g,
                           std::vector<float>& relief) {
    NetworkSystem s;
    const std::size_t sectors = g.sector_vertex.size();
    const auto& order = stars.order();
    // Each used vertex gets a block of couplings (an upper bound of its term count) and fills
    // it alone, in parallel; a sector's row is a run inside its vertex's block.
    BigArray<std::size_t> block(order.size() + 1, 0);
    for (std::uint32_t k = 0; k < order.size(); ++k) {
        const std::size_t corners = stars.corner_count(k);
        block[k + 1] =
            block[k] + corners + stars.fan_count(k) + (stars.on_hard_edge(k) ? corners : 0);
    }
    if (block.back() > std::numeric_limits<std::uint32_t>::max()) {
        throw Error("gradients: the TIN is too large for the network's 32-bit indices");
    }
    s.couplings.resize(block.back());
    // The vertices in sector order: the walks below read them in the triangles' order, not in
    // the (often random) input order.
    BigArray<Point3> at_sector(sectors);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sectors, 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t p = r.begin(); p != r.end(); ++p) {
                              at_sector[p] = tin.vertices[g.sector_vertex[p]];
                          }
                      });
    s.rows.assign(sectors, {0, 0});
    s.rhs.assign(sectors, {});
    BigArray<std::array<double, 3>> diag(sectors, {0.0, 0.0, 0.0});
    struct Term {
        std::uint32_t sector;
        float rise;
        NetworkSystem::Coupling coupling;
    };
    const auto coupling = [&](const Point3& a, Corner far, std::uint32_t p, double weight) {
        const std::uint32_t q = g.corner_sector[far.t][static_cast<std::size_t>(far.i)];
        const Point3& b = at_sector[q];
        const double dx = b.x - a.x, dy = b.y - a.y, h = b.z - a.z;
        const double l2 = dx * dx + dy * dy;
        const double l = std::sqrt(l2);
        const double w = weight / (l2 * l);
        const double scale = 2.0 * std::sqrt(weight / (l2 * l));
        diag[p][0] += 8.0 * w * dx * dx;
        diag[p][1] += 8.0 * w * dx * dy;
        diag[p][2] += 8.0 * w * dy * dy;
        s.rhs[p].dx += 12.0 * w * h * dx;
        s.rhs[p].dy += 12.0 * w * h * dy;
        return NetworkSystem::Coupling{scale * dx, scale * dy, q};
    };
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, order.size(), 1 << 11),
        [&](const tbb::blocked_range<std::size_t>& r) {
            std::vector<Term> terms;
            const auto rise = [&](const Point3& a, Corner far) {
                return static_cast<float>(std::abs(
                    at_sector[g.corner_sector[far.t][static_cast<std::size_t>(far.i)]].z - a.z));
            };
            for (std::size_t k = r.begin(); k != r.end(); ++k) {
                const auto rank = static_cast<std::uint32_t>(k);
                const Point3& a = at_sector[k];
                auto at = static_cast<std::uint32_t>(block[k]);
                if (!stars.on_hard_edge(rank)) {  // one sector: the row is the whole block
                    s.rows[rank][0] = at;
                    each_term_of(stars, g, rank, [&](std::uint32_t, Corner far, double weight) {
                        s.couplings[at++] = coupling(a, far, rank, weight);
                        relief[rank] = std::max(relief[rank], rise(a, far));
                    });
                    s.rows[rank][1] = at;
                    continue;
                }
                terms.clear();
                each_term_of(stars, g, rank, [&](std::uint32_t p, Corner far, double weight) {
                    terms.push_back({p, rise(a, far), coupling(a, far, p, weight)});
                });
                std::stable_sort(terms.begin(), terms.end(),
                                 [](const Term& x, const Term& y) { return x.sector < y.sector; });
                for (std::size_t i = 0; i < terms.size(); ++i) {
                    if (i == 0 || terms[i].sector != terms[i - 1].sector) {
                        s.rows[terms[i].sector][0] = at;
                    }
                    s.couplings[at++] = terms[i].coupling;
                    s.rows[terms[i].sector][1] = at;
                    relief[terms[i].sector] = std::max(relief[terms[i].sector], terms[i].rise);
                }
            }
        });
    regularise_undetermined(stars, g, at_sector, diag, s.rhs);
    s.kinv.resize(sectors);
    for (std::size_t p = 0; p < sectors; ++p) {
        const auto [a, b, c] = diag[p];
        const double det = a * c - b * b;
        s.kinv[p] = det > 0.0 ? std::array<double, 3>{c / det, -b / det, a / det}
                              : std::array<double, 3>{0.0, 0.0, 0.0};
    }
    return s;
}

Gradient apply(const std::array<double, 3>& m, double x, double y) {
    return {m[0] * x + m[1] * y, m[1] * x + m[2] * y};
}

void solve(const NetworkSystem& s,
           const GradientOptions& options,
           TinGradients& out,
           const Progress& progress) {
    const std::size_t n = s.kinv.size();
    std::vector<Gradient>& g = out.gradient;
    g.assign(n, {});
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 1 << 14),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t p = r.begin(); p != r.end(); ++p) {
                              const Gradient x = apply(s.kinv[p], s.rhs[p].dx, s.rhs[p].dy);
                              g[p] = {x.dx * (2.0 / 3.0), x.dy * (2.0 / 3.0)};
                          }
                      });
    std::vector<Gradient> next(n);
    const auto max_abs = [&](const std::vector<Gradient>& v) {
        return tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, n, 1 << 14), 0.0,
            [&](const tbb::blocked_range<std::size_t>& r, double m) {
                for (std::size_t p = r.begin(); p != r.end(); ++p) {
                    m = std::max({m, std::abs(v[p].dx), std::abs(v[p].dy)});
                }
                return m;
            },
            [](double a, double b) { return std::max(a, b); });
    };
    out.iterations = 0;
    out.change = 0.0;
    // Sweeps over fixed chunks of sectors in parallel: inside a chunk the sectors are updated in
    // order with the new values of the chunk's earlier sectors (Gauss-Seidel), across chunks
    // with the values of the previous sweep (Jacobi). The chunks never depend on the thread
    // count, so neither does the result.
    constexpr std::size_t chunk = 2048;
    const std::size_t chunks = (n + chunk - 1) / chunk;
    for (unsigned it = 0; it < options.max_iterations; ++it) {
        progress.check();
        const double change = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, chunks, 1), 0.0,
            [&](const tbb::blocked_range<std::size_t>& r, double m) {
                for (std::size_t ch = r.begin(); ch != r.end(); ++ch) {
                    const std::size_t c0 = ch * chunk, c1 = std::min(n, c0 + chunk);
                    for (std::size_t p = c0; p < c1; ++p) {
                        double x = s.rhs[p].dx, y = s.rhs[p].dy;
                        for (std::uint32_t k = s.rows[p][0]; k < s.rows[p][1]; ++k) {
                            const auto& c = s.couplings[k];
                            const Gradient& q =
                                c.sector >= c0 && c.sector < p ? next[c.sector] : g[c.sector];
                            const double f = c.ax * q.dx + c.ay * q.dy;
                            x -= f * c.ax;
                            y -= f * c.ay;
                        }
                        next[p] = apply(s.kinv[p], x, y);
                        m = std::max(
                            {m, std::abs(next[p].dx - g[p].dx), std::abs(next[p].dy - g[p].dy)});
                    }
                }
                return m;
            },
            [](double a, double b) { return std::max(a, b); });
        g.swap(next);
        ++out.iterations;
        const double scale = max_abs(g);
        out.change = scale > 0.0 ? change / scale : 0.0;
        progress.report(std::min(1.0, static_cast<double>(it + 1) / 40.0), "gradients");
        if (out.change <= options.tolerance) {
            break;
        }
    }
}

/// Where a hard breakline ends inside the TIN, its vertex has one sector all around, whose
/// gradient mixes both sides of the crease (dominated by the side with the shorter, steeper
/// edges) and throws the cubic off on the other side. So the crease is carried one edge further:
/// the edge most nearly continuing the breakline (within 45 degrees of straight on) is treated
/// as hard too, and the crease fades out at its far end.
void extend_breakline_ends(const Tin& tin, std::vector<std::uint8_t>& hard) {
    const VertexStars stars(tin, hard);
    std::vector<std::pair<TriangleIndex, std::size_t>> extensions;
    for (std::uint32_t rank = 0; rank < stars.order().size(); ++rank) {
        if (!stars.on_hard_edge(rank) || stars.fan_count(rank) != 1) {
            continue;
        }
        const Point3& v = tin.vertices[stars.order()[rank]];
        std::size_t hard_count = 0;
        bool closed = true;
        Point2 along{};
        std::vector<Corner> corners;
        stars.for_each_fan(
            rank, [&](bool open) { closed = !open; },
            [&](Corner c) {
                corners.push_back(c);
                if (stars.hard(c, 1)) {  // the edge to corner i + 1, counted once per fan
                    ++hard_count;
                    const Point3& w = tin.vertices[tin.triangles[c.t].v[(c.i + 1) % 3]];
                    along = {w.x - v.x, w.y - v.y};
                }
            });
        if (!closed || hard_count != 1) {
            continue;
        }
        const double len = std::hypot(along.x, along.y);
        double best = -std::sqrt(0.5);  // the cosine of 135 degrees: at least that straight
        Corner pick{};
        for (const Corner c : corners) {
            const Point3& w = tin.vertices[tin.triangles[c.t].v[(c.i + 1) % 3]];
            const double dx = w.x - v.x, dy = w.y - v.y;
            const double cosine = (dx * along.x + dy * along.y) / (std::hypot(dx, dy) * len);
            if (cosine < best) {  // the most nearly opposite edge
                best = cosine;
                pick = c;
            }
        }
        if (pick.t != no_triangle) {
            extensions.push_back({pick.t, static_cast<std::size_t>((pick.i + 2) % 3)});
        }
    }
    for (const auto& [t, e] : extensions) {
        hard[t] = static_cast<std::uint8_t>(hard[t] | (1U << e));
        const TriangleIndex u = tin.triangles[t].n[e];
        if (u != no_triangle) {
            const auto& n = tin.triangles[u].n;
            const std::size_t back = n[0] == t ? 0 : (n[1] == t ? 1 : 2);
            hard[u] = static_cast<std::uint8_t>(hard[u] | (1U << back));
        }
    }
}

TinGradients estimate(const Tin& tin, const GradientOptions& options, const Progress& progress) {
    TinGradients out;
    const detail::TriangleEdgeKinds kinds = options.crease_at_breaklines
                                                ? detail::triangle_edge_kinds(tin)
                                                : detail::TriangleEdgeKinds{};
    out.hard_edges.assign(tin.triangles.size(), 0);
    for (std::size_t t = 0; t < kinds.size(); ++t) {
        std::uint8_t bits = 0;
        for (std::size_t e = 0; e < 3; ++e) {
            if (detail::is_hard(kinds[t][e])) {
                bits = static_cast<std::uint8_t>(bits | (1U << e));
            }
        }
        out.hard_edges[t] = bits;
    }
    if (std::any_of(out.hard_edges.begin(), out.hard_edges.end(), [](auto b) { return b != 0; })) {
        extend_breakline_ends(tin, out.hard_edges);
    }
    const VertexStars stars(tin, out.hard_edges);
    detail::number_sectors(tin, stars, out.corner_sector, out.sector_vertex);
    out.relief.assign(out.sector_vertex.size(), 0.0F);
    const NetworkSystem system = build_system(tin, stars, out, out.relief);
    solve(system, options, out, progress);
    progress.report(1.0, "gradients");
    return out;
}

}  // namespace

TinGradients estimate_gradients(const Tin& tin,
                                const GradientOptions& options,
                                const Progress& progress) {
    if (options.threads > 0) {
        tbb::task_arena arena(static_cast<int>(options.threads));
        return arena.execute([&] { return estimate(tin, options, progress); });
    }
    return estimate(tin, options, progress);
}

}  // namespace dtm
