// SPDX-License-Identifier: MIT
// Vertex gradients for the C1 surface: Nielson's minimum-norm network, split at hard breaklines.
//
// 1. Sectors. Around a vertex, the triangles are cut into fans at the hard breakline edges
//    through it (found by walking the vertex's star through the neighbour links); each fan is a
//    sector with its own gradient. Most vertices touch no hard breakline: their one sector is
//    the vertex itself, and nothing is walked for them.
// 2. The network. Each edge (a, b) of length L, with d = b - a and height difference h, gets the
//    cubic Hermite curve defined by the heights and the slopes m_a = g_a.d/L, m_b = g_b.d/L of
//    the gradients of the sectors it bounds, and its energy
//        E = integral of (curve'')^2 = (4/L)(m_a^2 + m_a m_b + m_b^2) - (12/L^2) h (m_a + m_b)
//            + (12/L^3) h^2,
//    which is zero exactly when the curve is a straight line (for a linear surface, the exact
//    gradient makes every edge energy zero). A plain edge is one term; a hard breakline edge is
//    one term per side (each side's surface ends at the breakline); a border edge one term.
// 3. The minimum of the sum over all edges is the solution of a sparse symmetric positive
//    definite system with one 2 x 2 block row per sector:
//        (sum 8 d d^T / L^3) g_p + sum_q (4 d d^T / L^3) g_q = sum 12 h d / L^3.
//    Block Jacobi iterations solve it in parallel; they converge fast because the diagonal
//    blocks dominate (each off-diagonal block is half of its edge's contribution to the
//    diagonal). The start is the weighted least-squares plane of each sector's edges (2/3 of
//    the first Jacobi step). Jacobi is deterministic: the result never depends on the threads.
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

#include "algo/detail/edge_kinds.hpp"

namespace dtm {
namespace {

constexpr std::uint32_t unassigned = std::numeric_limits<std::uint32_t>::max();

/// Walks the fans of vertices on hard breaklines and numbers their sectors.
class SectorBuilder {
public:
    SectorBuilder(const Tin& tin, TinGradients& out) : tin_(tin), out_(out) {}

    /// Fills out.corner_sector; returns the number of sectors.
    std::size_t run() {
        const std::size_t n = tin_.vertices.size();
        std::vector<std::uint8_t> split(n, 0);
        for (std::size_t t = 0; t < tin_.triangles.size(); ++t) {
            for (std::size_t e = 0; e < 3; ++e) {
                if ((out_.hard_edges[t] >> e) & 1U) {
                    split[tin_.triangles[t].v[(e + 1) % 3]] = 1;
                    split[tin_.triangles[t].v[(e + 2) % 3]] = 1;
                }
            }
        }
        out_.corner_sector.resize(tin_.triangles.size());
        tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tin_.triangles.size(), 1 << 14),
                          [&](const tbb::blocked_range<std::size_t>& r) {
                              for (std::size_t t = r.begin(); t != r.end(); ++t) {
                                  for (std::size_t i = 0; i < 3; ++i) {
                                      const VertexIndex v = tin_.triangles[t].v[i];
                                      out_.corner_sector[t][i] = split[v] ? unassigned : v;
                                  }
                              }
                          });
        count_ = n;
        primary_used_.assign(n, 0);
        for (std::size_t t = 0; t < tin_.triangles.size(); ++t) {
            for (std::size_t i = 0; i < 3; ++i) {
                if (out_.corner_sector[t][i] == unassigned) {
                    walk_fan(static_cast<TriangleIndex>(t), static_cast<int>(i));
                }
            }
        }
        return count_;
    }

private:
    struct Corner {
        TriangleIndex t;
        int i;
    };

