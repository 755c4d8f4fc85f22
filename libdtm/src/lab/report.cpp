// SPDX-License-Identifier: MIT
// The lab's files (dtm/lab/compare.hpp): results.csv (one row per cell), results.json (the same
// plus every run's time, the method's own counters and the angle histograms), report.md (tables
// per distribution, the scaling summary that docs/performance.md quotes, the thesis' Fig. 36
// next to today's uniform-grid, the plots). Each file is written atomically.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include "dtm/core/error.hpp"
#include "dtm/io/atomic_file.hpp"
#include "dtm/io/json_writer.hpp"
#include "dtm/lab/compare.hpp"
#include "lab/report_detail.hpp"

namespace dtm::lab {
namespace {

std::string num(double v, const char* format = "%.4g") {
    if (!std::isfinite(v)) return "";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, v);
    return buffer;
}

std::string csv_field(const std::string& s) {
    if (s.find_first_of(",\"\n") == std::string::npos) return s;
    std::string out = "\"";
    for (char c : s) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

using io::json_string;  // the one JSON string escaper (dtm/io/json_writer.hpp)

std::string json_number(double v) {
    if (!std::isfinite(v)) return "null";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return buffer;
}

std::uint64_t extra(const Measurement& c, const char* key) {
    const auto it = c.counters.extra.find(key);
    return it == c.counters.extra.end() ? 0 : it->second;
}

double thesis_total(std::size_t n) {
    for (const HistoricalTiming& row : thesis_fig36()) {
        if (row.n == n) return row.grid_seconds + row.triangulation_seconds;
    }
    return NAN;
}

/// The row values of a cell, in csv_columns() order.
std::vector<std::string> row(const Measurement& c) {
    const bool ok = c.status == Status::ok;
    const detail::Rates r = detail::rates(c);
    const auto v = [&](double x) { return ok ? num(x, "%.6g") : std::string(); };
    const auto u = [&](std::uint64_t x) { return ok ? std::to_string(x) : std::string(); };
    const double historical =
        c.method == "uniform-grid" && c.distribution == "uniform" ? thesis_total(c.n) : NAN;
    return {c.method,
            c.family,
            c.quadratic ? "1" : "0",
            c.distribution,
            std::to_string(c.n),
            c.historical_only ? "historical" : "main",
            std::string(status_name(c.status)),
            c.note,
            std::to_string(c.seconds.size()),
            v(c.mean_seconds),
            v(c.min_seconds),
            v(r.per_n),
            v(r.per_nlogn),
            v(r.per_nlog10n),
            v(r.per_n43),
            u(c.counters.orient_calls),
            u(c.counters.incircle_calls),
            u(extra(c, "distance_calls")),
            u(c.counters.flips),
            u(c.counters.walk_steps),
            u(c.counters.peak_bytes),
            u(c.peak_rss_bytes),
            v(r.bytes_per_point),
            u(c.vertices),
            u(c.triangles),
            u(c.faces),
            ok && c.angles.faces ? num(c.angles.min_mean, "%.3f") : "",
            ok && c.angles.faces ? num(c.angles.max_mean, "%.3f") : "",
            ok && c.angles.faces ? num(c.angles.min_min, "%.4f") : "",
            ok && c.angles.faces ? num(c.angles.max_max, "%.4f") : "",
            num(historical, "%.6g")};
}

void write_text(const std::filesystem::path& path, const std::string& text) {
    io::AtomicOutput out(path);
    {
        std::ofstream f(out.temp_path(), std::ios::binary);
        f << text;
        if (!f) throw Error("methods compare: cannot write " + path.string());
    }
    out.commit();
}

std::string csv(const CompareResult& result) {
    std::string out;
    const auto& cols = csv_columns();
    for (std::size_t i = 0; i < cols.size(); ++i) out += (i ? "," : "") + cols[i];
    out += "\n";
    for (const Measurement& c : result.cells) {
        const auto fields = row(c);
        for (std::size_t i = 0; i < fields.size(); ++i)
            out += (i ? "," : "") + csv_field(fields[i]);
        out += "\n";
    }
    return out;
}

std::string json(const CompareResult& result) {
    const CompareOptions& o = result.options;
    std::ostringstream out;
    out << "{\n  \"date\": " << json_string(result.date)
        << ",\n  \"machine\": {\"cpu\": " << json_string(result.machine.cpu)
        << ", \"cores\": " << result.machine.cores
        << ", \"caches\": " << json_string(result.machine.caches) << "},\n  \"options\": {";
    out << "\"methods\": [";
    std::set<std::string> names;
    for (const Measurement& c : result.cells) names.insert(c.method);
    std::size_t k = 0;
    for (const std::string& n : names) out << (k++ ? ", " : "") << json_string(n);
    out << "], \"sizes\": [";
    for (std::size_t i = 0; i < o.sizes.size(); ++i) out << (i ? ", " : "") << o.sizes[i];
    out << "], \"distributions\": [";
    for (std::size_t i = 0; i < o.distributions.size(); ++i) {
        out << (i ? ", " : "")
            << json_string(std::string(methods::distribution_name(o.distributions[i])));
    }
    out << "], \"sets\": " << o.sets << ", \"repeat\": " << o.repeat << ", \"seed\": " << o.seed
        << ", \"threads\": " << o.threads << ", \"cap_seconds\": " << json_number(o.cap_seconds)
        << "},\n  \"thesis_fig36\": [";
    for (std::size_t i = 0; i < thesis_fig36().size(); ++i) {
        const HistoricalTiming& h = thesis_fig36()[i];
        out << (i ? ", " : "") << "{\"n\": " << h.n
            << ", \"grid_seconds\": " << json_number(h.grid_seconds)
            << ", \"triangulation_seconds\": " << json_number(h.triangulation_seconds) << "}";
    }
    out << "],\n  \"cells\": [";
    const auto& cols = csv_columns();
    for (std::size_t i = 0; i < result.cells.size(); ++i) {
        const Measurement& c = result.cells[i];
        const auto fields = row(c);
        out << (i ? ",\n    {" : "\n    {");
        for (std::size_t f = 0; f < cols.size(); ++f) {
            const bool text = f < 9 && f != 4 && f != 2 && f != 8;
            out << (f ? ", " : "") << json_string(cols[f]) << ": "
                << (text ? json_string(fields[f]) : (fields[f].empty() ? "null" : fields[f]));
        }
        out << ", \"seconds\": [";
        for (std::size_t s = 0; s < c.seconds.size(); ++s)
            out << (s ? ", " : "") << json_number(c.seconds[s]);
        out << "], \"counters\": {";
        std::size_t e = 0;
        for (const auto& [key, value] : c.counters.extra)
            out << (e++ ? ", " : "") << json_string(key) << ": " << value;
        out << "}, \"min_angle_histogram\": [";
        for (int b = 0; b < AngleStats::bins; ++b)
            out << (b ? ", " : "") << c.angles.min_histogram[std::size_t(b)];
        out << "], \"max_angle_histogram\": [";
        for (int b = 0; b < AngleStats::bins; ++b)
            out << (b ? ", " : "") << c.angles.max_histogram[std::size_t(b)];
        out << "]}";
    }
    out << "\n  ]\n}\n";
    return out.str();
}

}  // namespace

const std::vector<std::string>& csv_columns() {
    static const std::vector<std::string> columns{"method",
                                                  "family",
                                                  "quadratic",
                                                  "distribution",
                                                  "n",
                                                  "role",
                                                  "status",
                                                  "note",
                                                  "runs",
                                                  "seconds_mean",
                                                  "seconds_min",
                                                  "s_per_n",
                                                  "s_per_nlogn",
                                                  "s_per_nlog10n",
                                                  "s_per_n43",
                                                  "orient_calls",
                                                  "incircle_calls",
                                                  "distance_calls",
                                                  "flips",
                                                  "walk_steps",
                                                  "method_peak_bytes",
                                                  "peak_rss_bytes",
                                                  "rss_bytes_per_point",
                                                  "vertices",
                                                  "triangles",
                                                  "faces",
                                                  "min_angle_mean",
                                                  "max_angle_mean",
                                                  "min_angle_min",
                                                  "max_angle_max",
                                                  "thesis_486_seconds"};
    return columns;
}

void write_compare(const CompareResult& result, const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir / "plots", ec);
    if (ec)
        throw Error("methods compare: cannot create " + (dir / "plots").string() + ": " +
                    ec.message());
    write_text(dir / "results.csv", csv(result));
    write_text(dir / "results.json", json(result));
    const std::vector<std::string> plots = detail::write_plots(result, dir / "plots");
    write_text(dir / "report.md", detail::markdown(result, plots));
}

}  // namespace dtm::lab
