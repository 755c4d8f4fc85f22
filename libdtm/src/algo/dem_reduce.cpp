// SPDX-License-Identifier: MIT
// DEM cells against a survey, and DEM thinning by greedy insertion.
//   - Clipping: the survey points and the breakline segments go into a hash grid of 2R buckets
//     (segments by samples every R along them), so every cell checks the 3 x 3 buckets around
//     it and the exact point and segment distances decide.
//   - Thinning: M. Garland and P. S. Heckbert, "Fast polygonal approximation of terrains and
//     height fields", CMU-CS-95-181, 1995: start from a coarse TIN, repeatedly insert the input
//     point of largest error as a vertex until the error is within the bound. As in their
//     "Algorithm III/IV" the candidate of each triangle is its worst cell; unlike their one-at-a-
//     time loop (a priority queue over incrementally updated triangles) the worst candidates
//     are inserted together, worst first, skipping triangles next to one already inserting in
//     the pass (their errors will change), and the pass re-runs the constrained
//     Delaunay triangulation of survey + chosen cells with the pipeline's triangulate() (so
//     breaklines, boundaries and holes hold exactly as in any other TIN of dtm). The result is
//     within the bound at every cell (each cell is measured on the final TIN); the vertex count is
//     a little above the sequential greedy's (bench/dem_simplify.sh compares it with delatin).
#include "dtm/algo/dem_reduce.hpp"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <unordered_map>

#include "dtm/algo/surface_sampler.hpp"
#include "dtm/core/error.hpp"
#include "dtm/geom/predicates.hpp"

namespace dtm {
namespace {

void check_option(double value, const char* field) {
    if (!std::isfinite(value) || value < 0.0) {
        throw OptionError(field, std::string("`") + field +
                                     "`: expected a distance of 0 or more, got " +
                                     std::to_string(value));
    }
}

/// Survey points and line segments near a position (hash grid of square buckets).
class NearSurvey {
public:
    NearSurvey(const TerrainInput& survey, double radius) : r_(radius), bucket_(2.0 * radius) {
        for (const Point3& p : survey.points) add_point(p.xy());
        for (const auto* lines : {&survey.breaklines, &survey.soft_breaklines}) {
            for (const Polyline& l : *lines) {
                for (std::size_t i = 0; i < l.points.size(); ++i) {
                    const std::size_t j = i + 1 < l.points.size() ? i + 1 : 0;
                    if (j == 0 && !l.closed) break;
                    add_segment(l.points[i].xy(), l.points[j].xy());
                }
            }
        }
    }

    [[nodiscard]] bool near(Point2 p) const {
        const auto [cx, cy] = cell_of(p);
        for (std::int64_t dy = -1; dy <= 1; ++dy) {
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                const auto it = grid_.find(key(cx + dx, cy + dy));
                if (it == grid_.end()) continue;
                for (const std::uint32_t s : it->second) {
                    if (distance(p, segments_[s]) <= r_) return true;
                }
            }
        }
        return false;
    }

private:
    struct Segment {
        Point2 a, b;
    };
    static double distance(Point2 p, const Segment& s) {
        const double dx = s.b.x - s.a.x;
        const double dy = s.b.y - s.a.y;
        const double len2 = dx * dx + dy * dy;
        double t = len2 > 0.0 ? ((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / len2 : 0.0;
        t = std::clamp(t, 0.0, 1.0);
        return std::hypot(p.x - (s.a.x + t * dx), p.y - (s.a.y + t * dy));
    }
    [[nodiscard]] std::pair<std::int64_t, std::int64_t> cell_of(Point2 p) const {
        return {static_cast<std::int64_t>(std::floor(p.x / bucket_)),
                static_cast<std::int64_t>(std::floor(p.y / bucket_))};
    }
    static std::uint64_t key(std::int64_t x, std::int64_t y) {
        return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y & 0xffffffff);
    }
    void add_point(Point2 p) { add_segment(p, p); }
    void add_segment(Point2 a, Point2 b) {
        const auto index = static_cast<std::uint32_t>(segments_.size());
        segments_.push_back({a, b});
        // samples every R: a position within R of the segment is within 1.5 R of a sample,
        // so within one bucket (2 R) of the sample's bucket
        const double length = std::hypot(b.x - a.x, b.y - a.y);
        const auto steps = static_cast<std::size_t>(std::ceil(length / r_));
        std::uint64_t last = 0;
        for (std::size_t k = 0; k <= steps; ++k) {
            const double t = steps == 0 ? 0.0 : static_cast<double>(k) / static_cast<double>(steps);
            const auto [cx, cy] = cell_of({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)});
            const std::uint64_t kk = key(cx, cy);
            if (k > 0 && kk == last) continue;
            last = kk;
            std::vector<std::uint32_t>& list = grid_[kk];
            if (list.empty() || list.back() != index) list.push_back(index);
        }
    }
    double r_;
    double bucket_;
    std::vector<Segment> segments_;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid_;
};

/// Indices of the cells at the corners of their convex hull (Andrew's monotone chain with the
/// exact orientation; collinear cells on hull edges are not corners).
std::vector<std::size_t> hull_cells(const std::vector<Point3>& cells,
                                    const std::vector<std::size_t>& candidates) {
    std::vector<std::size_t> order = candidates;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return cells[a].x != cells[b].x ? cells[a].x < cells[b].x : cells[a].y < cells[b].y;
    });
    if (order.size() < 3) return order;
    std::vector<std::size_t> hull(2 * order.size());
    std::size_t k = 0;
    const auto turn = [&](std::size_t a, std::size_t b, std::size_t c) {
        return geom::orient2d(cells[a], cells[b], cells[c]);
    };
    for (const std::size_t i : order) {  // lower hull
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], i) <= 0) --k;
        hull[k++] = i;
    }
    const std::size_t lower = k + 1;
    for (std::size_t n = order.size() - 1; n-- > 0;) {  // upper hull
        const std::size_t i = order[n];
        while (k >= lower && turn(hull[k - 2], hull[k - 1], i) <= 0) --k;
        hull[k++] = i;
    }
    hull.resize(k - 1);
    std::sort(hull.begin(), hull.end());
    hull.erase(std::unique(hull.begin(), hull.end()), hull.end());
    return hull;
}

