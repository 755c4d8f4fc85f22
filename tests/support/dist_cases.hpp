// SPDX-License-Identifier: MIT
/// @file
/// @brief Inputs of the distributed tests and the serial kernel's tree as their oracle.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "algo/detail/delaunay_dc.hpp"
#include "dist/global_mesh.hpp"
#include "dtm/dist/duplicates.hpp"
#include "dtm/dist/partition.hpp"

namespace dtm::test {

struct DistCase {
    std::string name;
    std::vector<dist::Point> points;  ///< pairwise distinct, id = index
};

/// Uniform, a grid whose cuts run through rows and columns (cocircular), Gaussian clusters,
/// S-JTSK magnitudes, collinear runs, and sets smaller than the rank count.
inline std::vector<DistCase> dist_cases(std::size_t n) {
    std::vector<DistCase> cases;
    std::mt19937_64 rng(20261202);
    const auto add = [&](std::string name, auto make) {
        DistCase c{std::move(name), {}};
        std::set<std::pair<double, double>> seen;
        for (std::size_t i = 0; c.points.size() < n && i < 4 * n; ++i) {
            const auto [x, y] = make(i);
            if (seen.emplace(x, y).second) c.points.push_back({x, y, c.points.size()});
        }
        cases.push_back(std::move(c));
    };
    std::uniform_real_distribution<double> u(0.0, 1000.0);
    std::normal_distribution<double> g(0.0, 8.0);
    add("uniform", [&](std::size_t) { return std::pair{u(rng), u(rng)}; });
    const auto side = static_cast<std::size_t>(std::sqrt(static_cast<double>(n))) + 1;
    add("grid", [&](std::size_t i) {
        return std::pair{static_cast<double>(i % side), static_cast<double>(i / side)};
    });
    add("clusters", [&](std::size_t i) {
        const double cx = static_cast<double>(i % 5) * 200.0;
        return std::pair{cx + g(rng), cx * 0.5 + g(rng)};
    });
    add("sjtsk", [&](std::size_t) {
        return std::pair{-750000.0 + std::round(u(rng) * 1000.0) / 1000.0,
                         -1050000.0 + std::round(u(rng) * 1000.0) / 1000.0};
    });
    add("collinear", [&](std::size_t i) {
        return i % 3 == 0 ? std::pair{static_cast<double>(i), 0.0}
                          : std::pair{static_cast<double>(i % 17), static_cast<double>(i % 13)};
    });
    // Fewer points than ranks, and nodes of at most 16 points below the top (cut by x, the
    // strip rule, where the alternation would cut by y).
    for (std::size_t tiny : {0, 1, 2, 3, 5, 12, 20, 40, 100}) {
        DistCase c{"tiny" + std::to_string(tiny), {}};
        for (std::size_t i = 0; i < tiny; ++i) {
            c.points.push_back({u(rng), u(rng), i});
        }
        cases.push_back(std::move(c));
    }
    return cases;
}

/// The serial kernel's result in global numbers: every slot, and the point id at every position.
struct SerialKernel {
    std::vector<dist::GlobalTriangle> tris;
    std::vector<std::uint64_t> ids;
};

inline SerialKernel serial_kernel(const std::vector<dist::Point>& points) {
    using namespace dtm::detail;
    BigArray<KernelPoint> pts(points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
        pts[i] = {{points[i].x, points[i].y}, static_cast<std::uint32_t>(points[i].id)};
    }
    GhostMesh mesh;
    delaunay_divide_and_conquer(pts, mesh, DelaunayDcOptions{}, Progress{});
    SerialKernel s;
    for (const Triangle& t : mesh.tris) s.tris.push_back(dist::to_global(t, 0, 0));
    if (points.size() >= 2) {
        for (std::size_t i = 0; i < mesh.points.size(); ++i) s.ids.push_back(mesh.points[i].id);
    }
    return s;
}

/// The ids in the serial kernel's order: positions [lo, hi) of a subtree are its points.
inline std::vector<std::uint64_t> serial_kernel_order(const std::vector<dist::Point>& points) {
    if (points.size() >= 2) return serial_kernel(points).ids;
    std::vector<std::uint64_t> ids;
    for (const auto& p : points) ids.push_back(p.id);
    return ids;
}

/// The part of @p points that rank @p r of @p ranks starts with: a contiguous index range, or
/// every ranks-th point when @p strided.
inline std::vector<dist::Point> initial_share(const std::vector<dist::Point>& points,
                                              int r,
                                              int ranks,
                                              bool strided) {
    std::vector<dist::Point> out;
    const std::size_t n = points.size();
    const auto p = static_cast<std::size_t>(ranks);
    const auto k = static_cast<std::size_t>(r);
    if (strided) {
        for (std::size_t i = k; i < n; i += p) out.push_back(points[i]);
    } else {
        out.assign(points.begin() + static_cast<std::ptrdiff_t>(k * n / p),
                   points.begin() + static_cast<std::ptrdiff_t>((k + 1) * n / p));
    }
    return out;
}

/// Points on a coarse lattice (many exact duplicates, 0.0 and -0.0 among them) and soft
/// breaklines whose vertices often coincide with them (heights unknown).
inline TerrainInput duplicate_rich_input(std::size_t n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_int_distribution<int> cell(-20, 20);
    std::uniform_real_distribution<double> height(100.0, 200.0);
    const auto coordinate = [&] {
        const int c = cell(rng);
        return c == 0 && rng() % 2 ? -0.0 : -750000.0 * (c != 0) + 0.25 * c;
    };
    TerrainInput input;
    for (std::size_t i = 0; i < n; ++i)
        input.points.push_back({coordinate(), coordinate(), height(rng)});
    for (std::size_t k = 0; k < n / 20; ++k) {
        Polyline line;
        line.points.push_back({coordinate(), coordinate(), 0.0});
        line.points.push_back({coordinate() + 0.125, coordinate(), 0.0});
        input.soft_breaklines.push_back(line);
    }
    return input;
}

inline std::vector<dist::InputPoint> combined_input(const TerrainInput& input) {
    std::vector<dist::InputPoint> out;
    for (const Point3& p : input.points) out.push_back({p, true});
    for (const Polyline& line : input.soft_breaklines) {
        for (const Point3& p : line.points) out.push_back({p, false});
    }
    return out;
}

}  // namespace dtm::test
