// SPDX-License-Identifier: MIT
/// @file
/// @brief Exact sections of a TIN along polylines (long profiles, cross-sections): a breakpoint
/// wherever the line crosses a TIN edge or passes through a vertex, chainage from the line's
/// start, and gaps where the surface is absent.
#pragma once

#include <memory>
#include <span>
#include <vector>

#include "dtm/core/point.hpp"
#include "dtm/core/progress.hpp"
#include "dtm/core/tin.hpp"

namespace dtm {

struct ProfilePoint {
    double chainage = 0.0;  ///< distance along the line from its start (plan length)
    double x = 0.0;
    double y = 0.0;
    double z = 0.0;  ///< the surface height here
};

/// A continuous part of a section: the surface exists all along it; z is linear between points.
struct ProfileRun {
    std::vector<ProfilePoint> points;
};

/// The section of one surface along one line. Between runs the surface is absent (a gap).
struct Profile {
    std::vector<ProfileRun> runs;
    double length = 0.0;  ///< plan length of the line
};

/// Height of @p profile at @p chainage by linear interpolation; false where it has no surface.
[[nodiscard]] bool profile_height(const Profile& profile, double chainage, double& z);

/// Cuts sections of one TIN; build once, cut many lines (thread-safe).
class TinSection {
public:
    /// @p tin must outlive the object.
    explicit TinSection(const Tin& tin);
    TinSection(const TinSection&) = delete;
    TinSection& operator=(const TinSection&) = delete;
    ~TinSection();

    /// The section along the polyline @p line (vertices in order; x, y read).
    /// Which triangles the line meets, where it passes through a vertex or runs along an edge,
    /// and where the surface starts and ends are decided exactly (orient2d); crossing parameters
    /// are computed from each edge in a fixed direction, so the triangles on both sides of an
    /// edge agree on the breakpoint.
    [[nodiscard]] Profile cut(std::span<const Point3> line) const;

    /// Sections along many lines, in parallel (@p threads 0: all cores). @throws Cancelled
    [[nodiscard]] std::vector<Profile> cut_all(std::span<const std::vector<Point3>> lines,
                                               unsigned threads = 0,
                                               const Progress& progress = {}) const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace dtm