    [[nodiscard]] int corner_of(TriangleIndex t, VertexIndex v) const {
        const auto& tv = tin_.triangles[t].v;
        return tv[0] == v ? 0 : (tv[1] == v ? 1 : 2);
    }
    [[nodiscard]] bool hard(TriangleIndex t, int e) const {
        return ((out_.hard_edges[t] >> e) & 1U) != 0;
    }
    /// The next corner counter-clockwise around the vertex (across the edge to v[i+2]), or
    /// t == no_triangle at the border.
    [[nodiscard]] Corner ccw(Corner c) const {
        const TriangleIndex u = tin_.triangles[c.t].n[static_cast<std::size_t>((c.i + 1) % 3)];
        const VertexIndex v = tin_.triangles[c.t].v[static_cast<std::size_t>(c.i)];
        return u == no_triangle ? Corner{no_triangle, 0} : Corner{u, corner_of(u, v)};
    }
    [[nodiscard]] Corner cw(Corner c) const {
        const TriangleIndex u = tin_.triangles[c.t].n[static_cast<std::size_t>((c.i + 2) % 3)];
        const VertexIndex v = tin_.triangles[c.t].v[static_cast<std::size_t>(c.i)];
        return u == no_triangle ? Corner{no_triangle, 0} : Corner{u, corner_of(u, v)};
    }

    /// Assigns the sectors of the fan around the vertex of corner @p from.
    void walk_fan(TriangleIndex t, int i) {
        const VertexIndex v = tin_.triangles[t].v[static_cast<std::size_t>(i)];
        const std::size_t limit = tin_.triangles.size() + 1;
        // Start of the fan: the clockwise-most triangle of an open fan; for a closed fan, the
        // triangle after its first hard edge (counter-clockwise from t), or t.
        Corner start{t, i};
        bool closed = false;
        for (std::size_t k = 0; k < limit; ++k) {
            const Corner prev = cw(start);
            if (prev.t == no_triangle) {
                break;
            }
            if (prev.t == t) {
                closed = true;
                start = {t, i};
                break;
            }
            start = prev;
        }
        if (closed) {
            Corner c{t, i};
            for (std::size_t k = 0; k < limit; ++k) {
                const Corner next = ccw(c);
                if (hard(c.t, (c.i + 1) % 3)) {
                    start = next;
                    break;
                }
                c = next;
                if (c.t == t) {
                    break;
                }
            }
        }
        std::uint32_t sector = primary_used_[v] ? next_sector() : v;
        primary_used_[v] = 1;
        Corner c = start;
        for (std::size_t k = 0; k < limit; ++k) {
            out_.corner_sector[c.t][static_cast<std::size_t>(c.i)] = sector;
            const Corner next = ccw(c);
            if (next.t == no_triangle || next.t == start.t) {
                break;
            }
            if (hard(c.t, (c.i + 1) % 3)) {
                sector = next_sector();
            }
            c = next;
        }
    }

    std::uint32_t next_sector() { return static_cast<std::uint32_t>(count_++); }

    const Tin& tin_;
    TinGradients& out_;
    std::size_t count_ = 0;
    std::vector<std::uint8_t> primary_used_;
};

/// The block system of the network: per sector, a CSR row of off-diagonal couplings.
struct NetworkSystem {
    std::vector<VertexIndex> vertex;          ///< per sector, its vertex
    std::vector<std::array<double, 3>> kinv;  ///< per sector, inverse diagonal block (xx, xy, yy)
    std::vector<Gradient> rhs;                ///< per sector
    std::vector<std::uint32_t> offsets;       ///< CSR: couplings of sector p
    struct Coupling {
        std::uint32_t sector;  ///< the other end's sector
        double weight;         ///< 1 / L^3
    };
    std::vector<Coupling> couplings;
};

