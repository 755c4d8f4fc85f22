// SPDX-License-Identifier: MIT
//
// Breaklines (hard and soft), boundaries and holes in a distributed run. The lines are few against
// the points, so every rank reads them whole (departure from R-D2: no feature ranges) and computes
// the same things: the heights of 2-D vertices from the survey points at their positions (each rank
// looks in its run of the input, the lowest rank's find wins: the serial first point), the serial
// combined order (add_lines), and after the distributed duplicate merge the serial segments in
// vertex numbers. The split pre-pass (split_segments, docs/algorithms/cdt.md) then runs on every
// rank over the line vertices alone, renumbered monotonically: its decisions read coordinates and
// segment indices only, except that a crossing falling exactly on an existing vertex becomes that
// vertex; line vertices are in the copy, and survey points that crossings land on (which only their
// ranks know) are looked up on all ranks and added, the split run again, until none lands on a new
// one. Crossing vertices are numbered after every merged vertex, in pair order, as serially.
#include "products/detail/distributed_lines.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <optional>
#include <span>
#include <unordered_map>
#include <unordered_set>

#include "algo/detail/segment_split.hpp"
#include "dtm/algo/line_heights.hpp"
#include "dtm/core/error.hpp"
#include "dtm/io/inputs.hpp"

namespace dtm::products::detail {
namespace {

struct NumberedPoint {
    std::uint64_t id;
    Point3 p;
    std::uint64_t z_known;  ///< 0 for a soft line's vertex without a height yet
};

std::pair<std::uint64_t, std::uint64_t> key(double x, double y) {
    return {std::bit_cast<std::uint64_t>(x == 0.0 ? 0.0 : x),
            std::bit_cast<std::uint64_t>(y == 0.0 ? 0.0 : y)};
}

struct KeyHash {
    std::size_t operator()(const std::pair<std::uint64_t, std::uint64_t>& k) const noexcept {
        return std::hash<std::uint64_t>{}(k.first * 0x9e3779b97f4a7c15ull ^ k.second);
    }
};

}  // namespace

TerrainInput read_distributed_lines(const DistributedSource& source,
                                    const std::string& crs_wkt,
                                    std::optional<io::UtmZone> utm) {
    if (source.lines.empty()) return {};
    io::LoadOptions load;
    load.files = source.lines;
    load.read = source.read;
    load.crs = {source.default_crs, utm ? std::string() : crs_wkt};
    load.utm_zone = utm;
    TerrainInput t = io::load_inputs(load).terrain;
    if (!t.points.empty()) {
        throw UsageError(
            "a distributed run takes lines only from breakline, soft breakline, boundary and "
            "hole files (no points in them yet)");
    }
    return t;
}

void distributed_line_heights(dist::Comm& comm,
                              std::span<const dist::InputPoint> mine,
                              TerrainInput& lines) {
    // The positions of the vertices without a height, each once; every rank holds the lines.
    std::unordered_map<std::pair<std::uint64_t, std::uint64_t>, std::size_t, KeyHash> slot;
    for (const auto* kind :
         {&lines.breaklines, &lines.boundaries, &lines.holes, &lines.soft_breaklines}) {
        for (const Polyline& line : *kind) {
            for (const Point3& p : line.points) {
                if (std::isnan(p.z)) slot.emplace(key(p.x, p.y), slot.size());
            }
        }
    }
    if (slot.empty()) return;
    // This rank's first survey point at each (its points are a contiguous run of the input, in
    // order), then over ranks the lowest rank's: the serial first point in input order.
    struct Found {
        double z = 0.0;
        std::uint64_t found = 0;
    };
    std::vector<Found> here(slot.size());
    for (const dist::InputPoint& q : mine) {
        const auto it = slot.find(key(q.p.x, q.p.y));
        if (it != slot.end() && here[it->second].found == 0) here[it->second] = {q.p.z, 1};
    }
    comm.set_phase("line heights");
    const std::vector<dist::Bytes> all =
        comm.allgatherv(dist::to_bytes(std::span<const Found>(here)));
    std::vector<Found> first(slot.size());
    for (const dist::Bytes& bytes : all) {
        const std::vector<Found> theirs = dist::from_bytes<Found>(bytes);
        for (std::size_t i = 0; i < theirs.size() && i < first.size(); ++i) {
            if (first[i].found == 0) first[i] = theirs[i];
        }
    }
    (void)heights_from_survey_points(lines, [&](const Point2& p) -> std::optional<double> {
        const auto it = slot.find(key(p.x, p.y));
        if (it == slot.end() || first[it->second].found == 0) return std::nullopt;
        return first[it->second].z;
    });
}

DistributedLines combine_lines(const TerrainInput& lines) {
    DistributedLines out;
    ::dtm::detail::add_lines(lines, out.combined);
    out.has_boundary = !lines.boundaries.empty();
    out.hole_seeds = lines.hole_seeds;
    return out;
}

PlacedLines place_lines(dist::Comm& comm,
                        dist::MergedShare& merged,
                        const ::dtm::detail::CombinedInput& lines,
                        std::uint64_t first_line_input,
                        double z_tolerance) {
    PlacedLines out;
    if (lines.points.empty()) return out;
    const int last = comm.size() - 1;
    comm.set_phase("breaklines");
    // The vertex number of every line vertex, from the last rank, which holds them.
    std::vector<std::uint64_t> number;
    if (comm.rank() == last) {
        number.assign(
            merged.vertex_of_input.begin() + static_cast<std::ptrdiff_t>(first_line_input),
            merged.vertex_of_input.end());
    }
    dist::Bytes bytes = dist::to_bytes(std::span<const std::uint64_t>(number));
    comm.bcast(bytes, last);
    number = dist::from_bytes<std::uint64_t>(bytes);

    // The serial segments (merge_input: equal ends dropped) over the vertices they use.
    std::vector<std::array<std::uint64_t, 2>> ends;
    std::vector<std::uint8_t> bits;
    std::vector<std::uint64_t> used;
    for (const ::dtm::detail::InputSegment& s : lines.segments) {
        const std::uint64_t a = number[s.a];
        const std::uint64_t b = number[s.b];
        if (a == b) continue;
        ends.push_back({a, b});
        bits.push_back(s.bits);
        used.insert(used.end(), {a, b});
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());

    // The split over those vertices and the survey points that crossings fall on, found by
    // rounds: a crossing that lands exactly on a survey point becomes that point serially, so
    // the point joins the copy and the split runs again, until no new crossing lands on one.
    ::dtm::detail::MergedInput in;
    std::vector<bool> known_before;  // of the split's vertices, as merged
    for (int round = 0;; ++round) {
        if (round == 16) {
            throw Error("breaklines: crossings keep landing on survey points after 16 rounds");
        }
        // Kept positions and heights (after the duplicate rule), from the ranks holding them.
        std::vector<NumberedPoint> mine;
        for (const dist::Vertex& v : merged.vertices) {
            if (std::binary_search(used.begin(), used.end(), v.id)) {
                mine.push_back({v.id, v.p, v.z_known ? 1U : 0U});
            }
        }
        std::vector<NumberedPoint> kept = dist::concatenated<NumberedPoint>(
            comm.allgatherv(dist::to_bytes(std::span<const NumberedPoint>(mine))));
        std::sort(kept.begin(), kept.end(),
                  [](const NumberedPoint& a, const NumberedPoint& b) { return a.id < b.id; });
        in = {};
        for (const NumberedPoint& k : kept) {
            in.vertices.push_back(k.p);
            in.z_known.push_back(k.z_known != 0);
        }
        known_before = in.z_known;
        const auto compact = [&](std::uint64_t v) {
            return static_cast<VertexIndex>(std::lower_bound(used.begin(), used.end(), v) -
                                            used.begin());
        };
        for (std::size_t i = 0; i < ends.size(); ++i) {
            in.segments.push_back({compact(ends[i][0]), compact(ends[i][1]), bits[i]});
        }
        const ::dtm::detail::SegmentSplit split = ::dtm::detail::split_segments(in, z_tolerance);
        if (!split.all_free) {
            throw Error(
                "breaklines: crossings left after the split's rounds are not taken by a "
                "distributed run yet");
        }
        std::unordered_set<std::pair<std::uint64_t, std::uint64_t>, KeyHash> at;
        for (std::size_t v = used.size(); v < in.vertices.size(); ++v) {
            at.insert(key(in.vertices[v].x, in.vertices[v].y));
        }
        std::vector<std::uint64_t> landed;
        if (!at.empty()) {
            for (const dist::Vertex& v : merged.vertices) {
                if (at.contains(key(v.p.x, v.p.y))) landed.push_back(v.id);
            }
        }
        landed = dist::concatenated<std::uint64_t>(
            comm.allgatherv(dist::to_bytes(std::span<const std::uint64_t>(landed))));
        if (landed.empty()) break;
        used.insert(used.end(), landed.begin(), landed.end());
        std::sort(used.begin(), used.end());
        used.erase(std::unique(used.begin(), used.end()), used.end());
    }
    const std::size_t first_crossing = used.size();
    out.crossings = in.vertices.size() - first_crossing;

    // A soft line's vertex on a hard segment took the segment's height in the split: its owner
    // keeps it.
    for (std::size_t v = 0; v < first_crossing; ++v) {
        if (known_before[v] || !in.z_known[v]) continue;
        if (dist::Vertex* kept = merged.kept(used[v])) {
            kept->p.z = in.vertices[v].z;
            kept->z_known = true;
        }
    }
    const std::uint64_t first_new = merged.total_vertices;
    if (comm.rank() == last) {
        for (std::size_t v = first_crossing; v < in.vertices.size(); ++v) {
            merged.vertices.push_back({in.vertices[v],
                                       (first_new + (v - first_crossing)) & dist::vertex_id_bits,
                                       static_cast<bool>(in.z_known[v])});
        }
    }
    merged.total_vertices += out.crossings;
    const auto global = [&](VertexIndex v) {
        return v < first_crossing ? used[v] : first_new + (v - first_crossing);
    };
    for (const ::dtm::detail::InputSegment& s : in.segments) {
        out.segments.push_back({global(s.a), global(s.b), s.bits});
    }
    return out;
}

}  // namespace dtm::products::detail
