// SPDX-License-Identifier: MIT
// The sample survey: a jittered grid of spot heights (rounded to the millimetre, as a total
// station records them), the road breaklines sampled every 4 m, the boundary and the building
// with their true heights, a few points beyond the boundary, a few re-measured points, two
// corrupt CSV records and random check points.
#include "sample_site.hpp"

#include <cmath>
#include <cstdio>

namespace dtm::sample {
namespace {

/// SplitMix64 (Steele, Lea, Flood 2014): tiny, deterministic on every platform.
class Random {
public:
    explicit Random(std::uint64_t seed) : state_(seed) {}
    double uniform()  ///< in [0, 1)
    {
        state_ += 0x9E3779B97F4A7C15ULL;
        std::uint64_t z = state_;
        z = (z ^ (z >> 30U)) * 0xBF58476D1CE4E5B9ULL;
        z = (z ^ (z >> 27U)) * 0x94D049BB133111EBULL;
        z ^= z >> 31U;
        return static_cast<double>(z >> 11U) * 0x1.0p-53;
    }

private:
    std::uint64_t state_;
};

double round_to(double value, double step) { return std::round(value / step) * step; }

SurveyPoint survey_point(std::string id, double u, double v) {
    const double e = round_to(origin_e + u, 0.001);
    const double n = round_to(origin_n + v, 0.001);
    return {std::move(id), e, n, round_to(true_z(e, n), 0.001)};
}

std::string numbered(const char* prefix, std::size_t number) {
    char text[32];
    std::snprintf(text, sizeof text, "%s%zu", prefix, number);
    return text;
}

bool near_road(double u, double v) {
    const Road road;
    const double d = road.station_offset(u, v).v;
    return d > corridor_south - 0.8 && d < corridor_north + 0.8;  // the breaklines cover it
}

void add_spot_heights(Survey& survey, const SurveyOptions& options, Random& random) {
    const auto boundary = boundary_local();
    const auto building = building_local();
    std::size_t number = 1;
    for (double v = 0.0; v <= 180.0; v += options.spacing) {
        for (double u = 0.0; u <= 250.0; u += options.spacing) {
            const double pu = u + (random.uniform() - 0.5) * 0.6 * options.spacing;
            const double pv = v + (random.uniform() - 0.5) * 0.6 * options.spacing;
            if (!inside(boundary, pu, pv) || distance_to_ring(boundary, pu, pv) < 0.8 ||
                inside(building, pu, pv) || distance_to_ring(building, pu, pv) < 0.8 ||
                near_road(pu, pv)) {
                continue;
            }
            survey.points.push_back(survey_point(numbered("P", number++), pu, pv));
        }
    }
    // Beyond the boundary: the crew also shot the neighbour's fence line to the west.
    for (double v = 20.0; v <= 160.0; v += 12.0) {
        survey.points.push_back(survey_point(numbered("P", number++), -6.0, v));
        ++survey.outside_points;
    }
    // Re-measured control points: same position, same rounded height.
    for (std::size_t k = 0; k < 8; ++k) {
        const SurveyPoint again = survey.points[(k * 331 + 17) % (survey.points.size() / 2)];
        survey.points.push_back({numbered("R", k + 1), again.e, again.n, again.z});
        ++survey.repeated_points;
    }
}

/// True where a breakline vertex may go: inside the boundary, at least 1 m from it.
bool well_inside(const Uv& p) {
    const auto boundary = boundary_local();
    return inside(boundary, p.u, p.v) && distance_to_ring(boundary, p.u, p.v) >= 1.0;
}

/// The station where the line at offset d leaves the well-inside region, between an inside
/// station and an outside one (bisection).
double exit_station(const Road& road, double d, double in, double out) {
    for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (in + out);
        (well_inside(road.at(mid, d)) ? in : out) = mid;
    }
    return in;
}

void add_breaklines(Survey& survey) {
    const Road road;
    std::size_t number = 1;
    for (std::size_t i = 0; i < breakline_offsets.size(); ++i) {
        const double d = breakline_offsets[i];
        double first = 130.0;  // the middle of the road is well inside
        while (well_inside(road.at(first - 4.5, d))) {
            first -= 4.5;
        }
        first = exit_station(road, d, first, first - 4.5);
        double last = 130.0;
        while (well_inside(road.at(last + 4.5, d))) {
            last += 4.5;
        }
        last = exit_station(road, d, last, last + 4.5);
        Line line{breakline_names[i], {}};
        const auto steps = static_cast<std::size_t>(std::ceil((last - first) / 4.5));
        for (std::size_t k = 0; k <= steps; ++k) {
            const Uv p = road.at(
                first + (last - first) * static_cast<double>(k) / static_cast<double>(steps), d);
            line.vertices.push_back(survey_point(numbered("B", number++), p.u, p.v));
        }
        survey.breaklines.push_back(std::move(line));
    }
}

/// A closed ring with a surveyed vertex at most every 4 m along its edges.
Line ring_line(const char* kind, const char* prefix, const std::vector<Uv>& ring) {
    Line line{kind, {}};
    std::size_t number = 1;
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const Uv& a = ring[i];
        const Uv& b = ring[(i + 1) % ring.size()];
        const auto steps =
            static_cast<std::size_t>(std::ceil(std::hypot(b.u - a.u, b.v - a.v) / 4.0));
        for (std::size_t k = 0; k < steps; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(steps);
            line.vertices.push_back(survey_point(numbered(prefix, number++), a.u + t * (b.u - a.u),
                                                 a.v + t * (b.v - a.v)));
        }
    }
    line.vertices.push_back(line.vertices.front());
    return line;
}

void add_check_points(Survey& survey, const SurveyOptions& options, Random& random) {
    while (survey.check_points.size() < options.check_points) {
        const double u = random.uniform() * 250.0;
        const double v = random.uniform() * 180.0;
        if (!on_surface(u, v) || distance_to_ring(boundary_local(), u, v) < 3.0 ||
            distance_to_ring(building_local(), u, v) < 2.0) {
            continue;
        }
        const double e = round_to(origin_e + u, 0.001);  // as written to checkpoints.csv
        const double n = round_to(origin_n + v, 0.001);
        survey.check_points.push_back(
            {numbered("C", survey.check_points.size() + 1), e, n, true_z(e, n)});
    }
}

}  // namespace

Survey make_survey(const SurveyOptions& options) {
    Survey survey;
    Random random(options.seed);
    add_spot_heights(survey, options, random);
    add_breaklines(survey);
    survey.boundary = ring_line("boundary", "H", boundary_local());
    survey.building = ring_line("building", "D", building_local());
    survey.bad_lines = {"P9001,-750150.000,-1050100.000", "P9002,-750140.000,-1050100.000,n/a"};
    add_check_points(survey, options, random);
    return survey;
}

Survey natural_survey(const Survey& built) {
    Survey natural = built;
    const auto ground = [](SurveyPoint& p) {
        p.z = round_to(natural_z(p.e - origin_e, p.n - origin_n), 0.001);
    };
    for (SurveyPoint& p : natural.points) {
        ground(p);
    }
    for (Line& line : natural.breaklines) {
        for (SurveyPoint& p : line.vertices) {
            ground(p);
        }
    }
    for (Line* ring : {&natural.boundary, &natural.building}) {
        for (SurveyPoint& p : ring->vertices) {
            ground(p);
        }
    }
    natural.bad_lines.clear();
    natural.check_points.clear();
    return natural;
}

}  // namespace dtm::sample