/// One cell's error on the current TIN, for the worst-per-triangle choice.
struct Miss {
    TriangleIndex triangle;
    double error;
    std::size_t cell;
};

struct PassErrors {
    std::vector<Miss> misses;  ///< cells in error that are not vertices yet
    double max_error = 0.0;
    double sum_squares = 0.0;
    std::size_t measured = 0;
    std::size_t outside = 0;
    std::size_t over_error = 0;  ///< kept cells still in error
};

PassErrors measure(const Tin& tin,
                   const std::vector<Point3>& cells,
                   const std::vector<std::size_t>& candidates,
                   const std::vector<char>& chosen,
                   double bound,
                   const Progress& progress) {
    const SurfaceSampler sampler(tin);
    constexpr std::size_t block = 4096;
    const std::size_t blocks = (candidates.size() + block - 1) / block;
    std::vector<PassErrors> parts(blocks);
    tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
        progress.check();
        PassErrors& part = parts[b];
        SurfaceSampler::Cursor cursor;
        const std::size_t end = std::min(candidates.size(), (b + 1) * block);
        for (std::size_t n = b * block; n < end; ++n) {
            const std::size_t c = candidates[n];
            const Point2 p = cells[c].xy();
            const TinLocation where = sampler.locate(p, cursor);
            if (where.kind == TinLocation::Kind::outside) {
                ++part.outside;
                continue;
            }
            const double e = std::abs(sampler.height_at(where, p) - cells[c].z);
            ++part.measured;
            part.max_error = std::max(part.max_error, e);
            part.sum_squares += e * e;
            if (!(e > bound)) continue;
            if (chosen[c] != 0) {
                ++part.over_error;
            } else {
                part.misses.push_back({where.edge.triangle, e, c});
            }
        }
    });
    PassErrors all;
    for (PassErrors& part : parts) {
        all.max_error = std::max(all.max_error, part.max_error);
        all.sum_squares += part.sum_squares;
        all.measured += part.measured;
        all.outside += part.outside;
        all.over_error += part.over_error;
        all.misses.insert(all.misses.end(), part.misses.begin(), part.misses.end());
    }
    return all;
}