NetworkSystem build_system(const Tin& tin, const TinGradients& g, std::size_t sectors) {
    NetworkSystem s;
    s.vertex.assign(sectors, no_vertex);
    for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
        for (std::size_t i = 0; i < 3; ++i) {
            s.vertex[g.corner_sector[t][i]] = tin.triangles[t].v[i];
        }
    }
    std::vector<std::array<double, 3>> diag(sectors, {0.0, 0.0, 0.0});
    s.rhs.assign(sectors, {});
    s.offsets.assign(sectors + 1, 0);
    // Every term is visited from the triangle that owns it: a plain interior edge from its
    // lower-numbered triangle, a hard or border edge from each triangle it bounds.
    const auto each_term = [&](auto&& fn) {
        for (std::size_t t = 0; t < tin.triangles.size(); ++t) {
            const Triangle& tri = tin.triangles[t];
            for (std::size_t e = 0; e < 3; ++e) {
                const TriangleIndex u = tri.n[e];
                if (u != no_triangle && u < t && ((g.hard_edges[t] >> e) & 1U) == 0) {
                    continue;
                }
                fn(g.corner_sector[t][(e + 1) % 3], g.corner_sector[t][(e + 2) % 3]);
            }
        }
    };
    each_term([&](std::uint32_t p, std::uint32_t q) {
        ++s.offsets[p + 1];
        ++s.offsets[q + 1];
    });
    for (std::size_t p = 0; p < sectors; ++p) {
        s.offsets[p + 1] += s.offsets[p];
    }
    s.couplings.resize(s.offsets.back());
    std::vector<std::uint32_t> fill(s.offsets.begin(), s.offsets.end() - 1);
    each_term([&](std::uint32_t p, std::uint32_t q) {
        const Point3& a = tin.vertices[s.vertex[p]];
        const Point3& b = tin.vertices[s.vertex[q]];
        const double dx = b.x - a.x, dy = b.y - a.y, h = b.z - a.z;
        const double l2 = dx * dx + dy * dy;
        const double w = 1.0 / (l2 * std::sqrt(l2));
        for (const std::uint32_t r : {p, q}) {
            diag[r][0] += 8.0 * w * dx * dx;
            diag[r][1] += 8.0 * w * dx * dy;
            diag[r][2] += 8.0 * w * dy * dy;
            s.rhs[r].dx += 12.0 * w * h * dx;
            s.rhs[r].dy += 12.0 * w * h * dy;
        }
        s.couplings[fill[p]++] = {q, w};
        s.couplings[fill[q]++] = {p, w};
    });
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

void solve(const Tin& tin,
           const NetworkSystem& s,
           const GradientOptions& options,
           TinGradients& out,
           const Progress& progress) {
    const std::size_t n = s.vertex.size();
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
    for (unsigned it = 0; it < options.max_iterations; ++it) {
        progress.check();
        const double change = tbb::parallel_reduce(
            tbb::blocked_range<std::size_t>(0, n, 1 << 12), 0.0,
            [&](const tbb::blocked_range<std::size_t>& r, double m) {
                for (std::size_t p = r.begin(); p != r.end(); ++p) {
                    const Point3& a = tin.vertices[s.vertex[p]];
                    double x = s.rhs[p].dx, y = s.rhs[p].dy;
                    for (std::uint32_t k = s.offsets[p]; k < s.offsets[p + 1]; ++k) {
                        const auto& c = s.couplings[k];
                        const Point3& b = tin.vertices[s.vertex[c.sector]];
                        const double dx = b.x - a.x, dy = b.y - a.y;
                        const double f =
                            4.0 * c.weight * (dx * g[c.sector].dx + dy * g[c.sector].dy);
                        x -= f * dx;
                        y -= f * dy;
                    }
                    next[p] = apply(s.kinv[p], x, y);
                    m = std::max(
                        {m, std::abs(next[p].dx - g[p].dx), std::abs(next[p].dy - g[p].dy)});
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

TinGradients estimate(const Tin& tin, const GradientOptions& options, const Progress& progress) {
    TinGradients out;
    const detail::TriangleEdgeKinds kinds = detail::triangle_edge_kinds(tin);
    out.hard_edges.resize(tin.triangles.size());
    for (std::size_t t = 0; t < kinds.size(); ++t) {
        std::uint8_t bits = 0;
        for (std::size_t e = 0; e < 3; ++e) {
            if (detail::is_hard(kinds[t][e])) {
                bits = static_cast<std::uint8_t>(bits | (1U << e));
            }
        }
        out.hard_edges[t] = bits;
    }
    const std::size_t sectors = SectorBuilder(tin, out).run();
    const NetworkSystem system = build_system(tin, out, sectors);
    solve(tin, system, options, out, progress);
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
