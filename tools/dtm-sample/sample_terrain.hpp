// SPDX-License-Identifier: MIT
/// @file
/// @brief The analytic terrain behind samples/sjtsk: a small building site in S-JTSK (EPSG:5514)
/// with a road in a side-hill cut-and-fill section. Header-only and free of I/O so the generator
/// (dtm-sample) and the tests share the same truth.
///
/// Local coordinates u, v (metres) are E - origin_e and N - origin_n. The natural ground is
///
///     natural(u, v) = 310 + 0.03 u + 0.08 v + 5 exp(-((u - 175)^2 + (v - 135)^2) / (2 * 30^2))
///
/// (a plane rising 8 % to the north and 3 % to the east, plus a 5 m Gaussian hill).
/// The road runs along the straight centre line from (-10, 55) to (250, 82). At station s and
/// signed offset d (positive to the north, uphill) the road level is zc(s) = natural(centre(s)) +
/// 0.3 and the cross-section, piecewise linear in d, is:
///
///      d:  -7.5    -4.5  -3.5     0     3.5  4.5  5.5       9.0
///           toe   shoulder edge  crown  edge ditch top   cut top
///    natural \_____/-----/   ^   \-----\  \/  /        /  natural
///            fill slope    camber 2 %   ditch 0.6 m   cut slope
///
/// - carriageway |d| <= 3.5: zc - 0.02 |d| (crown in the middle);
/// - north (cut): ditch bottom at d = 4.5, 0.6 m below the edge; ditch top at d = 5.5 at edge
///   level; then a straight blend up to the natural ground at d = 9;
/// - south (fill): level shoulder to d = -4.5; then a straight blend down to the natural ground
///   at the embankment toe d = -7.5.
/// Every kink of the cross-section is a breakline, so between breaklines the surface is linear
/// across the road and varies only slowly along it.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace dtm::sample {

inline constexpr double origin_e = -750300.0;   ///< E of the site's local (0, 0)
inline constexpr double origin_n = -1050200.0;  ///< N of the site's local (0, 0)
inline constexpr int epsg = 5514;

struct Uv {
    double u = 0.0;
    double v = 0.0;
};

inline double natural_z(double u, double v) {
    const double du = u - 175.0;
    const double dv = v - 135.0;
    return 310.0 + 0.03 * u + 0.08 * v + 5.0 * std::exp(-(du * du + dv * dv) / (2.0 * 30.0 * 30.0));
}

/// The road centre line: start, unit direction, and the unit normal pointing north (left).
struct Road {
    Uv start{-10.0, 55.0};
    Uv end{250.0, 82.0};
    [[nodiscard]] double length() const { return std::hypot(end.u - start.u, end.v - start.v); }
    [[nodiscard]] Uv direction() const {
        return {(end.u - start.u) / length(), (end.v - start.v) / length()};
    }
    [[nodiscard]] Uv normal() const { return {-direction().v, direction().u}; }
    /// The point at station s and offset d.
    [[nodiscard]] Uv at(double s, double d) const {
        const Uv t = direction();
        const Uv n = normal();
        return {start.u + s * t.u + d * n.u, start.v + s * t.v + d * n.v};
    }
    /// Station and offset of (u, v).
    [[nodiscard]] Uv station_offset(double u, double v) const {
        const Uv t = direction();
        const Uv n = normal();
        const double du = u - start.u;
        const double dv = v - start.v;
        return {du * t.u + dv * t.v, du * n.u + dv * n.v};
    }
};

/// Offsets of the road breaklines, south to north, and their names.
inline constexpr std::array<double, 8> breakline_offsets{-7.5, -4.5, -3.5, 0.0, 3.5, 4.5, 5.5, 9.0};
inline constexpr std::array<const char*, 8> breakline_names{
    "embankment_toe",  "embankment_top", "road_edge_south", "road_crown",
    "road_edge_north", "ditch_bottom",   "ditch_top",       "cut_top"};
inline constexpr double corridor_south = -7.5;
inline constexpr double corridor_north = 9.0;

/// True elevation at local (u, v).
inline double true_z_local(double u, double v) {
    const Road road;
    const Uv so = road.station_offset(u, v);
    const double d = so.v;
    if (d <= corridor_south || d >= corridor_north) {
        return natural_z(u, v);
    }
    const Uv centre = road.at(so.u, 0.0);
    const double zc = natural_z(centre.u, centre.v) + 0.3;
    const double edge = zc - 0.02 * 3.5;
    if (std::fabs(d) <= 3.5) {
        return zc - 0.02 * std::fabs(d);
    }
    if (d > 0.0) {
        if (d <= 4.5) {
            return edge - 0.6 * (d - 3.5);
        }
        if (d <= 5.5) {
            return edge - 0.6 * (5.5 - d);
        }
        const Uv top = road.at(so.u, 9.0);
        const double t = (d - 5.5) / 3.5;
        return (1.0 - t) * edge + t * natural_z(top.u, top.v);
    }
    if (d >= -4.5) {
        return edge;
    }
    const Uv toe = road.at(so.u, -7.5);
    const double t = (-4.5 - d) / 3.0;
    return (1.0 - t) * edge + t * natural_z(toe.u, toe.v);
}

/// True elevation at S-JTSK (E, N).
inline double true_z(double e, double n) { return true_z_local(e - origin_e, n - origin_n); }

/// Outer boundary of the survey (counter-clockwise, local coordinates, not repeated).
inline std::vector<Uv> boundary_local() {
    return {{2, 4}, {120, 0}, {238, 6}, {248, 90}, {232, 176}, {130, 180}, {6, 172}, {0, 95}};
}

/// The building footprint (a hole): 22 x 12 m rotated by 12 degrees about (70, 135).
inline std::vector<Uv> building_local() {
    const double a = 12.0 * 3.14159265358979323846 / 180.0;
    const double c = std::cos(a);
    const double s = std::sin(a);
    std::vector<Uv> ring;
    for (const auto& [x, y] : std::array<std::array<double, 2>, 4>{
             {{-11.0, -6.0}, {11.0, -6.0}, {11.0, 6.0}, {-11.0, 6.0}}}) {
        ring.push_back({70.0 + c * x - s * y, 135.0 + s * x + c * y});
    }
    return ring;
}

/// Even-odd point-in-polygon test on a ring (local coordinates).
inline bool inside(const std::vector<Uv>& ring, double u, double v) {
    bool in = false;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Uv& a = ring[i];
        const Uv& b = ring[j];
        if ((a.v > v) != (b.v > v) && u < (b.u - a.u) * (v - a.v) / (b.v - a.v) + a.u) {
            in = !in;
        }
    }
    return in;
}

/// Distance from (u, v) to the ring's edges.
inline double distance_to_ring(const std::vector<Uv>& ring, double u, double v) {
    double best = INFINITY;
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
        const Uv& a = ring[j];
        const Uv& b = ring[i];
        const double eu = b.u - a.u;
        const double ev = b.v - a.v;
        const double t =
            std::clamp(((u - a.u) * eu + (v - a.v) * ev) / (eu * eu + ev * ev), 0.0, 1.0);
        best = std::min(best, std::hypot(u - (a.u + t * eu), v - (a.v + t * ev)));
    }
    return best;
}

/// True if (u, v) is on the surveyed surface: inside the boundary and outside the building.
inline bool on_surface(double u, double v) {
    return inside(boundary_local(), u, v) && !inside(building_local(), u, v);
}

}  // namespace dtm::sample
