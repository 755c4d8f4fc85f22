// SPDX-License-Identifier: MIT
// libFuzzer target for the delimited-text reader: arbitrary bytes through layout detection and
// row parsing, for every role and with --skip-bad-lines on and off. Only InputError and
// UsageError may escape the reader; anything else (crash, sanitizer report, other exception)
// is a bug. The same bytes read in tiny blocks and chunks (sizes taken from the input) must give
// exactly what the one-block read gives, error included.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "dtm/core/error.hpp"
#include "dtm/io/formats/csv.hpp"
#include "io/formats/csv/csv_detail.hpp"

namespace {

void add_points(std::string& out, const std::vector<dtm::Point3>& points) {
    const std::size_t at = out.size();
    const std::size_t bytes = points.size() * sizeof(dtm::Point3);
    out.resize(at + bytes);
    if (bytes > 0) std::memcpy(out.data() + at, points.data(), bytes);
    out += '|';
}

/// Everything a read gives (the points bit for bit), or its error.
std::string digest(std::string_view text,
                   dtm::io::InputRole role,
                   const dtm::io::ReadOptions& options,
                   const dtm::io::csv::Cuts& cuts) {
    std::string out;
    try {
        const dtm::io::ReadResult r = dtm::io::csv::parse_csv_text(
            text, dtm::io::InputFile{"fuzz.csv", role}, options, {}, cuts);
        if (!r.labels.ids.empty() && r.labels.ids.size() != r.terrain.points.size()) {
            __builtin_trap();  // labels must stay parallel to points
        }
        add_points(out, r.terrain.points);
        for (const auto* lines : {&r.terrain.breaklines, &r.terrain.soft_breaklines,
                                  &r.terrain.boundaries, &r.terrain.holes}) {
            for (const dtm::Polyline& l : *lines) {
                add_points(out, l.points);
                out += l.source + (l.closed ? "c|" : "o|");
            }
        }
        for (const dtm::Point2& p : r.terrain.hole_seeds) add_points(out, {{p.x, p.y, 0.0}});
        for (const auto* labels : {&r.labels.ids, &r.labels.codes, &r.summary.warnings}) {
            for (const std::string& s : *labels) out += s + '|';
        }
        out += std::to_string(r.summary.skipped_lines) + r.crs_wkt;
    } catch (const dtm::InputError& e) {
        out = std::string("input error: ") + e.what();
    } catch (const dtm::UsageError& e) {
        out = std::string("usage error: ") + e.what();
    }
    return out;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    constexpr dtm::io::InputRole roles[] = {
        dtm::io::InputRole::points, dtm::io::InputRole::breaklines, dtm::io::InputRole::boundary,
        dtm::io::InputRole::holes};
    const dtm::io::csv::Cuts tiny{1 + size % 61, 1 + size % 13};
    for (const dtm::io::InputRole role : roles) {
        for (const bool skip : {false, true}) {
            dtm::io::ReadOptions options;
            options.skip_bad_lines = skip;
            if (digest(text, role, options, {}) != digest(text, role, options, tiny)) {
                __builtin_trap();  // reading in blocks and chunks changed the result
            }
        }
    }
    (void)dtm::io::csv_has_geometry_column(text);
    return 0;
}