/// Marks the cells to insert: the worst cell of each triangle in error, worst first, skipping a
/// triangle next to one that already inserts in this pass (the new vertex will change its
/// neighbours' errors, as the one-at-a-time greedy would see). Ties: the lower cell index.
void choose(const Tin& tin, std::vector<Miss>& misses, std::vector<char>& chosen) {
    std::sort(misses.begin(), misses.end(), [](const Miss& x, const Miss& y) {
        if (x.triangle != y.triangle) return x.triangle < y.triangle;
        if (x.error != y.error) return x.error > y.error;
        return x.cell < y.cell;
    });
    std::vector<Miss> worst;
    for (std::size_t i = 0; i < misses.size(); ++i) {
        if (i == 0 || misses[i].triangle != misses[i - 1].triangle) worst.push_back(misses[i]);
    }
    std::sort(worst.begin(), worst.end(), [](const Miss& x, const Miss& y) {
        return x.error != y.error ? x.error > y.error : x.cell < y.cell;
    });
    std::vector<char> blocked(tin.triangles.size(), 0);
    for (const Miss& m : worst) {
        if (blocked[m.triangle] != 0) continue;
        chosen[m.cell] = 1;
        blocked[m.triangle] = 1;
        for (const TriangleIndex n : tin.triangles[m.triangle].n) {
            if (n != no_triangle) blocked[n] = 1;
        }
    }
}

TerrainInput with_cells(const TerrainInput& survey,
                        const std::vector<Point3>& cells,
                        const std::vector<char>& chosen,
                        std::vector<std::size_t>* kept) {
    TerrainInput t = survey;
    for (std::size_t c = 0; c < cells.size(); ++c) {
        if (chosen[c] == 0) continue;
        t.points.push_back(cells[c]);
        if (kept != nullptr) kept->push_back(c);
    }
    return t;
}

}  // namespace

DemReduceResult reduce_dem(TerrainInput survey,
                           const std::vector<Point3>& cells,
                           const DemReduceOptions& options,
                           const TriangulateOptions& triangulate_options,
                           const Progress& progress) {
    check_option(options.clip_radius, "dem.clip_radius");
    check_option(options.max_error, "dem.max_error");
    DemReduceResult out;
    DemReduceReport& r = out.report;
    r.cells = cells.size();
    std::vector<std::size_t> candidates;
    candidates.reserve(cells.size());
    if (options.clip_radius > 0.0) {
        const NearSurvey near(survey, options.clip_radius);
        for (std::size_t c = 0; c < cells.size(); ++c) {
            if (c % 65536 == 0) progress.check();
            if (!near.near(cells[c].xy())) candidates.push_back(c);
        }
    } else {
        for (std::size_t c = 0; c < cells.size(); ++c) candidates.push_back(c);
    }
    r.clipped = cells.size() - candidates.size();
    std::vector<char> chosen(cells.size(), 0);
    if (!(options.max_error > 0.0)) {
        for (const std::size_t c : candidates) chosen[c] = 1;
        out.terrain = with_cells(survey, cells, chosen, &out.kept);
        r.kept = out.kept.size();
        return out;
    }
    for (const std::size_t c : hull_cells(cells, candidates)) chosen[c] = 1;
    const auto run = [&](auto&& body) {
        if (triangulate_options.threads > 0) {
            tbb::task_arena arena(static_cast<int>(triangulate_options.threads));
            arena.execute(body);
        } else {
            body();
        }
    };
    for (std::size_t pass = 0;; ++pass) {
        // passes roughly double the vertex count: pass k of about log2(cells) gets its share
        const double a = 1.0 - std::pow(0.5, static_cast<double>(pass));
        const double b = 1.0 - std::pow(0.5, static_cast<double>(pass + 1));
        out.triangulation = triangulate(with_cells(survey, cells, chosen, nullptr),
                                        triangulate_options, progress.sub(a, (a + b) / 2.0));
        ++r.passes;
        PassErrors e;
        run([&] {
            e = measure(out.triangulation.tin, cells, candidates, chosen, options.max_error,
                        progress.sub((a + b) / 2.0, b));
        });
        r.max_error = e.max_error;
        r.rms_error =
            e.measured > 0 ? std::sqrt(e.sum_squares / static_cast<double>(e.measured)) : 0.0;
        r.measured = e.measured;
        r.outside = e.outside;
        r.over_error = e.over_error;
        if (e.misses.empty() || pass + 1 >= options.max_passes) break;
        choose(out.triangulation.tin, e.misses, chosen);
        progress.report(b, "simplifying the DEM");
    }
    out.terrain = with_cells(survey, cells, chosen, &out.kept);
    out.triangulated = true;
    r.kept = out.kept.size();
    r.vertices = out.triangulation.tin.vertices.size();
    progress.report(1.0, "simplifying the DEM");
    return out;
}

}  // namespace dtm
